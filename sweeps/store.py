"""A finished sweep's dataset from its chunks: written atomically as netCDF one chunk at a time,
or gathered in memory; its provenance (package version, git commit)."""
from __future__ import annotations

import os
import subprocess
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import numpy as np
import xarray as xr

from .models.registry import STATUS_MEANINGS
from .dependence import reductions, stored_cells
from .grid import Grid
from .labels import labelled_dataset
from .parts import is_zarr, written_atomically
from .spec import Sweep
from .storage import integral_values


def package_version() -> str:
    try:
        return version("bearing-sweep")
    except PackageNotFoundError:
        return "unknown"


def git_commit() -> str | None:
    """The project's commit (``-dirty`` when it has uncommitted changes), if it is a checkout."""
    root = Path(__file__).resolve().parents[1]
    try:
        commit = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True,
                                text=True, timeout=10, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain",
                                "--untracked-files=no"], capture_output=True, text=True,
                               timeout=10, check=True).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return None
    return commit + ("-dirty" if dirty else "")


def provenance(scheduler: str) -> dict:
    """How a dataset was made, for its global attributes (:func:`labels.labelled_dataset`)."""
    return {"scheduler": scheduler, "package_version": package_version(),
            "git_commit": git_commit()}


def tally(grid: Grid, parts, chunks) -> tuple[dict, list, dict]:
    """The count of points by status, the model's error messages and the counts of the
    outputs the model declares ``counted``, read one chunk at a time."""
    return summed(grid.model, (chunk_tally(grid.model, parts.load(start, stop))
                               for start, stop in chunks))


def chunk_tally(model, part: dict) -> dict:
    """What :func:`tally` counts in one computed chunk, as JSON-ready lists and numbers (a
    zarr output keeps it, not the values, for each finished chunk)."""
    noted = {}
    for output in (o for o in model.outputs if o.counted):
        text, where = output.counted
        found = int(np.count_nonzero(where(part["outputs"][output.name])))
        noted[text] = noted.get(text, 0) + found
    return {"status": np.bincount(part["status"], minlength=len(STATUS_MEANINGS)).tolist(),
            "errors": sorted(set(part["errors"])), "noted": noted}


def summed(model, tallies) -> tuple[dict, list, dict]:
    """The sweep's counts (as :func:`tally` returns them) from its chunks' :func:`chunk_tally`."""
    counts = np.zeros(len(STATUS_MEANINGS), dtype=np.int64)
    errors = set()
    noted = {o.counted[0]: 0 for o in model.outputs if o.counted}
    for one in tallies:
        counts += one["status"]
        errors.update(one["errors"])
        for text, count in one["noted"].items():
            noted[text] += count
    return dict(zip(STATUS_MEANINGS, counts.tolist())), sorted(errors), noted


def gather(sweep: Sweep, grid: Grid, parts, chunks, scheduler: str, errors=()) -> xr.Dataset:
    """The sweep's labelled dataset in memory, from its chunks: the dataset :func:`assemble`
    writes (``errors``: the model's messages, from :func:`tally`)."""
    reduced = reductions(grid)
    outputs = {o.name: np.full(_flat_shape(grid, o), np.nan) for o in grid.model.outputs
               if o.name not in reduced}
    status = np.zeros(grid.size, dtype=np.int8)
    for start, stop in chunks:
        part = parts.load(start, stop)
        for name, values in _per_point_outputs(part, reduced, start, stop).items():
            outputs[name][start:stop] = values
        status[start:stop] = part["status"]
    outputs.update({name: reduction.values for name, reduction in reduced.items()})
    return labelled_dataset(sweep, grid, outputs, status, provenance(scheduler), errors)


def assemble(sweep: Sweep, grid: Grid, parts, chunks, path, scheduler: str, errors=()):
    """Write the sweep's dataset from its chunks, one chunk in memory at a time.

    The file's structure (coordinates, attributes, empty variables, each stored as
    ``sweep.storage`` says) is written by xarray, the chunks' values then into it, region by
    region, and the finished file renamed into place: an existing file at ``path`` stays
    intact until then. ``errors``: the model's messages, from :func:`tally`. An output that
    depends on fewer inputs than the grid (:mod:`dependence`) is gathered from every chunk and
    written last.
    """
    import dask.array
    import netCDF4

    lazy = {o.name: dask.array.full(_flat_shape(grid, o), np.nan, chunks=-1)  # never computed
            for o in grid.model.outputs}
    status = dask.array.zeros(grid.size, dtype=np.int8, chunks=-1)
    skeleton = labelled_dataset(sweep, grid, lazy, status, provenance(scheduler), errors)
    with written_atomically(path) as temporary:
        # The structure only: dump_to_store queues the lazy values for a write that is never
        # made (the parts fill them in below), and closing the store closes the file.
        skeleton_store = xr.backends.NetCDF4DataStore.open(temporary, mode="w")
        try:
            skeleton.dump_to_store(skeleton_store)
        finally:
            skeleton_store.close()
        del skeleton
        integral = {o.name for o in grid.model.outputs if o.dtype == "int"}
        reduced = reductions(grid)
        with netCDF4.Dataset(temporary, "r+") as target:
            for start, stop in chunks:
                part = parts.load(start, stop)
                for name, index, block in stored_blocks(
                        grid, start, stop, _per_point_outputs(part, reduced, start, stop),
                        part["status"]):
                    target.variables[name][index or ...] = block
            for name, reduction in reduced.items():
                target.variables[name][...] = stored_reduction(reduction, name in integral)


