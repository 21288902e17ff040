"""Sweep definitions: what is accepted, and one clear line for each kind of mistake."""
import re

import numpy as np
import pytest

from bearing_sweep import spec
from bearing_sweep.cli import main
from bearing_sweep.definition.axes import RESERVED_NAMES
from bearing_sweep.spec import SpecError

GOOD = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "0.004 mm"
slices = 60
crown_profile = "logarithmic"
[axes]
radial_load = ["2 kN", "4 kN", "8 kN"]
"""


def parse(text):
    return spec.parse(text, "def.toml")


def test_a_good_definition_resolves_presets_defaults_and_units():
    sweep = parse(GOOD)
    assert sweep.model.name == "crb_radial"
    assert sweep.fixed["roller_count"].si == 14 and sweep.origin["roller_count"] == "preset paper000-D"
    assert sweep.fixed["crown"].si == pytest.approx(4e-6)
    assert sweep.fixed["speed"].si == 0.0 and sweep.origin["speed"] == "default"
    assert sweep.fixed["contact_constant"] is None
    axis = sweep.axes[0]
    assert [v.si for v in axis.values["radial_load"]] == [2000.0, 4000.0, 8000.0]
    assert [v.shown for v in axis.values["radial_load"]] == [2.0, 4.0, 8.0]
    assert axis.values["radial_load"][0].unit == "kN"


def test_fixed_values_override_the_preset():
    sweep = parse(GOOD + '[axes.x]\nlabels = ["a"]\neffective_length = ["25 mm"]\n'
                  .replace("[axes.x]", "[axes.case]"))
    assert "effective_length" not in sweep.fixed
    sweep = parse(GOOD.replace('crown = "0.004 mm"', 'crown = "0.004 mm"\nroller_count = 20'))
    assert sweep.fixed["roller_count"].si == 20 and sweep.origin["roller_count"] == "fixed"


def test_axis_forms():
    sweep = parse("""
        [sweep]
        model = "crb_radial"
        bearing = "paper000-D"
        [fixed]
        radial_load = "4 kN"
        [axes]
        clearance = { start = "0 mm", stop = "0.04 mm", num = 5 }
        crown = { start = "0 um", stop = "4 um", step = "1 um" }
        speed = { values = [0, 5000], units = "rpm" }
        slices = [10, 60]
        slice_law = ["uniform", "paper"]
        [axes.case]
        labels = ["l25", "l28"]
        effective_length = ["25 mm", "28000 um"]
        """.replace("        ", ""))
    shown = {a.name: [v.shown for v in next(iter(a.values.values()))] for a in sweep.axes}
    np.testing.assert_allclose(shown["clearance"], [0, 0.01, 0.02, 0.03, 0.04])
    np.testing.assert_allclose(shown["crown"], [0, 1, 2, 3, 4])
    assert shown["speed"] == [0, 5000] and shown["slices"] == [10, 60]
    case = sweep.axes[-1]
    assert case.labels == ["l25", "l28"]
    assert [v.shown for v in case.values["effective_length"]] == [25, 28]  # in the first's unit
    assert case.values["effective_length"][1].si == pytest.approx(0.028)
    assert sweep.axes[2].values["speed"][1].si == pytest.approx(5000 * 2 * np.pi / 60)


def test_an_empty_axes_table_is_one_point():
    sweep = parse(GOOD.replace('radial_load = ["2 kN", "4 kN", "8 kN"]', "")
                  .replace("[fixed]", '[fixed]\nradial_load = "3 kN"'))
    assert sweep.axes == []


BAD = [
    # (what is wrong, replace this, with this, words the message must contain)
    ("TOML syntax", 'slices = 60', 'slices = = 60', ["not valid TOML"]),
    ("unknown model", '"crb_radial"', '"crb_radal"', ["sweep.model", "unknown model", "crb_radial"]),
    ("unknown parameter", 'crown = "0.004 mm"', 'crwn = "0.004 mm"',
     ["fixed.crwn", "unknown parameter", "did you mean 'crown'"]),
    ("unknown axis parameter", "radial_load = [", "radial_lod = [",
     ["axes.radial_lod", "did you mean 'radial_load'"]),
    ("given twice", "slices = 60", 'slices = 60\nradial_load = "3 kN"',
     ["given twice", "radial_load"]),
    ("bare number", 'crown = "0.004 mm"', "crown = 0.004", ["fixed.crown", "no units", "mm"]),
    ("missing units in a string", 'crown = "0.004 mm"', 'crown = "0.004"', ["no units"]),
    ("incompatible units", 'crown = "0.004 mm"', 'crown = "0.004 kN"',
     ["fixed.crown", "do not fit"]),
    ("angle units for a speed", "slices = 60", 'slices = 60\nspeed = "100 Hz"',
     ["fixed.speed", "do not fit"]),
    ("unknown unit", 'crown = "0.004 mm"', 'crown = "0.004 furlongz"', ["unknown unit"]),
    ("negative length", 'crown = "0.004 mm"', 'crown = "-0.004 mm"', ["out of range", ">= 0"]),
    ("crown larger than the roller", 'crown = "0.004 mm"', 'crown = "6 mm"',
     ["crown must be smaller than the roller radius", "roller_diameter = 10 mm"]),
    ("too few slices", "slices = 60", "slices = 0", ["fixed.slices", ">= 1"]),
    ("non-integer count", "slices = 60", "slices = 6.5", ["fixed.slices", "integer"]),
    ("unknown choice", '"logarithmic"', '"logaritmic"', ["crown_profile", "did you mean 'logarithmic'"]),
    ("empty axis", '["2 kN", "4 kN", "8 kN"]', "[]", ["axes.radial_load", "empty axis"]),
    ("empty range", '["2 kN", "4 kN", "8 kN"]', '{ start = "2 kN", stop = "1 kN", step = "1 kN" }',
     ["empty axis"]),
    ("range with num and step", '["2 kN", "4 kN", "8 kN"]',
     '{ start = "2 kN", stop = "4 kN", step = "1 kN", num = 3 }', ["exactly one of"]),
    ("unknown preset", '"paper000-D"', '"paper000-E"', ["sweep.bearing", "unknown preset"]),
    ("unknown section", "[fixed]", "[fixd]", ["unknown section", "did you mean 'fixed'"]),
    ("rollers do not fit", 'crown = "0.004 mm"', 'crown = "0.004 mm"\nroller_count = 30',
     ["do not fit on the pitch circle", "roller_count = 30"]),
    ("missing required", 'bearing = "paper000-D"', "", ["missing parameters", "'roller_count', 'pitch_diameter' [mm]"]),
    ("scalar axis", '["2 kN", "4 kN", "8 kN"]', '"2 kN"', ["an axis is a list"]),
    ("list in fixed", 'crown = "0.004 mm"', 'crown = ["1 um", "2 um"]', ["put it in [axes]"]),
    ("wrong type", "slices = 60", "slices = true", ["fixed.slices", "must be an integer"]),
]


@pytest.mark.parametrize("what, old, new, words", BAD, ids=[b[0] for b in BAD])
def test_each_mistake_is_one_clear_line(what, old, new, words):
    assert old in GOOD
    with pytest.raises(SpecError) as caught:
        parse(GOOD.replace(old, new, 1))
    message = str(caught.value)
    assert "\n" not in message
    assert message.startswith("def.toml: ")
    for word in words:
        assert word in message, message


def test_ragged_zipped_axis():
    text = GOOD + '[axes.case]\nlabels = ["a", "b"]\neffective_length = ["25 mm", "26 mm", "27 mm"]\n'
    with pytest.raises(SpecError, match="ragged zipped axis: effective_length has 3, labels has 2"):
        parse(text)


def test_out_of_range_value_on_an_axis_names_the_position():
    with pytest.raises(SpecError, match=r"axes.radial_load\[1\]: '-4 kN' is out of range"):
        parse(GOOD.replace('"4 kN"', '"-4 kN"'))


def test_constraint_across_axes_names_the_failing_combination():
    text = GOOD + 'crown = ["1 um", "6 mm"]\n'
    text = text.replace('crown = "0.004 mm"\n', "")
    with pytest.raises(SpecError, match="crown = 6000 um, roller_diameter = 10 mm"):
        parse(text)


@pytest.mark.parametrize("what, old, new, words", BAD[:6], ids=[b[0] for b in BAD[:6]])
def test_the_command_line_exits_2_and_writes_nothing(what, old, new, words, tmp_path, capsys):
    path = tmp_path / "def.toml"
    path.write_text(GOOD.replace(old, new, 1))
    output = tmp_path / "out" / "result.nc"
    assert main(["run", str(path), "-o", str(output), "--workers", "0"]) == 2
    error = capsys.readouterr().err.strip()
    assert error.startswith("error: ") and len(error.splitlines()) == 1
    assert "Traceback" not in error
    assert not output.exists() and not output.parent.exists()


def test_unreadable_definitions(tmp_path):
    with pytest.raises(SpecError, match="cannot read the definition"):
        spec.load(tmp_path / "missing.toml")
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b"\xff\xfe\x00garbage")
    with pytest.raises(SpecError, match="not a text file"):
        spec.load(binary)


def test_an_unwritable_output_is_one_line(tmp_path, capsys):
    path = tmp_path / "def.toml"
    path.write_text(GOOD)
    blocked = tmp_path / "file"
    blocked.write_text("")
    assert main(["run", str(path), "-o", str(blocked / "out.nc"), "--workers", "0"]) == 2
    error = capsys.readouterr().err.strip()
    assert error.startswith("error: ") and len(error.splitlines()) == 1


CAGE = """
[sweep]
model = "cage_slip"
bearing = "paper002-test"
[fixed]
radial_load = "500 N"
speed = "6000 rpm"
[axes]
oil_temperature = { start = "20 degC", stop = "80 degC", step = "STEP" }
"""


@pytest.mark.parametrize("step, shown", [("15 delta_degC", [20, 35, 50, 65, 80]),
                                         ("15 degC", [20, 35, 50, 65, 80]),
                                         ("20 K", [20, 40, 60, 80]),
                                         ("27 delta_degF", [20, 35, 50, 65, 80])])
def test_a_temperature_step_is_a_difference(step, shown):
    values = parse(CAGE.replace("STEP", step)).axes[0].values["oil_temperature"]
    assert [v.shown for v in values] == pytest.approx(shown)
    assert [v.si for v in values] == pytest.approx([t + 273.15 for t in shown])


@pytest.mark.parametrize("written", ["3000 r/min", "3000 rev/min", "3000 1/min", "3000 min^-1",
                                     "50 r/s", "3000 rpm", "314.159265 rad/s"])
def test_rotational_speeds_as_engineers_write_them(written):
    sweep = parse(GOOD.replace('crown = "0.004 mm"', f'crown = "0.004 mm"\nspeed = "{written}"'))
    assert sweep.fixed["speed"].si == pytest.approx(100 * np.pi, rel=1e-8)


def test_presets_and_models_suggest_the_close_name_and_a_preset_shows_its_values(capsys):
    assert main(["presets", "paper000-D"]) == 0
    shown = capsys.readouterr().out
    assert "pitch_diameter = 65 mm" in shown and "Table 4" in shown
    assert main(["presets", "paper000-Q"]) == 2
    assert "did you mean 'paper000-D'?" in capsys.readouterr().err
    assert main(["describe", "crb_radail"]) == 2
    assert "did you mean 'crb_radial'?" in capsys.readouterr().err
    assert main(["study", "cage_slp", "--workers", "0"]) == 2
    assert "did you mean 'cage_slip'?" in capsys.readouterr().err


def test_a_long_range_converts_at_once_exactly_as_value_by_value():
    # A range's values are converted in one array operation (a 1e5-value axis used to cost a
    # unit parse per value); each must be bitwise the value the one-by-one path gives, also
    # for an offset unit (degC) and a rotational speed.
    from bearing_sweep.definition.tables import Reader
    from bearing_sweep.definition.values import ValueReader
    from bearing_sweep.spec import parse

    sweep = parse('[sweep]\nmodel = "cage_slip"\nbearing = "paper002-test"\n'
                  '[fixed]\nradial_load = "800 N"\n'
                  '[axes]\noil_temperature = { start = "-20 degC", stop = "120 degC", num = 57 }\n'
                  'speed = { start = "100 rpm", stop = "20000 rpm", step = "137 rpm" }\n')
    checker = ValueReader(Reader("<test>"))
    for axis in sweep.axes:
        declared = sweep.model.input(axis.name)
        for value in axis.values[axis.name]:
            one = checker.value(declared, value.shown, axis.name, value.unit)
            assert one.si == value.si and one.shown == value.shown


def test_a_models_inputs_read_below_a_dotted_path_are_those_read_at_the_top():
    # One model's inputs are read from any table of a definition: a sub-table (a shaft's
    # support A, say) gives the same values as the top, and its keys in messages carry its
    # path.
    import tomllib

    from bearing_sweep.definition.inputs import ModelInputs
    from bearing_sweep.definition.tables import Reader

    sweep = parse(GOOD)
    below = Reader("shaft.toml").within("supports").within("A")
    table = tomllib.loads(GOOD)
    fixed, origin, axes, sampling = ModelInputs(below, sweep.model).read(
        table, "paper000-D", "bearing")
    assert fixed == sweep.fixed and origin == sweep.origin and sampling is None
    assert [(a.name, a.values) for a in axes] == [(a.name, a.values) for a in sweep.axes]
    table["fixed"]["clearence"] = "10 um"
    with pytest.raises(SpecError, match=r"^shaft\.toml: supports\.A\.fixed\.clearence: unknown "
                       r"parameter 'clearence' of model crb_radial; did you mean 'clearance'\?"):
        ModelInputs(below, sweep.model).read(table, "paper000-D", "bearing")
    with pytest.raises(SpecError, match=r"^shaft\.toml: supports\.A\.bearing: unknown preset"):
        ModelInputs(below, sweep.model).read(table, "paper000-X", "bearing")


def test_a_byte_order_mark_before_the_definition_is_read_past(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes("\ufeff".encode() + GOOD.encode())
    with_mark, without = spec.load(path), parse(GOOD)
    assert with_mark.sha256 == without.sha256  # the same definition, the same parts
    assert [v.si for v in with_mark.axes[0].values["radial_load"]] == [2000.0, 4000.0, 8000.0]
    assert main(["run", str(path), "-o", str(tmp_path / "bom.nc"), "--workers", "0",
                 "--quiet"]) == 0


@pytest.mark.parametrize("raw, words", [
    ("nan", "nan is not a number (NaN)"), ("inf", "inf is infinite"),
    ("-inf", "-inf is infinite"), ('"nan"', "'nan': NaN is not a number"),
    ('"inf"', "'inf': an infinite value is not accepted"),
    ('"1e400"', "'1e400' is too large to compute with")])
def test_a_value_that_is_not_a_finite_number_is_named_for_what_it_is(raw, words):
    with pytest.raises(SpecError) as caught:
        parse(GOOD.replace("slices = 60", f"slices = 60\npoisson_ratio = {raw}"))
    assert f"fixed.poisson_ratio: {words}" in str(caught.value)
    assert "too large" not in str(caught.value) or "1e400" in raw


@pytest.mark.parametrize("axis", ['{ values = [0, nan], units = "mm" }',
                                  '{ start = "0 mm", stop = "nan mm", num = 3 }',
                                  '{ start = "0 mm", stop = "1 mm", step = "nan mm" }'])
def test_nan_on_an_axis_is_not_a_number(axis):
    text = GOOD.replace('crown = "0.004 mm"\n', "") + f"crown = {axis}\n"
    with pytest.raises(SpecError, match="NaN"):
        parse(text)


def test_a_sampled_distribution_with_nan_or_inf_is_refused():
    for parameter in ('high = "nan mm"', 'high = "inf mm"'):
        text = (GOOD.replace('crown = "0.004 mm"\n', "") + '[sample]\nn = 8\nmethod = "random"\n'
                f'crown = {{ distribution = "uniform", low = "0 mm", {parameter} }}\n')
        with pytest.raises(SpecError, match="sample.crown.high: .*(NaN|infinite)"):
            parse(text)


@pytest.mark.parametrize("name", ["a/b", "", "1case", "a b", "x.y", "case-2", "é"])
def test_an_axis_name_a_file_cannot_hold_is_refused(name):
    text = GOOD + f'[axes."{name}"]\nlabels = ["a", "b"]\neffective_length = ["9 mm", "9.6 mm"]\n'
    with pytest.raises(SpecError, match="cannot name an axis"):
        parse(text)


@pytest.mark.parametrize("name", sorted(RESERVED_NAMES))
def test_an_axis_name_a_result_or_its_analysis_uses_is_refused(name):
    text = GOOD + f'[axes.{name}]\nlabels = ["a", "b"]\neffective_length = ["9 mm", "9.6 mm"]\n'
    with pytest.raises(SpecError, match="reserved"):
        parse(text)


@pytest.mark.parametrize("key, raw, words", [
    ("model", "3", "sweep.model: 3 is not a model's name"),
    ("model", "[\"crb_radial\"]", "is not a model's name"),
    ("title", "{ a = 1 }", "sweep.title: {'a': 1}: expected a string"),
    ("title", "42", "sweep.title: 42: expected a string"),
    ("bearing", "3", "sweep.bearing: 3: expected a string")])
def test_a_sweep_key_of_the_wrong_type_is_named(key, raw, words):
    lines = [line for line in GOOD.splitlines() if not line.startswith(f"{key} =")]
    lines.insert(lines.index("[sweep]") + 1, f"{key} = {raw}")
    with pytest.raises(SpecError) as caught:
        parse("\n".join(lines))
    assert words in str(caught.value)


ONE_AXIS = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
radial_load = "4 kN"
[axes]
"""


