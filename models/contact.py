"""Contact mechanics: the sliced line contact of a crowned roller, and Hertz point contact."""
from __future__ import annotations

import numpy as np

from .lubrication import MINERAL_OIL_PRESSURE_VISCOSITY, point_contact_film
from .registry import (CONVERGED, INFEASIBLE, NOT_CONVERGED, OUT_OF_VALIDITY, Constraint,
                             Input, Model, Output)
from .solvers import solve_increasing

#: Load-deflection exponent of a line contact, Q = K delta^n [-] (Palmgren).
LINE_CONTACT_EXPONENT = 10.0 / 9.0

# Palmgren's steel line contact Q = 8.06e4 l^(8/9) delta^(10/9) with Q in N, l and delta in mm
# (Harris & Kotzalas, Rolling Bearing Analysis, eq. for line contact). In SI the coefficient
# is 8.06e4 N/mm^2 = 8.06e10 N/m^2, since l^(8/9) delta^(10/9) has the dimension of an area.
PALMGREN_COEFFICIENT = 8.06e10  # [N/m^2]

SLICE_LAWS = ("uniform", "paper")


def palmgren_constant(effective_length):
    """Load-deflection constant of one steel roller-raceway line contact.

    Parameters
    ----------
    effective_length : array_like
        Effective contact length of the roller ``l`` [m].

    Returns
    -------
    numpy.ndarray
        ``K = 8.06e4 l^(8/9)`` in N/mm^(10/9), returned in SI [N/m^(10/9)], so that
        ``Q = K delta^(10/9)`` for one contact.

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., ch. 6 (Palmgren's
       line-contact load-deflection relation).
    """
    return PALMGREN_COEFFICIENT * np.asarray(effective_length, dtype=float) ** (8.0 / 9.0)


def sliced_line_contact(approach, gaps, counts, contact_constant, slice_law="uniform"):
    """Load and contact stiffness of a roller-raceway contact cut into slices.

    Parameters
    ----------
    approach : numpy.ndarray
        Approach of roller and raceway at the roller's middle ``delta`` [m], shape ``S``.
    gaps : numpy.ndarray
        Crown gap of each distinct slice ``c_lambda`` [m], shape ``S + (m,)``.
    counts : numpy.ndarray
        Number of slices sharing each gap, shape ``(m,)``; ``k = counts.sum()`` slices in all.
    contact_constant : numpy.ndarray
        Whole-roller load-deflection constant ``K`` [N/m^n], shape ``S``.
    slice_law : {'uniform', 'paper'}
        ``'uniform'`` (default): each slice carries ``K/k (delta - c_lambda)^n``, which
        reduces to ``K delta^n`` for a straight roller at any ``k`` (the slicing of
        ISO/TS 16281). ``'paper'``: eq. 9 of [1] as printed, the sum over the ``k_j`` loaded
        slices divided by ``k_j``; the load then drops each time a slice pair comes into
        contact, and the stiffness treats ``k_j`` as constant (eq. 15).

    Returns
    -------
    load : numpy.ndarray
        Contact load ``Q`` [N], shape ``S``.
    stiffness : numpy.ndarray
        ``dQ/d delta`` [N/m], shape ``S``.

    References
    ----------
    .. [1] Paper 000, "Radial stiffness analysis of cylindrical roller bearing", eq. 5, 7, 9, 15.
    """
    n = LINE_CONTACT_EXPONENT
    penetration = approach[..., None] - gaps
    np.maximum(penetration, 0.0, out=penetration)
    slope_term = penetration ** (n - 1.0)  # one power gives both load and stiffness
    # einsum sums each point's slices in one pass, in the same order whatever the batch.
    load_sum = np.einsum("...m,...m,m->...", penetration, slope_term, counts)
    slope_sum = np.einsum("...m,m->...", slope_term, counts)
    if slice_law == "uniform":
        divisor = counts.sum()
    elif slice_law == "paper":
        divisor = np.einsum("...m,m->...", (penetration > 0.0).astype(float), counts)
        divisor = np.where(divisor > 0.0, divisor, 1.0)  # no loaded slice: the sums are zero
    else:
        raise ValueError(f"unknown slice law {slice_law!r}; expected one of {SLICE_LAWS}")
    scale = contact_constant / divisor
    return scale * load_sum, scale * n * slope_sum


