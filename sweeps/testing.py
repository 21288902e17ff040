"""Checks for a model author's own tests, like ``xarray.testing``.

A package that adds models (docs/user-guide/adding-a-model.md) can call these from its tests::

    from bearing_sweep.testing import assert_chunking_invariant, assert_valid_declaration
    from my_bearings.models import MODELS

    def test_declarations():
        for model in MODELS:
            assert_valid_declaration(model)

    def test_chunking(tmp_path):
        assert_chunking_invariant('[sweep]\\nmodel = "my_model"\\n[axes]\\nload = ...', tmp_path)
"""
from __future__ import annotations

import inspect
import re
import textwrap
from pathlib import Path

import numpy as np

from .models.registry import Model, declaration_problems
from . import spec, stores, units
from .compute import Executor, run_sweep


def assert_valid_declaration(model: Model):
    """Assert that ``model``'s declaration matches its function and holds together.

    Beyond what the registry refuses when it loads a plug-in
    (:func:`bearing_sweep.models.registry.declaration_problems`: parameters and inputs alike
    and in order, required inputs without defaults, choice and count defaults equal, output
    dimensions sized, no name twice), every declared unit must read, each entry unit of an
    output must match the shape of its dimensions, the function's default of a quantity
    must be the declared default in SI base units, and the Parameters section of the
    function's docstring (numpydoc) must describe each declared input once, and nothing else.

    Raises
    ------
    AssertionError
        Naming the model and every problem found.
    """
    problems = declaration_problems(model) + _unit_problems(model) + _docstring_problems(model)
    assert not problems, f"model {model.name!r}: " + "; ".join(problems)


def _unit_problems(model: Model) -> list[str]:
    problems = []
    for item in model.inputs + model.outputs:
        entry_units = getattr(item, "entry_units", ())
        for unit in np.ravel(entry_units).tolist() if entry_units else [item.unit]:
            try:
                units.parse_unit(unit)
            except units.UnitError as error:
                problems.append(f"{item.name!r}: {error}")
    for output in model.outputs:
        if output.entry_units and all(d in model.dim_sizes for d in output.dims):
            shape = tuple(len(model.dim_sizes[d]) for d in output.dims)
            if np.shape(output.entry_units) != shape:
                problems.append(f"output {output.name!r}: entry_units of shape "
                                f"{np.shape(output.entry_units)}, its dimensions' labels {shape}")
    parameters = inspect.signature(model.function).parameters
    for item in model.inputs:
        if item.structural or item.required or item.default is None \
                or item.name not in parameters:
            continue  # compared by the registry, or nothing to compare
        try:
            si = units.to_si(item.default, units.parse_unit(item.unit))
        except units.UnitError:
            continue  # named above
        try:
            same = np.allclose(parameters[item.name].default, si, rtol=1e-9, atol=0)
        except (TypeError, ValueError):  # not a number at all
            same = False
        if not same:
            problems.append(f"input {item.name!r}: the function's default "
                            f"{parameters[item.name].default!r} is not the declared "
                            f"{item.default!r} {item.unit} in SI base units "
                            f"({np.asarray(si).tolist()!r})")
    return problems


#: A section title of a numpydoc docstring: a line, then a line of dashes.
_SECTION = re.compile(r"^(\w[\w ]*)\n-+$", re.MULTILINE)


def documented_parameters(function) -> list[str] | None:
    """The names the Parameters section of ``function``'s numpydoc docstring describes, in
    order (None without such a section): each entry's header, its unindented lines, a list
    of names that goes on after a trailing comma, then `` : type``."""
    doc = inspect.getdoc(function) or ""
    sections = {m.group(1): m.end() for m in _SECTION.finditer(doc)}
    if "Parameters" not in sections:
        return None
    body = doc[sections["Parameters"]:]
    following = _SECTION.search(body)
    headers, continued = [], False
    for line in (body[:following.start()] if following else body).splitlines():
        if not line.strip() or line.startswith(" "):
            continued = False
            continue
        if continued:
            headers[-1] += " " + line
        else:
            headers.append(line)
        continued = line.rstrip().endswith(",")
    return [name.strip() for header in headers for name in header.split(" : ")[0].split(",")]


def _docstring_problems(model: Model) -> list[str]:
    documented = documented_parameters(model.function)
    if documented is None:
        return ["its function's docstring has no Parameters section (numpydoc)"]
    declared = [i.name for i in model.inputs]
    problems = []
    for words, names in (("documented but not declared", set(documented) - set(declared)),
                         ("declared but not documented", set(declared) - set(documented)),
                         ("documented twice", {n for n in documented
                                               if documented.count(n) > 1})):
        if names:
            problems.append(f"the docstring's Parameters: {', '.join(sorted(names))} "
                            f"{words}")
    return problems


def assert_chunking_invariant(definition: str, folder, chunk_size: int = 1):
    """Assert that a sweep's numbers do not depend on how its grid is cut into chunks.

    Runs ``definition`` (the text of a sweep definition, dedented) in this process twice, all
    points in one chunk and in chunks of ``chunk_size`` points, writes both files into
    ``folder`` (pytest's ``tmp_path``) and compares every variable to the last bit. A model
    whose points influence each other (a mean over the call, a solver's shared step) fails.

    Raises
    ------
    AssertionError
        Naming the first variable that differs.
    """
    sweep = spec.parse(textwrap.dedent(definition), "definition.toml")
    results = []
    with Executor(workers=0) as executor:
        for name, size in (("whole", spec.MAX_POINTS), ("chunked", chunk_size)):
            path = Path(folder) / f"{name}.nc"
            run_sweep(sweep, path, executor, chunk_size=size, progress=False)
            results.append(stores.open_result(path))
    assert_same_numbers(*results, label=sweep.model.name)


def assert_same_numbers(expected, actual, label: str = ""):
    """Assert that two sweeps' datasets hold the same variables with equal values, bit for
    bit (NaN where the other has NaN)."""
    assert sorted(expected.data_vars) == sorted(actual.data_vars), label
    for variable in expected.data_vars:
        np.testing.assert_array_equal(expected[variable].values, actual[variable].values,
                                      err_msg=f"{label}.{variable}")
