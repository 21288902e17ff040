"""A JSON Schema of sweep definitions, generated from the model registry.

Editors that read schemas for TOML (taplo, VS Code's Even Better TOML) then complete parameter
names, show each parameter's meaning, unit, default and range, and mark an unknown key, a
wrong type or an unknown choice as the user types.

A schema cannot check everything the engine checks: it reads "0.04 mm" as "a number and a
unit" (whether the unit fits the parameter, and the value its range, is for ``bearing-sweep
run`` to say), and conditions between parameters are out of its reach. What it refuses, the
engine refuses too.

The schema is JSON Schema draft-07, with the any-model schema a ``oneOf`` over the models
keyed on ``sweep.model`` (taplo documents draft 4 features; ``if``/``then`` and ``const`` are
not used for that reason).
"""
from __future__ import annotations

import math
from dataclasses import replace

from .models.catalogue import PRESETS
from .models.registry import Input, Model, all_models
from . import sample, units
from .definition.axes import AXIS_NAME, RESERVED_NAMES, TIME_SHARE
from .storage import ENCODINGS, Storage

DRAFT = "http://json-schema.org/draft-07/schema#"

#: A number followed by a unit, as ``units.split_quantity`` reads it ("0.04 mm", "6000 rpm",
#: "6000 1/min", "4kN"). No look-arounds: editors' regex engines may lack them.
QUANTITY_PATTERN = r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(\s+\S.*|[^\s\d.eE+-].*)$"
#: The same without a minus sign, for a parameter that cannot be negative in any unit.
POSITIVE_QUANTITY_PATTERN = QUANTITY_PATTERN.replace("[-+]?(", "[+]?(", 1)
#: A number with or without a unit, for a dimensionless parameter ("0.3", "30 %").
NUMBER_PATTERN = r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(\s*\S.*)?$"

_LABELS = {"type": "array", "minItems": 1, "uniqueItems": True,
           "items": {"type": ["string", "integer"]},
           "description": "the zipped axis' labels, one per value of its parameters"}


def schema(model: str | None = None) -> dict:
    """The JSON Schema of a sweep definition of ``model``, or of any registered model.

    Parameters
    ----------
    model : str, optional
        A registered model's name; None for a schema that accepts a definition of any model
        (one branch per model, chosen by ``sweep.model``).

    Returns
    -------
    dict
        The schema, ready for ``json.dumps``.

    Raises
    ------
    KeyError
        If ``model`` is not a registered model.
    """
    models = all_models()
    if model is not None:
        one = _definition(models[model])
        return {"$schema": DRAFT, "$id": f"bearing-sweep-{model}.schema.json",
                "title": f"bearing-sweep definition of a {model} sweep", **one}
    return {"$schema": DRAFT, "$id": "bearing-sweep.schema.json",
            "title": "bearing-sweep sweep definition",
            "description": "A sweep of one of the models: " + ", ".join(sorted(models)),
            "type": "object",
            "required": ["sweep"],
            "properties": {"sweep": {"type": "object", "required": ["model"], "properties": {
                "model": {"enum": sorted(models), "description": "the model to run "
                          "(`bearing-sweep models` lists them)"}}}},
            "oneOf": [_definition(m) for m in models.values()]}


