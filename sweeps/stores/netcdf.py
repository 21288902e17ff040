"""A sweep's result as one netCDF file, written as its chunks arrive and renamed into place
once complete (:class:`NetcdfStore`); any dataset written so (:func:`write_netcdf`).

The file's structure (coordinates, attributes, empty variables, each stored as the sweep's
``[output]`` says) is written at once, each chunk's values into their regions as they arrive
(one chunk in memory at a time, while the others compute): either by netCDF4 here, or encoded
by the worker that computed them and written as bytes (:mod:`.hdf5_chunks`). Finished chunks
are kept beside the output until the file is in place (:mod:`.resume`), so that an interrupted
run resumes.
"""
from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..dependence import reductions
from ..duty_cycle import cycle_names, stored_cycle
from ..grid import Grid, block_shape
from ..spec import Sweep
from . import hdf5_chunks
from .base import FileStore
from .blocks import chunk_tally, per_point_outputs, stored_blocks, stored_reduction
from .durable import OutputLock, closed_after, writing, written_atomically
from .resume import Parts
from .structure import coordinate_lists, global_attributes, provenance, stored_as, structure

if TYPE_CHECKING:  # xarray only where a dataset is made or read: a run writes without it
    import xarray as xr


class NetcdfStore(FileStore):
    """A result written as one netCDF file at ``output``; its finished chunks kept beside it
    (:class:`.resume.Parts`, or :class:`.hdf5_chunks.EncodedParts` where the workers encode
    them) until the file is in place."""

    direct = False

    def resume_state(self, key: dict):
        # A netCDF file's chunks encoded by the workers, the driver writing their bytes.
        self.direct = hdf5_chunks.writes_directly(self.sweep.storage, self.grid)
        key = {**key, "parts_hold": hdf5_chunks.parts_hold(self.direct, self.sweep.storage,
                                                           self.grid)}
        kind = hdf5_chunks.EncodedParts if self.direct else Parts
        return kind(self.output, key, self.grid, self.sweep.storage)

    @contextmanager
    def recording(self, chunk_size: int, scheduler: str, before_rename=None):
        with result_file(self.sweep, self.grid, self.output, provenance(scheduler),
                         chunk_size, self.direct, before_rename) as writer:
            self.writer = writer
            for start, stop in sorted(self.parts.finished()):  # an interrupted run's
                self._write(start, stop, self.parts.load(start, stop))
            # Each chunk encoded by the process that computes it, or its values sent here.
            yield writer.encoder if self.direct else None
            self.finishing()

    def record(self, start: int, stop: int, result: dict):
        self.parts.save(start, stop, result)
        self._write(start, stop, result)

    def _write(self, start: int, stop: int, part: dict):
        self.tallies.append(part["tally"] if self.direct
                            else chunk_tally(self.grid.model, part))
        self.writer.write(start, stop, part)

    def stored_bytes(self, result: dict) -> int | None:
        if not self.direct:
            return None
        return sum(len(data) for _, data in result["chunks"].values())


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
        write_structure(structure, target, {o.name for o in grid.model.outputs} | {"status"}
                        | set(cycle_names(sweep)))

    def _structure(self):
        return structure(self.sweep, self.grid, self.provenance, sorted(self.errors))

    def write(self, start: int, stop: int, part: dict):
        """Write the values of points ``start..stop-1`` (a computed ``part``); those of an
        output stored on fewer dimensions are gathered for :meth:`finish`."""
        self.errors.update(part["errors"])
        for name, index, block in stored_blocks(
                self.grid, start, stop, per_point_outputs(part, self.reduced, start, stop),
                part["status"]):
            with writing(self.output):
                self.target.variables[name][index or ...] = block
        with writing(self.output):
            self.target.sync()  # the HDF5 chunks this completed are compressed now

    def _stored(self, name: str) -> np.ndarray:
        """The values of variable ``name`` as the file holds them, NaN where it has none."""
        values = self.target.variables[name][...]
        return np.ma.filled(values, np.nan) if values.dtype.kind == "f" else np.asarray(values)

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
        with writing(self.output):
            for name, values in stored_cycle(self.sweep, self.grid, self._stored).items():
                self.target.variables[name][...] = values
        structure = self._structure()
        with writing(self.output):
            write_attributes(structure, self.target)


def write_netcdf(dataset: xr.Dataset, path) -> Path:
    """Write ``dataset`` to ``path`` atomically: an existing file at ``path`` stays intact
    until the new one is complete. The output's lock is held meanwhile (another run writing
    it is refused; the temporary files of a writer killed before are removed)."""
    with OutputLock(path), written_atomically(path) as temporary, writing(path):
        # As each variable's encoding says (a sweep's outputs: its [output] table).
        dataset.to_netcdf(temporary, engine="netcdf4")
    return Path(path)


#: The netCDF4 encodings a sweep's variables use, passed to ``createVariable`` as they are.
_FILTERS = ("compression", "complevel", "shuffle", "chunksizes")


def write_structure(labelled, target, placeholders=frozenset()):
    """Write ``labelled`` into the open, empty ``netCDF4.Dataset`` ``target``, the values of
    the variables named in ``placeholders`` aside: those are created empty, for their values
    to be written later (and the global attributes rewritten: :func:`write_attributes`)."""
    variables = {**labelled.data_vars, **labelled.coords}  # xarray's order
    sizes = {}
    for dims, values, _ in variables.values():
        for dim, size in zip(dims, np.shape(values)):
            sizes.setdefault(dim, size)
    for dim, size in sizes.items():
        target.createDimension(dim, size)
    listed = coordinate_lists(labelled)
    for name, (dims, values, attrs) in variables.items():
        encoding = labelled.encodings.get(name, {})
        values = np.asarray(values)
        stored, fill = stored_as(values, encoding)
        variable = target.createVariable(
            name, str if stored.kind in "OU" else stored, dims, fill_value=fill,
            **{key: encoding[key] for key in _FILTERS if key in encoding})
        attrs = dict(attrs)
        if name in listed:
            attrs["coordinates"] = listed[name]
        variable.setncatts(attrs)
        if name not in placeholders:
            variable[...] = values.astype(stored) if stored.kind != "U" else values
    write_attributes(labelled, target)


def write_attributes(labelled, target):
    """Set ``target``'s global attributes to ``labelled``'s (:func:`global_attributes`)."""
    for name in target.ncattrs():
        target.delncattr(name)
    for name, value in global_attributes(labelled).items():
        target.setncattr(name, value)

