"""Rating life of rolling bearings: ISO 281 [ISO281]_ from an equivalent load, ISO/TS 16281
[TS16281]_ from the rolling-element loads a model computes, and the life modification factor
a_ISO.

Shared by every model that loads rolling elements. Element loads are arrays whose last axis
runs over the rolling elements (balls), or whose last two axes run over the rolling elements
and the laminae (slices) of each roller, ``(..., Z, n_s)``; everything else broadcasts over
the leading axes, so a chunk of grid points is one call. SI units throughout (N, m, m^2/s,
rad/s, s); lives are in millions of revolutions, the unit in which both standards state them.

References
----------
.. [ISO281] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life.
.. [TS16281] ISO/TS 16281:2008, Rolling bearings - Methods for calculating the modified
   reference rating life for universally loaded bearings.
"""
from __future__ import annotations

import numpy as np

from .registry import below

KINDS = ("ball", "roller")
RINGS = ("inner", "outer")

# ISO 281: L10 = (C/P)^p, p = 3 for ball, 10/3 for roller bearings (5.3, 7.3).
LIFE_EXPONENT = {"ball": 3.0, "roller": 10.0 / 3.0}

# ISO/TS 16281 4.3.2 (balls) and 5.3.3 (laminae): the equivalent load of the ring that rotates
# against the load is the mean of the element loads to the power 3 (ball) or 4 (line contact);
# the stationary ring, whose most loaded point stays in the load zone, takes 10/3 and 9/2.
ROTATING_EXPONENT = {"ball": 3.0, "roller": 4.0}
STATIONARY_EXPONENT = {"ball": 10.0 / 3.0, "roller": 4.5}

# Lundberg-Palmgren ratios J_r/J_1 and J_r/J_2 of the radial load integral to the rotating and
# stationary ring's mean-load integrals at the rating load zone (epsilon = 0.5): they turn the
# bearing's C_r into the load a rolling element can carry for 1e6 revolutions on each ring.
BALL_RATING_RATIO = {"inner": 0.407, "outer": 0.389}  # ISO/TS 16281 eq. (19)-(20)
ROLLER_RATING_RATIO = {"inner": 0.378, "outer": 0.364}  # ISO/TS 16281 eq. (47)-(48)
ROLLER_REDUCTION_FACTOR = 0.83  # lambda nu of radial roller bearings, ISO/TS 16281 eq. (49)

# ISO 281 9.3.3: a_ISO is bounded, and kappa above 4 counts as 4; below 0.1 not covered.
LIFE_MODIFICATION_CAP = 50.0
VISCOSITY_RATIO_RANGE = (0.1, 4.0)


def _check_kind(kind):
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, not {kind!r}")


def _check_ring(rotating_ring):
    if rotating_ring not in RINGS:
        raise ValueError(f"rotating_ring must be one of {RINGS}, not {rotating_ring!r}")


def basic_rating_life(dynamic_load_rating, equivalent_load, kind="ball"):
    """ISO 281 basic rating life ``L10 = (C / P)^p``.

    Parameters
    ----------
    dynamic_load_rating : array_like
        Basic dynamic load rating ``C`` (radial ``C_r`` or axial ``C_a``) [N].
    equivalent_load : array_like
        Dynamic equivalent load ``P`` of the same direction [N].
    kind : {'ball', 'roller'}
        Life exponent ``p``: 3 for ball, 10/3 for roller bearings.

    Returns
    -------
    numpy.ndarray
        ``L10`` [10^6 revolutions]; infinite where ``P = 0``.

    References
    ----------
    .. [1] ISO 281:2007, 5.3 (eq. for radial ball bearings) and 7.3 (radial roller bearings).
    """
    _check_kind(kind)
    with np.errstate(divide="ignore"):
        ratio = np.asarray(dynamic_load_rating, dtype=float) / np.asarray(equivalent_load,
                                                                          dtype=float)
    return ratio ** LIFE_EXPONENT[kind]


#: ISO 281:2007, Table 3: single-row angular contact ball bearings with Fa/Fr > e, by nominal
#: contact angle: (alpha [deg], e, X, Y); at or below e, X = 1 and Y = 0. The rows of 25, 30
#: and 40 deg as reproduced by NTN-SNR's catalogue pages (eshop.ntn-snr.com, "Coefficients
#: Industrie ACBB" and "HPACBB") and LYC's (lycbearing.com, "Equivalent dynamic load -
#: angular contact ball bearings"); those of 20, 35 and 45 deg from ISO 281:2007 Table 3
#: itself (no reproduction of them was found to check them against).
ANGULAR_CONTACT_FACTORS = np.array([
    (20.0, 0.57, 0.43, 1.00),
    (25.0, 0.68, 0.41, 0.87),
    (30.0, 0.80, 0.39, 0.76),
    (35.0, 0.95, 0.37, 0.66),
    (40.0, 1.14, 0.35, 0.57),
    (45.0, 1.34, 0.33, 0.50),
])
_ANGLE_ROUNDING = 1e-9  # [deg]: 20 deg given in radians and read back in degrees