def slice_loads(approach, gaps, counts, contact_constant, slice_law="uniform"):
    """Load of each distinct slice of a sliced line contact [N].

    Parameters
    ----------
    approach, gaps, counts, contact_constant, slice_law
        As :func:`sliced_line_contact`.

    Returns
    -------
    numpy.ndarray
        ``q_lambda = K/k (delta - c_lambda)^n`` ('uniform'; ``K/k_j`` with ``k_j`` loaded
        slices for 'paper'), shape ``S + (m,)``; each of the ``counts[lambda]`` slices of a
        gap carries it, so ``(q * counts).sum(-1)`` is :func:`sliced_line_contact`'s load.
        These are the laminae of ISO/TS 16281, 5.3.
    """
    penetration = np.maximum(approach[..., None] - gaps, 0.0)
    if slice_law == "uniform":
        divisor = counts.sum()
    elif slice_law == "paper":
        divisor = np.einsum("...m,m->...", (penetration > 0.0).astype(float), counts)
        divisor = np.where(divisor > 0.0, divisor, 1.0)[..., None]
    else:
        raise ValueError(f"unknown slice law {slice_law!r}; expected one of {SLICE_LAWS}")
    return np.asarray(contact_constant)[..., None] / divisor * penetration**LINE_CONTACT_EXPONENT


def largest_slice_line_load(approach, gaps, counts, contact_constant, effective_length,
                            slice_law="uniform"):
    """Load per unit length of the most loaded slice of a sliced line contact [N/m].

    Parameters
    ----------
    approach, gaps, counts, contact_constant, slice_law
        As :func:`sliced_line_contact`.
    effective_length : numpy.ndarray
        Effective contact length of the roller ``l`` [m], shape ``S``.

    Returns
    -------
    numpy.ndarray
        ``w = q_max / (l / k)``: the slice with the smallest gap carries the largest of
        :func:`slice_loads`, ``q_max = K/k (delta - c_min)^n`` ('uniform'; ``K/k_j`` with
        ``k_j`` loaded slices for 'paper') on its length ``l/k``, so
        ``w = K/l (delta - c_min)^n`` ('uniform'). Shape ``S``; zero where no slice touches.
        Only the smallest gap is raised to the power: a point's other slices cost nothing.
    """
    n = LINE_CONTACT_EXPONENT
    deepest = np.maximum(approach - gaps.min(axis=-1), 0.0)
    if slice_law == "uniform":
        share = 1.0
    elif slice_law == "paper":
        loaded = np.einsum("...m,m->...", (approach[..., None] > gaps).astype(float), counts)
        share = counts.sum() / np.where(loaded > 0.0, loaded, 1.0)
    else:
        raise ValueError(f"unknown slice law {slice_law!r}; expected one of {SLICE_LAWS}")
    return share * contact_constant / effective_length * deepest**n


def line_contact_pressure(line_load, curvature_sum, modulus):
    """Maximum pressure of a Hertz line contact (two parallel cylinders).

    Parameters
    ----------
    line_load : array_like
        Load per unit length ``w`` [N/m].
    curvature_sum : array_like
        ``sum(rho) = 1/R_1 + 1/R_2`` [1/m] across the contact line (negative for a concave
        body), the inverse of Johnson's relative radius ``R``.
    modulus : array_like
        ``E* = 1 / [(1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2]`` [Pa] (:func:`effective_modulus`).

    Returns
    -------
    numpy.ndarray
        ``p0 = (w E* / (pi R))^(1/2) = (w E* sum(rho) / pi)^(1/2)`` [Pa] (Johnson eq. 4.45;
        the same as Harris' ``sigma_max = 2Q / (pi l b)`` with
        ``b = [8 Q (1 - nu^2) / (pi l E sum(rho))]^(1/2)`` for two steel bodies).

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), eq. 4.45
       (two-dimensional contact of cylinders: semi-width ``a = (4 w R / (pi E*))^(1/2)``,
       ``p0 = 2 w / (pi a)``).
    .. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., ch. 6 (line
       contact).
    """
    return np.sqrt(np.asarray(line_load) * modulus * curvature_sum / np.pi)


# -- validity limits shared by the bearing models ---------------------------------------------