@pytest.mark.parametrize("axis, where", [
    ('crown = ["1 um", "3 um", "2 um"]', "axes.crown[2]"), ("slices = [60, 10, 30]", "axes.slices[2]"),
    ('clearance = ["0.01 mm", "20 um", "0.015 mm"]', "axes.clearance[2]"),
    ('speed = ["1000 rpm", "20 1/s", "1100 r/min"]', "axes.speed[2]")])
def test_an_axis_out_of_order_is_refused_a_coordinate_is_monotonic(axis, where):
    # CF 1.10 section 5: a coordinate variable is strictly monotonic.
    with pytest.raises(SpecError, match=rf"{re.escape(where)}: the values of an axis run in one"):
        parse(ONE_AXIS + axis)


def test_an_axis_in_decreasing_order_and_a_range_of_tenths_are_kept_as_written():
    sweep = parse(ONE_AXIS + 'clearance = ["0.02 mm", "10 um", "0 mm"]\n'
                  'crown = { start = "0 um", stop = "0.3 um", step = "0.1 um" }\n')
    assert [v.shown for v in sweep.axes[0].values["clearance"]] == [0.02, 0.01, 0]
    assert [v.shown for v in sweep.axes[1].values["crown"]] == [0, 0.1, 0.2, 0.3]  # not ...004