def radial_ball_equivalent_load(radial_load, axial_load, contact_angle, moment_load=0.0):
    """ISO 281 dynamic equivalent radial load ``P = X F_r + Y F_a`` of a single-row radial
    ball bearing.

    ``P = F_r`` where ``F_a / F_r <= e``; above, ``X``, ``Y`` and ``e`` of the nominal contact
    angle from ISO 281's Table 3 (:data:`ANGULAR_CONTACT_FACTORS`), interpolated linearly in
    the angle between the tabulated 20, 25, 30, 35, 40 and 45 deg (the standard tabulates
    those angles only). A pure axial load (``F_r = 0``) is beyond ``e``: ``P = Y F_a``.

    Parameters
    ----------
    radial_load : array_like
        ``F_r`` [N], the magnitude of the radial load (its sign is ignored).
    axial_load : array_like
        ``F_a`` [N] (its sign is ignored).
    contact_angle : array_like
        Nominal contact angle ``alpha`` [rad].
    moment_load : array_like
        Magnitude of a tilting moment on the bearing [N m]; ISO 281's equivalent load holds
        radial and axial loads only.

    Returns
    -------
    numpy.ndarray
        ``P`` [N]. NaN where the standard gives no value from these inputs: a non-zero
        ``moment_load``; a contact angle above 45 deg (thrust bearings); an axial load with a
        contact angle below 20 deg (deep-groove bearings and angular contact ones of 5 to 15
        deg), whose ``e`` and ``Y`` depend on ``f_0 F_a / C_0r`` and so on the static load
        rating, not an input here (without axial load ``P = F_r`` for them too).

    References
    ----------
    .. [1] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life, 5.2
       (dynamic equivalent radial load of radial ball bearings) and Table 3 (factors X, Y
       and e).
    """
    radial = np.abs(np.asarray(radial_load, dtype=float))
    axial = np.abs(np.asarray(axial_load, dtype=float))
    degrees = np.degrees(np.asarray(contact_angle, dtype=float))
    angles, limit, radial_factor, axial_factor = ANGULAR_CONTACT_FACTORS.T
    # F_a / F_r > e (F_r = 0 too); F_a / F_r = e written exactly stays at e whatever rounding
    # the loads' and the angle's conversions left
    beyond = below(np.interp(degrees, angles, limit) * radial, axial)
    load = np.where(beyond, np.interp(degrees, angles, radial_factor) * radial
                    + np.interp(degrees, angles, axial_factor) * axial, radial)
    tabulated = ((degrees >= angles[0] - _ANGLE_ROUNDING)
                 | ((degrees >= 0.0) & (axial == 0.0)))
    known = tabulated & (degrees <= angles[-1] + _ANGLE_ROUNDING) & (
        np.asarray(moment_load, dtype=float) == 0.0)
    return np.where(known, load, np.nan)


def life_duration(life, speed):
    """Time a life lasts at a constant speed.

    Parameters
    ----------
    life : array_like
        Rating life [10^6 revolutions].
    speed : array_like
        Speed of the rotating ring relative to the stationary one [rad/s].

    Returns
    -------
    numpy.ndarray
        Duration [s] (``/ 3600`` gives ISO 281's ``L10h`` in hours); infinite at rest.
    """
    with np.errstate(divide="ignore"):
        return np.asarray(life, dtype=float) * 1e6 * 2.0 * np.pi / np.abs(speed)


