"""The grid of a sweep: its shape, and the model inputs of any range of its points.

Points are numbered in C order over the axes (the last axis varies fastest). A chunk of points
is a range of those numbers, so its inputs are built where it is computed, from the axes alone:
the grid never holds per-point arrays for all points at once.
"""
from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass

import numpy as np

from .models.registry import Model
from .spec import Sweep


#: Points of a grid at most on which a model's cost function is evaluated.
COST_SAMPLE = 1000


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
        """Ranges ``[start, stop)`` of point numbers covering the grid, in order: each chunk
        of at most ``chunk_size`` points fills one block (:func:`block_shape`), one zarr or
        HDF5 chunk of every output stored per point."""
        return block_chunks(self.shape, block_shape(self.shape, chunk_size))

    def inputs(self, start: int, stop: int) -> tuple[dict, dict]:
        """Model inputs of points ``start..stop-1``.

        Returns the inputs that vary on the grid as arrays with the points first, and the
        axis index of each point on every axis (to group points by structural inputs).
        """
        return self._at(np.arange(start, stop))

    def _at(self, points: np.ndarray) -> tuple[dict, dict]:
        index = np.unravel_index(points, self.shape) if self.shape else ()
        varying = {name: values[index[position]]
                   for name, (position, values) in self.axis_values.items()}
        return varying, dict(zip(self.dims, index))

    @property
    def seconds_per_point(self) -> float:
        """Rough cost of one point on one core [s]: the model's constant, or, where the model
        gives it as a function of the points' inputs, its mean over the grid (over every
        point, or ``COST_SAMPLE`` of them drawn at random: a regular stride would alias with
        the fastest axes)."""
        cost = self.model.seconds_per_point
        if not callable(cost):
            return cost
        points = np.arange(self.size) if self.size <= COST_SAMPLE else np.sort(
            np.random.default_rng(0).choice(self.size, COST_SAMPLE, replace=False))
        varying, _ = self._at(points)
        values = {name: value for name, value in self.fixed.items() if value is not None}
        return float(np.mean(cost(values | varying)))


def block_shape(shape: tuple, size: int) -> tuple:
    """The block of a grid of ``shape`` that one chunk of at most ``size`` points fills: the
    shape of a zarr chunk, and of an HDF5 chunk, along the grid's axes.

    Whole rows of the last axes: 1 along the leading axes, a block of one axis, every index
    of the axes after it (``(1, 1, c, n3, n4)``). C-ordered points then fill each block in
    one unbroken range, so each chunk of points is one block (:func:`block_chunks`). Along
    the blocked axis the blocks are of nearly equal length (1001 rows by 1000 points: two
    blocks of 501 and 500, not 1000 and 1).
    """
    for axis, length in enumerate(shape):
        inner = math.prod(shape[axis + 1:])
        if inner <= size:
            pieces = math.ceil(length / max(1, size // inner))
            return (1,) * axis + (math.ceil(length / pieces),) + tuple(shape[axis + 1:])
    return ()


def block_chunks(shape: tuple, block: tuple) -> list[tuple[int, int]]:
    """The ranges ``[start, stop)`` of C-ordered point numbers that fill each block of
    shape ``block`` (:func:`block_shape`) of a grid of ``shape``, in order."""
    if not shape:
        return [(0, 1)]
    counts = [math.ceil(n / b) for n, b in zip(shape, block)]
    chunks = []
    for position in np.ndindex(*counts):
        first = [p * b for p, b in zip(position, block)]
        last = [min((p + 1) * b, n) - 1 for p, b, n in zip(position, block, shape)]
        chunks.append((int(np.ravel_multi_index(first, shape)),
                       int(np.ravel_multi_index(last, shape)) + 1))
    return chunks
