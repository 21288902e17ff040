"""Tapered roller bearing: load distribution under combined load, and the roller-end / rib
contact (paper 003).

Outer ring (cup) fixed; the inner ring (cone) is displaced radially by ``delta_r`` along the
radial load and axially by ``delta_a``; roller ``i`` sits at azimuth ``2 pi (i - 1) / Z`` from
the radial load, so roller 1 carries the most (the paper's Table 2 numbering).

The rib contact is drawn in the plane through the bearing axis and the most loaded roller,
in a frame on the inner raceway line: ``x`` along it towards the rib, ``y`` across it towards
the roller axis, origin at the roller's large-end corner. The roller is a cone of half angle
``phi`` whose large end, of diameter ``D_w1``, is a sphere of radius ``SR`` through the
large-end edge, centred on the roller axis; the rib is a cone of the inner ring whose
generatrix makes the rib angle ``Psi`` with the raceway line and meets it at ``A``; the oil
groove takes the first ``m`` of the rib from ``A``.
"""
from __future__ import annotations

import numpy as np

from .bearing_film import (FILM_INPUTS, MINERAL_OIL_DENSITY, bearing_film, film_outputs,
                           oil_viscosity)
from .bearing_life import (DEFAULT_CONTAMINATION_FACTOR, LIFE_CONSTRAINTS, LIFE_INPUTS,
                           SPEED_INPUT, life_outputs, rating_lives)
from .contact import (APPROACH_LIMIT, ROLLER_PRESSURE_LIMIT, STIFFEST_SOLID, effective_modulus,
                      hertz_point, line_contact_pressure)
from .friction import (bearing_friction, friction_constraints, friction_inputs,
                       friction_outputs)
from .geometry import elements_fit
from .kernels import Kernels
from .life import roller_bearing_reference_life, tapered_equivalent_load
from .limits import (OIL_VALIDITY, SOFTEST_BEARING_SOLID, SPEED_VALIDITY, STEEL_VALIDITY,
                     not_steel, outside_operation)
from .lubrication import (CELSIUS, MINERAL_OIL_PRESSURE_VISCOSITY, entrainment_speed,
                          line_contact_film, walther_viscosity)
from .operating_clearance import (BEARING_STEEL_EXPANSION, OPERATING_INPUTS,
                                  REFERENCE_TEMPERATURE, mounted_clearance,
                                  operating_constraints, operating_outputs)
from .registry import (CONVERGED, INFEASIBLE, NO_ROOT_IN_RANGE, NOT_CONVERGED,
                       OUT_OF_VALIDITY, Constraint, Input, Model, Output, below,
                       combine_status)
from .solvers import solve_increasing
from .static_safety import STATIC_INPUTS, roller_rating, static_outputs, static_safety

#: Load-deflection exponent of a roller between its raceways, Q = K delta^1.11 (eq. 13-18).
LOAD_EXPONENT = 1.11
RIB_FORCES = ("balance", "paper")
RIB_CURVATURES = ("exact", "paper")
_RESIDUAL_TOLERANCE = 1e-12  # relative to the load [-]
_LIMIT_BRACKET = (np.radians(80.0), np.radians(90.0))  # rib angles searched for the limit
_LIMIT_NODES = 41  # grid of the limit search: 0.25 deg steps
_ANGLE_TOLERANCE = 1e-9  # [rad], 0.0002 arcsec
_MAX_ITERATIONS = 200
#: Largest relative difference between the large-end diameter given and the one the roller's
#: cone has, ``D_w + l tan(phi)`` [-]: drawings round each to 0.01 mm (paper 003's roller:
#: 15.21 against 15.2134 mm, 0.02 %), and 0.5 % of D_w1 (0.08 mm there) moves its limit rib
#: angle by about 1', less than the 2' steps of the paper's sweep.
LARGE_END_TOLERANCE = 0.005
#: Points this process may compute with the interpreted equilibrium before it loads the
#: compiled one: about as long as numba takes to import and load it (benchmarks/RESULTS.md).
INTERPRETED_POINTS = 1000
#: :mod:`models.tapered_equilibrium` for a call of a number of points, compiled or interpreted
#: (the same numbers).
_EQUILIBRIUM = Kernels(f"{__package__}.tapered_equilibrium", INTERPRETED_POINTS)
_kernels = _EQUILIBRIUM.for_points


def paper_contact_constant(effective_length, roller_mean_diameter):
    """``K_ne = 2.89e4 l^0.82 D_w^0.11`` (paper 003 eq. 14; N, mm) in SI, [N/m^1.11].

    Parameters
    ----------
    effective_length, roller_mean_diameter : array_like
        ``l`` and ``D_w`` [m].
    """
    per_mm = 2.89e4 * (1e3 * np.asarray(effective_length)) ** 0.82 * (
        1e3 * np.asarray(roller_mean_diameter)) ** 0.11
    return per_mm * 1e3**LOAD_EXPONENT


def _roller_azimuths(roller_count):
    return 2.0 * np.pi * np.arange(roller_count) / roller_count


def cone_curvature_sum(roller_mean_diameter, pitch_diameter, contact_angle):
    """Curvature sum of a tapered roller on the cone (inner raceway), across the contact line.

    Parameters
    ----------
    roller_mean_diameter, pitch_diameter : array_like
        ``D_w``, ``d_m`` [m].
    contact_angle : array_like
        Angle of the raceway line to the bearing axis [rad].

    Returns
    -------
    numpy.ndarray
        ``sum(rho) = 2/D_w + 2 cos(a) / (d_m - D_w cos(a))`` [1/m]: the roller as a cylinder
        of its mean diameter, the cone by its radius of curvature across the generatrix,
        ``r / cos(a)`` with ``r = (d_m - D_w cos a)/2`` the raceway's radius at the middle
        of the contact (Meusnier: the normal's length to the axis).
    """
    cos_angle = np.cos(contact_angle)
    return 2.0 / np.asarray(roller_mean_diameter) + 2.0 * cos_angle / (
        np.asarray(pitch_diameter) - roller_mean_diameter * cos_angle)


#: The unmounted clearance of a single tapered roller bearing.
_CLEARANCE = Input("clearance", "mm", "diametral radial internal clearance at 20 degC, "
                   "unmounted (negative: preload); a single bearing's rollers carry the same "
                   "loads whatever it is, the cone moving on axially by (P_d / 2) cot(alpha)",
                   default=0.0, minimum=-1.0, maximum=1.0, label="clearance")


def _rings_hold_rollers(bore, outside_diameter, roller_mean_diameter, outer_contact_angle):
    """Where the rings' section has room for the rollers between them."""
    return (outside_diameter - bore
            > 2.0 * roller_mean_diameter * np.cos(outer_contact_angle))


