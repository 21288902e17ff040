"""A sweep's result as a zarr store, each chunk written by the process that computed it.

With ``-o result.zarr`` no values pass through the process that runs the sweep: it writes the
store's structure (coordinates, attributes, the outputs without values), and every task
computes its chunk of points and writes it into its own region of the store, returning only
its counts. The store is zarr format 2 (read by zarr-python 2 and 3 and by netCDF-C's NCZarr;
its compressors, numcodecs' Zlib and Zstd, are the netCDF file's: ``storage.Storage``), on a
filesystem every worker shares with the driver.

The zarr chunks along the grid's axes are the sweep's chunks (:func:`grid.block_shape`): a chunk of
points fills one whole zarr chunk of every output, so no two tasks ever write one zarr chunk
(a zarr chunk is written whole: two writers of one would lose the values of one of them). An
output stored on fewer axes (``dependence``) is the exception: each task returns one value per
cell of those axes, and the driver writes them once every chunk has given its own.

Until the sweep is complete the store lives in ``<output>.parts/store.zarr``, beside the
manifest of :class:`.resume.Parts` and one small mark per finished chunk (its counts and its values
of the outputs on fewer axes), written once the worker has written the chunk's values and
flushed them to the disk: an interrupted run resumes from the chunks so marked. At the end
the global attributes are completed (model errors, scheduler, history), the metadata
consolidated, and the store renamed to the output: a store found at the output path is always
complete, and never replaced (a reader reads a store's chunks by their paths as it needs them).
"""
from __future__ import annotations

import os
import shutil
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from ..dependence import reductions, split_reduced
from ..duty_cycle import stored_cycle
from ..grid import Grid, block_shape
from ..spec import Sweep
from .base import FileStore
from .blocks import chunk_tally, stored_blocks, stored_reduction, summed
from .durable import OutputLock, fsync_path, writing
from .resume import Parts, counts_damage, load_counts, saved_counts
from .structure import (coordinate_lists, global_attributes, provenance, stored_as,
                        structure)

#: How many files a task flushes to the disk at once.
FLUSHING_THREADS = 8
#: zarr format 2: its codecs are numcodecs' Zlib and Zstd, the netCDF file's, and readers of
#: format 3 read it too (format 3 has no zlib codec, and zarr-python 2 cannot read it).
ZARR_FORMAT = 2


def write_structure(sweep: Sweep, grid: Grid, block: tuple, scheduler: str, path: Path):
    """Write the store's structure at ``path``: coordinates, attributes, and the outputs and
    status without values, in zarr chunks of ``block`` along the grid's axes (whole along
    their own), each stored as the netCDF file stores it (``[output]``: type, fill value,
    compression). Its metadata consolidated: a task reads one file, not two per variable."""
    labelled = structure(sweep, grid, provenance(scheduler))
    sizes = dict(zip(grid.dims, block))
    layouts = {}
    for name in [o.name for o in grid.model.outputs] + ["status"]:
        dims, values, _ = labelled.data_vars[name]
        stored, _ = stored_as(values, labelled.encodings[name])
        layouts[name] = sweep.storage.zarr_codecs(stored.itemsize) | {
            "chunks": tuple(sizes.get(d, n) for d, n in zip(dims, values.shape))}
    write_labelled(labelled, path, layouts, ZARR_FORMAT)


