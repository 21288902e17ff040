"""The [axes] table: each axis a list of values, ``{values = [...], units = "..."}``, a range
``{start, stop, num or step}``, or a zipped axis of several parameters under one name."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

import numpy as np

from ..models.registry import Input, Model
from .. import units
from .tables import plain, short, written
from .values import VALUES_KEYS, Value, ValueReader, convert_written, stack

_RANGE_KEYS = {"start", "stop", "num", "step", "units"}
#: Names a result or its analysis uses: the status of each point, the [sample] axis and
#: the blocks of its Saltelli design, the dimensions of `analyze`'s output, and a duty
#: cycle's time shares and status.
RESERVED_NAMES = {"status", "sample", "saltelli_block", "saltelli_replicate", "statistic",
                  "output", "input", "bound", "time_share", "status_over_duty_cycle"}
#: A name of a variable or dimension (CF conventions 2.3), at most 64 characters.
AXIS_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
#: The column of a zipped axis that makes it a duty cycle: each load case's share of the time,
#: over which the model's rating lives are combined (``Output.cycle``).
TIME_SHARE = "time_share"
#: Most values on one axis (each is validated on its own before any computing).
MAX_AXIS_VALUES = 10**6
#: Two values of an axis closer than this, relative to their size, are one value written
#: twice (rounding in a unit conversion is some 1e-16; a file stores 15 digits).
SAME_VALUE = 1e-9


@dataclass
class Axis:
    """One dimension of the grid: a parameter's values, or several parameters zipped."""

    name: str
    values: dict[str, list[Value]]
    labels: list | None = None  # a zipped axis' labels
    #: A duty cycle's axis: each load case's share of the time (:data:`TIME_SHARE`).
    time_shares: list[float] | None = None
    #: Each parameter's SI values stacked, points first: built once, for the conditions
    #: between parameters and for every chunk's model inputs.
    si: dict[str, np.ndarray] = field(init=False, repr=False)

    def __post_init__(self):
        self.si = {name: stack(values) for name, values in self.values.items()}

    def __len__(self) -> int:
        return len(next(iter(self.values.values())))


