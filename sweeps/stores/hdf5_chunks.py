"""A netCDF result's chunks encoded where they are computed, the driver writing their bytes.

Each chunk of points fills one HDF5 chunk of every output stored per point and of ``status``
(``grid.block_shape`` along the grid's axes, then the output's own dimensions whole). The
process that computes a chunk (a dask worker, or the driver's own loop in-process) also
encodes it as the file stores it: the stored type and fill value, an edge block padded to the
whole HDF5 chunk with the fill value, HDF5's shuffle filter (the bytes of the values grouped by
significance), then its deflate filter (a zlib stream at the file's level: :func:`deflated`)
or the zstd plugin filter (a zstd frame, as netCDF-C's plugin writes it: ``ZSTD_compress``).
The driver writes those bytes into the file unchanged (h5py's direct chunk write: HDF5
neither decompresses nor compresses them): no per-value work in the driver, whose single core
otherwise compresses the whole sweep while the workers wait for it.

How each variable is stored is read from the file netCDF4 has just created (its type, byte
order, chunk shape, filters and fill value: :func:`layouts`), so that the bytes are what HDF5
itself would have written. netCDF4 and h5py each bundle their own HDF5 library: the file is
never open in both at once (:func:`.netcdf.result_file`). A grid of one point is written through
netCDF4 (its variables are not chunked).

An interrupted run keeps each chunk as the worker returned it (:class:`EncodedParts`); the
manifest names the storage and the outputs' declaration they were encoded for
(:func:`parts_hold`), so that a run storing otherwise computes them again rather than write
them as they are.
"""
from __future__ import annotations

import hashlib
import time
import zlib
from dataclasses import dataclass

import numpy as np
from isal import isal_zlib

from ..dependence import reduced_outputs, split_reduced, stored_dims
from ..grid import Grid, block_shape
from ..interrupts import interruptions_raised
from .blocks import STATUS_CODES, chunk_tally, regions, stored_blocks
from .durable import closed_after, writing
from .resume import Parts, counts_damage, load_counts, saved_counts, status_damage

#: The compressions whose HDF5 filters :func:`encoded` applies, as ``storage.Storage`` and
#: netCDF4's ``Variable.filters()`` name them (HDF5's deflate, the zstd plugin, or none).
COMPRESSORS = ("zlib", "zstd")
DIRECT_COMPRESSIONS = ("none",) + COMPRESSORS
KNOWN_FILTERS = COMPRESSORS + ("shuffle", "complevel")
#: How long [s] an opening of the file just closed is retried. A process the cluster starts
#: meanwhile (from another thread) holds a copy of every open file until it runs its own
#: program, and with it HDF5's lock on the file: a moment, longer on a busy machine.
REOPEN_SECONDS = 5.0


def writes_directly(storage, grid: Grid) -> bool:
    """Whether a netCDF result of ``grid`` stored as ``storage`` (``storage.Storage``) has its
    chunks encoded by the workers: in a compression encoded here, on a grid with axes."""
    return storage.compression in DIRECT_COMPRESSIONS and bool(grid.shape)


def parts_hold(direct: bool, storage, grid: Grid) -> str:
    """What the parts of an interrupted netCDF run hold, for their manifest: chunks encoded
    for ``storage``, and for the variables the model's declaration gives (which outputs are
    stored per point, on which dimensions, as integers or not: a digest), are not another
    storage's nor another declaration's, even under the same model version."""
    if not direct:
        return "arrays"
    declared = [(o.name, stored_dims(grid, o) + o.dims, o.dtype) for o in grid.model.outputs]
    digest = hashlib.sha256(repr(declared).encode()).hexdigest()[:16]
    return f"hdf5 chunks, {storage.text()}, outputs {digest}"


@dataclass(frozen=True)
class Layout:
    """How one variable's HDF5 chunks are stored: the numpy type (with its byte order), the
    chunk's shape, the fill value beyond the grid's edge, and the filters: shuffle, and the
    ``compressor`` (one of ``COMPRESSORS``, or None) at ``level``."""

    dtype: str
    chunk: tuple
    fill: float | int
    shuffle: bool
    compressor: str | None
    level: int


