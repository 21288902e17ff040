"""Oil and traction: viscosity against temperature and pressure, EHL film thickness of line
and elliptical contacts, and the traction curve of a lubricated rolling contact against
sliding speed."""
from __future__ import annotations

import numpy as np

from .solvers import solve_increasing

CELSIUS = 273.15
#: Kinematic viscosities at 40 deg C of the ISO viscosity grades, VG 2 (1.98-2.42 mm^2/s) to
#: VG 3200 (2880-3520 mm^2/s), ISO 3448:1992 Table 1: the oils a bearing runs in [mm^2/s].
VISCOSITY_GRADES = (1.98, 3520.0)
#: Walther's law takes log10(log10(nu + 0.7)) with nu in mm^2/s: defined above 0.3 mm^2/s.
WALTHER_FLOOR = 0.3
#: Densities of lubricating oils [kg/m^3]: from light mineral oils (about 820 at 15 deg C) to
#: perfluoropolyethers (about 1900), with room on both sides; an oil outside it is a slip of
#: units.
OIL_DENSITIES = (600.0, 2000.0)


#: Viscosity indices real lubricants have [-], with room on both sides: naphthenic mineral
#: oils reach down to about 0 and a few below, paraffinic ones 80-120, hydrocracked and
#: synthetic hydrocarbons, esters and polyglycols up to about 250, silicone fluids, the
#: highest, about 400 (L. R. Rudnick (ed.), Synthetics, Mineral Oils, and Bio-Based
#: Lubricants, 3rd ed., CRC Press (2020)). Beyond them the two viscosities are no oil's.
VISCOSITY_INDEX_RANGE = (-100.0, 500.0)
#: ISO 2909 / ASTM D2270 Table 1: the viscosities at 40 deg C of the reference oils of
#: viscosity index 0 (L) and 100 (H) that have the kinematic viscosity Y at 100 deg C, all in
#: mm^2/s, at the table's rows listed here; between them log-log interpolation stays within
#: 0.2 % of every row of the table (2-70 mm^2/s). Above 70 the standard's own formulas.
_VI_ROWS = np.array([2.0, 2.3, 2.8, 3.4, 4.0, 4.2, 4.4, 5.1, 5.5, 5.9, 6.5, 7.1, 7.5, 8.6,
                     14.9, 20.2, 30.0, 41.5, 57.0, 70.0])
_VI_L = np.array([7.994, 10.0, 13.8, 19.12, 25.32, 27.75, 30.48, 41.99, 49.09, 56.2, 67.12,
                  80.25, 88.85, 113.9, 293.0, 501.5, 1023.0, 1851.0, 3340.0, 4905.0])
_VI_H = np.array([6.394, 7.944, 10.87, 14.93, 19.56, 21.21, 22.92, 29.46, 33.34, 37.23,
                  43.18, 49.61, 53.98, 66.48, 148.2, 233.0, 421.7, 689.1, 1127.0, 1558.0])


def viscosity_index(viscosity_40, viscosity_100):
    """Viscosity index of an oil (ISO 2909, ASTM D2270, procedures A and B).

    Parameters
    ----------
    viscosity_40, viscosity_100 : array_like
        Kinematic viscosity at 40 and 100 deg C [m^2/s].

    Returns
    -------
    numpy.ndarray
        ``VI = 100 (L - U) / (L - H)`` where ``U`` (the viscosity at 40 deg C) exceeds ``H``,
        else ``VI = (10^N - 1) / 0.00715 + 100`` with ``N = (log H - log U) / log Y``, ``Y``
        the viscosity at 100 deg C, all in mm^2/s [-]; NaN below ``Y = 2`` mm^2/s, where the
        standard defines none.

    References
    ----------
    .. [1] ISO 2909:2002, Petroleum products - Calculation of viscosity index from kinematic
       viscosity; ASTM D2270-10, Table 1 and sections 6-7.
    """
    lower = np.asarray(viscosity_100, dtype=float) * 1e6
    return np.where(lower >= _VI_ROWS[0], _index(viscosity_40, viscosity_100), np.nan)