class AxisReader:
    """Reads the axes of one model's inputs; ``claim(name, key)`` marks an input as given
    (once only) at ``key``."""

    def __init__(self, values: ValueReader, model: Model, claim):
        self.values = values
        self.reader = values.reader
        self.fail = values.fail
        self.model = model
        self.inputs = {i.name: i for i in model.inputs}
        self.claim = claim

    def axis(self, name: str, raw) -> Axis:
        key = f"axes.{name}"
        model, inputs = self.model, self.inputs
        if name in inputs:
            if isinstance(raw, dict) and "labels" in raw:
                self.fail(key, "a zipped axis needs a name that is not a parameter of "
                          f"{model.name}")
            self.claim(name, key)
            spec = inputs[name]
            values = self.axis_values(spec, raw, key) if spec.broadcast or not spec.dims else []
            if spec.dims and (not spec.broadcast or any(np.ndim(v.shown) for v in values)):
                self.fail(key, f"{name!r} is a pattern (one value per {spec.dims[0]}): vary it "
                          f"on a labelled axis, [axes.<name>] labels = [...], {name} = [...]")
            return Axis(name, {name: values})
        if not isinstance(raw, dict):
            self.claim(name, key)  # not an input: refused as one
        if not AXIS_NAME.fullmatch(name):
            self.fail(key, f"{short(name)!r} cannot name an axis: a name starts with a letter "
                      "and holds letters, digits and underscores, at most 64 characters (CF "
                      "conventions 2.3; netCDF and zarr read other characters as paths or "
                      "refuse them)")
        taken = {o.name for o in model.outputs} | {d for o in model.outputs for d in o.dims} \
            | {f"{o.name}_units" for o in model.outputs if o.entry_units} \
            | {f"{o.name}_over_duty_cycle" for o in model.outputs}
        if name in taken | RESERVED_NAMES:
            self.fail(key, f"the axis name {name!r} is taken by an output or its dimension"
                      if name in taken else f"the axis name {name!r} is reserved (for the "
                      "status of each point, the [sample] axis, the analysis of a sampled "
                      "result and a duty cycle's time shares and status)")
        values = {}
        for parameter, column in raw.items():
            if parameter in ("labels", TIME_SHARE):
                continue
            self.claim(parameter, f"{key}.{parameter}")
            values[parameter] = self.axis_values(inputs[parameter], column, f"{key}.{parameter}",
                                                 zipped=True)
        if not values:
            self.fail(key, "a zipped axis needs at least one parameter besides 'labels'")
        for parameter, column in values.items():
            sizes = {np.size(v.si) for v in column if np.ndim(v.shown)} | {1}
            if len(sizes) > 2:
                self.fail(f"{key}.{parameter}", "the patterns differ in length ("
                          + ", ".join(str(n) for n in sorted(sizes - {1})) + " values)")
        lengths = {p: len(v) for p, v in values.items()}
        labels = raw.get("labels")
        if labels is not None:
            self.check_labels(labels, f"{key}.labels")
            lengths["labels"] = len(labels)
        shares = None
        if TIME_SHARE in raw:
            shares = self.time_shares(raw[TIME_SHARE], f"{key}.{TIME_SHARE}")
            lengths[TIME_SHARE] = len(shares)
        if len(set(lengths.values())) > 1:
            described = ", ".join(f"{p} has {n}" for p, n in lengths.items())
            self.fail(key, f"ragged zipped axis: {described} values; all must have the same number")
        if shares is not None and "speed" in values and not any(
                share * np.max(v.si) > 0 for share, v in zip(shares, values["speed"])):
            self.fail(f"{key}.{TIME_SHARE}", "every load case that takes time is at rest "
                      "(speed 0): a duty cycle's lives share its revolutions, and there are none")
        return Axis(name, values, labels if labels is not None else list(range(len(
            next(iter(values.values()))))), shares)

    def time_shares(self, raw, key: str) -> list[float]:
        """A duty cycle's time shares: numbers >= 0, not all 0 (their sum need not be 1: the
        shares are in proportion to them), for a model with a life to combine."""
        if not any(o.cycle for o in self.model.outputs):
            self.fail(key, f"a duty cycle combines rating lives, and {self.model.name!r} "
                      "reports none: leave time_share out")
        if not isinstance(raw, list) or not raw or not all(
                isinstance(x, (int, float)) and not isinstance(x, bool) for x in raw):
            self.fail(key, "expected a non-empty list of numbers, each load case's share of "
                      "the duty cycle's time (in proportion: 0.25 or 25 or 6 h alike)")
        for index, share in enumerate(raw):
            if not (math.isfinite(share) and share >= 0):
                self.fail(f"{key}[{index}]", f"{share!r}: a share of time is a finite number "
                          ">= 0")
        for index, share in enumerate(raw):
            if isinstance(share, int):
                self.reader.fits(share, f"{key}[{index}]")
        if not max(raw) > 0:
            self.fail(key, "every share is 0: give at least one load case a share of the time")
        return [float(x) for x in raw]

    def check_labels(self, labels, key: str):
        """A zipped axis' labels: strings a file stores as written, or integers in order."""
        if not isinstance(labels, list) or not labels or not all(
                isinstance(x, (str, int)) and not isinstance(x, bool) for x in labels):
            self.fail(key, "expected a non-empty list of strings or integers")
        for index, label in enumerate(labels):
            if isinstance(label, str) and not (0 < len(label) <= 256 and label.isprintable()):
                self.fail(f"{key}[{index}]", f"{short(label)!r}: a label is 1 to 256 printable "
                          "characters (no control characters: a file would not keep them)")
            if isinstance(label, int):
                self.reader.fits(label, f"{key}[{index}]")
        if len({type(x) for x in labels}) > 1:
            self.fail(key, "labels are all strings or all integers")
        if len(set(labels)) != len(labels):
            self.fail(key, "labels must be unique")
        if isinstance(labels[0], int):
            self.monotonic(labels, key, "labels")

    def monotonic(self, numbers, key: str, what: str = "values"):
        """Refuse numbers of an axis out of order: a coordinate variable is strictly
        monotonic (CF conventions 1.10, section 5), so that a reader can select ranges."""
        steps = np.sign(np.diff(np.asarray(numbers, dtype=float)))
        if len(steps) and not (np.all(steps > 0) or np.all(steps < 0)):
            turn = int(np.argmax(steps != steps[0])) + 1  # the first value out of order
            self.fail(f"{key}[{turn}]" if what == "values" else key,
                      f"the {what} of an axis run in one direction, increasing or decreasing "
                      f"(CF 1.10 section 5: a coordinate is monotonic); sort them")

    def axis_values(self, spec: Input, raw, key: str, zipped=False) -> list[Value]:
        """The values of one parameter on an axis (``zipped``: one column of a zipped axis,
        whose values may repeat and come in any order)."""
        value = self.values.value
        if isinstance(raw, list):
            values = [value(spec, item, f"{key}[{i}]") for i, item in enumerate(raw)]
        elif isinstance(raw, dict) and set(raw) <= VALUES_KEYS and "values" in raw:
            if not isinstance(raw["values"], list):
                self.fail(f"{key}.values", "expected a list")
            unit = raw.get("units")
            values = [value(spec, item, f"{key}.values[{i}]", unit)
                      for i, item in enumerate(raw["values"])]
        elif isinstance(raw, dict) and set(raw) <= _RANGE_KEYS and {"start", "stop"} <= set(raw):
            values = self.value_range(spec, raw, key)
        else:
            self.fail(key, "an axis is a list of values, {values = [...], units = \"...\"} or "
                      "{start = ..., stop = ..., num = ... (or step = ...)}")
        if not values:
            self.fail(key, "empty axis: give at least one value")
        if not zipped and not any(np.ndim(v.si) for v in values):
            self.unique(values, key)
            if not isinstance(values[0].si, str):
                self.monotonic([v.si for v in values], key)
        return same_unit(values)

    def value_range(self, spec: Input, raw: dict, key: str) -> list[Value]:
        if spec.kind in ("choice", "subset") or (spec.dims and not spec.broadcast):
            self.fail(key, f"{spec.name!r} cannot take a range; list its values")
        if ("num" in raw) == ("step" in raw):
            self.fail(key, "a range needs exactly one of 'num' (number of values) or 'step'")
        value = self.values.value
        unit = raw.get("units")
        start = value(spec, raw["start"], f"{key}.start", unit, check_range=False)
        stop = value(spec, raw["stop"], f"{key}.stop", unit, check_range=False)
        with np.errstate(over="ignore", invalid="ignore"):
            stop_shown = convert_written(stop.shown, stop.unit, start.unit) \
                if start.unit not in ("", "1") else stop.shown
        if not np.isfinite(stop_shown):
            self.fail(f"{key}.stop", f"{written(raw['stop'])} is too large to compute with in "
                      f"the unit of the start ({start.unit})")
        if "num" in raw:
            num = raw["num"]
            if isinstance(num, bool) or not isinstance(num, int) or num < 1:
                self.fail(f"{key}.num", f"{num!r}: expected an integer >= 1")
            self.axis_size(num, f"{key}.num")
            if num == 1 and not np.isclose(stop_shown, start.shown, rtol=SAME_VALUE, atol=0):
                self.fail(f"{key}.num", "1 value from start to a different stop would leave the "
                          "stop out: give num >= 2, or the one value as a list")
            shown = units.tidy(np.linspace(start.shown, stop_shown, num))
        else:
            step = value(spec, raw["step"], f"{key}.step", unit, check_range=False)
            step_shown = step.shown
            if start.unit not in ("", "1"):  # a step is a difference: 10 K on a degC axis
                with np.errstate(over="ignore", invalid="ignore", under="ignore"):
                    step_shown = convert_written(step.shown, step.unit, start.unit,
                                                 difference=True)
            if not step_shown > 0:
                self.fail(f"{key}.step", "the step must be positive")
            with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
                count = np.floor((stop_shown - start.shown) / step_shown + 1e-9) + 1
            if count < 1:
                self.fail(key, "empty axis: 'stop' is below 'start'")
            if count == 1 and not np.isclose(stop_shown, start.shown, rtol=SAME_VALUE, atol=0):
                self.fail(f"{key}.step", "the step is larger than the range from start to stop: "
                          "the axis would hold the start only; take a smaller step")
            self.axis_size(count, f"{key}.step")
            shown = units.tidy(start.shown + step_shown * np.arange(int(count)))
        if spec.kind == "count":
            return [value(spec, float(x), f"{key}") for x in shown]
        if spec.dims:
            return [value(spec, float(x), f"{key}", start.unit) for x in shown]
        return self.range_values(spec, shown, key, start.unit)

    def range_values(self, spec: Input, shown: np.ndarray, key: str, unit_text: str):
        """The values of a scalar quantity's range, all in ``unit_text``: the first checked
        by :meth:`ValueReader.value` (units and all), the rest converted and range-checked at
        once (a long axis would otherwise cost a unit parse per value)."""
        first = self.values.value(spec, float(shown[0]), key, unit_text)
        declared = units.parse_unit(spec.unit)
        unit = units.revolutions(units.parse_unit(unit_text), declared)
        si = self.values.finite_si(spec, shown, unit, key, "a value of the range")
        self.values.in_range(spec, convert_written(shown, unit, declared), spec.unit, key,
                             list(shown))
        return [first] + [Value(float(a), float(b), unit_text)
                          for a, b in zip(si[1:], shown[1:])]

    def axis_size(self, count, key: str):
        """Refuse an axis too long to validate, from its arithmetic alone."""
        if not count <= MAX_AXIS_VALUES:
            self.fail(key, f"the axis would have {float(count):.3g} values, more than "
                      f"{MAX_AXIS_VALUES:.0e} on one axis; take fewer values or a larger step")

    def unique(self, values: list[Value], key: str):
        """Refuse an axis that names one value twice ("1 kN" and "1000 N", "70 degC" and
        "158 degF"): its index would not be unique. Quantities are compared in SI, as equal
        within :data:`SAME_VALUE` of their size, so that two spellings of one value that
        differ only by rounding in the conversion count as one."""
        order = sorted(range(len(values)), key=lambda i: _order_key(values[i].si))
        for before, after in zip(order, order[1:]):
            first, second = values[before].si, values[after].si
            same = first == second if isinstance(first, str) or isinstance(second, str) \
                else abs(first - second) <= SAME_VALUE * max(abs(first), abs(second))
            if same:
                index, earlier = max(before, after), min(before, after)
                value = values[index]
                self.fail(f"{key}[{index}]", f"{plain(value.shown)!s}"
                          f"{'' if value.unit in ('', '1') else ' ' + value.unit} is the same "
                          f"value as {self.reader.key(key)}[{earlier}]: each value of an axis "
                          "must differ")


def same_unit(values: list[Value]) -> list[Value]:
    """Every value of an axis expressed in the unit of its first value."""
    first = values[0].unit
    if first in ("", "1"):
        return values
    return [v if v.unit == first else Value(v.si, convert_written(v.shown, v.unit, first), first)
            for v in values]


def _order_key(si) -> tuple:
    """Sorts an axis' values: strings (choices) apart from numbers."""
    return (1, si, 0.0) if isinstance(si, str) else (0, "", float(si))
