"""One value of a model's input: read as written (a quantity such as ``"10 mm"``, a number
in the declared unit of a dimensionless input, a choice, a pattern), checked against the
input's range, and converted to SI for the model; and the one conversion of a value written in
one unit to another (:func:`convert_written`) that axes, stored coordinates and selections by
quantity share."""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from ..models.registry import Input
from .. import units
from .tables import Reader, integers, plain, suggestion, written

#: The keys of a table that gives numbers and their unit apart.
VALUES_KEYS = {"values", "units"}


@dataclass(frozen=True)
class Value:
    """One parameter value: in SI for the model, and as written for the netCDF file."""

    si: object  # float, int, str or numpy array, in SI base units
    shown: object  # the magnitude in ``unit``
    unit: str  # the unit the user wrote; "1" when dimensionless, "" for a choice


def stack(values: list[Value]) -> np.ndarray:
    """The SI values of an axis (or a fixed value) as one array, points first; a single
    value given for a pattern input is repeated to the length of the others."""
    first = values[0].si
    if isinstance(first, str):
        return np.array([v.si for v in values], dtype=object)
    if isinstance(first, (int, np.integer)):
        return np.array([v.si for v in values], dtype=np.int64)
    arrays = [np.asarray(v.si, dtype=float) for v in values]
    if len({a.shape for a in arrays}) > 1:  # single values stand for a whole pattern
        size = max(a.size for a in arrays)
        arrays = [np.broadcast_to(a, (size,)) for a in arrays]
    return np.stack(arrays)


@lru_cache(maxsize=256)
def _parsed(text: str):
    return units.parse_unit(text)


def convert_written(magnitude, unit, target, *, difference: bool = False,
                    tidy: bool = False):
    """``magnitude``, written in ``unit``, expressed in ``target`` (each a unit's text or a
    parsed unit): the one way from what a definition or a
    selection wrote to the unit an axis, a stored coordinate or a range check wants.

    ``difference``: the magnitude is a difference (a step or a width: "10 K" on a degC
    axis). ``tidy``: rounded to 15 digits, as stored (:func:`units.tidy`). A plain
    reciprocal time against a rotational speed is revolutions per that time
    (:func:`units.convert`); units that do not fit raise pint's ``DimensionalityError``.
    """
    unit = _parsed(unit) if isinstance(unit, str) else unit
    target = _parsed(target) if isinstance(target, str) else target
    if difference:
        unit, target = units.as_difference(unit), units.as_difference(target)
    converted = units.convert(magnitude, unit, target)
    return units.tidy(converted, units.conversion_scale(unit, target)) if tidy else converted


def default_value(spec: Input) -> Value:
    """The value an input takes where a definition leaves it out."""
    if spec.kind == "subset":
        return Value(" ".join(spec.default), " ".join(spec.default), "")
    if spec.kind in ("choice", "count"):
        return Value(spec.default, spec.default, spec.unit)
    unit = units.parse_unit(spec.unit)
    return Value(float(units.to_si(spec.default, unit)), spec.default, spec.unit)


