"""Ball bearing under combined load: 5-DOF equilibrium of the inner ring and its stiffness.

Outer ring fixed; inner ring displaced by ``q = (delta_x, delta_y, delta_z, phi_y, phi_z)``
(paper 001, eq. 2-3); ball ``j`` sits at azimuth ``psi_j = 2 pi j / Z`` from the y axis
towards z. Ball centrifugal force and gyroscopic moments are neglected (a static model, as in
the paper), so a ball's two contacts share one line of action and one approach.

Inside this module the tilts are multiplied by the radius ``R`` of the locus of inner groove
curvature centres and the moments divided by it: all five displacements are then lengths and
all five loads forces, the stiffness matrix is well conditioned and one norm measures the
residual.
"""
from __future__ import annotations

import functools

import numpy as np

from .bearing_film import (FILM_INPUTS, MINERAL_OIL_DENSITY, bearing_film, film_outputs,
                           oil_viscosity)
from .bearing_life import (DEFAULT_CONTAMINATION_FACTOR, LIFE_CONSTRAINTS, LIFE_INPUTS,
                           SPEED_INPUT, life_outputs, rating_lives)
from .contact import POINT_CONTACT_EXPONENT, STIFFEST_SOLID, effective_modulus, hertz_point
from .friction import (bearing_friction, friction_constraints, friction_inputs,
                       friction_outputs)
from .geometry import elements_fit
from .kernels import Kernels
from .life import ball_bearing_reference_life, radial_ball_equivalent_load
from .limits import (OIL_VALIDITY, SOFTEST_BEARING_SOLID, SPEED_VALIDITY, not_steel,
                     outside_operation)
from .lubrication import (CELSIUS, MINERAL_OIL_PRESSURE_VISCOSITY, entrainment_speed,
                          point_contact_film, walther_viscosity)
from .operating_clearance import (BEARING_STEEL_EXPANSION, OPERATING_INPUTS,
                                  REFERENCE_TEMPERATURE, mounted_clearance,
                                  operating_constraints, operating_outputs)
from .registry import (CONVERGED, INFEASIBLE, NOT_CONVERGED, OUT_OF_VALIDITY, Constraint,
                             Input, Model, Output, combine_status)
from .static_safety import STATIC_INPUTS, ball_rating, static_outputs, static_safety

DOFS = ("axial", "radial_y", "radial_z", "tilt_y", "tilt_z")
GEOMETRIES = ("jones", "fixed_angle")
_LOADS = ("axial_load", "radial_load", "radial_load_z", "moment_y", "moment_z")
_TILTS = slice(3, 5)
_RESIDUAL_TOLERANCE = 1e-10  # relative to the load [-]
_MAX_ITERATIONS = 200
_START_DAMPING = 0.01  # of the preloaded stiffness: a start close to Newton
_SINGULAR = 1e-9  # reciprocal condition number below which the stiffness is singular [-]

#: Validity limits (``out_of_validity`` beyond them; see ``MODELS[0].validity``).
#: ISO 76:2006, 3.1: the basic static load rating of ball bearings other than self-aligning
#: ones is the load that gives this contact stress at the centre of the most loaded contact;
#: the permanent deformation of ball and raceway is then about 1e-4 of the ball diameter, so
#: beyond it the contact is no longer the elastic one of Hertz theory.
MAX_CONTACT_PRESSURE = 4200e6  # [Pa]
#: Hertz theory takes the contact to be small against the bodies (K. L. Johnson, Contact
#: Mechanics, 1985, sec. 4.1); a ball on a plane reaches an approach of 1 % of its diameter
#: with a contact radius of 0.14 times its radius. Steel balls reach it just beyond
#: MAX_CONTACT_PRESSURE; softer materials or a given contact_constant may reach it first.
MAX_APPROACH_PER_DIAMETER = 0.01  # [-]


def raceway_contacts(ball_diameter, pitch_diameter, contact_angle, inner_curvature_ratio,
                     outer_curvature_ratio, youngs_modulus=207e9, poisson_ratio=0.3):
    """Hertz contacts of a ball with its inner and outer raceways under a load of 1 N.

    Parameters
    ----------
    ball_diameter, pitch_diameter : array_like
        ``D``, ``d_m`` [m].
    contact_angle : array_like
        ``alpha`` [rad]; the raceway curvature in the rolling direction is taken there.
    inner_curvature_ratio, outer_curvature_ratio : array_like
        ``f_i = r_i / D``, ``f_o = r_o / D`` [-], groove radius over ball diameter (> 0.5).
    youngs_modulus, poisson_ratio : array_like
        Of balls and rings [Pa], [-].

    Returns
    -------
    inner, outer : dict of numpy.ndarray
        :func:`models.contact.hertz_point` at ``Q = 1 N``: ``contact_constant`` ``K``
        [N/m^1.5] in ``Q = K delta^1.5``, ``max_pressure`` [Pa] (``p0`` grows as ``Q^(1/3)``,
        since both semi-axes do), ``semi_major`` [m], ``status``, ...

    Notes
    -----
    With ``gamma = D cos(alpha) / d_m``, the ball's curvatures are ``2/D`` in both planes; the
    inner raceway's are ``(2/D) gamma / (1 - gamma)`` (rolling) and ``-1/(f_i D)`` (groove),
    the outer raceway's ``-(2/D) gamma / (1 + gamma)`` and ``-1/(f_o D)`` (Harris and
    Kotzalas, ch. 2). Paper 001 eq. 5 in the same terms.
    """
    ball = 2.0 / np.asarray(ball_diameter)
    gamma = ball_diameter * np.cos(contact_angle) / np.asarray(pitch_diameter)
    return tuple(
        hertz_point(1.0, ball, ball, rolling, -1.0 / (np.asarray(groove) * ball_diameter),
                    youngs_modulus, poisson_ratio)
        for rolling, groove in ((ball * gamma / (1.0 - gamma), inner_curvature_ratio),
                                (-ball * gamma / (1.0 + gamma), outer_curvature_ratio)))