def _raceways_known(pitch_diameter, shaft_fit, housing_fit, inner_ring_temperature,
                    outer_ring_temperature, bore, speed):
    """Where the operating clearance's inputs leave it the clearance, or the raceways are
    known."""
    quiet = ((shaft_fit == 0) & (housing_fit == 0)
             & (inner_ring_temperature == REFERENCE_TEMPERATURE)
             & (outer_ring_temperature == REFERENCE_TEMPERATURE)
             & ~(np.isfinite(bore) & (speed > 0)))
    return np.isfinite(pitch_diameter) | quiet


def _mounted(clearance, pitch, diameter, angle, speed, youngs_modulus, poisson_ratio,
             *operating):
    """The operating clearance (:func:`models.operating_clearance.mounted_clearance`) with
    the raceways at the rollers' middle, ``d_m -+ D cos(alpha)``. Without a pitch diameter the
    raceways are unknown, and nothing may act on the clearance (a ``ValueError`` says so)."""
    unknown = np.isnan(pitch)
    bore, outside = operating[2], operating[3]
    # With nothing acting, the changes are zero whatever the raceways: any inside the rings
    # stand in for unknown ones.
    stand_in = np.where(np.isfinite(bore) & np.isfinite(outside), 0.5 * (bore + outside),
                        np.where(np.isfinite(bore), bore + 3.0 * diameter,
                                 np.where(np.isfinite(outside), outside - 3.0 * diameter,
                                          10.0 * diameter)))
    middle = np.where(unknown, stand_in, pitch)
    offset = diameter * np.cos(angle)
    mounted = mounted_clearance(clearance, middle - offset, middle + offset, diameter, speed,
                                youngs_modulus, poisson_ratio, *operating)
    acting = ((mounted["clearance_change_fit"] != 0)
              | (mounted["clearance_change_temperature"] != 0)
              | (np.nan_to_num(mounted["clearance_change_speed"]) != 0))
    if np.any(unknown & acting):
        raise ValueError("the operating clearance of trb_load needs pitch_diameter: fits, "
                         "temperatures and speed change the raceways' diameters")
    return mounted