@pytest.mark.parametrize("labels, words", [
    ('["a\\u0000", "a"]', "labels[0]: 'a\\x00': a label is 1 to 256 printable characters"),
    ('[""]', "a label is 1 to 256 printable"), ("[3, 1, 2]", "labels: the labels of an axis run"),
    ('[1, "a"]', "labels are all strings or all integers"),
    ("[1, 18446744073709551616]", "is too large: an integer of a definition")])
def test_labels_a_file_would_not_keep_as_written_are_refused(labels, words):
    count = len(labels.split(","))
    column = ", ".join(['"9.6 mm"'] * count)
    with pytest.raises(SpecError) as caught:
        parse(GOOD + f"[axes.case]\nlabels = {labels}\neffective_length = [{column}]\n")
    assert words in str(caught.value)


@pytest.mark.parametrize("where, text", [
    ("fixed.poisson_ratio", "poisson_ratio = 1" + "0" * 400),
    ("fixed.slices", "slices = 1" + "0" * 400),
    ("axes.crown.values[1]", 'crown = { values = [0, 1' + "0" * 30 + '], units = "mm" }')])
def test_an_integer_beyond_64_bits_is_one_line(where, text):
    document = GOOD.replace("slices = 60\n", "").replace('crown = "0.004 mm"\n', "")
    section = "[axes]" if where.startswith("axes") else "[fixed]"
    with pytest.raises(SpecError, match=rf"{re.escape(where)}: 1000.* is too large"):
        parse(document.replace(section, f"{section}\n{text}"))


