"""Spatial transient model of a cylindrical roller bearing with circular pockets: rollers and
cage with six degrees of freedom, conformal pocket, end-face and rib contacts, cage mass
eccentricity and ring misalignment (paper 002, sections 1 and 3).

Started from the steady state of :func:`models.cage_slip.cage_slip` and the quasi-static ring
position of :func:`models.cylindrical.crb_radial`, the equations of
:mod:`models.cage_dynamics_6dof_rhs` are integrated by an implicit-explicit additive
Runge-Kutta method that takes the stiff pocket films and raceway contacts implicitly
(``integrator="imex"``,
:mod:`models.cage_dynamics_6dof_imex`; the default with the paper's end films), by an
adaptive Dormand-Prince 5(4) method (``integrator="adaptive"``), by a linearly implicit
Rosenbrock-W method (``integrator="rosenbrock"``, :mod:`models.cage_dynamics_6dof_implicit`),
by variable-order multistep formulas for stiff end films (``integrator="bdf"``,
:mod:`models.cage_dynamics_6dof_multistep`; the default with their pressure) or by the paper's
fixed-step fourth-order Runge-Kutta method (``integrator="rk4"``, ``rk4_step`` 1e-7 s).
"""
from __future__ import annotations

import numpy as np

from . import cage_dynamics_6dof_imex as imex
from . import cage_dynamics_6dof_implicit as implicit
from . import cage_dynamics_6dof_multistep as multistep
from . import cage_dynamics_6dof_rhs as rhs
from .cage_dynamics import (_SETTLED, CAGE_MASS_CENTRE, GRAVITY, RUN_VALIDITY, SAMPLES_FIT,
                            _samples, roller_pass_period, run_validity)
from .cage_dynamics_rhs import roller_loads
from .cage_end_faces import coverage_holds, element_coverage, face_elements
from .cage_slip import MODELS as STEADY_MODELS
from .cage_slip import VALIDITY as STEADY_VALIDITY
from .cage_slip import _pitch_diameter, bearing_terms, cage_slip, cage_windage
from .contact import (STIFFEST_SOLID, effective_modulus, line_contact_pressure,
                      palmgren_constant)
from .contact_laws import palmgren_slice, qin_damping_coefficient, winkler_modulus
from .limits import CAGE_DENSITIES, SOFTEST_BEARING_SOLID
from .cylindrical import crb_radial
from .profiles import slice_centres
from .registry import (CONVERGED, NOT_CONVERGED, OUT_OF_VALIDITY, VALIDITY_MASK, Constraint,
                       DimCoordinate, Input, Model, Output, outcome)

#: The deepest a dry end-face element may press into its face, as a share of the Winkler
#: layer's depth: a linear elastic layer holds strains of that order, not a roller end
#: crushed into a rib.
WINKLER_STRAIN_LIMIT = 0.01
INTEGRATORS = ("auto", "imex", "adaptive", "rosenbrock", "bdf", "rk4")
#: The end-face and rib films: the paper's shear only (eq. 7), or with the film's pressure.
END_FILMS = ("shear", "reynolds")
_MAX_STEPS = 50_000_000
_SLIP_SMOOTHING = 1e-3  # [m/s] Coulomb friction ramps up over this sliding speed
# The steady start's end film covers a quarter of the end faces (cage_slip's default).
_START_END_FILL = 0.25
# cage_slip's inputs this model shares; its pocket and end films come from the elements here.
STEADY_INPUTS = tuple(i.name for i in STEADY_MODELS[0].inputs if i.name not in (
    "orbit_points", "pocket_wrap_angle", "pocket_film_fill", "end_film_thickness",
    "end_film_fill"))


