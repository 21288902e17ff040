"""Parametric studies of rolling bearings: definition -> grid -> dask map -> labelled dataset.

The Python API (:mod:`bearing_sweep.api`): :func:`run`, :func:`check`, :func:`analyze` (of
a sampled result), :func:`list_models`, :func:`describe`, and :func:`plot` (:mod:`bearing_sweep.quicklook`) for a quick look at a
result; every mistake in what is asked is a :class:`SpecError`. The model functions are in
:mod:`bearing_sweep.models`.
"""
import sys
from typing import TYPE_CHECKING

#: Where each name of the API lives: imported when first asked for, since xarray (the API's)
#: and matplotlib (plot's) cost more to import than a small sweep takes to run, and pint
#: (the definitions') a good part of what the program takes to start.
_LAZY = {"run": "api", "check": "api", "analyze": "api", "list_models": "api",
         "describe": "api", "plot": "quicklook", "explore": "explorer", "SpecError": "spec"}


def program(argv=None) -> int:
    """The ``bearing-sweep`` command (:func:`bearing_sweep.cli.program`), imported here so that
    a Ctrl-C while its modules load is one line and exit 130, as one at any later moment.

    An interrupt that lands in a callback Python cannot raise from (importlib's module locks
    and weak references' callbacks call them while modules load) would be printed as
    "Exception ignored" and dropped, the program going on: for the program's lifetime such
    an interrupt is signalled again a moment later, from another thread, to be raised where
    the main thread runs by then (should that be such a callback again, the same follows)."""
    previous = sys.unraisablehook

    def raise_again(unraisable):
        if isinstance(unraisable.exc_value, KeyboardInterrupt):
            import signal
            import threading
            terminated = type(unraisable.exc_value).__name__ == "Terminated"
            signum = signal.SIGTERM if terminated else signal.SIGINT
            if hasattr(signal, "pthread_kill"):  # a real signal: it also ends a wait
                again = threading.Timer(0.01, signal.pthread_kill,
                                        (threading.main_thread().ident, signum))
            else:
                import _thread
                again = threading.Timer(0.01, _thread.interrupt_main, (signum,))
            again.daemon = True
            again.start()
        else:
            previous(unraisable)

    sys.unraisablehook = raise_again
    try:
        try:
            from .interrupts import interruptions_raised
            # An interrupt that lands where Python wraps it in another error (a class's
            # __set_name__, while a module loads) is raised as itself.
            with interruptions_raised():
                from .cli import program as command
        except KeyboardInterrupt:
            print("interrupted while starting: nothing was done", file=sys.stderr)
            return 130
        return command(argv)
    finally:
        sys.unraisablehook = previous


def __getattr__(name):
    if name == "__version__":  # the installed distribution's, as every result records it
        from .stores.structure import package_version
        return package_version()
    if name in _LAZY:
        from importlib import import_module
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(__all__)


__all__ = ["run", "check", "analyze", "list_models", "describe", "plot", "explore", "SpecError",
           "__version__"]

if TYPE_CHECKING:  # what type checkers and editors see of the names imported when asked for
    from .api import analyze, check, describe, list_models, run
    from .explorer import explore
    from .quicklook import plot
    from .spec import SpecError

    __version__: str