def layouts(target, names) -> dict[str, Layout]:
    """The :class:`Layout` of each variable ``names`` of the open netCDF4.Dataset ``target``;
    ``ValueError`` for one whose chunks :func:`encoded` cannot make (contiguous, or another
    filter)."""
    import netCDF4

    found = {}
    for name in names:
        variable = target.variables[name]
        filters = variable.filters() or {}
        other = sorted(key for key, on in filters.items() if on and key not in KNOWN_FILTERS)
        chunking = variable.chunking()
        if other or chunking == "contiguous":
            raise ValueError(f"{name}: stored {' '.join(other) or 'contiguous'}, its chunks "
                             "cannot be written directly")
        order = {"native": "=", "little": "<", "big": ">"}[variable.endian()]
        fill = (variable.getncattr("_FillValue") if "_FillValue" in variable.ncattrs()
                else netCDF4.default_fillvals[variable.dtype.str[1:]])
        compressor = next((one for one in COMPRESSORS if filters.get(one)), None)
        found[name] = Layout(variable.dtype.newbyteorder(order).str, tuple(chunking),
                             np.asarray(fill).item(), bool(filters.get("shuffle")),
                             compressor, int(filters.get("complevel", 0)))
    return found


def encoded(values: np.ndarray, layout: Layout) -> bytes:
    """The bytes of an HDF5 chunk holding ``values`` (its first indices; the rest of the chunk
    the fill value) as stored with ``layout``: what HDF5's filters would write (a value
    beyond float32's range infinite, without numpy's warning)."""
    with np.errstate(over="ignore"):
        if values.shape == layout.chunk:
            data = np.ascontiguousarray(values, dtype=layout.dtype)
        else:  # an edge block: the part of the chunk beyond the grid is never read
            data = np.full(layout.chunk, layout.fill, dtype=layout.dtype)
            data[tuple(slice(0, n) for n in values.shape)] = values
    size = data.dtype.itemsize
    if layout.shuffle and size > 1:  # byte 0 of every value, then byte 1, ...
        data = data.reshape(-1).view(np.uint8).reshape(-1, size).T.copy()
    if layout.compressor == "zlib":
        return deflated(data, layout.level)
    if layout.compressor == "zstd":  # one frame, its size in its header, as ZSTD_compress
        import numcodecs

        return numcodecs.Zstd(level=layout.level).encode(data)
    return data.tobytes()


def deflated(data, level: int) -> bytes:
    """``data`` as a zlib stream (HDF5's deflate filter) at zlib's ``level``: the fastest,
    1, by ISA-L's deflate (several times zlib's speed, its streams as small), the others by
    zlib's own."""
    if level == 1:
        return isal_zlib.compress(data, 1)
    return zlib.compress(data, level)


@dataclass(frozen=True)
class ChunkEncoder:
    """Encodes a computed chunk as the file stores it (small: it travels with every task to
    the process that computes the chunk); ``layouts``: by variable name, from :func:`layouts`."""

    layouts: dict

    def write(self, grid: Grid, start: int, stop: int, part: dict) -> dict:
        """Points ``start..stop-1`` (a computed ``part``, as ``evaluate.evaluate_chunk`` returns
        it) as the driver writes them: ``{"chunks": {name: (offset, bytes)}, "firsts":
        {name: (points, values)}, "tally": dict}``, one HDF5 chunk per variable at ``offset``
        (its first index on each dimension), the :func:`dependence.first_held` values of the
        outputs stored on fewer dimensions, and the chunk's counts (:func:`.blocks.chunk_tally`)."""
        firsts, per_point = split_reduced(grid, start, stop, part)
        tally, chunks = chunk_tally(grid.model, part), {}
        for name, index, block in stored_blocks(grid, start, stop, per_point, part["status"]):
            layout = self.layouts[name]
            if name in chunks or any(s.start % c for s, c in zip(index, layout.chunk)):
                raise ValueError(f"points {start}..{stop - 1} are not one block of the grid")
            offset = tuple(s.start for s in index) + (0,) * (len(layout.chunk) - len(index))
            chunks[name] = (offset, encoded(block, layout))
        return {"chunks": chunks, "firsts": firsts, "tally": tally}


def reopened(open_file):
    """``open_file()`` (the file closed a moment ago, opened again), retried for
    ``REOPEN_SECONDS`` while it fails (HDF5 finds the file locked)."""
    deadline = time.monotonic() + REOPEN_SECONDS
    while True:
        try:
            with interruptions_raised():
                return open_file()
        except OSError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.01)