def trb_load(radial_load, axial_load, roller_count, effective_length, roller_mean_diameter,
             outer_contact_angle, contact_constant=None, pitch_diameter=None,
             youngs_modulus=206e9, poisson_ratio=0.3, pressure_limit=ROLLER_PRESSURE_LIMIT,
             speed=0.0, dynamic_load_rating=None, fatigue_load_limit=None,
             contamination_factor=DEFAULT_CONTAMINATION_FACTOR, oil_temperature=70.0 + CELSIUS,
             viscosity_40=None, viscosity_100=None, oil_density=MINERAL_OIL_DENSITY,
             pressure_viscosity=MINERAL_OIL_PRESSURE_VISCOSITY, composite_roughness=None,
             minimum_static_safety=None, friction_method="skf", lubrication_method="oil_bath",
             skf_rolling_constant_1=None, skf_rolling_constant_2=None,
             skf_sliding_constant_1=None, skf_sliding_constant_2=None,
             boundary_friction_coefficient=0.15, full_film_friction_coefficient=0.002,
             palmgren_speed_factor=None, palmgren_load_factor=None, oil_level=None,
             drag_loss_factor=None, bearing_width=None, clearance=0.0, shaft_fit=0.0,
             housing_fit=0.0, bore=None, outside_diameter=None, shaft_bore=0.0,
             housing_outside_diameter=None, inner_ring_temperature=REFERENCE_TEMPERATURE,
             outer_ring_temperature=REFERENCE_TEMPERATURE, shaft_temperature=None,
             housing_temperature=None, shaft_youngs_modulus=207e9, shaft_poisson_ratio=0.3,
             shaft_expansion=BEARING_STEEL_EXPANSION, housing_youngs_modulus=207e9,
             housing_poisson_ratio=0.3, housing_expansion=BEARING_STEEL_EXPANSION):
    """Displacements, roller loads, contact pressure, lubricant film, friction and rating
    life of a tapered roller bearing under combined load.

    Parameters
    ----------
    radial_load, axial_load : array_like
        ``F_r``, ``F_a`` [N] on the inner ring.
    roller_count : int
        ``Z``.
    effective_length, roller_mean_diameter : array_like
        ``l``, ``D_w`` [m] (enter only the default contact constant).
    outer_contact_angle : array_like
        ``alpha`` [rad], the cup's contact angle.
    contact_constant : array_like or None
        ``K_ne`` [N/m^1.11] of a roller between both raceways; None: eq. 14.
    pitch_diameter : array_like or None
        ``d_m`` [m], for the contact pressure only; None: the pressure is not computed (NaN).
    youngs_modulus, poisson_ratio : array_like
        Of rollers and rings [Pa], [-], for the contact pressure only.
    pressure_limit : array_like
        Contact pressure above which a point is ``out_of_validity`` [Pa] (default 4000 MPa,
        ISO 76's reference stress for roller bearings of through-hardened steel).
    speed : array_like
        Inner-ring speed [rad/s], for the lives in hours and the viscosity ratio only.
    dynamic_load_rating, fatigue_load_limit, contamination_factor, oil_temperature,
    viscosity_40, viscosity_100 : array_like or None
        ``C_r``, ``C_u`` [N], ``e_C`` [-], oil temperature [K], kinematic viscosities at 40
        and 100 deg C [m^2/s]; None: no life (no modified life, no film), NaN.
    oil_density, pressure_viscosity : array_like
        Of the oil at its temperature [kg/m^3], [1/Pa], for the film.
    composite_roughness : array_like or None
        ``sigma`` of rollers and raceways [m], for the film parameter; None: NaN.
    minimum_static_safety : array_like or None
        The smallest ``pressure_safety_factor`` the application needs [-]; None: no check.
    friction_method, lubrication_method, skf_rolling_constant_1, skf_rolling_constant_2,
    skf_sliding_constant_1, skf_sliding_constant_2, boundary_friction_coefficient,
    full_film_friction_coefficient, palmgren_speed_factor, palmgren_load_factor, oil_level,
    drag_loss_factor, bearing_width : str or array_like or None
        The friction torque's method and constants (:func:`models.friction.bearing_friction`,
        SKF's in its units; coefficients and factors [-]; lengths [m]), with
        ``Y = 0.4 cot(alpha)`` (ISO 281, Table 8); without bore and outside diameter, SKF's
        mean diameter is the pitch diameter and ``phi_rs = 1``.
    clearance : array_like
        Diametral radial clearance ``P_d`` [m], unmounted; negative for a preload.
    shaft_fit, housing_fit, bore, outside_diameter, shaft_bore, housing_outside_diameter,
    inner_ring_temperature, outer_ring_temperature, shaft_temperature, housing_temperature,
    shaft_youngs_modulus, shaft_poisson_ratio, shaft_expansion, housing_youngs_modulus,
    housing_poisson_ratio, housing_expansion : array_like or None
        The bearing as mounted, for its operating clearance
        (:func:`models.operating_clearance.operating_clearance`; lengths [m], temperatures
        [K], moduli [Pa], expansion coefficients [1/K]), with the raceways at the rollers'
        middle, ``d_m -+ D cos(alpha)``; they need ``pitch_diameter``. A single bearing's
        rollers carry the same loads whatever its clearance: each roller's gap along its
        contact normal, ``(P_d / 2) cos(alpha)``, is closed by the cone moving on axially by
        ``(P_d / 2) cot(alpha)``, which ``axial_displacement`` includes.

    Returns
    -------
    dict of numpy.ndarray
        ``radial_displacement`` ``delta_r``, ``axial_displacement`` ``delta_a`` [m],
        ``roller_load`` ``(N, Z)`` [N] (eq. 18 with its exponent 1.11), ``loaded_rollers``,
        ``max_contact_pressure`` ``(N, Z)`` [Pa], the films of
        :func:`models.bearing_film.bearing_film` [m, -], the static safety of
        :func:`models.static_safety.static_safety` [-] and ISO 76's rating of
        :func:`models.static_safety.roller_rating` [N, -] (all NaN without
        ``pitch_diameter``), the lives of
        :func:`models.bearing_life.rating_lives` [rad, s], ``status``: infeasible where
        ``F_r tan(alpha) > F_a`` (the rollers cannot carry the radial load without pulling)
        or ``F_a = 0``; not converged where the equilibrium was not found (or an input is
        NaN); out of validity as below.

    Notes
    -----
    Roller ``i`` is compressed by ``delta_r cos(psi_i) cos(alpha) + delta_a sin(alpha)``
    and carries ``Q_i = K_ne delta_i^1.11`` along the cup's normal; eq. 16 balances the sums
    of ``Q_i cos(alpha) cos(psi_i)`` and ``Q_i sin(alpha)`` with ``F_r`` and ``F_a``.

    The maximum contact pressure is the cone's (inner raceway): with one contact angle for
    both raceways, as eq. 13-18 take it, a roller carries its load ``Q`` on both, and the
    convex cone is the more curved of the two (:func:`cone_curvature_sum`). ``Q`` is spread
    evenly over ``l`` (the model has no crown or tilt) and ``p0 = (w E* sum(rho) / pi)^(1/2)``
    with ``w = Q / l`` (Hertz line contact, :func:`models.contact.line_contact_pressure`).
    The real cone carries ``Q (cos 2 phi + sin 2 phi cot Psi)`` (``trb_rib``'s
    ``inner_load``), 0.7 % less with paper 003's roller (``phi`` = 4 deg, ``Psi`` = 89 deg).

    Film (needs ``pitch_diameter``): each loaded roller's cone and cup contact by Pan and
    Hamrock's isothermal line-contact formulas (:func:`models.lubrication.line_contact_film`),
    the roller as a cylinder of its mean diameter carrying ``Q`` evenly over ``l`` at the
    cup's contact angle on both raceways, as the pressure takes it; ``R_x`` from
    :func:`cone_curvature_sum` (cone) and ``1 / (2/D_w - 2 cos(a) / (d_m + D_w cos a))``
    (cup), the entrainment speed of pure rolling with the inner ring turning
    (:func:`models.lubrication.entrainment_speed`), the oil's dynamic viscosity at its
    temperature and ``E' = 2 E*``.

    Life (inner ring rotating, loads stationary; needs ``pitch_diameter``): ISO/TS 16281's
    reference life of line contacts with each roller one lamina carrying ``Q`` on both
    raceways (the model has no crown or tilt, so the load is even along the roller, and the
    standard's laminae would all carry ``Q / n_s``, which gives the same life); the ratings
    at the cup's contact angle. ISO 281's equivalent load is
    :func:`models.life.tapered_equivalent_load`.

    Validity: a solved point is ``out_of_validity`` (values kept) where a roller's contact
    pressure exceeds ``pressure_limit`` (default 4000 MPa, ISO 76's reference stress for roller
    bearings, beyond which the permanent deformation exceeds 1e-4 of the roller diameter and
    the contact is no longer elastic; checked only with ``pitch_diameter``), or its compression
    exceeds 2 % of ``D_w``, where the fixed contact angle and azimuths of the model no longer
    hold, or the static safety lies below ``minimum_static_safety``; and, whatever the
    outcome, where the inputs describe no bearing: eq. 14's constant (fitted to steel) with ``youngs_modulus`` and ``poisson_ratio`` whose ``E*`` lies more
    than 10 % from steel's (:func:`models.limits.not_steel`), a speed factor ``n d_m`` above
    4e6 mm r/min or an oil whose viscosity index no lubricant has
    (:func:`models.limits.outside_operation`).

    References
    ----------
    .. [1] Paper 003, eq. 13-18 and Table 2.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), eq. 4.45.
    .. [3] ISO 76:2006, Rolling bearings - Static load ratings, 3.1.
    .. [4] ISO/TS 16281:2008, 5.3; ISO 281:2007, 7 and 9.3.
    """
    arrays = np.broadcast_arrays(*(np.atleast_1d(np.asarray(
        np.nan if a is None else a, dtype=float)) for a in (
            radial_load, axial_load, effective_length, roller_mean_diameter, outer_contact_angle,
            contact_constant, pitch_diameter, effective_modulus(youngs_modulus, poisson_ratio),
            pressure_limit, speed, dynamic_load_rating, fatigue_load_limit,
            contamination_factor, oil_temperature, viscosity_40, viscosity_100, oil_density,
            pressure_viscosity, composite_roughness, minimum_static_safety,
            skf_rolling_constant_1, skf_rolling_constant_2, skf_sliding_constant_1,
            skf_sliding_constant_2, boundary_friction_coefficient,
            full_film_friction_coefficient, palmgren_speed_factor, palmgren_load_factor,
            oil_level, drag_loss_factor, bearing_width, youngs_modulus, poisson_ratio,
            clearance, shaft_fit, housing_fit, bore, outside_diameter, shaft_bore,
            housing_outside_diameter, inner_ring_temperature, outer_ring_temperature,
            shaft_temperature, housing_temperature, shaft_youngs_modulus, shaft_poisson_ratio,
            shaft_expansion, housing_youngs_modulus, housing_poisson_ratio, housing_expansion)))
    radial, axial, length, diameter, angle, given, pitch, modulus, pressure_limit = arrays[:9]
    speed, life, oil, minimum_safety = arrays[9], arrays[10:16], arrays[16:19], arrays[19]
    friction = arrays[20:31]
    mounted = _mounted(arrays[33], pitch, diameter, angle, speed, *arrays[31:33],
                       *arrays[34:])
    fit_lost = mounted.pop("fit_lost")
    constant = np.where(np.isnan(given), paper_contact_constant(length, diameter), given)
    # Inputs that describe no bearing, whatever the outcome: eq. 14's steel constant with
    # other elastic constants, a speed or an oil no bearing runs with.
    no_bearing = (np.isnan(given) & not_steel(youngs_modulus, poisson_ratio)) \
        | outside_operation(speed, pitch, life[4], life[5])
    carried = _carried(radial, axial, angle)
    # Start from the axial displacement of eq. 15 (all rollers equally loaded by F_a) with
    # a radial shift that keeps every roller compressed.
    sin_angle = np.sin(angle)
    axial_start = (np.maximum(axial, 0.0) / (roller_count * constant * sin_angle
                                             ** (LOAD_EXPONENT + 1.0))) ** (1 / LOAD_EXPONENT)
    typical = LOAD_EXPONENT * roller_count * constant * axial_start ** (LOAD_EXPONENT - 1.0)
    with np.errstate(all="ignore"):  # IEEE results, as compiled
        displacement, converged, compression, roller_load = _kernels(radial.size).equilibria(
            np.ascontiguousarray(radial), np.ascontiguousarray(axial),  # owned: not views
            0.5 * axial_start * np.tan(angle), axial_start, 0.01 * typical,
            _RESIDUAL_TOLERANCE * np.hypot(radial, axial), np.cos(angle), sin_angle,
            constant, np.cos(_roller_azimuths(roller_count)), _MAX_ITERATIONS)
    pressure = line_contact_pressure(
        roller_load / length[:, None],
        cone_curvature_sum(diameter, pitch, angle)[:, None], modulus[:, None])
    converged &= np.isfinite(displacement).all(axis=-1) & np.isfinite(roller_load).all(axis=-1)
    static, unsafe = static_safety(pressure.max(axis=-1), "roller", minimum_safety)
    beyond = unsafe | ((pressure > pressure_limit[:, None])
              | (compression > APPROACH_LIMIT * diameter[:, None])).any(axis=-1)
    status = combine_status(
        np.select([~carried, ~converged], [INFEASIBLE, NOT_CONVERGED], CONVERGED),
        np.where((carried & converged & beyond) | no_bearing, OUT_OF_VALIDITY, CONVERGED))
    with np.errstate(divide="ignore", invalid="ignore"):
        reference_life = roller_bearing_reference_life(roller_load[..., None], life[0],
                                                       diameter, pitch, angle)
    outputs = {"radial_displacement": displacement[:, 0],
               "axial_displacement": displacement[:, 1], "roller_load": roller_load,
               "loaded_rollers": np.count_nonzero(compression > 0, axis=-1).astype(float),
               "max_contact_pressure": pressure,
               "largest_contact_pressure": pressure.max(axis=-1), **static,
               **roller_rating(roller_count, length, diameter, pitch, angle, radial, axial),
               **_film(roller_load, length, diameter, pitch, angle, modulus, speed, life, *oil),
               **rating_lives(reference_life, tapered_equivalent_load(radial, axial, angle),
                              "roller", speed, pitch, *life)}
    outputs.update(bearing_friction(
        "tapered_roller", friction_method, lubrication_method, speed, pitch, radial, axial,
        walther_viscosity(*life[3:]), dict(zip(("r1", "r2", "s1", "s2"), friction[:4])),
        *friction[4:8], outputs["static_equivalent_load"], *arrays[36:38],
        axial_load_factor=0.4 / np.tan(angle), oil_level=friction[8],
        drag_loss_factor=friction[9], bearing_width=friction[10]))
    # A clearance only moves the cone on axially: every roller's gap along its contact
    # normal, (P_d / 2) cos(alpha), is closed by delta_a sin(alpha), the loads unchanged.
    outputs["axial_displacement"] = (outputs["axial_displacement"]
                                     + 0.5 * mounted["operating_clearance"] / np.tan(angle))
    outputs.update(mounted)
    status = np.where(fit_lost, status | OUT_OF_VALIDITY, status)
    # A point without a solution has no values: NaN, not the iteration's last guess.
    solved = carried & converged
    outputs = {name: np.where(solved.reshape((-1,) + (1,) * (value.ndim - 1)), value, np.nan)
               for name, value in outputs.items()}
    return {**outputs, "status": status.astype(np.int8)}


