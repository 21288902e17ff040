"""Sweep definitions: read a TOML file and validate it completely before any computing.

Every mistake is reported as a :class:`SpecError` whose message is one line: the file, the key,
what is wrong and what would be accepted.
"""
from __future__ import annotations

import difflib
import hashlib
import json
import re
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from .models.catalogue import PRESETS
from .models.registry import Input, Model, all_models, get_model
from . import sample, units
from .storage import COMPRESSIONS, DEFAULT_LEVELS, ENCODINGS, Storage

_RANGE_KEYS = {"start", "stop", "num", "step", "units"}
_VALUES_KEYS = {"values", "units"}
#: Names a result or its analysis uses: the status of each point, the [sample] axis and
#: the blocks of its Saltelli design, and the dimensions of `analyze`'s output.
RESERVED_NAMES = {"status", "sample", "saltelli_block", "saltelli_replicate", "statistic",
                  "output", "input", "bound"}
#: A name of a variable or dimension (CF conventions 2.3), at most 64 characters.
AXIS_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
#: The largest magnitude of an integer in a definition: what 64 bits hold.
MAX_INTEGER = 2**63 - 1
#: The keys of a [sample] table that are not sampled parameters.
_SAMPLE_SETTINGS = ("n", "method", "seed")
#: The keys of an [output] table.
_OUTPUT_KEYS = ("encoding", "compression", "shuffle")
#: Most points in one sweep: beyond, the result files alone would fill a disk.
MAX_POINTS = 10**9
#: Most values on one axis (each is validated on its own before any computing).
MAX_AXIS_VALUES = 10**6
#: Two values of an axis closer than this, relative to their size, are one value written
#: twice (rounding in a unit conversion is some 1e-16; a file stores 15 digits).
SAME_VALUE = 1e-9


class SpecError(Exception):
    """A mistake in a sweep definition; ``str(error)`` is the line shown to the user."""


@dataclass(frozen=True)
class Value:
    """One parameter value: in SI for the model, and as written for the netCDF file."""

    si: object  # float, int, str or numpy array, in SI base units
    shown: object  # the magnitude in ``unit``
    unit: str  # the unit the user wrote; "1" when dimensionless, "" for a choice


@dataclass
class Axis:
    """One dimension of the grid: a parameter's values, or several parameters zipped."""

    name: str
    values: dict[str, list[Value]]
    labels: list | None = None  # a zipped axis' labels
    #: Each parameter's SI values stacked, points first: built once, for the conditions
    #: between parameters and for every chunk's model inputs.
    si: dict[str, np.ndarray] = field(init=False, repr=False)

    def __post_init__(self):
        self.si = {name: stack(values) for name, values in self.values.items()}

    def __len__(self) -> int:
        return len(next(iter(self.values.values())))


@dataclass(frozen=True)
class Sampling:
    """How the ``sample`` axis was drawn, for the file's attributes and ``analyze``."""

    method: str
    n: int  # samples asked for; Saltelli's design holds replicates * n * (inputs + 2)
    seed: int
    distributions: dict  # sampled input -> its distribution in words, in the declared unit
    #: Saltelli's design: the name of each block of ``replicates * n`` samples (A, B,
    #: AB_<input>...), and its independent scramblings (``sample.saltelli_blocks``).
    blocks: tuple[str, ...] | None = None
    replicates: int = 1


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
    return _Parser(where).sweep(document, text)


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


def toml_text(document: dict, where: str = "<definition>") -> str:
    """``document`` as TOML text: each table under its header, its values inline (a nested
    table keeps its place among the others: the order of axes is the order of dimensions)."""
    lines = [f"{_toml_key(k, where)} = {_toml_value(v, k, where)}" for k, v in document.items()
             if not isinstance(v, dict)]
    for name, table in document.items():
        if isinstance(table, dict):
            lines += ["", f"[{_toml_key(name, where)}]"] + [
                f"{_toml_key(k, where)} = {_toml_value(v, f'{name}.{k}', where)}"
                for k, v in table.items()]
    return "\n".join(lines).lstrip("\n") + "\n"


def _toml_key(key, where: str) -> str:
    if not isinstance(key, str):
        raise SpecError(f"{where}: {key!r}: a key is a string")
    return key if key and all(c.isalnum() and c.isascii() or c in "_-" for c in key) \
        else json.dumps(key, ensure_ascii=False)


def _toml_value(value, key: str, where: str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)  # its escapes are TOML's too
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v, f"{key}[{i}]", where)
                               for i, v in enumerate(value)) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{_toml_key(k, where)} = {_toml_value(v, f'{key}.{k}', where)}"
                                for k, v in value.items()) + " }"
    raise SpecError(f"{where}: {key}: {value!r} is not a value of a definition (a string with "
                    "units, a number, a boolean, a list or a table)")


def suggestion(name: str, options) -> str:
    """'; did you mean ...?' for the option closest to ``name``, or nothing."""
    close = difflib.get_close_matches(name, list(options), n=1, cutoff=0.6)
    return f"; did you mean {close[0]!r}?" if close else ""


def storage_options(base: Storage, encoding=None, compression=None,
                    named=lambda key: f"--{key}") -> Storage:
    """``base`` with the ``encoding`` and ``compression`` given (None: as in ``base``),
    written as on the command line and in an [output] table: ``"float32"``, ``"zlib:4"``;
    ``named(key)`` says where, in a :class:`SpecError` for a mistake."""
    if encoding is not None and encoding not in ENCODINGS:
        raise SpecError(f"{named('encoding')}: {encoding!r} is not accepted; the encoding is "
                        + " or ".join(repr(e) for e in ENCODINGS)
                        + suggestion(str(encoding), ENCODINGS))
    name, level = base.compression, base.level
    if compression is not None:
        name, level = _compression(compression, named("compression"))
    return replace(base, encoding=encoding or base.encoding, compression=name, level=level)