def _definition(model: Model) -> dict:
    """The schema of a whole definition of ``model``: [sweep], [fixed], [axes], [sample] and
    [output]."""
    presets = sorted(p.name for p in PRESETS.values() if model.name in p.models)
    sweep = {"type": "object", "additionalProperties": False, "required": ["model"],
             "properties": {
                 "model": {"enum": [model.name], "description": model.summary},
                 "bearing": {"type": "string", "description": "a preset from the catalogue "
                             "whose values any [fixed] or [axes] entry overrides "
                             "(`bearing-sweep presets` lists them)",
                             **({"enum": presets} if presets else {"not": {}})},
                 "title": {"type": "string", "description": "the result's title"}}}
    fixed = {name: _fixed(spec) for name, spec in ((i.name, i) for i in model.inputs)}
    axes = {i.name: _plain_axis(i) for i in model.inputs}
    fixed_table = {"type": "object", "additionalProperties": False, "properties": fixed,
                   "description": "one value for each parameter held fixed"}
    zipped = {"type": "object", "additionalProperties": False, "minProperties": 1,
              "description": "a zipped axis: its parameters vary together, one value per label",
              "properties": {"labels": _LABELS,
                             **{i.name: _column(i) for i in model.inputs}}}
    if any(o.cycle for o in model.outputs):
        zipped["properties"][TIME_SHARE] = {
            "type": "array", "minItems": 1, "items": {"type": "number", "minimum": 0},
            "description": "a duty cycle: each load case's share of the time, in proportion; "
                           "the result holds the rating lives over the cycle beside each "
                           "case's"}
    axes_table = {"type": "object", "properties": axes, "additionalProperties": zipped,
                  "propertyNames": {"pattern": f"^{AXIS_NAME.pattern}$",
                                    "not": {"enum": sorted(RESERVED_NAMES)}},
                  "description": "each key a dimension of the grid, in order: a parameter's "
                                 "values, or a table of zipped parameters"}
    sampled = _sample(model)
    if model.tables:  # the inputs of the system's supports and loads, named either way
        system = {"patternProperties": {_SYSTEM_INPUT_NAMES: {}}}
        fixed_table |= system
        sampled |= system
        zipped |= system
        axes_table |= system | {"propertyNames": {"anyOf": [
            axes_table["propertyNames"], {"pattern": _SYSTEM_INPUT_NAMES}]}}
    return {"type": "object", "additionalProperties": False, "required": ["sweep"],
            "description": f"{model.name}: {model.summary}",
            "properties": {
                "sweep": sweep,
                "fixed": fixed_table,
                "axes": axes_table,
                "sample": sampled,
                "output": OUTPUT, **_system_tables(model)}}


#: The inputs of a shaft system's supports and loads, as [fixed], [axes] and [sample] may
#: name them: ``supports.A.clearance`` or ``supports_A_clearance``.
_SYSTEM_INPUT_NAMES = r"^(supports|loads)(\.[^.]+\.|_)[A-Za-z0-9_]+$"


def _system_tables(model: Model) -> dict:
    """The tables that give a model's structure (a shaft's [shaft], [supports], [loads]) and,
    where it has them, the names of their inputs in [fixed], [axes] and [sample]."""
    if not model.tables:
        return {}
    from .models import shaft_system as system

    def inputs(declared, required=None):
        """A table of ``declared`` inputs; ``required`` None: those the declaration requires
        (a section's). A support's and a load's may come from a preset or an axis."""
        return {"type": "object", "additionalProperties": False,
                "required": [i.name for i in declared if i.required] if required is None
                else list(required),
                "properties": {i.name: _fixed(i) for i in declared}}

    kinds = [inputs(declared, ["model"]) for declared in system.SUPPORT_INPUTS.values()]
    for kind, schema in zip(system.SUPPORT_INPUTS, kinds):
        schema["properties"] |= {"model": {"const": kind}, "bearing": {"type": "string"}}
    name = {"pattern": f"^{system.NAME_PATTERN}$"}
    return {
        "shaft": {"type": "object", "additionalProperties": False, "required": ["sections"],
                  "properties": {"sections": {"type": "array", "minItems": 1,
                                              "items": inputs(system.SECTION_INPUTS)}}},
        "supports": {"type": "object", "minProperties": 1, "propertyNames": name,
                     "additionalProperties": {"oneOf": kinds}},
        "loads": {"type": "object", "minProperties": 1, "propertyNames": name,
                  "additionalProperties": inputs(system.LOAD_INPUTS, [])}}


#: The [output] table: how the result file stores the outputs (``definition.output.storage_options``).
OUTPUT = {"type": "object", "additionalProperties": False,
          "description": "how the result file stores the outputs",
          "properties": {
              "encoding": {"enum": list(ENCODINGS), "default": Storage().encoding,
                           "description": "the type of the outputs that are not integers"},
              "compression": {"type": "string", "pattern": r"^(none|zlib(:[1-9])?|zstd(:([1-9]|1"
                                                           r"[0-9]|2[0-2]))?)$",
                              "default": f"{Storage().compression}:{Storage().level}",
                              "description": "none, zlib[:1-9] or zstd[:1-22]"},
              "shuffle": {"type": "boolean", "default": Storage().shuffle,
                          "description": "the shuffle filter before zlib"}}}