class RollerEnd:
    """The most loaded roller's large end against the rib, in the raceway frame.

    All angles [rad] and lengths [m], arrays of the points.
    """

    def __init__(self, roller_large_diameter, roller_half_angle, roller_end_radius,
                 oil_groove_size, rib_diameter, inner_contact_angle, curvature_form="exact"):
        radius = 0.5 * roller_large_diameter
        self.large_diameter = roller_large_diameter
        self.end_radius, self.groove = roller_end_radius, oil_groove_size
        self.rib_diameter, self.inner_angle = rib_diameter, inner_contact_angle
        self.curvature_form = curvature_form
        # The end sphere passes through the large-end edge: its centre lies on the roller
        # axis sqrt(SR^2 - (D_w1/2)^2) behind the edge's plane.
        behind = np.sqrt(roller_end_radius**2 - radius**2)
        self.centre = np.stack([-radius * np.sin(roller_half_angle) - behind * np.cos(
            roller_half_angle), radius * np.cos(roller_half_angle) - behind * np.sin(
            roller_half_angle)], -1)

    def rib_distance(self, rib_angle, index=slice(None)):
        """``AE``: from the rib's foot on the raceway line to the contact point [m].

        The contact point is where the rib's normal passes through the sphere's centre,
        ``E = S + SR (sin Psi, cos Psi)``; ``AE = y_E / sin Psi``. ``index`` picks points.
        """
        height = self.centre[index, 1] + self.end_radius[index] * np.cos(rib_angle)
        return height / np.sin(rib_angle)

    def groove_distance(self, rib_angle, index=slice(None)):
        """``CE`` [m], the contact point's distance from the oil groove's edge (eq. 19)."""
        return self.rib_distance(rib_angle, index) - self.groove[index]

    def rib_curvature_radius(self, rib_angle, index=slice(None)):
        """The rib cone's radius of curvature at ``E`` across the generatrix, ``R_12`` [m].

        For a surface of revolution it is the length of the normal from ``E`` to the axis:
        ``r_E / cos(Psi - beta)``, ``r_E = d_i/2 + AE sin(Psi - beta)`` ('exact'). Eq. 6
        ('paper'), ``sqrt((d_i / (2 sin beta))^2 - AE^2)``, takes the normal from the foot of
        the rib along the raceway, as if the rib were square to it, and misses how the normal
        turns with the rib angle.
        """
        if self.curvature_form == "paper":
            return np.sqrt((0.5 * self.rib_diameter[index] / np.sin(self.inner_angle[index]))**2
                           - self.rib_distance(rib_angle, index)**2)
        tilt = rib_angle - self.inner_angle[index]
        radius = 0.5 * self.rib_diameter[index] + self.rib_distance(rib_angle, index) * np.sin(
            tilt)
        return radius / np.cos(tilt)


