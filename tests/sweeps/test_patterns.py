"""Array-valued parameters (a per-roller pattern), fixed or one whole pattern per label."""
import numpy as np
import pytest

import bearing_sweep.models.registry as registry
from bearing_sweep.models.registry import Input, Model, Output
from bearing_sweep import spec, stores
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.spec import SpecError


def pattern_total(scale, pattern):
    """Toy model: each point's pattern summed and scaled [m]."""
    total = np.asarray(scale) * np.asarray(pattern).sum(axis=-1)
    return {"total": total, "status": np.zeros(np.shape(total), dtype=np.int8)}


@pytest.fixture
def toy_model(monkeypatch):
    registry.all_models()  # load the real ones before adding the toy
    model = Model(name="pattern_total", function=pattern_total, summary="toy", reference="test",
                  version="1",
                  inputs=(Input("scale", "1", "factor"),
                          Input("pattern", "um", "per-roller error", dims=("roller",))),
                  outputs=(Output("total", "um", "scaled sum"),))
    monkeypatch.setitem(registry._MODELS, model.name, model)
    return model


def test_fixed_pattern_and_a_pattern_per_label(toy_model, tmp_path):
    text = """
    [sweep]
    model = "pattern_total"
    [axes]
    scale = [1, 2]
    [axes.arrangement]
    labels = ["increasing", "alternating"]
    pattern = [{ values = [1, 2, 3], units = "um" }, ["3 um", "0.001 mm", "2 um"]]
    """
    sweep = spec.parse(text.replace("    ", ""), "p.toml")
    run_sweep(sweep, tmp_path / "p.nc", Executor(workers=0), progress=False)
    data = stores.open_result(tmp_path / "p.nc")
    np.testing.assert_allclose(data.total.values, [[6, 6], [12, 12]])
    assert data.pattern.dims == ("arrangement", "roller")
    np.testing.assert_allclose(data.pattern.values, [[1, 2, 3], [3, 1, 2]])
    assert data.pattern.attrs["units"] == "um"

    fixed = spec.parse('[sweep]\nmodel = "pattern_total"\n[fixed]\nscale = 3\n'
                       'pattern = { values = [1, 1], units = "mm" }\n')
    assert fixed.fixed["pattern"].si.tolist() == [1e-3, 1e-3]


@pytest.mark.parametrize("value, words", [
    ('["1 um", "2"]', "pattern[1]: '2' has no units"),
    ('["1 um", "2 N"]', "units differ in kind"),
    ("[]", "a non-empty list"),
    ('{ values = [1, 2] }', "has no units"),
    ('"1 um"', "is a pattern"),
])
def test_bad_patterns(toy_model, value, words):
    with pytest.raises(SpecError, match=words.replace("[", r"\[").replace("]", r"\]")):
        spec.parse(f'[sweep]\nmodel = "pattern_total"\n[fixed]\nscale = 1\npattern = {value}\n')


def test_a_pattern_on_a_plain_axis_is_refused(toy_model):
    with pytest.raises(SpecError, match="vary it on a labelled axis"):
        spec.parse('[sweep]\nmodel = "pattern_total"\n[fixed]\nscale = 1\n'
                   '[axes]\npattern = [["1 um"], ["2 um"]]\n')


RUNOUT = """
[sweep]
model = "crb_runout"
bearing = "paper004-NU208-1"
[fixed]
steps_per_revolution = 360
revolutions = 1
"""


def test_one_value_stands_for_every_roller_where_the_input_allows(tmp_path):
    # crb_runout's roller roundness: one value for all rollers, fixed or on a plain axis,
    # mixed with whole patterns on a zipped axis.
    text = RUNOUT + ('roller_roundness_amplitude = "0.5 um"\n[axes]\n'
                     'roller_roundness_order = [2, 4]\n[axes.rows]\nlabels = ["same", "own"]\n'
                     'roller_roundness_phase = ["0 deg", { values = [' + ", ".join(
                         ["0"] * 13 + ["90"]) + '], units = "deg" }]\n')
    sweep = spec.parse(text, "def.toml")
    assert sweep.fixed["roller_roundness_amplitude"].si.tolist() == [0.5e-6]
    run_sweep(sweep, tmp_path / "out.nc", Executor(workers=0), progress=False)
    data = stores.open_result(tmp_path / "out.nc")
    assert data.roller_roundness_amplitude.dims == ()
    assert data.roller_roundness_order.dims == ("roller_roundness_order",)
    assert data.roller_roundness_phase.dims == ("rows", "roller")
    np.testing.assert_array_equal(data.roller_roundness_phase.sel(rows="same"), np.zeros(14))
    assert (data.status == 0).all()


@pytest.mark.parametrize("axes, words", [
    ('[axes]\nroller_diameter_error = [["1 um", "2 um"], ["1 um", "2 um"]]\n',
     "vary it on a labelled axis"),
    ('[axes.rows]\nlabels = ["a", "b"]\nroller_diameter_error = [{ values = [1, 2], units = '
     '"um" }, { values = [1, 2, 3], units = "um" }]\n', "the patterns differ in length (2, 3"),
])
def test_patterns_that_cannot_be_laid_out(axes, words):
    with pytest.raises(SpecError) as caught:
        spec.parse(RUNOUT + axes, "def.toml")
    assert words in str(caught.value)


def test_a_count_range_may_step_by_less_than_its_minimum():
    sweep = spec.parse(RUNOUT + "[axes]\nroller_count = { start = 12, stop = 15, step = 1 }\n")
    assert [v.si for v in sweep.axes[0].values["roller_count"]] == [12, 13, 14, 15]