def cage_dynamics_6dof(radial_load, speed, roller_count, inner_raceway_diameter, roller_diameter,
                       roller_length, effective_length, clearance, cage_inner_diameter,
                       cage_outer_diameter, cage_width, roller_density=7820.0,
                       oil_temperature=298.15, viscosity_40=26e-6, viscosity_100=5.4e-6,
                       oil_density=1000.0, pressure_viscosity=1.1e-8, youngs_modulus=207e9,
                       poisson_ratio=0.28, traction_peak=0.05, traction_peak_speed=2.0,
                       traction_limit=0.036, oil_fraction=0.05, drag_coefficient=1.0,
                       pocket_clearance=1e-4, pocket_friction=0.1, pocket_film_fill=1.0,
                       end_film_thickness=1.5e-5,
                       pocket_axial_clearance=1.5e-5, rib_height=2e-3, end_chamfer=5e-4,
                       cage_density=8600.0, cage_youngs_modulus=106e9, cage_poisson_ratio=0.32,
                       winkler_depth=1e-3, restitution=0.8, impact_speed=0.1,
                       film_breakdown=1e-6, end_film="shear", end_film_fill=1.0,
                       initial_skew=0.0, cage_eccentricity=0.0, cage_axial_eccentricity=0.0,
                       misalignment_x=0.0, misalignment_y=0.0, inner_ring_mass=0.1,
                       damping_ratio=0.1, duration=0.05, output_interval=1e-4, slices=10,
                       arc_axial_points=3, arc_angle_points=8, face_rings=5, face_angles=12,
                       relative_tolerance=1e-5, integrator="auto", rk4_step=1e-7,
                       branch="high_slip"):
    """Cage and roller motion in space and time.

    Parameters
    ----------
    radial_load, speed, roller_count, inner_raceway_diameter, roller_diameter,
    roller_length, effective_length, clearance, cage_inner_diameter, cage_outer_diameter,
    cage_width, roller_density, oil_temperature, viscosity_40, viscosity_100, oil_density,
    pressure_viscosity, youngs_modulus, poisson_ratio, traction_peak, traction_peak_speed,
    traction_limit, oil_fraction, drag_coefficient, pocket_clearance, pocket_friction, branch
        As :func:`models.cage_slip.cage_slip`; ``pocket_friction`` is the Coulomb coefficient
        of every dry element (eq. 2, 0.1 in the paper).
    pocket_film_fill : array_like
        Share of the pocket arcs under oil [-] (flooded: 1): scales the film's pressure and
        shear.
    end_film_thickness : array_like
        Axial play of a roller between the inner ring's ribs (Table 2: 0.015 mm) [m].
    pocket_axial_clearance : array_like
        Axial play of a roller between its pocket's end faces (Table 2: 0.015 mm) [m].
    rib_height, end_chamfer : array_like
        Rib height above the inner raceway and the roller end's chamfer (the end face is a
        disc of radius ``D/2 - end_chamfer``) [m]; not in the paper.
    cage_density, cage_youngs_modulus, cage_poisson_ratio : array_like
        The cage's material (Table 3, brass: 8600 kg/m^3, 106 GPa, 0.32) [kg/m^3], [Pa], [-].
    winkler_depth : array_like
        Depth ``H`` of the elastic layer of eq. 1 [m] (not in the paper).
    restitution, impact_speed : array_like
        Qin's damping of eq. 1: coefficient of restitution ``e`` [-] and the approach speed
        it refers to [m/s] (not in the paper).
    film_breakdown : array_like
        Smallest film the short-bearing and shear films use [m]: below it the surfaces'
        roughness carries the load (the dry state begins at contact, eq. 9).
    end_film : {"shear", "reynolds"}
        The oil film between a roller end and its pocket's end face or the rib. ``"shear"``
        is the paper's (eq. 7): the film drags but carries no load. ``"reynolds"`` adds the
        film's pressure from Reynolds' equation across the band where the faces meet
        (:func:`models.cage_dynamics_6dof_rhs._face_pressure`): the squeeze of a closing film
        and the wedge of a leaning one. With shear alone, the aligned bearing's plane is
        unstable: a roller's skew and tilt feed each other through the shear of its spinning
        end faces, and a small skew grows fast (+293 /s at 2 kN, 6000 r/min). The squeeze
        damps them; the wedge pushes across the lean, as a journal bearing's film across
        the journal's displacement, and a skew falls, then grows ten times slower (+24 /s).
        The films are stiff (their damping rate far above the pocket films'): the default
        ``integrator="auto"`` integrates them by the multistep formulas (``"bdf"``).
    end_film_fill : array_like
        Share of the end faces' films under oil [-] (flooded: 1): scales their shear and
        pressure. :func:`models.cage_slip.cage_slip`'s ``end_film_fill`` (0.25 there) is the
        same share, of a film the whole roller end wide against the ribs only.
    initial_skew : array_like
        Every roller's skew at the start [rad], its axis turned about its radial direction
        towards the direction of rotation: a disturbance whose growth or decay says whether
        the rollers' running is stable.
    cage_eccentricity, cage_axial_eccentricity : array_like
        Radial ``e_r`` (along ``x_b``, through pocket 1) and axial ``e_a`` offsets of the
        cage's mass centre from its geometric centre [m] (section 1.5.2).
    misalignment_x, misalignment_y : array_like
        Inner ring turned about X, then about Y [rad].
    inner_ring_mass, damping_ratio : array_like
        The inner ring's mass [kg] and the damping ratio of its radial motion [-].
    duration, output_interval : float
        Bearing time simulated and the interval of the returned samples [s].
    slices, arc_axial_points, arc_angle_points, face_rings, face_angles : int
        Slices of each raceway contact; the Winkler elements of a pocket arc (axial x
        angular, on each of the two arcs) and of a roller end face (rings of equal area x
        angles). A pocket arc's axial elements sit at Gauss-Legendre points, weighted by
        their areas: the short-bearing film's parabolic pressure along an aligned roller is
        summed exactly from two points on, where equal elements overstate it by ``1/(2 m^2)``
        (six of them put the mean cage slip over 10 ms 0.6-1.1 % low at 800 and 200 N).
        Three points give the mean slips over 10 ms within 0.2 % of sixteen, aligned or
        misaligned by 1 deg. Round the arcs, 8 equal elements put the mean cage slip
        0.7-1.3 % high against 32 (Gauss-Legendre points gained nothing there, where the
        film cavitates).
        The end faces converge slowest, and not steadily (an element counts wholly or not at
        all where the face's annulus cuts the end disc): over 10 ms at 800 N, 12000 r/min
        the defaults put the mean roller slip 3.6 % below 24 x 72 end-face elements (the
        cage slip 1.1 %), and with 1 deg of misalignment 6.1 % (cage 5.2 %); 10 x 36 lie
        within 0.8 % (roller) and 2.4 % (cage) of 24 x 72, at about twice the defaults'
        cost. A face that covers a thin part of the end disc (a low rib, a thin cage) meets
        few elements or none: a sweep is refused where the elements facing the cage or the
        rib give the area of the end disc within it, or its centroid, wrong by more than a
        quarter (:mod:`models.cage_end_faces`), and where the rib does not reach the flat
        end face above the chamfer.
    relative_tolerance : float
        Of the adaptive integrators (the absolute ones follow from it: see
        :func:`_absolute_tolerances`), at most the default 1e-5: over 20 ms at 800 N,
        12000 r/min the additive method's mean cage slip at 3e-5 lies 3.9 % below its value
        at 1e-5 and its whirl deviation ratio is twice it, at 1e-4 15 % and three times, at
        1e-2 the slips are nonsense (-86 %). At the default 1e-5 Dormand-Prince's mean slip over
        10 ms at 800 N, 12000 r/min lies 1 % from its value at 1e-7 (converged: 5e-8 gives
        the same to 5 digits), at 80 % of the cost; its steps are mostly held by the
        stability of the stiff pocket films, not by the tolerance. The Rosenbrock-W method
        works to a tenth of it: of third order, with a second-order estimate of its error,
        it needs that to be as accurate (at 2 kN, 6000 r/min over 5 ms, its mean cage slip at
        1e-5 itself lies 11 % from the converged one, at 1e-6 0.2 %). So do the multistep
        formulas, whose error estimate is the Newton iterations' correction: at 800 N,
        12000 r/min with the end films' pressure, over 60 ms, their mean cage slip at 1e-5
        itself lies 0.9 % from the converged one, at 1e-6 0.03 %. The additive method
        works to it as Dormand-Prince does: over 2 ms at 800 N, 12000 r/min its mean slip at
        1e-5 lies 0.08 % from its value at 1e-7. Its steps are held by the tolerance, 1.8
        times as many for each tenth of it: the rollers outside the load zone, pressed on the
        outer raceway by their centrifugal force alone, vibrate there near 28 kHz, lightly
        damped, and the rollers' mean slip depends on that motion being followed (at ten
        times the absolute tolerance of the speeds, 0.1 s takes 43 % fewer steps and the
        mean roller slip falls from 26 % to 18 %).
    integrator : {"auto", "imex", "adaptive", "rosenbrock", "bdf", "rk4"}
        ``"auto"`` (the default) takes ``"imex"``, or ``"bdf"`` with
        ``end_film="reynolds"``. The additive Runge-Kutta method ARK4(3)6L[2]SA with step
        control, the pocket films and contacts and the raceway contacts implicit, the rest
        explicit (:mod:`models.cage_dynamics_6dof_imex`): its steps are not held by the
        pocket films (at 800 N, 12000 r/min, over 0.1 s, 23 % of Dormand-Prince's steps in
        39 % of the time; under a thin pocket film half the time), but are by the end films'
        pressure, whose squeeze damping its implicit part cannot follow where the films
        cavitate and refill (9 100 steps over 2 ms, against the Rosenbrock-W method's 670)
        and, where
        the rollers ride their ribs (1 deg of misalignment), by the end contacts (52 000
        steps per 0.1 s, against Dormand-Prince's 89 000-93 000); Dormand-Prince
        5(4) with step control; the linearly implicit Rosenbrock-W method
        RA34PW2 with step control and the stiff terms' Jacobian in closed form after every
        accepted step (:mod:`models.cage_dynamics_6dof_implicit`), whose steps the stiff
        films do not hold (with ``end_film="reynolds"`` it takes a hundredth of the adaptive
        method's steps; where the pockets touch dry, as under a thin pocket film, its steps
        shrink at every contact and the adaptive method is faster); the numerical
        differentiation formulas of orders 1 to 5 with step and order control
        (:mod:`models.cage_dynamics_6dof_multistep`), whose Newton iterations keep the
        closed-form Jacobian until they stop converging with it: with the end films'
        pressure, where the motion is smooth, a sixth of the Rosenbrock-W method's time
        (800 N, 12000 r/min, 60 ms: 6 100 steps against 31 800, the mean slips within
        0.1 % of either method's at a tenth of the tolerance); where dry contacts come and
        go faster than that Jacobian follows them (a thin pocket film) the iterations stall
        (:data:`models.cage_dynamics_6dof_multistep.STALLED_FAILURES`): ``"bdf"`` then
        reports the run not converged, and ``"auto"`` runs the Rosenbrock-W method in its
        place; or the paper's fixed-step fourth-order Runge-Kutta method at ``rk4_step``.
    rk4_step : float
        The fixed step of ``integrator="rk4"`` [s].

    Returns
    -------
    dict of numpy.ndarray
        Over time ``(N, samples)``: ``cage_slip`` [-] (eq. 27), ``cage_x``, ``cage_y``,
        ``cage_z`` (geometric centre) [m], ``whirl_speed`` (the mass centre's speed in the
        radial plane, eq. 28's ``v`` as the paper's Fig. 18 caption reads) [m/s],
        ``sample_time`` [s]; ``(N, samples, Z)``: ``roller_slip`` [-],
        ``roller_skew`` (axis turned about the radial direction), ``roller_tilt`` (about the
        tangential direction) [rad]. Settled half: ``mean_cage_slip``, ``mean_roller_slip``
        [-], ``whirl_deviation_ratio`` (eq. 28 of the mass centre's speed) and
        ``centre_whirl_deviation_ratio`` (of the geometric centre's, as the paper's text
        reads) [-], ``rms_roller_skew``,
        ``rms_roller_tilt`` [rad]; per pocket ``pocket_arc_force`` ``(N, Z, axial, angle)``
        (largest dry force of each arc element) [N]; ``pocket_end_clearance`` and
        ``rib_clearance`` ``(N, Z, side, ring, angle)`` (smallest gap of each end-face element;
        negative: pressed in; NaN where the face has no counterpart) [m]; contact events
        (dry contacts begun between samples, all rollers) ``pocket_arc_events``,
        ``pocket_end_events``, ``rib_events``; ``integration_steps``; ``status``
        (``out_of_validity`` where the steady start is, where the run's own state is none
        the model holds, :data:`models.cage_dynamics.RUN_VALIDITY`, or where a roller end
        pressed into a pocket end face or a rib deeper than :data:`WINKLER_STRAIN_LIMIT` of
        ``winkler_depth``).

    References
    ----------
    .. [1] Paper 002, sections 1.3-1.5 (eqs. 1-26), eqs. 27-28, section 3.
    """
    given = dict(locals())
    integer = ("roller_count", "slices", "arc_axial_points", "arc_angle_points", "face_rings",
               "face_angles")
    text = ("integrator", "branch", "end_film")
    numeric = [k for k in given if k not in integer + text]
    for k, v in zip(numeric, np.broadcast_arrays(*(np.atleast_1d(np.asarray(
            given[k], dtype=float)) for k in numeric))):
        given[k] = v
    if integrator not in INTEGRATORS:
        raise ValueError(f"integrator must be one of {INTEGRATORS}, not {integrator!r}")
    if end_film not in END_FILMS:
        raise ValueError(f"end_film must be one of {END_FILMS}, not {end_film!r}")
    points = given["radial_load"].size
    samples = int(np.floor(np.max(given["duration"] / given["output_interval"]) + 1e-9)) + 1
    sizes = {"roller": roller_count, "axial": arc_axial_points, "angle": 2 * arc_angle_points,
             "side": 2, "ring": face_rings, "face": face_angles}
    outputs = _empty(points, samples, sizes)
    for point in range(points):
        one = {k: (given[k][point] if k in numeric else given[k]) for k in given}
        status, result = _run(one)
        outputs["status"][point] = status
        for name, value in (result or {}).items():
            target = outputs[name]
            if np.ndim(value):
                target[(point,) + tuple(slice(0, n) for n in np.shape(value))] = value
            else:
                target[point] = value
    return outputs


