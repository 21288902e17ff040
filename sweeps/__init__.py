"""Parametric studies of rolling bearings: definition -> grid -> dask map -> labelled dataset.

The Python API (:mod:`bearing_sweep.api`): :func:`run`, :func:`check`, :func:`analyze` (of
a sampled result), :func:`list_models`, :func:`describe`, and :func:`plot` (:mod:`bearing_sweep.quicklook`) for a quick look at a
result; every mistake in what is asked is a :class:`SpecError`. The model functions are in
:mod:`bearing_sweep.models`.
"""
from .spec import SpecError

#: Where each name of the API lives: imported when first asked for, since xarray (the API's)
#: and matplotlib (plot's) cost more to import than a small sweep takes to run.
_LAZY = {"run": "api", "check": "api", "analyze": "api", "list_models": "api",
         "describe": "api", "plot": "quicklook"}


def __getattr__(name):
    if name in _LAZY:
        from importlib import import_module
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(__all__)


__all__ = ["run", "check", "analyze", "list_models", "describe", "plot", "SpecError"]
