"""Planar transient model of a cylindrical roller bearing with a roller-guided cage: cage
whirl, pocket contact, cage slip in time (paper 002, section 3).

Started from the steady state of :func:`models.cage_slip.cage_slip` (cage speed, each roller's
spin at its orbit position) and the quasi-static ring position of :func:`crb_radial`, the
equations of :mod:`models.cage_dynamics_rhs` are integrated by the adaptive Dormand-Prince
5(4) method of :mod:`models.dormand_prince`, compiled whole. The load acts along -y
with gravity; the cage's mass centre lies ``cage_eccentricity`` from its geometric centre.
"""
from __future__ import annotations

import numpy as np

from . import cage_dynamics_rhs as rhs
from .cage_slip import MODELS as STEADY_MODELS
from .cage_slip import VALIDITY as STEADY_VALIDITY
from .cage_slip import bearing_terms, cage_slip, cage_windage
from .contact import (ROLLER_PRESSURE_LIMIT, effective_modulus, line_contact_pressure,
                      palmgren_constant)
from .limits import CAGE_DENSITIES
from .cylindrical import crb_radial
from .registry import (CONVERGED, NOT_CONVERGED, OUT_OF_VALIDITY, Constraint, DimCoordinate,
                       Input, Model, Output, VALIDITY_MASK, outcome)

GRAVITY = 9.81
_SETTLED = 0.5  # the settled part: the last half of the run
# Relative tolerance of the integration (with _tolerances' absolute ones): the settled mean
# slips hardly move against every tolerance far tighter (benchmarks/RESULTS.md).
_RELATIVE_TOLERANCE = 1e-4
#: Steps the integration may take before it gives up.
_MAX_STEPS = 10_000_000


