"""Every accepted spelling of every kind of input, followed to where a user reads it: the
stored coordinate or variable (in the model's declared unit) and the SI value the model is
given. The expected numbers come from the units' exact definitions, typed here (NIST SP 811,
appendix B; DIN 1301-1 for a speed in 1/min), not from pint."""
import math
import tomllib
from pathlib import Path

import pytest

from bearing_sweep import labels, spec
from bearing_sweep.models.catalogue import PRESETS
from bearing_sweep.models.registry import all_models
from bearing_sweep.spec import SpecError

EVERY_MODEL = Path(__file__).parents[1] / "data" / "every_model"

INCH = 0.0254  # m, exact
POUND = 0.45359237  # kg, exact
POUND_FORCE = POUND * 9.80665  # N, exact
PSI = POUND_FORCE / INCH**2  # Pa
TURN = 2 * math.pi  # rad

#: How many SI units one declared unit is (a temperature: its offset too).
SI_PER_DECLARED = {
    "rpm": TURN / 60, "N": 1.0, "mm": 1e-3, "um": 1e-6, "deg": math.pi / 180, "mrad": 1e-3,
    "rad": 1.0, "mm^2/s": 1e-6, "GPa": 1e9, "MPa": 1e6, "1/GPa": 1e-9, "kg/m^3": 1.0,
    "N*m": 1.0, "mPa*s": 1e-3, "1/K": 1.0, "kg": 1.0, "m/s": 1.0, "s": 1.0, "1": 1.0, "1/mm": 1e3, "N/m": 1.0,
    "m/s^2": 1.0,
}

#: Spellings of each declared unit: (unit as written, its magnitude for a declared value v).
SPELLINGS = {
    "rpm": [("rpm", lambda v: v), ("r/min", lambda v: v), ("rev/min", lambda v: v),
            ("revolution/minute", lambda v: v), ("1/min", lambda v: v),
            ("min^-1", lambda v: v), ("min**-1", lambda v: v), ("1/s", lambda v: v / 60),
            ("s^-1", lambda v: v / 60), ("r/s", lambda v: v / 60), ("1/h", lambda v: v * 60),
            ("rad/s", lambda v: v * TURN / 60), ("deg/s", lambda v: v * 360 / 60)],
    "N": [("N", lambda v: v), ("kN", lambda v: v / 1e3), ("lbf", lambda v: v / POUND_FORCE),
          ("kgf", lambda v: v / 9.80665)],
    "mm": [("mm", lambda v: v), ("m", lambda v: v / 1e3), ("um", lambda v: v * 1e3),
           ("in", lambda v: v / 25.4), ("thou", lambda v: v / 0.0254)],
    "um": [("um", lambda v: v), ("mm", lambda v: v / 1e3), ("nm", lambda v: v * 1e3),
           ("thou", lambda v: v / 25.4)],
    "deg": [("deg", lambda v: v), ("degree", lambda v: v), ("rad", lambda v: v * math.pi / 180),
            ("arcmin", lambda v: v * 60)],
    "mrad": [("mrad", lambda v: v), ("rad", lambda v: v / 1e3),
             ("deg", lambda v: v / 1e3 * 180 / math.pi)],
    "rad": [("rad", lambda v: v), ("deg", lambda v: v * 180 / math.pi)],
    "degC": [("degC", lambda v: v), ("K", lambda v: v + 273.15),
             ("degF", lambda v: v * 9 / 5 + 32), ("degR", lambda v: (v + 273.15) * 9 / 5)],
    "mm^2/s": [("mm^2/s", lambda v: v), ("cSt", lambda v: v), ("m^2/s", lambda v: v * 1e-6)],
    "GPa": [("GPa", lambda v: v), ("MPa", lambda v: v * 1e3),
            ("psi", lambda v: v * 1e9 / PSI)],
    "MPa": [("MPa", lambda v: v), ("GPa", lambda v: v / 1e3), ("psi", lambda v: v * 1e6 / PSI)],
    "1/GPa": [("1/GPa", lambda v: v), ("1/Pa", lambda v: v * 1e-9),
              ("1/MPa", lambda v: v * 1e-3)],
    "kg/m^3": [("kg/m^3", lambda v: v), ("g/cm^3", lambda v: v / 1e3),
               ("lb/in^3", lambda v: v * INCH**3 / POUND)],
    "N*m": [("N*m", lambda v: v), ("N*mm", lambda v: v * 1e3),
            ("lbf*in", lambda v: v / (POUND_FORCE * INCH))],
    "1/K": [("1/K", lambda v: v), ("1/MK", lambda v: v * 1e6), ("K^-1", lambda v: v)],
    "mPa*s": [("mPa*s", lambda v: v), ("cP", lambda v: v), ("Pa*s", lambda v: v / 1e3)],
    "kg": [("kg", lambda v: v), ("g", lambda v: v * 1e3), ("lb", lambda v: v / POUND)],
    "m/s": [("m/s", lambda v: v), ("mm/s", lambda v: v * 1e3), ("km/h", lambda v: v * 3.6)],
    "s": [("s", lambda v: v), ("ms", lambda v: v * 1e3), ("min", lambda v: v / 60)],
    "1": [("1", lambda v: v), ("%", lambda v: v * 100)],
    "1/mm": [("1/mm", lambda v: v), ("1/m", lambda v: v * 1e3), ("mm^-1", lambda v: v)],
    "N/m": [("N/m", lambda v: v), ("N/mm", lambda v: v / 1e3)],
    "m/s^2": [("m/s^2", lambda v: v), ("mm/s^2", lambda v: v * 1e3),
              ("ft/s^2", lambda v: v / 0.3048)],
}