def tapered_equivalent_load(radial_load, axial_load, contact_angle):
    """ISO 281 dynamic equivalent radial load of a single-row tapered roller bearing.

    ``P = F_r`` for ``F_a / F_r <= e``, else ``P = 0.4 F_r + 0.4 cot(alpha) F_a``, with
    ``e = 1.5 tan(alpha)``.

    Parameters
    ----------
    radial_load, axial_load : array_like
        ``F_r``, ``F_a`` [N] (the axial load's magnitude counts).
    contact_angle : array_like
        Nominal contact angle ``alpha`` [rad] (the cup's).

    Returns
    -------
    numpy.ndarray
        ``P`` [N].

    References
    ----------
    .. [1] ISO 281:2007, 7.2, Table 8 (radial roller bearings with ``alpha != 0``, single
       row: ``X = 0.4``, ``Y = 0.4 cot(alpha)``, ``e = 1.5 tan(alpha)``).
    """
    radial = np.abs(np.asarray(radial_load, dtype=float))
    axial = np.abs(np.asarray(axial_load, dtype=float))
    tangent = np.tan(contact_angle)
    return np.where(axial <= 1.5 * tangent * radial, radial,
                    0.4 * radial + 0.4 / tangent * axial)


def reference_viscosity(speed, pitch_diameter):
    """Reference kinematic viscosity ``nu_1`` for adequate lubrication (ISO 281).

    ``nu_1 = 45000 n^-0.83 d_m^-0.5`` for ``n < 1000`` r/min and ``4500 n^-0.5 d_m^-0.5``
    above, with ``n`` in r/min, ``d_m`` in mm and ``nu_1`` in mm^2/s (converted here).

    Parameters
    ----------
    speed : array_like
        Speed of the rotating ring [rad/s] (its magnitude counts).
    pitch_diameter : array_like
        Mean diameter ``d_m`` [m].

    Returns
    -------
    numpy.ndarray
        ``nu_1`` [m^2/s]; infinite at rest.

    References
    ----------
    .. [1] ISO 281:2007, 9.3.3, eq. (28)-(29) (the equations of its Figure 6).
    """
    rpm = np.abs(np.asarray(speed, dtype=float)) * 60.0 / (2.0 * np.pi)
    millimetres = np.asarray(pitch_diameter, dtype=float) * 1e3
    with np.errstate(divide="ignore"):
        slow = 45000.0 * rpm**-0.83 * millimetres**-0.5
        fast = 4500.0 * rpm**-0.5 * millimetres**-0.5
    # "1000 rpm" comes back from rad/s as 999.9999999999999: it takes the standard's n >= 1000
    return np.where(below(rpm, 1000.0), slow, fast) * 1e-6


def viscosity_ratio(viscosity, speed, pitch_diameter):
    """Viscosity ratio ``kappa = nu / nu_1`` (ISO 281:2007, 9.3.3, eq. (27)).

    Parameters
    ----------
    viscosity : array_like
        Kinematic viscosity of the oil at operating temperature [m^2/s], for example from
        :func:`models.lubrication.walther_viscosity`.
    speed, pitch_diameter : array_like
        As for :func:`reference_viscosity` [rad/s], [m].

    Returns
    -------
    numpy.ndarray
        ``kappa`` [-]; zero at rest.
    """
    return np.asarray(viscosity, dtype=float) / reference_viscosity(speed, pitch_diameter)


