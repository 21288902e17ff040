"""Every input of one model, from the tables that give them: a preset, [fixed], [axes] and
[sample], the declared defaults for the rest; then the conditions between them (a pattern as
long as its count, the model's constraints) over the whole grid.

:class:`ModelInputs` reads them below any table of a definition: its reader's dotted path
names where (the top for a definition of one model; a sub-table such as ``supports.A`` for
one model among several), and every key in its messages is written from there.
"""
from __future__ import annotations

import numpy as np

from ..models.catalogue import PRESETS
from ..models.registry import Model
from .axes import Axis, AxisReader
from .sampling import SampleReader, Sampling
from .tables import Reader, plain, suggestion
from .values import Value, ValueReader, default_value, stack


#: An input not given, in the check of a constraint that takes it (as NaN).
_UNSET = Value(np.nan, "not given", "")


class ModelInputs:
    """Reads the inputs of ``model`` from a table; each input may be given once only."""

    def __init__(self, reader: Reader, model: Model):
        self.reader = reader
        self.fail = reader.fail
        self.model = model
        self.inputs = {i.name: i for i in model.inputs}
        self.values = ValueReader(reader)
        self.seen: dict[str, str] = {}  # each input given so far, and where

    def claim(self, name: str, key: str):
        """Check that ``name`` is an input of the model, given only once."""
        model = self.model
        if name not in self.inputs:
            self.fail(key, f"unknown parameter {name!r} of model {model.name}"
                      + suggestion(name, self.inputs)
                      + f" (`bearing-sweep describe {model.name}` lists them)")
        if name in self.seen:
            self.fail(key, f"parameter {name!r} is given twice (also at {self.seen[name]})")
        self.seen[name] = self.reader.key(key)

    def read(self, table: dict, bearing, bearing_key: str, presets=()
             ) -> tuple[dict[str, Value | None], dict[str, str], list[Axis], Sampling | None]:
        """The inputs given in ``table`` (its [fixed], [axes] and [sample] tables) over the
        preset ``bearing`` (None: none; named at ``bearing_key``) and the values of
        ``presets`` (``(values, where they come from)``, such as a shaft's supports'
        presets): every input's fixed value (None: derived by the model), where each came
        from, the axes (the drawn ``sample`` axis first) and how it was drawn."""
        model, reader = self.model, self.reader
        fixed_raw = reader.table(table, "fixed", None)
        axes_raw = reader.table(table, "axes", None)
        fixed: dict[str, Value | None] = {}
        origin: dict[str, str] = {}
        if bearing is not None:
            for key, value in self.preset(bearing, bearing_key).items():
                fixed[key], origin[key] = value, f"preset {bearing}"
        for values, where in presets:
            for key, value in values.items():
                fixed[key], origin[key] = value, where
        for key, raw in fixed_raw.items():
            where = f"fixed.{key}"
            self.claim(key, where)
            fixed[key], origin[key] = self.values.value(self.inputs[key], raw, where,
                                                        fixed=True), "fixed"
        axis_reader = AxisReader(self.values, model, self.claim)
        axes = [axis_reader.axis(key, raw) for key, raw in axes_raw.items()]
        cycles = [axis.name for axis in axes if axis.time_shares is not None]
        if len(cycles) > 1:
            self.fail(f"axes.{cycles[1]}.time_share", f"a second duty cycle (axes.{cycles[0]} "
                      "is one): one zipped axis holds the load cases and their time shares")
        sample_raw = reader.table(table, "sample", None)
        samples = SampleReader(self.values, model, self.claim)
        sampled = samples.sampled(sample_raw)
        on_axes = {p for axis in axes for p in axis.values} | set(sampled)
        for key in on_axes:
            fixed.pop(key, None)
            origin.pop(key, None)
        missing = [s for s in model.inputs
                   if s.required and s.name not in fixed and s.name not in on_axes]
        if missing:
            described = ", ".join(f"{s.name!r}" + ("" if s.unit in ("", "1") else f" [{s.unit}]")
                                  for s in missing)
            self.fail("fixed", f"missing parameter{'s' * (len(missing) > 1)} {described}; give "
                      "them in [fixed] or [axes], or name a preset in [sweep] bearing")
        for spec in model.inputs:
            if spec.name not in fixed and spec.name not in on_axes:
                fixed[spec.name] = None if spec.default is None else default_value(spec)
                origin[spec.name] = "default"
        sampling = None
        if "sample" in table:
            axis, sampling = samples.sample_axis(sample_raw, sampled, fixed)
            axes.insert(0, axis)  # every sample at every point of the other axes
        return fixed, origin, axes, sampling

    def preset(self, name, key: str) -> dict[str, Value]:
        """The values of the preset ``name`` (named at ``key``) for this model."""
        model = self.model
        if not isinstance(name, str) or name not in PRESETS:
            self.fail(key, f"unknown preset {name!r}" + suggestion(str(name), PRESETS)
                      + " (`bearing-sweep presets` lists them)")
        preset = PRESETS[name]
        if model.name not in preset.models:
            self.fail(key, f"preset {name!r} is for {' and '.join(preset.models)}, "
                      f"not {model.name!r}")
        return {input_name: self.values.value(model.input(input_name), raw,
                                              f"preset {name}.{input_name}")
                for input_name, raw in preset.values.items()}

    # -- conditions between parameters ----------------------------------------------------
    def check(self, fixed: dict, origin: dict, axes: list[Axis]):
        """The conditions between inputs, over every point of the grid."""
        self.check_pattern_lengths(fixed, origin, axes)
        self.check_constraints(fixed, axes)

    def check_pattern_lengths(self, fixed: dict, origin: dict, axes: list[Axis]):
        """A pattern with one value per roller has as many values as there are rollers."""
        model = self.model
        for spec in model.inputs:
            count_name = model.dim_sizes.get(spec.dims[0]) if spec.dims else None
            if not isinstance(count_name, str) or count_name not in self.inputs:
                continue
            patterns, where = values_of(fixed, origin, axes, spec.name)
            counts, _ = values_of(fixed, origin, axes, count_name)
            lengths = {np.size(v.si) for v in patterns} - ({1} if spec.broadcast else set())
            wanted = {int(v.si) for v in counts}
            for length in lengths:
                if wanted != {length}:
                    other = ", ".join(str(n) for n in sorted(wanted - {length}))
                    self.fail(where, f"{spec.name} has {length} values but {count_name} is "
                              f"{other}: give one value per {spec.dims[0]}"
                              + (" (or a single value for all)" if spec.broadcast else ""))

    def check_constraints(self, fixed: dict, axes: list[Axis]):
        for constraint in self.model.constraints:
            columns, si, axis_of = {}, {}, {}
            for name in constraint.inputs:
                if name in fixed:
                    if fixed[name] is None and not constraint.unset:
                        break
                    columns[name] = [fixed[name] or _UNSET]
                    si[name] = stack(columns[name])
                else:
                    axis = next(a for a in axes if name in a.values)
                    columns[name], axis_of[name] = axis.values[name], axis.name
                    si[name] = axis.si[name]
            else:
                self.check_constraint(constraint, columns, si, axis_of)

    def check_constraint(self, constraint, columns: dict, si: dict, axis_of: dict):
        axis_names = list(dict.fromkeys(axis_of.values()))
        arrays = {}
        for name, column in columns.items():
            shape = [1] * len(axis_names)
            if name in axis_of:
                shape[axis_names.index(axis_of[name])] = len(column)
            values = si[name]
            arrays[name] = values.reshape(shape + list(values.shape[1:]))  # patterns: trailing
        valid = np.broadcast_to(constraint.check(**arrays), np.broadcast_shapes(
            *(a.shape[:len(axis_names)] for a in arrays.values())))
        if not valid.all():
            where = np.unravel_index(np.argmin(valid), valid.shape) if valid.ndim else ()
            shown = []
            for name, column in columns.items():
                index = where[axis_names.index(axis_of[name])] if name in axis_of else 0
                value = column[index]
                if value is _UNSET:
                    shown.append(f"{name} not given")
                    continue
                unit = "" if value.unit in ("", "1") else f" {value.unit}"
                if self.model.input(name).kind == "subset":  # as written: a list of names
                    shown.append(f"{name} = {value.shown.split()}")
                    continue
                shown.append(f"{name} = {plain(value.shown)}{unit}")
            section = ("sample" if "sample" in axis_of.values() else "axes") if axis_of \
                else "fixed"
            self.fail(section, f"{constraint.message} ({', '.join(shown)})")


def values_of(fixed: dict, origin: dict, axes: list[Axis], name: str) -> tuple[list, str]:
    """Every value ``name`` takes on the grid, and where it was given."""
    for axis in axes:
        if name in axis.values:
            where = f"axes.{axis.name}" + (f".{name}" if axis.name != name else "")
            return axis.values[name], where
    given = origin.get(name, "fixed")
    return [fixed[name]], (f"fixed.{name}" if given == "fixed" else f"{given}.{name}")
