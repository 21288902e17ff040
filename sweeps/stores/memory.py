"""A sweep returned without a file: its finished chunks held in memory, then gathered into its
labelled dataset."""
from __future__ import annotations

from contextlib import contextmanager
from typing import TYPE_CHECKING

import numpy as np

from ..dependence import reductions
from ..grid import Grid
from ..labels import labelled_dataset
from ..spec import Sweep
from .base import Store
from .blocks import chunk_tally, flat_shape, per_point_outputs
from .structure import provenance

if TYPE_CHECKING:
    import xarray as xr


class HeldChunks:
    """Finished chunks held in memory, for a sweep returned without a file: the interface of
    :class:`.resume.Parts`, with nothing to resume."""

    folder = None

    def __init__(self):
        self.chunks = {}

    def open(self, chunk_size: int, fresh: bool, chunks_of=None) -> int:
        return chunk_size

    def begin(self, log):
        pass

    def finished(self) -> set:
        return set(self.chunks)

    def save(self, start: int, stop: int, result: dict):
        self.chunks[start, stop] = result

    def load(self, start: int, stop: int) -> dict:
        return self.chunks[start, stop]

    def remove(self):
        self.chunks.clear()



def gather(sweep: Sweep, grid: Grid, parts, chunks, scheduler: str, errors=()) -> xr.Dataset:
    """The sweep's labelled dataset in memory, from its chunks: the dataset
    :func:`.netcdf.result_file` writes (``errors``: the model's messages, from
    :func:`.blocks.summed`)."""
    reduced = reductions(grid)
    outputs = {o.name: np.full(flat_shape(grid, o), np.nan) for o in grid.model.outputs
               if o.name not in reduced}
    status = np.zeros(grid.size, dtype=np.int8)
    for start, stop in chunks:
        part = parts.load(start, stop)
        for name, values in per_point_outputs(part, reduced, start, stop).items():
            outputs[name][start:stop] = values
        status[start:stop] = part["status"]
    outputs.update({name: reduction.values for name, reduction in reduced.items()})
    return labelled_dataset(sweep, grid, outputs, status, provenance(scheduler), errors)


class MemoryStore(Store):
    """A result returned as a dataset (:attr:`dataset`), without a file: its chunks held in
    memory (:class:`HeldChunks`) and gathered once all are in."""

    def __init__(self, sweep: Sweep):
        super().__init__(None, sweep)

    @property
    def where(self) -> str:
        return "(in memory)"

    def resume_state(self, key: dict):
        return HeldChunks()

    @contextmanager
    def recording(self, chunk_size: int, scheduler: str, before_rename=None):
        self.scheduler = scheduler
        yield None

    def record(self, start: int, stop: int, result: dict):
        self.parts.save(start, stop, result)
        self.tallies.append(chunk_tally(self.grid.model, result))

    def counts(self, chunks) -> tuple[dict, list, dict]:
        """:meth:`Store.counts`, and the result gathered into :attr:`dataset`."""
        counts, errors, noted = super().counts(chunks)
        self.dataset = gather(self.sweep, self.grid, self.parts, chunks, self.scheduler, errors)
        return counts, errors, noted