def _sample(model: Model) -> dict:
    """The [sample] table: its settings, and a distribution for each sampled parameter."""
    settings = {
        "n": {"type": "integer", "minimum": 1, "description": "number of samples (saltelli: "
              f"base samples of each of its {sample.SALTELLI_REPLICATES} replicates, at least "
              f"{sample.SALTELLI_MIN_N}; sobol and saltelli: a power of 2)"},
        "method": {"enum": list(sample.METHODS), "description": "the design of the samples"},
        "seed": {"type": "integer", "minimum": 0, "default": 0,
                 "description": "the same seed draws the same samples"}}
    return {"type": "object", "additionalProperties": False, "required": ["n", "method"],
            "description": "parameters drawn from distributions into one dimension 'sample'",
            "properties": {**settings, **{i.name: _distribution(i) for i in model.inputs
                                          if not i.structural}}}


def _distribution(spec: Input) -> dict:
    """One sampled parameter: a distribution and its parameters, each with a unit."""
    # Widths and deviations may be negative, and the engine checks the range of what a
    # distribution reaches: no bounds here.
    value = _one(replace(spec, dims=(), broadcast=False, minimum=None, maximum=None))
    forms = []
    for name, parameters in sample.DISTRIBUTIONS.items():
        properties = {"distribution": {"enum": [name]}, **{p: value for p, _ in parameters}}
        if name == "tolerance":
            properties["distribution_within"] = {"enum": list(sample.WITHIN)}
        forms.append({"type": "object", "additionalProperties": False,
                      "required": ["distribution", *(p for p, _ in parameters)],
                      "properties": properties})
    per = f", each {spec.dims[0]}'s value drawn on its own" if spec.dims else ""
    return {"anyOf": forms, "description": f"{describe(spec)}; drawn from a distribution{per}"}


def describe(spec: Input) -> str:
    """A parameter's description: meaning, unit, default and valid range."""
    unit = "" if spec.unit in ("", "1") else f" [{spec.unit}]"
    per = f", one value per {spec.dims[0]}" if spec.dims else ""
    if spec.required:
        default = "required"
    elif spec.default is None:
        default = "derived by the model when not given"
    else:
        default = f"default {_written(spec)!r}"
    return f"{spec.meaning}{unit}{per}; {default}; {spec.range_text()}"


def _written(spec: Input):
    """The parameter's default as a user writes it: "0.04 mm", 60, "logarithmic", [...]."""
    if spec.kind == "subset":
        return list(spec.default)
    if spec.kind in ("count", "choice") or spec.unit in ("", "1"):
        return spec.default
    return f"{spec.default:g} {spec.unit}"


def _annotated(spec: Input, body: dict) -> dict:
    """``body`` with the parameter's description and default."""
    annotated = {**body, "description": describe(spec)}
    if not spec.required and spec.default is not None:
        annotated["default"] = _written(spec)
    return annotated


def _one(spec: Input, with_units: bool = False) -> dict:
    """One value of a scalar parameter; ``with_units``: a bare number beside ``units``."""
    if spec.kind == "choice":
        return {"enum": list(spec.choices)}
    if spec.kind == "subset":
        return {"type": "array", "uniqueItems": True, "items": {"enum": list(spec.choices)}}
    if spec.kind == "count":
        bounds = {}
        if spec.minimum is not None:  # an integer above an exclusive bound: the next one up
            bounds["minimum"] = (math.floor(spec.minimum) + 1 if spec.exclusive_minimum
                                 else math.ceil(spec.minimum))
        if spec.maximum is not None:
            bounds["maximum"] = math.floor(spec.maximum)
        return {"type": "integer", **bounds}
    number = {"type": "number"}
    if spec.unit in ("", "1"):  # a bare number is in the declared unit: its range applies
        if spec.minimum is not None:
            number["exclusiveMinimum" if spec.exclusive_minimum else "minimum"] = spec.minimum
        if spec.maximum is not None:
            number["maximum"] = spec.maximum
        if with_units:
            return {"type": "number"}
        return {"anyOf": [number, {"type": "string", "pattern": NUMBER_PATTERN}]}
    if with_units:
        return number
    # A unit with a shifted zero (degC) can make a negative number a positive temperature.
    unsigned = (spec.minimum is not None and spec.minimum >= 0
                and not units.is_offset(units.parse_unit(spec.unit)))
    return {"type": "string", "pattern": POSITIVE_QUANTITY_PATTERN if unsigned
            else QUANTITY_PATTERN,
            "examples": [f"{_example(spec):g} {spec.unit}"]}