def _compression(text, where: str) -> tuple[str, int]:
    """``"none"``, ``"zlib"``, ``"zlib:4"``, ``"zstd:3"`` as (name, level)."""
    accepted = "'none', 'zlib' or 'zlib:LEVEL' (1-9), 'zstd' or 'zstd:LEVEL' (1-22)"
    if not isinstance(text, str):
        raise SpecError(f"{where}: {text!r}: expected a string, {accepted}")
    name, _, level_text = text.partition(":")
    if name not in COMPRESSIONS:
        raise SpecError(f"{where}: {text!r} is not accepted; the compression is {accepted}"
                        + suggestion(name, COMPRESSIONS))
    levels = COMPRESSIONS[name]
    if levels is None:
        if level_text:
            raise SpecError(f"{where}: {text!r}: 'none' takes no level")
        return name, 0
    if level_text and not (level_text.isdigit() and int(level_text) in levels):
        raise SpecError(f"{where}: {text!r}: the level of {name} is an integer from "
                        f"{levels.start} to {levels.stop - 1}")
    if name == "zstd":
        import netCDF4

        if not getattr(netCDF4, "__has_zstandard_support__", False):
            raise SpecError(f"{where}: {text!r}: the installed netCDF4 {netCDF4.__version__} "
                            f"(HDF5 {netCDF4.__hdf5libversion__}) cannot write zstd; use "
                            "'zlib'")
    return name, int(level_text) if level_text else DEFAULT_LEVELS[name]


