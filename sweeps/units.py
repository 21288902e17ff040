"""Units at the boundary: parse what users write, convert to SI for the models and back."""
from __future__ import annotations

import os
import re
import shutil
import sys
import tempfile
from functools import lru_cache
from pathlib import Path

import numpy as np
import pint


def _registry(folder: Path) -> pint.UnitRegistry:
    """pint's registry, its parsed definitions kept in ``folder`` for the next process.

    Parsing pint's definitions costs a seventh of a second, every run and every worker; read
    from pint's own cache they take a hundredth. The cache is written once, whole, into a
    folder of its own that is then renamed into place, so a process never reads one half
    written (pint writes its files in place); where it cannot be written (an installation
    that is not ours to write), or not read, the definitions are parsed as before.
    """
    if folder.is_dir():
        try:
            return pint.UnitRegistry(cache_folder=folder)
        except Exception:  # noqa: BLE001 (a cache we cannot read is one we do not use)
            pass
    try:
        folder.parent.mkdir(exist_ok=True)
        temporary = Path(tempfile.mkdtemp(prefix=folder.name, dir=folder.parent))
    except OSError:
        return pint.UnitRegistry()
    try:
        registry = pint.UnitRegistry(cache_folder=temporary)
        os.rename(temporary, folder)  # another process may have been first: then it stays
    except OSError:
        pass
    finally:
        shutil.rmtree(temporary, ignore_errors=True)
    return registry


UREG = _registry(Path(__file__).parent / "__pycache__"
                 / f"pint-{pint.__version__}.{sys.implementation.cache_tag}")
# Engineers write rotational speeds in r/min (DIN 1301) as often as in rpm.
UREG.define("@alias turn = r = rev")

_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


class UnitError(ValueError):
    """A unit that cannot be read or does not fit; the message is for the user."""


#: The longest unit text read, and the largest power in one: a unit that needs more is a
#: mistake, and pint's evaluation of one ("N*N*...", "N^(2^(2^9))") recurses or never ends.
MAX_UNIT_LENGTH = 64
MAX_POWER = 10
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_POWER = re.compile(r"(?:\^|\*\*)\s*(?:(" + _NUMBER + r")|\(\s*(" + _NUMBER + r")\s*(?:/\s*("
                    + _NUMBER + r")\s*)?\))(?![\w.]*\s*(?:\^|\*\*))")
_POWER_SIGN = re.compile(r"\^|\*\*")


def parse_unit(text: str) -> pint.Unit:
    """The pint unit for ``text`` ("mm", "N/mm^(10/9)", "rpm", "1", ...)."""
    if not isinstance(text, str):
        raise UnitError(f"{text!r} is not a unit: expected a string")
    return _parsed_unit(text)


@lru_cache(maxsize=1024)  # every value of an axis names its unit: parse each unit once
def _parsed_unit(text: str) -> pint.Unit:
    problem = _unreadable(text)
    if problem:
        raise UnitError(f"unknown unit {_short(text)!r} ({problem})")
    try:
        return UREG.parse_units(text)
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError,
            AttributeError, TypeError, ValueError, AssertionError, ArithmeticError,
            RecursionError) as error:
        raise UnitError(f"unknown unit {_short(text)!r}") from error


def _unreadable(text: str) -> str | None:
    """Why a unit text is refused before pint reads it, or None."""
    if len(text) > MAX_UNIT_LENGTH:
        return f"longer than {MAX_UNIT_LENGTH} characters"
    powers = list(_POWER.finditer(text))
    if len(powers) != len(_POWER_SIGN.findall(text)):
        return "a power is a number or a (fraction), e.g. mm^2 or mm^(10/9)"
    for power in powers:
        numerator, denominator = float(power.group(1) or power.group(2)), power.group(3)
        if denominator is not None and float(denominator) == 0:
            return "a power divided by zero"
        exponent = numerator / float(denominator) if denominator else numerator
        if not abs(exponent) <= MAX_POWER:
            return f"powers are at most {MAX_POWER}"
    depth = 0
    for character in text:
        depth += (character == "(") - (character == ")")
        if depth > 2:
            return "parentheses nested too deeply"
    return None