def _empty(points, samples, sizes):
    def nan(*shape):
        return np.full((points,) + shape, np.nan)

    z = sizes["roller"]
    face = (z, 2, sizes["ring"], sizes["face"])
    return {
        **{name: nan(samples) for name in ("cage_slip", "cage_x", "cage_y", "cage_z",
                                            "whirl_speed", "sample_time")},
        **{name: nan(samples, z) for name in ("roller_slip", "roller_skew", "roller_tilt")},
        **{name: nan() for name in ("mean_cage_slip", "mean_roller_slip",
                                    "whirl_deviation_ratio", "centre_whirl_deviation_ratio",
                                    "rms_roller_skew",
                                    "rms_roller_tilt", "pocket_arc_events", "pocket_end_events",
                                    "rib_events", "integration_steps",
                                    "largest_contact_pressure")},
        "pocket_arc_force": nan(z, sizes["axial"], sizes["angle"]),
        "pocket_end_clearance": nan(*face), "rib_clearance": nan(*face),
        "status": np.full(points, NOT_CONVERGED, dtype=np.int8),
    }


def geometry(terms, one):
    """The elements: slice positions along the roller [m]; the pocket arcs' angles from the
    pocket's radial axis [rad], their axial positions [m] and element areas [m^2], angle x
    axial (Gauss-Legendre points and weights along the pocket's length); the end faces' ring
    radii [m], angles [rad] and element areas [m^2]; and the arcs' wrapped angle [rad]."""
    radius, length = terms["radius"], one["roller_length"]
    slice_z = slice_centres(int(one["slices"])) * 0.5 * terms["contact_length"]
    pocket_radius = radius + 0.5 * terms["pocket_clearance"]
    # The arcs lie where the cage is: between its bore and outside diameter.
    low = np.clip((0.5 * terms["cage_in"] - terms["pitch_radius"]) / pocket_radius, -1, 1)
    high = np.clip((0.5 * terms["cage_out"] - terms["pitch_radius"]) / pocket_radius, -1, 1)
    first, last = np.arccos(high), np.arccos(low)
    n = int(one["arc_angle_points"])
    step = (last - first) / n
    one_arc = first + (np.arange(n) + 0.5) * step
    arc_theta = np.concatenate([-one_arc[::-1], one_arc])
    # Gauss-Legendre points along the arc: the short-bearing film's parabolic pressure along
    # an aligned roller is summed exactly from two points on, where equal elements need many
    # (round the arc, where the film cavitates, they gained nothing on equal ones).
    nodes, weights = np.polynomial.legendre.leggauss(int(one["arc_axial_points"]))
    arc_z = 0.5 * length * nodes
    arc_area = np.outer(np.full(2 * n, pocket_radius * step), 0.5 * length * weights)
    face_r, face_phi, face_area = face_elements(radius - one["end_chamfer"],
                                                int(one["face_rings"]), int(one["face_angles"]))
    return (slice_z, arc_theta, arc_z, arc_area, face_r, face_phi, face_area), 2 * (last - first)


