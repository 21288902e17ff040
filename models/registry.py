"""Model registry: every model's inputs and outputs, with units, defaults and valid ranges.

A model is a pure function of numpy arrays in SI base units. Its declaration here says, in the
units engineers customarily write (mm, N, r/min, ...), what each input means, its default and
the range in which the model is valid, and what each output is, with its own dimensions.
The sweep engine uses the declarations to validate definitions, convert units at the boundary
and label the netCDF output; the models never see a unit string.

Models are found through the entry-point group ``bearing_sweep.models`` (ours are declared in
this package's ``pyproject.toml``, other packages declare theirs the same way): each entry
point names a module holding a list ``MODELS``, or (``module:attribute``) one ``Model`` or a
list of them. A plug-in that cannot be used is left out with one logged line naming it; the
other models stay available.
"""
from __future__ import annotations

import inspect
import logging
import re
import types
from dataclasses import dataclass, field
from importlib.metadata import EntryPoint, PackageNotFoundError, distribution, entry_points
from typing import Callable

import numpy as np

#: Status codes shared by all models (netCDF ``flag_masks`` / ``flag_values`` /
#: ``flag_meanings``). A point's status is a bit field: its outcome (bits 0, 1 and 3:
#: converged, not converged, infeasible, model error or no root in range, one of them) and,
#: apart from it, bit 2 where the point lies outside the model's stated validity, whatever its
#: outcome: ``NO_ROOT_IN_RANGE | OUT_OF_VALIDITY`` is both. A point converged within validity
#: is 0, as before; an earlier file's ``no_root_in_range`` was 5.
CONVERGED, NOT_CONVERGED, INFEASIBLE, MODEL_ERROR = range(4)
OUT_OF_VALIDITY, NO_ROOT_IN_RANGE = 4, 8
#: The bits of a status that hold its outcome, and the one that says "outside validity".
OUTCOME_MASK, VALIDITY_MASK = 0b1011, OUT_OF_VALIDITY
STATUS_MEANINGS = ("converged", "not_converged", "infeasible", "model_error",
                   "out_of_validity", "no_root_in_range")
#: Each meaning's value and mask (``status & mask == value`` where it holds), in the order of
#: :data:`STATUS_MEANINGS`.
STATUS_VALUES = (CONVERGED, NOT_CONVERGED, INFEASIBLE, MODEL_ERROR, OUT_OF_VALIDITY,
                 NO_ROOT_IN_RANGE)
STATUS_MASKS = (OUTCOME_MASK,) * 4 + (VALIDITY_MASK, OUTCOME_MASK)
#: What each status says of a point, for ``describe``, the documentation and the netCDF ``comment``.
STATUS_DESCRIPTIONS = {
    "converged": "solved; the values hold",
    "not_converged": "the solver stopped without meeting its tolerance; outputs are NaN",
    "infeasible": "no solution exists for these inputs (e.g. a load the bearing cannot "
                  "carry); outputs are NaN",
    "model_error": "the model raised an exception for this group of points; outputs are NaN",
    "out_of_validity": "outside the model's stated validity (its limits are in "
                       "`bearing-sweep describe MODEL`), whatever the point's other status: "
                       "values kept where it has them, do not trust them",
    "no_root_in_range": "solved, but the root the model searches for (a limit angle, a cage "
                        "equilibrium) is not in its search range; the outputs that need it "
                        "are NaN, the others hold",
}
#: Outcomes whose values the engine keeps; the others are NaN whatever the model returned.
VALUES_KEPT = (CONVERGED, NO_ROOT_IN_RANGE)
#: Order in which the outcomes of one point combine (the last named wins).
_SEVERITY = (CONVERGED, NO_ROOT_IN_RANGE, INFEASIBLE, NOT_CONVERGED, MODEL_ERROR)


def combine_status(*codes):
    """The status of points that went through several steps (arrays that broadcast): the
    most severe outcome of ``codes``, in the order converged < no_root_in_range < infeasible
    < not_converged < model_error, and out of validity where any of them is."""
    codes = [np.asarray(c, dtype=np.int64) for c in np.broadcast_arrays(*codes)]
    rank = np.full(OUTCOME_MASK + 1, len(_SEVERITY) - 1)  # an unknown outcome: model_error
    rank[list(_SEVERITY)] = np.arange(len(_SEVERITY))
    worst = np.max([rank[c & OUTCOME_MASK] for c in codes], axis=0)
    outside = np.any([c & VALIDITY_MASK for c in codes], axis=0)
    return (np.asarray(_SEVERITY, dtype=np.int8)[worst] | np.where(outside, OUT_OF_VALIDITY, 0)
            ).astype(np.int8)