def _short(text: str) -> str:
    return text if len(text) <= 40 else text[:37] + "..."


def split_quantity(text: str) -> tuple[float, str]:
    """Split ``"0.04 mm"`` into ``(0.04, "mm")``; the unit is ``""`` when none is written."""
    match = _QUANTITY.match(text)
    special = re.match(r"\s*[-+]?(nan|inf)", text, re.IGNORECASE)
    if not match and special:
        raise UnitError(f"{text!r}: " + ("NaN is not a number" if special.group(1).lower()
                                         == "nan" else "an infinite value is not accepted"))
    if not match:
        raise UnitError(f"{text!r} is not a number followed by a unit")
    return float(match.group(1)), match.group(2)


def _angle_power(unit: pint.Unit) -> float:
    # pint treats angles as dimensionless, so 'Hz' would pass for 'rpm' by dimension alone;
    # comparing the power of radian in the root units keeps cycles and radians apart.
    return dict(UREG.get_root_units(unit)[1]._units).get("radian", 0.0)


def compatible(unit: pint.Unit, declared: pint.Unit) -> bool:
    """Whether a value in ``unit`` can be given for a parameter declared in ``declared``."""
    return (unit.dimensionality == declared.dimensionality
            and np.isclose(_angle_power(unit), _angle_power(declared)))


def is_offset(unit: pint.Unit) -> bool:
    """Whether ``unit`` has a shifted zero (degC, degF): its differences are other units."""
    return not UREG.Quantity(1.0, unit)._is_multiplicative


def as_difference(unit: pint.Unit) -> pint.Unit:
    """The unit of a difference of values in ``unit``: delta_degC for degC, the unit itself
    for K or mm (a step of "15 degC" on a temperature axis is 15 kelvin wide)."""
    return UREG.parse_units("delta_" + str(unit)) if is_offset(unit) else unit


def revolutions(unit: pint.Unit, declared: pint.Unit) -> pint.Unit:
    """A plain reciprocal time ("1/min", "min^-1") given for a rotational speed, read as
    revolutions per that time (DIN 1301's speed in 1/min); every other unit unchanged.
    ``Hz`` is left alone, to be refused: pint reads it as radians per second."""
    if (_angle_power(declared) == 1 and _angle_power(unit) == 0
            and unit.dimensionality == UREG.parse_units("1/s").dimensionality
            and "hertz" not in str(unit)):
        return unit * UREG.turn
    return unit


def _read_as_revolutions(unit: pint.Unit, target: pint.Unit) -> tuple[pint.Unit, pint.Unit]:
    """``unit`` and ``target`` with a plain reciprocal time on either side read as revolutions
    when the other is a rotational speed (:func:`revolutions`); a conversion between a
    frequency and a rotational speed that is still left (Hz against rpm) is refused, as pint
    would take it for radians. An angle to a plain number is pint's: radians ("deg" to "1")."""
    unit, target = revolutions(unit, target), revolutions(target, unit)
    per_time = UREG.parse_units("1/s").dimensionality
    if (unit.dimensionality == per_time
            and not np.isclose(_angle_power(unit), _angle_power(target))):
        raise UnitError(f"{_shown(unit)!r} and {_shown(target)!r} differ by an angle (Hz is "
                        "ambiguous for a rotational speed: write rpm, r/min or 1/min)")
    return unit, target


def _shown(unit: pint.Unit) -> str:
    return f"{unit:~}" or "1"


def to_si(magnitude, unit: pint.Unit):
    """``magnitude`` in ``unit``, converted to SI base units (rad/s for rpm, m for mm, ...)."""
    return UREG.Quantity(np.asarray(magnitude, dtype=float), unit).to_base_units().magnitude


def convert(magnitude, unit: pint.Unit, target: pint.Unit):
    """``magnitude`` in ``unit`` expressed in ``target``.

    The one conversion between two units that every value passes through (what was written
    to the declared unit, an axis' values to its first one's, a quantity to select by to
    the stored unit): a plain reciprocal time is revolutions per that time against a
    rotational speed on either side ("3000 1/min" is 3000 rpm), never radians.
    """
    unit, target, factor = _conversion(unit, target)
    magnitude = np.asarray(magnitude, dtype=float)
    if factor is None:
        return UREG.Quantity(magnitude, unit).to(target).magnitude
    return magnitude * factor  # as pint multiplies, without its cost for every value