def life_modification_factor(viscosity_ratio, contamination_factor, fatigue_load_limit,
                             equivalent_load, kind="ball"):
    """ISO 281 life modification factor ``a_ISO`` for the systems approach.

    With ``x = e_C C_u / P`` and ``kappa`` limited to 4:

    - ball bearings: ``a_ISO = 0.1 [1 - (2.5671 - c / kappa^q)^0.83 x^(1/3)]^-9.3``,
    - roller bearings: ``a_ISO = 0.1 [1 - (1.5859 - c / kappa^q) x^0.4]^-9.185``,

    with ``(c, q)`` = (2.2649, 0.054381) ball, (1.3993, 0.054381) roller for
    ``0.1 <= kappa < 0.4``; (1.9987, 0.19087) ball, (1.2348, 0.19087) roller for
    ``0.4 <= kappa < 1``; (1.9987, 0.071739) ball, (1.2348, 0.071739) roller for
    ``1 <= kappa <= 4``. The two pieces of each kind meet at ``kappa = 0.4`` and ``1``.

    Parameters
    ----------
    viscosity_ratio : array_like
        ``kappa = nu / nu_1`` [-] (:func:`viscosity_ratio`).
    contamination_factor : array_like
        ``e_C`` [-], 0 to 1 (ISO 281 Table 13; 1 for extreme cleanliness).
    fatigue_load_limit : array_like
        ``C_u`` [N] (ISO 281 Annex B or the manufacturer's value).
    equivalent_load : array_like
        ``P`` [N]: the dynamic equivalent load for ``L10m``, the dynamic equivalent reference
        load (:func:`equivalent_reference_load`) for ``L10rm``.
    kind : {'ball', 'roller'}

    Returns
    -------
    numpy.ndarray
        ``a_ISO`` [-], at most 50 (also where the bracket is no longer positive, the limit of
        the formula as ``x`` grows); NaN where ``kappa < 0.1``, outside the standard's range.
        Not applied: the standard's option for EP additives (``kappa < 1``, ``e_C >= 0.2``).

    References
    ----------
    .. [1] ISO 281:2007, 9.3.3, eq. (31)-(33) (radial ball bearings) and (34)-(36) (radial
       roller bearings); the cap at 50 and the limit ``kappa <= 4``, 9.3.3.
    """
    _check_kind(kind)
    kappa = np.minimum(np.asarray(viscosity_ratio, dtype=float), VISCOSITY_RATIO_RANGE[1])
    load_ratio = (np.asarray(contamination_factor, dtype=float)
                  * np.asarray(fatigue_load_limit, dtype=float)
                  / np.asarray(equivalent_load, dtype=float))
    low, middle = kappa < 0.4, kappa < 1.0
    exponent = np.where(low, 0.054381, np.where(middle, 0.19087, 0.071739))
    with np.errstate(divide="ignore", invalid="ignore"):
        if kind == "ball":
            coefficient = np.where(low, 2.2649, 1.9987)
            bracket = 1.0 - (2.5671 - coefficient / kappa**exponent) ** 0.83 * np.cbrt(load_ratio)
            power = -9.3
        else:
            coefficient = np.where(low, 1.3993, 1.2348)
            bracket = 1.0 - (1.5859 - coefficient / kappa**exponent) * load_ratio**0.4
            power = -9.185
        factor = np.where(bracket > 0.0, 0.1 * np.abs(bracket) ** power, np.inf)
    factor = np.minimum(factor, LIFE_MODIFICATION_CAP)
    usable = (kappa >= VISCOSITY_RATIO_RANGE[0]) & np.isfinite(load_ratio) & (load_ratio >= 0.0)
    return np.where(usable, factor, np.nan)


def equivalent_element_load(loads, exponent, axis=-1):
    """Mean of the rolling-element loads over a revolution, ``((1/Z) sum Q_j^e)^(1/e)``.

    Parameters
    ----------
    loads : array_like
        Contact loads ``Q_j`` of all ``Z`` rolling elements (or of one lamina of each roller)
        [N]; unloaded elements count in ``Z`` with zero load.
    exponent : float
        ``e``: :data:`ROTATING_EXPONENT` or :data:`STATIONARY_EXPONENT` of the kind.
    axis : int
        The axis that runs over the rolling elements.

    Returns
    -------
    numpy.ndarray
        Equivalent load [N], the element axis removed.

    References
    ----------
    .. [1] ISO/TS 16281:2008, eq. (25)-(28) (balls) and (61)-(64) (laminae).
    """
    loads = np.clip(np.asarray(loads, dtype=float), 0.0, None)
    return np.mean(loads**exponent, axis=axis) ** (1.0 / exponent)


def _ring_exponents(kind, rotating_ring):
    """Exponents of the inner and the outer ring's equivalent load."""
    _check_ring(rotating_ring)
    if rotating_ring == "inner":
        return ROTATING_EXPONENT[kind], STATIONARY_EXPONENT[kind]
    return STATIONARY_EXPONENT[kind], ROTATING_EXPONENT[kind]


