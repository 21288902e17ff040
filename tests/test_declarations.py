"""Each model input is written three times: the function's signature (its default in SI),
the model's ``Input`` declaration (in the customary unit) and the docstring's Parameters.
These tests hold the three to one another for every registered model."""
import inspect
import re

import numpy as np
import pytest

from bearing_sweep import units
from bearing_sweep.models.registry import all_models

MODELS = all_models()
#: A section title of a numpydoc docstring: a line, then a line of dashes as long.
SECTION = re.compile(r"^(\w[\w ]*)\n-+$", re.MULTILINE)


def documented_parameters(function) -> list[str]:
    """The names the Parameters section of ``function``'s docstring describes, in order: each
    entry's header (the unindented lines, a list of names that goes on after a trailing
    comma, then `` : type``)."""
    doc = inspect.getdoc(function) or ""
    sections = {m.group(1): m.end() for m in SECTION.finditer(doc)}
    assert "Parameters" in sections, f"{function.__qualname__}: no Parameters section"
    body = doc[sections["Parameters"]:]
    following = SECTION.search(body)
    body = body[:following.start()] if following else body
    headers, continued = [], False
    for line in body.splitlines():
        if not line.strip() or line.startswith(" "):
            continued = False
            continue
        if continued:
            headers[-1] += " " + line
        else:
            headers.append(line)
        continued = line.rstrip().endswith(",")
    names = []
    for header in headers:
        names += [name.strip() for name in header.split(" : ")[0].split(",")]
    return names


@pytest.mark.parametrize("name", sorted(MODELS))
def test_the_signature_declares_the_same_inputs_as_the_model(name):
    model = MODELS[name]
    signature = list(inspect.signature(model.function).parameters)
    assert sorted(signature) == sorted(i.name for i in model.inputs)


@pytest.mark.parametrize("name", sorted(MODELS))
def test_the_docstring_describes_each_declared_input_once(name):
    model = MODELS[name]
    documented = documented_parameters(model.function)
    declared = [i.name for i in model.inputs]
    assert sorted(documented) == sorted(declared), (
        f"described only: {sorted(set(documented) - set(declared))}; declared only: "
        f"{sorted(set(declared) - set(documented))}; twice: "
        f"{sorted({n for n in documented if documented.count(n) > 1})}")


@pytest.mark.parametrize("name", sorted(MODELS))
def test_each_declared_default_is_the_signature_s_default_in_si(name):
    model = MODELS[name]
    parameters = inspect.signature(model.function).parameters
    for declared in model.inputs:
        default = parameters[declared.name].default
        where = f"{name}.{declared.name}"
        if declared.required:
            assert default is inspect.Parameter.empty, f"{where}: declared required"
        elif declared.default is None or default is None:
            # None: the model derives the value (declared) or leaves the output NaN.
            assert declared.default is default is None, where
        elif declared.kind == "subset":  # the model receives the names, space-separated
            assert default == " ".join(declared.default), where
        elif declared.kind in ("choice", "count"):
            assert type(default) is type(declared.default) and default == declared.default, \
                where
        else:
            in_si = units.to_si(declared.default, units.parse_unit(declared.unit))
            assert np.asarray(default, dtype=float).shape == np.shape(in_si), where
            np.testing.assert_allclose(default, in_si, rtol=1e-12, atol=0, err_msg=where)