def cage_dynamics(radial_load, speed, roller_count, inner_raceway_diameter, roller_diameter,
                  roller_length, effective_length, clearance, cage_inner_diameter,
                  cage_outer_diameter, cage_width, roller_density=7820.0,
                  oil_temperature=298.15, viscosity_40=26e-6, viscosity_100=5.4e-6,
                  oil_density=1000.0, pressure_viscosity=1.1e-8, youngs_modulus=207e9,
                  poisson_ratio=0.28, traction_peak=0.05, traction_peak_speed=2.0,
                  traction_limit=0.036, oil_fraction=0.05, drag_coefficient=1.0,
                  pocket_clearance=1e-4, pocket_wrap_angle=1.0, pocket_film_fill=1.0,
                  end_film_thickness=1.5e-5, end_film_fill=0.25, pocket_friction=0.1,
                  cage_density=8600.0, cage_eccentricity=0.0, inner_ring_mass=0.1,
                  pocket_stiffness=5e7, damping_ratio=0.1, duration=0.05,
                  output_interval=1e-4, branch="high_slip"):
    """Cage and roller motion in time.

    Parameters
    ----------
    radial_load, speed, roller_count, inner_raceway_diameter, roller_diameter,
    roller_length, effective_length, clearance, cage_inner_diameter, cage_outer_diameter,
    cage_width, roller_density, oil_temperature, viscosity_40, viscosity_100, oil_density,
    pressure_viscosity, youngs_modulus, poisson_ratio, traction_peak, traction_peak_speed,
    traction_limit, oil_fraction, drag_coefficient, pocket_clearance,
    pocket_wrap_angle, pocket_film_fill, end_film_thickness, end_film_fill, pocket_friction
        As :func:`models.cage_slip.cage_slip`.
    cage_density : array_like
        [kg/m^3]; the cage is an annulus of the given diameters and width, less its pockets.
    cage_eccentricity : array_like
        Distance of the cage's mass centre from its geometric centre [m].
    inner_ring_mass : array_like
        [kg].
    pocket_stiffness, damping_ratio : array_like
        Pocket contact stiffness [N/m] and the damping ratio of pocket and ring contacts.
    duration, output_interval : float
        Bearing time simulated and the interval of the returned samples [s].
    branch : {"high_slip", "low_slip"}
        The steady state the run starts from where the steady cage balance has several
        (:func:`models.cage_slip.cage_slip`).

    Returns
    -------
    dict of numpy.ndarray
        ``cage_slip`` ``(N, samples)`` [-], ``mean_cage_slip`` over the settled half [-],
        ``cage_x``, ``cage_y`` ``(N, samples)`` [m] (mass centre), ``cage_centre_x``,
        ``cage_centre_y`` ``(N, samples)`` [m] (geometric centre), ``whirl_speed``
        ``(N, samples)`` [m/s] (speed of the mass centre), ``whirl_deviation_ratio`` (eq. 28
        over the settled half) [-], ``largest_contact_pressure`` over the settled half [Pa],
        ``roller_slip`` ``(N, samples, Z)`` [-], ``sample_time``
        ``(N, samples)`` [s], ``status``: the steady state's where it has none to start from;
        ``out_of_validity`` where the steady state is (cage_slip's validity) or the run's own
        state is none the model holds (:data:`RUN_VALIDITY`), beside the transient's own
        outcome.

    References
    ----------
    .. [1] Paper 002, eq. 27-28 and section 3.
    """
    given = dict(locals())
    numeric = [k for k in given if k not in ("roller_count", "branch")]
    for k, v in zip(numeric, np.broadcast_arrays(*(np.atleast_1d(np.asarray(
            given[k], dtype=float)) for k in numeric))):
        given[k] = v  # every input as an array over the points
    steady_inputs = {k: given[k] for k in _STEADY_NAMES if k != "branch"}
    terms = bearing_terms(**steady_inputs)
    points = terms["load"].size
    samples = int(np.floor(np.max(given["duration"] / given["output_interval"]) + 1e-9)) + 1
    outputs = {"cage_slip": np.full((points, samples), np.nan),
               "mean_cage_slip": np.full(points, np.nan),
               "cage_x": np.full((points, samples), np.nan),
               "cage_y": np.full((points, samples), np.nan),
               "cage_centre_x": np.full((points, samples), np.nan),
               "cage_centre_y": np.full((points, samples), np.nan),
               "whirl_speed": np.full((points, samples), np.nan),
               "whirl_deviation_ratio": np.full(points, np.nan),
               "largest_contact_pressure": np.full(points, np.nan),
               "roller_slip": np.full((points, samples, roller_count), np.nan),
               "sample_time": np.full((points, samples), np.nan),
               "status": np.full(points, NOT_CONVERGED, dtype=np.int8)}
    extra = [given[k] for k in ("cage_density", "cage_eccentricity", "inner_ring_mass",
                                "pocket_stiffness", "damping_ratio", "duration",
                                "output_interval")]
    for point in range(points):
        one = {k: v[point] for k, v in steady_inputs.items() if k != "roller_count"}
        status, result = _run(dict(one, branch=branch), roller_count,
                              {k: v[point] for k, v in terms.items() if k != "traction"},
                              terms["traction"], point, *(e[point] for e in extra))
        outputs["status"][point] = status
        if result is None:
            continue
        for name, value in result.items():
            target = outputs[name]
            if np.ndim(value):
                target[(point,) + tuple(slice(0, n) for n in np.shape(value))] = value
            else:
                target[point] = value
    return outputs


