"""Outputs that depend on fewer inputs than the grid holds (``Output.depends_on``: a roller's
centrifugal force depends on the speed and the roller's size, not on the load): each is stored
on the grid's axes that hold those inputs only.

A zipped axis (a ``sample`` too) holding any of them is kept whole; an input that is fixed
holds no axis. The value of a cell of the kept axes is that of its first point, in grid
order, whose status keeps values (a failed point's NaN says nothing of the output); a cell
whose points all failed is NaN. Every other point of the cell whose values hold must agree:
a model whose output varies along an axis it says it does not depend on has a wrong
declaration, and the sweep stops with :class:`InconsistentOutput` rather than store one of
its values for all of them.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .models.registry import STATUS_MEANINGS, STATUS_VALUES, VALUES_KEPT, values_kept
from .duty_cycle import SUFFIX as CYCLE_SUFFIX
from .grid import Grid

if TYPE_CHECKING:
    import xarray as xr

#: How closely [relative] the points of a cell must agree. The same inputs give the same bits
#: in a pure model; the margin spares a finished sweep a failure over a last-bit difference
#: (a library's vector loop and its scalar tail), far below any real dependence.
AGREEMENT = 1e-12
#: The source of a cell no point has given a value yet: beyond every point.
UNKNOWN = np.iinfo(np.int64).max


class InconsistentOutput(ValueError):
    """An output differs along an axis of an input it is declared not to depend on."""


def stored_dims(grid: Grid, output) -> tuple[str, ...]:
    """The grid's dimensions ``output`` is stored on, in the grid's order: all of them, or,
    for an output that declares ``depends_on``, those of the axes holding any of its inputs."""
    if output.depends_on is None:
        return grid.dims
    axes = {grid.axis_values[name][0] for name in output.depends_on
            if name in grid.axis_values}
    return tuple(dim for axis, dim in enumerate(grid.dims) if axis in axes)


def stored_shape(grid: Grid, output) -> tuple[int, ...]:
    """The sizes of ``output``'s :func:`stored_dims`."""
    return tuple(grid.shape[grid.dims.index(d)] for d in stored_dims(grid, output))


def stored_cells(grid: Grid, output) -> int:
    """How many values of ``output`` the file holds along the grid's dimensions."""
    return int(np.prod(stored_shape(grid, output), dtype=np.int64))


def reduced_outputs(grid: Grid) -> list:
    """The outputs of the grid's model stored on fewer dimensions than the grid has."""
    return [output for output in grid.model.outputs if stored_dims(grid, output) != grid.dims]


def reductions(grid: Grid) -> dict[str, "Reduction"]:
    """A :class:`Reduction` for each of the grid's :func:`reduced_outputs`, by name."""
    return {output.name: Reduction(grid, output) for output in reduced_outputs(grid)}


