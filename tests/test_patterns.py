"""Array-valued parameters (a per-roller pattern), fixed or one whole pattern per label."""
import numpy as np
import pytest

import models.registry as registry
from models.registry import Input, Model, Output
from sweeps import spec, store
from sweeps.run import Executor, run_sweep
from sweeps.spec import SpecError


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
    data = store.open_result(tmp_path / "p.nc")
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