def _run(one, count, t, traction, point, cage_density, eccentricity, ring_mass, pocket_k,
         damping, duration, interval):
    """One point: set up, start from the steady state, integrate, sample. Returns the
    point's status and its outputs (None where there are none)."""
    steady = cage_slip(**one, roller_count=count, orbit_points=20 * count)
    if outcome(steady["status"][0]) != CONVERGED:
        return steady["status"][0], None
    validity = steady["status"][0] & VALIDITY_MASK  # the steady start's, carried on
    omega_c = steady["cage_speed"][0]
    ring = crb_radial(one["radial_load"], count, 2 * t["pitch_radius"], t["diameter"],
                      t["contact_length"], clearance=t["play"], slices=1, speed=t["omega_i"],
                      roller_density=t["mass"] / (np.pi * t["radius"]**2 * t["contact_length"]))
    pocket_share = count * (t["diameter"] + t["pocket_clearance"]) / (
        2 * np.pi * t["pitch_radius"])
    cage_mass = cage_density * np.pi / 4 * (t["cage_out"]**2 - t["cage_in"]**2) \
        * t["width"] * (1 - pocket_share)
    p = np.zeros(rhs.PARAMETERS)
    p[rhs.OMEGA_I], p[rhs.RADIAL_LOAD] = t["omega_i"], t["load"]
    p[rhs.R_INNER], p[rhs.R_OUTER], p[rhs.R_ROLLER] = t["r_i"], t["r_o"], t["radius"]
    p[rhs.R_PITCH], p[rhs.CONTACT] = t["pitch_radius"], palmgren_constant(t["contact_length"])
    p[rhs.HALF_PLAY], p[rhs.M_ROLLER], p[rhs.J_ROLLER] = 0.5 * t["play"], t["mass"], t["inertia"]
    p[rhs.POCKET_FILM], p[rhs.END_FILM] = t["pocket_film"], t["end_film"]
    p[rhs.WINDAGE], p[rhs.MU_POCKET] = t["windage"], t["mu_pocket"]
    p[rhs.M_RING] = ring_mass
    p[rhs.C_RING] = 2 * damping * np.sqrt(np.ravel(ring["radial_stiffness"])[0] * ring_mass)
    p[rhs.M_CAGE] = cage_mass
    p[rhs.J_CAGE] = cage_mass * (t["cage_out"]**2 + t["cage_in"]**2) / 8
    p[rhs.ECCENTRICITY], p[rhs.HALF_POCKET] = eccentricity, 0.5 * t["pocket_clearance"]
    p[rhs.K_POCKET] = pocket_k
    p[rhs.C_POCKET] = 2 * damping * np.sqrt(pocket_k * t["mass"])
    p[rhs.GRAVITY] = GRAVITY
    drag = cage_windage(omega_c, t["cage_out"], t["width"], t["effective_density"],
                        t["kinematic_viscosity"])
    p[rhs.CAGE_DRAG] = drag / omega_c**1.5  # laminar disc: moment ~ omega^1.5
    p[rhs.TRACTION_A:rhs.TRACTION_D + 1] = (traction.a[point], traction.b[point],
                                            traction.c[point], traction.d[point])
    state = _start(count, steady, np.ravel(ring["radial_displacement"])[0], omega_c, eccentricity,
                   t["spin_kin"])
    times = np.arange(int(np.floor(duration / interval + 1e-9)) + 1) * interval
    samples, reached = rhs.integrate(state, times, p, count, _RELATIVE_TOLERANCE,
                                     _tolerances(count), _MAX_STEPS)
    if not reached:
        return NOT_CONVERGED | validity, None
    y = samples.T
    cage = 4 + 3 * count
    settled = times >= _SETTLED * times[-1]
    slip = 1 - y[cage + 5] / t["omega_kin"]
    speed_of_centre = np.hypot(y[cage + 2], y[cage + 3])
    settled_speed = speed_of_centre[settled]
    outputs = {
        "cage_slip": slip, "mean_cage_slip": slip[settled].mean(), "sample_time": times,
        "cage_x": y[cage], "cage_y": y[cage + 1],
        "cage_centre_x": y[cage] - eccentricity * np.cos(y[cage + 4]),
        "cage_centre_y": y[cage + 1] - eccentricity * np.sin(y[cage + 4]),
        "whirl_speed": speed_of_centre,
        "whirl_deviation_ratio": settled_speed.std(ddof=1) / settled_speed.mean(),
        "roller_slip": (1 - y[6:cage:3] / t["spin_kin"]).T}
    outputs["largest_contact_pressure"] = _largest_pressure(samples[settled], p, count, t)
    validity |= run_validity(outputs["mean_cage_slip"], outputs["roller_slip"][settled].mean(),
                             outputs["cage_centre_x"], outputs["cage_centre_y"],
                             t["pocket_clearance"], t["play"], times,
                             roller_pass_period(count, t["omega_kin"]),
                             outputs["largest_contact_pressure"])
    return CONVERGED | validity, outputs