def outcome(status):
    """The outcome of each status (its validity bit cleared)."""
    return np.asarray(status) & OUTCOME_MASK


def values_kept(status):
    """Where a status keeps the point's values (converged or no root in range, within
    validity or not)."""
    return np.isin(outcome(status), VALUES_KEPT)


def out_of_validity(status):
    """Where a status says the point lies outside the model's validity."""
    return (np.asarray(status) & VALIDITY_MASK) != 0


def known_status(status):
    """Where a model's status is one this registry defines (an outcome, with or without the
    validity bit)."""
    status = np.asarray(status)
    return (status >= 0) & ((status & ~(OUTCOME_MASK | VALIDITY_MASK)) == 0) & np.isin(
        status & OUTCOME_MASK, _SEVERITY)


#: Relative rounding that a value written in a customary unit ("1000 rpm", "45 deg") may
#: carry once converted to SI and back ("1000 rpm" reads 999.9999999999999 r/min again): a
#: branch of a formula at a round value of an input compares with this much room.
UNIT_ROUNDING = 1e-12


def below(value, branch_point):
    """Where ``value`` lies below ``branch_point`` by more than :data:`UNIT_ROUNDING`: the
    branch "under" of a formula whose branch point is written in the input's customary unit,
    so that an input written exactly at the branch point takes the branch "at or above" it
    whatever rounding its conversion to SI left."""
    return np.asarray(value) < np.asarray(branch_point) * (1.0 - UNIT_ROUNDING)


#: Marks an input that has no default and must be given.
REQUIRED = object()

#: The entry-point group through which packages declare models (this one included).
ENTRY_POINT_GROUP = "bearing_sweep.models"
#: The distribution whose models keep their names when a plug-in declares the same.
_OWN_DISTRIBUTION = "bearing-sweep"

_LOG = logging.getLogger(__name__)


@dataclass(frozen=True)
class Input:
    """One model input.

    ``kind`` is ``"quantity"`` (a number with units), ``"number"`` (a dimensionless number),
    ``"count"`` (a positive integer that sets array shapes), ``"choice"`` (one of
    ``choices``) or ``"subset"`` (a list of distinct ``choices``, possibly empty, passed to the
    model as their names in the order of ``choices``, separated by spaces). Counts, choices
    and subsets are *structural*: the engine calls the model once per distinct combination.
    ``minimum``/``maximum`` are in ``unit``. A ``default`` of ``None`` means the model derives
    the value itself when it is not given (the meaning says how). ``dims`` names the
    dimensions of an array-valued input (a per-roller pattern).
    """

    name: str
    unit: str
    meaning: str
    default: object = REQUIRED
    kind: str = "quantity"
    minimum: float | None = None
    maximum: float | None = None
    exclusive_minimum: bool = False
    choices: tuple[str, ...] = ()
    dims: tuple[str, ...] = ()
    #: For a pattern (``dims``): a single value stands for every entry, and may vary on a
    #: plain axis; the model then receives a pattern of length one.
    broadcast: bool = False
    #: A short name for an axis label (netCDF ``long_name``); ``meaning`` goes to ``comment``.
    #: Derived from ``meaning`` when not given.
    label: str = ""

    @property
    def short(self) -> str:
        if self.label:
            return self.label
        if self.kind in ("choice", "subset"):
            return self.name.replace("_", " ")
        return short_label(self.meaning)

    @property
    def structural(self) -> bool:
        return self.kind in ("count", "choice", "subset")

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    def range_text(self) -> str:
        """The valid range in words, for error messages and ``describe``."""
        if self.kind == "choice":
            return "one of " + ", ".join(repr(c) for c in self.choices)
        if self.kind == "subset":
            return "a list of distinct values from " + ", ".join(repr(c) for c in self.choices)
        unit = "" if self.unit in ("1", "") else " " + self.unit
        low = high = ""
        if self.minimum is not None:
            low = (">" if self.exclusive_minimum else ">=") + f" {_bound(self.minimum)}{unit}"
        if self.maximum is not None:
            high = f"<= {_bound(self.maximum)}{unit}"
        kind = "an integer " if self.kind == "count" else ""
        return kind + (" and ".join(t for t in (low, high) if t) or "any value")


