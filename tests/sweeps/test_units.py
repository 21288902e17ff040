"""pint's registry read from its cache beside the package: the same units as one parsed anew,
and parsed anew wherever the cache cannot be read or written."""
import pint
import pytest

from bearing_sweep import units
from bearing_sweep.models.registry import all_models

WRITTEN = ["rpm", "r/min", "1/min", "degC", "delta_degC", "um", "N/mm^(10/9)", "mm^2/s",
           "kN", "deg", "Mturn", "h", "thou", "GPa", "kg/m^3"]


def _declared_and_written():
    declared = {item.unit for model in all_models().values()
                for item in model.inputs + model.outputs if item.unit and "," not in item.unit}
    return sorted(declared | set(WRITTEN))


def _same_units(registry: pint.UnitRegistry, fresh: pint.UnitRegistry):
    registry.define("@alias turn = r = rev")
    for text in _declared_and_written():
        ours, theirs = registry.Quantity(2.5, text), fresh.Quantity(2.5, text)
        assert str(ours.dimensionality) == str(theirs.dimensionality), text
        if ours._is_multiplicative:
            assert ours.to_base_units().magnitude == theirs.to_base_units().magnitude, text


@pytest.fixture(scope="module")
def fresh():
    registry = pint.UnitRegistry()
    registry.define("@alias turn = r = rev")
    return registry


def test_a_cached_registry_reads_every_unit_as_one_parsed_anew(tmp_path, fresh):
    folder = tmp_path / "pint"
    _same_units(units._registry(folder), fresh)  # parses, and writes the cache
    assert any(folder.glob("*.pickle"))
    assert [p.name for p in tmp_path.iterdir()] == ["pint"]  # no half-made folder left
    _same_units(units._registry(folder), fresh)  # read from the cache


def test_an_unreadable_cache_is_parsed_anew(tmp_path, fresh):
    folder = tmp_path / "pint"
    units._registry(folder)
    for pickled in folder.glob("*.pickle"):
        pickled.write_bytes(b"not a pickle")
    _same_units(units._registry(folder), fresh)
    assert [p.name for p in tmp_path.iterdir()] == ["pint"]


def test_a_place_that_cannot_be_written_parses_anew(tmp_path, fresh):
    (tmp_path / "a file").write_text("")
    _same_units(units._registry(tmp_path / "a file" / "pint"), fresh)
    assert [p.name for p in tmp_path.iterdir()] == ["a file"]


@pytest.mark.parametrize("text", [
    "*".join(["N"] * 5000), "(" * 3000 + "N" + ")" * 3000, "N" + "^2" * 2000, "k" * 5000 + "N",
    "N^(2^(2^(2^9)))", "N^2^2^2^2^2^2", "N**1e308", "N^1e20", "N^(1/0)", "N/0", "N^N", "N^-",
    "N**0.5**2", "((((N))))", "N;import os", "__class__", "N.__class__", "[N]"])
def test_a_unit_pint_cannot_read_safely_is_one_error(text):
    # Each was a RecursionError, a ZeroDivisionError or a computation that never ends.
    with pytest.raises(units.UnitError) as caught:
        units.parse_unit(text)
    assert "\n" not in str(caught.value) and len(str(caught.value)) < 200


@pytest.mark.parametrize("text", ["N/mm^(10/9)", "N/mm^1.5", "N/mm^1.11", "mm^2/s", "kg/m^3",
                                  "m**-1", "1/GPa", "N*m", "lbf*in", "(N/mm)^2", "%"])
def test_the_units_of_bearings_are_read(text):
    assert units.parse_unit(text) is not None


@pytest.mark.parametrize("written, declared, value, expected", [
    ("1/min", "rpm", 3000, 3000), ("min^-1", "rpm", 3000, 3000), ("1/s", "rpm", 50, 3000),
    ("rpm", "1/min", 3000, 3000), ("r/min", "rad/s", 60, 2 * 3.141592653589793),
    ("1/min", "rad/s", 60, 2 * 3.141592653589793)])
def test_a_plain_reciprocal_time_against_a_speed_is_revolutions_either_way(written, declared,
                                                                          value, expected):
    # DIN 1301-2: a rotational speed in 1/min counts revolutions.
    converted = units.convert(value, units.parse_unit(written), units.parse_unit(declared))
    assert converted == pytest.approx(expected, rel=1e-14)


def test_hertz_against_a_speed_is_refused_not_read_as_radians():
    with pytest.raises(units.UnitError, match="Hz is ambiguous"):
        units.convert(50, units.parse_unit("Hz"), units.parse_unit("rpm"))


def test_an_angle_to_a_plain_number_is_in_radians_as_pint_reads_it():
    # Not a speed: the refusal of Hz against rpm leaves angles alone ("deg" -> "1": radians).
    assert units.convert(180, units.parse_unit("deg"), units.parse_unit("1")) == \
        pytest.approx(3.141592653589793, rel=1e-15)