@dataclass(frozen=True)
class StoreWriter:
    """Writes a computed chunk into its region of the store at ``path`` (small: it travels
    with every task to the worker that computes it); a failure to write it (a full disk) is
    an ``OSError`` naming ``output``, the store's name once complete."""

    path: str
    output: str

    def write(self, grid: Grid, start: int, stop: int, part: dict) -> dict:
        """Write points ``start..stop-1`` (a computed ``part``, as ``evaluate_chunk`` returns
        it) and flush their zarr chunks to the disk, so that the chunk's mark never outlives
        its values in a power loss.

        Returns ``{"firsts": {name: (points, values)}, "tally": dict, "stored_bytes":
        int}``: for each output stored on fewer dimensions (``dependence``), the chunk's
        :func:`dependence.first_held` points and values, one per cell, for the driver to
        write once every chunk has given its own; the chunk's counts
        (:func:`.blocks.chunk_tally`); and the size of the zarr chunks written.
        """
        from zarr.core.sync import sync

        firsts, per_point = split_reduced(grid, start, stop, part)
        tally = chunk_tally(grid.model, part)
        blocks = list(stored_blocks(grid, start, stop, per_point, part["status"]))
        with writing(self.output):  # every array's block at once, in zarr's own event loop
            chunks = sync(_write_blocks(self.path, blocks))
        written = []
        for (name, index, _), sizes in zip(blocks, chunks):
            position = [s.start // c for s, c in zip(index, sizes)]
            position += [0] * (len(sizes) - len(position))
            written.append(Path(self.path, name, ".".join(map(str, position)) or "0"))
        # A zarr chunk equal to the fill value everywhere has no file (zarr writes none).
        with writing(self.output):
            flush(written + sorted({path.parent for path in written}))
        return {"firsts": firsts, "tally": tally,
                "stored_bytes": sum(path.stat().st_size for path in written if path.exists())}


async def _write_blocks(path, blocks) -> list:
    """Write each ``(name, index, block)`` into its array of the zarr group at ``path``,
    concurrently: one at a time, each write waited on zarr's event loop in turn. Returns each
    array's chunk shape."""
    import asyncio

    from zarr.api.asynchronous import open_group

    group = await open_group(store=path, mode="r+", zarr_format=ZARR_FORMAT,
                             use_consolidated=True)

    async def write(name, index, block):
        array = await group.getitem(name)
        await array.setitem(index or ..., block.astype(array.dtype, copy=False))
        return array.chunks

    return await asyncio.gather(*(write(*block) for block in blocks))


class StoreParts(Parts):
    """A zarr output on its way: ``<output>.parts/`` with the manifest, the store being written
    (``store.zarr``) and, for each chunk whose values are in it, a mark: an ``.npz`` file of
    its counts (``blocks.chunk_tally``) and of the values it gives the outputs stored on fewer
    dimensions (one per cell, :meth:`StoreWriter.write`). The interface of
    :class:`.resume.Parts`, which it extends."""

    own_entries = Parts.own_entries + ("store.zarr", ".store.zarr.tmp")

    def __init__(self, output, key: dict, grid=None, storage=None):
        super().__init__(output, key, grid, storage)
        self.output = str(output)
        self.store = self.folder / "store.zarr"

    def prepare(self, sweep: Sweep, grid: Grid, chunk_size: int, scheduler: str):
        """Write the store's structure, unless an interrupted run of this sweep did: the
        folder has it once it is whole (written aside, then renamed into place)."""
        if self.store.exists():
            return
        for marker in self.folder.glob(f"chunk-*{self.suffix}"):
            marker.unlink()  # the values they vouch for went with the store
        temporary = self.folder / ".store.zarr.tmp"
        shutil.rmtree(temporary, ignore_errors=True)
        with writing(self.output):
            write_structure(sweep, grid, block_shape(grid.shape, chunk_size), scheduler,
                            temporary)
            flush([temporary, *temporary.rglob("*")])
        os.replace(temporary, self.store)

    @property
    def writer(self) -> StoreWriter:
        return StoreWriter(str(self.store.absolute()), self.output)

    def damage(self, data, start: int, stop: int) -> str | None:
        """:func:`.resume.counts_damage`; a mark without the store it vouches for is none."""
        if not self.store.is_dir():
            return "no store beside it"
        return counts_damage(data, self.grid, start, stop)

    def arrays(self, result: dict) -> dict:
        """A chunk's mark (its values being in the store): its counts and the values it
        gives the outputs stored on fewer dimensions."""
        return saved_counts(result)

    @staticmethod
    def load(path: Path) -> tuple[dict, dict]:
        """A mark's counts, and its ``{name: (points, values)}``."""
        with np.load(path) as data:
            return load_counts(data)

    def tally(self, model, chunks) -> tuple[dict, list, dict]:
        """The sweep's counts (as ``blocks.summed`` gives them) from its chunks' marks."""
        return summed(model, (self.load(self.path(start, stop))[0] for start, stop in chunks))

    def finish(self, sweep: Sweep, grid: Grid, chunks, output, scheduler: str, errors=(),
               before_rename=None):
        """Write the outputs stored on fewer dimensions from the ``chunks``' marks, complete
        the store's global attributes (as the netCDF file's: model errors, scheduler,
        history), consolidate its metadata, and give it the output's name (calling
        ``before_rename()`` just before), where nothing is (``paths.check_output`` refuses
        an earlier store: it is never replaced)."""
        import zarr

        attributes = global_attributes(structure(sweep, grid, provenance(scheduler), errors))
        group = zarr.open_group(self.store, mode="r+", zarr_format=ZARR_FORMAT,
                                use_consolidated=False)
        reduced = reductions(grid)
        for start, stop in chunks:
            for name, (points, values) in self.load(self.path(start, stop))[1].items():
                reduced[name].add_firsts(points, values)
        with writing(self.output):
            for name, reduction in reduced.items():
                group[name][...] = stored_reduction(reduction, reduction.output.dtype == "int")
            for name, values in stored_cycle(sweep, grid, lambda n: group[n][...]).items():
                group[name][...] = values
            group.attrs.put(attribute_values(attributes))
            zarr.consolidate_metadata(str(self.store), zarr_format=ZARR_FORMAT)
            flush([self.store / ".zattrs", self.store / ".zmetadata", self.store])
        if before_rename is not None:
            before_rename()
        # Fails where something holds the name (but an empty folder): nothing is replaced.
        os.replace(self.store, output)
        fsync_path(Path(output).parent)


class ZarrStore(FileStore):
    """A result written as a zarr store at ``output``, each chunk by the worker that computed
    it (:class:`StoreWriter`), the store kept in its parts folder until complete
    (:class:`StoreParts`); an earlier store is never replaced (:func:`.paths.check_output`)."""

    netcdf = False

    def resume_state(self, key: dict):
        return StoreParts(self.output, key, self.grid, self.sweep.storage)

    @contextmanager
    def recording(self, chunk_size: int, scheduler: str, before_rename=None):
        self.parts.prepare(self.sweep, self.grid, chunk_size, scheduler)
        yield self.parts.writer  # the chunks and their counts are in the store and its marks
        self.finishing()  # nothing has taken its place meanwhile
        self.parts.finish(self.sweep, self.grid, self.chunks, self.output, scheduler,
                          self.errors, before_rename)

    def stored_bytes(self, result: dict) -> int | None:
        return result.get("stored_bytes")

    def counts(self, chunks) -> tuple[dict, list, dict]:
        self.chunks = chunks
        counts, self.errors, noted = self.parts.tally(self.grid.model, chunks)
        return counts, self.errors, noted


def write_dataset(dataset, path):
    """Write an xarray ``dataset`` (an analysis) as a zarr store at ``path``, of the format a
    run's store has, its metadata consolidated: built beside it while the output's lock is
    held, flushed to the disk and renamed to ``path``, where nothing is (an earlier store is
    never replaced, as a run's is not); nothing is left beside it if the writing fails."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    with OutputLock(path):
        try:
            with writing(path):
                dataset.to_zarr(temporary, mode="w", zarr_format=ZARR_FORMAT, consolidated=True)
                flush([*temporary.rglob("*"), temporary])
            os.replace(temporary, path)  # fails where something holds the name
            fsync_path(path.parent)
        finally:
            shutil.rmtree(temporary, ignore_errors=True)


def flush(paths):
    """fsync every file and folder in ``paths``, all at once: the filesystem's journal then
    commits them together (one at a time, a chunk's took longer than writing it)."""
    with ThreadPoolExecutor(FLUSHING_THREADS) as pool:
        list(pool.map(fsync_path, paths))


def write_labelled(labelled, path, layouts: dict, zarr_format: int):
    """Write ``labelled`` as a new zarr group at ``path``, its metadata consolidated. The
    arrays named in ``layouts`` (``{name: {"chunks": ..., "compressors": ..., "filters":
    ...}}``, as xarray's encoding gives them) are created so and left without values, for
    them to be written later; the others get zarr's defaults and their values.

    As xarray's ``to_zarr`` writes it (``tests`` compare the two stores), without xarray: a
    run writes its store's structure so, its workers the values. What xarray does on writing
    zarr format 2 that matters here, beside what it does for netCDF (:mod:`.structure`): the
    fill value is the array's (``.zarray``), not an attribute; each array's dimensions are its
    attribute ``_ARRAY_DIMENSIONS``; arrays without an encoding get zarr's default chunks and
    compressor; attribute values are plain JSON (an array a list)."""
    import zarr

    group = zarr.open_group(path, mode="w", zarr_format=zarr_format)
    group.attrs.put(attribute_values(global_attributes(labelled)))
    listed = coordinate_lists(labelled)
    for name, (dims, values, attrs) in {**labelled.data_vars, **labelled.coords}.items():
        values = np.asarray(values)
        stored, fill = stored_as(values, labelled.encodings.get(name, {}))
        array = group.create(name, shape=values.shape, dtype=stored, fill_value=fill,
                             overwrite=True, **layouts.get(name, {"chunks": "auto"}))
        attrs = dict(attrs) | ({"coordinates": listed[name]} if name in listed else {})
        array.attrs.put(attribute_values(attrs | {"_ARRAY_DIMENSIONS": list(dims)}))
        if name not in layouts:
            array[...] = values.astype(stored)
    zarr.consolidate_metadata(str(path), zarr_format=zarr_format)


def attribute_values(attributes: dict) -> dict:
    """``attributes`` as JSON holds them, as xarray stores them: an array as a list, a numpy
    number as a Python one."""
    return {key: value.tolist() if isinstance(value, (np.ndarray, np.generic)) else value
            for key, value in attributes.items()}