def _bound(value) -> str:
    """A bound as short as it reads back exactly (2 pi: 6.283185307179586, not 6.28319, which
    a value the bound refuses would read as)."""
    short = f"{value:g}"
    return short if float(short) == value else repr(float(value))


@dataclass(frozen=True)
class Output:
    """One model output: customary ``unit`` and the output's own ``dims`` after the grid's.

    An output whose entries differ in kind (a displacement vector of translations and tilts)
    gives ``entry_units``: one unit per entry, nested like its own dims; ``unit`` then names
    them all ("mm, rad"), and the dataset carries the units of each entry beside it.
    """

    name: str
    unit: str
    meaning: str
    dims: tuple[str, ...] = ()
    entry_units: tuple = ()
    #: A short name for an axis label (netCDF ``long_name``); derived from ``meaning`` when
    #: not given.
    label: str = ""
    #: ``(text, where)``: the run's summary counts the points where ``where(values)`` is true
    #: ("points with two stable equilibria"); ``values`` are in the declared ``unit``, as
    #: stored, not in SI.
    counted: tuple = ()
    #: ``"int"`` for an output whose values are whole numbers (a count of loaded rollers):
    #: stored as integers, with a fill value where a point has none; its unit is ``"1"``.
    dtype: str = "float"
    #: The inputs the output depends on, where the physics says they are fewer than all (a
    #: roller's centrifugal force: the speed and the roller's size, not the load). The engine
    #: stores it on the grid's axes that hold those inputs only, after checking that its
    #: values are the same along the others. None: it may depend on every input.
    depends_on: tuple[str, ...] | None = None
    #: How a duty cycle combines a rating life over its load cases, by Palmgren and Miner
    #: (``life_combination.duty_cycle_life``): ``"revolutions"`` for a life in revolutions,
    #: over the cases' shares of the revolutions; ``"time"`` for one in hours, over their
    #: shares of the time. Empty: not combined.
    cycle: str = ""

    @property
    def short(self) -> str:
        return self.label or short_label(self.meaning)


def short_label(meaning: str) -> str:
    """The part of a meaning that reads as an axis label: up to its first parenthesis,
    semicolon or comma ("radial stiffness dFr/d(delta_r), implicit ..." -> "radial stiffness
    dFr/d(delta_r)")."""
    return re.split(r" \(|; |, ", meaning, maxsplit=1)[0]


@dataclass(frozen=True)
class DimCoordinate:
    """The values along an output dimension (a time, an angle), from the inputs that set them.

    ``values(size, **inputs)`` gets the dimension's size and the single SI value of each of
    ``inputs``; it returns SI values, stored in ``unit``. Where one of ``inputs`` varies on the
    grid, the dimension is numbered instead and its ``meaning`` names the output to use.
    """

    inputs: tuple[str, ...]
    values: Callable[..., object]
    unit: str
    meaning: str


@dataclass(frozen=True)
class Constraint:
    """A condition between inputs, checked on every combination before any computing.

    ``check`` takes the named inputs as SI arrays and returns True where they are valid.
    An input not given whose default is None (the model derives it or goes without) skips
    the check, unless ``unset``: then it comes as NaN, for a condition on which inputs go
    together ("a fit needs the ring's bore").
    """

    inputs: tuple[str, ...]
    check: Callable[..., object]
    message: str
    unset: bool = False


