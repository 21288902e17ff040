"""Bearings on a shaft as one model: a stepped shaft of Timoshenko beam elements on rolling
bearings and linear supports, under forces and moments at positions.

A definition gives the system's structure in tables of its own (the shaft's sections, each
support with its model and inputs, each load); :func:`assemble` builds from them the model
of that system, whose inputs are the shaft's (:data:`SHAFT_INPUTS`), each support's
(``supports_<name>_<input>``) and each load's (``loads_<name>_<input>``), so that any of
them can be an axis or be sampled. Each point is the coupled nonlinear equilibrium of
:func:`models.shaft_bearings.solve_shaft_on_bearings`: the shaft's stiffness with every
bearing's own force-displacement law and analytic stiffness, solved by Newton's method.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press
   (2006), vol. 2, ch. 1 (bearings on a flexible shaft), doi:10.1201/9781420006582.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from .bearing_life import LIFE_INPUTS
from .ball import DOF_UNITS, DOFS, MODELS as BALL_MODELS, STIFFNESS_UNITS
from .cylindrical import MODELS as ROLLER_MODELS
from .registry import (CONVERGED, INFEASIBLE, NOT_CONVERGED, OUT_OF_VALIDITY, REQUIRED,
                       Constraint, DimCoordinate, Input, Model, Output)
from .life_combination import WEIBULL_SLOPES, system_life
from .limits import SPEED_VALIDITY, beyond_speed_factor
from .shaft import NODE_DOFS
from .shaft_bearings import BallSupport, RollerSupport, solve_shaft_on_bearings
from .shaft_mounting import SUPPORT_OPERATING_INPUTS, mounted, support_constraints
from .shaft_tapered import TaperedSupport
from .tapered import MODELS as TAPERED_MODELS

#: The kinds of support a definition names in ``[supports.<name>] model``.
SUPPORT_KINDS = ("ball_5dof", "crb_radial", "trb_load", "spring")
#: Names of supports and loads: they prefix input names, so they are plain identifiers.
NAME_PATTERN = r"[A-Za-z][A-Za-z0-9]*(_[A-Za-z0-9]+)*"

#: One section of the shaft, as ``[shaft] sections`` lists them.
SECTION_INPUTS = (
    Input("length", "mm", "length of the section", minimum=0.0, exclusive_minimum=True),
    Input("diameter", "mm", "outside diameter of the section", minimum=0.0,
          exclusive_minimum=True),
    Input("bore", "mm", "bore of a hollow section (0: solid)", default=0.0, minimum=0.0),
)

SHAFT_INPUTS = (
    Input("shaft_youngs_modulus", "GPa", "Young's modulus of the shaft", default=210.0,
          minimum=0.0, exclusive_minimum=True),
    Input("shaft_poisson_ratio", "1", "Poisson's ratio of the shaft", default=0.3,
          minimum=0.0, maximum=0.5, exclusive_minimum=True),
    Input("shaft_density", "kg/m^3", "density of the shaft, for its own weight",
          default=7850.0, minimum=0.0),
    Input("gravity_x", "m/s^2", "acceleration of gravity along the shaft's axis x (0: the "
          "shaft's weight left out)", default=0.0),
    Input("gravity_y", "m/s^2", "acceleration of gravity along y (-9.81 for a horizontal "
          "shaft whose y points up)", default=0.0),
    Input("gravity_z", "m/s^2", "acceleration of gravity along z", default=0.0),
    Input("speed", "rpm", "speed of the shaft and its bearings' inner rings: the rollers' "
          "centrifugal force, the inner rings' centrifugal growth", default=0.0, minimum=0.0,
          label="shaft speed"),
    Input("station_count", "1", "number of stations, evenly spaced from the shaft's left end "
          "to its right end, where the deflection line is reported", default=21, kind="count",
          minimum=2, maximum=2001),
)

_POSITION = Input("position", "mm", "axial position along the shaft, from its left end",
                  minimum=0.0)
#: The inputs of :func:`models.ball.ball_5dof` that make a ball bearing a support (its loads
#: and displacements are the shaft's).
_BALL_GEOMETRY = ("ball_count", "ball_diameter", "pitch_diameter", "contact_angle",
                  "inner_curvature_ratio", "outer_curvature_ratio", "clearance",
                  "youngs_modulus", "poisson_ratio", "contact_constant", "geometry",
                  "pressure_limit")
#: The inputs of :func:`models.cylindrical.crb_radial` that make a cylindrical roller
#: bearing a support (its radial load and displacement are the shaft's).
_ROLLER_GEOMETRY = ("roller_count", "pitch_diameter", "roller_diameter", "effective_length",
                    "clearance", "crown", "crown_profile", "slices", "slice_law",
                    "outer_contact", "roller_density", "contact_constant",
                    "youngs_modulus", "poisson_ratio", "pressure_limit")
#: The inputs of :func:`models.tapered.trb_load` that make a tapered roller bearing a
#: support (its loads and displacements are the shaft's).
_TAPERED_GEOMETRY = ("roller_count", "effective_length", "roller_mean_diameter",
                     "outer_contact_angle", "pitch_diameter", "clearance", "contact_constant",
                     "youngs_modulus", "poisson_ratio", "pressure_limit")
#: Each rolling-element kind's support, the inputs it is built from, its Weibull slope.
_BEARINGS = {"ball_5dof": (BallSupport, _BALL_GEOMETRY, WEIBULL_SLOPES["ball"]),
             "crb_radial": (RollerSupport, _ROLLER_GEOMETRY, WEIBULL_SLOPES["roller"]),
             "trb_load": (TaperedSupport, _TAPERED_GEOMETRY, WEIBULL_SLOPES["roller"])}
#: Each rolling-element kind's own model, whose conditions between inputs its support keeps.
_OWN_MODELS = {"ball_5dof": BALL_MODELS[0], "crb_radial": ROLLER_MODELS[0],
               "trb_load": TAPERED_MODELS[0]}
_AXIAL_DIRECTION = Input(
    "axial_direction", "", "the direction of the shaft's thrust the bearing carries: "
    "positive along x (as ball_5dof and trb_load take it), or negative (the bearing mounted "
    "the other way round)", default="positive", kind="choice", choices=("positive", "negative"))
#: Each kind of support's inputs, as one support's table names them.
SUPPORT_INPUTS = {
    "ball_5dof": (replace(_POSITION, meaning="axial position of the bearing's centre along "
                          "the shaft, from its left end"),)
    + tuple(BALL_MODELS[0].input(name) for name in _BALL_GEOMETRY) + SUPPORT_OPERATING_INPUTS
    + (next(spec for spec in LIFE_INPUTS if spec.name == "dynamic_load_rating"),)
    + (_AXIAL_DIRECTION,),
    "crb_radial": (replace(_POSITION, meaning="axial position of the bearing's centre "
                           "along the shaft, from its left end"),)
    + tuple(ROLLER_MODELS[0].input(name) for name in _ROLLER_GEOMETRY) + SUPPORT_OPERATING_INPUTS
    + (next(spec for spec in LIFE_INPUTS if spec.name == "dynamic_load_rating"),),
    "trb_load": (replace(_POSITION, meaning="axial position of the bearing's centre along "
                         "the shaft, from its left end"),)
    + tuple(replace(TAPERED_MODELS[0].input(name), default=REQUIRED,
                    meaning="pitch diameter dm at the middle of the rollers", label="")
            if name == "pitch_diameter" else TAPERED_MODELS[0].input(name)
            for name in _TAPERED_GEOMETRY) + SUPPORT_OPERATING_INPUTS
    + (next(spec for spec in LIFE_INPUTS if spec.name == "dynamic_load_rating"),
       _AXIAL_DIRECTION),
    "spring": (
        replace(_POSITION, meaning="axial position of the support along the shaft, from its "
                "left end"),
        Input("radial_stiffness", "N/mm", "stiffness in each radial direction (y and z)",
              minimum=0.0),
        Input("axial_stiffness", "N/mm", "axial stiffness (0: free axially)", default=0.0,
              minimum=0.0),
        Input("tilt_stiffness", "N*m/rad", "stiffness against a tilt about y and about z "
              "(0: free to tilt)", default=0.0, minimum=0.0),
    ),
}
#: A load's inputs, as one load's table names them: on the shaft, in the bearings' axes.
LOAD_INPUTS = (
    replace(_POSITION, meaning="axial position of the load along the shaft, from its left "
            "end"),
    Input("force_x", "N", "axial force Fx on the shaft", default=0.0),
    Input("force_y", "N", "radial force Fy on the shaft", default=0.0),
    Input("force_z", "N", "radial force Fz on the shaft", default=0.0),
    Input("moment_y", "N*m", "moment My on the shaft", default=0.0),
    Input("moment_z", "N*m", "moment Mz on the shaft", default=0.0),
)

#: The radial directions of the deflection line.
_DIRECTIONS = ("y", "z")
_LOAD_UNITS = ("N", "N", "N", "N*m", "N*m")

def outputs(support_count: int, load_count: int) -> tuple[Output, ...]:
    """The outputs of a system of ``support_count`` supports and ``load_count`` loads (their
    entry units are nested per support and per load)."""
    return (
    Output("support_load", "N, N*m", "forces and moments the shaft puts on each support "
           "(Fx, Fy, Fz, My, Mz; the support's reaction is their opposite)",
           dims=("support", "dof"), entry_units=(_LOAD_UNITS,) * support_count,
           label="load on the support"),
    Output("radial_support_load", "N", "radial load on each support, sqrt(Fy^2 + Fz^2)",
           dims=("support",), label="radial load on the support"),
    Output("support_displacement", "m, rad", "displacement and tilt of the shaft at each "
           "support (a bearing's inner ring, its outer ring held)", dims=("support", "dof"),
           entry_units=(DOF_UNITS,) * support_count, label="displacement at the support"),
    Output("reference_rating_life", "Mturn", "basic reference rating life L10r of each "
           "bearing, ISO/TS 16281, from its ball or lamina loads, the inner ring rotating; "
           "millions of revolutions, NaN for a spring or without a dynamic_load_rating",
           dims=("support",), label="reference rating life L10r", cycle="revolutions"),
    Output("operating_clearance", "um", "each bearing's diametral clearance as mounted: "
           "its clearance changed by its fits, temperatures and the inner ring's speed "
           "(negative: a preload; NaN for a spring)", dims=("support",),
           label="operating clearance"),
    Output("system_reference_life", "Mturn", "reference rating life of the bearings "
           "together, the system failing with its first bearing: sum (L/L10r_i)^e = 1 with "
           "Weibull slopes e = 10/9 for ball and 9/8 for roller bearings (Lundberg and "
           "Palmgren; Harris and Kotzalas ch. 11); NaN where a bearing has no life",
           label="system reference life"),
    Output("largest_contact_pressure", "MPa", "largest maximum Hertz contact pressure of "
           "each bearing's rolling elements (NaN for a spring)", dims=("support",),
           label="largest contact pressure"),
    Output("stiffness_at_load", "N/m, N/rad, N, N*m/rad", "stiffness matrix dF_i/dq_j of "
           "the whole system at each load's position (the inverse of its compliance there), in "
           "SI so that it is symmetric as stored", dims=("load", "load_dof", "dof"),
           entry_units=(STIFFNESS_UNITS,) * load_count, label="stiffness at the load"),
    Output("support_stiffness", "N/m, N/rad, N, N*m/rad", "each support's own stiffness "
           "matrix dF_i/dq_j at the equilibrium (a bearing's tangent, a spring's diagonal), in "
           "SI so that it is symmetric as stored: a bearing's springs for a rotor-dynamics "
           "model", dims=("support", "load_dof", "dof"),
           entry_units=(STIFFNESS_UNITS,) * support_count, label="stiffness of the support"),
    Output("deflection", "um", "radial displacements v (y) and w (z) of the shaft's axis "
           "along its length, at the stations", dims=("position", "direction"),
           label="deflection"),
    Output("largest_deflection", "um", "largest radial displacement of the shaft's axis "
           "over the stations, sqrt(v^2 + w^2)", label="largest deflection"),
    Output("slope", "mrad", "slopes dv/dx and dw/dx of the shaft's deflection line at the "
           "stations", dims=("position", "direction"), label="slope of the deflection line"),
    )


def _shaft_template(shaft_youngs_modulus=210e9, shaft_poisson_ratio=0.3, shaft_density=7850.0,
                    gravity_x=0.0, gravity_y=0.0, gravity_z=0.0, speed=0.0, station_count=21):
    """The inputs every shaft system shares; the system itself is built by :func:`assemble`
    from its definition's ``[shaft]``, ``[supports]`` and ``[loads]`` tables, and computed
    by the model that builds.

    Parameters
    ----------
    shaft_youngs_modulus : float
        Young's modulus of the shaft [Pa].
    shaft_poisson_ratio : float
        Poisson's ratio of the shaft [-].
    shaft_density : float
        Density of the shaft, for its own weight [kg/m^3].
    gravity_x, gravity_y, gravity_z : float
        Acceleration of gravity along x, y and z [m/s^2] (0: no weight).
    speed : float
        Speed of the shaft and its bearings' inner rings [rad/s]: the rollers' centrifugal
        force, the inner rings' centrifugal growth.
    station_count : int
        Number of stations, evenly spaced from the shaft's left end to its right end, where
        the deflection line is reported [-].

    Raises
    ------
    ValueError
        Always: the shaft, its supports and its loads are not inputs of this function.
    """
    raise ValueError("a shaft system needs its [shaft], [supports] and [loads] tables: "
                     "build its model with models.shaft_system.assemble")


_SUMMARY = ("A stepped shaft on rolling bearings and linear supports under forces and moments: "
            "the coupled nonlinear equilibrium (Timoshenko beam elements, each bearing's own "
            "force-displacement law), the loads on each support, the shaft's deflection line.")
_REFERENCE = ("Przemieniecki, Theory of Matrix Structural Analysis (1968), 5.6; paper 001, "
              "eq. 1-9 for the ball bearings; paper 000, eq. 1-10 for the cylindrical roller "
              "bearings; paper 003, eq. 13-18 for the tapered roller bearings; Harris & "
              "Kotzalas, Rolling Bearing Analysis (2006), vol. 2, ch. 1")
_VALIDITY = ("a bearing's solution outside its own model's validity (for ball_5dof: contact "
             "pressure above its pressure_limit, a ball's approach above 1 % of its diameter, "
             "the ring beyond the grooves, a ball on the cut-away side of its groove; for "
             "crb_radial and trb_load: contact pressure above its pressure_limit, a roller's "
             "approach above 2 % of its diameter); a ring whose fit is lost at temperature "
             "or speed; for a bearing, " + SPEED_VALIDITY + ". Not modelled: the shaft's "
             "torsion, the "
             "housings' compliance (give a spring for it), centrifugal and gyroscopic ball "
             "loads; a cylindrical roller bearing's axial load (its rings slide), its "
             "rollers' own moment balance (each takes half the shaft's tilt, as crb_radial's "
             "misalignment has it), and the direction of its rollers against a radial "
             "displacement: it answers one in any direction as crb_radial answers one along "
             "its load line; a tapered roller bearing's rollers tilted by "
             "the shaft's slope (their load moves, its spread along them does not: trb_load "
             "has no crown).")
_VERSION = "5"


def assemble(sections, supports, loads) -> Model:
    """The model of one shaft system.

    Parameters
    ----------
    sections : sequence of (float, float, float)
        Each section's length, outside diameter and bore [m], from the shaft's left end.
    supports : dict
        Each support's kind (one of :data:`SUPPORT_KINDS`) by its name.
    loads : sequence of str
        The loads' names.

    Returns
    -------
    Model
        ``shaft_system`` with the inputs :data:`SHAFT_INPUTS`, ``supports_<name>_<input>``
        for each support's :data:`SUPPORT_INPUTS` and ``loads_<name>_<input>`` for each
        load's :data:`LOAD_INPUTS`, the :func:`outputs` on dimensions ``support``
        (named as the definition names them), ``dof`` and ``position`` (the stations).
    """
    sections = np.asarray(sections, dtype=float).reshape(-1, 3)
    supports, loads = dict(supports), tuple(loads)
    if not len(sections) or not supports:
        raise ValueError("a shaft system needs at least one section and one support")
    length = float(sections[:, 0].sum())
    inputs = list(SHAFT_INPUTS)
    for name, kind in supports.items():
        inputs += [_prefixed(spec, "supports", name) for spec in SUPPORT_INPUTS[kind]]
    for name in loads:
        inputs += [_prefixed(spec, "loads", name) for spec in LOAD_INPUTS]
    positions = tuple(f"supports_{name}_position" for name in supports) + tuple(
        f"loads_{name}_position" for name in loads)

    def on_shaft(**values):
        inside = True
        for name in positions:
            inside = inside & (values[name] >= 0.0) & (values[name] <= length * (1 + 1e-12))
        return inside

    def apart(**values):
        at, separate = [values[f"supports_{name}_position"] for name in supports], True
        for index, first in enumerate(at):
            for second in at[index + 1:]:
                separate = separate & (np.abs(first - second) > 1e-9 * length)
        return separate

    def shaft_system(**values):
        return _solve(sections, supports, loads, values)

    bearing_columns = [i for i, kind in enumerate(supports.values()) if kind in _BEARINGS]
    slopes = [_BEARINGS[kind][2] for kind in supports.values() if kind in _BEARINGS]

    def system_over_cycle(combined):
        """The system's life over a duty cycle: its bearings' lives over the cycle (each
        by Palmgren and Miner) combined as in one load case."""
        lives = combined["reference_rating_life"]
        if not bearing_columns:
            return np.full(lives.shape[:-1], np.nan)
        return system_life(lives[..., bearing_columns], slopes)

    return Model(
        name="shaft_system", function=shaft_system, summary=_SUMMARY, reference=_REFERENCE,
        version=_VERSION, inputs=tuple(inputs), outputs=outputs(len(supports), len(loads)),
        dim_sizes={"support": tuple(supports), "load": loads, "dof": DOFS, "load_dof": DOFS,
                   "direction": _DIRECTIONS, "position": "station_count"},
        dim_coordinates={"position": DimCoordinate(
            ("station_count",), lambda size, station_count: np.linspace(0.0, length, size),
            "mm", "axial position along the shaft")},
        constraints=(
            Constraint(positions, on_shaft, f"every support and load lies on the shaft, "
                       f"between 0 and its length {length * 1e3:g} mm"),
            Constraint(positions[:len(supports)], apart, "two supports at one position: "
                       "give one support the stiffness of both"),
        ) + tuple(constraint for name, kind in supports.items() if kind in _BEARINGS
                  for constraint in support_constraints(sections, name, _OWN_MODELS[kind],
                                                        SUPPORT_INPUTS[kind]))
        + tuple(Constraint((f"supports_{name}_outer_contact",), _crowned_outer,
                           f"support {name}: outer_contact 'paper' (a straight outer contact) "
                           "takes no tilt, and the shaft tilts its bearings; use 'crowned'")
                for name, kind in supports.items() if kind == "crb_radial"),
        seconds_per_point=2e-4, points_per_call=1000, validity=_VALIDITY,
        cycle_combinations={"system_reference_life": system_over_cycle})


def _crowned_outer(**given):
    (outer_contact,) = given.values()
    return np.asarray(outer_contact) != "paper"


#: The longest label of an axis (its netCDF ``long_name``) a figure shows whole.
_LABEL_LENGTH = 48


def _prefixed(spec: Input, table: str, name: str) -> Input:
    """A support's or load's input as the system names it, labelled with its owner."""
    label = f"{name}: {spec.short}"
    if len(label) > _LABEL_LENGTH:
        label = f"{name}: {spec.name.replace('_', ' ')}"
    return replace(spec, name=f"{table}_{name}_{spec.name}", label=label)


class _Mirrored:
    """A bearing mounted the other way round: its axial direction and tilts reversed."""

    _FLIP = np.array([-1.0, 1.0, 1.0, -1.0, -1.0])

    def __init__(self, bearing):
        self.bearing = bearing

    def loads(self, displacement, cases=None):
        load, stiffness = self.bearing.loads(displacement * self._FLIP, cases)
        return load * self._FLIP, stiffness * self._FLIP[:, None] * self._FLIP[None, :]

    def outside_validity(self, displacement, cases=None):
        return self.bearing.outside_validity(displacement * self._FLIP, cases)

    def largest_pressure(self, displacement, cases=None):
        return self.bearing.largest_pressure(displacement * self._FLIP, cases)

    def reference_life(self, displacement, rating, cases=None):
        return self.bearing.reference_life(displacement * self._FLIP, rating, cases)


def _solve(sections, supports, loads, values):
    """Every point's equilibrium: ``values`` each input's SI value, one per point or one for
    all. Points whose shaft, positions and springs are the same are solved together."""
    count = max([np.size(v) for v in values.values() if not isinstance(v, str)] + [1])

    def every(name):
        value = values[name]
        return value if isinstance(value, str) else np.broadcast_to(value, (count,))

    stations = np.linspace(0.0, sections[:, 0].sum(), int(values["station_count"]))
    names = list(supports)
    bearing_names = [n for n in names if supports[n] in _BEARINGS]
    springs = [n for n in names if supports[n] == "spring"]
    spring_fields = ("axial_stiffness", "radial_stiffness", "radial_stiffness",
                     "tilt_stiffness", "tilt_stiffness")
    linear = np.stack(
        [every("shaft_youngs_modulus"), every("shaft_poisson_ratio")]
        + [every(f"supports_{n}_position") for n in bearing_names + springs]
        + [every(f"loads_{n}_position") for n in loads]
        + [every(f"supports_{n}_{field}") for n in springs for field in spring_fields],
        axis=-1)
    load_vectors = np.stack([np.stack([every(f"loads_{n}_{spec.name}")
                                       for spec in LOAD_INPUTS[1:]], axis=-1) for n in loads],
                            axis=1) if loads else np.zeros((count, 0, NODE_DOFS))
    out = {"support_load": np.full((count, len(names), NODE_DOFS), np.nan),
           "support_displacement": np.full((count, len(names), NODE_DOFS), np.nan),
           "largest_contact_pressure": np.full((count, len(names)), np.nan),
           "reference_rating_life": np.full((count, len(names)), np.nan),
           "deflection": np.full((count, stations.size, 2), np.nan),
           "slope": np.full((count, stations.size, 2), np.nan),
           "stiffness_at_load": np.full((count, len(loads), NODE_DOFS, NODE_DOFS), np.nan),
           "support_stiffness": np.full((count, len(names), NODE_DOFS, NODE_DOFS), np.nan),
           "operating_clearance": np.full((count, len(names)), np.nan),
           "status": np.full(count, NOT_CONVERGED, dtype=np.int8)}
    order = [names.index(n) for n in bearing_names] + [names.index(n) for n in springs]
    # The columns of ``linear``: the shaft's material, then the positions and the springs.
    cut = np.cumsum([2, len(bearing_names), len(springs), len(loads)])
    bearings_at, springs_at = slice(cut[0], cut[1]), slice(cut[1], cut[2])
    loads_at, stiffness_at = slice(cut[2], cut[3]), slice(cut[3], None)
    _, group_of = np.unique(linear, axis=0, return_inverse=True)
    for group in np.unique(group_of):
        members = np.flatnonzero(group_of.ravel() == group)
        first = linear[members[0]]
        bearings = []
        fit_lost = np.zeros(members.size, dtype=bool)
        for name in bearing_names:
            kind, fields, _ = _BEARINGS[supports[name]]

            def given(field, name=name):
                value = values[f"supports_{name}_{field}"]
                return value if isinstance(value, str) or value is None \
                    or np.ndim(value) == 0 else value[members]

            def numbers(field, name=name):
                value = values[f"supports_{name}_{field}"]
                return np.broadcast_to(np.nan if value is None else value, (count,))[members]

            clearance = mounted(sections, name, supports[name], numbers,
                                every("shaft_youngs_modulus")[members],
                                every("shaft_poisson_ratio")[members], every("speed")[members])
            fit_lost |= clearance["fit_lost"] | beyond_speed_factor(
                every("speed")[members], numbers("pitch_diameter"))
            out["operating_clearance"][members, names.index(name)] = \
                clearance["operating_clearance"]
            chosen = {field: given(field) for field in fields}
            chosen["clearance"] = clearance["operating_clearance"]
            if supports[name] == "crb_radial":
                chosen["speed"] = every("speed")[members]
            bearing = kind(**chosen, cases=members.size)
            bearings.append(_Mirrored(bearing) if values.get(
                f"supports_{name}_axial_direction") == "negative" else bearing)
        try:
            solved = solve_shaft_on_bearings(
                sections[:, 0], sections[:, 1], sections[:, 2], first[0], first[1],
                first[bearings_at], bearings, first[loads_at], load_vectors[members],
                first[springs_at], first[stiffness_at].reshape(-1, NODE_DOFS), stations,
                compliance_at=first[loads_at],
                own_weight=(every("shaft_density")[members], np.stack(
                    [every(f"gravity_{axis}")[members] for axis in "xyz"], axis=-1)))
        except ValueError:  # the shaft's system cannot be put together at these inputs
            out["status"][members] = INFEASIBLE | np.where(fit_lost, OUT_OF_VALIDITY, 0)
            continue
        fine = solved["converged"]
        solved_points = members[fine]
        place = {"support_load": np.concatenate([solved["bearing_load"],
                                                 solved["spring_load"]], axis=1),
                 "support_displacement": np.concatenate([solved["bearing_displacement"],
                                                         solved["spring_displacement"]],
                                                        axis=1)}
        for key, value in place.items():
            out[key][solved_points[:, None], order] = value[fine]
        cases = np.flatnonzero(fine)
        for index, (name, bearing) in enumerate(zip(bearing_names, bearings)):
            if cases.size:
                at_bearing = solved["bearing_displacement"][cases, index]
                column = names.index(name)
                out["largest_contact_pressure"][solved_points, column] = \
                    bearing.largest_pressure(at_bearing, cases)
                out["support_stiffness"][solved_points, column] = bearing.loads(
                    at_bearing, cases)[1]
                rating = values[f"supports_{name}_dynamic_load_rating"]
                if rating is not None:
                    out["reference_rating_life"][solved_points, column] = \
                        bearing.reference_life(at_bearing, rating if np.ndim(rating) == 0
                                               else rating[members][cases], cases)
        out["stiffness_at_load"][solved_points] = _stiffness_at(
            solved["compliance"], len(loads))[fine]
        line = solved["station_displacement"][fine]
        out["deflection"][solved_points] = line[..., 1:3]
        out["slope"][solved_points] = np.stack([line[..., 4], -line[..., 3]],
                                               axis=-1)  # dv/dx, dw/dx
        out["status"][solved_points] = CONVERGED | np.where(
            solved["bearing_outside_validity"][fine].any(axis=-1), OUT_OF_VALIDITY, 0)
        # A ring whose fit is lost may creep, a bearing may run faster than any does:
        # outside validity, whatever the outcome.
        out["status"][members[fit_lost]] |= OUT_OF_VALIDITY
    solved = np.flatnonzero(np.isfinite(out["support_load"]).all(axis=(1, 2)))
    diagonal = np.arange(NODE_DOFS)
    for name in springs:  # a spring's stiffness: its own, at every point that is solved
        stiffness = np.zeros((solved.size, NODE_DOFS, NODE_DOFS))
        stiffness[:, diagonal, diagonal] = np.stack(
            [every(f"supports_{name}_{field}")[solved] for field in spring_fields], axis=-1)
        out["support_stiffness"][solved, names.index(name)] = stiffness
    turns = 2e6 * np.pi  # 10^6 revolutions [rad]
    lives = out["reference_rating_life"][:, [names.index(n) for n in bearing_names]]
    slopes = [_BEARINGS[supports[n]][2] for n in bearing_names]
    out["system_reference_life"] = (system_life(lives, slopes) if bearing_names
                                    else np.full(count, np.nan)) * turns
    out["reference_rating_life"] *= turns
    out["largest_deflection"] = np.hypot(out["deflection"][..., 0],
                                         out["deflection"][..., 1]).max(axis=-1)
    out["radial_support_load"] = np.hypot(out["support_load"][..., 1],
                                          out["support_load"][..., 2])
    return out


def _stiffness_at(compliance, count):
    """The system's tangent stiffness at each of ``count`` positions, one 5 x 5 matrix per
    load case: the inverse of the compliance block of that position."""
    stiffness = np.full((len(compliance), count, NODE_DOFS, NODE_DOFS), np.nan)
    solvable = np.isfinite(compliance).all(axis=(1, 2))
    for index in range(count):
        part = slice(NODE_DOFS * index, NODE_DOFS * (index + 1))
        stiffness[solvable, index] = np.linalg.inv(compliance[solvable, part, part])
    return stiffness


MODELS = [Model(
    name="shaft_system", function=_shaft_template, summary=_SUMMARY, reference=_REFERENCE,
    version=_VERSION, inputs=SHAFT_INPUTS, outputs=outputs(0, 0),
    dim_sizes={"support": (), "load": (), "dof": DOFS, "load_dof": DOFS,
               "direction": _DIRECTIONS, "position": "station_count"},
    tables={"shaft": {"sections": SECTION_INPUTS}, "supports": SUPPORT_INPUTS,
            "loads": {"load": LOAD_INPUTS}}, assemble=assemble,
    seconds_per_point=2e-4, points_per_call=1000, validity=_VALIDITY)]