def parameters(one, terms, start_cage_speed, ring_stiffness, cage_mass):
    """The packed parameter array of :mod:`models.cage_dynamics_6dof_rhs`."""
    p = np.zeros(rhs.PARAMETERS)
    p[rhs.OMEGA_I], p[rhs.LOAD] = terms["omega_i"], terms["load"]
    p[rhs.R_INNER], p[rhs.R_OUTER] = terms["r_i"], terms["r_o"]
    p[rhs.RADIUS], p[rhs.LENGTH], p[rhs.PITCH] = (terms["radius"], one["roller_length"],
                                                  terms["pitch_radius"])
    mass, radius, length = terms["mass"], terms["radius"], one["roller_length"]
    p[rhs.M_ROLLER], p[rhs.J_AXIAL] = mass, 0.5 * mass * radius**2
    p[rhs.J_TRANSVERSE] = mass * (3 * radius**2 + length**2) / 12
    p[rhs.K_SLICE] = palmgren_constant(terms["contact_length"]) / one["slices"]
    p[rhs.HUNT] = qin_damping_coefficient(one["restitution"], one["impact_speed"])
    p[rhs.BED_POCKET] = winkler_modulus(one["cage_youngs_modulus"], one["cage_poisson_ratio"],
                                        one["winkler_depth"])
    p[rhs.BED_RIB] = winkler_modulus(terms["modulus"], terms["poisson"], one["winkler_depth"])
    p[rhs.MU_DRY], p[rhs.VISCOSITY] = terms["mu_pocket"], terms["viscosity"]
    p[rhs.FILM_FLOOR] = one["film_breakdown"]
    p[rhs.POCKET_RADIUS] = radius + 0.5 * terms["pocket_clearance"]
    p[rhs.POCKET_PLAY], p[rhs.RIB_PLAY] = (one["pocket_axial_clearance"],
                                           one["end_film_thickness"])
    p[rhs.RIB_RADIUS] = terms["r_i"] + one["rib_height"]
    p[rhs.CAGE_IN], p[rhs.CAGE_OUT] = 0.5 * terms["cage_in"], 0.5 * terms["cage_out"]
    p[rhs.WINDAGE] = terms["windage"]
    drag = cage_windage(start_cage_speed, terms["cage_out"], terms["width"],
                        terms["effective_density"], terms["kinematic_viscosity"])
    p[rhs.CAGE_DRAG] = drag / start_cage_speed**1.5  # laminar disc: moment ~ omega^1.5
    p[rhs.M_RING] = one["inner_ring_mass"]
    p[rhs.C_RING] = 2 * one["damping_ratio"] * np.sqrt(ring_stiffness * one["inner_ring_mass"])
    p[rhs.M_CAGE] = cage_mass
    outer, inner, width = 0.5 * terms["cage_out"], 0.5 * terms["cage_in"], terms["width"]
    p[rhs.J_CAGE_Z] = cage_mass * (outer**2 + inner**2) / 2
    p[rhs.J_CAGE_X] = cage_mass * (3 * (outer**2 + inner**2) + width**2) / 12
    p[rhs.ECC_RADIAL], p[rhs.ECC_AXIAL] = (one["cage_eccentricity"],
                                           one["cage_axial_eccentricity"])
    p[rhs.GRAVITY] = GRAVITY
    p[rhs.MISALIGN_X], p[rhs.MISALIGN_Y] = one["misalignment_x"], one["misalignment_y"]
    curve = terms["traction"]
    p[rhs.TRACTION_A:rhs.TRACTION_D + 1] = (curve.a[0], curve.b[0], curve.c[0], curve.d[0])
    p[rhs.RACEWAYS] = p[rhs.POCKETS] = p[rhs.ENDS] = p[rhs.DRAG] = 1.0
    p[rhs.END_FACES] = p[rhs.END_RIBS] = 1.0
    p[rhs.SLIP_SMOOTHING] = _SLIP_SMOOTHING
    p[rhs.FILM_FILL] = one["pocket_film_fill"]
    p[rhs.END_PRESSURE] = 1.0 if one["end_film"] == "reynolds" else 0.0
    p[rhs.END_FILL] = one["end_film_fill"]
    p[rhs.FACE_RADIUS] = terms["radius"] - one["end_chamfer"]
    return p


def setup(one):
    """Everything one point needs to integrate: parameters, elements, the steady start, the
    sample times and the kinematic speeds; or its status when the steady model has no start."""
    count = int(one["roller_count"])
    steady_inputs = {k: one[k] for k in STEADY_INPUTS if k != "roller_count"}
    terms = {k: (v[0] if isinstance(v, np.ndarray) else v) for k, v in bearing_terms(
        **{k: v for k, v in steady_inputs.items() if k != "branch"}, roller_count=count,
        pocket_wrap_angle=1.0, pocket_film_fill=1.0,
        end_film_thickness=one["end_film_thickness"], end_film_fill=_START_END_FILL,
        ).items()}
    elements, wrapped = geometry(terms, one)
    # The steady start with this model's pocket film: a centred roller's Couette couple over
    # the wrapped arcs at a film of half the pocket clearance, cage_slip's M_p with
    # theta_w = 2 x the wrapped angle.
    steady = cage_slip(**dict(steady_inputs, roller_count=count), pocket_wrap_angle=2 * wrapped,
                       pocket_film_fill=one["pocket_film_fill"],
                       end_film_thickness=one["end_film_thickness"],
                       end_film_fill=_START_END_FILL, orbit_points=20 * count)
    if outcome(steady["status"][0]) != CONVERGED:
        return steady["status"][0], None
    omega_c = steady["cage_speed"][0]
    ring = crb_radial(terms["load"], count, 2 * terms["pitch_radius"], terms["diameter"],
                      terms["contact_length"], clearance=terms["play"], slices=1,
                      speed=terms["omega_i"],
                      roller_density=terms["mass"] / (np.pi * terms["radius"]**2
                                                      * terms["contact_length"]))
    pocket_share = count * (terms["diameter"] + terms["pocket_clearance"]) / (
        2 * np.pi * terms["pitch_radius"])
    cage_mass = one["cage_density"] * np.pi / 4 * (terms["cage_out"]**2 - terms["cage_in"]**2) \
        * terms["width"] * (1 - pocket_share)
    p = parameters(one, terms, omega_c, np.ravel(ring["radial_stiffness"])[0],
                   cage_mass)
    state = start(count, p, palmgren_constant(terms["contact_length"]), steady,
                  np.ravel(ring["radial_displacement"])[0], omega_c, terms["spin_kin"],
                  one["initial_skew"])
    times = np.arange(int(np.floor(one["duration"] / one["output_interval"] + 1e-9)) + 1) \
        * one["output_interval"]
    return CONVERGED, dict(p=p, elements=elements, state=state, times=times, count=count,
                           omega_kin=terms["omega_kin"], spin_kin=terms["spin_kin"],
                           validity=steady["status"][0] & VALIDITY_MASK,
                           slice_length=terms["contact_length"] / one["slices"],
                           modulus=effective_modulus(terms["modulus"], terms["poisson"]))