#: Contact pressure at the centre of the most heavily loaded contact that defines the basic
#: static load rating of ISO 76:2006 (clauses 3.1-3.3), 4000 MPa for roller bearings and
#: 4200 MPa for ball bearings (4600 MPa self-aligning): there the total permanent deformation
#: of rolling element and raceway is about 1e-4 of the rolling element's diameter. Beyond it
#: the contact is no longer elastic and Hertz's theory, on which every contact law here
#: rests, no longer holds [Pa].
ROLLER_PRESSURE_LIMIT = 4000e6
#: The stiffest solid, diamond (Young's modulus 1050-1220 GPa; Klein and Cardinale, Diamond
#: Relat. Mater. 2 (1993) 918): a rolling element or ring stiffer than it is a slip of units
#: [GPa, the unit the models declare].
STIFFEST_SOLID = 1220.0
BALL_PRESSURE_LIMIT = 4200e6
#: Approach of a roller's contacts beyond which a bearing model's fixed, small-displacement
#: geometry (contact angles, azimuths, contact on the undeformed profiles) no longer holds, as
#: a fraction of the roller diameter [-]: two to four times a steel roller's approach (both
#: contacts) at the ISO 76 pressure (0.45 % with Palmgren's constant in paper 000's bearing D,
#: 1.05 % with paper 003's eq. 14), so it flags a soft contact constant.
APPROACH_LIMIT = 0.02
#: Largest semi-axis of a Hertz contact as a fraction of the smallest radius of curvature of
#: the two bodies [-]. Hertz takes the surfaces near the contact as paraboloids on elastic
#: half-spaces, which needs the contact small against the radii (Johnson, ch. 4.1, "a << R");
#: at a = 0.5 R the contact spans 60 deg of the body's arc and a circle's gap departs from
#: the paraboloid's by a^2 / (4 R^2) = 6 %. A ball in a conforming groove (radius 0.52 D)
#: reaches a = 0.3-0.5 R at the ISO 76 pressure, where practice still applies Hertz.
SEMI_AXIS_LIMIT = 0.5


# -- point contact (Hertz) ------------------------------------------------------------------

POINT_CONTACT_EXPONENT = 1.5
POINT_FORMULAS = ("exact", "hamrock_brewe")
#: Largest radius ratio ``alpha = R_y/R_x`` at which Hamrock and Brewe's closed forms are
#: used [-]: against the exact ellipse their approach errs by 2.7 % at most up to 70, by
#: 4.1 % at 100, 6.5 % at 200 and 12.7 % at 1000 (the semi-axes and pressure less).
HAMROCK_BREWE_RATIO_LIMIT = 70.0
# Below this elliptic parameter the closed form of F(rho) loses digits to cancellation; its
# series (both are within 1e-8 of each other there) takes over.
_SMALL_PARAMETER = 1e-4


def _curvature_difference(parameter):
    """F(rho) of an ellipse with elliptic parameter ``m = 1 - (b/a)^2``, and dF/dm.

    ``F = [(k^2 + 1) E - 2 K] / [(k^2 - 1) E]`` with ``k = a/b`` (Harris, eq. 6.28), written in
    ``m``; its series ``3m/8 + 3m^2/16`` is used below ``_SMALL_PARAMETER``.
    """
    from scipy.special import ellipe, ellipk  # here: a line contact's model needs no scipy

    m = np.asarray(parameter, dtype=float)
    small = m < _SMALL_PARAMETER
    safe = np.where(small, 0.5, m)
    first, second = ellipk(safe), ellipe(safe)
    numerator = (2.0 - safe) * second - 2.0 * (1.0 - safe) * first
    denominator = safe * second
    d_second = (second - first) / (2.0 * safe)
    d_first = (second - (1.0 - safe) * first) / (2.0 * safe * (1.0 - safe))
    d_numerator = -second + (2.0 - safe) * d_second + 2.0 * first - 2.0 * (1.0 - safe) * d_first
    d_denominator = second + safe * d_second
    value = numerator / denominator
    slope = (d_numerator * denominator - numerator * d_denominator) / denominator**2
    value = np.where(small, 3.0 * m / 8.0 + 3.0 * m**2 / 16.0, value)
    slope = np.where(small, 3.0 / 8.0 + 3.0 * m / 8.0, slope)
    return value, slope