def _film(roller_load, length, diameter, pitch, angle, modulus, speed, life, oil_density,
          pressure_viscosity, roughness):
    """The film outputs of every roller's cone and cup contact (see :func:`trb_load`'s
    Notes)."""
    cos_angle = np.cos(angle)
    cup = 2.0 / diameter - 2.0 * cos_angle / (pitch + diameter * cos_angle)
    films = [line_contact_film(
        roller_load, length[:, None], 1.0 / curvature[:, None],
        entrainment_speed(speed, pitch, diameter, angle)[:, None],
        oil_viscosity(life[3], life[4], life[5], oil_density)[:, None],
        pressure_viscosity[:, None], 2.0 * modulus[:, None])
        for curvature in (cone_curvature_sum(diameter, pitch, angle), cup)]
    return bearing_film(np.concatenate([films[0][0], films[1][0]], axis=-1),
                        np.concatenate([films[0][1], films[1][1]], axis=-1), roughness)


def rib_contact_force(roller_load, rib_angle, roller_half_angle, inner_contact_angle,
                      form="balance"):
    """Rib load ``Q_r`` of a roller whose cup contact carries ``Q_e`` [N].

    'balance': the roller's force balance (eq. 10) with the rib normal at ``Psi`` to the
    raceway line, ``Q_r = Q_e sin(alpha - beta) / sin(Psi)``; 'paper': eq. 12 as printed,
    ``Q_e sin(2 phi) / sin(Psi - 2 beta)``. With ``alpha - beta = 2 phi`` the two differ only in
    the denominator: eq. 11 carries ``theta - beta`` where eq. 10 gives ``theta + beta``.
    """
    numerator = roller_load * np.sin(2.0 * roller_half_angle)
    if form == "paper":
        return numerator / np.sin(rib_angle - 2.0 * inner_contact_angle)
    return numerator / np.sin(rib_angle)


def trb_rib(radial_load, axial_load, roller_count, effective_length, roller_mean_diameter,
            outer_contact_angle, roller_large_diameter, roller_half_angle, roller_end_radius,
            rib_angle, oil_groove_size, rib_diameter, youngs_modulus=206e9, poisson_ratio=0.3,
            contact_constant=None, rib_force="balance", rib_curvature="exact"):
    """Hertz contact of the most loaded roller's spherical end with the conical rib.

    Parameters
    ----------
    radial_load, axial_load, roller_count, effective_length, roller_mean_diameter,
    outer_contact_angle, contact_constant
        As :func:`trb_load`, which gives the most loaded roller's cup load ``Q_e`` [N].
    roller_large_diameter, roller_half_angle, roller_end_radius : array_like
        ``D_w1`` [m], ``phi`` [rad], ``SR`` [m]. The inner raceway's contact angle is
        ``beta = alpha - 2 phi``.
    rib_angle : array_like
        ``Psi`` [rad], between the rib generatrix and the inner raceway line.
    oil_groove_size : array_like
        ``m`` [m], the part of the rib taken by the oil groove.
    rib_diameter : array_like
        ``d_i`` [m], the inner ring's diameter where the rib meets the raceway line.
    youngs_modulus, poisson_ratio : array_like
        Of rollers and ring [Pa], [-].
    rib_force : {'balance', 'paper'}
        See :func:`rib_contact_force`.
    rib_curvature : {'exact', 'paper'}
        See :meth:`RollerEnd.rib_curvature_radius`.

    Returns
    -------
    dict of numpy.ndarray
        ``rib_load`` [N]; ``semi_major``, ``semi_minor`` ``b``, ``approach`` [m];
        ``max_pressure`` [Pa]; ``groove_distance`` ``CE`` and ``edge_margin`` ``CE - b`` [m];
        ``limit_rib_angle`` [rad], where ``CE = b`` for the point's other inputs (NaN with
        ``status`` ``NO_ROOT_IN_RANGE`` when no angle in 80-90 deg is; see
        :func:`_limit_angle`); ``roller_load`` ``Q_e`` and ``inner_load`` ``Q_i`` [N];
        ``inner_load_offset`` [m], where along the inner contact (from its middle, towards
        the rib) ``Q_i`` must act for the roller's moment balance; ``rib_curvature_radius``
        [m]; ``status``.

    Notes
    -----
    The raceway loads come from :func:`trb_load` with the pitch diameter at the middle of
    the roller, ``d_m = d_i - l sin(beta) + D_w cos(beta)``, so its validity (the cone's
    pressure and the rollers' compression) holds here too. The rib contact is
    ``out_of_validity`` (values kept) where its maximum pressure exceeds 4000 MPa (ISO 76's
    reference stress for roller bearings), where :func:`models.contact.hertz_point` finds
    it beyond its own limits, or where the oil groove cuts the contact ellipse
    (``edge_margin`` < 0): Hertz's pressure assumes the whole ellipse on the rib, and the
    truncated one has an edge stress the model does not give.

    References
    ----------
    .. [1] Paper 003, eq. 1-12, 19-20 and section 3.
    """
    pitch_diameter = rib_pitch_diameter(rib_diameter, effective_length, roller_mean_diameter,
                                        outer_contact_angle, roller_half_angle)
    load = trb_load(radial_load, axial_load, roller_count, effective_length,
                    roller_mean_diameter, outer_contact_angle, contact_constant, pitch_diameter,
                    youngs_modulus, poisson_ratio)
    cup_load = load["roller_load"].max(axis=-1)
    arrays = np.broadcast_arrays(cup_load, *(np.atleast_1d(np.asarray(a, dtype=float)) for a in (
        outer_contact_angle, roller_large_diameter, roller_half_angle, roller_end_radius,
        rib_angle, oil_groove_size, rib_diameter, youngs_modulus, poisson_ratio,
        effective_length)))
    (cup_load, alpha, large_diameter, half_angle, end_radius, angle, groove, diameter,
     modulus, poisson, length) = arrays
    inner_angle = alpha - 2.0 * half_angle
    end = RollerEnd(large_diameter, half_angle, end_radius, groove, diameter, inner_angle,
                    rib_curvature)

    def contact(psi, index=slice(None)):
        """Rib load and Hertz contact at the rib angles ``psi`` of the points ``index``."""
        force = rib_contact_force(cup_load[index], psi, half_angle[index],
                                  inner_angle[index], rib_force)
        sphere = 1.0 / end_radius[index]
        return force, hertz_point(force, sphere, sphere,
                                  -1.0 / end.rib_curvature_radius(psi, index), 0.0,
                                  modulus[index], poisson[index])

    force, hertz = contact(angle)
    limit, limit_status = _limit_angle(end, contact)
    groove_distance = end.groove_distance(angle)
    inner_load, offset = _roller_balance(end, cup_load, force, angle, half_angle, length)
    outputs = {
        "rib_load": force, "semi_major": hertz["semi_major"], "semi_minor": hertz["semi_minor"],
        "approach": hertz["approach"], "max_pressure": hertz["max_pressure"],
        "groove_distance": groove_distance, "edge_margin": groove_distance - hertz["semi_minor"],
        "limit_rib_angle": limit,
        "roller_load": cup_load, "inner_load": inner_load, "inner_load_offset": offset,
        "rib_curvature_radius": end.rib_curvature_radius(angle),
    }
    # The rib contact's own validity: the roller bearings' ISO 76 pressure, and an ellipse
    # cut by the oil groove (its pressure is then no longer Hertz's: the paper's very limit).
    beyond = (hertz["max_pressure"] > ROLLER_PRESSURE_LIMIT) | (outputs["edge_margin"] < 0.0)
    rib_status = np.where(beyond, OUT_OF_VALIDITY, CONVERGED)
    status = combine_status(load["status"], hertz["status"], rib_status, limit_status)
    outputs["status"] = status.astype(np.int8)
    return outputs