class ValueReader:
    """Reads single values of inputs; a mistake is a :class:`SpecError` from ``reader``."""

    def __init__(self, reader: Reader):
        self.reader = reader
        self.fail = reader.fail

    def value(self, spec: Input, raw, key: str, unit_text=None, check_range=True,
              fixed=False) -> Value:
        """One value of ``spec`` (a whole pattern for an array input); ``unit_text``: the
        unit given beside plain numbers; ``fixed``: given in [fixed], where a list is
        refused as an axis put in the wrong table."""
        for number in integers(raw):
            self.reader.fits(number, key)
        if spec.kind == "choice":
            if not isinstance(raw, str) or raw not in spec.choices:
                self.fail(key, f"{raw!r} is not accepted; {spec.name} is {spec.range_text()}"
                          + suggestion(str(raw), spec.choices))
            return Value(raw, raw, "")
        if spec.kind == "subset":
            return self.subset(spec, raw, key)
        if spec.dims and spec.broadcast and not isinstance(raw, (list, dict)):
            one = self.value(replace(spec, dims=()), raw, key, unit_text, check_range, fixed)
            return Value(np.atleast_1d(one.si), one.shown, one.unit)  # stands for every entry
        if unit_text is not None and spec.kind == "count":
            self.fail(key, f"{spec.name!r} is a count and takes no units")
        if spec.kind == "count":
            if (isinstance(raw, bool) or not isinstance(raw, (int, float))
                    or not np.isfinite(raw) or raw != int(raw)):
                self.fail(key, f"{raw!r}: {spec.name} must be {spec.range_text()}")
            if check_range:
                self.in_range(spec, int(raw), "1", key, raw)
            return Value(int(raw), int(raw), "1")
        magnitude, unit_text = self.magnitude(spec, raw, key, unit_text, fixed)
        try:
            unit = units.parse_unit(unit_text)
        except units.UnitError as error:
            self.fail(key, f"{error}; {spec.name} is in units like {spec.unit!r}")
        declared = units.parse_unit(spec.unit)
        unit = units.revolutions(unit, declared)
        if not units.compatible(unit, declared):
            hint = ""
            if unit_text.strip() in ("mil", "mils") and unit.dimensionless:
                hint = " (pint reads 'mil' as an angle; a thousandth of an inch is 'thou')"
            elif "hertz" in str(unit):
                hint = " (Hz is ambiguous for a rotational speed: write rpm, r/min or 1/min)"
            self.fail(key, f"units {unit_text!r} do not fit {spec.name}, which is in units like "
                      f"{spec.unit!r}{hint}")
        si = self.finite_si(spec, magnitude, unit, key, raw)
        if check_range:
            try:
                in_declared = convert_written(magnitude, unit, declared)
            except units.pint.errors.DimensionalityError:  # delta_degC for a temperature
                self.fail(key, f"{raw!r} is a difference of temperatures; {spec.name} is a "
                          f"temperature, in units like {spec.unit!r}")
            self.in_range(spec, in_declared, spec.unit, key, raw)
        return Value(si if spec.dims else float(si), magnitude, unit_text)

    def subset(self, spec: Input, raw, key: str) -> Value:
        """A list of distinct choices, as their names in declared order joined by spaces."""
        if not isinstance(raw, list) or not all(isinstance(x, str) for x in raw):
            self.fail(key, f"{raw!r}: {spec.name} is {spec.range_text()}, e.g. "
                      f"[{', '.join(repr(c) for c in spec.choices[:2])}] (on an axis: a list "
                      "of such lists)")
        for item in raw:
            if item not in spec.choices:
                self.fail(key, f"{item!r} is not accepted; {spec.name} is {spec.range_text()}"
                          + suggestion(item, spec.choices))
        if len(set(raw)) != len(raw):
            self.fail(key, f"{raw!r}: a value is listed twice")
        names = " ".join(c for c in spec.choices if c in raw)
        return Value(names, names, "")

    def magnitude(self, spec: Input, raw, key: str, unit_text, fixed=False):
        """The number(s) and unit text of a quantity written in any accepted form."""
        dimensionless = spec.unit == "1"
        if spec.dims:
            if isinstance(raw, dict) and set(raw) <= VALUES_KEYS and "values" in raw:
                raw, unit_text = raw["values"], raw.get("units", unit_text)
            if not isinstance(raw, list) or not raw:
                self.fail(key, f"{spec.name!r} is a pattern: a non-empty list, or "
                          "{values = [...], units = \"...\"}")
            if all(isinstance(x, str) for x in raw) and unit_text is None:
                return self.quantities(spec, raw, key)
            if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in raw):
                self.fail(key, f"{spec.name!r}: the pattern must hold numbers (with 'units') or "
                          "quantity strings")
            raw = np.array(raw, dtype=float)
        elif isinstance(raw, str):
            if unit_text is not None:
                self.fail(key, f"{raw!r}: give plain numbers together with 'units'")
            raw, unit_text = self.split(raw, spec, key)
            unit_text = unit_text or None
        elif isinstance(raw, list) and fixed:
            self.fail(key, "[fixed] takes one value; a list of values is an axis: put it in [axes]")
        elif isinstance(raw, bool) or not isinstance(raw, (int, float)):
            self.fail(key, f"{raw!r}: expected a number with units, e.g. '1.5 {spec.unit}'")
        if unit_text is None:
            if not dimensionless:
                self.fail(key, f"{raw!r} has no units; {spec.name} needs units like "
                          f"{spec.unit!r} (write e.g. '{plain(raw)} {spec.unit}')")
            unit_text = "1"
        return raw, unit_text

    def quantities(self, spec: Input, raw: list, key: str):
        """A pattern written as quantity strings, in the unit of its first entry."""
        parts = [self.split(x, spec, f"{key}[{i}]") for i, x in enumerate(raw)]
        found = []
        for i, (_, text) in enumerate(parts):
            if not text and spec.unit != "1":
                self.fail(f"{key}[{i}]", f"{raw[i]!r} has no units; {spec.name} needs "
                          f"units like {spec.unit!r}")
            found.append(self.unit_of(text or "1", f"{key}[{i}]"))
            if not units.compatible(found[-1], found[0]):
                self.fail(f"{key}[{i}]", f"{raw[i]!r}: units differ in kind from {raw[0]!r}")
        return np.array([convert_written(m, u, found[0]) for (m, _), u in
                         zip(parts, found)]), parts[0][1] or "1"

    def split(self, text: str, spec: Input, key: str) -> tuple[float, str]:
        try:
            return units.split_quantity(text)
        except units.UnitError as error:
            self.fail(key, f"{error}; write e.g. '1.5 {spec.unit}'")

    def unit_of(self, text: str, key: str):
        try:
            return units.parse_unit(text)
        except units.UnitError as error:
            self.fail(key, str(error))

    def finite_si(self, spec: Input, magnitude, unit, key: str, raw):
        """``magnitude`` in ``unit`` converted to SI; a NaN, an infinity or a value whose
        conversion overflows is refused, each for what it is."""
        magnitude = np.asarray(magnitude, dtype=float)
        if np.isnan(magnitude).any():
            self.fail(key, f"{written(raw)} is not a number (NaN); {spec.name} must be "
                      f"{spec.range_text()}")
        if np.isinf(magnitude).any() and not isinstance(raw, str):
            self.fail(key, f"{written(raw)} is infinite; {spec.name} must be "
                      f"{spec.range_text()}")
        with np.errstate(over="ignore", invalid="ignore"):
            si = units.to_si(magnitude, unit)
        if not np.all(np.isfinite(si)):
            self.fail(key, f"{written(raw)} is too large to compute with (not finite in SI "
                      f"units); {spec.name} must be {spec.range_text()}")
        return si

    def in_range(self, spec: Input, magnitude, unit: str, key: str, raw):
        """Refuse values (in the declared unit) outside the input's valid range."""
        values = np.atleast_1d(np.asarray(magnitude, dtype=float))
        low = spec.minimum
        bad = ~np.isfinite(values)
        if low is not None:
            bad |= values <= low if spec.exclusive_minimum else values < low
        if spec.maximum is not None:
            bad |= values > spec.maximum
        if bad.any():
            shown = raw if not isinstance(raw, (list, dict)) else f"{values[bad][0]:g} {unit}"
            self.fail(key, f"{shown!r} is out of range: {spec.name} must be {spec.range_text()}")