@dataclass(frozen=True)
class Model:
    """A registered model: its function and its declared interface.

    ``version`` changes whenever the model's numbers change: results made by another version
    are stale and a study recomputes them.
    """

    name: str
    function: Callable[..., dict]
    summary: str
    reference: str
    version: str
    inputs: tuple[Input, ...]
    outputs: tuple[Output, ...]
    #: Size of each output dimension: the name of a count input (its largest value on the
    #: grid is used; entries are numbered from 1), names of counts joined by "*" (their
    #: product), a tuple of the entries' labels, or a function of ``{input: all its values
    #: on the grid}`` giving the size.
    dim_sizes: dict = field(default_factory=dict)
    constraints: tuple[Constraint, ...] = ()
    #: Rough cost of one grid point on one core [s], to choose chunk sizes and whether a
    #: cluster is worth starting, and to tell a run's length; or a function of the points'
    #: inputs (``{input: its SI value, or its values at some of the grid's points}``, every
    #: input, defaults included) giving each point's cost.
    seconds_per_point: float | Callable[[dict], np.ndarray] = 1e-3
    #: Points per call of the function: a chunk is computed in blocks of this size, so that a
    #: model's temporaries stay small enough for the caches that workers share (crb_radial:
    #: two workers slowed each other's tasks by 40 % with 2500-point calls, 15 % with 500).
    points_per_call: int = 100_000
    #: The limits beyond which a point is marked ``out_of_validity`` (beside its outcome), in
    #: words, with their sources.
    validity: str = ""
    #: Values along output dimensions that a few inputs fix (``DimCoordinate``), by dimension.
    dim_coordinates: dict = field(default_factory=dict)
    #: The tables of a definition that give the structure of a model built anew for each
    #: definition (a shaft's sections, supports and loads), each with the inputs its entries
    #: take by kind of entry, and ``assemble``, which builds the model from what they hold
    #: (as the model's module says). Empty for a model of fixed inputs.
    tables: dict[str, dict[str, tuple[Input, ...]]] = field(default_factory=dict)
    assemble: Callable[..., "Model"] | None = None
    #: Outputs a duty cycle combines otherwise than by Palmgren and Miner (a system's life:
    #: the Weibull combination of its bearings' lives over the cycle), each a function of
    #: ``{name: values}`` of the outputs with ``cycle = "miner"`` combined over the cycle
    #: (the output's own dimensions last), by name.
    cycle_combinations: dict[str, Callable] = field(default_factory=dict)

    def input(self, name: str) -> Input:
        return next(i for i in self.inputs if i.name == name)


def declaration_problems(model: Model) -> list[str]:
    """How ``model``'s declaration departs from its function or from itself, in words (empty
    when it holds).

    Checked: the function's parameters are the declared inputs, in order; an input is
    required exactly where the function has no default; a choice's, count's or subset's
    default is the function's (a subset's as its names joined by spaces); every output
    dimension has a size in ``dim_sizes``; an integer output (``dtype="int"``) has unit "1";
    an output's ``depends_on`` names declared inputs, once each; no two inputs or outputs share
    a name (nor take ``status``). Quantity defaults in SI and readable units need the engine's
    unit handling: ``bearing_sweep.testing.assert_valid_declaration`` checks those as well.
    """
    try:
        parameters = inspect.signature(model.function).parameters
    except (TypeError, ValueError):
        return [f"its function {model.function!r} has no signature to compare"]
    problems = []
    declared = [i.name for i in model.inputs]
    if list(parameters) != declared:
        problems.append(f"the function's parameters ({', '.join(parameters)}) are not its "
                        f"declared inputs ({', '.join(declared)}) in that order")
    for item in model.inputs:
        if item.name not in parameters:
            continue
        default = parameters[item.name].default
        if item.required != (default is inspect.Parameter.empty):
            problems.append(f"input {item.name!r} is "
                            + ("required in the declaration but has a default in the function"
                               if item.required else
                               "required by the function but has a declared default"))
        elif item.kind == "subset" and default != " ".join(item.default):
            problems.append(f"input {item.name!r}: the function's default {default!r} is not "
                            f"the declared names joined by spaces {' '.join(item.default)!r}")
        elif (item.kind in ("choice", "count") or item.default is None) \
                and not item.required and default != item.default:
            problems.append(f"input {item.name!r}: the function's default {default!r} is not "
                            f"the declared {item.default!r}")
    for output in model.outputs:
        unsized = [d for d in output.dims if d not in model.dim_sizes]
        if unsized:
            problems.append(f"output {output.name!r}: dimension {', '.join(unsized)} has no "
                            "size in dim_sizes")
        if output.dtype not in ("float", "int"):
            problems.append(f"output {output.name!r}: dtype {output.dtype!r} is not 'float' "
                            "or 'int'")
        elif output.dtype == "int" and (output.unit != "1" or output.entry_units):
            problems.append(f"output {output.name!r}: an integer output has unit '1', not "
                            f"{output.unit!r}")
        if output.depends_on is not None:
            unknown = [n for n in output.depends_on if n not in declared]
            if unknown or len(set(output.depends_on)) < len(output.depends_on):
                problems.append(f"output {output.name!r}: depends_on "
                                f"({', '.join(output.depends_on)}) must name declared inputs, "
                                "once each" + (f"; not inputs: {', '.join(unknown)}"
                                               if unknown else ""))
    names = declared + [o.name for o in model.outputs] + ["status"]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:  # an output named like an input would clash with its coordinate in the dataset
        problems.append(f"name{'s' * (len(twice) > 1)} {', '.join(twice)} used twice among "
                        "inputs, outputs and status")
    return problems