def ball_contact_load_ratings(dynamic_load_rating, ball_count, ball_diameter, pitch_diameter,
                              contact_angle=0.0, inner_curvature_ratio=0.52,
                              outer_curvature_ratio=0.53, rows=1):
    """Basic dynamic load ratings ``Q_ci``, ``Q_ce`` of a ball's inner and outer raceway
    contacts, from the bearing's basic dynamic load rating.

    ``Q_ci = C_r / (0.407 Z i^0.7 cos(alpha)) [1 + t^(10/3)]^(3/10)`` and
    ``Q_ce = C_r / (0.389 Z i^0.7 cos(alpha)) [1 + t^(-10/3)]^(3/10)`` with
    ``t = 1.044 ((1 - gamma)/(1 + gamma))^1.72 [(f_i/f_e)(2 f_e - 1)/(2 f_i - 1)]^0.41``,
    ``gamma = D_w cos(alpha) / d_m``; ``t`` is ``Q_ci / Q_ce`` by Lundberg and Palmgren's
    contact ratings (osculation and curvature of each raceway), times ``0.407/0.389``.

    The stated ``C_r`` enters as the standard's equations do: the two contact ratings are
    scaled so that a bearing with them has the rating ``C_r`` under ISO 281's rating load
    distribution (radial load, half the ring loaded); the geometry only splits ``C_r`` between
    the rings. So a manufacturer's ``C_r`` (material, make) carries over to ``L10r``, which
    matches ISO 281's ``L10`` at the rating conditions.

    Parameters
    ----------
    dynamic_load_rating : array_like
        ``C_r`` [N].
    ball_count : array_like
        ``Z`` [-].
    ball_diameter, pitch_diameter : array_like
        ``D_w``, ``d_m`` [m].
    contact_angle : array_like
        Nominal contact angle ``alpha`` [rad] (the ratings use it, not the operating angles).
    inner_curvature_ratio, outer_curvature_ratio : array_like
        ``f_i = r_i / D_w``, ``f_e = r_e / D_w`` [-].
    rows : array_like
        Number of rows ``i`` [-]; ``Z`` is the count of one row.

    Returns
    -------
    tuple of numpy.ndarray
        ``Q_ci``, ``Q_ce`` [N].

    Notes
    -----
    The contact angle enters to the first power, as in the force balance
    ``F_r = Z J_r Q_max cos(alpha)`` of the rating load distribution, so that ``L10r = L10``
    there at any contact angle; ISO 281's ``(i cos(alpha))^0.7`` in ``C_r`` already holds the
    contact ratings' own ``cos(alpha)^-0.3``. Some implementations write ``cos(alpha)^0.7``
    here: the same at ``alpha = 0``, a rating larger by ``cos(alpha)^-0.3`` otherwise.

    References
    ----------
    .. [1] ISO/TS 16281:2008, 4.3.1.2, eq. (19)-(20).
    .. [2] G. Lundberg, A. Palmgren, Dynamic capacity of rolling bearings, Acta Polytechnica
       Mech. Eng. Series 1 (3), 1947.
    """
    diameter = np.asarray(ball_diameter, dtype=float)
    inner_ratio = np.asarray(inner_curvature_ratio, dtype=float)
    outer_ratio = np.asarray(outer_curvature_ratio, dtype=float)
    cosine = np.cos(contact_angle)
    gamma = diameter * cosine / np.asarray(pitch_diameter, dtype=float)
    osculation = (inner_ratio / outer_ratio) * (2.0 * outer_ratio - 1.0) / (2.0 * inner_ratio - 1.0)
    split = 1.044 * ((1.0 - gamma) / (1.0 + gamma)) ** 1.72 * osculation**0.41
    per_ball = (np.asarray(dynamic_load_rating, dtype=float)
                / (np.asarray(ball_count, dtype=float) * np.asarray(rows, dtype=float) ** 0.7
                   * cosine))
    inner = per_ball / BALL_RATING_RATIO["inner"] * (1.0 + split ** (10.0 / 3.0)) ** 0.3
    outer = per_ball / BALL_RATING_RATIO["outer"] * (1.0 + split ** (-10.0 / 3.0)) ** 0.3
    return inner, outer


def ball_reference_rating_life(inner_rating, outer_rating, inner_equivalent_load,
                               outer_equivalent_load):
    """Basic reference rating life of a ball bearing from its two rings.

    ``L10r = [(Q_ci / Q_ei)^(-10/3) + (Q_ce / Q_ee)^(-10/3)]^(-9/10)``: each ring's life
    ``(Q_c / Q_e)^3`` combined by the Weibull slope 10/9 of ball bearings.

    Parameters
    ----------
    inner_rating, outer_rating : array_like
        ``Q_ci``, ``Q_ce`` [N] (:func:`ball_contact_load_ratings`).
    inner_equivalent_load, outer_equivalent_load : array_like
        ``Q_ei``, ``Q_ee`` [N] (:func:`equivalent_element_load`).

    Returns
    -------
    numpy.ndarray
        ``L10r`` [10^6 revolutions]; infinite where no ball is loaded.

    References
    ----------
    .. [1] ISO/TS 16281:2008, 4.3.3, eq. (29).
    """
    with np.errstate(divide="ignore"):
        damage = ((np.asarray(inner_equivalent_load, dtype=float) / inner_rating) ** (10.0 / 3.0)
                  + (np.asarray(outer_equivalent_load, dtype=float) / outer_rating)
                  ** (10.0 / 3.0))
        return damage ** -0.9