def start(count, p, whole, steady, drop, omega_c, kinematic_spin, skew):
    """The steady state in space: ring dropped along the load, each roller at its orbit
    position (roller 1 on the load line, at -90 deg) pressed by its quasi-static contact
    loads (``whole``: the roller's Palmgren constant), spinning as the steady model says, axes
    parallel but for a ``skew`` [rad] about the radial direction; the cage centred, turning
    at the steady cage speed, pocket 1 at roller 1."""
    state = np.zeros(rhs.state_size(count))
    state[1] = -drop
    orbit = steady["orbit_angle"][0]
    spin = (1 - steady["roller_slip"][0]) * kinematic_spin
    half_play = 0.5 * (p[rhs.R_OUTER] - p[rhs.R_INNER] - 2 * p[rhs.RADIUS])
    centrifugal = p[rhs.M_ROLLER] * p[rhs.PITCH] * omega_c**2
    for j in range(count):
        position = 2 * np.pi * j / count
        angle = position - np.pi / 2
        approach = drop * np.sin(-angle) - half_play  # ring moved by (0, -drop)
        _, outer = roller_loads(approach, centrifugal, whole)
        rho = p[rhs.R_OUTER] - p[rhs.RADIUS] + (outer / whole) ** 0.9
        k = rhs.RING + rhs.ROLLER_SIZE * j
        state[k:k + 3] = rho * np.cos(angle), rho * np.sin(angle), 0.0
        state[k + 3:k + 6] = -rho * omega_c * np.sin(angle), rho * omega_c * np.cos(angle), 0.0
        state[k + 6:k + 9] = (-np.sin(skew) * np.sin(angle), np.sin(skew) * np.cos(angle),
                              np.cos(skew))
        state[k + 11] = omega_c - np.interp(position, orbit, spin, period=2 * np.pi)
    c = rhs.RING + rhs.ROLLER_SIZE * count
    phi = -np.pi / 2
    eccentric = p[rhs.ECC_RADIAL] * np.array([np.cos(phi), np.sin(phi)])
    state[c:c + 3] = eccentric[0], eccentric[1], p[rhs.ECC_AXIAL]
    state[c + 3:c + 5] = -omega_c * eccentric[1], omega_c * eccentric[0]
    state[c + 6:c + 10] = np.cos(phi / 2), 0.0, 0.0, np.sin(phi / 2)
    state[c + 12] = omega_c
    return state



def _absolute_tolerances(count, relative):
    """Absolute tolerances from the relative one: positions to ``1e-3 x relative`` m (10 nm at
    1e-5), speeds to ``10 x relative`` m/s, axes to ``1e-3 x relative``, angular speeds to
    ``10 x relative`` rad/s per mm of radius (1 rad/s at 1e-5 for a 10 mm roller)."""
    atol = np.empty(rhs.state_size(count))
    atol[0:2], atol[2:4] = 1e-3 * relative, 10 * relative
    for j in range(count):
        k = rhs.RING + rhs.ROLLER_SIZE * j
        atol[k:k + 3], atol[k + 3:k + 6] = 1e-3 * relative, 10 * relative
        atol[k + 6:k + 9], atol[k + 9:k + 12] = 1e-3 * relative, 1e5 * relative
    c = rhs.RING + rhs.ROLLER_SIZE * count
    atol[c:c + 3], atol[c + 3:c + 6] = 1e-3 * relative, 10 * relative
    atol[c + 6:c + 10], atol[c + 10:c + 13] = 1e-3 * relative, 1e4 * relative
    return atol


def chosen(integrator, end_film):
    """The integrator ``"auto"`` stands for: the additive method for the paper's end films,
    the multistep formulas for the end films with their pressure (the Rosenbrock-W method
    where their Newton iterations stall: see :func:`integrate`)."""
    if integrator != "auto":
        return integrator
    return "bdf" if end_film == "reynolds" else "imex"


def integrate(run, one):
    """Integrate a :func:`setup`; returns the integrator's samples, element extremes, events,
    steps and success. Where ``"auto"`` took the multistep formulas and they did not reach
    the end (their Newton iterations stalled on dry contacts), the Rosenbrock-W method runs
    it again from the start; the steps are both methods'."""
    count, times = run["count"], run["times"]
    elements = tuple(np.ascontiguousarray(e, dtype=float) for e in run["elements"])
    record = rhs.scratch(count, elements)
    settled_from = _SETTLED * times[-1]
    integrator = chosen(one["integrator"], one["end_film"])
    if integrator == "rk4":
        try:
            return rhs.integrate_fixed(run["state"], times, run["p"], count, elements, record,
                                       settled_from, float(one["rk4_step"]))
        except ZeroDivisionError:  # an unstable step's stages: a length fallen to zero
            return None, None, None, None, None, np.nan, False
    tolerance = float(one["relative_tolerance"])
    method = rhs.integrate
    if integrator in ("rosenbrock", "bdf"):  # each to a tenth: see relative_tolerance
        tolerance *= 0.1
        method = implicit.integrate if integrator == "rosenbrock" else multistep.integrate
    elif integrator == "imex":
        method = imex.integrate
    atol = _absolute_tolerances(count, tolerance)
    found = method(run["state"], times, run["p"], count, elements, record, settled_from,
                   tolerance, atol, _MAX_STEPS)
    if found[6] or integrator != "bdf" or one["integrator"] != "auto":
        return found
    again = implicit.integrate(run["state"], times, run["p"], count, elements, record,
                               settled_from, tolerance, atol, _MAX_STEPS)
    return *again[:5], again[5] + found[5], again[6]


def _run(one):
    status, run = setup(one)
    if run is None:
        return status, None
    samples, arc, end, rib, events, steps, reached = integrate(run, one)
    if not reached:  # the steady start's validity carried on
        return NOT_CONVERGED | run["validity"], {"integration_steps": float(steps)}
    outputs = results(samples, run)
    deepest = min(np.min(np.where(np.isnan(gaps), np.inf, gaps), initial=np.inf)
                  for gaps in (end, rib))  # NaN: an element that never faced its face
    outputs["largest_contact_pressure"] = raceway_pressure(samples, run)
    validity = run["validity"] | run_validity(
        outputs["mean_cage_slip"], outputs["mean_roller_slip"], outputs["cage_x"],
        outputs["cage_y"], one["pocket_clearance"], one["clearance"], run["times"],
        roller_pass_period(run["count"], run["omega_kin"]), outputs["largest_contact_pressure"])
    p = run["p"]
    lands = (p[rhs.CAGE_IN] - p[rhs.RIB_RADIUS], p[rhs.R_OUTER] - p[rhs.CAGE_OUT])
    if (not deepest >= -WINKLER_STRAIN_LIMIT * one["winkler_depth"]
            or not np.max(np.hypot(outputs["cage_x"] - samples[:, 0],
                                   outputs["cage_y"] - samples[:, 1])) < min(lands)):
        validity |= OUT_OF_VALIDITY
    return CONVERGED | validity, dict(
        outputs, pocket_arc_force=arc.transpose(0, 2, 1),
        pocket_end_clearance=end, rib_clearance=rib, pocket_arc_events=events[0],
        pocket_end_events=events[1], rib_events=events[2], integration_steps=float(steps))


def raceway_pressure(samples, run):
    """The largest Hertz line-contact pressure of any roller's raceway slice over the
    settled samples [Pa]: a slice's load ``K_slice delta^(10/9)`` over its length, at the
    inner raceway (curvature sum ``1/R + 1/r_i``) and the outer (``1/R - 1/r_o``)."""
    p, times = run["p"], run["times"]
    first = int(np.argmax(times >= _SETTLED * times[-1]))
    deepest = rhs.deepest_raceway_approaches(samples, first, p, run["count"],
                                             np.ascontiguousarray(run["elements"][0]))
    curvatures = (1 / p[rhs.RADIUS] + 1 / p[rhs.R_INNER], 1 / p[rhs.RADIUS] - 1 / p[rhs.R_OUTER])
    return max(float(line_contact_pressure(palmgren_slice(p[rhs.K_SLICE], approach)
                                           / run["slice_length"], curvature, run["modulus"]))
               for approach, curvature in zip(deepest, curvatures))