def test_a_seed_beyond_64_bits_is_refused_before_computing():
    text = (GOOD.replace('crown = "0.004 mm"\n', "") + '[sample]\nn = 8\nmethod = "random"\n'
            'seed = 18446744073709551616\ncrown = { distribution = "uniform", low = "0 mm", '
            'high = "1 um" }\n')
    with pytest.raises(SpecError, match="sample.seed: 18446744073709551616: expected an integer"):
        parse(text)


def test_an_axis_name_longer_than_64_characters_is_refused():
    with pytest.raises(SpecError, match="at most 64 characters"):
        parse(GOOD + f'[axes.{"a" * 301}]\nlabels = ["x"]\neffective_length = ["9 mm"]\n')


@pytest.mark.parametrize("axis, words", [
    ('{ start = "0 mm", stop = "0.01 mm", num = 1 }', "crown.num: 1 value from start to a"),
    ('{ start = "0 mm", stop = "0.01 mm", step = "0.02 mm" }', "crown.step: the step is larger")])
def test_a_range_that_would_leave_its_stop_out_silently_is_refused(axis, words):
    with pytest.raises(SpecError, match=words):
        parse(ONE_AXIS + f"crown = {axis}\n")
    assert parse(ONE_AXIS + 'crown = { start = "4 um", stop = "0.004 mm", num = 1 }\n').axes


def test_a_temperature_range_in_degf_is_stored_at_round_degc():
    from bearing_sweep import labels

    sweep = parse(CAGE.replace('{ start = "20 degC", stop = "80 degC", step = "STEP" }',
                               '{ start = "32 degF", stop = "212 degF", num = 3 }'))
    assert list(labels.coordinates(sweep)["oil_temperature"][1]) == [0.0, 50.0, 100.0]
