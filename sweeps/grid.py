"""The grid of a sweep: its shape, and the model inputs of any range of its points.

Points are numbered in C order over the axes (the last axis varies fastest). A chunk of points
is a range of those numbers, so its inputs are built where it is computed, from the axes alone:
the grid never holds per-point arrays for all points at once.
"""
from __future__ import annotations

import hashlib
from dataclasses import dataclass

import numpy as np

from .models.registry import Model
from .spec import Sweep


@dataclass
class Grid:
    """Everything a worker needs to build the model inputs of a chunk (small and picklable)."""

    model: Model  # travels to dask workers with the grid (dask pickles it with cloudpickle)
    dims: tuple[str, ...]
    shape: tuple[int, ...]
    fixed: dict  # input name -> SI value (or None) shared by all points
    axis_values: dict  # input name -> (axis position, SI values of that axis, stacked)
    dim_sizes: dict  # output dimension -> size

    @classmethod
    def from_sweep(cls, sweep: Sweep) -> "Grid":
        fixed = {name: None if v is None else v.si for name, v in sweep.fixed.items()}
        axis_values = {}
        for position, axis in enumerate(sweep.axes):
            for name, values in axis.si.items():
                axis_values[name] = (position, values)
        dim_sizes = {}
        for dim, size in sweep.model.dim_sizes.items():
            if callable(size):  # of the inputs' values anywhere on the grid
                size = size({name: axis_values[name][1] if name in axis_values
                             else np.atleast_1d(value) for name, value in fixed.items()
                             if value is not None} | {name: values for name, (_, values)
                                                      in axis_values.items()})
            elif isinstance(size, str):
                size = int(np.prod([np.max(axis_values[name][1]) if name in axis_values
                                    else fixed[name] for name in size.split("*")]))
            dim_sizes[dim] = size if isinstance(size, int) else len(size)
        return cls(sweep.model, tuple(a.name for a in sweep.axes),
                   tuple(len(a) for a in sweep.axes), fixed, axis_values, dim_sizes)

    @property
    def values_sha256(self) -> str:
        """Digest of every input value of the grid, fixed and along the axes (SI): parts
        computed for other values (a sample drawn by another library version, say) are not
        this grid's, even where the definition's text is the same."""
        digest = hashlib.sha256()
        for name, value in sorted(self.fixed.items()) + sorted(
                (name, values) for name, (_, values) in self.axis_values.items()):
            digest.update(name.encode())
            array = np.asarray(value)
            digest.update(array.tobytes() if array.dtype.kind in "biuf"
                          else repr(array.tolist()).encode())
        return digest.hexdigest()

    @property
    def size(self) -> int:
        return int(np.prod(self.shape, dtype=np.int64))

    def chunks(self, chunk_size: int) -> list[tuple[int, int]]:
        """Ranges ``[start, stop)`` of point numbers covering the grid."""
        return [(start, min(start + chunk_size, self.size))
                for start in range(0, self.size, chunk_size)]

    def inputs(self, start: int, stop: int) -> tuple[dict, dict]:
        """Model inputs of points ``start..stop-1``.

        Returns the inputs that vary on the grid as arrays with the points first, and the
        axis index of each point on every axis (to group points by structural inputs).
        """
        index = np.unravel_index(np.arange(start, stop), self.shape) if self.shape else ()
        varying = {name: values[index[position]]
                   for name, (position, values) in self.axis_values.items()}
        return varying, dict(zip(self.dims, index))