def _index(viscosity_40, viscosity_100):
    """:func:`viscosity_index`, and below ``Y = 2`` mm^2/s procedure A's ``100 (L - U) /
    (L - H)`` with the reference oils' lines continued as the table's first rows run
    (log-log), so that a thin oil can still be told from none."""
    upper = np.asarray(viscosity_40, dtype=float) * 1e6
    lower = np.asarray(viscosity_100, dtype=float) * 1e6
    rows = np.log(_VI_ROWS)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        logs = np.log(lower)

        def reference(column, formula):
            logs_of = np.log(column)
            slope = (logs_of[1] - logs_of[0]) / (rows[1] - rows[0])
            table = np.where(logs < rows[0], logs_of[0] + slope * (logs - rows[0]),
                             np.interp(logs, rows, logs_of))
            return np.where(lower > _VI_ROWS[-1], formula, np.exp(table))

        low = reference(_VI_L, 0.8353 * lower**2 + 14.67 * lower - 216.0)
        high = reference(_VI_H, 0.1684 * lower**2 + 11.85 * lower - 97.0)
        below_100 = 100.0 * (low - upper) / (low - high)
        exponent = (np.log10(high) - np.log10(upper)) / np.log10(lower)
        above_100 = (10.0**exponent - 1.0) / 0.00715 + 100.0
        return np.where((upper > high) | (lower < _VI_ROWS[0]), below_100, above_100)


def implausible_viscosity_index(viscosity_40, viscosity_100):
    """Where an oil's viscosities [m^2/s] give a viscosity index outside
    :data:`VISCOSITY_INDEX_RANGE`: no lubricant thins so much, or so little, from 40 to
    100 deg C. Below 2 mm^2/s at 100 deg C, where ISO 2909 defines no index, the reference
    oils' lines are continued (:func:`_index`); False where a viscosity is NaN."""
    index = _index(viscosity_40, viscosity_100)
    with np.errstate(invalid="ignore"):
        return (index < VISCOSITY_INDEX_RANGE[0]) | (index > VISCOSITY_INDEX_RANGE[1])


def viscosities_fall(viscosity_40, viscosity_100):
    """Whether an oil's viscosity at 100 deg C is below that at 40 deg C, as every oil's is
    (its viscosity falls as it warms); Walther's law through swapped values would make it
    thicken with temperature."""
    return np.asarray(viscosity_100) < np.asarray(viscosity_40)


def walther_viscosity(temperature, viscosity_40, viscosity_100):
    """Kinematic viscosity by Walther's law (ASTM D341) through two measured points.

    ``log10 log10(nu + 0.7) = A - B log10(T)`` with ``nu`` in mm^2/s and ``T`` in K.

    Parameters
    ----------
    temperature : array_like
        Oil temperature [K].
    viscosity_40, viscosity_100 : array_like
        Kinematic viscosity at 40 and 100 deg C [m^2/s].

    Returns
    -------
    numpy.ndarray
        Kinematic viscosity [m^2/s].

    References
    ----------
    .. [1] ASTM D341, Standard practice for viscosity-temperature equations for liquid
       petroleum products.
    """
    def walther(nu):
        return np.log10(np.log10(np.asarray(nu) * 1e6 + 0.7))

    low, high = np.log10(40.0 + CELSIUS), np.log10(100.0 + CELSIUS)
    slope = (walther(viscosity_40) - walther(viscosity_100)) / (high - low)
    value = walther(viscosity_40) - slope * (np.log10(temperature) - low)
    return (10.0 ** (10.0**value) - 0.7) * 1e-6


#: Pressure-viscosity coefficient of a mineral oil [1/Pa]: paraffinic and naphthenic mineral
#: oils measure about 15-35 GPa^-1 near 40 deg C (Hamrock, Schmid and Jacobson [1], ch. 4,
#: the table of pressure-viscosity coefficients), less when warmer; the default of the models'
#: film where the oil's own coefficient is not given.
MINERAL_OIL_PRESSURE_VISCOSITY = 20e-9