class _Parser:
    def __init__(self, where: str):
        self.where = where
        self.seen: dict[str, str] = {}

    def fail(self, key: str, message: str):
        raise SpecError(f"{self.where}: {key}: {message}")

    def table(self, document: dict, key: str, allowed) -> dict:
        table = document.get(key, {})
        if not isinstance(table, dict):
            self.fail(key, f"expected a table [{key}]")
        for name in table:
            if allowed is not None and name not in allowed:
                self.fail(f"{key}.{name}", "unknown key" + suggestion(name, allowed)
                          + f" (accepted: {', '.join(sorted(allowed))})")
        return table

    # -- the whole definition -------------------------------------------------------------
    def sweep(self, document: dict, text: str) -> Sweep:
        sections = ("sweep", "fixed", "axes", "sample", "output")
        for key in document:
            if key not in sections:
                self.fail(key, "unknown section" + suggestion(key, sections)
                          + " (accepted: [sweep], [fixed], [axes], [sample], [output])")
        storage = self.storage(self.table(document, "output", _OUTPUT_KEYS))
        head = self.table(document, "sweep", ("model", "bearing", "title"))
        name = head.get("model")
        if not isinstance(name, str):
            self.fail("sweep.model", ("missing" if name is None else f"{_written(name)} is not "
                      "a model's name (a string)") + ": name a model, one of "
                      + ", ".join(sorted(all_models())))
        for key in ("bearing", "title"):
            if key in head and not isinstance(head[key], str):
                self.fail(f"sweep.{key}", f"{_written(head[key])}: expected a string ("
                          + ("a preset's name: `bearing-sweep presets` lists them)"
                             if key == "bearing" else "the title of the result)"))
        try:
            model = find_model(name)
        except SpecError as error:
            self.fail("sweep.model", str(error))
        inputs = {i.name: i for i in model.inputs}
        fixed_raw = self.table(document, "fixed", None)
        axes_raw = self.table(document, "axes", None)

        fixed: dict[str, Value | None] = {}
        origin: dict[str, str] = {}
        bearing = head.get("bearing")
        if bearing is not None:
            for key, value in self.preset(bearing, model).items():
                fixed[key], origin[key] = value, f"preset {bearing}"
        for key, raw in fixed_raw.items():
            where = f"fixed.{key}"
            self.claim(key, where, inputs, model)
            fixed[key], origin[key] = self.value(inputs[key], raw, where), "fixed"
        axes = [self.axis(key, raw, inputs, model) for key, raw in axes_raw.items()]
        sample_raw = self.table(document, "sample", None)
        sampled = self.sampled(sample_raw, inputs, model)
        on_axes = {p for axis in axes for p in axis.values} | set(sampled)
        for key in on_axes:
            fixed.pop(key, None)
            origin.pop(key, None)
        missing = [s for s in model.inputs
                   if s.required and s.name not in fixed and s.name not in on_axes]
        if missing:
            described = ", ".join(f"{s.name!r}" + ("" if s.unit in ("", "1") else f" [{s.unit}]")
                                  for s in missing)
            self.fail("fixed", f"missing parameter{'s' * (len(missing) > 1)} {described}; give "
                      "them in [fixed] or [axes], or name a preset in [sweep] bearing")
        for spec in model.inputs:
            if spec.name not in fixed and spec.name not in on_axes:
                fixed[spec.name] = None if spec.default is None else self.default(spec)
                origin[spec.name] = "default"
        sampling = None
        if "sample" in document:
            axis, sampling = self.sample_axis(sample_raw, sampled, model, fixed)
            axes.insert(0, axis)  # every sample at every point of the other axes
        points = int(np.prod([len(axis) for axis in axes], dtype=np.float64))
        if points > MAX_POINTS:
            self.fail("sample.n" if sampling and len(axes) == 1 else "axes",
                      f"the grid has {points:.3g} points, too large for one sweep "
                      f"(at most {MAX_POINTS:.0e}); split it into several definitions")
        # A definition from a file is named after it; one given as text or a dict is not.
        title = model.name if self.where.startswith("<") else \
            f"{model.name}: {Path(self.where).stem}"
        sweep = Sweep(self.where, text, model, str(head.get("title") or title), bearing, fixed,
                      axes, origin, sampling, storage)
        self.check_pattern_lengths(sweep)
        self.check_constraints(sweep)
        return sweep

    def preset(self, name, model: Model) -> dict[str, Value]:
        if not isinstance(name, str) or name not in PRESETS:
            self.fail("sweep.bearing", f"unknown preset {name!r}" + suggestion(str(name), PRESETS)
                      + " (`bearing-sweep presets` lists them)")
        preset = PRESETS[name]
        if model.name not in preset.models:
            self.fail("sweep.bearing", f"preset {name!r} is for {' and '.join(preset.models)}, "
                      f"not {model.name!r}")
        return {key: self.value(model.input(key), raw, f"preset {name}.{key}")
                for key, raw in preset.values.items()}

    def claim(self, name: str, key: str, inputs: dict, model: Model):
        """Check that ``name`` is an input of the model, given only once."""
        if name not in inputs:
            self.fail(key, f"unknown parameter {name!r} of model {model.name}"
                      + suggestion(name, inputs)
                      + f" (`bearing-sweep describe {model.name}` lists them)")
        if name in self.seen:
            self.fail(key, f"parameter {name!r} is given twice (also at {self.seen[name]})")
        self.seen[name] = key

    def default(self, spec: Input) -> Value:
        if spec.kind == "subset":
            return Value(" ".join(spec.default), " ".join(spec.default), "")
        if spec.kind in ("choice", "count"):
            return Value(spec.default, spec.default, spec.unit)
        unit = units.parse_unit(spec.unit)
        return Value(float(units.to_si(spec.default, unit)), spec.default, spec.unit)

    # -- [output] -------------------------------------------------------------------------
    def storage(self, table: dict) -> Storage:
        """How the outputs are written, from the [output] table (defaults for what it omits)."""
        base = storage_options(Storage(), table.get("encoding"), table.get("compression"),
                               lambda key: f"{self.where}: output.{key}")
        shuffle = table.get("shuffle", base.shuffle)
        if not isinstance(shuffle, bool):
            self.fail("output.shuffle", f"{shuffle!r}: expected true or false")
        return replace(base, shuffle=shuffle)

    # -- [sample] -------------------------------------------------------------------------
    def sampled(self, table: dict, inputs: dict, model: Model) -> dict:
        """The parameters a [sample] table draws, each claimed (given only once)."""
        sampled = {}
        for name, raw in table.items():
            if name in _SAMPLE_SETTINGS:
                continue
            key = f"sample.{name}"
            if name not in inputs:
                self.fail(key, f"unknown key: neither a setting ({', '.join(_SAMPLE_SETTINGS)}) "
                          f"nor a parameter of model {model.name}"
                          + suggestion(name, list(_SAMPLE_SETTINGS) + list(inputs))
                          + f" (`bearing-sweep describe {model.name}` lists them)")
            self.claim(name, key, inputs, model)
            spec = inputs[name]
            if spec.structural:
                self.fail(key, f"{name!r} is a {spec.kind} and cannot be sampled (only numbers "
                          "and quantities can); vary it on an axis")
            if not isinstance(raw, dict) or not isinstance(raw.get("distribution"), str):
                self.fail(key, "expected a table naming its distribution, e.g. { distribution = "
                          "\"uniform\", low = ..., high = ... } (distributions: "
                          f"{', '.join(sample.DISTRIBUTIONS)})")
            sampled[name] = raw
        return sampled

    def sample_axis(self, table: dict, sampled: dict, model: Model,
                    fixed: dict) -> tuple[Axis, Sampling]:
        """The ``sample`` axis: a zipped axis of the drawn values, numbered from 0."""
        n = table.get("n")
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            self.fail("sample.n", f"{'missing' if n is None else repr(n)}: expected the number "
                      "of samples, a positive integer")
        method = table.get("method")
        if method not in sample.METHODS:
            self.fail("sample.method", ("missing" if method is None else f"{method!r} is not "
                      "accepted") + suggestion(str(method), sample.METHODS)
                      + f" (methods: {', '.join(sample.METHODS)})")
        seed = table.get("seed", 0)
        if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed <= MAX_INTEGER:
            self.fail("sample.seed", f"{_short(repr(seed))}: expected an integer from 0 to "
                      f"{MAX_INTEGER} (the same seed draws the same samples)")
        if method == "saltelli" and n < sample.SALTELLI_MIN_N:
            self.fail("sample.n", f"{n}: a saltelli design needs at least "
                      f"{sample.SALTELLI_MIN_N} base samples (each of its "
                      f"{sample.SALTELLI_REPLICATES} replicates needs so many for Sobol' "
                      "indices whose intervals hold)")
        if method in sample.POWER_OF_TWO and n & (n - 1):
            below = 1 << (n.bit_length() - 1)
            self.fail("sample.n", f"{n}: a {method} design needs a power of 2 (its balance "
                      f"depends on it); take {below} or {2 * below}")
        if not sampled:
            self.fail("sample", "no parameter to sample: give at least one, e.g. radial_load = "
                      "{ distribution = \"uniform\", low = \"1 kN\", high = \"8 kN\" }")
        replicates = sample.SALTELLI_REPLICATES if method == "saltelli" else 1
        size = n * replicates * (len(sampled) + 2) if method == "saltelli" else n
        if size > MAX_AXIS_VALUES:
            self.fail("sample.n", f"{n}: the design would have {size} samples, more than "
                      f"{MAX_AXIS_VALUES:.0e}")
        distributions = {name: self.distribution(model.input(name), raw, f"sample.{name}")
                         for name, raw in sampled.items()}
        widths = [self.sampled_length(model, model.input(name), fixed) for name in sampled]
        if method == "saltelli":
            cube = sample.saltelli_blocks(n, widths, seed, replicates)
        else:
            cube = sample.unit_hypercube(method, n, sum(widths), seed)
        values, column = {}, 0
        for (name, distribution), width in zip(distributions.items(), widths):
            spec = model.input(name)
            drawn = distribution.frozen().ppf(cube[:, column:column + width])
            column += width
            if not spec.dims:
                drawn = drawn[:, 0]
            si = units.to_si(drawn, units.parse_unit(spec.unit))
            values[name] = [Value(s if spec.dims else float(s), d if spec.dims else float(d),
                                  spec.unit) for s, d in zip(si, drawn)]
        blocks = tuple(sample.block_meanings(list(sampled))) if method == "saltelli" else None
        sampling = Sampling(method, n, seed, {name: d.text(model.input(name).unit)
                                              for name, d in distributions.items()}, blocks,
                            replicates)
        return Axis("sample", values, list(range(size))), sampling

    def distribution(self, spec: Input, raw: dict, key: str) -> sample.Distribution:
        """A sampled parameter's distribution, its parameters in the declared unit, checked
        against the parameter's valid range."""
        name = raw["distribution"]
        if name not in sample.DISTRIBUTIONS:
            self.fail(f"{key}.distribution", f"{name!r} is not accepted"
                      + suggestion(name, sample.DISTRIBUTIONS)
                      + f" (distributions: {', '.join(sample.DISTRIBUTIONS)})")
        wanted = sample.DISTRIBUTIONS[name]
        accepted = {"distribution"} | {p for p, _ in wanted} | (
            {"distribution_within"} if name == "tolerance" else set())
        for extra in raw:
            if extra not in accepted:
                self.fail(f"{key}.{extra}", f"not a parameter of a {name} distribution"
                          + suggestion(extra, accepted)
                          + f" (it takes {', '.join(p for p, _ in wanted)})")
        missing = [p for p, _ in wanted if p not in raw]
        if missing:
            self.fail(key, f"a {name} distribution needs {', '.join(missing)} (it takes "
                      f"{', '.join(p for p, _ in wanted)})")
        within = raw.get("distribution_within", "uniform")
        if within not in sample.WITHIN:
            self.fail(f"{key}.distribution_within", f"{within!r} is not accepted (accepted: "
                      f"{', '.join(repr(w) for w in sample.WITHIN)})")
        scalar = replace(spec, dims=(), broadcast=False)
        declared = units.parse_unit(spec.unit)
        parameters = {}
        for parameter, kind in wanted:
            value = self.value(scalar, raw[parameter], f"{key}.{parameter}", check_range=False)
            written = units.revolutions(units.parse_unit(value.unit), declared)
            target = declared
            if kind == "difference":  # a width: "2 K" or "2 delta_degC" on a degC parameter
                written, target = units.as_difference(written), units.as_difference(declared)
            parameters[parameter] = float(units.convert(value.shown, written, target))
        distribution = sample.Distribution(name, parameters, within)
        problem = distribution.problem()
        if problem:
            self.fail(key, f"{problem} ({distribution.text(spec.unit)})")
        low, high = distribution.support()
        below = spec.minimum is not None and (
            low <= spec.minimum if spec.exclusive_minimum else low < spec.minimum)
        above = spec.maximum is not None and high > spec.maximum
        if below or above:
            end = low if below else high
            reach = (f"has no {'lower' if below else 'upper'} bound" if np.isinf(end) else
                     f"reaches {end:g}" + ("" if spec.unit in ("", "1") else f" {spec.unit}"))
            self.fail(key, f"a {name} distribution {reach}, outside the valid range of "
                      f"{spec.name} ({spec.range_text()}); keep it within the range (a "
                      "truncated_normal with low and high, or a bounded distribution)")
        return distribution

    def sampled_length(self, model: Model, spec: Input, fixed: dict) -> int:
        """How many values one sample of ``spec`` draws: 1, or one per entry of a pattern
        whose length a fixed count sets. A pattern no count sizes that takes one value for
        all its entries (a raceway's single harmonic, say) draws that one value."""
        if not spec.dims:
            return 1
        count = model.dim_sizes.get(spec.dims[0])
        key = f"sample.{spec.name}"
        if not isinstance(count, str) or count not in {i.name for i in model.inputs}:
            if spec.broadcast:
                return 1
            self.fail(key, f"sampling of the pattern {spec.name!r} is not supported: no count "
                      f"sets its length (one value per {spec.dims[0]})")
        if fixed.get(count) is None:
            self.fail(key, f"sampling the pattern {spec.name!r} needs {count!r} fixed (it sets "
                      f"the pattern's length), not on an axis or sampled")
        return int(fixed[count].si)

    # -- axes -----------------------------------------------------------------------------
    def axis(self, name: str, raw, inputs: dict, model: Model) -> Axis:
        key = f"axes.{name}"
        if name in inputs:
            if isinstance(raw, dict) and "labels" in raw:
                self.fail(key, "a zipped axis needs a name that is not a parameter of "
                          f"{model.name}")
            self.claim(name, key, inputs, model)
            spec = inputs[name]
            values = self.axis_values(spec, raw, key) if spec.broadcast or not spec.dims else []
            if spec.dims and (not spec.broadcast or any(np.ndim(v.shown) for v in values)):
                self.fail(key, f"{name!r} is a pattern (one value per {spec.dims[0]}): vary it "
                          f"on a labelled axis, [axes.<name>] labels = [...], {name} = [...]")
            return Axis(name, {name: values})
        if not isinstance(raw, dict):
            self.fail(key, f"unknown parameter {name!r} of model {model.name}"
                      + suggestion(name, inputs)
                      + f" (`bearing-sweep describe {model.name}` lists them)")
        if not AXIS_NAME.fullmatch(name):
            self.fail(key, f"{_short(name)!r} cannot name an axis: a name starts with a letter "
                      "and holds letters, digits and underscores, at most 64 characters (CF "
                      "conventions 2.3; netCDF and zarr read other characters as paths or "
                      "refuse them)")
        taken = {o.name for o in model.outputs} | {d for o in model.outputs for d in o.dims} \
            | {f"{o.name}_units" for o in model.outputs if o.entry_units}
        if name in taken | RESERVED_NAMES:
            self.fail(key, f"the axis name {name!r} is taken by an output or its dimension"
                      if name in taken else f"the axis name {name!r} is reserved (for the "
                      "status of each point, the [sample] axis and the analysis of a sampled "
                      "result)")
        values = {}
        for parameter, column in raw.items():
            if parameter == "labels":
                continue
            self.claim(parameter, f"{key}.{parameter}", inputs, model)
            values[parameter] = self.axis_values(inputs[parameter], column, f"{key}.{parameter}")
        if not values:
            self.fail(key, "a zipped axis needs at least one parameter besides 'labels'")
        for parameter, column in values.items():
            sizes = {np.size(v.si) for v in column if np.ndim(v.shown)} | {1}
            if len(sizes) > 2:
                self.fail(f"{key}.{parameter}", "the patterns differ in length ("
                          + ", ".join(str(n) for n in sorted(sizes - {1})) + " values)")
        lengths = {p: len(v) for p, v in values.items()}
        labels = raw.get("labels")
        if labels is not None:
            self.check_labels(labels, f"{key}.labels")
            lengths["labels"] = len(labels)
        if len(set(lengths.values())) > 1:
            described = ", ".join(f"{p} has {n}" for p, n in lengths.items())
            self.fail(key, f"ragged zipped axis: {described} values; all must have the same number")
        return Axis(name, values, labels if labels is not None else list(range(len(
            next(iter(values.values()))))))

    def check_labels(self, labels, key: str):
        """A zipped axis' labels: strings a file stores as written, or integers in order."""
        if not isinstance(labels, list) or not labels or not all(
                isinstance(x, (str, int)) and not isinstance(x, bool) for x in labels):
            self.fail(key, "expected a non-empty list of strings or integers")
        for index, label in enumerate(labels):
            if isinstance(label, str) and not (0 < len(label) <= 256 and label.isprintable()):
                self.fail(f"{key}[{index}]", f"{_short(label)!r}: a label is 1 to 256 printable "
                          "characters (no control characters: a file would not keep them)")
            if isinstance(label, int):
                self.fits(label, f"{key}[{index}]")
        if len({type(x) for x in labels}) > 1:
            self.fail(key, "labels are all strings or all integers")
        if len(set(labels)) != len(labels):
            self.fail(key, "labels must be unique")
        if isinstance(labels[0], int):
            self.monotonic(labels, key, "labels")

    def monotonic(self, numbers, key: str, what: str = "values"):
        """Refuse numbers of an axis out of order: a coordinate variable is strictly
        monotonic (CF conventions 1.10, section 5), so that a reader can select ranges."""
        steps = np.sign(np.diff(np.asarray(numbers, dtype=float)))
        if len(steps) and not (np.all(steps > 0) or np.all(steps < 0)):
            turn = int(np.argmax(steps != steps[0])) + 1  # the first value out of order
            self.fail(f"{key}[{turn}]" if what == "values" else key,
                      f"the {what} of an axis run in one direction, increasing or decreasing "
                      f"(CF 1.10 section 5: a coordinate is monotonic); sort them")

    def fits(self, number: int, key: str):
        """Refuse an integer beyond what 64 bits hold (TOML's integers have no limit)."""
        if abs(number) > MAX_INTEGER:
            self.fail(key, f"{_short(str(number))} is too large: an integer of a definition is "
                      f"at most {MAX_INTEGER} in magnitude")

    def axis_values(self, spec: Input, raw, key: str) -> list[Value]:
        if isinstance(raw, list):
            values = [self.value(spec, item, f"{key}[{i}]") for i, item in enumerate(raw)]
        elif isinstance(raw, dict) and set(raw) <= _VALUES_KEYS and "values" in raw:
            if not isinstance(raw["values"], list):
                self.fail(f"{key}.values", "expected a list")
            unit = raw.get("units")
            values = [self.value(spec, item, f"{key}.values[{i}]", unit)
                      for i, item in enumerate(raw["values"])]
        elif isinstance(raw, dict) and set(raw) <= _RANGE_KEYS and {"start", "stop"} <= set(raw):
            values = self.value_range(spec, raw, key)
        else:
            self.fail(key, "an axis is a list of values, {values = [...], units = \"...\"} or "
                      "{start = ..., stop = ..., num = ... (or step = ...)}")
        if not values:
            self.fail(key, "empty axis: give at least one value")
        if key.count(".") == 1 and not any(np.ndim(v.si) for v in values):
            self.unique(values, key)  # a plain axis; a zipped one's columns may repeat
            if not isinstance(values[0].si, str):
                self.monotonic([v.si for v in values], key)
        return self.same_unit(values)

    def value_range(self, spec: Input, raw: dict, key: str) -> list[Value]:
        if spec.kind in ("choice", "subset") or (spec.dims and not spec.broadcast):
            self.fail(key, f"{spec.name!r} cannot take a range; list its values")
        if ("num" in raw) == ("step" in raw):
            self.fail(key, "a range needs exactly one of 'num' (number of values) or 'step'")
        unit = raw.get("units")
        start = self.value(spec, raw["start"], f"{key}.start", unit, check_range=False)
        stop = self.value(spec, raw["stop"], f"{key}.stop", unit, check_range=False)
        with np.errstate(over="ignore", invalid="ignore"):
            stop_shown = units.convert(stop.shown, units.parse_unit(stop.unit),
                                       units.parse_unit(start.unit)) \
                if start.unit not in ("", "1") else stop.shown
        if not np.isfinite(stop_shown):
            self.fail(f"{key}.stop", f"{_written(raw['stop'])} is too large to compute with in "
                      f"the unit of the start ({start.unit})")
        if "num" in raw:
            num = raw["num"]
            if isinstance(num, bool) or not isinstance(num, int) or num < 1:
                self.fail(f"{key}.num", f"{num!r}: expected an integer >= 1")
            self.axis_size(num, f"{key}.num")
            if num == 1 and not np.isclose(stop_shown, start.shown, rtol=SAME_VALUE, atol=0):
                self.fail(f"{key}.num", "1 value from start to a different stop would leave the "
                          "stop out: give num >= 2, or the one value as a list")
            shown = units.tidy(np.linspace(start.shown, stop_shown, num))
        else:
            step = self.value(spec, raw["step"], f"{key}.step", unit, check_range=False)
            step_shown = step.shown
            if start.unit not in ("", "1"):  # a step is a difference: 10 K on a degC axis
                with np.errstate(over="ignore", invalid="ignore", under="ignore"):
                    step_shown = units.convert(step.shown, units.as_difference(
                        units.parse_unit(step.unit)), units.as_difference(units.parse_unit(
                            start.unit)))
            if not step_shown > 0:
                self.fail(f"{key}.step", "the step must be positive")
            with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
                count = np.floor((stop_shown - start.shown) / step_shown + 1e-9) + 1
            if count < 1:
                self.fail(key, "empty axis: 'stop' is below 'start'")
            if count == 1 and not np.isclose(stop_shown, start.shown, rtol=SAME_VALUE, atol=0):
                self.fail(f"{key}.step", "the step is larger than the range from start to stop: "
                          "the axis would hold the start only; take a smaller step")
            self.axis_size(count, f"{key}.step")
            shown = units.tidy(start.shown + step_shown * np.arange(int(count)))
        if spec.kind == "count":
            return [self.value(spec, float(x), f"{key}") for x in shown]
        if spec.dims:
            return [self.value(spec, float(x), f"{key}", start.unit) for x in shown]
        return self.range_values(spec, shown, key, start.unit)

    def range_values(self, spec: Input, shown: np.ndarray, key: str, unit_text: str):
        """The values of a scalar quantity's range, all in ``unit_text``: the first checked
        by :meth:`value` (units and all), the rest converted and range-checked at once (a long
        axis would otherwise cost a unit parse per value)."""
        first = self.value(spec, float(shown[0]), key, unit_text)
        declared = units.parse_unit(spec.unit)
        unit = units.revolutions(units.parse_unit(unit_text), declared)
        si = self.finite_si(spec, shown, unit, key, "a value of the range")
        self.in_range(spec, units.convert(shown, unit, declared), spec.unit, key, list(shown))
        return [first] + [Value(float(a), float(b), unit_text)
                          for a, b in zip(si[1:], shown[1:])]

    def finite_si(self, spec: Input, magnitude, unit, key: str, raw):
        """``magnitude`` in ``unit`` converted to SI; a NaN, an infinity or a value whose
        conversion overflows is refused, each for what it is."""
        magnitude = np.asarray(magnitude, dtype=float)
        if np.isnan(magnitude).any():
            self.fail(key, f"{_written(raw)} is not a number (NaN); {spec.name} must be "
                      f"{spec.range_text()}")
        if np.isinf(magnitude).any() and not isinstance(raw, str):
            self.fail(key, f"{_written(raw)} is infinite; {spec.name} must be "
                      f"{spec.range_text()}")
        with np.errstate(over="ignore", invalid="ignore"):
            si = units.to_si(magnitude, unit)
        if not np.all(np.isfinite(si)):
            self.fail(key, f"{_written(raw)} is too large to compute with (not finite in SI "
                      f"units); {spec.name} must be {spec.range_text()}")
        return si

    def axis_size(self, count, key: str):
        """Refuse an axis too long to validate, from its arithmetic alone."""
        if not count <= MAX_AXIS_VALUES:
            self.fail(key, f"the axis would have {float(count):.3g} values, more than "
                      f"{MAX_AXIS_VALUES:.0e} on one axis; take fewer values or a larger step")

    def unique(self, values: list[Value], key: str):
        """Refuse an axis that names one value twice ("1 kN" and "1000 N", "70 degC" and
        "158 degF"): its index would not be unique. Quantities are compared in SI, as equal
        within :data:`SAME_VALUE` of their size, so that two spellings of one value that
        differ only by rounding in the conversion count as one."""
        order = sorted(range(len(values)), key=lambda i: _order_key(values[i].si))
        for before, after in zip(order, order[1:]):
            first, second = values[before].si, values[after].si
            same = first == second if isinstance(first, str) or isinstance(second, str) \
                else abs(first - second) <= SAME_VALUE * max(abs(first), abs(second))
            if same:
                index, earlier = max(before, after), min(before, after)
                value = values[index]
                self.fail(f"{key}[{index}]", f"{_plain(value.shown)!s}"
                          f"{'' if value.unit in ('', '1') else ' ' + value.unit} is the same "
                          f"value as {key}[{earlier}]: each value of an axis must differ")

    def same_unit(self, values: list[Value]) -> list[Value]:
        """Express every value of an axis in the unit of its first value."""
        first = values[0].unit
        if first in ("", "1"):
            return values
        target = units.parse_unit(first)
        return [v if v.unit == first else
                Value(v.si, units.convert(v.shown, units.parse_unit(v.unit), target), first)
                for v in values]

    # -- single values --------------------------------------------------------------------
    def value(self, spec: Input, raw, key: str, unit_text=None, check_range=True) -> Value:
        """One value of ``spec`` (a whole pattern for an array input)."""
        for number in _integers(raw):
            self.fits(number, key)
        if spec.kind == "choice":
            if not isinstance(raw, str) or raw not in spec.choices:
                self.fail(key, f"{raw!r} is not accepted; {spec.name} is {spec.range_text()}"
                          + suggestion(str(raw), spec.choices))
            return Value(raw, raw, "")
        if spec.kind == "subset":
            return self.subset(spec, raw, key)
        if spec.dims and spec.broadcast and not isinstance(raw, (list, dict)):
            one = self.value(replace(spec, dims=()), raw, key, unit_text, check_range)
            return Value(np.atleast_1d(one.si), one.shown, one.unit)  # stands for every entry
        if unit_text is not None and spec.kind == "count":
            self.fail(key, f"{spec.name!r} is a count and takes no units")
        if spec.kind == "count":
            if (isinstance(raw, bool) or not isinstance(raw, (int, float))
                    or not np.isfinite(raw) or raw != int(raw)):
                self.fail(key, f"{raw!r}: {spec.name} must be {spec.range_text()}")
            if check_range:
                self.in_range(spec, int(raw), "1", key, raw)
            return Value(int(raw), int(raw), "1")
        magnitude, unit_text = self.magnitude(spec, raw, key, unit_text)
        try:
            unit = units.parse_unit(unit_text)
        except units.UnitError as error:
            self.fail(key, f"{error}; {spec.name} is in units like {spec.unit!r}")
        declared = units.parse_unit(spec.unit)
        unit = units.revolutions(unit, declared)
        if not units.compatible(unit, declared):
            hint = ""
            if unit_text.strip() in ("mil", "mils") and unit.dimensionless:
                hint = " (pint reads 'mil' as an angle; a thousandth of an inch is 'thou')"
            elif "hertz" in str(unit):
                hint = " (Hz is ambiguous for a rotational speed: write rpm, r/min or 1/min)"
            self.fail(key, f"units {unit_text!r} do not fit {spec.name}, which is in units like "
                      f"{spec.unit!r}{hint}")
        si = self.finite_si(spec, magnitude, unit, key, raw)
        if check_range:
            try:
                in_declared = units.convert(magnitude, unit, declared)
            except units.pint.errors.DimensionalityError:  # delta_degC for a temperature
                self.fail(key, f"{raw!r} is a difference of temperatures; {spec.name} is a "
                          f"temperature, in units like {spec.unit!r}")
            self.in_range(spec, in_declared, spec.unit, key, raw)
        return Value(si if spec.dims else float(si), magnitude, unit_text)

    def subset(self, spec: Input, raw, key: str) -> Value:
        """A list of distinct choices, as their names in declared order joined by spaces."""
        if not isinstance(raw, list) or not all(isinstance(x, str) for x in raw):
            self.fail(key, f"{raw!r}: {spec.name} is {spec.range_text()}, e.g. "
                      f"[{', '.join(repr(c) for c in spec.choices[:2])}] (on an axis: a list "
                      "of such lists)")
        for item in raw:
            if item not in spec.choices:
                self.fail(key, f"{item!r} is not accepted; {spec.name} is {spec.range_text()}"
                          + suggestion(item, spec.choices))
        if len(set(raw)) != len(raw):
            self.fail(key, f"{raw!r}: a value is listed twice")
        names = " ".join(c for c in spec.choices if c in raw)
        return Value(names, names, "")

    def magnitude(self, spec: Input, raw, key: str, unit_text):
        """The number(s) and unit text of a quantity written in any accepted form."""
        dimensionless = spec.unit == "1"
        if spec.dims:
            if isinstance(raw, dict) and set(raw) <= _VALUES_KEYS and "values" in raw:
                raw, unit_text = raw["values"], raw.get("units", unit_text)
            if not isinstance(raw, list) or not raw:
                self.fail(key, f"{spec.name!r} is a pattern: a non-empty list, or "
                          "{values = [...], units = \"...\"}")
            if all(isinstance(x, str) for x in raw) and unit_text is None:
                parts = [self.split(x, spec, f"{key}[{i}]") for i, x in enumerate(raw)]
                found = []
                for i, (_, text) in enumerate(parts):
                    if not text and spec.unit != "1":
                        self.fail(f"{key}[{i}]", f"{raw[i]!r} has no units; {spec.name} needs "
                                  f"units like {spec.unit!r}")
                    found.append(self.unit_of(text or "1", f"{key}[{i}]"))
                    if not units.compatible(found[-1], found[0]):
                        self.fail(f"{key}[{i}]", f"{raw[i]!r}: units differ in kind from "
                                  f"{raw[0]!r}")
                return np.array([units.convert(m, u, found[0]) for (m, _), u in
                                 zip(parts, found)]), parts[0][1] or "1"
            if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in raw):
                self.fail(key, f"{spec.name!r}: the pattern must hold numbers (with 'units') or "
                          "quantity strings")
            raw = np.array(raw, dtype=float)
        elif isinstance(raw, str):
            if unit_text is not None:
                self.fail(key, f"{raw!r}: give plain numbers together with 'units'")
            raw, unit_text = self.split(raw, spec, key)
            unit_text = unit_text or None
        elif isinstance(raw, list) and key.startswith("fixed."):
            self.fail(key, "[fixed] takes one value; a list of values is an axis: put it in [axes]")
        elif isinstance(raw, bool) or not isinstance(raw, (int, float)):
            self.fail(key, f"{raw!r}: expected a number with units, e.g. '1.5 {spec.unit}'")
        if unit_text is None:
            if not dimensionless:
                self.fail(key, f"{raw!r} has no units; {spec.name} needs units like "
                          f"{spec.unit!r} (write e.g. '{_plain(raw)} {spec.unit}')")
            unit_text = "1"
        return raw, unit_text

    def split(self, text: str, spec: Input, key: str) -> tuple[float, str]:
        try:
            return units.split_quantity(text)
        except units.UnitError as error:
            self.fail(key, f"{error}; write e.g. '1.5 {spec.unit}'")

    def unit_of(self, text: str, key: str):
        try:
            return units.parse_unit(text)
        except units.UnitError as error:
            self.fail(key, str(error))

    def in_range(self, spec: Input, magnitude, unit: str, key: str, raw):
        values = np.atleast_1d(np.asarray(magnitude, dtype=float))
        low = spec.minimum
        bad = ~np.isfinite(values)
        if low is not None:
            bad |= values <= low if spec.exclusive_minimum else values < low
        if spec.maximum is not None:
            bad |= values > spec.maximum
        if bad.any():
            shown = raw if not isinstance(raw, (list, dict)) else f"{values[bad][0]:g} {unit}"
            self.fail(key, f"{shown!r} is out of range: {spec.name} must be {spec.range_text()}")

    # -- conditions between parameters ----------------------------------------------------
    def check_pattern_lengths(self, sweep: Sweep):
        """A pattern with one value per roller has as many values as there are rollers."""
        model = sweep.model
        for spec in model.inputs:
            count_name = model.dim_sizes.get(spec.dims[0]) if spec.dims else None
            if not isinstance(count_name, str) or count_name not in {i.name for i in
                                                                       model.inputs}:
                continue
            patterns, where = self.values_of(sweep, spec.name)
            counts, _ = self.values_of(sweep, count_name)
            lengths = {np.size(v.si) for v in patterns} - ({1} if spec.broadcast else set())
            wanted = {int(v.si) for v in counts}
            for length in lengths:
                if wanted != {length}:
                    other = ", ".join(str(n) for n in sorted(wanted - {length}))
                    self.fail(where, f"{spec.name} has {length} values but {count_name} is "
                              f"{other}: give one value per {spec.dims[0]}"
                              + (" (or a single value for all)" if spec.broadcast else ""))

    @staticmethod
    def values_of(sweep: Sweep, name: str) -> tuple[list, str]:
        """Every value ``name`` takes on the grid, and where it was given."""
        for axis in sweep.axes:
            if name in axis.values:
                where = f"axes.{axis.name}" + (f".{name}" if axis.name != name else "")
                return axis.values[name], where
        origin = sweep.origin.get(name, "fixed")
        return [sweep.fixed[name]], (f"fixed.{name}" if origin == "fixed"
                                     else f"{origin}.{name}")

    def check_constraints(self, sweep: Sweep):
        for constraint in sweep.model.constraints:
            columns, si, axis_of = {}, {}, {}
            for name in constraint.inputs:
                if name in sweep.fixed:
                    if sweep.fixed[name] is None:
                        break
                    columns[name] = [sweep.fixed[name]]
                    si[name] = stack(columns[name])
                else:
                    axis = next(a for a in sweep.axes if name in a.values)
                    columns[name], axis_of[name] = axis.values[name], axis.name
                    si[name] = axis.si[name]
            else:
                self.check_constraint(constraint, columns, si, axis_of, sweep.model)

    def check_constraint(self, constraint, columns: dict, si: dict, axis_of: dict,
                         model: Model):
        axis_names = list(dict.fromkeys(axis_of.values()))
        arrays = {}
        for name, column in columns.items():
            shape = [1] * len(axis_names)
            if name in axis_of:
                shape[axis_names.index(axis_of[name])] = len(column)
            values = si[name]
            arrays[name] = values.reshape(shape + list(values.shape[1:]))  # patterns: trailing
        valid = np.broadcast_to(constraint.check(**arrays), np.broadcast_shapes(
            *(a.shape[:len(axis_names)] for a in arrays.values())))
        if not valid.all():
            where = np.unravel_index(np.argmin(valid), valid.shape) if valid.ndim else ()
            shown = []
            for name, column in columns.items():
                index = where[axis_names.index(axis_of[name])] if name in axis_of else 0
                value = column[index]
                unit = "" if value.unit in ("", "1") else f" {value.unit}"
                if model.input(name).kind == "subset":  # as written: a list of names
                    shown.append(f"{name} = {value.shown.split()}")
                    continue
                shown.append(f"{name} = {_plain(value.shown)}{unit}")
            section = ("sample" if "sample" in axis_of.values() else "axes") if axis_of \
                else "fixed"
            raise SpecError(f"{self.where}: {section}: {constraint.message} "
                            f"({', '.join(shown)})")