def results(samples, run):
    """The outputs over time and their settled statistics from the sampled states."""
    count, times, p = run["count"], run["times"], run["p"]
    c = rhs.RING + rhs.ROLLER_SIZE * count
    settled = times >= _SETTLED * times[-1]
    turns = np.array([rhs.rotation(q) for q in samples[:, c + 6:c + 10]])  # body axes
    cage_rate = np.einsum("sij,sj->si", turns, samples[:, c + 10:c + 13])
    slip = 1 - np.einsum("si,si->s", cage_rate, turns[:, :, 2]) / run["omega_kin"]
    offset = turns[:, :, 0] * p[rhs.ECC_RADIAL] + turns[:, :, 2] * p[rhs.ECC_AXIAL]
    centre = samples[:, c:c + 3] - offset
    centre_velocity = samples[:, c + 3:c + 6] - np.cross(cage_rate, offset)
    centre_speed = np.hypot(centre_velocity[:, 0], centre_velocity[:, 1])
    speed = np.hypot(samples[:, c + 3], samples[:, c + 4])  # the mass centre's
    rollers = samples[:, rhs.RING:c].reshape(times.size, count, rhs.ROLLER_SIZE)
    position, velocity = rollers[..., 0:3], rollers[..., 3:6]
    axis, omega = rollers[..., 6:9], rollers[..., 9:12]
    rho2 = position[..., 0]**2 + position[..., 1]**2
    orbit_rate = (position[..., 0] * velocity[..., 1] - position[..., 1] * velocity[..., 0]) \
        / rho2
    spin = orbit_rate * axis[..., 2] - np.einsum("stk,stk->st", omega, axis)
    roller_slip = 1 - spin / run["spin_kin"]
    radial = position[..., :2] / np.sqrt(rho2)[..., None]
    along_radius = axis[..., 0] * radial[..., 0] + axis[..., 1] * radial[..., 1]
    along_tangent = -axis[..., 0] * radial[..., 1] + axis[..., 1] * radial[..., 0]
    skew = np.arctan2(along_tangent, axis[..., 2])
    tilt = np.arctan2(along_radius, axis[..., 2])
    return {
        "cage_slip": slip, "cage_x": centre[:, 0], "cage_y": centre[:, 1],
        "cage_z": centre[:, 2], "whirl_speed": speed, "sample_time": times,
        "roller_slip": roller_slip, "roller_skew": skew, "roller_tilt": tilt,
        "mean_cage_slip": slip[settled].mean(),
        "mean_roller_slip": roller_slip[settled].mean(),
        "whirl_deviation_ratio": _deviation_ratio(speed[settled]),
        "centre_whirl_deviation_ratio": _deviation_ratio(centre_speed[settled]),
        "rms_roller_skew": np.sqrt(np.mean(skew[settled] ** 2)),
        "rms_roller_tilt": np.sqrt(np.mean(tilt[settled] ** 2)),
    }


def _deviation_ratio(speed):
    """Standard deviation over mean of a speed's samples (eq. 28)."""
    return speed.std(ddof=1) / speed.mean()


def _sample_times(size, output_interval):
    return np.arange(size) * output_interval


def _arc_angles(values) -> int:
    return 2 * int(np.max(values["arc_angle_points"]))


def _axially_on_cage(cage_axial_eccentricity, cage_width):
    return np.abs(cage_axial_eccentricity) < 0.5 * cage_width


def _face_fits(roller_diameter, end_chamfer):
    return end_chamfer < 0.5 * roller_diameter


def _rib_below_cage(inner_raceway_diameter, rib_height, cage_inner_diameter):
    return inner_raceway_diameter + 2 * rib_height < cage_inner_diameter


def _rib_reaches_face(inner_raceway_diameter, roller_diameter, clearance, end_chamfer,
                      rib_height):
    pitch = 0.5 * _pitch_diameter(inner_raceway_diameter, roller_diameter, clearance)
    return 0.5 * inner_raceway_diameter + rib_height > pitch - (0.5 * roller_diameter
                                                                 - end_chamfer)


def _end_faces_resolved(inner_raceway_diameter, roller_diameter, clearance, end_chamfer,
                        rib_height, cage_inner_diameter, cage_outer_diameter, face_rings,
                        face_angles):
    pitch = 0.5 * _pitch_diameter(inner_raceway_diameter, roller_diameter, clearance)
    face, ring = 0.5 * roller_diameter - end_chamfer, 0.5 * inner_raceway_diameter
    cage, rib = (coverage_holds(*element_coverage(face, pitch, low, high, face_rings,
                                                  face_angles))
                 for low, high in ((0.5 * cage_inner_diameter, 0.5 * cage_outer_diameter),
                                   (ring, ring + rib_height)))
    return cage & rib


def _layer_within_bodies(winkler_depth, cage_inner_diameter, cage_outer_diameter,
                         rib_height):
    return winkler_depth <= np.minimum(0.5 * (cage_outer_diameter - cage_inner_diameter),
                                       rib_height)


def _floor_below_films(film_breakdown, pocket_clearance, end_film_thickness,
                       pocket_axial_clearance):
    return film_breakdown < 0.5 * np.minimum(np.minimum(pocket_clearance, end_film_thickness),
                                             pocket_axial_clearance)


def _rk4_steps_fit(duration, rk4_step):
    return duration / rk4_step <= 1e9


def _skewed(rms_roller_skew):
    # The summary counts from the stored values, in the declared unit (deg), not in SI.
    return rms_roller_skew > 0.05


_PLANAR = {i.name: i for i in STEADY_MODELS[0].inputs}
#: Rough cost of a millisecond of bearing time on one core [s], by end film and adaptive
#: integrator (benchmarks/RESULTS.md, cage dynamics: 0.1 s at 800 N, 12000 r/min), and of
#: the paper's RK4 at its 1e-7 s step.
_SECONDS_PER_MS = {("shear", "imex"): 0.13, ("shear", "adaptive"): 0.45,
                   ("shear", "rosenbrock"): 0.2, ("reynolds", "imex"): 5.5,
                   ("reynolds", "adaptive"): 26.0, ("reynolds", "rosenbrock"): 0.36,
                   ("shear", "bdf"): 0.11, ("reynolds", "bdf"): 0.05}
_RK4_SECONDS_PER_MS = 3.0
#: A misaligned inner ring makes the rollers ride their ribs, whose dry contacts shorten the
#: steps: 1 deg cost 2.2 times the aligned run (the study cage_dynamics_3d, 800 N, 12000
#: r/min: 28 against 13 s, 52 000 against 22 000 steps). Only 1 deg is measured: the extra
#: cost is taken in proportion to the angle up to it, and as at 1 deg beyond.
_MISALIGNED_EXTRA, _MISALIGNED_MEASURED = 1.2, np.radians(1.0)
#: A pocket clearance below the test bearing's 0.1 mm stiffens the pocket films: the steps
#: grow as about (0.1 mm / c_p)^2.7 (benchmarks/RESULTS.md, cage dynamics: 0.05 to 0.01 mm).
_POCKET_MEASURED, _POCKET_EXPONENT = 1e-4, 2.7