def series_constant(inner, outer, exponent=POINT_CONTACT_EXPONENT):
    """Constant of two contacts in series that carry the same load (paper 001 eq. 4, corrected).

    ``Q = K_i d_i^n = K_o d_o^n`` and ``d = d_i + d_o`` give
    ``K = [(1/K_i)^(1/n) + (1/K_o)^(1/n)]^(-n)``; the paper prints the exponents swapped.
    """
    return (np.asarray(inner) ** (-1.0 / exponent)
            + np.asarray(outer) ** (-1.0 / exponent)) ** (-exponent)


class BallRings:
    """Per-point geometry of one group of points with the same ball count and geometry, for
    the compiled equilibrium (:mod:`models.ball_equilibrium`).

    Per point: curvature-centre distance ``A``, unloaded contact angle, half clearance and
    contact constant, all ``(N,)``. ``geometry`` is 'jones' or 'fixed_angle'.
    """

    def __init__(self, ball_count, distance, contact_angle, half_clearance, constant, geometry):
        self.compiled = compiled = _kernels(np.size(distance))
        self.psi = compiled.azimuth_functions(ball_count)
        self.jones = geometry == "jones"
        sin0, cos0 = np.sin(contact_angle), np.cos(contact_angle)
        self.offset0 = half_clearance * cos0
        # The columns DISTANCE..CONSTANT of models.ball_equilibrium, in its order.
        self.rings = np.stack(np.broadcast_arrays(
            distance, sin0, cos0, distance * sin0, distance * cos0 - half_clearance,
            self.offset0, constant), -1).astype(float)
        self.constant = self.rings[:, compiled.CONSTANT]

    def contacts(self, scaled, index):
        """Each ball's approach, load, load slope, unit normal (axial and radial parts) and
        centre distance (NaN in the fixed-angle geometry) at the displacement ``scaled`` of
        the points ``index`` (``(n, Z)`` each)."""
        with np.errstate(all="ignore"):  # IEEE results, as compiled
            return tuple(self.compiled.contacts_at(*self._points(scaled, index), self.rings,
                                                   self.jones, self.psi))

    def reaction(self, scaled, index):
        """Scaled generalised force the balls put on the inner ring (paper eq. 6-7),
        ``(n, 5)``."""
        with np.errstate(all="ignore"):
            return self.compiled.sums_at(*self._points(scaled, index), self.rings,
                                         self.jones, self.psi)[0]

    def reaction_and_stiffness(self, scaled, index):
        """:meth:`reaction` and :meth:`stiffness` at once."""
        with np.errstate(all="ignore"):
            return self.compiled.sums_at(*self._points(scaled, index), self.rings,
                                         self.jones, self.psi)[:2]

    def stiffness(self, scaled, index):
        """Scaled tangent stiffness d(reaction)/d(displacement), ``(n, 5, 5)`` (eq. 9)."""
        with np.errstate(all="ignore"):
            return self.compiled.sums_at(*self._points(scaled, index), self.rings,
                                         self.jones, self.psi)[1]

    @staticmethod
    def _points(scaled, index):
        return (np.ascontiguousarray(scaled, dtype=float),
                np.ascontiguousarray(index, dtype=np.int64))


