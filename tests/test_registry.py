"""Every model's declaration matches its function; every preset is valid for its model."""
import inspect

import numpy as np
import pytest

from bearing_sweep.models.catalogue import PRESETS
from bearing_sweep.models.registry import REQUIRED, all_models
from bearing_sweep import spec, units

MODELS = list(all_models().values())


@pytest.mark.parametrize("model", MODELS, ids=[m.name for m in MODELS])
def test_inputs_match_the_function_signature(model):
    parameters = inspect.signature(model.function).parameters
    assert list(parameters) == [i.name for i in model.inputs]
    for declared in model.inputs:
        default = parameters[declared.name].default
        if declared.default is REQUIRED:
            assert default is inspect.Parameter.empty, declared.name
        elif declared.kind == "subset":  # passed as the names joined by spaces
            assert default == " ".join(declared.default), declared.name
        elif declared.kind in ("choice", "count") or declared.default is None:
            assert default == declared.default, declared.name
        else:  # the function's default is the declared one in SI
            si = units.to_si(declared.default, units.parse_unit(declared.unit))
            assert default == pytest.approx(si), declared.name


@pytest.mark.parametrize("model", MODELS, ids=[m.name for m in MODELS])
def test_declared_units_are_readable_and_dims_have_sizes(model):
    for item in model.inputs + model.outputs:
        if item.unit and not getattr(item, "entry_units", ()):
            units.parse_unit(item.unit)
    for output in model.outputs:
        for dim in output.dims:
            assert dim in model.dim_sizes
        if output.entry_units:  # one readable unit per entry, nested like the dims
            shape = tuple(len(model.dim_sizes[d]) for d in output.dims)
            assert np.array(output.entry_units).shape == shape
            for unit in np.ravel(output.entry_units):
                units.parse_unit(unit)


@pytest.mark.parametrize("model", MODELS, ids=[m.name for m in MODELS])
def test_outputs_and_inputs_have_distinct_names(model):
    # An output named like an input would clash with that input's coordinate in the dataset.
    names = [i.name for i in model.inputs] + [o.name for o in model.outputs] + ["status"]
    assert len(set(names)) == len(names)


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_every_preset_is_a_valid_definition_and_returns_every_output(name):
    preset = PRESETS[name]
    model = all_models()[preset.model]
    required = [i for i in model.inputs if i.required and i.name not in preset.values]
    # A value inside each missing input's declared range (1 where the range allows it).
    middle = {i.name: 0.5 * (i.minimum + i.maximum) if i.minimum is not None and i.maximum
              is not None and not i.minimum <= 1 <= i.maximum else 1 for i in required}
    fixed = "\n".join(f'{i.name} = "{middle[i.name]} {i.unit}"' for i in required)
    sweep = spec.parse(f'[sweep]\nmodel = "{model.name}"\nbearing = "{name}"\n[fixed]\n{fixed}\n')
    arguments = {k: (None if v is None else v.si) for k, v in sweep.fixed.items()}
    result = model.function(**arguments)
    assert set(result) == {o.name for o in model.outputs} | {"status"}
    assert np.all(result["status"] == 0)
    assert preset.source.startswith("Paper")