def point_seconds(values) -> np.ndarray:
    """Each point's rough cost on one core [s], from its bearing time, end film,
    integrator, misalignment and pocket clearance (the model's ``seconds_per_point``)."""
    duration_ms, film, integrator, step, about_x, about_y, pocket = np.broadcast_arrays(
        1e3 * np.asarray(values["duration"], dtype=float),
        *(np.asarray(values[name]) for name in ("end_film", "integrator", "rk4_step")),
        *(np.asarray(values.get(name, 0.0), dtype=float)
          for name in ("misalignment_x", "misalignment_y")),
        np.asarray(values.get("pocket_clearance", _POCKET_MEASURED), dtype=float))
    methods = [chosen(i, f) for i, f in zip(integrator.ravel(), film.ravel())]
    rate = np.array([_RK4_SECONDS_PER_MS * 1e-7 / float(s) if i == "rk4"
                     else _SECONDS_PER_MS.get((f, i), 1.0)
                     for f, i, s in zip(film.ravel(), methods, step.ravel())])
    tilt = np.minimum(np.hypot(about_x, about_y).ravel() / _MISALIGNED_MEASURED, 1.0)
    tight = np.maximum(_POCKET_MEASURED / pocket.ravel(), 1.0) ** _POCKET_EXPONENT
    return duration_ms.ravel() * rate * (1.0 + _MISALIGNED_EXTRA * tilt) * tight


