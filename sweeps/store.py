"""A finished sweep's dataset from its chunks: written atomically as netCDF as the chunks arrive,
or gathered in memory; its provenance (package version, git commit)."""
from __future__ import annotations

import contextlib
import errno
import os
import re
import subprocess
from contextlib import contextmanager
from functools import lru_cache
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .models.registry import (OUTCOME_MASK, STATUS_MASKS, STATUS_MEANINGS, STATUS_VALUES,
                              VALIDITY_MASK)
from .dependence import reductions, stored_cells
from .grid import Grid, block_shape
from .interrupts import interruptions_raised
from .labels import labelled, labelled_dataset
from .netcdf_structure import write_attributes, write_structure
from .output_paths import is_zarr
from .parts import OutputLock, written_atomically
from .spec import Sweep
from .storage import integral_values

if TYPE_CHECKING:  # xarray only where a dataset is made or read: a run writes without it
    import xarray as xr


@lru_cache(maxsize=1)  # asked for every chunk: the code a process runs does not change
def package_version() -> str:
    try:
        return version("bearing-sweep")
    except PackageNotFoundError:
        return "unknown"


def git_commit() -> str | None:
    """The project's commit (``-dirty`` when it has uncommitted changes), if it is a checkout."""
    root = Path(__file__).resolve().parents[1]
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


#: How many status codes there are (the outcome and validity bits in every combination).
STATUS_CODES = (OUTCOME_MASK | VALIDITY_MASK) + 1


def chunk_tally(model, part: dict) -> dict:
    """What one computed chunk counts: points by status code, the model's error messages and the
    points where each output the model declares ``counted`` says so, as plain lists and
    numbers (:func:`summed` adds them up)."""
    noted = {}
    for output in (o for o in model.outputs if o.counted):
        text, where = output.counted
        noted[text] = noted.get(text, 0) + int(np.count_nonzero(where(part["outputs"][
            output.name])))
    return {"status": np.bincount(part["status"], minlength=STATUS_CODES).tolist(),
            "errors": sorted(set(part["errors"])), "noted": noted}


def summed(model, tallies) -> tuple[dict, list, dict]:
    """The sweep's count of points by status meaning (where each flag holds: the outcomes
    share the points out, ``out_of_validity`` counts the points outside validity whatever their
    outcome), the model's error messages and the counts of the outputs the model declares
    ``counted``, from its chunks' :func:`chunk_tally`."""
    counts = np.zeros(STATUS_CODES, dtype=np.int64)
    errors = set()
    noted = {o.counted[0]: 0 for o in model.outputs if o.counted}
    for one in tallies:
        counts += one["status"]
        errors.update(one["errors"])
        for text, count in one["noted"].items():
            noted[text] += count
    codes = np.arange(STATUS_CODES)
    by_meaning = {meaning: int(counts[(codes & mask) == value].sum())
                  for meaning, value, mask in zip(STATUS_MEANINGS, STATUS_VALUES, STATUS_MASKS)}
    return by_meaning, sorted(errors), noted


def gather(sweep: Sweep, grid: Grid, parts, chunks, scheduler: str, errors=()) -> xr.Dataset:
    """The sweep's labelled dataset in memory, from its chunks: the dataset
    :func:`result_file` writes (``errors``: the model's messages, from :func:`summed`)."""
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


@contextmanager
def result_file(sweep: Sweep, grid: Grid, path, provenance: dict, chunk_size: int,
                direct: bool = False, before_rename=None):
    """Write the sweep's netCDF file at ``path`` as its chunks (of ``chunk_size`` points)
    arrive; yields a :class:`ChunkWriter`, or with ``direct`` an
    :class:`hdf5_chunks.DirectWriter` of the chunks the workers encode (its ``encoder``).

    The file's structure (coordinates, attributes, empty variables, each stored as
    ``sweep.storage`` says) is written at once, each chunk's values into their regions as
    :meth:`ChunkWriter.write` receives them (one chunk in memory at a time, while the others
    compute), and when the block ends without an error the outputs that depend on fewer
    inputs than the grid (:mod:`dependence`, gathered from every chunk) and the global
    attributes are written and the file renamed into place: an existing file at ``path``
    stays intact until then. ``provenance``: as :func:`provenance` gives it.

    Each output stored per point is stored in HDF5 chunks of one sweep chunk's points (the
    block of the grid it fills, :func:`grid.block_shape`): every HDF5 chunk is complete when
    its sweep chunk arrives. ``direct``: each is encoded (compressed) by the worker and its
    bytes written as they are (:mod:`hdf5_chunks`), the file opened with h5py meanwhile and
    with netCDF4 again for :meth:`ChunkWriter.finish`; otherwise netCDF4 writes the values and
    the file is flushed after each sweep chunk, so that HDF5 compresses each chunk once.

    A failure of HDF5 or netCDF to write the file (a full disk) is an ``OSError`` naming
    ``path`` (:func:`writing`), never hidden by the file's failure to close after it.
    ``before_rename()``: called just before the complete file takes its name.
    """
    import netCDF4

    from . import hdf5_chunks

    with written_atomically(path, before_rename) as temporary:
        with writing(path):
            opened = netCDF4.Dataset(temporary, "w")
        with closed_after(opened, path) as target:
            writer = ChunkWriter(sweep, grid, target, provenance, chunk_size, path)
            if not direct:
                yield writer
                writer.finish()
                return
            names = [o.name for o in grid.model.outputs if o.name not in writer.reduced]
            encoder = hdf5_chunks.ChunkEncoder(hdf5_chunks.layouts(target, names + ["status"]))
        # Never open in netCDF4 and h5py at once: each has its own HDF5 library.
        with hdf5_chunks.DirectWriter(temporary, encoder, writer) as chunks:
            yield chunks
        with writing(path):
            opened = hdf5_chunks.reopened(lambda: netCDF4.Dataset(temporary, "a"))
        with closed_after(opened, path) as target:
            writer.reopen(target)
            writer.finish()