def ball_5dof(ball_count, ball_diameter, pitch_diameter, contact_angle,
              inner_curvature_ratio=0.52, outer_curvature_ratio=0.53, clearance=0.0,
              youngs_modulus=207e9, poisson_ratio=0.3, contact_constant=None, axial_load=0.0,
              radial_load=0.0, radial_load_z=0.0, moment_y=0.0, moment_z=0.0,
              geometry="jones", fixed_dofs="", pressure_limit=MAX_CONTACT_PRESSURE,
              speed=0.0, dynamic_load_rating=None, fatigue_load_limit=None,
              contamination_factor=DEFAULT_CONTAMINATION_FACTOR,
              oil_temperature=70.0 + CELSIUS, viscosity_40=None, viscosity_100=None,
              oil_density=MINERAL_OIL_DENSITY, pressure_viscosity=MINERAL_OIL_PRESSURE_VISCOSITY,
              composite_roughness=None, minimum_static_safety=None, shaft_fit=0.0,
              housing_fit=0.0, bore=None, outside_diameter=None, shaft_bore=0.0,
              housing_outside_diameter=None, inner_ring_temperature=REFERENCE_TEMPERATURE,
              outer_ring_temperature=REFERENCE_TEMPERATURE, shaft_temperature=None,
              housing_temperature=None, shaft_youngs_modulus=207e9, shaft_poisson_ratio=0.3,
              shaft_expansion=BEARING_STEEL_EXPANSION, housing_youngs_modulus=207e9,
              housing_poisson_ratio=0.3, housing_expansion=BEARING_STEEL_EXPANSION,
              friction_method="skf", lubrication_method="oil_bath",
              skf_rolling_constant_1=None, skf_rolling_constant_2=None,
              skf_rolling_constant_3=None, skf_sliding_constant_1=None,
              skf_sliding_constant_2=None, skf_sliding_constant_3=None,
              boundary_friction_coefficient=0.15, full_film_friction_coefficient=0.05,
              palmgren_speed_factor=None, palmgren_load_factor=None, oil_level=None,
              drag_loss_factor=None):
    """Equilibrium, 5 x 5 stiffness matrix, contact pressures, lubricant film and rating life
    of a ball bearing's inner ring.

    Parameters
    ----------
    ball_count : int
        Number of balls ``Z``.
    ball_diameter, pitch_diameter : array_like
        ``D``, ``d_m`` [m].
    contact_angle : array_like
        Unloaded contact angle ``alpha_0`` [rad]: the direction of the line between the groove
        curvature centres with the rings centred.
    inner_curvature_ratio, outer_curvature_ratio : array_like
        ``f_i``, ``f_o`` [-]: groove radius over ball diameter.
    clearance : array_like
        Diametral clearance ``P_d`` [m] in addition to the contact at ``alpha_0``: the outer
        groove centres lie ``P_d / 2`` further out (negative: preload).
    youngs_modulus, poisson_ratio : array_like
        [Pa], [-], for the Hertz constant.
    contact_constant : array_like or None
        ``K`` [N/m^1.5] of ball and both raceways in series, ``Q = K delta^1.5``; None: from
        Hertz theory and the curvature ratios (:func:`raceway_contacts`).
    axial_load, radial_load, radial_load_z : array_like
        Loads on the inner ring along x, y, z [N].
    moment_y, moment_z : array_like
        Moments on the inner ring about y and z [N m].
    geometry : {'jones', 'fixed_angle'}
        'jones': each ball's line of action joins its groove centres as displaced, so contact
        angles follow the load [2]; 'fixed_angle': the approach is the displacement projected
        on the unloaded contact angle, paper 001 eq. 2-7 as printed.
    fixed_dofs : str or sequence of str
        Displacements held at zero (names from ``DOFS``; a string separates them by spaces).
    pressure_limit : array_like
        Contact pressure above which a point is ``out_of_validity`` [Pa] (default 4200 MPa,
        ISO 76's reference stress for ball bearings of through-hardened steel).
    speed : array_like
        Speed of the inner ring [rad/s], for the lives in hours, the viscosity ratio and the
        film only (the load distribution is static).
    dynamic_load_rating, fatigue_load_limit : array_like or None
        The bearing's basic dynamic load rating ``C_r`` and fatigue load limit ``C_u`` [N];
        None: no life (no modified life) (NaN).
    contamination_factor : array_like
        ``e_C`` [-] (ISO 281 Table 13).
    oil_temperature, viscosity_40, viscosity_100 : array_like or None
        Oil temperature [K] and kinematic viscosities at 40 and 100 deg C [m^2/s]; None: no
        modified life and no film.
    oil_density, pressure_viscosity : array_like
        Of the oil at its temperature [kg/m^3], [1/Pa], for the film.
    composite_roughness : array_like or None
        ``sigma`` of balls and raceways [m], for the film parameter; None: NaN.
    minimum_static_safety : array_like or None
        The smallest ``pressure_safety_factor`` the application needs [-]; None: no check.
    shaft_fit, housing_fit, bore, outside_diameter, shaft_bore, housing_outside_diameter,
    inner_ring_temperature, outer_ring_temperature, shaft_temperature, housing_temperature,
    shaft_youngs_modulus, shaft_poisson_ratio, shaft_expansion, housing_youngs_modulus,
    housing_poisson_ratio, housing_expansion : array_like or None
        The bearing as mounted, for its operating clearance
        (:func:`models.operating_clearance.operating_clearance`; lengths [m], temperatures
        [K], moduli [Pa], expansion coefficients [1/K]): the equilibrium takes the operating
        clearance in place of ``clearance``, the raceways at the groove bottoms ``d_m -+ D``.
    friction_method, lubrication_method, skf_rolling_constant_1, skf_rolling_constant_2,
    skf_rolling_constant_3, skf_sliding_constant_1, skf_sliding_constant_2,
    skf_sliding_constant_3, boundary_friction_coefficient, full_film_friction_coefficient,
    palmgren_speed_factor, palmgren_load_factor, oil_level,
    drag_loss_factor : str or array_like or None
        The friction torque's method and constants (:func:`models.friction.bearing_friction`,
        SKF's in its units; coefficients and factors [-]; level [m]), from the radial and
        axial loads (SKF's model takes no moment).

    Returns
    -------
    dict of numpy.ndarray
        ``displacement`` ``(N, 5)`` [m, m, m, rad, rad]; ``axial_displacement``,
        ``radial_displacement`` (magnitude in the y-z plane) [m]; ``stiffness_matrix``
        ``(N, 5, 5)`` ``K_ij = dF_i/dq_j`` [N/m, N/rad; N (N m/m), N m/rad], symmetric;
        ``axial_stiffness`` ``K_11``, ``radial_stiffness`` ``K_22`` [N/m], ``tilt_stiffness``
        ``K_44`` [N m/rad] (eq. 10, the diagonal); ``ball_load`` ``(N, Z)`` [N];
        ``ball_contact_angle`` ``(N, Z)`` [rad]; ``loaded_balls``; ``max_contact_pressure``
        ``(N, Z)`` [Pa], the larger Hertz ``p0 = 3Q/(2 pi a b)`` of each ball's two contacts
        (exact ellipse, raceway curvatures at ``alpha_0`` as for the Hertz constant [3]),
        ``largest_contact_pressure`` over the balls [Pa]; the films of
        :func:`models.bearing_film.bearing_film` [m, -]; the operating clearance and its parts
        of :func:`models.operating_clearance.operating_clearance` [m]; ISO 76's rating of
        :func:`models.static_safety.ball_rating` [N, -]; the static safety of
        :func:`models.static_safety.static_safety` [-]; the lives of
        :func:`models.bearing_life.rating_lives` (Notes) [rad: 10^6 revolutions of 2 pi; s],
        ``equivalent_dynamic_load`` [N], ``viscosity_ratio``, ``life_modification_factor``
        [-]; ``hertz_contact_constant`` [N/m^1.5] (whether or not ``contact_constant``
        replaces it); ``status``: not converged (1); infeasible (2) where the free displacements'
        stiffness is singular under load (the load cannot be carried, or not by a unique
        displacement) or where the iteration ran the ring out of the bearing (farther than
        ``A``) without an equilibrium; out of validity (4, values kept) beyond the limits of
        ``MODELS[0].validity``: ``p0`` above ``pressure_limit`` [4], a static safety below
        ``minimum_static_safety``, an approach above
        ``MAX_APPROACH_PER_DIAMETER`` ``D`` [5], a displacement beyond ``A``, or a loaded
        ball's contact angle of the opposite sign to ``alpha_0 > 0``; and, whatever the
        outcome, a speed factor ``n d_m`` above 4e6 mm r/min or an oil whose viscosity index
        no lubricant has (:func:`models.limits.outside_operation`).

    Notes
    -----
    Film: each loaded ball's inner and outer contact by Hamrock and Dowson's isothermal
    formulas (:func:`models.lubrication.point_contact_film`) with the ellipticity of the
    exact Hertz ellipse and ``R_x = D (1 -+ gamma) / 2`` at ``alpha_0`` (the curvatures the
    Hertz constant takes), the entrainment speed of pure rolling with the inner ring turning
    (:func:`models.lubrication.entrainment_speed`), the oil's dynamic viscosity at its
    temperature and ``E' = 2 E*``.

    Life: the inner ring rotates, the outer ring and the load stand still. ISO/TS 16281's
    reference life ``L10r`` is formed from every ball's load (one load for both contacts:
    no centrifugal force), with the inner ring's exponent 3 and the outer ring's 10/3 over
    the balls, the contact ratings from ``C_r``, the groove curvatures and ``alpha_0`` [6];
    so clearance, moments and the contact angles that follow the load enter it through the
    ball loads. ISO 281's equivalent load is ``P = X F_r + Y F_a`` with ``F_r`` the radial
    load's magnitude in the y-z plane and ``F_a = |F_x|``
    (:func:`models.life.radial_ball_equivalent_load`): ``P = F_r`` without axial load, the
    factors of Table 3 for ``20 <= alpha_0 <= 45`` deg; NaN under a moment, or with an
    axial load below 20 deg (deep-groove bearings: ``e`` and ``Y`` need the static load
    rating) [7]. The modified lives take ``a_ISO`` with the viscosity ratio of the oil at
    its temperature (:func:`models.bearing_life.rating_lives`).

    In the fixed-angle geometry a ball's approach is ``(dx + R(phi_y sin psi - phi_z cos
    psi)) sin(alpha_0) + (dy cos psi + dz sin psi) cos(alpha_0)``: ``dz = -R tan(alpha_0)
    phi_y`` (and ``dy = R tan(alpha_0) phi_z``), a tilt about the apex of the contact cone,
    changes no approach, so with ``tilt_y`` and ``radial_z`` (or ``tilt_z`` and ``radial_y``)
    free the stiffness is singular at every load; the declaration refuses such definitions.
    Every ball's force then also has the axial part ``Q sin(alpha_0)``, so with the axial
    displacement free a load needs at least ``F_x >= |F_r| tan(alpha_0)``: without it the
    iteration runs away axially and the point is infeasible.

    References
    ----------
    .. [1] Paper 001, eq. 1-10.
    .. [2] A. B. Jones, A general theory for elastically constrained ball and radial roller
       bearings under arbitrary load and speed conditions, J. Basic Eng. 82 (1960) 309-320.
    .. [3] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., ch. 6 (Hertz
       point contact).
    .. [4] ISO 76:2006, Rolling bearings - Static load ratings, 3.1 (4200 MPa for ball
       bearings other than self-aligning ones).
    .. [5] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985, sec. 4.1.
    .. [6] ISO/TS 16281:2008, Rolling bearings - Methods for calculating the modified
       reference rating life for universally loaded bearings, 4.3.
    .. [7] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life, 5.2 and
       Table 3; 9.3 (a_ISO).
    """
    names = fixed_dofs.split() if isinstance(fixed_dofs, str) else list(fixed_dofs)
    unknown = [name for name in names if name not in DOFS]
    if unknown or geometry not in GEOMETRIES:
        raise ValueError(f"fixed_dofs must name {DOFS}, geometry one of {GEOMETRIES}")
    free = np.array([dof not in names for dof in DOFS])
    life = (dynamic_load_rating, fatigue_load_limit, contamination_factor, oil_temperature,
            viscosity_40, viscosity_100)
    arrays = np.broadcast_arrays(*(np.atleast_1d(np.asarray(np.nan if a is None else a,
                                                            dtype=float)) for a in (
        ball_diameter, pitch_diameter, contact_angle, inner_curvature_ratio,
        outer_curvature_ratio, clearance, youngs_modulus, poisson_ratio, axial_load,
        radial_load, radial_load_z, moment_y, moment_z, contact_constant, pressure_limit,
        speed) + life + (oil_density, pressure_viscosity, composite_roughness,
                         minimum_static_safety, shaft_fit, housing_fit, bore, outside_diameter,
                         shaft_bore, housing_outside_diameter, inner_ring_temperature,
                         outer_ring_temperature, shaft_temperature, housing_temperature,
                         shaft_youngs_modulus, shaft_poisson_ratio, shaft_expansion,
                         housing_youngs_modulus, housing_poisson_ratio, housing_expansion,
                         skf_rolling_constant_1, skf_rolling_constant_2,
                         skf_rolling_constant_3, skf_sliding_constant_1,
                         skf_sliding_constant_2, skf_sliding_constant_3,
                         boundary_friction_coefficient, full_film_friction_coefficient,
                         palmgren_speed_factor, palmgren_load_factor, oil_level,
                         drag_loss_factor)))
    (diameter, pitch, angle, inner_ratio, outer_ratio, clearance, modulus, poisson,
     *loads, given, pressure_limit, speed) = arrays[:16]
    life, oil, minimum_safety = arrays[16:22], arrays[22:25], arrays[25]
    mounted = mounted_clearance(clearance, pitch - diameter, pitch + diameter, diameter, speed,
                                modulus, poisson, *arrays[26:42])
    fit_lost = mounted.pop("fit_lost")
    inner, outer = _per_distinct_row(raceway_contacts, diameter, pitch, angle, inner_ratio,
                                     outer_ratio, modulus, poisson)
    hertz_ok = (inner["status"] == CONVERGED) & (outer["status"] == CONVERGED)
    hertz_constant = series_constant(inner["contact_constant"], outer["contact_constant"])
    constant = np.where(np.isnan(given), hertz_constant, given)
    constant = np.where(np.isfinite(constant), constant, 1.0)  # failed Hertz: flagged below
    distance = (inner_ratio + outer_ratio - 1.0) * diameter
    radius = 0.5 * pitch + (inner_ratio - 0.5) * diameter * np.cos(angle)
    scale = np.stack([np.ones_like(radius)] * 3 + [radius] * 2, -1)  # length per unit dof
    load = np.stack(loads, -1) / scale
    load[:, ~free] = 0.0
    rings = BallRings(ball_count, distance, angle, 0.5 * mounted["operating_clearance"], constant,
                   geometry)
    scaled, converged, stiffness, condition, contacts = _equilibrium(rings, load, free,
                                                                     ball_count)
    approach, ball_load, _, normal_axial, normal_radial, _ = contacts
    singular = condition < _SINGULAR
    loaded = np.linalg.norm(load, axis=-1) > 0
    # A ring moved farther than the groove-centre distance A has left its bearing: the
    # iteration of a load the balls cannot balance runs away so (in the fixed-angle geometry,
    # any load off the cone of the balls' contact directions, e.g. a radial load without
    # axial load), and a solution out there is outside either geometry.
    left_bearing = np.abs(scaled).max(axis=-1) > distance
    status = np.select([~hertz_ok, ~converged & (singular | left_bearing), ~converged,
                        singular & loaded],
                       [NOT_CONVERGED, INFEASIBLE, NOT_CONVERGED, INFEASIBLE], CONVERGED)
    contact_angle = np.arctan2(normal_axial, normal_radial)
    # Both semi-axes grow as Q^(1/3), so p0 = 3Q/(2 pi a b) does too.
    unit_pressure = np.maximum(inner["max_pressure"], outer["max_pressure"])
    pressure = unit_pressure[:, None] * np.cbrt(ball_load)
    crossed = (angle[:, None] > 0) & (ball_load > 0) & (contact_angle < 0)
    static, unsafe = static_safety(pressure.max(axis=-1), "ball", minimum_safety)
    outside = (unsafe | (pressure.max(axis=-1) > pressure_limit)
               | (approach.max(axis=-1) > MAX_APPROACH_PER_DIAMETER * diameter)
               | left_bearing | crossed.any(axis=-1))
    # Judged on a solution only: a failed point's last iterate says nothing of the bearing;
    # a speed or an oil no bearing runs with, whatever the outcome.
    # A given constant holds for the material it was found for, steel for paper 001's (a
    # preset's): with other balls and rings the same contacts carry other loads.
    no_bearing = (outside_operation(speed, pitch, life[4], life[5])
                  | (np.isfinite(given) & not_steel(modulus, poisson)))
    status = combine_status(status, np.where(
        (outside & (status == CONVERGED)) | no_bearing | fit_lost, OUT_OF_VALIDITY,
        CONVERGED))
    displacement = scaled / scale
    matrix = stiffness * scale[:, :, None] * scale[:, None, :]
    outputs = {
        "displacement": displacement,
        "axial_displacement": displacement[:, 0],
        "radial_displacement": np.hypot(displacement[:, 1], displacement[:, 2]),
        "stiffness_matrix": matrix,
        "axial_stiffness": matrix[:, 0, 0],
        "radial_stiffness": matrix[:, 1, 1],
        "tilt_stiffness": matrix[:, 3, 3],
        "ball_load": ball_load,
        "ball_contact_angle": contact_angle,
        "loaded_balls": np.count_nonzero(approach > 0, axis=-1).astype(float),
        "max_contact_pressure": pressure,
        "largest_contact_pressure": pressure.max(axis=-1),
        "hertz_contact_constant": hertz_constant,
        **static,
        **mounted,
    }
    axial, radial, radial_z, moment_y, moment_z = loads
    equivalent_load = radial_ball_equivalent_load(np.hypot(radial, radial_z), axial, angle,
                                                  np.hypot(moment_y, moment_z))
    outputs.update(ball_rating(ball_count, diameter, pitch, angle, np.hypot(radial, radial_z),
                               axial, np.hypot(moment_y, moment_z)))
    outputs.update(rating_lives(
        _reference_life(ball_load, life[0], diameter, pitch, angle, inner_ratio, outer_ratio),
        equivalent_load, "ball", speed, pitch, *life))
    outputs.update(_film(ball_load, inner, outer, diameter, pitch, angle, modulus, poisson,
                         speed, life, *oil))
    friction = arrays[42:]
    outputs.update(bearing_friction(
        "angular_contact_ball", friction_method, lubrication_method, speed, pitch,
        np.hypot(radial, radial_z), axial, walther_viscosity(*life[3:]),
        dict(zip(("r1", "r2", "r3", "s1", "s2", "s3"), friction[:6])), *friction[6:10],
        outputs["static_equivalent_load"], *arrays[28:30], oil_level=friction[10],
        drag_loss_factor=friction[11]))
    outputs["status"] = status.astype(np.int8)
    return outputs


