"""Per-point kernels compiled with numba, run uncompiled for a process's first few points.

A model whose hot loop does not vectorise solves it one point at a time in a module of numba
functions (``cache=True``: the compiled code is kept once per machine, :mod:`.compiled_cache`,
so workers load it).
Importing numba and loading that code costs about half a second, more than a small sweep
computes. So a process's first points run the same module's source by the interpreter: the
module is executed a second time, under another name, with ``INTERPRETED`` set, and its
:func:`compiler` then returns a decorator that leaves the functions as they are. IEEE
operations in the same order give the same numbers, so a sweep's results do not depend on
which of the two ran (each such module's tests hold them bitwise equal).

A kernel module uses numpy's error model (a division by zero gives an infinity or NaN for that
point, as vectorised numpy did, rather than an exception for the whole block) and no
``fastmath`` (no reassociation: a point's numbers depend neither on the other points of the
call nor on the machine's vector width). Interpreted, its arithmetic must then be on numpy
scalars (read from the arrays), whose divisions follow the same model, under
``numpy.errstate``.
"""
from __future__ import annotations

import importlib
import importlib.util
import sys


def compiler(namespace):
    """``numba.njit`` for the kernel module whose ``globals()`` are ``namespace``; where the
    module runs interpreted, a decorator of the same signature that compiles nothing."""
    if namespace.get("INTERPRETED"):
        return lambda *_, **__: (lambda function: function)
    from .compiled_cache import njit
    return njit


class Kernels:
    """The kernel module ``name``, compiled or interpreted, for calls of a number of points.

    Parameters
    ----------
    name : str
        The module's full name.
    interpreted_points : int
        Points this process computes with the interpreted module before it loads the compiled
        one: about as many as the interpreter computes in the time numba takes to import and
        load the module, so that a small sweep never pays for numba and a large one pays at
        most twice that.
    """

    def __init__(self, name, interpreted_points):
        self.name, self.interpreted_points = name, interpreted_points
        self.computed = 0  # points computed interpreted so far

    def for_points(self, points):
        """The module for a call of ``points`` points: interpreted while numba has not loaded
        it and fewer than ``interpreted_points`` points have been computed so."""
        return self.compiled_for(points) or self.interpreted()

    def compiled_for(self, points):
        """The compiled module for a call of ``points`` points, or None while numba has not
        loaded it and fewer than ``interpreted_points`` points have been computed without it
        (counted here): for a model whose points are then computed another way, vectorised,
        with the same numbers."""
        if self.name in sys.modules or self.computed + points > self.interpreted_points:
            return importlib.import_module(self.name)
        self.computed += points
        return None

    def interpreted(self):
        """The module's source run by the interpreter, numba not imported."""
        package, _, module = self.name.rpartition(".")
        name = f"{package}._{module}_interpreted"
        if name not in sys.modules:
            spec = importlib.util.spec_from_file_location(
                name, importlib.util.find_spec(self.name).origin)
            loaded = importlib.util.module_from_spec(spec)
            loaded.INTERPRETED = True  # read by compiler(): no numba
            spec.loader.exec_module(loaded)
            sys.modules[name] = loaded
        return sys.modules[name]