def ellipse_parameters(curvature_difference, formula="exact"):
    """Ellipticity and complete elliptic integrals of a Hertz point contact.

    Parameters
    ----------
    curvature_difference : array_like
        ``F(rho) = |(rho_1x - rho_1y) + (rho_2x - rho_2y)| / sum(rho)`` [-], in [0, 1).
    formula : {'exact', 'hamrock_brewe'}
        ``'exact'``: ``k`` solves Harris' eq. 6.28 with scipy's complete elliptic integrals
        (safeguarded Newton, all points at once). ``'hamrock_brewe'``: the closed forms
        ``k = alpha^(2/pi)``, ``E = 1 + (pi/2 - 1)/alpha``, ``K = pi/2 + (pi/2 - 1) ln alpha``
        with ``alpha = R_y/R_x = (1 + F)/(1 - F)`` [2].

    Returns
    -------
    ellipticity, second_kind, first_kind : numpy.ndarray
        ``k = a/b`` [-], ``E`` and ``K`` [-].
    converged : numpy.ndarray of bool

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, ch. 6 (Hertz point contact).
    .. [2] B. J. Hamrock, D. E. Brewe, Simplified solution for stresses and deformations,
       J. Lubrication Technology 105 (1983) 171-177.
    """
    from scipy.special import ellipe, ellipk  # here: a line contact's model needs no scipy

    difference = np.asarray(curvature_difference, dtype=float)
    alpha = (1.0 + difference) / (1.0 - difference)
    if formula == "hamrock_brewe":
        return (alpha ** (2.0 / np.pi), 1.0 + (np.pi / 2 - 1.0) / alpha,
                np.pi / 2 + (np.pi / 2 - 1.0) * np.log(alpha), np.ones(difference.shape, bool))
    if formula != "exact":
        raise ValueError(f"unknown point-contact formula {formula!r}; expected {POINT_FORMULAS}")
    flat = difference.ravel()
    start = np.clip(1.0 - alpha.ravel() ** (-4.0 / np.pi), 0.0, 1.0 - 1e-15)  # Hamrock-Brewe k

    def residual(parameter, index):
        value, slope = _curvature_difference(parameter)
        return value - flat[index], slope

    parameter, converged = solve_increasing(residual, np.zeros(flat.size),
                                            np.full(flat.size, 1.0 - 1e-15), start, 1e-15)
    parameter = parameter.reshape(difference.shape)
    return (1.0 / np.sqrt(1.0 - parameter), ellipe(parameter), ellipk(parameter),
            converged.reshape(difference.shape))


def effective_modulus(youngs_modulus, poisson_ratio, youngs_modulus_2=None, poisson_ratio_2=None):
    """``E* = 1 / [(1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2]`` [Pa]; body 2 defaults to body 1."""
    youngs_modulus_2 = youngs_modulus if youngs_modulus_2 is None else youngs_modulus_2
    poisson_ratio_2 = poisson_ratio if poisson_ratio_2 is None else poisson_ratio_2
    return 1.0 / ((1.0 - np.asarray(poisson_ratio) ** 2) / youngs_modulus
                  + (1.0 - np.asarray(poisson_ratio_2) ** 2) / youngs_modulus_2)


def curvature_sum_difference(curvature_1x, curvature_1y, curvature_2x, curvature_2y):
    """Curvature sum and difference of two bodies touching at a point.

    Parameters
    ----------
    curvature_1x, curvature_1y, curvature_2x, curvature_2y : array_like
        Principal curvatures [1/m] (positive convex, negative concave) in planes x and y.

    Returns
    -------
    curvature_sum, curvature_difference, touching : numpy.ndarray
        ``sum(rho)`` [1/m] and ``F(rho) = |rho_x - rho_y| / sum(rho)`` [-] (Harris eq. 6.5-6.6,
        with ``rho_x``, ``rho_y`` the relative curvatures), and whether both relative
        curvatures are positive (a point contact); elsewhere the sum is 2 and ``F`` is 0.
    """
    relative_x = np.asarray(curvature_1x) + curvature_2x
    relative_y = np.asarray(curvature_1y) + curvature_2y
    touching = (relative_x > 0) & (relative_y > 0)  # else no point contact: infeasible
    relative_x = np.where(touching, relative_x, 1.0)
    relative_y = np.where(touching, relative_y, 1.0)
    total = relative_x + relative_y
    return total, np.abs(relative_x - relative_y) / total, touching