class DirectWriter:
    """Writes encoded chunks (:meth:`ChunkEncoder.write`) into the file at ``path``, opened
    with h5py; the values of the outputs stored on fewer dimensions and the model's errors go
    to ``writer`` (the ``netcdf.ChunkWriter`` that wrote the file's structure), for its
    ``finish``."""

    def __init__(self, path, encoder: ChunkEncoder, writer):
        import h5py

        self.encoder, self.writer = encoder, writer
        with writing(writer.output):
            self.file = reopened(lambda: h5py.File(path, "r+"))

    def __enter__(self):
        self.closing = closed_after(self.file, self.writer.output)
        self.closing.__enter__()
        return self

    def __exit__(self, *exc):
        return self.closing.__exit__(*exc)

    def write(self, start: int, stop: int, part: dict):
        """Write one chunk of points ``start..stop-1``: the bytes as they are."""
        self.writer.errors.update(part["tally"]["errors"])
        for name, (points, values) in part["firsts"].items():
            self.writer.reduced[name].add_firsts(points, values)
        for name, (offset, data) in part["chunks"].items():
            with writing(self.writer.output):
                self.file[name].id.write_direct_chunk(tuple(int(i) for i in offset), data)


class EncodedParts(Parts):
    """The parts of an interrupted netCDF run whose chunks are encoded by the workers: each
    chunk's :meth:`ChunkEncoder.write` result and counts (``blocks.chunk_tally``), as the
    driver writes them. The interface of :class:`.resume.Parts`; what a part says of itself is
    checked against its grid and storage (:meth:`damage`)."""

    def arrays(self, result: dict) -> dict:
        arrays = saved_counts(result)
        for name, (offset, data) in result["chunks"].items():
            arrays[f"offset_{name}"] = np.array(offset, dtype=np.int64)
            arrays[f"chunk_{name}"] = np.frombuffer(data, dtype=np.uint8)
        return arrays

    def read(self, data) -> dict:
        tally, firsts = load_counts(data)
        chunks = {key[len("chunk_"):]: (tuple(data["offset_" + key[len("chunk_"):]].tolist()),
                                        data[key].tobytes())
                  for key in data.files if key.startswith("chunk_")}
        return {"chunks": chunks, "tally": tally, "firsts": firsts}

    def damage(self, data, start: int, stop: int) -> str | None:
        """:func:`.resume.counts_damage`, then: an HDF5 chunk for each variable the file
        stores per point, each at the block of points ``start..stop-1``, and statuses that
        are the counts' (the status chunk decoded: one byte a point)."""
        reason = counts_damage(data, self.grid, start, stop)
        if reason or self.grid is None:
            return reason
        reduced = {o.name for o in reduced_outputs(self.grid)}
        expected = sorted([o.name for o in self.grid.model.outputs if o.name not in reduced]
                          + ["status"])
        found = sorted(key[len("chunk_"):] for key in data.files if key.startswith("chunk_"))
        if found != expected:
            return f"chunks of {found}, not of {expected}"
        (index, _, _), = regions(self.grid.shape, start, stop)
        for name in found:
            offset = tuple(data[f"offset_{name}"].tolist())
            if offset[:len(index)] != tuple(s.start for s in index) or any(offset[len(index):]):
                return f"its chunk of {name} at {offset}, not at the block of its points"
        status = decoded_status(data["chunk_status"].tobytes(), self.storage.compression,
                                block_shape(self.grid.shape, self.size),
                                tuple(s.stop - s.start for s in index))
        reason = status_damage(status, stop - start)
        if reason:
            return reason
        counts = np.bincount(status, minlength=STATUS_CODES).tolist()
        return None if counts == load_counts(data)[0]["status"] else \
            "counts that are not those of its statuses"


def decoded_status(data: bytes, compression: str, chunk: tuple, block: tuple) -> np.ndarray:
    """The statuses of a block of points (``block``: its shape) from the bytes of the HDF5
    chunk (of shape ``chunk``) that :func:`encoded` made of them (one byte each: shuffle
    leaves them as they are); ``ValueError`` for bytes that do not decode to it."""
    try:
        if compression == "zlib":
            data = zlib.decompress(data)
        elif compression == "zstd":
            import numcodecs

            data = bytes(numcodecs.Zstd().decode(data))
    except (zlib.error, RuntimeError) as error:
        raise ValueError(f"its status chunk does not decode ({error})") from None
    values = np.frombuffer(data, dtype=np.int8)
    if values.size != int(np.prod(chunk)):
        raise ValueError(f"{values.size} bytes of status, not {int(np.prod(chunk))}")
    return values.reshape(chunk)[tuple(slice(0, n) for n in block)].ravel()