def _largest_pressure(states, p, count, t):
    """The largest Hertz line-contact pressure of any roller at either raceway over
    ``states`` (one per row) [Pa]: each roller's loads as the right-hand side finds them
    (:func:`models.cage_dynamics_rhs.contact_loads`), over its contact length, at the inner
    raceway (curvature sum ``1/R + 1/r_i``) and the outer (``1/R - 1/r_o``)."""
    loads = rhs.largest_contact_loads(np.ascontiguousarray(states), p, count)
    modulus = effective_modulus(t["modulus"], t["poisson"])
    radius = t["radius"]
    return max(float(line_contact_pressure(load / t["contact_length"], curvature, modulus))
               for load, curvature in zip(loads, (1 / radius + 1 / t["r_i"],
                                                  1 / radius - 1 / t["r_o"])))


def _start(count, steady, drop, omega_c, eccentricity, kinematic_spin):
    """Steady state: ring dropped along the load, rollers at their orbit speed and spin,
    cage pockets around them (roller 1 on the load line, at -90 deg)."""
    state = np.zeros(4 + 3 * count + 6)
    state[1] = -drop
    orbit = steady["orbit_angle"][0]
    spin = (1 - steady["roller_slip"][0]) * kinematic_spin
    for j in range(count):
        position = 2 * np.pi * j / count  # from the load line, as the steady model's orbit
        k = 4 + 3 * j
        state[k], state[k + 1] = position - np.pi / 2, omega_c
        state[k + 2] = np.interp(position, orbit, spin, period=2 * np.pi)
    cage = 4 + 3 * count
    phi = -np.pi / 2
    state[cage], state[cage + 1] = eccentricity * np.cos(phi), eccentricity * np.sin(phi)
    state[cage + 2] = -eccentricity * omega_c * np.sin(phi)
    state[cage + 3] = eccentricity * omega_c * np.cos(phi)
    state[cage + 4], state[cage + 5] = phi, omega_c
    return state


def _tolerances(count):
    """Absolute tolerances: 10 nm for positions, 1e-6 rad for angles, matching speeds."""
    atol = np.empty(4 + 3 * count + 6)
    atol[0:2], atol[2:4] = 1e-8, 1e-4
    atol[4:4 + 3 * count:3], atol[5:4 + 3 * count:3] = 1e-6, 1e-2
    atol[6:4 + 3 * count:3] = 1e-1
    cage = 4 + 3 * count
    atol[cage:cage + 2], atol[cage + 2:cage + 4] = 1e-8, 1e-4
    atol[cage + 4], atol[cage + 5] = 1e-6, 1e-2
    return atol


_STEADY_NAMES = tuple(i.name for i in STEADY_MODELS[0].inputs if i.name != "orbit_points")


def _sample_times(size, output_interval):
    """The samples' bearing times [s] when one output interval serves the whole grid."""
    return np.arange(size) * output_interval


def _samples(values) -> int:
    """Samples of the longest run on the grid at its finest output interval."""
    return int(np.floor(np.max(values["duration"]) / np.min(values["output_interval"])
                        + 1e-9)) + 1


def _has_mass(cage_width):
    return cage_width > 0


def mass_centre_on_cage(cage_eccentricity, cage_inner_diameter, cage_outer_diameter):
    """Whether a cage with the models' polar inertia about its mass centre, that of a ring
    ``m (R_o^2 + R_i^2) / 2``, can have its mass centre ``e`` from its axis with all its mass
    within the outside radius: about the axis its inertia ``J + m e^2`` is at most
    ``m R_o^2``, so ``e^2 <= (R_o^2 - R_i^2) / 2``."""
    return cage_eccentricity**2 < (cage_outer_diameter**2 - cage_inner_diameter**2) / 8


#: The cage's mass centre and inertia agree with its outline (:func:`mass_centre_on_cage`).
CAGE_MASS_CENTRE = Constraint(
    ("cage_eccentricity", "cage_inner_diameter", "cage_outer_diameter"), mass_centre_on_cage,
    "cage_eccentricity must be below sqrt((cage_outer_diameter^2 - cage_inner_diameter^2) / 8): "
    "a cage with a ring's inertia about its mass centre and all its mass inside its outside "
    "diameter has its mass centre no farther from its axis")