@lru_cache(maxsize=1024)  # once per pair of units, not per value converted
def _conversion(unit: pint.Unit, target: pint.Unit) -> tuple:
    """:func:`_read_as_revolutions`' units and the factor pint multiplies a value in the one
    by to express it in the other; None where either has a shifted zero (pint adds the
    offsets)."""
    unit, target = _read_as_revolutions(unit, target)
    if is_offset(unit) or is_offset(target):
        return unit, target, None
    return unit, target, UREG.Quantity(1.0, unit).to(target).magnitude


def tidy(values, scale: float = 0.0) -> np.ndarray:
    """``values`` to 15 significant digits, as written: the last bit a conversion or a
    range's arithmetic leaves is gone, so that "4 kN" is stored as 4000 N, not
    4000.0000000000005, and a range's third step of 0.1 as 0.3. Where a conversion went
    through larger numbers (``scale``: 273.15 for a temperature), the values are rounded at
    that size's 15th digit: "32 degF" is 0 degC, not 5.7e-14."""
    values = np.asarray(values, dtype=float)
    if scale:  # at the 15th digit of the scale
        values = np.round(values, int(14 - np.floor(np.log10(abs(scale))))) + 0.0  # not -0
    if values.ndim == 0:  # one value of an axis: most of them
        return np.array(float(f"{values:.15g}"))
    return np.array([float(f"{v:.15g}") for v in values.ravel()]).reshape(values.shape)


@lru_cache(maxsize=1024)
def conversion_scale(unit: pint.Unit, target: pint.Unit) -> float:
    """The size of the numbers a conversion from ``unit`` to ``target`` goes through: an
    offset unit's zero (absolute zero in degC is -273.15), else 0."""
    if not (is_offset(unit) or is_offset(target)):
        return 0.0
    return float(abs(UREG.Quantity(0.0, "kelvin").to(target).magnitude)) if is_offset(target) \
        else float(abs(UREG.Quantity(0.0, "kelvin").to(unit).magnitude))


def from_si(values, unit_text: str):
    """SI values expressed in ``unit_text`` (the customary unit of a model output)."""
    unit, base, factor = _from_base(unit_text)
    values = np.asarray(values, dtype=float)
    if factor is None:
        return UREG.Quantity(values, base).to(unit).magnitude
    return values * factor  # what pint multiplies by, without its cost for every chunk


@lru_cache(maxsize=None)
def _from_base(unit_text: str):
    """``unit_text`` parsed, its SI base unit and the factor from that unit to it (None for
    a shifted zero): parsing costs more than converting a block of a few thousand values,
    and every block of a sweep converts the same units."""
    unit = parse_unit(unit_text)
    base = UREG.get_base_units(unit)[1]
    factor = None if is_offset(unit) else UREG.Quantity(1.0, base).to(unit).magnitude
    return unit, base, factor


_FRACTIONAL_POWER = re.compile(r"\^\s*\(?\s*-?\d*\.\d|\^\s*\(\s*-?\d+\s*/")


def cf_units(text: str) -> str | None:
    """``text`` as a UDUNITS-2 unit string for a netCDF ``units`` attribute ("deg" ->
    "degree"), or None where UDUNITS has no form for it: a fractional power ("N/mm^1.5"
    would read as 5000 N/m)."""
    if _FRACTIONAL_POWER.search(text):
        return None
    return re.sub(r"\bdeg\b", "degree", text)


def si_text(text: str) -> str:
    """A unit with a fractional power written in metres ("N/mm^1.5" -> "N/m^1.5"): the unit
    of its values in SI."""
    return re.sub(r"\bmm\b", "m", text)


def stored_unit(unit: str) -> str:
    """The unit values are stored in: the declared one, or SI where UDUNITS cannot express
    the declared one (a fractional power: "N/mm^1.5" would read as 5000 N/m)."""
    return unit if cf_units(unit or "1") is not None else si_text(unit)
