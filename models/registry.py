"""Model registry: every model's inputs and outputs, with units, defaults and valid ranges.

A model is a pure function of numpy arrays in SI base units. Its declaration here says, in the
units engineers customarily write (mm, N, r/min, ...), what each input means, its default and
the range in which the model is valid, and what each output is, with its own dimensions.
The sweep engine uses the declarations to validate definitions, convert units at the boundary
and label the netCDF output; the models never see a unit string.
"""
from __future__ import annotations

import importlib
import re
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

#: Status codes shared by all models (netCDF ``flag_values`` / ``flag_meanings``).
CONVERGED, NOT_CONVERGED, INFEASIBLE, MODEL_ERROR, OUT_OF_VALIDITY, NO_ROOT_IN_RANGE = range(6)
STATUS_MEANINGS = ("converged", "not_converged", "infeasible", "model_error",
                   "out_of_validity", "no_root_in_range")
#: What each status says of a point, for ``describe``, the README and the netCDF ``comment``.
STATUS_DESCRIPTIONS = {
    "converged": "solved; the values hold",
    "not_converged": "the solver stopped without meeting its tolerance; outputs are NaN",
    "infeasible": "no solution exists for these inputs (e.g. a load the bearing cannot "
                  "carry); outputs are NaN",
    "model_error": "the model raised an exception for this group of points; outputs are NaN",
    "out_of_validity": "solved, but outside the model's stated validity (its limits are in "
                       "`bearing-sweep describe MODEL`); values kept, do not trust them",
    "no_root_in_range": "solved, but the root the model searches for (a limit angle, a cage "
                        "equilibrium) is not in its search range; the outputs that need it "
                        "are NaN, the others hold",
}
#: Statuses whose values the engine keeps; the others are NaN whatever the model returned.
VALUES_KEPT = (CONVERGED, OUT_OF_VALIDITY, NO_ROOT_IN_RANGE)
#: Order in which statuses of one point combine (the last named wins).
_SEVERITY = (CONVERGED, OUT_OF_VALIDITY, NO_ROOT_IN_RANGE, INFEASIBLE, NOT_CONVERGED,
             MODEL_ERROR)


def combine_status(*codes):
    """The status of points that went through several steps: the most severe of ``codes``
    (arrays that broadcast), in the order converged < out_of_validity < no_root_in_range <
    infeasible < not_converged < model_error."""
    rank = np.argsort(_SEVERITY)  # status code -> its place in the order
    worst = np.max([rank[np.asarray(c, dtype=np.int64)] for c in np.broadcast_arrays(*codes)],
                   axis=0)
    return np.asarray(_SEVERITY, dtype=np.int8)[worst]

#: Marks an input that has no default and must be given.
REQUIRED = object()

# Modules that declare models (each defines a list ``MODELS``), imported on first use so that
# model modules can import the declaration classes below without a cycle.
_DECLARING_MODULES = ("cylindrical", "contact", "ball", "tapered", "runout", "cage_slip",
                      "cage_dynamics")


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
            low = (">" if self.exclusive_minimum else ">=") + f" {self.minimum:g}{unit}"
        if self.maximum is not None:
            high = f"<= {self.maximum:g}{unit}"
        kind = "an integer " if self.kind == "count" else ""
        return kind + (" and ".join(t for t in (low, high) if t) or "any value")


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
    #: ("points with two stable equilibria").
    counted: tuple = ()

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
    """

    inputs: tuple[str, ...]
    check: Callable[..., object]
    message: str


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
    #: cluster is worth starting.
    seconds_per_point: float = 1e-3
    #: Points per call of the function: a chunk is computed in blocks of this size, so that a
    #: model's temporaries stay small enough for the caches that workers share (crb_radial:
    #: two workers slowed each other's tasks by 40 % with 2500-point calls, 15 % with 500).
    points_per_call: int = 100_000
    #: The limits beyond which a solved point is marked ``out_of_validity``, in words.
    validity: str = ""
    #: Values along output dimensions that a few inputs fix (``DimCoordinate``), by dimension.
    dim_coordinates: dict = field(default_factory=dict)

    def input(self, name: str) -> Input:
        return next(i for i in self.inputs if i.name == name)



_MODELS: dict[str, Model] = {}


def all_models() -> dict[str, Model]:
    """Every registered model, by name."""
    if not _MODELS:
        for module_name in _DECLARING_MODULES:
            for model in importlib.import_module(f".{module_name}", __package__).MODELS:
                _MODELS[model.name] = model
    return dict(_MODELS)


def get_model(name: str) -> Model:
    """The model called ``name``; ``KeyError`` if there is none."""
    return all_models()[name]