def point_contact_constant(curvature_sum, curvature_difference, modulus, formula="exact"):
    """Load-deflection constant ``K`` of a Hertz point contact, ``Q = K delta^1.5`` [N/m^1.5].

    Parameters
    ----------
    curvature_sum : array_like
        ``sum(rho)`` [1/m]. curvature_difference : ``F(rho)`` [-]. modulus : ``E*`` [Pa].
    formula : {'exact', 'hamrock_brewe'}
        See :func:`ellipse_parameters`.

    Returns
    -------
    constant, converged : numpy.ndarray
        From ``delta = delta* [3Q/(2 sum(rho) E*)]^(2/3) sum(rho)/2`` (Harris, eq. 6.43 with
        ``delta* = (2K/pi) (pi/(2 k^2 E))^(1/3)``), which is ``Q^(2/3)`` times a constant.
    """
    kappa, second, first, converged = ellipse_parameters(curvature_difference, formula)
    unit = _unit_approach(kappa, second, first, curvature_sum, modulus)
    return unit ** (-POINT_CONTACT_EXPONENT), converged


def _unit_approach(kappa, second, first, curvature_sum, modulus):
    """Approach under a unit load, ``delta / Q^(2/3)`` [m/N^(2/3)]."""
    total = np.asarray(curvature_sum, dtype=float)
    approach_star = 2.0 * first / np.pi * (np.pi / (2.0 * kappa**2 * second)) ** (1.0 / 3.0)
    return approach_star * (1.5 / (total * modulus)) ** (2.0 / 3.0) * total / 2.0