def _per_distinct_row(function, *arrays):
    """``function(*arrays)``, a tuple of dicts of per-point arrays, computed once for each
    distinct row of the ``(N,)`` ``arrays``: a sweep's bearing is mostly the same at every
    point, and its Hertz contacts cost as much as the equilibrium. Each row's numbers are
    those of a call with that row alone."""
    table = np.stack(arrays, -1)
    if (table == table[:1]).all():
        distinct, where = table[:1], np.zeros(len(table), dtype=int)
    else:
        distinct, where = np.unique(table, axis=0, return_inverse=True)
    found = function(*distinct.T)
    return tuple({name: np.asarray(value)[where.reshape(-1)] for name, value in part.items()}
                 for part in found)


def _reference_life(ball_load, rating, diameter, pitch, angle, inner_ratio, outer_ratio):
    """ISO/TS 16281's L10r of the inner ring rotating under the ball loads [10^6
    revolutions]; infinite without load, NaN without a rating."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return ball_bearing_reference_life(ball_load, rating, diameter, pitch, angle,
                                           inner_ratio, outer_ratio)


def _film(ball_load, inner, outer, diameter, pitch, angle, modulus, poisson, speed, life,
          oil_density, pressure_viscosity, roughness):
    """The film outputs of every ball's two contacts (see :func:`ball_5dof`'s Notes)."""
    gamma = diameter * np.cos(angle) / pitch
    films = [point_contact_film(
        ball_load, (0.5 * diameter * (1.0 + sign * gamma))[:, None],
        contact["ellipticity"][:, None],
        entrainment_speed(speed, pitch, diameter, angle)[:, None],
        oil_viscosity(life[3], life[4], life[5], oil_density)[:, None],
        pressure_viscosity[:, None], 2.0 * effective_modulus(modulus, poisson)[:, None])
        for sign, contact in ((-1.0, inner), (1.0, outer))]
    return bearing_film(np.concatenate([films[0][0], films[1][0]], axis=-1),
                        np.concatenate([films[0][1], films[1][1]], axis=-1), roughness)


def _equilibrium(rings: BallRings, load, free, ball_count):
    """Displacements where the balls' reaction balances ``load`` in the free directions, the
    stiffness and each ball's contact there (:func:`models.ball_equilibrium.equilibria`).

    An unloaded bearing has no stiffness, so the damped Newton iteration starts from the
    displacement the load gives a bearing whose balls are all compressed as much as the load
    would compress them (``Z K delta^1.5 = |F|``), with a damping of a hundredth of that
    bearing's stiffness.
    """
    # Force scale: the load, or the balls' preload from a negative clearance if larger.
    preload = ball_count * rings.constant * np.maximum(-rings.offset0, 0.0) ** 1.5
    magnitude = np.linalg.norm(load, axis=-1) + preload
    typical = (magnitude / (ball_count * rings.constant)) ** (1.0 / POINT_CONTACT_EXPONENT)
    damping = _START_DAMPING * POINT_CONTACT_EXPONENT * ball_count * rings.constant * np.sqrt(
        typical)
    # Unloaded points without preload (typical 0) stay centred.
    with np.errstate(all="ignore"):
        return rings.compiled.equilibria(
            rings.rings, np.ascontiguousarray(load), typical, damping,
            _RESIDUAL_TOLERANCE * magnitude, free, rings.jones, _MAX_ITERATIONS, rings.psi)


#: Points this process may compute with the interpreted equilibrium before it loads the
#: compiled one: about as long as numba takes to import and load it (benchmarks/RESULTS.md).
INTERPRETED_POINTS = 300
_EQUILIBRIUM = Kernels(f"{__package__}.ball_equilibrium", INTERPRETED_POINTS)
#: :mod:`models.ball_equilibrium` for a call of a number of points, compiled or interpreted.
_kernels = _EQUILIBRIUM.for_points
_interpreted_kernels = _EQUILIBRIUM.interpreted


def _fits(ball_count, pitch_diameter, ball_diameter):
    return elements_fit(ball_count, pitch_diameter, ball_diameter)


def _clearance_fits(clearance, ball_diameter, inner_curvature_ratio, outer_curvature_ratio,
                    contact_angle):
    distance = (inner_curvature_ratio + outer_curvature_ratio - 1.0) * ball_diameter
    return np.abs(clearance) < 2.0 * distance * np.cos(contact_angle)


def _no_load_on_held(fixed_dofs, axial_load, radial_load, radial_load_z, moment_y, moment_z):
    held = np.vectorize(lambda text: tuple(d in text.split() for d in DOFS), otypes=[bool] * 5)(
        np.asarray(fixed_dofs, dtype=object))
    loads = (axial_load, radial_load, radial_load_z, moment_y, moment_z)
    return functools.reduce(np.logical_and, [~h | (np.asarray(f) == 0)
                                             for h, f in zip(held, loads)])


def _something_free(fixed_dofs):
    """False where every displacement is held: there is nothing to solve."""
    return np.vectorize(lambda held: len(held.split()) < len(DOFS), otypes=[bool])(
        np.asarray(fixed_dofs, dtype=object))


def _fixed_angle_not_singular(geometry, fixed_dofs):
    """False where the fixed-angle geometry leaves a tilt free with the radial displacement
    that a tilt about the contact-cone apex goes with: such a stiffness is singular at every
    load (:func:`ball_5dof`, Notes)."""
    def regular(geometry, held):
        free = {dof for dof in DOFS if dof not in held.split()}
        return geometry != "fixed_angle" or not ({"tilt_y", "radial_z"} <= free
                                                 or {"tilt_z", "radial_y"} <= free)
    return np.vectorize(regular, otypes=[bool])(np.asarray(geometry, dtype=object),
                                                np.asarray(fixed_dofs, dtype=object))


#: The SI unit of each displacement of :data:`DOFS`, and of each entry of a stiffness matrix
#: over them.
DOF_UNITS = ("m", "m", "m", "rad", "rad")
# Entry (i, j) is dF_i/dq_j in SI; N*m/m is N. Stored so, the matrix is symmetric.
STIFFNESS_UNITS = tuple(
    tuple("N" if (load, dof) == ("N*m", "m") else f"{load}/{dof}" for dof in DOF_UNITS)
    for load in ("N", "N", "N", "N*m", "N*m"))

MODELS = [Model(
    name="ball_5dof",
    function=ball_5dof,
    summary="Ball bearing under axial, radial and moment loads: 5-DOF equilibrium of the inner "
            "ring, ball loads and contact angles, the full 5 x 5 stiffness matrix, contact "
            "pressures, lubricant film and rating lives (ISO/TS 16281, ISO 281).",
    reference="Paper 001, eq. 1-10; Jones (1960); Harris & Kotzalas, Rolling Bearing Analysis; "
              "ISO/TS 16281:2008; ISO 281:2007",
    version="11",
    inputs=(
        Input("ball_count", "1", "number of balls Z", kind="count", minimum=3, maximum=1000),
        Input("ball_diameter", "mm", "ball diameter D", minimum=0.0, exclusive_minimum=True),
        Input("pitch_diameter", "mm", "pitch diameter dm", minimum=0.0, exclusive_minimum=True),
        Input("contact_angle", "deg", "unloaded contact angle alpha0", minimum=0.0,
              maximum=80.0),
        Input("inner_curvature_ratio", "1", "inner groove radius / ball diameter fi",
              default=0.52, minimum=0.5, exclusive_minimum=True, maximum=1.0),
        Input("outer_curvature_ratio", "1", "outer groove radius / ball diameter fo",
              default=0.53, minimum=0.5, exclusive_minimum=True, maximum=1.0),
        Input("clearance", "mm", "diametral clearance Pd beyond contact at alpha0 (negative: "
              "preload)", default=0.0,
              label="diametral clearance"),
        Input("youngs_modulus", "GPa", "Young's modulus of balls and rings", default=207.0,
              minimum=SOFTEST_BEARING_SOLID, maximum=STIFFEST_SOLID),
        Input("poisson_ratio", "1", "Poisson's ratio of balls and rings", default=0.3,
              minimum=0.0, maximum=0.5),
        Input("contact_constant", "N/mm^1.5", "load-deflection constant K of a ball and both "
              "raceways, Q = K delta^1.5; default: Hertz, from the curvature ratios",
              default=None, minimum=0.0, exclusive_minimum=True,
              label="load-deflection constant K"),
        Input("axial_load", "N", "axial load Fx on the inner ring", default=0.0),
        Input("radial_load", "N", "radial load Fy on the inner ring", default=0.0),
        Input("radial_load_z", "N", "radial load Fz on the inner ring", default=0.0),
        Input("moment_y", "N*m", "moment My on the inner ring", default=0.0),
        Input("moment_z", "N*m", "moment Mz on the inner ring", default=0.0),
        Input("geometry", "", "jones: contact angles follow the displacement; fixed_angle: "
              "paper eq. 2-7 as printed", default="jones", kind="choice", choices=GEOMETRIES),
        Input("fixed_dofs", "", "displacements held at zero", default=(), kind="subset",
              choices=DOFS),
        Input("pressure_limit", "MPa", "contact pressure above which a point is out of "
              "validity (ISO 76: 4200 for ball bearings of through-hardened steel)",
              default=4200.0, minimum=0.0, exclusive_minimum=True,
              label="contact pressure limit"),
        SPEED_INPUT,
    ) + LIFE_INPUTS + FILM_INPUTS + STATIC_INPUTS + OPERATING_INPUTS
    + friction_inputs("angular_contact_ball"),
    outputs=(
        Output("displacement", "m, rad", "displacement of the inner ring", dims=("dof",),
               entry_units=DOF_UNITS,
               label="displacement of the inner ring"),
        Output("axial_displacement", "mm", "axial displacement of the inner ring"),
        Output("radial_displacement", "mm", "radial displacement of the inner ring (y-z)"),
        Output("stiffness_matrix", "N/m, N/rad, N, N*m/rad", "stiffness matrix "
               "dF_i/dq_j (eq. 9), in SI so that it is symmetric as stored",
               dims=("load_dof", "dof"), entry_units=STIFFNESS_UNITS,
               label="stiffness matrix"),
        Output("axial_stiffness", "N/mm", "axial stiffness dFx/d(delta_x) (eq. 10)"),
        Output("radial_stiffness", "N/mm", "radial stiffness dFy/d(delta_y) (eq. 10)"),
        Output("tilt_stiffness", "N*m/rad", "tilt stiffness dMy/d(phi_y) (eq. 10)"),
        Output("ball_load", "N", "contact load Q of each ball (eq. 1)", dims=("ball",)),
        Output("ball_contact_angle", "deg", "contact angle of each ball (of its line of "
               "groove centres when unloaded)", dims=("ball",)),
        Output("loaded_balls", "1", "number of balls carrying load", dtype="int"),
        Output("max_contact_pressure", "MPa", "maximum Hertz contact pressure p0 = 3Q/(2 pi a "
               "b) of each ball, the larger of its inner and outer contact", dims=("ball",),
               label="maximum contact pressure"),
        Output("largest_contact_pressure", "MPa", "largest maximum contact pressure of all "
               "balls", label="largest contact pressure"),
        # In SI: UDUNITS reads no fractional power of a prefixed unit such as mm^1.5.
        Output("hertz_contact_constant", "N/m^1.5", "load-deflection constant K that Hertz "
               "theory gives for the curvature ratios (eq. 4-5, series law corrected); "
               "Q = K delta^1.5, K in N/m^1.5",
               label="Hertz load-deflection constant K"),
    ) + film_outputs("every loaded ball's inner and outer contact (Hamrock and Dowson)")
    + static_outputs("ball") + operating_outputs() + friction_outputs()
    + life_outputs("ball loads, inner ring rotating", "X Fr + Y Fa (ISO 281 5.2, Table 3; "
                   "NaN under a moment, or with an axial load below 20 deg)"),
    dim_sizes={"ball": "ball_count", "dof": DOFS, "load_dof": DOFS},
    constraints=(
        Constraint(("ball_count", "pitch_diameter", "ball_diameter"), _fits,
                   "the balls do not fit on the pitch circle: pitch_diameter * sin(180 deg / "
                   "ball_count) must exceed ball_diameter"),
        Constraint(("clearance", "ball_diameter", "inner_curvature_ratio",
                    "outer_curvature_ratio", "contact_angle"), _clearance_fits,
                   "|clearance| must be below 2 (fi + fo - 1) D cos(alpha0), or the balls "
                   "leave their grooves"),
        Constraint(("fixed_dofs",) + _LOADS, _no_load_on_held,
                   "a load is given along a displacement held in fixed_dofs (axial_load, "
                   "radial_load, radial_load_z, moment_y, moment_z go with axial, radial_y, "
                   "radial_z, tilt_y, tilt_z)"),
        Constraint(("fixed_dofs",), _something_free,
                   "fixed_dofs holds all five displacements: nothing is left to solve; free "
                   "at least one"),
        Constraint(("geometry", "fixed_dofs"), _fixed_angle_not_singular,
                   "geometry 'fixed_angle' with tilt_y and radial_z free (or tilt_z and "
                   "radial_y) is singular at every load: a tilt about the contact-cone apex "
                   "with a radial shift changes no ball's approach; hold the tilts (fixed_dofs "
                   "= [\"tilt_y\", \"tilt_z\"]) or use geometry 'jones'"),
    ) + LIFE_CONSTRAINTS + operating_constraints("ball_diameter")
    + friction_constraints("angular_contact_ball"),
    # Measured by benchmarks/declared_costs.py. Compiled point by point, the model keeps few
    # temporaries: large blocks pay its per-call overhead seldom.
    seconds_per_point=8e-6,
    points_per_call=4096,
    validity="max_contact_pressure above pressure_limit (default 4200 MPa, ISO 76:2006: the "
             "contact stress of the "
             "static load rating of ball bearings, where raceways deform permanently by about "
             "1e-4 D; elastic Hertz theory no longer holds); a ball's approach (both contacts) "
             "above 1 % of the ball diameter D (Hertz theory needs contacts small against the "
             "ball); a ring displacement (translation, or tilt times R) beyond the groove-centre "
             "distance A = (fi + fo - 1) D, where the balls leave their grooves; a loaded ball "
             "whose contact angle has the opposite sign to a non-zero alpha0 (it runs on the "
             "side of the groove an angular-contact ring's low shoulder cuts away); a "
             "pressure_safety_factor below minimum_static_safety, where given; a tight fit "
             "lost at temperature and speed (the ring may creep). Not "
             "checked: the contact ellipse running over a groove shoulder (shoulder heights "
             "are not inputs); centrifugal and gyroscopic ball loads (a static model). "
             f"Whatever the outcome, inputs that describe no bearing: {SPEED_VALIDITY}; "
             f"{OIL_VALIDITY}; a given contact_constant with balls and rings whose E* = "
             "E / (2 (1 - nu^2)) lies more than 10 % from steel's (207 GPa, 0.3): the constant "
             "is taken as given, and paper 001's is for steel (leave it out to use Hertz's "
             "for the material).",
)]