def ball_bearing_reference_life(inner_loads, dynamic_load_rating, ball_diameter, pitch_diameter,
                                contact_angle=0.0, inner_curvature_ratio=0.52,
                                outer_curvature_ratio=0.53, outer_loads=None,
                                rotating_ring="inner", rows=1):
    """ISO/TS 16281 basic reference rating life of a ball bearing from its ball loads.

    Parameters
    ----------
    inner_loads : array_like
        Inner-raceway contact load of every ball, ``(..., Z)`` [N] (zero for unloaded balls).
    dynamic_load_rating : array_like
        ``C_r`` [N], broadcast against the leading axes.
    ball_diameter, pitch_diameter, contact_angle, inner_curvature_ratio,
    outer_curvature_ratio, rows : array_like
        As for :func:`ball_contact_load_ratings`.
    outer_loads : array_like or None
        Outer-raceway contact loads, ``(..., Z)`` [N]; None: the inner ones (no centrifugal
        force).
    rotating_ring : {'inner', 'outer'}
        The ring that rotates against a stationary load.

    Returns
    -------
    numpy.ndarray
        ``L10r`` [10^6 revolutions].

    References
    ----------
    .. [1] ISO/TS 16281:2008, 4.3, eq. (19)-(20), (25)-(29).
    """
    inner_loads = np.asarray(inner_loads, dtype=float)
    outer_loads = inner_loads if outer_loads is None else np.asarray(outer_loads, dtype=float)
    inner_exponent, outer_exponent = _ring_exponents("ball", rotating_ring)
    inner_rating, outer_rating = ball_contact_load_ratings(
        dynamic_load_rating, inner_loads.shape[-1], ball_diameter, pitch_diameter,
        contact_angle, inner_curvature_ratio, outer_curvature_ratio, rows)
    return ball_reference_rating_life(
        inner_rating, outer_rating, equivalent_element_load(inner_loads, inner_exponent),
        equivalent_element_load(outer_loads, outer_exponent))


def roller_contact_load_ratings(dynamic_load_rating, roller_count, roller_diameter,
                                pitch_diameter, contact_angle=0.0, rows=1,
                                reduction_factor=ROLLER_REDUCTION_FACTOR):
    """Basic dynamic load ratings ``Q_ci``, ``Q_ce`` of a roller's inner and outer raceway
    contacts (whole roller), from the bearing's basic dynamic load rating.

    ``Q_ci = C_r / (lambda nu 0.378 Z i^(7/9) cos(alpha)) [1 + t^(9/2)]^(2/9)``,
    ``Q_ce = C_r / (lambda nu 0.364 Z i^(7/9) cos(alpha)) [1 + t^(-9/2)]^(2/9)``,
    ``t = 1.038 ((1 - gamma)/(1 + gamma))^(143/108)``, ``gamma = D_we cos(alpha) / d_m``.

    ``C_r`` enters as for balls (:func:`ball_contact_load_ratings`). The reduction factor
    ``lambda nu`` of ISO 281's roller rating (edge stresses and uneven load along the roller)
    is divided out: the laminae carry those effects in their own loads.

    Parameters
    ----------
    dynamic_load_rating : array_like
        ``C_r`` [N].
    roller_count : array_like
        ``Z`` [-].
    roller_diameter : array_like
        Mean roller diameter ``D_we`` [m].
    pitch_diameter : array_like
        ``d_m`` [m].
    contact_angle : array_like
        Nominal contact angle ``alpha`` [rad] (tapered: the cup's).
    rows : array_like
        ``i`` [-].
    reduction_factor : array_like
        ``lambda nu`` [-]; 0.83 for radial roller bearings.

    Returns
    -------
    tuple of numpy.ndarray
        ``Q_ci``, ``Q_ce`` [N].

    References
    ----------
    .. [1] ISO/TS 16281:2008, 5.3.1.2, eq. (47)-(49).
    """
    cosine = np.cos(contact_angle)
    gamma = np.asarray(roller_diameter, dtype=float) * cosine / np.asarray(pitch_diameter,
                                                                            dtype=float)
    split = 1.038 * ((1.0 - gamma) / (1.0 + gamma)) ** (143.0 / 108.0)
    per_roller = (np.asarray(dynamic_load_rating, dtype=float)
                  / (np.asarray(reduction_factor, dtype=float)
                     * np.asarray(roller_count, dtype=float)
                     * np.asarray(rows, dtype=float) ** (7.0 / 9.0) * cosine))
    inner = per_roller / ROLLER_RATING_RATIO["inner"] * (1.0 + split**4.5) ** (2.0 / 9.0)
    outer = per_roller / ROLLER_RATING_RATIO["outer"] * (1.0 + split**-4.5) ** (2.0 / 9.0)
    return inner, outer