def entrainment_speed(speed, pitch_diameter, element_diameter, contact_angle=0.0):
    """Mean entrainment speed of a rolling element's raceway contacts, one ring turning.

    ``u = |omega| (d_m^2 - D^2 cos^2 alpha) / (4 d_m)``: the surface speed of either raceway
    relative to the cage, which the rolling element shares, in pure rolling with the cage at
    its kinematic speed ``omega (1 - D cos(alpha) / d_m) / 2`` (the same at both contacts).

    Parameters
    ----------
    speed : array_like
        Speed ``omega`` of the turning ring (the other stands still) [rad/s].
    pitch_diameter, element_diameter : array_like
        ``d_m``, ``D`` [m] (a tapered roller's mean diameter).
    contact_angle : array_like
        ``alpha`` [rad].

    Returns
    -------
    numpy.ndarray
        ``u`` [m/s].

    References
    ----------
    .. [1] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid Film
       Lubrication, 2nd ed., Marcel Dekker (2004), ch. 24 (rolling-element bearings:
       kinematics and the entraining velocity).
    """
    projected = np.asarray(element_diameter) * np.cos(contact_angle)
    return np.abs(speed) * (np.asarray(pitch_diameter) ** 2 - projected**2) / (
        4.0 * np.asarray(pitch_diameter))


def line_contact_film(load, length, radius, speed, viscosity, pressure_viscosity,
                      reduced_modulus):
    """Central and minimum EHL film thickness of an isothermal line contact (Pan and
    Hamrock, 1989).

    ``h_c / R = 2.922 W'^-0.166 U^0.692 G^0.470`` and ``h_min / R = 1.714 W'^-0.128 U^0.694
    G^0.568`` with ``U = eta_0 u / (E' R)``, ``G = alpha E'``, ``W' = Q / (l E' R)``.

    Parameters
    ----------
    load : array_like
        Contact load ``Q`` [N]. length : contact length ``l`` [m]. radius : reduced radius of
        curvature in the rolling direction ``R`` [m]. speed : mean entraining speed ``u``
        [m/s]. viscosity : ``eta_0`` [Pa s]. pressure_viscosity : ``alpha`` [1/Pa].
        reduced_modulus : ``E' = 2 / [(1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2]`` [Pa].

    Returns
    -------
    central, minimum : numpy.ndarray
        ``h_c``, ``h_min`` [m]; zero at rest, NaN where the contact carries no load.

    References
    ----------
    .. [1] P. Pan, B. J. Hamrock, Simple formulas for performance parameters used in
       elastohydrodynamically lubricated line contacts, J. Tribology 111 (1989) 246-251.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        load_parameter = np.asarray(load) / (length * reduced_modulus * radius)
        speed_parameter = viscosity * np.abs(speed) / (reduced_modulus * radius)
        material = pressure_viscosity * reduced_modulus
        central = radius * 2.922 * load_parameter**-0.166 * speed_parameter**0.692 * (
            material) ** 0.470
        minimum = radius * 1.714 * load_parameter**-0.128 * speed_parameter**0.694 * (
            material) ** 0.568
    loaded = np.asarray(load) > 0
    return np.where(loaded, central, np.nan), np.where(loaded, minimum, np.nan)


def point_contact_film(load, radius, ellipticity, speed, viscosity, pressure_viscosity,
                       reduced_modulus):
    """Central and minimum EHL film thickness of an isothermal elliptical contact (Hamrock
    and Dowson, 1977), entrained along the ellipse's minor axis.

    ``h_c / R_x = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^(-0.73 k))`` and ``h_min / R_x =
    3.63 U^0.68 G^0.49 W^-0.073 (1 - e^(-0.68 k))`` with ``U = eta_0 u / (E' R_x)``,
    ``G = alpha E'``, ``W = Q / (E' R_x^2)``, and ``k = a / b`` the contact's own ellipticity
    (the exact Hertz ellipse, rather than the fits ``1.03 (R_y/R_x)^0.64`` of [1] or
    ``(R_y/R_x)^(2/pi)`` of Hamrock and Brewe: the formulas were fitted to numerical solutions
    whose ``k`` was the exact one).

    Parameters
    ----------
    load : array_like
        Contact load ``Q`` [N]. radius : reduced radius of curvature ``R_x`` in the rolling
        direction [m]. ellipticity : ``k = a / b >= 1``, ``a`` across the rolling direction
        [-]. speed : mean entraining speed ``u`` [m/s]. viscosity : ``eta_0`` [Pa s].
        pressure_viscosity : ``alpha`` [1/Pa]. reduced_modulus : ``E'`` [Pa], as for
        :func:`line_contact_film`.

    Returns
    -------
    central, minimum : numpy.ndarray
        ``h_c``, ``h_min`` [m]; zero at rest, NaN where the contact carries no load.

    References
    ----------
    .. [1] B. J. Hamrock, D. Dowson, Isothermal elastohydrodynamic lubrication of point
       contacts, Part III - Fully flooded results, J. Lubrication Technology 99 (1977)
       264-276.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        load_parameter = np.asarray(load) / (reduced_modulus * np.square(radius))
        speed_parameter = viscosity * np.abs(speed) / (reduced_modulus * radius)
        material = pressure_viscosity * reduced_modulus
        central = radius * 2.69 * speed_parameter**0.67 * material**0.53 \
            * load_parameter**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * ellipticity))
        minimum = radius * 3.63 * speed_parameter**0.68 * material**0.49 \
            * load_parameter**-0.073 * (1.0 - np.exp(-0.68 * ellipticity))
    loaded = np.asarray(load) > 0
    return np.where(loaded, central, np.nan), np.where(loaded, minimum, np.nan)


