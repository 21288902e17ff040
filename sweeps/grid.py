"""The labelled grid of a sweep: coordinates, and the model inputs of any range of its points.

Points are numbered in C order over the axes (the last axis varies fastest). A chunk of points
is a range of those numbers, so its inputs are built where it is computed, from the axes alone:
the grid never holds per-point arrays for all points at once.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import units
from .models.registry import Model
from .spec import Sweep, Value


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


def coordinates(sweep: Sweep) -> dict:
    """xarray coordinates of the grid, each input in the unit the model declares for it.

    Returns ``{name: (dims, values, attrs)}``: one dimension coordinate per axis (a zipped
    axis' labels) and a coordinate along its axis for each zipped parameter. Every file of a
    model stores an input in the same unit, so files combine safely; the unit the user wrote
    is kept in the attribute ``written_units``.
    """
    coords = {}
    for axis in sweep.axes:
        if axis.labels is None:
            name, values = next(iter(axis.values.items()))
            coords[name] = ((name,), declared_values(sweep, name, values),
                            input_attrs(sweep, name, values[0].unit))
            continue
        labels = np.array(axis.labels)
        coords[axis.name] = ((axis.name,), labels, {"long_name": axis.name.replace("_", " "),
                                                    "comment": "labels of a zipped axis"}
                             | ({"units": "1"} if labels.dtype.kind in "iu" else {}))
        for name, values in axis.values.items():
            extra = sweep.model.input(name).dims if any(np.ndim(v.shown) for v in values) else ()
            coords[name] = ((axis.name,) + extra, declared_values(sweep, name, values),
                            input_attrs(sweep, name, values[0].unit))
    return coords


def fixed_inputs(sweep: Sweep) -> dict:
    """The inputs not on an axis, as variables ``{name: (dims, value, attrs)}`` in their
    declared units: kept in the file, but not as scalar coordinates (xarray would print them
    all in every plot's title)."""
    variables = {}
    for name, value in sweep.fixed.items():
        if value is None:
            continue
        attrs = input_attrs(sweep, name, value.unit)
        attrs["origin"] = sweep.origin.get(name, "")
        dims = sweep.model.input(name).dims if np.ndim(value.shown) else ()
        variables[name] = (dims, declared_values(sweep, name, [value])[0], attrs)
    return variables


def declared_values(sweep: Sweep, name: str, values: list[Value]) -> np.ndarray:
    """The values of input ``name`` in its declared unit, stacked (points first)."""
    spec = sweep.model.input(name)
    first = values[0].shown
    if isinstance(first, str):
        return np.array([v.shown for v in values])
    target = stored_unit(spec.unit)
    declared = units.parse_unit(target) if spec.kind == "quantity" else None
    shown = []
    for value in values:
        magnitude = np.asarray(value.shown, dtype=float)
        if declared is not None and value.unit != target:
            # One conversion from what was written, tidied to 15 digits so that "4 kN" is
            # stored as 4000 N, not 4000.0000000000005.
            magnitude = _tidy(units.convert(magnitude, units.parse_unit(value.unit), declared))
        shown.append(magnitude)
    size = max(np.size(a) for a in shown)
    if any(a.ndim for a in shown):  # a single value on a zipped axis of patterns: repeat it
        shown = [np.broadcast_to(a, (size,)) for a in shown]
    stacked = np.stack(shown)
    return stacked.astype(np.int64) if spec.kind == "count" else stacked


def input_attrs(sweep: Sweep, name: str, written: str) -> dict:
    """``long_name``, UDUNITS ``units`` and the unit the user wrote, of input ``name``."""
    spec = sweep.model.input(name)
    if spec.kind in ("choice", "subset"):
        return described(spec.short, spec.meaning, None) | {
            "accepted_values": " ".join(spec.choices)}
    attrs = described(spec.short, spec.meaning, spec.unit)
    if written and written not in ("1", spec.unit):
        attrs["written_units"] = written
    return attrs


def stored_unit(unit: str) -> str:
    """The unit values are stored in: the declared one, or SI where UDUNITS cannot express
    the declared one (a fractional power: "N/mm^1.5" would read as 5000 N/m)."""
    return unit if units.cf_units(unit or "1") is not None else units.si_text(unit)


def described(label: str, meaning: str, unit: str | None) -> dict:
    """``long_name``, ``units`` (UDUNITS) and ``comment`` of a variable; a unit UDUNITS
    cannot express is named in the comment instead (with the values in SI)."""
    attrs = {"long_name": label}
    comment = meaning if meaning != label else ""
    if unit is not None:
        cf = units.cf_units(unit or "1")
        if cf is not None:
            attrs["units"] = cf
        else:
            comment += (". " if comment else "") + (
                f"Units: {units.si_text(unit)} (SI); UDUNITS has no fractional powers, so "
                "there is no units attribute")
    if comment:
        attrs["comment"] = comment
    return attrs


def _tidy(values) -> np.ndarray:
    values = np.asarray(values, dtype=float)
    return np.array([float(f"{v:.15g}") for v in values.ravel()]).reshape(values.shape)