_MODELS: dict[str, Model] = {}


def all_models() -> dict[str, Model]:
    """Every model declared in the entry-point group ``bearing_sweep.models``, by name.

    Ours come first and keep their names; other packages' follow, sorted by distribution and
    entry-point name. A plug-in that cannot be imported, holds no models, declares a model
    whose declaration does not hold (:func:`declaration_problems`) or takes a name already
    taken is left out, with one warning line on the ``bearing_sweep.models.registry`` logger
    naming it; the others are kept.
    """
    if not _MODELS:
        origins: dict[str, str] = {}  # model name -> "distribution version" that declared it
        read = set()  # a module named by several entry points (one per model) is read once
        for entry_point in sorted(entry_points(group=ENTRY_POINT_GROUP), key=_loading_order):
            source = (entry_point.dist.name if entry_point.dist else None, entry_point.value)
            if source not in read:
                read.add(source)
                _MODELS.update(_models_of(entry_point, origins))
    return dict(_MODELS)


def _loading_order(entry_point: EntryPoint):
    # Names compare normalised (PEP 503): metadata may spell ours bearing_sweep.
    distribution = re.sub(r"[-_.]+", "-", entry_point.dist.name).lower() \
        if entry_point.dist else ""
    return distribution != _OWN_DISTRIBUTION, distribution, entry_point.name


def _models_of(entry_point: EntryPoint, origins: dict[str, str]) -> dict[str, Model]:
    """The usable models an entry point declares, recorded in ``origins``; a logged line for
    each one that is not usable."""
    dist = entry_point.dist
    origin = f"{dist.name} {dist.version}" if dist else "an unnamed distribution"
    where = f"model plug-in {entry_point.name!r} ({origin}: {entry_point.value})"
    try:
        loaded = entry_point.load()
    except Exception as error:  # any failure of someone else's import must not stop ours
        message = f"{type(error).__name__}: {error}".splitlines()[0]
        _LOG.warning(f"{where} cannot be imported ({message}); its models are left out")
        return {}
    declared = getattr(loaded, "MODELS", None) if isinstance(loaded, types.ModuleType) \
        else loaded
    declared = [declared] if isinstance(declared, Model) else declared
    if not isinstance(declared, (list, tuple)) or not declared \
            or not all(isinstance(m, Model) for m in declared):
        _LOG.warning(f"{where} holds no models: expected a module with a list MODELS of "
                     "bearing_sweep.models.registry.Model, or one Model; left out")
        return {}
    found = {}
    for model in declared:
        problems = declaration_problems(model)
        if model.name in origins:
            problems.append(f"the name is already taken by a model of {origins[model.name]}")
        if problems:
            _LOG.warning(f"{where}: model {model.name!r} left out: {'; '.join(problems)}")
            continue
        found[model.name] = model
        origins[model.name] = origin
    return found


def own_entry_points() -> dict[str, EntryPoint]:
    """This package's own entry points of the group, by name: each is named after the model
    it declares. Read from this distribution's metadata alone (the whole group's reads every
    installed distribution's); empty where the package runs uninstalled."""
    try:
        found = distribution(_OWN_DISTRIBUTION).entry_points.select(group=ENTRY_POINT_GROUP)
    except PackageNotFoundError:
        return {}
    return {entry_point.name: entry_point for entry_point in found}


def get_model(name: str) -> Model:
    """The model called ``name``; ``KeyError`` if there is none.

    One of ours is found through the entry point named after it, in its own module, without
    importing the others (the cage models' numba and scipy.integrate cost half a second to
    import; ours keep their names whatever plug-ins declare, so the answer is the same); any
    other name loads every entry point.
    """
    if not _MODELS:
        entry_point = own_entry_points().get(name)
        for model in getattr(entry_point.load(), "MODELS", ()) if entry_point else ():
            if model.name == name:
                return model
    return all_models()[name]
