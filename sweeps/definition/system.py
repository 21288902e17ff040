"""A definition whose own tables give its model's structure: a shaft's ``[shaft]`` sections,
its ``[supports.<name>]`` and its ``[loads.<name>]`` (:mod:`..models.shaft_system`).

The tables are checked where they are written, then read as the inputs of the model they
build: a support's or load's key ``clearance`` is the input ``supports_<name>_clearance``.
A support's preset gives the values below its table's, and an axis or a sample replaces
either; [fixed], [axes] and [sample] may name those inputs either way,
``supports.A.clearance`` or ``supports_A_clearance``.
"""
from __future__ import annotations

import re

from ..models.catalogue import PRESETS
from ..models.registry import Model
from .tables import Reader, suggestion, written
from .values import Value, ValueReader

#: A dotted input name of a support or a load, as [axes], [fixed] and [sample] may write it.
_DOTTED = re.compile(r"(supports|loads)\.([^.]+)\.([^.]+)")
#: The keys of a support's table besides its inputs.
_SUPPORT_KEYS = ("model", "bearing")


def assembled(reader: Reader, document: dict, template: Model
              ) -> tuple[Model, dict, list[tuple[dict[str, Value], str]]]:
    """The model of the system the definition ``document`` describes (``template``: the
    registered model that names its tables), the document with its names as that model's
    (dotted names undotted, the system's tables taken out) and the values the system's
    tables give, each group with where it comes from: a support's preset, then the
    support's or load's own table (an axis or a sample of the same input replaces them)."""
    from ..models import shaft_system as system

    values = ValueReader(reader)
    sections = _sections(reader.within("shaft"), values,
                         reader.table(document, "shaft", ("sections",)), system)
    supports, loads, given = {}, [], {}
    for table, kinds in (("supports", system.SUPPORT_KINDS), ("loads", None)):
        entries = reader.table(document, table, None)
        if table == "supports" and not entries:
            reader.fail("supports", "a shaft system needs at least one support: "
                        "[supports.<name>] with model = " + " or ".join(
                            repr(k) for k in kinds))
        if table == "loads" and not entries:  # its outputs per load need one
            reader.fail("loads", "a shaft system needs at least one load: [loads.<name>] "
                        "with a position (its forces may be zero, the shaft's weight alone)")
        for name, entry in entries.items():
            where = reader.within(table)
            if not re.fullmatch(system.NAME_PATTERN, name):
                where.fail(name, "a name of a support or a load starts with a letter and holds "
                           "letters and digits, words joined by single underscores")
            entry = where.table(entries, name, None)
            own = where.within(name)
            if kinds is None:
                declared = system.LOAD_INPUTS
            else:
                kind = entry.get("model")
                if kind not in kinds:
                    own.fail("model", ("missing" if kind is None else f"{written(kind)} is "
                             "not a kind of support") + ": one of "
                             + ", ".join(repr(k) for k in kinds))
                supports[name], declared = kind, system.SUPPORT_INPUTS[kind]
            inputs = {spec.name: spec for spec in declared}
            for key, raw in entry.items():
                if kinds is not None and key in _SUPPORT_KEYS:
                    continue
                if key not in inputs:
                    accepted = sorted(inputs) + (list(_SUPPORT_KEYS) if kinds else [])
                    own.fail(key, "unknown key" + suggestion(key, accepted)
                             + f" (accepted: {', '.join(accepted)})")
                if isinstance(raw, list) and not inputs[key].dims:
                    own.fail(key, f"one value here; vary it on an axis instead: [axes] "
                             f'"{table}.{name}.{key}" = [...]')
                given.setdefault(f"{table}.{name}", {})[f"{table}_{name}_{key}"] = \
                    ValueReader(own).value(inputs[key], raw, key, fixed=True)
            if kinds is None:
                loads.append(name)
    model = template.assemble(sections, supports, loads)
    names = [spec.name for spec in model.inputs]
    twice = sorted({name for name in names if names.count(name) > 1})
    if twice:
        reader.fail("supports", f"two inputs of the system are both called {twice[0]!r} "
                    "(a support's or load's name followed by an input's): rename one")
    translated = {key: value for key, value in document.items()
                  if key not in template.tables}
    fixed = _undotted_table(reader, "fixed", document.get("fixed", {})) \
        if isinstance(document.get("fixed", {}), dict) else document["fixed"]
    for table, entries in given.items():
        for key in entries:
            if key in fixed:
                reader.fail(f"fixed.{key}", f"given twice (also in its own table [{table}])")
    translated["fixed"] = fixed
    for table in ("axes", "sample"):
        if isinstance(document.get(table), dict):
            translated[table] = {
                key: _undotted_table(reader, f"{table}.{key}", raw) if isinstance(raw, dict)
                else raw for key, raw in _undotted_table(reader, table,
                                                         document[table]).items()}
    presets = []
    for name, kind in supports.items():
        bearing = document["supports"][name].get("bearing")
        if bearing is not None:
            presets.append((_preset(reader.within(f"supports.{name}"), values, model, name,
                                    kind, bearing), f"preset {bearing}"))
    presets += [(entries, table) for table, entries in given.items()]
    _check_given(reader, system, supports, loads, presets, translated)
    return model, translated, presets