def point_seconds(values) -> np.ndarray:
    """Each point's rough cost on one core [s]: 1.4 s per second of bearing time
    (benchmarks/declared_costs.py), the model's ``seconds_per_point``."""
    return 1.4 * np.ravel(np.asarray(values["duration"], dtype=float))


def _samples_fit(duration, output_interval):
    """At least three samples, so that the settled half's whirl deviation ratio (a standard
    deviation) has two, and at most 1e5 + 1; the last at ``duration`` (a run ends at its
    last sample)."""
    intervals = duration / output_interval
    return ((2.0 * output_interval <= duration * (1.0 + 1e-9)) & (intervals <= 1e5)
            & (np.abs(intervals - np.round(intervals)) <= 1e-9 * intervals))


#: How far a cage's geometric centre may leave the bearing's axis in a transient run, in
#: pocket clearances and diametral clearances together (:func:`run_validity`).
EXCURSION_LIMIT = 2.0
#: Roller passes the settled half must span: a mean over a shorter time does not average the
#: load zone's cycle, and the cage has not left its start (:func:`run_validity`).
SETTLED_PASSES = 2

#: What a transient run's own state puts outside the model's validity (:func:`run_validity`).
RUN_VALIDITY = ("a settled mean cage or roller slip beyond -100 % or +100 % (a cage turning "
                "backwards or at twice its kinematic speed, rollers spinning backwards: no "
                "running state, but an integration too loose or a speed too low for the "
                "traction to drive the rollers); a cage centre farther from the bearing's axis "
                f"than {EXCURSION_LIMIT:g} x (pocket clearance + diametral clearance) at any "
                "sample (its pockets would pass through the rollers); a settled half shorter "
                f"than {SETTLED_PASSES} roller passes, 2 pi / (Z omega_c,kin) each (its means "
                "are not yet the running state's); a raceway contact pressure above 4000 MPa "
                "(ISO 76's reference stress for roller bearings) at a settled sample (the "
                "inner ring's weight loads the bearing besides radial_load)")


def roller_pass_period(roller_count, kinematic_cage_speed):
    """Time between two rollers passing a point of the cage's orbit at the kinematic cage
    speed, ``2 pi / (Z omega_c,kin)`` [s]: the period of the load zone's cycle on the cage."""
    return 2 * np.pi / (roller_count * kinematic_cage_speed)


def run_validity(mean_cage_slip, mean_roller_slip, centre_x, centre_y, pocket_clearance,
                 clearance, times, pass_period, largest_pressure):
    """``OUT_OF_VALIDITY`` where a transient run's own state is none the model holds
    (:data:`RUN_VALIDITY`), else 0; NaN means count as beyond.

    Parameters
    ----------
    mean_cage_slip, mean_roller_slip : float
        Settled means [-].
    centre_x, centre_y : numpy.ndarray
        The cage's geometric centre at each sample [m].
    pocket_clearance, clearance : float
        Pocket clearance and the bearing's diametral clearance [m].
    times : numpy.ndarray
        The samples' times [s] (the settled ones from ``_SETTLED`` of the last on).
    pass_period : float
        :func:`roller_pass_period` [s].
    largest_pressure : float
        The largest raceway contact pressure over the settled samples [Pa].
    """
    excursion = np.max(np.hypot(centre_x, centre_y))
    limit = EXCURSION_LIMIT * (pocket_clearance + clearance)
    settled_span = times[-1] - times[times >= _SETTLED * times[-1]][0]
    inside = (abs(mean_cage_slip) <= 1.0 and abs(mean_roller_slip) <= 1.0
              and excursion <= limit and settled_span >= SETTLED_PASSES * pass_period
              and largest_pressure <= ROLLER_PRESSURE_LIMIT)
    return 0 if inside else OUT_OF_VALIDITY


#: A run's samples (:func:`_samples_fit`).
SAMPLES_FIT = Constraint(
    ("duration", "output_interval"), _samples_fit,
    "duration must hold from two to 1e5 output_intervals, a whole number of them (the "
    "settled half's whirl deviation ratio needs two samples; a run ends at its last sample)")