def _limit_angle(end: RollerEnd, contact):
    """The rib angle at which the ellipse's edge reaches the groove, ``CE = b`` (eq. 20).

    The margin ``b - CE`` grows with the rib angle (the contact point moves towards the
    groove), but the roller end and the rib touch at a point only where the rib curves less
    than the end sphere (``R_12 > SR``), which may hold on part of the range alone: with
    ``SR`` = 107 mm the paper's bearing has no point contact below 80.5 deg. The margin is
    therefore first evaluated on a grid of ``_LIMIT_NODES`` rib angles; where the contact is
    not a point contact it stands at ``-CE``, the limit of a vanishing ellipse (``b -> 0`` as
    the rib's relative curvature vanishes). The first grid step where it turns from negative
    to positive brackets the limit, which safeguarded Newton steps then refine (the slope
    takes ``dCE/dPsi`` alone, which dominates; the bracket keeps the steps safe).

    Returns
    -------
    limit : numpy.ndarray
        [rad]; NaN where there is none in the range or the search failed.
    status : numpy.ndarray
        ``CONVERGED``, ``NO_ROOT_IN_RANGE`` (no rib angle of the range puts the ellipse's
        edge on the groove's edge), or ``NOT_CONVERGED`` (the refinement failed, or a margin
        on the grid could not be computed before any crossing was found).
    """
    count = end.end_radius.size
    nodes = np.linspace(*_LIMIT_BRACKET, _LIMIT_NODES)
    everything = np.arange(count)

    def margin(psi, index):
        _, hertz = contact(psi, index)
        # A rib that curves as much as the sphere or more: no point contact, no ellipse.
        width = np.where(hertz["status"] == INFEASIBLE, 0.0, hertz["semi_minor"])
        return width - end.groove_distance(psi, index), hertz["status"] == INFEASIBLE

    on_grid, _ = margin(np.tile(nodes, count), np.repeat(everything, nodes.size))
    on_grid = on_grid.reshape(count, nodes.size)
    # Only the nodes before a margin that could not be computed count: beyond it an earlier
    # crossing could hide.
    known = np.cumprod(np.isfinite(on_grid), axis=-1).astype(bool)
    rising = (on_grid[:, :-1] < 0.0) & (on_grid[:, 1:] >= 0.0) & known[:, 1:]
    found = rising.any(axis=-1)
    step = np.argmax(rising, axis=-1)
    lower, upper = nodes[step], nodes[step + 1]

    searched = np.flatnonzero(found)

    def residual(psi, entries):
        index = searched[entries]
        slope = (end.end_radius[index] + end.centre[index, 1] * np.cos(psi)) / np.sin(psi)**2
        return margin(psi, index)[0], slope

    angle = np.full(count, np.nan)
    converged = np.zeros(count, dtype=bool)
    angle[searched], converged[searched] = solve_increasing(
        residual, lower[searched], upper[searched], 0.5 * (lower[searched] + upper[searched]),
        _ANGLE_TOLERANCE)
    # A limit on the extension (no point contact there) is no limit: the ellipse vanished.
    point_contact = np.zeros(count, dtype=bool)
    if searched.size:
        point_contact[searched] = ~margin(angle[searched], searched)[1]
    limit = found & converged & point_contact
    computed = np.where(found, converged, known[:, -1])
    status = np.select([~computed, limit], [NOT_CONVERGED, CONVERGED], NO_ROOT_IN_RANGE)
    return np.where(limit, angle, np.nan), status.astype(np.int8)


def _roller_balance(end: RollerEnd, cup_load, rib_load, rib_angle, half_angle, length):
    """Inner raceway load of the roller and where it acts, from the roller's balance.

    Forces on the roller in the raceway frame: the cup's ``Q_e (sin 2phi, -cos 2phi)`` at the
    middle of the cup contact, the rib's ``Q_r (-sin Psi, -cos Psi)`` through the end sphere's
    centre, the cone's ``Q_i (0, 1)`` at ``x_i``. The ``y`` balance gives ``Q_i``; moments
    about the sphere's centre give ``x_i``, returned from the middle of the cone contact
    (``x = -l/2``; both contacts end at the large end).
    """
    inner_load = cup_load * np.cos(2.0 * half_angle) + rib_load * np.cos(rib_angle)
    large = end.large_diameter
    corner = np.stack([-large * np.sin(half_angle), large * np.cos(half_angle)], -1)
    direction = np.stack([np.cos(2.0 * half_angle), np.sin(2.0 * half_angle)], -1)
    cup_point = corner - 0.5 * length[:, None] * direction
    arm = cup_point - end.centre
    cup_moment = arm[:, 0] * (-cup_load * np.cos(2.0 * half_angle)) - arm[:, 1] * (
        cup_load * np.sin(2.0 * half_angle))
    position = end.centre[:, 0] - cup_moment / inner_load
    return inner_load, position + 0.5 * length


def _carried(radial_load, axial_load, outer_contact_angle):
    # F_r tan(alpha) = F_a written exactly is carried (the rollers opposite just unload),
    # whatever rounding the conversions of the loads and the angle left
    return (np.asarray(axial_load) > 0) & ~below(axial_load,
                                                 radial_load * np.tan(outer_contact_angle))


def _cone_beneath(pitch_diameter, roller_mean_diameter):
    return pitch_diameter > roller_mean_diameter