def stored_blocks(grid: Grid, start: int, stop: int, outputs: dict, status: np.ndarray):
    """The values of points ``start..stop-1`` as a result stores them: the ``outputs`` stored
    per point (integral ones as integers) and the ``status``. Yields ``(name, index, block)``:
    a tuple of slices of the grid's dimensions and the variable's values there (empty for a
    grid of one point: index with ``...``)."""
    integral = {o.name for o in grid.model.outputs if o.dtype == "int"}
    values = {name: integral_values(data, name) if name in integral else data
              for name, data in outputs.items()}
    values["status"] = status
    for name, data in values.items():
        for index, low, high in _regions(grid.shape, start, stop):
            block = data[low - start:high - start]
            yield name, index, block.reshape(tuple(s.stop - s.start for s in index)
                                             + block.shape[1:])


def stored_reduction(reduction, integral: bool) -> np.ndarray:
    """The values of an output stored on fewer dimensions (a :class:`dependence.Reduction`
    holding every chunk's), as a result stores them: on its dimensions, as integers if
    ``integral``."""
    data = reduction.values
    data = integral_values(data, reduction.output.name) if integral else data
    return data.reshape(reduction.shape + data.shape[1:])


def _per_point_outputs(part: dict, reduced: dict, start: int, stop: int) -> dict:
    """A chunk's outputs stored per point; those stored on fewer dimensions (``reduced``, by
    name) are handed to their :class:`dependence.Reduction` instead."""
    for name, reduction in reduced.items():
        reduction.add(start, stop, part["outputs"][name], part["status"])
    return {name: values for name, values in part["outputs"].items() if name not in reduced}


def _flat_shape(grid: Grid, output) -> tuple:
    """An output's shape with the grid's cells it is stored on flat (every point, or fewer:
    :func:`dependence.stored_dims`), then its own dimensions."""
    return (stored_cells(grid, output),) + tuple(grid.dim_sizes[d] for d in output.dims)


def _regions(shape: tuple, start: int, stop: int, offset: int = 0):
    """Split points ``start..stop-1`` of a C-ordered grid into rectangular regions.

    Yields ``(index, low, high)``: a tuple of slices (one per axis) and the range of point
    numbers it holds, in order; at most two regions per axis.
    """
    if start >= stop:
        return
    if not shape:
        yield (), offset + start, offset + stop
        return
    inner = int(np.prod(shape[1:], dtype=np.int64))
    first, head = divmod(start, inner)
    last, tail = divmod(stop, inner)
    if first == last:
        for index, low, high in _regions(shape[1:], head, tail, offset + first * inner):
            yield (slice(first, first + 1),) + index, low, high
        return
    if head:
        for index, low, high in _regions(shape[1:], head, inner, offset + first * inner):
            yield (slice(first, first + 1),) + index, low, high
        first += 1
    if last > first:
        yield ((slice(first, last),) + tuple(slice(0, n) for n in shape[1:]),
               offset + first * inner, offset + last * inner)
    if tail:
        for index, low, high in _regions(shape[1:], 0, tail, offset + last * inner):
            yield (slice(last, last + 1),) + index, low, high


def write_netcdf(dataset: xr.Dataset, path) -> Path:
    """Write ``dataset`` to ``path`` atomically: an existing file at ``path`` stays intact
    until the new one is complete."""
    with written_atomically(path) as temporary:
        # As each variable's encoding says (a sweep's outputs: its [output] table).
        dataset.to_netcdf(temporary, engine="netcdf4")
    return Path(path)


def open_result(path) -> xr.Dataset:
    """Open a sweep's netCDF file (or zarr store) fully into memory (it is closed afterwards)."""
    with xr.open_dataset(path, engine=result_engine(path)) as dataset:
        return dataset.load()


def is_result(path) -> bool:
    """Whether ``path`` holds something to open as a result: a file, or a zarr store (a
    folder); :func:`open_result` says whether it is one."""
    return os.path.isfile(path) or (is_zarr(path) and os.path.isdir(path))


def result_engine(path) -> str:
    """xarray's engine for a sweep's result at ``path``: zarr for a ``.zarr`` store."""
    return "zarr" if is_zarr(path) else "netcdf4"