def hertz_point(load, curvature_1x, curvature_1y, curvature_2x=0.0, curvature_2y=0.0,
                youngs_modulus=207e9, poisson_ratio=0.3, youngs_modulus_2=None,
                poisson_ratio_2=None, formula="exact", entrainment_speed=0.0, viscosity=None,
                pressure_viscosity=MINERAL_OIL_PRESSURE_VISCOSITY):
    """Hertz contact of two bodies touching at a point, and its lubricant film.

    Parameters
    ----------
    load : array_like
        Normal load ``Q`` [N].
    curvature_1x, curvature_1y, curvature_2x, curvature_2y : array_like
        Principal curvatures of body 1 and body 2 in two common planes x and y [1/m]:
        positive convex, zero flat, negative concave. Both relative curvatures
        ``rho_1x + rho_2x`` and ``rho_1y + rho_2y`` must be positive.
    youngs_modulus, poisson_ratio : array_like
        ``E_1`` [Pa] and ``nu_1`` [-] of body 1.
    youngs_modulus_2, poisson_ratio_2 : array_like or None
        ``E_2`` [Pa] and ``nu_2`` [-] of body 2 (None: the same material as body 1).
    formula : {'exact', 'hamrock_brewe'}
        Ellipticity and elliptic integrals exact or by Hamrock and Brewe's closed forms.
    entrainment_speed : array_like
        Mean speed ``u`` of the two surfaces along x, the rolling direction [m/s].
    viscosity : array_like or None
        Dynamic viscosity ``eta_0`` of the oil at the contact's inlet, at ambient pressure
        [Pa s]; None: no film (NaN).
    pressure_viscosity : array_like
        Pressure-viscosity coefficient ``alpha`` of the oil [1/Pa] (default:
        :data:`models.lubrication.MINERAL_OIL_PRESSURE_VISCOSITY`).

    Returns
    -------
    dict of numpy.ndarray
        ``semi_major`` ``a`` and ``semi_minor`` ``b`` [m], ``approach`` ``delta`` [m],
        ``max_pressure`` ``p0 = 3Q/(2 pi a b)`` [Pa], ``ellipticity`` ``k = a/b`` [-],
        ``contact_constant`` ``K = Q/delta^1.5`` [N/m^1.5], ``central_film_thickness``
        ``h_c`` and ``minimum_film_thickness`` ``h_min`` [m] (Hamrock and Dowson,
        :func:`models.lubrication.point_contact_film`, with this ellipse's ``k``, ``R_x`` the
        relative radius in plane x and ``E' = 2 E*``), ``status``.

    Notes
    -----
    Validity: a solved point is ``out_of_validity`` (values kept) where the semi-major axis
    exceeds ``SEMI_AXIS_LIMIT`` (0.5) times the smallest radius of curvature of either body
    (Hertz's small contact on half-spaces), or the maximum pressure exceeds
    ``BALL_PRESSURE_LIMIT`` (4200 MPa, ISO 76's reference stress of a ball bearing's point
    contacts, for hardened bearing steel: beyond it the contact deforms plastically), or,
    with ``formula='hamrock_brewe'``, where the radius ratio ``R_y/R_x`` exceeds
    ``HAMROCK_BREWE_RATIO_LIMIT`` (70: beyond it the closed forms err by more than 3 %), or,
    with a viscosity, where the oil is entrained along the ellipse's major axis (``R_x >
    R_y``): Hamrock and Dowson fitted their formulas to contacts entrained along the minor
    axis, ``k`` from 1 to 8; the film there is that of ``k = b/a < 1``, which they do not
    vouch for.

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., ch. 6: a, b, delta
       and the maximum pressure from a*, b*, delta* (eq. 6.36-6.44).
    .. [2] B. J. Hamrock, D. E. Brewe, J. Lubrication Technology 105 (1983) 171-177.
    .. [3] B. J. Hamrock, D. Dowson, Isothermal elastohydrodynamic lubrication of point
       contacts, Part III - Fully flooded results, J. Lubrication Technology 99 (1977)
       264-276.
    """
    arrays = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (
        load, curvature_1x, curvature_1y, curvature_2x, curvature_2y)))
    load = arrays[0]
    total, difference, touching = curvature_sum_difference(*arrays[1:])
    modulus = effective_modulus(youngs_modulus, poisson_ratio, youngs_modulus_2, poisson_ratio_2)
    kappa, second, first, converged = ellipse_parameters(difference, formula)
    scale = (1.5 * load / (total * modulus)) ** (1.0 / 3.0)
    semi_major = (2.0 * kappa**2 * second / np.pi) ** (1.0 / 3.0) * scale
    semi_minor = (2.0 * second / (np.pi * kappa)) ** (1.0 / 3.0) * scale
    unit = _unit_approach(kappa, second, first, total, modulus)
    approach = unit * load ** (2.0 / 3.0)
    constant = unit ** (-POINT_CONTACT_EXPONENT)
    with np.errstate(invalid="ignore", divide="ignore"):
        pressure = np.where(load > 0, 1.5 * load / (np.pi * semi_major * semi_minor), 0.0)
    # Rolling along x: the ellipse's minor axis lies along x where the bodies curve more in x.
    relative_x = np.asarray(arrays[1]) + arrays[3]
    along_minor = relative_x >= total / 2.0
    central, minimum = point_contact_film(
        load, 1.0 / relative_x, np.where(along_minor, kappa, 1.0 / kappa), entrainment_speed,
        np.nan if viscosity is None else viscosity, pressure_viscosity, 2.0 * modulus)
    outputs = {"semi_major": semi_major, "semi_minor": semi_minor, "approach": approach,
               "max_pressure": pressure, "ellipticity": kappa, "contact_constant": constant,
               "central_film_thickness": central, "minimum_film_thickness": minimum}
    film_names = ("central_film_thickness", "minimum_film_thickness")
    ok = converged & touching
    for name, value in outputs.items():  # a NaN input fails the point; no film is no failure
        if name not in film_names:
            ok &= np.isfinite(value)
    outputs = {name: np.where(ok, value, np.nan) for name, value in outputs.items()}
    with np.errstate(divide="ignore"):  # four flat surfaces are no point contact anyway
        smallest_radius = 1.0 / np.max(np.abs(arrays[1:]), axis=0)
    approximate = formula == "hamrock_brewe"
    beyond = ((outputs["semi_major"] > SEMI_AXIS_LIMIT * smallest_radius)
              | (outputs["max_pressure"] > BALL_PRESSURE_LIMIT)
              | (approximate & ((1.0 + difference) > HAMROCK_BREWE_RATIO_LIMIT
                                * (1.0 - difference)))
              | (~along_minor & np.isfinite(outputs["minimum_film_thickness"])))
    outputs["status"] = np.select([ok & beyond, ok, ~touching],
                                  [OUT_OF_VALIDITY, CONVERGED, INFEASIBLE],
                                  NOT_CONVERGED).astype(np.int8)
    return outputs


def _point_contact(curvature_1x, curvature_1y, curvature_2x, curvature_2y):
    return (curvature_1x + curvature_2x > 0) & (curvature_1y + curvature_2y > 0)