def stack(values: list[Value]) -> np.ndarray:
    """The SI values of an axis (or a fixed value) as one array, points first; a single
    value given for a pattern input is repeated to the length of the others."""
    first = values[0].si
    if isinstance(first, str):
        return np.array([v.si for v in values], dtype=object)
    if isinstance(first, (int, np.integer)):
        return np.array([v.si for v in values], dtype=np.int64)
    arrays = [np.asarray(v.si, dtype=float) for v in values]
    if len({a.shape for a in arrays}) > 1:  # single values stand for a whole pattern
        size = max(a.size for a in arrays)
        arrays = [np.broadcast_to(a, (size,)) for a in arrays]
    return np.stack(arrays)


def _written(raw) -> str:
    """A value as the definition wrote it, for a message: TOML's nan and inf by name."""
    if isinstance(raw, float) and not np.isfinite(raw):
        return "nan" if np.isnan(raw) else ("-inf" if raw < 0 else "inf")
    return repr(raw) if isinstance(raw, (str, float, int)) else str(raw)


def _integers(raw):
    """The integers in a value as TOML gives it (a number, or a list or table of them)."""
    if isinstance(raw, int) and not isinstance(raw, bool):
        yield raw
    elif isinstance(raw, (list, dict)):
        for item in (raw.values() if isinstance(raw, dict) else raw):
            yield from _integers(item)


def _short(text: str) -> str:
    return text if len(text) <= 40 else text[:37] + "..."


def _order_key(si) -> tuple:
    """Sorts an axis' values: strings (choices) apart from numbers."""
    return (1, si, 0.0) if isinstance(si, str) else (0, "", float(si))


def _plain(number) -> str:
    return f"{number:g}" if isinstance(number, (int, float)) else str(number)
