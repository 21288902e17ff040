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