def lamina_load_rating(contact_rating, laminae):
    """Basic dynamic load rating of one of ``n_s`` equal laminae, ``q_c = Q_c n_s^(-7/9)``.

    Parameters
    ----------
    contact_rating : array_like
        ``Q_ci`` or ``Q_ce`` of the whole roller [N].
    laminae : int
        ``n_s`` [-].

    Returns
    -------
    numpy.ndarray
        ``q_ci`` or ``q_ce`` [N].

    References
    ----------
    .. [1] ISO/TS 16281:2008, 5.3.2, eq. (56)-(57).
    """
    return np.asarray(contact_rating, dtype=float) * float(laminae) ** (-7.0 / 9.0)


def roller_reference_rating_life(inner_lamina_rating, outer_lamina_rating,
                                 inner_lamina_equivalent_loads, outer_lamina_equivalent_loads,
                                 lamina_weights=None):
    """Basic reference rating life of a roller bearing summed over laminae.

    ``L10r = {sum_k [(q_ei,k / q_ci)^(9/2) + (q_ee,k / q_ce)^(9/2)]}^(-8/9)``: each lamina
    and ring a life ``(q_c / q_e)^4`` (line contact), combined by the Weibull slope 9/8.

    Parameters
    ----------
    inner_lamina_rating, outer_lamina_rating : array_like
        ``q_ci``, ``q_ce`` [N] (:func:`lamina_load_rating`), one value per point.
    inner_lamina_equivalent_loads, outer_lamina_equivalent_loads : array_like
        ``q_ei,k``, ``q_ee,k`` of every lamina, ``(..., n_s)`` [N].
    lamina_weights : array_like or None
        Number of laminae each column stands for, ``(n_s,)`` [-] (a symmetric roller
        stored as its distinct slices with their counts, as
        :func:`models.contact.sliced_line_contact` does); None: one each.

    Returns
    -------
    numpy.ndarray
        ``L10r`` [10^6 revolutions]; infinite where nothing is loaded.

    References
    ----------
    .. [1] ISO/TS 16281:2008, 5.3.4, eq. (65).
    """
    inner_rating = np.asarray(inner_lamina_rating, dtype=float)[..., None]
    outer_rating = np.asarray(outer_lamina_rating, dtype=float)[..., None]
    damage = ((np.asarray(inner_lamina_equivalent_loads, dtype=float) / inner_rating) ** 4.5
              + (np.asarray(outer_lamina_equivalent_loads, dtype=float) / outer_rating) ** 4.5)
    weights = 1.0 if lamina_weights is None else np.asarray(lamina_weights, dtype=float)
    damage = np.sum(damage * weights, axis=-1)
    with np.errstate(divide="ignore"):
        return damage ** (-8.0 / 9.0)


def roller_bearing_reference_life(inner_lamina_loads, dynamic_load_rating, roller_diameter,
                                  pitch_diameter, contact_angle=0.0, outer_lamina_loads=None,
                                  rotating_ring="inner", rows=1,
                                  reduction_factor=ROLLER_REDUCTION_FACTOR, stress_factor=1.0,
                                  lamina_weights=None):
    """ISO/TS 16281 basic reference rating life of a roller bearing from its lamina loads.

    Parameters
    ----------
    inner_lamina_loads : array_like
        Inner-raceway contact load of every lamina of every roller, ``(..., Z, n_s)`` [N];
        rollers that are not sliced: ``(..., Z, 1)`` (one lamina, the whole roller).
    dynamic_load_rating : array_like
        ``C_r`` [N], broadcast against the leading axes.
    roller_diameter, pitch_diameter, contact_angle, rows, reduction_factor : array_like
        As for :func:`roller_contact_load_ratings`.
    outer_lamina_loads : array_like or None
        Outer-raceway lamina loads, ``(..., Z, n_s)`` [N]; None: the inner ones.
    rotating_ring : {'inner', 'outer'}
        The ring that rotates against a stationary load.
    stress_factor : array_like
        Factor on each lamina's load for a stress concentration the load distribution does
        not hold (ISO/TS 16281's factor ``f_k`` at the roller ends), ``(n_s,)`` or scalar
        [-]; 1: the lamina loads as given.
    lamina_weights : array_like or None
        Number of laminae each column of the lamina loads stands for, ``(n_s,)`` [-]
        (distinct slices of a symmetric roller with their counts); None: one each. The
        lamina count of the ratings is their sum.

    Returns
    -------
    numpy.ndarray
        ``L10r`` [10^6 revolutions].

    Notes
    -----
    The standard asks for at least 30 laminae for a load distribution it computes itself;
    here the laminae are the model's slices, equal in length.

    References
    ----------
    .. [1] ISO/TS 16281:2008, 5.3, eq. (47)-(49), (56)-(57), (61)-(65).
    """
    inner_lamina_loads = np.asarray(inner_lamina_loads, dtype=float) * stress_factor
    outer_lamina_loads = (inner_lamina_loads if outer_lamina_loads is None
                          else np.asarray(outer_lamina_loads, dtype=float) * stress_factor)
    roller_count, laminae = inner_lamina_loads.shape[-2:]
    if lamina_weights is not None:
        laminae = float(np.sum(lamina_weights))
    inner_exponent, outer_exponent = _ring_exponents("roller", rotating_ring)
    inner_rating, outer_rating = roller_contact_load_ratings(
        dynamic_load_rating, roller_count, roller_diameter, pitch_diameter, contact_angle, rows,
        reduction_factor)
    return roller_reference_rating_life(
        lamina_load_rating(inner_rating, laminae), lamina_load_rating(outer_rating, laminae),
        equivalent_element_load(inner_lamina_loads, inner_exponent, axis=-2),
        equivalent_element_load(outer_lamina_loads, outer_exponent, axis=-2), lamina_weights)