MODELS = [Model(
    name="cage_dynamics_6dof",
    function=cage_dynamics_6dof,
    summary="Cylindrical roller bearing with circular pockets in space and time: rollers and "
            "cage with six degrees of freedom, Winkler pocket, end-face and rib contacts, cage "
            "mass eccentricity and ring misalignment (paper 002's own model).",
    reference="Paper 002, sections 1.3-1.5 (eqs. 1-26), eqs. 27-28, section 3",
    version="15",
    inputs=tuple(_PLANAR[name] for name in STEADY_INPUTS if name != "branch") + (
        _PLANAR["pocket_film_fill"],
        Input("end_film_thickness", "mm", "axial play of a roller between the ribs (Table 2: "
              "0.015)", default=0.015, minimum=0.0, exclusive_minimum=True,
              label="rib axial clearance"),
        Input("pocket_axial_clearance", "mm", "axial play of a roller between its pocket's "
              "end faces (Table 2: 0.015)", default=0.015, minimum=0.0,
              exclusive_minimum=True, label="pocket axial play"),
        Input("rib_height", "mm", "inner-ring rib height above the raceway (not stated)",
              default=2.0, minimum=0.0, exclusive_minimum=True),
        Input("end_chamfer", "mm", "roller end chamfer: the end face is a disc of radius "
              "D/2 - chamfer (not stated)", default=0.5, minimum=0.0,
              label="roller end chamfer"),
        Input("cage_density", "kg/m^3", "cage density (brass: 8600; cages: 900 for polymers "
              "to 9000 for bronze)", default=8600.0, minimum=CAGE_DENSITIES[0],
              maximum=CAGE_DENSITIES[1]),
        Input("cage_youngs_modulus", "GPa", "cage Young's modulus (brass: 106)", default=106.0,
              minimum=SOFTEST_BEARING_SOLID, maximum=STIFFEST_SOLID),
        Input("cage_poisson_ratio", "1", "cage Poisson's ratio (brass: 0.32)", default=0.32,
              minimum=0.0, maximum=0.49),
        Input("winkler_depth", "mm", "depth H of the Winkler layer of eq. 1 (not stated)",
              default=1.0, minimum=0.0, exclusive_minimum=True),
        # A restitution is the ratio of the speeds of separation and approach: 0 to 1 by the
        # energy an impact cannot gain; a damping ratio 0 to critical and beyond (see
        # cage_dynamics).
        Input("restitution", "1", "coefficient of restitution e of Qin's damping (eq. 1; "
              "not stated)", default=0.8, minimum=0.0, exclusive_minimum=True, maximum=1.0),
        Input("impact_speed", "m/s", "approach speed v- at which e holds (Qin's damping; "
              "not stated)", default=0.1, minimum=0.0, exclusive_minimum=True),
        Input("film_breakdown", "um", "smallest film the pocket and end films use",
              default=1.0, minimum=0.0, exclusive_minimum=True),
        Input("end_film", "1", "roller end and rib films: shear only (the paper's eq. 7) or "
              "reynolds (with the film's squeeze and wedge pressure)", default="shear",
              kind="choice", choices=END_FILMS, label="end-face film"),
        Input("end_film_fill", "1", "share of the end faces' films under oil (flooded: 1)",
              default=1.0, minimum=0.0, maximum=1.0, label="end film fill"),
        Input("initial_skew", "deg", "every roller's skew at the start, a disturbance to "
              "see whether the running is stable", default=0.0, minimum=-1.0, maximum=1.0,
              label="initial roller skew"),
        Input("cage_eccentricity", "mm", "radial distance e_r of the cage's mass centre from "
              "its geometric centre", default=0.0, minimum=0.0,
              label="radial cage mass eccentricity"),
        Input("cage_axial_eccentricity", "mm", "axial distance e_a of the cage's mass centre "
              "from its geometric centre", default=0.0,
              label="axial cage mass eccentricity"),
        Input("misalignment_x", "deg", "inner ring turned about X (horizontal, across the "
              "load)", default=0.0, minimum=-5.0, maximum=5.0),
        Input("misalignment_y", "deg", "inner ring turned about Y (along the load)",
              default=0.0, minimum=-5.0, maximum=5.0),
        Input("inner_ring_mass", "kg", "inner ring mass (its weight loads the bearing "
              "besides radial_load)", default=0.1, minimum=0.0, exclusive_minimum=True),
        Input("damping_ratio", "1", "damping ratio of the inner ring's radial motion",
              default=0.1, minimum=0.0, maximum=2.0),
        Input("duration", "s", "bearing time simulated", default=0.05, minimum=0.0,
              exclusive_minimum=True, maximum=10.0),
        Input("output_interval", "s", "interval of the returned samples", default=1e-4,
              minimum=0.0, exclusive_minimum=True),
        Input("slices", "1", "slices of each raceway contact", default=10, kind="count",
              minimum=1, maximum=200),
        Input("arc_axial_points", "1", "Winkler elements along a pocket arc (Gauss-Legendre "
              "points)", default=3,
              kind="count", minimum=1, maximum=100),
        Input("arc_angle_points", "1", "Winkler elements around each of a pocket's two arcs",
              default=8, kind="count", minimum=1, maximum=100,
              label="pocket-arc elements around each arc"),
        Input("face_rings", "1", "rings of equal area of a roller end face's elements",
              default=5, kind="count", minimum=1, maximum=50, label="end-face element rings"),
        Input("face_angles", "1", "angles of a roller end face's elements", default=12,
              kind="count", minimum=3, maximum=360),
        Input("relative_tolerance", "1", "relative tolerance of the adaptive integrators",
              default=1e-5, minimum=1e-12, maximum=1e-5),
        Input("integrator", "1", "auto (imex, or bdf with end_film = reynolds), imex "
              "(additive Runge-Kutta, the pocket films and raceway contacts implicit), adaptive "
              "(Dormand-Prince 5(4)), rosenbrock (linearly implicit Rosenbrock-W), bdf "
              "(variable-order multistep formulas, for stiff end films) or rk4 (the paper's "
              "fixed step)",
              default="auto", kind="choice", choices=INTEGRATORS),
        Input("rk4_step", "s", "step of the rk4 integrator (the paper: 1e-7 s; a step too "
              "long for the contacts' stiffness is unstable: not converged)", default=1e-7,
              minimum=0.0, exclusive_minimum=True),
        _PLANAR["branch"],
    ),
    outputs=(
        Output("cage_slip", "percent", "cage slip 1 - omega_c / omega_c,kin (eq. 27)",
               dims=("elapsed_time",), label="cage slip"),
        Output("cage_x", "um", "cage geometric centre, horizontal", dims=("elapsed_time",),
               label="cage centre x"),
        Output("cage_y", "um", "cage geometric centre, vertical (load and gravity along -y)",
               dims=("elapsed_time",), label="cage centre y"),
        Output("cage_z", "um", "cage geometric centre, axial", dims=("elapsed_time",),
               label="cage centre z"),
        Output("whirl_speed", "mm/s", "speed of the cage's mass centre in the radial plane "
               "(eq. 28's v, as the caption of the paper's Fig. 18 reads)",
               dims=("elapsed_time",), label="cage mass centre speed"),
        Output("sample_time", "ms", "bearing time of each sample", dims=("elapsed_time",)),
        Output("roller_slip", "percent", "roller spin slip against kinematic spin",
               dims=("elapsed_time", "roller")),
        Output("roller_skew", "deg", "roller axis turned about the radial direction",
               dims=("elapsed_time", "roller")),
        Output("roller_tilt", "deg", "roller axis turned about the tangential direction",
               dims=("elapsed_time", "roller"), label="roller tilt"),
        Output("mean_cage_slip", "percent", "cage slip over the settled second half",
               label="mean cage slip"),
        Output("mean_roller_slip", "percent", "roller slip over the settled half and all "
               "rollers", label="mean roller slip"),
        Output("whirl_deviation_ratio", "1", "standard deviation over mean of the cage's mass "
               "centre's speed, settled half (eq. 28, as the planar cage_dynamics)",
               label="whirl speed deviation ratio"),
        Output("centre_whirl_deviation_ratio", "1", "standard deviation over mean of the "
               "cage's geometric centre's speed, settled half (eq. 28 as the paper's text "
               "reads it)", label="centre whirl deviation ratio"),
        Output("rms_roller_skew", "deg", "root mean square roller skew, settled half",
               counted=("points with rms skew above 0.05 deg", _skewed)),
        Output("rms_roller_tilt", "deg", "root mean square roller tilt, settled half"),
        Output("largest_contact_pressure", "MPa", "largest Hertz line-contact pressure of "
               "any roller's raceway slice over the settled samples",
               label="largest raceway contact pressure"),
        Output("pocket_arc_force", "N", "largest dry contact force of each pocket-arc "
               "element over the settled samples", dims=("roller", "arc_axial", "arc_angle"),
               label="largest dry pocket-arc force"),
        Output("pocket_end_clearance", "um", "smallest gap of each roller end-face element "
               "to its pocket's end face over the settled samples (negative: dry contact)",
               dims=("roller", "end", "face_ring", "face_angle"),
               label="smallest pocket end-face gap"),
        Output("rib_clearance", "um", "smallest gap of each roller end-face element to the "
               "rib over the settled samples (negative: dry contact)",
               dims=("roller", "end", "face_ring", "face_angle"), label="smallest rib gap"),
        Output("pocket_arc_events", "1", "dry pocket-arc contacts begun between settled "
               "samples, all rollers", label="dry pocket-arc contacts", dtype="int"),
        Output("pocket_end_events", "1", "dry pocket end-face contacts begun between settled "
               "samples, all rollers", label="dry pocket end-face contacts",
               dtype="int"),
        Output("rib_events", "1", "dry rib contacts begun between settled samples, all "
               "rollers", dtype="int"),
        Output("integration_steps", "1", "steps of the integrator", dtype="int"),
    ),
    dim_sizes={"elapsed_time": _samples, "roller": "roller_count",
               "arc_axial": "arc_axial_points", "arc_angle": _arc_angles, "end": ("left", "right"),
               "face_ring": "face_rings", "face_angle": "face_angles"},
    dim_coordinates={"elapsed_time": DimCoordinate(
        ("output_interval",), _sample_times, "ms", "time since the steady start")},
    constraints=STEADY_MODELS[0].constraints + (
        CAGE_MASS_CENTRE,
        Constraint(("cage_axial_eccentricity", "cage_width"), _axially_on_cage,
                   "|cage_axial_eccentricity| must be below half the cage_width: a body's "
                   "mass centre lies within its outline"),
        Constraint(("roller_diameter", "end_chamfer"), _face_fits,
                   "end_chamfer must be less than the roller's radius"),
        Constraint(("inner_raceway_diameter", "rib_height", "cage_inner_diameter"),
                   _rib_below_cage, "the rib must stay below the cage's bore"),
        Constraint(("inner_raceway_diameter", "roller_diameter", "clearance", "end_chamfer",
                    "rib_height"), _rib_reaches_face,
                   "rib_height must exceed end_chamfer + clearance / 4: the rib meets the "
                   "roller's flat end face (the model has no contact on the chamfer)"),
        Constraint(("inner_raceway_diameter", "roller_diameter", "clearance", "end_chamfer",
                    "rib_height", "cage_inner_diameter", "cage_outer_diameter", "face_rings",
                    "face_angles"), _end_faces_resolved,
                   "face_rings x face_angles too coarse for the faces a roller's end meets: "
                   "the end-face elements facing the cage (bore to outside diameter) and the "
                   "rib must give the area of the end face within each to 25 % and its "
                   "centroid to 25 % of its radial width; raise face_rings and face_angles "
                   "(a 10 mm roller with a 0.5 mm chamfer beside a 1 mm rib: 10 x 24)"),
        Constraint(("winkler_depth", "cage_inner_diameter", "cage_outer_diameter",
                    "rib_height"), _layer_within_bodies,
                   "winkler_depth must not exceed the cage's wall (cage_outer_diameter - "
                   "cage_inner_diameter) / 2 nor rib_height: the elastic layer lies within "
                   "the bodies it stands for"),
        Constraint(("film_breakdown", "pocket_clearance", "end_film_thickness",
                    "pocket_axial_clearance"), _floor_below_films,
                   "film_breakdown must be below half of pocket_clearance, end_film_thickness "
                   "and pocket_axial_clearance: the smallest film lies below a centred "
                   "roller's films"),
        SAMPLES_FIT,
        Constraint(("duration", "rk4_step"), _rk4_steps_fit,
                   "duration / rk4_step must not exceed 1e9 steps"),
    ),
    seconds_per_point=point_seconds,
    points_per_call=1,
    validity="cage_slip's, for the steady state it starts from: " + STEADY_VALIDITY
    + "; of a run that reaches its end, " + RUN_VALIDITY + ", a roller end pressed into a "
    f"pocket end face or a rib deeper than {WINKLER_STRAIN_LIMIT:g} of winkler_depth (a "
    "raceway contact's pressure is a slice's), or the cage's centre as far from the ring's "
    "as the gap between the cage's bore and the rib or its outside diameter and the outer "
    "raceway (the model has no contact between them)",
)]