def first_held(grid: Grid, output, start: int, stop: int, values: np.ndarray,
               status: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The first point whose values hold in each cell of ``output``'s :func:`stored_dims`
    that points ``start..stop-1`` (their ``values`` and ``status``) fall in, and its value:
    one value per cell, what :meth:`Reduction.add_firsts` takes. :class:`InconsistentOutput`
    where another held point of the cell disagrees with it."""
    held = values_kept(status)
    points = np.arange(start, stop)[held]
    values = values[held]
    cells = _cells(grid, output, points)
    _, first, inverse = np.unique(cells, return_index=True, return_inverse=True)
    source, expected = points[first][inverse], values[first][inverse]
    agree = _agree(values, expected)
    if not agree.all():
        wrong = np.flatnonzero(~agree)[0]
        raise InconsistentOutput(_disagreement(grid, output, points[wrong], values[wrong],
                                               source[wrong], expected[wrong]))
    return points[first], values[first]


def split_reduced(grid: Grid, start: int, stop: int, part: dict) -> tuple[dict, dict]:
    """A computed chunk of points ``start..stop-1`` (``part``, as ``evaluate.evaluate_chunk``
    returns it) as the process that computed it sends it on: the :func:`first_held` points
    and values of each output stored on fewer dimensions, ``{name: (points, values)}``, and
    the other outputs' values, ``{name: values}``."""
    reduced = {output.name: output for output in reduced_outputs(grid)}
    firsts = {name: first_held(grid, output, start, stop, part["outputs"][name],
                               part["status"]) for name, output in reduced.items()}
    return firsts, {name: values for name, values in part["outputs"].items()
                    if name not in reduced}


def _cells(grid: Grid, output, points: np.ndarray) -> np.ndarray:
    """The cell of ``output``'s :func:`stored_dims` (flat) each point falls in."""
    axes = [grid.dims.index(d) for d in stored_dims(grid, output)]
    if not axes:
        return np.zeros(points.size, dtype=np.int64)
    index = np.unravel_index(points, grid.shape)
    return np.ravel_multi_index([index[a] for a in axes], stored_shape(grid, output))


def _agree(values: np.ndarray, expected: np.ndarray) -> np.ndarray:
    """Whether each point's values (its own dimensions too) agree with the expected ones."""
    with np.errstate(invalid="ignore"):
        agree = np.isclose(values, expected, rtol=AGREEMENT, atol=0.0, equal_nan=True)
    return agree.all(axis=tuple(range(1, agree.ndim)))


class Reduction:
    """The values of one output on its :func:`stored_dims`, gathered from the chunks of a
    sweep (:meth:`add`, in any order), then read from :attr:`values`: flat over the cells,
    then the output's own dimensions. Holds one value per cell (the grid's size divided by
    the sizes of the dimensions it drops, times its own dimensions' sizes)."""

    def __init__(self, grid: Grid, output):
        self.grid, self.output = grid, output
        self.dims = stored_dims(grid, output)
        self.shape = stored_shape(grid, output)
        cells = stored_cells(grid, output)
        self.values = np.full((cells,) + tuple(grid.dim_sizes[d] for d in output.dims), np.nan)
        # The point each value comes from; none yet: beyond every point.
        self.source = np.full(cells, UNKNOWN, dtype=np.int64)

    def add(self, start: int, stop: int, values: np.ndarray, status: np.ndarray):
        """Take the values of points ``start..stop-1`` (their ``status``): a cell takes the
        value of its first held point in grid order; :class:`InconsistentOutput` where a held
        point disagrees with it."""
        self.add_firsts(*first_held(self.grid, self.output, start, stop, values, status))

    def add_firsts(self, points: np.ndarray, values: np.ndarray):
        """Take a chunk's :func:`first_held` points (one per cell) and their values: a cell
        keeps the value of its earliest point, whatever order the chunks come in;
        :class:`InconsistentOutput` where a chunk disagrees with another."""
        cells = _cells(self.grid, self.output, points)
        known = self.source[cells] != UNKNOWN
        expected = self.values[cells]
        agree = _agree(values, expected) | ~known
        if not agree.all():
            wrong = np.flatnonzero(~agree)[0]
            raise InconsistentOutput(_disagreement(self.grid, self.output, points[wrong],
                                                   values[wrong], self.source[cells[wrong]],
                                                   expected[wrong]))
        earlier = points < self.source[cells]
        self.values[cells[earlier]] = values[earlier]
        self.source[cells[earlier]] = points[earlier]


def _disagreement(grid: Grid, output, point, value, source, expected) -> str:
    inputs = ", ".join(output.depends_on) or "no input"
    unit = "" if output.unit in ("", "1") else " " + output.unit
    return (f"model {grid.model.name!r}, output {output.name!r}: declared to "
            f"depend on {inputs} only (depends_on), it differs between points that share "
            f"those: {_shown(expected)}{unit} at {_where(grid, source)} and "
            f"{_shown(value)}{unit} at {_where(grid, point)}; the model's declaration is "
            "wrong (remove or widen its depends_on)")


def _where(grid: Grid, point) -> str:
    index = np.unravel_index(point, grid.shape)
    return "point " + ", ".join(f"{d}[{i}]" for d, i in zip(grid.dims, index))


def _shown(value) -> str:
    value = np.asarray(value)
    return f"{value.item():.10g}" if value.size == 1 else np.array2string(value, precision=10)


def on_grid(data: xr.Dataset) -> xr.Dataset:
    """A sweep's dataset with every output on all the grid's dimensions, as each point holds
    it: an output stored on fewer (:func:`stored_dims`) is broadcast over the others, and NaN
    where a point's status keeps no values (as the model's other outputs are there)."""
    status = data["status"]
    held = held_points(status)
    data = data.copy()
    for name, variable in data.data_vars.items():
        if variable.attrs.get("coverage_content_type") != "modelResult" \
                or set(status.dims) <= set(variable.dims) or name.endswith(CYCLE_SUFFIX):
            continue
        own = [d for d in variable.dims if d not in status.dims]
        data[name] = variable.broadcast_like(status).where(held).transpose(
            *status.dims, *own).assign_attrs(variable.attrs)
    return data


def held_points(status: xr.DataArray) -> xr.DataArray:
    """Where a point's values hold, from the flags of a dataset's ``status`` variable (a file
    written before statuses were bit fields kept the values of its ``out_of_validity``
    points too)."""
    kept = [STATUS_MEANINGS[STATUS_VALUES.index(code)] for code in VALUES_KEPT]
    if "flag_masks" not in status.attrs:
        kept.append("out_of_validity")
    held = False
    for meaning in kept:
        held = held | flag_holds(status, meaning)
    return held


def flag_holds(status: xr.DataArray, meaning: str) -> xr.DataArray:
    """Where the CF flag ``meaning`` of ``status`` holds: ``status & mask == value`` by its
    ``flag_masks`` and ``flag_values``, or ``status == value`` where it has no masks; false
    everywhere for a meaning it does not name."""
    meanings = status.attrs["flag_meanings"].split()
    if meaning not in meanings:
        return status.copy(data=np.zeros(status.shape, dtype=bool))
    index = meanings.index(meaning)
    value = int(np.atleast_1d(status.attrs["flag_values"])[index])
    if "flag_masks" in status.attrs:
        return (status & int(np.atleast_1d(status.attrs["flag_masks"])[index])) == value
    return status == value