MODELS = [Model(
    name="hertz_point",
    function=hertz_point,
    summary="Hertz point contact of two elastic bodies: contact ellipse, approach, maximum "
            "pressure and load-deflection constant, exact or by Hamrock and Brewe; the "
            "lubricant film by Hamrock and Dowson.",
    reference="Harris & Kotzalas, Rolling Bearing Analysis, ch. 6; Hamrock & Brewe (1983); "
              "Hamrock & Dowson (1977)",
    version="5",
    inputs=(
        Input("load", "N", "normal load Q", minimum=0.0),
        Input("curvature_1x", "1/mm", "principal curvature of body 1 in plane x (negative: "
              "concave)"),
        Input("curvature_1y", "1/mm", "principal curvature of body 1 in plane y"),
        Input("curvature_2x", "1/mm", "principal curvature of body 2 in plane x (0: flat)",
              default=0.0),
        Input("curvature_2y", "1/mm", "principal curvature of body 2 in plane y", default=0.0),
        Input("youngs_modulus", "GPa", "Young's modulus of body 1 (and 2 unless given)",
              default=207.0, minimum=0.0, exclusive_minimum=True,
              label="Young's modulus", maximum=STIFFEST_SOLID),
        Input("poisson_ratio", "1", "Poisson's ratio of body 1 (and 2 unless given)",
              default=0.3, minimum=0.0, maximum=0.5,
              label="Poisson's ratio"),
        Input("youngs_modulus_2", "GPa", "Young's modulus of body 2; default: body 1's",
              default=None, minimum=0.0, exclusive_minimum=True, maximum=STIFFEST_SOLID),
        Input("poisson_ratio_2", "1", "Poisson's ratio of body 2; default: body 1's",
              default=None, minimum=0.0, maximum=0.5),
        Input("formula", "", "exact: elliptic integrals; hamrock_brewe: closed-form "
              "approximation", default="exact", kind="choice", choices=POINT_FORMULAS),
        Input("entrainment_speed", "m/s", "mean speed u of the two surfaces along x, the "
              "rolling direction (film only)", default=0.0, minimum=0.0,
              label="entrainment speed"),
        Input("viscosity", "mPa*s", "dynamic viscosity eta0 of the oil at the inlet, at "
              "ambient pressure (film only); default: no film (NaN)", default=None,
              minimum=0.0, exclusive_minimum=True, label="oil viscosity"),
        Input("pressure_viscosity", "1/GPa", "pressure-viscosity coefficient alpha of the oil "
              "(film only; mineral oils about 15-35)", default=20.0, minimum=0.0,
              exclusive_minimum=True, maximum=100.0, label="pressure-viscosity coefficient"),
    ),
    outputs=(
        Output("semi_major", "mm", "semi-major axis a of the contact ellipse"),
        Output("semi_minor", "mm", "semi-minor axis b of the contact ellipse"),
        Output("approach", "mm", "approach delta of the two bodies"),
        Output("max_pressure", "MPa", "maximum contact pressure p0"),
        Output("ellipticity", "1", "ellipticity k = a/b"),
        Output("contact_constant", "N/mm^1.5", "load-deflection constant K, Q = K delta^1.5"),
        Output("central_film_thickness", "um", "central EHL film thickness hc (Hamrock and "
               "Dowson, 1977; rolling along x); NaN without viscosity",
               label="central film thickness"),
        Output("minimum_film_thickness", "um", "minimum EHL film thickness hmin (Hamrock and "
               "Dowson, 1977; rolling along x); NaN without viscosity",
               label="minimum film thickness"),
    ),
    constraints=(
        Constraint(("curvature_1x", "curvature_1y", "curvature_2x", "curvature_2y"),
                   _point_contact, "the bodies must touch at a point: curvature_1x + "
                   "curvature_2x and curvature_1y + curvature_2y must both be positive (zero is "
                   "a line contact)"),
    ),
    seconds_per_point=7e-7,  # measured by benchmarks/declared_costs.py
    validity="a semi-axis above 0.5 of the smallest radius of curvature of either body "
             "(Hertz: a small contact on half-spaces) or a maximum pressure above 4200 MPa "
             "(ISO 76's reference stress for the point contacts of ball bearings; bearing "
             "steel); with formula hamrock_brewe, a radius ratio Ry/Rx above 70 (beyond it "
             "the closed forms err by more than 3 % against the exact ellipse); with a "
             "viscosity, oil entrained along the ellipse's major axis (Rx > Ry: Hamrock and "
             "Dowson fitted contacts entrained along the minor axis, k = 1 to 8)",
)]