def equivalent_reference_load(dynamic_load_rating, reference_life, kind="ball"):
    """Dynamic equivalent reference load ``P_ref = C / L10r^(1/p)``: the load that gives
    ``L10r`` by ISO 281's life equation, and the load of ``a_ISO`` for ``L10rm``.

    Parameters
    ----------
    dynamic_load_rating : array_like
        ``C`` [N].
    reference_life : array_like
        ``L10r`` [10^6 revolutions].
    kind : {'ball', 'roller'}

    Returns
    -------
    numpy.ndarray
        ``P_ref`` [N]; zero where ``L10r`` is infinite.

    References
    ----------
    .. [1] ISO/TS 16281:2008, 4.3.4 (ball) and 5.3.5 (roller bearings).
    """
    _check_kind(kind)
    return np.asarray(dynamic_load_rating, dtype=float) / np.asarray(
        reference_life, dtype=float) ** (1.0 / LIFE_EXPONENT[kind])


def modified_reference_rating_life(reference_life, dynamic_load_rating, viscosity_ratio,
                                   contamination_factor, fatigue_load_limit, kind="ball"):
    """Modified reference rating life ``L10rm = a_ISO L10r`` (90 % reliability, ``a_1 = 1``).

    ``a_ISO`` (:func:`life_modification_factor`) takes the dynamic equivalent reference load
    ``P_ref`` (:func:`equivalent_reference_load`) for ``P``.

    Parameters
    ----------
    reference_life : array_like
        ``L10r`` [10^6 revolutions].
    dynamic_load_rating, viscosity_ratio, contamination_factor, fatigue_load_limit : array_like
        ``C`` [N], ``kappa`` [-], ``e_C`` [-], ``C_u`` [N].
    kind : {'ball', 'roller'}

    Returns
    -------
    numpy.ndarray
        ``L10rm`` [10^6 revolutions]; NaN where ``kappa < 0.1``.

    References
    ----------
    .. [1] ISO/TS 16281:2008, 4.3.5 and 5.3.6; ISO 281:2007, 9.3.
    """
    load = equivalent_reference_load(dynamic_load_rating, reference_life, kind)
    return life_modification_factor(viscosity_ratio, contamination_factor, fatigue_load_limit,
                                    load, kind) * np.asarray(reference_life, dtype=float)


def modified_rating_life(dynamic_load_rating, equivalent_load, viscosity_ratio,
                         contamination_factor, fatigue_load_limit, kind="ball"):
    """ISO 281 modified rating life ``L10m = a_ISO L10`` (90 % reliability, ``a_1 = 1``).

    Parameters
    ----------
    dynamic_load_rating, equivalent_load : array_like
        ``C``, ``P`` [N].
    viscosity_ratio, contamination_factor, fatigue_load_limit : array_like
        ``kappa`` [-], ``e_C`` [-], ``C_u`` [N].
    kind : {'ball', 'roller'}

    Returns
    -------
    numpy.ndarray
        ``L10m`` [10^6 revolutions].

    References
    ----------
    .. [1] ISO 281:2007, 9.1 and 9.3.
    """
    return (life_modification_factor(viscosity_ratio, contamination_factor, fatigue_load_limit,
                                     equivalent_load, kind)
            * basic_rating_life(dynamic_load_rating, equivalent_load, kind))
