"""A result's structure as both stores write it: the labelled dataset with placeholders for
the values (:func:`structure`), its provenance (package version, git commit), and what xarray
does on writing it that matters here, without xarray (``xarray.conventions``): a float
variable without a ``_FillValue`` in its encoding gets NaN as its fill value, the values are
stored in the encoding's ``dtype``, and coordinates that are not dimensions are listed in the
``coordinates`` attribute of each variable that spans their dimensions (the others in a
global ``coordinates`` attribute). Importing xarray (and the dask.array xarray imports as soon
as it makes a variable) costs more than a small sweep computes.
"""
from __future__ import annotations

import subprocess
from functools import lru_cache
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import numpy as np

from ..grid import Grid
from ..labels import labelled
from ..spec import Sweep
from .blocks import flat_shape



def stored_as(values: np.ndarray, encoding: dict) -> tuple:
    """The type a variable's ``values`` are stored in and their fill value (None: none), as
    xarray stores them: the ``encoding``'s ``dtype`` and ``_FillValue``, and NaN for
    floating-point values without one."""
    stored = np.dtype(encoding.get("dtype", values.dtype))
    if "_FillValue" in encoding:
        fill = encoding["_FillValue"]
    else:
        fill = np.nan if stored.kind == "f" else None
    return stored, None if fill is None else stored.type(fill)


def global_attributes(labelled) -> dict:
    """``labelled``'s global attributes, in their order, with xarray's global
    ``coordinates`` where a coordinate spans no variable."""
    attributes = dict(labelled.attrs)
    unlisted = _non_dimension_coordinates(labelled) - {
        name for text in coordinate_lists(labelled).values() for name in text.split()}
    if unlisted:
        attributes["coordinates"] = " ".join(sorted(unlisted))
    return attributes


def coordinate_lists(labelled) -> dict:
    """The ``coordinates`` attribute of each variable that has one: the coordinates that are
    not dimensions and span some of its dimensions (CF's auxiliary coordinates), sorted."""
    variables = {**labelled.data_vars, **labelled.coords}
    auxiliary = _non_dimension_coordinates(labelled)
    lists = {}
    for name, (dims, _, _) in variables.items():
        if name in auxiliary or name in dims:
            continue
        spanned = sorted(c for c in auxiliary if set(labelled.coords[c][0]) <= set(dims))
        if spanned:
            lists[name] = " ".join(spanned)
    return lists


def _non_dimension_coordinates(labelled) -> set:
    dimensions = {d for dims, _, _ in {**labelled.data_vars, **labelled.coords}.values()
                  for d in dims}
    return set(labelled.coords) - dimensions


@lru_cache(maxsize=1)  # asked for every chunk: the code a process runs does not change
def package_version() -> str:
    try:
        return version("bearing-sweep")
    except PackageNotFoundError:
        return "unknown"


def git_commit() -> str | None:
    """The project's commit (``-dirty`` when it has uncommitted changes), if it is a checkout."""
    root = Path(__file__).resolve().parents[2]
    try:  # one git process: the branch header names the commit, every other line a change
        lines = subprocess.run(["git", "-C", str(root), "status", "--porcelain=v2", "--branch",
                                "--untracked-files=no"], capture_output=True, text=True,
                               timeout=10, check=True).stdout.splitlines()
    except (OSError, subprocess.SubprocessError):
        return None
    commit = next((line.split()[2] for line in lines if line.startswith("# branch.oid ")), None)
    if commit is None or commit == "(initial)":  # a repository without a commit yet
        return None
    dirty = any(not line.startswith("#") for line in lines)
    return commit + ("-dirty" if dirty else "")


def provenance(scheduler: str) -> dict:
    """How a dataset was made, for its global attributes (:func:`labels.labelled_dataset`)."""
    return {"scheduler": scheduler, "package_version": package_version(),
            "git_commit": git_commit()}


def structure(sweep: Sweep, grid: Grid, provenance: dict, errors=()):
    """The sweep's labelled dataset (:func:`labels.labelled`) with placeholders for the
    outputs' and the status' values, which are never written: a result's structure."""
    placeholders = {o.name: np.broadcast_to(np.nan, flat_shape(grid, o))
                    for o in grid.model.outputs}
    status = np.broadcast_to(np.int8(0), (grid.size,))
    return labelled(sweep, grid, placeholders, status, provenance, errors)

