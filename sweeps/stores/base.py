"""The interface every output store has: what a run asks of the place its result goes.

A run (:func:`bearing_sweep.compute.run_sweep`) uses a store in this order, and nothing else
of it: :meth:`Store.locked` for the whole run; :meth:`Store.open` (the resume state looked
at, nothing changed: the chunk size to use) and :meth:`Store.finished` (the chunks an
interrupted run computed); :meth:`Store.footprint` (what the result takes, refused if the disk
cannot hold it); :meth:`Store.begin` once every refusal has passed; :meth:`Store.recording`
around the computing, yielding what the workers write their chunks with (or None), with
:meth:`Store.record` for each computed chunk and :meth:`Store.counts` at the end; the result
is complete at its place when that block ends without an error; then :meth:`Store.remove`
(the resume state) and :attr:`Store.dataset` (a result held in memory, or None).
"""
from __future__ import annotations

import contextlib

from .footprint import Footprint
from .durable import OutputLock
from .paths import check_output, check_parts_folder


class Store:
    """Where a sweep's result goes (``output``: its path, None for a result in memory);
    ``sweep``: the definition being run. A backend sets :attr:`parts` (its resume state, with
    ``open``, ``begin``, ``finished``, ``save``, ``load`` and ``remove``: :mod:`.resume`) in
    :meth:`open`, and writes in :meth:`recording` and :meth:`record`."""

    #: The result in memory (:mod:`.memory`), None for a result at its path.
    dataset = None
    #: The resume state, made by :meth:`open`.
    parts = None

    def __init__(self, output, sweep):
        self.output, self.sweep = output, sweep
        self.grid = None
        self.tallies = []

    @property
    def where(self) -> str:
        """The result's place, as the run's summary names it."""
        return str(self.output)

    def locked(self):
        """A context holding the output for the run (nothing to hold here)."""
        return contextlib.nullcontext()

    def open(self, grid, key: dict, chunk_size: int, fresh: bool) -> int:
        """Look at the resume state of a run of ``grid`` keyed by ``key`` (nothing changes:
        :meth:`begin` does it); return the chunk size to use (a resumed run keeps its own)."""
        self.grid = grid
        self.parts = self.resume_state(key)
        return self.parts.open(chunk_size, fresh, grid.chunks)

    def resume_state(self, key: dict):
        raise NotImplementedError

    def finished(self) -> set:
        """``(start, stop)`` of every chunk already computed."""
        return self.parts.finished()

    def footprint(self, points: int, workers: int):
        """The run's :class:`.footprint.Footprint` for ``points`` to compute, or None where it
        takes no disk; ``.footprint.InsufficientSpace`` where the disk cannot hold it."""
        return None

    def begin(self, log):
        """Make the resume state this run's (once every refusal has passed)."""
        self.parts.begin(log)

    @contextlib.contextmanager
    def recording(self, chunk_size: int, scheduler: str, before_rename=None):
        """The block in which chunks are computed and :meth:`record` ed; yields the writer a
        worker writes its chunk with (an object with ``write(grid, start, stop, part)``), or
        None where the values come back to this process. The result is complete at its
        place once the block ends without an error (``before_rename()`` called just
        before it takes its name)."""
        yield None

    def record(self, start: int, stop: int, result: dict):
        """Keep the computed chunk of points ``start..stop-1`` (as the task returned it)."""
        self.parts.save(start, stop, result)

    def stored_bytes(self, result: dict) -> int | None:
        """The bytes a computed chunk takes in the result, where it is known yet."""
        return None

    def counts(self, chunks) -> tuple[dict, list, dict]:
        """The run's counts by status meaning, the model's error messages and the counted
        outputs' counts (:func:`.blocks.summed`), once every chunk of ``chunks`` is in."""
        from .blocks import summed
        return summed(self.grid.model, self.tallies)

    def remove(self):
        """Remove the resume state (the result is in place)."""
        self.parts.remove()


class FileStore(Store):
    """A result at the path ``output``, held by its lock for the run. An output path that
    must not be written is refused here, before anything is computed
    (:func:`.paths.check_output`)."""

    #: Whether the result is a netCDF file (a zarr store's takes more room on the disk).
    netcdf = True

    def __init__(self, output, sweep):
        check_output(output, sweep.path)
        check_parts_folder(output)
        super().__init__(output, sweep)

    def locked(self):
        return OutputLock(self.output)

    def footprint(self, points: int, workers: int) -> Footprint:
        footprint = Footprint.of(self.sweep, self.grid, self.output, points, workers,
                                 netcdf=self.netcdf)
        footprint.refuse_if_too_large()
        return footprint

    def finishing(self):
        """Refuse to finish where something has taken the output's place meanwhile."""
        check_output(self.output, self.sweep.path)
