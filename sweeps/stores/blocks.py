"""What every store does with a computed chunk: its values cut into the regions of the grid
a result stores them in (:func:`stored_blocks`), its outputs stored on fewer dimensions
gathered (:func:`per_point_outputs`), and its counts (:func:`chunk_tally`, :func:`summed`)."""
from __future__ import annotations

import numpy as np

from ..models.registry import (OUTCOME_MASK, STATUS_MASKS, STATUS_MEANINGS, STATUS_VALUES,
                               VALIDITY_MASK)
from ..dependence import stored_cells
from ..grid import Grid
from ..storage import integral_values


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
        for index, low, high in regions(grid.shape, start, stop):
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


def per_point_outputs(part: dict, reduced: dict, start: int, stop: int) -> dict:
    """A chunk's outputs stored per point; those stored on fewer dimensions (``reduced``, by
    name) are handed to their :class:`dependence.Reduction` instead."""
    for name, reduction in reduced.items():
        reduction.add(start, stop, part["outputs"][name], part["status"])
    return {name: values for name, values in part["outputs"].items() if name not in reduced}


def flat_shape(grid: Grid, output) -> tuple:
    """An output's shape with the grid's cells it is stored on flat (every point, or fewer:
    :func:`dependence.stored_dims`), then its own dimensions."""
    return (stored_cells(grid, output),) + tuple(grid.dim_sizes[d] for d in output.dims)


def regions(shape: tuple, start: int, stop: int, offset: int = 0):
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
        for index, low, high in regions(shape[1:], head, tail, offset + first * inner):
            yield (slice(first, first + 1),) + index, low, high
        return
    if head:
        for index, low, high in regions(shape[1:], head, inner, offset + first * inner):
            yield (slice(first, first + 1),) + index, low, high
        first += 1
    if last > first:
        yield ((slice(first, last),) + tuple(slice(0, n) for n in shape[1:]),
               offset + first * inner, offset + last * inner)
    if tail:
        for index, low, high in regions(shape[1:], 0, tail, offset + last * inner):
            yield (slice(last, last + 1),) + index, low, high

