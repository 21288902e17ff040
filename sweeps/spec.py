"""Sweep definitions: read a TOML file and validate it completely before any computing.

Every mistake is reported as a :class:`SpecError` whose message is one line: the file, the key,
what is wrong and what would be accepted. The pieces of the reading are in
:mod:`.definition` (tables and keys, values and units, axes, samples, output options, TOML
writing); this module holds the whole definition and its entry points.
"""
from __future__ import annotations

import hashlib
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .models.registry import Model, all_models, get_model
from .definition.axes import Axis
from .definition.inputs import ModelInputs
from .definition.output import output_table
from .definition.sampling import Sampling
from .definition.system import assembled
from .definition.tables import Reader, SpecError, suggestion, written
from .definition.values import Value
from .definition.writing import toml_text
from .storage import Storage

__all__ = ["SpecError", "Sweep", "MAX_POINTS", "load", "parse", "from_dict", "find_model"]

#: Most points in one sweep: beyond, the result files alone would fill a disk.
MAX_POINTS = 10**9
#: The tables of a definition.
SECTIONS = ("sweep", "fixed", "axes", "sample", "output")


@dataclass
class Sweep:
    """A validated sweep definition."""

    path: str
    text: str
    model: Model
    title: str
    bearing: str | None
    fixed: dict[str, Value | None]  # every input not on an axis; None: derived by the model
    axes: list[Axis]
    origin: dict[str, str] = field(default_factory=dict)  # where each fixed value came from
    sampling: Sampling | None = None  # a [sample] table: its axis is the first of ``axes``
    storage: Storage = Storage()  # the [output] table: how the outputs are written

    @property
    def duty_cycle(self) -> Axis | None:
        """The zipped axis of a duty cycle's load cases (with their ``time_shares``), if any."""
        return next((axis for axis in self.axes if axis.time_shares is not None), None)

    @property
    def sha256(self) -> str:
        return hashlib.sha256(self.text.encode()).hexdigest()


def load(path) -> Sweep:
    """Read and validate the sweep definition at ``path``."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as error:
        raise SpecError(f"{path}: cannot read the definition: {error.strerror}") from None
    except UnicodeDecodeError:
        raise SpecError(f"{path}: not a text file (a definition is UTF-8 TOML)") from None
    return parse(text, str(path))


def parse(text: str, where: str = "<definition>") -> Sweep:
    """Validate the sweep definition ``text``; ``where`` names it in error messages."""
    text = text.removeprefix("\ufeff")  # the byte order mark some editors write first
    try:
        document = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise SpecError(f"{where}: not valid TOML: {error}") from None
    except RecursionError:
        raise SpecError(f"{where}: not valid TOML for a definition: arrays or tables nested "
                        "too deeply (a definition needs at most a list of lists)") from None
    return _sweep(Reader(where), document, text)


def find_model(name: str) -> Model:
    """The registered model called ``name``; :class:`SpecError` (with the closest name)
    if there is none."""
    try:
        return get_model(name)
    except KeyError:
        models = all_models()
        raise SpecError(f"unknown model {name!r}" + suggestion(name, models)
                        + " (models: " + ", ".join(sorted(models)) + ")") from None


def from_dict(document: dict, where: str = "<definition>") -> Sweep:
    """Validate a definition given as a dict of the TOML's structure (units in strings).

    It is written out as TOML and parsed as text, so that it meets the same checks and
    messages, and its text is stored in the result and keys its resumable parts.
    """
    if not isinstance(document, dict):
        raise SpecError(f"{where}: a definition is TOML text, a path or a dict, not "
                        f"{type(document).__name__}")
    return parse(toml_text(document, where), where)


def _sweep(reader: Reader, document: dict, text: str) -> Sweep:
    """The whole definition: its [sweep] head and [output], the model's inputs, the grid."""
    storage = output_table(reader, document)
    head = reader.table(document, "sweep", ("model", "bearing", "title"))
    name = head.get("model")
    if not isinstance(name, str):
        reader.fail("sweep.model", ("missing" if name is None else f"{written(name)} is not "
                    "a model's name (a string)") + ": name a model, one of "
                    + ", ".join(sorted(all_models())))
    for key in ("bearing", "title"):
        if key in head and not isinstance(head[key], str):
            reader.fail(f"sweep.{key}", f"{written(head[key])}: expected a string ("
                        + ("a preset's name: `bearing-sweep presets` lists them)"
                           if key == "bearing" else "the title of the result)"))
    try:
        model = find_model(name)
    except SpecError as error:
        reader.fail("sweep.model", str(error))
    sections = SECTIONS + tuple(model.tables)
    for key in document:
        if key not in sections:
            reader.fail(key, "unknown section" + suggestion(key, sections)
                        + " (accepted: " + ", ".join(f"[{s}]" for s in sections) + ")")
    bearing, presets = head.get("bearing"), []
    if model.tables:
        if bearing is not None:
            reader.fail("sweep.bearing", f"a {model.name} names each support's bearing in "
                        "its own table: [supports.<name>] bearing = ...")
        model, document, presets = assembled(reader, document, model)
    inputs = ModelInputs(reader, model)
    fixed, origin, axes, sampling = inputs.read(document, bearing, "sweep.bearing", presets)
    points = int(np.prod([len(axis) for axis in axes], dtype=np.float64))
    if points > MAX_POINTS:
        reader.fail("sample.n" if sampling and len(axes) == 1 else "axes",
                    f"the grid has {points:.3g} points, too large for one sweep "
                    f"(at most {MAX_POINTS:.0e}); split it into several definitions")
    # A definition from a file is named after it; one given as text or a dict is not.
    title = model.name if reader.where.startswith("<") else \
        f"{model.name}: {Path(reader.where).stem}"
    inputs.check(fixed, origin, axes)
    return Sweep(reader.where, text, model, str(head.get("title") or title), bearing, fixed,
                 axes, origin, sampling, storage)