def _rollers_fit(roller_count, pitch_diameter, roller_mean_diameter):
    return elements_fit(roller_count, pitch_diameter, roller_mean_diameter)


def rib_pitch_diameter(rib_diameter, effective_length, roller_mean_diameter,
                       outer_contact_angle, roller_half_angle):
    """``d_m = d_i - l sin(beta) + D_w cos(beta)``, ``beta = alpha - 2 phi``: the pitch
    diameter at the middle of the roller, from the rib's foot on the raceway line (diameter
    ``d_i``) half the contact length down the cone, then half the roller across it."""
    inner_angle = np.asarray(outer_contact_angle) - 2.0 * np.asarray(roller_half_angle)
    return (np.asarray(rib_diameter) - np.asarray(effective_length) * np.sin(inner_angle)
            + np.asarray(roller_mean_diameter) * np.cos(inner_angle))


def _rib_rollers_fit(roller_count, rib_diameter, effective_length, roller_mean_diameter,
                     outer_contact_angle, roller_half_angle):
    return elements_fit(roller_count, rib_pitch_diameter(
        rib_diameter, effective_length, roller_mean_diameter, outer_contact_angle,
        roller_half_angle), roller_mean_diameter)


def _cone_angle_positive(outer_contact_angle, roller_half_angle):
    return 2.0 * np.asarray(roller_half_angle) < np.asarray(outer_contact_angle)


def _large_end_larger(roller_large_diameter, roller_mean_diameter):
    return np.asarray(roller_large_diameter) > np.asarray(roller_mean_diameter)


def _large_end_of_the_cone(roller_large_diameter, roller_mean_diameter, effective_length,
                           roller_half_angle):
    # Both contacts end at the large end (RollerEnd, _roller_balance): the cone of mean
    # diameter D_w in the middle of the contact widens to D_w + l tan(phi) there.
    cone = roller_mean_diameter + effective_length * np.tan(roller_half_angle)
    return np.abs(roller_large_diameter - cone) <= LARGE_END_TOLERANCE * roller_large_diameter


def _end_sphere_fits(roller_end_radius, roller_large_diameter):
    return roller_end_radius > roller_large_diameter / 2


_CARRIED = Constraint(("radial_load", "axial_load", "outer_contact_angle"), _carried,
                      "a single tapered roller bearing needs axial_load > 0 and radial_load * "
                      "tan(outer_contact_angle) <= axial_load, or its rollers would pull")
_LOAD_INPUTS = (
    Input("radial_load", "N", "radial load Fr on the inner ring", minimum=0.0),
    Input("axial_load", "N", "axial load Fa on the inner ring", minimum=0.0,
          exclusive_minimum=True),
    Input("roller_count", "1", "number of rollers Z", kind="count", minimum=3, maximum=1000),
    Input("effective_length", "mm", "effective roller length l", minimum=0.0,
          exclusive_minimum=True),
    Input("roller_mean_diameter", "mm", "mean roller diameter Dw", minimum=0.0,
          exclusive_minimum=True),
    Input("outer_contact_angle", "deg", "cup contact angle alpha", minimum=0.0,
          exclusive_minimum=True, maximum=60.0),
)
_CONSTANT = Input("contact_constant", "N/mm^1.11", "load-deflection constant Kne of a roller, "
                  "Q = Kne delta^1.11; default eq. 14, 2.89e4 l^0.82 Dw^0.11 (N, mm)",
                  default=None, minimum=0.0, exclusive_minimum=True)
_MODULUS = Input("youngs_modulus", "GPa", "Young's modulus of rollers and rings", default=206.0,
                 minimum=SOFTEST_BEARING_SOLID, maximum=STIFFEST_SOLID)
_POISSON = Input("poisson_ratio", "1", "Poisson's ratio of rollers and rings", default=0.3,
                 minimum=0.0, maximum=0.5)
_REFERENCE = "Paper 003, Optimization of the rib angle of tapered roller bearings"