def _check_given(reader: Reader, system, supports: dict, loads: list, presets: list,
                 translated: dict):
    """Every required input of each support and load given somewhere: its table, its
    preset, [fixed], an axis or a sample; else one line at its table."""
    named = {key for values, _ in presets for key in values}
    for table in ("fixed", "axes", "sample"):
        for key, raw in (translated.get(table) or {}).items():
            named.add(key)
            if isinstance(raw, dict):  # a zipped axis' columns
                named.update(raw)
    entries = [("supports", name, system.SUPPORT_INPUTS[kind])
               for name, kind in supports.items()]
    entries += [("loads", name, system.LOAD_INPUTS) for name in loads]
    for table, name, declared in entries:
        missing = [spec for spec in declared
                   if spec.required and f"{table}_{name}_{spec.name}" not in named]
        if missing:
            described = ", ".join(f"{spec.name!r}" + ("" if spec.unit in ("", "1")
                                                      else f" [{spec.unit}]")
                                  for spec in missing)
            what = "its preset (bearing = ...), " if table == "supports" else ""
            reader.within(table).fail(name, f"missing {described}: give "
                                      f"{'them' if len(missing) > 1 else 'it'} in "
                                      f"[{table}.{name}], {what}or on an axis")


def _sections(reader: Reader, values: ValueReader, shaft: dict, system) -> list:
    """Each section's length, diameter and bore [m]."""
    raw = shaft.get("sections")
    if not isinstance(raw, list) or not raw or not all(isinstance(s, dict) for s in raw):
        reader.fail("sections", "expected a list of sections from the shaft's left end, each "
                    "{ length = \"120 mm\", diameter = \"40 mm\" } (bore optional)")
    declared = {spec.name: spec for spec in system.SECTION_INPUTS}
    sections = []
    for number, section in enumerate(raw, start=1):
        key = f"sections[{number}]"
        for name in section:
            if name not in declared:
                reader.fail(f"{key}.{name}", "unknown key" + suggestion(name, declared)
                            + f" (accepted: {', '.join(declared)})")
        row = []
        for name, spec in declared.items():
            if name not in section and spec.required:
                reader.fail(f"{key}.{name}", f"missing: the section's {spec.meaning}")
            row.append(float(values.value(spec, section[name], f"{key}.{name}").si)
                       if name in section else float(spec.default))
        if row[2] >= row[1]:
            reader.fail(f"{key}.bore", "the bore must be smaller than the section's diameter")
        sections.append(row)
    return sections


def _preset(reader: Reader, values: ValueReader, model: Model, name: str, kind: str,
            bearing) -> dict[str, Value]:
    """The values of a support's preset ``bearing`` that are inputs of its kind."""
    if not isinstance(bearing, str) or bearing not in PRESETS:
        reader.fail("bearing", f"unknown preset {bearing!r}" + suggestion(str(bearing), PRESETS)
                    + " (`bearing-sweep presets` lists them)")
    preset = PRESETS[bearing]
    if kind not in preset.models:
        reader.fail("bearing", f"preset {bearing!r} is for {' and '.join(preset.models)}, "
                    f"not {kind!r}")
    inputs = {spec.name: spec for spec in model.inputs}
    found = {}
    for key, raw in preset.values.items():
        input_name = f"supports_{name}_{key}"
        if input_name in inputs:
            found[input_name] = values.value(inputs[input_name], raw,
                                             f"preset {bearing}.{key}")
    return found


def _undotted(key: str) -> str:
    """``supports.A.clearance`` as the model names it, ``supports_A_clearance``."""
    match = _DOTTED.fullmatch(key)
    return "_".join(match.groups()) if match else key


def _undotted_table(reader: Reader, where: str, table: dict) -> dict:
    """``table`` with its dotted keys undotted; one line at ``where`` for an input written
    both ways (``"supports.A.clearance"`` and ``supports_A_clearance``)."""
    undotted = {}
    for key, value in table.items():
        name = _undotted(key)
        if name in undotted:
            earlier = next(k for k in table if _undotted(k) == name)
            reader.fail(f"{where}.{key}", f"given twice: also as {earlier!r} (the same input)")
        undotted[name] = value
    return undotted
