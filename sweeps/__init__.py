"""Parametric studies of rolling bearings: definition -> grid -> dask map -> labelled dataset.

The Python API (:mod:`bearing_sweep.api`): :func:`run`, :func:`check`, :func:`analyze` (of
a sampled result), :func:`list_models`, :func:`describe`, and :func:`plot` (:mod:`bearing_sweep.quicklook`) for a quick look at a
result; every mistake in what is asked is a :class:`SpecError`. The model functions are in
:mod:`bearing_sweep.models`.
"""
import sys

#: Where each name of the API lives: imported when first asked for, since xarray (the API's)
#: and matplotlib (plot's) cost more to import than a small sweep takes to run, and pint
#: (the definitions') a good part of what the program takes to start.
_LAZY = {"run": "api", "check": "api", "analyze": "api", "list_models": "api",
         "describe": "api", "plot": "quicklook", "SpecError": "spec"}


def program(argv=None) -> int:
    """The ``bearing-sweep`` command (:func:`bearing_sweep.cli.program`), imported here so that
    a Ctrl-C while its modules load is one line and exit 130, as one at any later moment."""
    try:
        from .cli import program as command
    except KeyboardInterrupt:
        print("interrupted while starting: nothing was done", file=sys.stderr)
        return 130
    return command(argv)


def __getattr__(name):
    if name in _LAZY:
        from importlib import import_module
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(__all__)


__all__ = ["run", "check", "analyze", "list_models", "describe", "plot", "SpecError"]