def _si(declared: str, value: float) -> float:
    return value + 273.15 if declared == "degC" else value * SI_PER_DECLARED[declared]


def _document(model: str) -> dict:
    return tomllib.loads((EVERY_MODEL / f"{model}.toml").read_text())


def _declared_value(document: dict, item) -> float | None:
    """The input's value in its declared unit, from the definition or its preset as written
    there, or its default; None where it is written in another unit."""
    preset = PRESETS[document["sweep"]["bearing"]].values if "bearing" in document["sweep"] \
        else {}
    raw = document.get("fixed", {}).get(item.name, preset.get(item.name, item.default))
    axis = document.get("axes", {}).get(item.name)
    if isinstance(axis, list):
        raw = axis[0]
    if isinstance(raw, str):
        number, _, unit = raw.partition(" ")
        return float(number) if unit == item.unit else None
    plain = isinstance(raw, (int, float)) and not isinstance(raw, bool)
    return float(raw) if plain else None


def _cases():
    """Every spelling of each declared unit on one input, and one other spelling on every
    input (the conversion is per unit; the path to the file is per input)."""
    seen = set()
    for model in sorted(all_models().values(), key=lambda m: m.name):
        document = _document(model.name)
        for item in model.inputs:
            if item.kind not in ("quantity", "number") or item.dims:
                continue
            value = _declared_value(document, item)
            if value == 0 and (item.maximum is None or item.maximum >= 0.01):
                value = 0.01  # zero reads the same in every unit: take a value that does not
            if value is None or value == 0 or item.unit not in SPELLINGS:
                continue
            spellings = SPELLINGS[item.unit] if item.unit not in seen else \
                SPELLINGS[item.unit][1:2]
            seen.add(item.unit)
            for written, magnitude in spellings:
                yield pytest.param(model.name, item.name, item.unit, value,
                                   f"{magnitude(value)!r} {written}",
                                   id=f"{model.name}.{item.name}[{written}]")


CASES = list(_cases())


def test_every_declared_unit_has_spellings_and_is_covered():
    declared = {item.unit for model in all_models().values() for item in model.inputs
                if item.kind == "quantity" and "^(" not in item.unit and "^1." not in item.unit}
    assert declared <= set(SPELLINGS), declared - set(SPELLINGS)
    covered = {case.values[2] for case in CASES}
    assert covered == declared & set(SPELLINGS), declared - covered


def _with(document: dict, section: str, name: str, raw) -> dict:
    changed = {key: dict(table) for key, table in document.items()}
    for table in ("fixed", "axes"):
        changed.setdefault(table, {}).pop(name, None)
    changed[section][name] = raw
    if "fixed_dofs" in {i.name for i in all_models()[document["sweep"]["model"]].inputs}:
        for parameter in ("fixed_dofs", "geometry"):  # a load of any direction may be given
            changed["axes"].pop(parameter, None)
        changed["fixed"].update(fixed_dofs=[], geometry="jones")
    return changed


@pytest.mark.parametrize("model, name, declared, value, written", CASES)
def test_a_fixed_value_is_stored_in_the_declared_unit(model, name, declared, value, written):
    sweep = spec.from_dict(_with(_document(model), "fixed", name, written))
    stored = labels.fixed_inputs(sweep)[name]
    assert stored[1] == pytest.approx(value, rel=1e-12)
    assert stored[2].get("units", "1") == labels.described("", "", declared).get("units", "1")
    assert sweep.fixed[name].si == pytest.approx(_si(declared, value), rel=1e-12)


