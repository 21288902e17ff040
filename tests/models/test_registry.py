"""Every model's declaration matches its function; every preset is valid for its model."""
import numpy as np
import pytest

from bearing_sweep.models.catalogue import PRESETS
from bearing_sweep.models.registry import all_models
from bearing_sweep import spec
from bearing_sweep.testing import assert_valid_declaration

MODELS = list(all_models().values())


@pytest.mark.parametrize("model", MODELS, ids=[m.name for m in MODELS])
def test_declaration_matches_the_function_and_holds_together(model):
    assert_valid_declaration(model)


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_every_preset_is_a_valid_definition_and_returns_every_output(name):
    preset = PRESETS[name]
    model = all_models()[preset.model]
    required = [i for i in model.inputs if i.required and i.name not in preset.values]
    # A value inside each missing input's declared range (1 where the range allows it; a
    # load of 1 kN, which every preset's bearing carries within its models' validity).
    middle = {i.name: 1000 if i.unit == "N" else 0.5 * (i.minimum + i.maximum)
              if i.minimum is not None and i.maximum is not None
              and not i.minimum <= 1 <= i.maximum else 1 for i in required}
    fixed = "\n".join(f'{i.name} = "{middle[i.name]} {i.unit}"' for i in required)
    sweep = spec.parse(f'[sweep]\nmodel = "{model.name}"\nbearing = "{name}"\n[fixed]\n{fixed}\n')
    arguments = {k: (None if v is None else v.si) for k, v in sweep.fixed.items()}
    result = model.function(**arguments)
    assert set(result) == {o.name for o in model.outputs} | {"status"}
    assert np.all(result["status"] == 0)
    assert preset.source.startswith("Paper")


def test_each_of_our_models_has_an_entry_point_named_after_it_in_its_module(monkeypatch):
    # get_model finds one of ours in its own module alone, through the entry point of its
    # name: every model of ours needs one, naming the module that declares it, and every
    # such entry point a model, or a model would be missed or taken from the wrong module.
    from bearing_sweep.models import registry

    ours = {name: model for name, model in registry.all_models().items()
            if model.function.__module__.startswith("bearing_sweep.models.")}
    entry_points = registry.own_entry_points()
    assert {name: e.value for name, e in entry_points.items()} == {
        name: model.function.__module__ for name, model in ours.items()}
    monkeypatch.setattr(registry, "_MODELS", {})  # the path a sweep of one model takes
    assert all(registry.get_model(name) is ours[name] for name in ours)
    assert registry._MODELS == {}


def test_a_sweep_of_one_model_imports_no_other_models_module(tmp_path):
    # Start-up: a sweep imports what its model needs and no more. hertz_point needs no numba
    # (crb_radial compiles its rollers' balance with it); neither needs scipy.integrate,
    # matplotlib, scipy.stats or another model's module (each costs a fraction of a second),
    # nor, run in-process, dask.distributed; nor xarray (nor the dask.array it imports as soon
    # as it makes a variable): the file is written with netCDF4 alone, a store with zarr.
    import subprocess
    import sys

    (tmp_path / "h.toml").write_text('[sweep]\nmodel = "hertz_point"\n[fixed]\n'
                                     'curvature_1x = "0.2 1/mm"\ncurvature_1y = "0.2 1/mm"\n'
                                     '[axes]\nload = ["1 kN", "2 kN"]\n')
    (tmp_path / "d.toml").write_text('[sweep]\nmodel = "crb_radial"\nbearing = "paper000-D"\n'
                                     '[axes]\nradial_load = ["1 kN", "2 kN"]\n')
    script = ("import sys\nfrom bearing_sweep import cli\n"
              "unwanted = ('scipy.integrate', 'matplotlib', 'scipy.stats', "
              "'bearing_sweep.models.cage_slip', 'distributed', 'xarray', 'dask.array', "
              "'pandas')\n"
              "cli.main(['run', 'h.toml', '-o', 'h.nc'])\n"
              "print(sorted(m for m in ('numba', 'bearing_sweep.models.cylindrical') + unwanted "
              "if m in sys.modules))\n"
              "cli.main(['run', 'd.toml', '-o', 'd.nc'])\n"
              "print(sorted(m for m in unwanted if m in sys.modules))\n"
              "cli.main(['run', 'h.toml', '-o', 'h.zarr'])\n"
              "print(sorted(m for m in unwanted if m in sys.modules))\n")
    done = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    printed = [line for line in done.stdout.splitlines() if line.startswith("[")]
    assert printed == ["[]", "[]", "[]"]