def _example(spec: Input) -> float:
    if isinstance(spec.default, (int, float)) and not isinstance(spec.default, bool):
        return spec.default
    return spec.minimum + 1 if spec.minimum is not None else 1


def _with_units(items: dict, dimensionless: bool) -> dict:
    """``{values = [...], units = "..."}`` holding ``items``; units optional when
    ``dimensionless``."""
    return {"type": "object", "additionalProperties": False,
            "required": ["values"] if dimensionless else ["values", "units"],
            "properties": {"values": {"type": "array", "minItems": 1, "items": items},
                           "units": {"type": "string", "description": "the unit of every value"}}}


def _pattern(spec: Input) -> dict:
    """A whole pattern (one value per roller, per harmonic): a list of quantity strings or
    numbers with ``units``; a single value too where it stands for every entry."""
    scalar = replace(spec, dims=())
    dimensionless = spec.unit in ("", "1")
    forms = [{"type": "array", "minItems": 1, "items": _one(scalar)},
             _with_units(_one(scalar, with_units=True), dimensionless)]
    if spec.broadcast:
        forms.insert(0, _one(scalar))
    return {"anyOf": forms}


def _value(spec: Input) -> dict:
    """One value of any parameter, scalar or pattern, as [fixed] takes it."""
    return _pattern(spec) if spec.dims else _one(spec)


def _fixed(spec: Input) -> dict:
    return _annotated(spec, _value(spec))


def _column(spec: Input, scalars: bool = False) -> dict:
    """The values of ``spec`` along an axis: a list, ``{values, units}`` or a range;
    ``scalars``: single values only (a pattern's single value on a plain axis)."""
    scalar = replace(spec, dims=())
    patterns = bool(spec.dims) and not scalars
    forms = [{"type": "array", "minItems": 1, "items": _value(spec) if patterns else
              _one(scalar)}]
    if spec.kind == "count":
        forms.append({"type": "object", "additionalProperties": False, "required": ["values"],
                      "properties": {"values": {"type": "array", "minItems": 1,
                                                "items": _one(spec)}}})
    elif spec.kind == "choice":
        forms.append(_with_units(_one(spec), True))
    elif spec.kind != "subset":
        numbers = {"type": "array", "minItems": 1, "items": {"type": "number"}}
        bare = {"type": "number"}
        if patterns:
            bare = {"anyOf": [bare, numbers]} if spec.broadcast else numbers
        forms.append(_with_units(bare, spec.unit in ("", "1")))
    if spec.kind not in ("choice", "subset") and (spec.broadcast or not spec.dims):
        forms.append(_range(scalar))
    return _annotated(spec, {"anyOf": forms})


def _range(spec: Input) -> dict:
    """``{start, stop, num | step, units}``: its values are checked as any others."""
    if spec.kind == "count":
        end, step = _one(spec), {"type": "integer", "minimum": 1}
    else:
        bare = {"type": "number"}
        end = {"anyOf": [bare, _one(spec)]}
        step = {"anyOf": [bare, _one(replace(spec, minimum=None, maximum=None))]}
    return {"type": "object", "additionalProperties": False, "required": ["start", "stop"],
            "oneOf": [{"required": ["num"]}, {"required": ["step"]}],
            "properties": {"start": end, "stop": end,
                           "num": {"type": "integer", "minimum": 1,
                                   "description": "number of values, ends included"},
                           "step": {**step, "description": "the difference between values"},
                           **({} if spec.kind == "count" else {"units": {
                               "type": "string",
                               "description": "the unit of bare numbers"}})}}


def _plain_axis(spec: Input) -> dict:
    """An axis named after the parameter it varies: single values, each named once."""
    if spec.dims and not spec.broadcast:  # refused: a pattern varies on a zipped axis
        return {"not": {}, "description": f"{spec.name} is a pattern (one value per "
                f"{spec.dims[0]}): vary it on a zipped axis, [axes.<name>] labels = [...], "
                f"{spec.name} = [...]"}
    column = _column(spec, scalars=True)
    column["anyOf"][0]["uniqueItems"] = True  # the engine refuses a value named twice
    return column