@pytest.mark.parametrize("model, name, declared, value, written", CASES)
def test_an_axis_value_is_stored_in_the_declared_unit(model, name, declared, value, written):
    sweep = spec.from_dict(_with(_document(model), "axes", name, [written]))
    coordinate = labels.coordinates(sweep)[name]
    assert coordinate[1][0] == pytest.approx(value, rel=1e-12)
    axis = next(a for a in sweep.axes if a.name == name)
    assert axis.si[name][0] == pytest.approx(_si(declared, value), rel=1e-12)


@pytest.mark.parametrize("model, name, declared, value, written", CASES)
def test_the_same_value_twice_on_an_axis_is_refused(model, name, declared, value, written):
    # Written once in the declared unit and once in another spelling: one index value twice.
    with pytest.raises(SpecError, match="the same value as"):
        spec.from_dict(_with(_document(model), "axes", name, [f"{value!r} {declared}", written]))


def test_mixed_speed_spellings_on_one_axis_are_stored_in_rpm():
    document = _with(_document("crb_radial"), "axes", "speed", ["1000 rpm", "3000 1/min",
                                                                 "60 1/s", "500 rad/s"])
    coordinate = labels.coordinates(spec.from_dict(document))["speed"]
    assert list(coordinate[1]) == pytest.approx([1000, 3000, 3600, 30000 / TURN], rel=1e-12)


def test_a_speed_in_1_per_min_is_computed_and_stored_as_revolutions():
    import bearing_sweep

    def result(speed):
        return bearing_sweep.run({"sweep": {"model": "crb_radial", "bearing": "paper000-D"},
                                  "fixed": {"radial_load": "4 kN", "speed": speed}},
                                 workers=0, progress=False)

    written, reference = result("6000 1/min"), result("6000 rev/min")
    assert float(written.speed) == 6000 and written.speed.attrs["units"] == "rpm"
    assert float(written.radial_stiffness) == float(reference.radial_stiffness)
    assert float(reference.radial_stiffness) != float(result("6000 rad/s").radial_stiffness)


@pytest.mark.parametrize("axis", [
    {"start": "1000 rpm", "stop": "1200 1/min", "step": "100 1/min"},
    {"start": "1000 1/min", "stop": "1200 rpm", "num": 3},
    {"start": "1000 1/min", "stop": "20 1/s", "step": "100 r/min"},
    {"values": [1000, 1100, 1200], "units": "1/min"}])
def test_a_speed_range_mixing_spellings_counts_revolutions(axis):
    sweep = spec.from_dict(_with(_document("crb_radial"), "axes", "speed", axis))
    assert list(labels.coordinates(sweep)["speed"][1]) == pytest.approx([1000, 1100, 1200])
    assert list(sweep.axes[-1].si["speed"]) == pytest.approx(
        [1000 * TURN / 60, 1100 * TURN / 60, 1200 * TURN / 60], rel=1e-12)


def _pattern_sweep(column):
    document = _document("crb_runout")
    document["axes"] = {"form": {"labels": ["a", "b"], "roller_diameter_error": column}}
    return spec.from_dict(document)


def test_a_pattern_in_any_unit_is_stored_in_the_declared_unit():
    pattern = [0.5, -1.0, 2.0] + [0.0] * 11  # um, one value per roller of the NU208 (14)
    column = [{"values": [v / 1e3 for v in pattern], "units": "mm"},
              [f"{v / 25.4!r} thou" if i % 2 else f"{v * 1e3!r} nm" for i, v in
               enumerate(pattern)]]
    sweep = _pattern_sweep(column)
    stored = labels.coordinates(sweep)["roller_diameter_error"]
    assert stored[0] == ("form", "roller") and stored[2]["units"] == "um"
    for row in stored[1]:
        assert list(row) == pytest.approx(pattern, rel=1e-12, abs=1e-15)
    for row in sweep.axes[-1].si["roller_diameter_error"]:
        assert list(row) == pytest.approx([v * 1e-6 for v in pattern], rel=1e-12, abs=1e-21)


@pytest.mark.parametrize("low, high", [("1000 1/min", "2000 rpm"), ("1000 rpm", "2000 r/min"),
                                       ("1000 min^-1", "2000 1/min")])
def test_a_sampled_speed_is_drawn_in_revolutions_whatever_it_is_written_in(low, high):
    document = _with(_document("crb_radial"), "axes", "speed", ["1 rpm"])
    del document["axes"]["speed"]
    document["sample"] = {"n": 16, "method": "random",
                          "speed": {"distribution": "uniform", "low": low, "high": high}}
    sweep = spec.from_dict(document)
    drawn = labels.coordinates(sweep)["speed"][1]
    assert 1000 <= drawn.min() and drawn.max() <= 2000 and drawn.max() - drawn.min() > 100
    assert sweep.sampling.distributions["speed"] == "uniform(low=1000 rpm, high=2000 rpm)"