MODELS = [Model(
    name="cage_dynamics",
    function=cage_dynamics,
    summary="Cylindrical roller bearing, planar transient: cage whirl, pocket contact, cage and "
            "roller slip in time, from the steady state.",
    reference="Paper 002, eq. 27-28 and section 3",
    version="8",
    inputs=tuple(i for i in STEADY_MODELS[0].inputs if i.name not in ("orbit_points", "branch"))
    + (
        Input("cage_density", "kg/m^3", "cage density (brass: 8600; cages: 900 for polymers "
              "to 9000 for bronze)", default=8600.0, minimum=CAGE_DENSITIES[0],
              maximum=CAGE_DENSITIES[1]),
        Input("cage_eccentricity", "mm", "distance of the cage's mass centre from its "
              "geometric centre", default=0.0, minimum=0.0,
              label="cage mass eccentricity"),
        Input("inner_ring_mass", "kg", "inner ring mass (its weight loads the bearing "
              "besides radial_load)", default=0.1, minimum=0.0, exclusive_minimum=True),
        Input("pocket_stiffness", "N/m", "pocket contact stiffness", default=5e7, minimum=0.0,
              exclusive_minimum=True),
        # A linear spring-dashpot contact rebounds with restitution exp(-pi z / sqrt(1 - z^2))
        # below critical damping (z = 1), not at all above it: 2 bounds every contact with room.
        Input("damping_ratio", "1", "damping ratio of pocket and ring contacts", default=0.1,
              minimum=0.0, maximum=2.0,
              label="contact damping ratio"),
        Input("duration", "s", "bearing time simulated", default=0.05, minimum=0.0,
              exclusive_minimum=True, maximum=10.0),
        Input("output_interval", "s", "interval of the returned samples", default=1e-4,
              minimum=0.0, exclusive_minimum=True),
        STEADY_MODELS[0].input("branch"),
    ),
    outputs=(
        Output("cage_slip", "percent", "cage slip 1 - omega_c / omega_c,kin (eq. 27)",
               dims=("elapsed_time",),
               label="cage slip"),
        Output("mean_cage_slip", "percent", "cage slip averaged over the settled second half",
               label="mean cage slip"),
        Output("cage_x", "um", "cage mass centre, horizontal", dims=("elapsed_time",),
               label="cage mass centre x"),
        Output("cage_y", "um", "cage mass centre, vertical (load and gravity along -y)",
               dims=("elapsed_time",), label="cage mass centre y"),
        Output("cage_centre_x", "um", "cage geometric centre, horizontal",
               dims=("elapsed_time",), label="cage geometric centre x"),
        Output("cage_centre_y", "um", "cage geometric centre, vertical",
               dims=("elapsed_time",), label="cage geometric centre y"),
        Output("whirl_speed", "mm/s", "speed of the cage's mass centre (its spread over its "
               "mean: eq. 28)", dims=("elapsed_time",)),
        Output("whirl_deviation_ratio", "1", "standard deviation over mean of the cage centre's "
               "speed, settled half (eq. 28)",
               label="whirl speed deviation ratio"),
        Output("roller_slip", "percent", "roller spin slip against kinematic spin",
               dims=("elapsed_time", "roller")),
        Output("largest_contact_pressure", "MPa", "largest Hertz line-contact pressure of "
               "any roller at either raceway over the settled samples",
               label="largest raceway contact pressure"),
        Output("sample_time", "ms", "bearing time of each sample", dims=("elapsed_time",)),
    ),
    dim_sizes={"elapsed_time": _samples, "roller": "roller_count"},
    # Named elapsed_time, not time: CF reserves a coordinate called time for dates.
    dim_coordinates={"elapsed_time": DimCoordinate(
        ("output_interval",), _sample_times, "ms", "time since the steady start")},
    constraints=STEADY_MODELS[0].constraints + (
        Constraint(("cage_width",), _has_mass, "the transient needs a cage of some width"),
        CAGE_MASS_CENTRE,
        SAMPLES_FIT,
    ),
    seconds_per_point=point_seconds,
    points_per_call=1,
    validity="cage_slip's, for the steady state it starts from: " + STEADY_VALIDITY
    + "; of a run that reaches its end, " + RUN_VALIDITY,
)]
