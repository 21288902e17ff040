"""Parametric studies of rolling bearings: definition -> grid -> dask map -> labelled dataset.

The Python API (:mod:`bearing_sweep.api`): :func:`run`, :func:`check`, :func:`analyze` (of
a sampled result), :func:`list_models`, :func:`describe`, and :func:`plot` (:mod:`bearing_sweep.quicklook`) for a quick look at a
result; every mistake in what is asked is a :class:`SpecError`. The model functions are in
:mod:`bearing_sweep.models`.
"""
from .api import analyze, check, describe, list_models, run
from .spec import SpecError


def __getattr__(name):
    # matplotlib costs a third of a second to import: only for who plots.
    if name == "plot":
        from .quicklook import plot
        return plot
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = ["run", "check", "analyze", "list_models", "describe", "plot", "SpecError"]