class TractionCurve:
    """Traction coefficient against sliding speed, ``mu(u) = (A + B u) exp(-C u) + D``.

    Gupta's form (ADORE family): zero at no slip, a peak ``mu_m`` at ``u_m``, tending to
    ``mu_inf`` at high slip; odd in ``u``. ``D = mu_inf``, ``A = -mu_inf``,
    ``C = B / (A + B u_m)``, and ``B`` from the peak, through ``s = A + B u_m``:
    ``s exp(A/s - 1) = mu_m - mu_inf``.

    Parameters
    ----------
    peak, peak_speed, limit : array_like
        ``mu_m`` [-], ``u_m`` [m/s], ``mu_inf`` [-] with ``mu_m > mu_inf >= 0``.

    References
    ----------
    .. [1] P. K. Gupta, Advanced Dynamics of Rolling Elements, Springer (1984), ch. 3.
    """

    def __init__(self, peak, peak_speed, limit):
        peak, peak_speed, limit = np.broadcast_arrays(*(np.atleast_1d(np.asarray(
            a, dtype=float)) for a in (peak, peak_speed, limit)))
        self.a, self.d = -limit, limit
        rise = peak - limit

        def condition(s, index):  # s exp(A/s - 1) - (mu_m - mu_inf), increasing in s > 0
            growth = np.exp(self.a[index] / s - 1.0)
            return s * growth - rise[index], growth * (1.0 - self.a[index] / s)

        top = np.maximum(10.0 * rise * np.e + limit, 1.0)
        s, _ = solve_increasing(condition, np.full(peak.shape, 1e-12), top, 0.5 * top,
                                1e-15 * top)
        self.b = (s - self.a) / peak_speed
        self.c = self.b / s

    def __call__(self, sliding, index=slice(None)):
        """``mu`` and ``dmu/du`` at the sliding speeds ``sliding`` [m/s] of points ``index``
        (the points along the first axis, broadcast against the rest)."""
        shape = (-1,) + (1,) * (np.ndim(sliding) - 1)
        a, b, c, d = (v[index].reshape(shape) for v in (self.a, self.b, self.c, self.d))
        speed = np.abs(sliding)
        decay = np.exp(-c * speed)
        value = (a + b * speed) * decay + d
        slope = decay * (b - c * (a + b * speed))
        return np.sign(sliding) * value, slope