@contextmanager
def writing(output):
    """The block's failures of HDF5 or netCDF writing the file of ``output`` (``OSError``,
    ``RuntimeError``: a full disk, a file larger than the process may write) as one
    ``OSError`` naming ``output``, in the words of its errno where they give one; a Ctrl-C
    that the libraries turned into another exception stays one. A value beyond the range of
    the type it is stored in (float32) is stored as infinite, without numpy's warning."""
    try:
        with interruptions_raised(), np.errstate(over="ignore"):
            yield
    except (OSError, RuntimeError) as error:
        code = error.errno if isinstance(getattr(error, "errno", None), int) else None
        if not code or code < 0:  # netCDF's own codes are negative; HDF5 says it in words
            found = re.search(r"errno = (\d+)", str(error))
            code = int(found[1]) if found else None
        text = os.strerror(code) if code else (str(error).splitlines() or ["not written"])[0]
        raise OSError(code or errno.EIO, text, str(output)) from None


@contextmanager
def closed_after(opened, output):
    """``opened`` (a netCDF4 or h5py file) for the block, closed after it. A failure of the
    block is not hidden by the file's failure to close after it (HDF5 cannot flush to a full
    disk either); a failure to close it otherwise is one of :func:`writing`."""
    try:
        yield opened
    except BaseException:
        with contextlib.suppress(Exception):
            opened.close()
        raise
    with writing(output):
        opened.close()


class ChunkWriter:
    """Writes a sweep's chunks into the netCDF file :func:`result_file` opened."""

    def __init__(self, sweep: Sweep, grid: Grid, target, provenance: dict, chunk_size: int,
                 output=None):
        self.sweep, self.grid, self.target, self.provenance = sweep, grid, target, provenance
        self.output = output  # the result's path, for the message of a failure to write
        self.errors = set()
        self.reduced = reductions(grid)
        structure = self._structure()
        points = block_shape(grid.shape, chunk_size)
        for name in [o.name for o in grid.model.outputs if o.name not in self.reduced] + [
                "status"]:
            shape = np.shape(structure.data_vars[name][1])
            if shape:  # a scalar is stored whole, without chunks
                structure.encodings[name]["chunksizes"] = points + shape[len(grid.shape):]
        write_structure(structure, target, {o.name for o in grid.model.outputs} | {"status"})

    def _structure(self):
        return structure(self.sweep, self.grid, self.provenance, sorted(self.errors))

    def write(self, start: int, stop: int, part: dict):
        """Write the values of points ``start..stop-1`` (a computed ``part``); those of an
        output stored on fewer dimensions are gathered for :meth:`finish`."""
        self.errors.update(part["errors"])
        for name, index, block in stored_blocks(
                self.grid, start, stop, _per_point_outputs(part, self.reduced, start, stop),
                part["status"]):
            with writing(self.output):
                self.target.variables[name][index or ...] = block
        with writing(self.output):
            self.target.sync()  # the HDF5 chunks this completed are compressed now

    def reopen(self, target):
        """Go on with ``target``, the file opened again (its chunks written meanwhile)."""
        self.target = target

    def finish(self):
        """Write the outputs stored on fewer dimensions, and the global attributes of the
        finished sweep (its time, the model's errors)."""
        for name, reduction in self.reduced.items():
            values = stored_reduction(reduction, reduction.output.dtype == "int")
            with writing(self.output):
                self.target.variables[name][...] = values
        structure = self._structure()
        with writing(self.output):
            write_attributes(structure, self.target)


def structure(sweep: Sweep, grid: Grid, provenance: dict, errors=()):
    """The sweep's labelled dataset (:func:`labels.labelled`) with placeholders for the
    outputs' and the status' values, which are never written: a result's structure."""
    placeholders = {o.name: np.broadcast_to(np.nan, _flat_shape(grid, o))
                    for o in grid.model.outputs}
    status = np.broadcast_to(np.int8(0), (grid.size,))
    return labelled(sweep, grid, placeholders, status, provenance, errors)


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
    until the new one is complete. The output's lock is held meanwhile (another run writing
    it is refused; the temporary files of a writer killed before are removed)."""
    with OutputLock(path), written_atomically(path) as temporary, writing(path):
        # As each variable's encoding says (a sweep's outputs: its [output] table).
        dataset.to_netcdf(temporary, engine="netcdf4")
    return Path(path)


def open_result(path) -> xr.Dataset:
    """Open a sweep's netCDF file (or zarr store) fully into memory (it is closed afterwards)."""
    import xarray as xr

    with xr.open_dataset(path, engine=result_engine(path)) as dataset:
        return dataset.load()


def is_result(path) -> bool:
    """Whether ``path`` holds something to open as a result: a file, or a zarr store (a
    folder); :func:`open_result` says whether it is one."""
    return os.path.isfile(path) or (is_zarr(path) and os.path.isdir(path))


def result_engine(path) -> str:
    """xarray's engine for a sweep's result at ``path``: zarr for a ``.zarr`` store."""
    return "zarr" if is_zarr(path) else "netcdf4"