MODELS = [
    Model(
        name="trb_load",
        function=trb_load,
        summary="Tapered roller bearing under radial and axial load: radial and axial "
                "displacement, the load of every roller, contact pressure, lubricant film and "
                "rating lives.",
        reference=_REFERENCE + ", eq. 13-18",
        version="10",
        inputs=_LOAD_INPUTS + (
            _CONSTANT,
            Input("pitch_diameter", "mm", "pitch diameter dm at the middle of the rollers, for "
                  "the contact pressure only; default: no pressure (NaN)", default=None,
                  minimum=0.0, exclusive_minimum=True),
            _MODULUS, _POISSON,
            Input("pressure_limit", "MPa", "contact pressure above which a point is out of "
                  "validity (ISO 76: 4000 for roller bearings of through-hardened steel)",
                  default=4000.0, minimum=0.0, exclusive_minimum=True,
                  label="contact pressure limit"),
            SPEED_INPUT) + LIFE_INPUTS + FILM_INPUTS + STATIC_INPUTS
        + friction_inputs("tapered_roller") + (_CLEARANCE,) + OPERATING_INPUTS,
        outputs=(
            Output("radial_displacement", "mm", "radial displacement delta_r of the inner ring",
                   label="radial displacement"),
            Output("axial_displacement", "mm", "axial displacement delta_a of the inner ring",
                   label="axial displacement"),
            Output("roller_load", "N", "cup contact load Qe of each roller (eq. 18); roller 1 "
                   "on the radial load", dims=("roller",)),
            Output("loaded_rollers", "1", "number of rollers carrying load", dtype="int"),
            Output("max_contact_pressure", "MPa", "Hertz line-contact pressure of each roller "
                   "on the cone (inner raceway, the more curved), its load Qe spread over l; "
                   "NaN without pitch_diameter", dims=("roller",),
                   label="maximum contact pressure"),
            Output("largest_contact_pressure", "MPa", "largest maximum contact pressure of "
                   "all rollers (NaN without pitch_diameter)",
                   label="largest contact pressure"),
        ) + film_outputs("every loaded roller's cone and cup contact (Pan and Hamrock's line "
                         "contact); NaN without pitch_diameter") + static_outputs("roller")
        + friction_outputs() + operating_outputs()
        + life_outputs("roller loads (one lamina each), inner ring rotating; NaN without "
                         "pitch_diameter", "ISO 281 Table 8, P = Fr for Fa/Fr <= 1.5 tan(alpha), "
                         "else 0.4 Fr + 0.4 cot(alpha) Fa"),
        dim_sizes={"roller": "roller_count"},
        constraints=(_CARRIED, Constraint(
            ("pitch_diameter", "roller_mean_diameter"), _cone_beneath,
            "pitch_diameter must exceed roller_mean_diameter"), Constraint(
            ("roller_count", "pitch_diameter", "roller_mean_diameter"), _rollers_fit,
            "the rollers do not fit on the pitch circle: pitch_diameter * sin(180 deg / "
            "roller_count) must exceed roller_mean_diameter"), Constraint(
            ("bore", "outside_diameter", "roller_mean_diameter", "outer_contact_angle"),
            _rings_hold_rollers, "outside_diameter - bore must exceed the rollers' radial "
            "extent twice, 2 roller_mean_diameter cos(outer_contact_angle)")) + LIFE_CONSTRAINTS
        + friction_constraints("tapered_roller")
        + operating_constraints("roller_mean_diameter", "outer_contact_angle") + (Constraint(
            ("pitch_diameter", "shaft_fit", "housing_fit", "inner_ring_temperature",
             "outer_ring_temperature", "bore", "speed"), _raceways_known,
            "the operating clearance needs pitch_diameter: fits, ring temperatures other "
            "than 20 degC, and speed with a bore change the raceways' diameters",
            unset=True),),
        # Measured by benchmarks/declared_costs.py; solved point by point, large blocks share
        # the per-call cost of the outputs' numpy and unit conversions
        # (benchmarks/trb_load_kernel.py, benchmarks/RESULTS.md).
        seconds_per_point=5e-6,
        points_per_call=4096,
        validity="a roller's cone contact pressure above pressure_limit (default 4000 MPa, "
                 "ISO 76's reference stress for roller bearings; checked when pitch_diameter "
                 "is given) or its compression above 2 % of the mean roller diameter; a "
                 "pressure_safety_factor below minimum_static_safety, where given; "
                 "whatever the outcome, inputs that describe no bearing: "
                 f"{STEEL_VALIDITY} (eq. 14's constant); {SPEED_VALIDITY} (with "
                 f"pitch_diameter); {OIL_VALIDITY}",
    ),
    Model(
        name="trb_rib",
        function=trb_rib,
        summary="Tapered roller bearing: Hertz contact of the most loaded roller's spherical end "
                "with the conical rib, its distance from the oil groove, and the rib angle at "
                "which the contact ellipse reaches the groove.",
        reference=_REFERENCE + ", eq. 1-12, 19-20",
        version="4",
        inputs=_LOAD_INPUTS + (
            Input("roller_large_diameter", "mm", "large-end roller diameter Dw1", minimum=0.0,
                  exclusive_minimum=True),
            Input("roller_half_angle", "deg", "roller half cone angle phi", minimum=0.0,
                  exclusive_minimum=True, maximum=20.0),
            Input("roller_end_radius", "mm", "radius SR of the roller's spherical end",
                  minimum=0.0, exclusive_minimum=True),
            Input("rib_angle", "deg", "rib angle Psi between rib generatrix and inner raceway",
                  minimum=80.0, maximum=90.0, exclusive_minimum=True,
                  label="rib angle"),
            Input("oil_groove_size", "mm", "oil groove size m along the rib", minimum=0.0),
            Input("rib_diameter", "mm", "inner ring diameter di where the rib meets the raceway "
                  "line", minimum=0.0, exclusive_minimum=True,
                  label="rib diameter di"),
            _MODULUS, _POISSON,
            _CONSTANT,
            Input("rib_force", "", "balance: the roller's force balance (eq. 10); paper: "
                  "eq. 12 as printed", default="balance", kind="choice", choices=RIB_FORCES),
            Input("rib_curvature", "", "exact: the rib's radius of curvature across its "
                  "generatrix from the geometry; paper: eq. 6", default="exact",
                  kind="choice", choices=RIB_CURVATURES),
        ),
        outputs=(
            Output("rib_load", "N", "rib contact load Qr"),
            Output("semi_major", "mm", "semi-major axis a of the rib contact ellipse",
                   label="semi-major axis a"),
            Output("semi_minor", "mm", "semi-minor axis b of the rib contact ellipse",
                   label="semi-minor axis b"),
            Output("approach", "mm", "approach delta of roller end and rib"),
            Output("max_pressure", "MPa", "maximum rib contact pressure p0"),
            Output("groove_distance", "mm", "distance CE of the contact point from the oil "
                   "groove's edge (eq. 19)",
                   label="distance CE to the oil groove"),
            Output("edge_margin", "mm", "CE - b: negative where the ellipse is cut by the "
                   "groove (eq. 20)",
                   label="edge margin CE - b"),
            Output("limit_rib_angle", "deg", "rib angle at which CE = b for the other inputs",
                   label="limit rib angle"),
            Output("roller_load", "N", "cup load Qe of the most loaded roller"),
            Output("inner_load", "N", "inner raceway load Qi of that roller"),
            Output("inner_load_offset", "mm", "where Qi acts for the roller's moment balance, "
                   "from the middle of the contact towards the rib",
                   label="inner load offset"),
            Output("rib_curvature_radius", "mm", "rib radius of curvature R12 at the contact",
                   label="rib radius of curvature R12"),
        ),
        constraints=(_CARRIED, Constraint(
            ("roller_end_radius", "roller_large_diameter"), _end_sphere_fits,
            "roller_end_radius must exceed half the roller_large_diameter"), Constraint(
            ("outer_contact_angle", "roller_half_angle"), _cone_angle_positive,
            "roller_half_angle must be below half the outer_contact_angle: the cone's "
            "raceway angle beta = alpha - 2 phi is positive in a tapered roller bearing"),
            Constraint(("roller_large_diameter", "roller_mean_diameter"), _large_end_larger,
                       "roller_large_diameter must exceed roller_mean_diameter: the large "
                       "end is the larger"),
            Constraint(("roller_large_diameter", "roller_mean_diameter", "effective_length",
                        "roller_half_angle"), _large_end_of_the_cone,
                       "roller_large_diameter must be the large end of the roller's cone, "
                       "roller_mean_diameter + effective_length * tan(roller_half_angle), "
                       "within 0.5 %: the model takes both raceway contacts to end at the "
                       "large end (paper 003: 13.71 + 21.5 tan 4 deg = 15.21 mm)"),
            Constraint(("roller_count", "rib_diameter", "effective_length",
                        "roller_mean_diameter", "outer_contact_angle", "roller_half_angle"),
                       _rib_rollers_fit, "the rollers do not fit on the pitch circle "
                       "(d_i - l sin(beta) + D_w cos(beta)): its chord between neighbours, "
                       "d_m sin(180 deg / roller_count), must exceed roller_mean_diameter")),
        seconds_per_point=3.7e-4,  # measured by benchmarks/declared_costs.py
        points_per_call=2000,
        validity="trb_load's limits for the raceways (pitch diameter from rib_diameter; its "
                 "steel constant with other elastic constants included); the "
                 "rib contact's pressure above 4000 MPa (ISO 76, roller bearings), an ellipse "
                 "cut by the oil groove (edge_margin < 0), or hertz_point's limits",
    ),
]
