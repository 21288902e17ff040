"""Static safety as a bearing model reports it: the input and output every model that loads
rolling elements declares alike, and the one function that forms them from its largest
contact pressure.

ISO 76 sets a bearing's basic static load rating C0 at the load that raises the contact
pressure of its most loaded rolling element to a reference stress: 4200 MPa for ball bearings
(other than self-aligning ones), 4000 MPa for roller bearings, where the permanent deformation
of rolling element and raceway together reaches about 1e-4 of the rolling element's
diameter. A model that knows its load distribution knows that pressure itself: the factor by
which its most loaded contact's load may grow before it reaches the reference stress is
``(p_ref / p_max)^3`` for a point contact (``p_0`` grows as ``Q^(1/3)``) and ``(p_ref /
p_max)^2`` for a line contact (as ``w^(1/2)``).
"""
from __future__ import annotations

import numpy as np

from .contact import BALL_PRESSURE_LIMIT, ROLLER_PRESSURE_LIMIT
from .registry import Input, Output

#: ISO 76's reference stress and how a contact's load grows with its pressure, by contact.
_REFERENCES = {"ball": (BALL_PRESSURE_LIMIT, 3.0), "roller": (ROLLER_PRESSURE_LIMIT, 2.0)}

#: Declared after the film inputs (the function's last parameter).
STATIC_INPUTS = (
    Input("minimum_static_safety", "1", "smallest static safety the application needs: a "
          "point whose pressure_safety_factor is below it is out of validity, values kept "
          "(catalogues ask about 1 for quiet running, 2 or more for shock loads and "
          "demands on running accuracy; up to 20); default: no check", default=None,
          minimum=0.0, exclusive_minimum=True, maximum=20.0, label="minimum static safety"),
)

STATIC_OUTPUT_NAMES = ("pressure_safety_factor",)
#: The outputs of ISO 76's static load rating, for roller bearings.
RATING_OUTPUT_NAMES = ("static_load_rating", "static_equivalent_load", "static_safety_factor")
#: ISO 76:2006, 5.1: the factor of a radial roller bearing's rating [N/mm^2].
_ROLLER_RATING_FACTOR = 44e6  # [Pa]


def static_outputs(kind):
    """Output declarations of :func:`static_safety`'s results for ``kind`` ('ball' or
    'roller') bearings; roller bearings' include ISO 76's rating (:func:`roller_rating`)."""
    reference, exponent = _REFERENCES[kind]
    pressure = (
        Output("pressure_safety_factor", "1", "static safety from the load distribution: "
               f"(p_ref / p_max)^{exponent:g}, the factor by which the most loaded contact's "
               f"load may grow before its pressure reaches ISO 76's reference stress p_ref = "
               f"{reference / 1e6:g} MPa (that of the static load rating C0)",
               label="static safety from contact pressure"),
    )
    rating, equivalent = {
        "roller": ("C0r = 44 (1 - D cos a / dm) Z l D cos a (ISO 76:2006, 5.1; N, mm)",
                   "ISO 76:2006, 5.2: Fr at a = 0; else the larger of Fr and 0.5 Fr + 0.22 "
                   "cot(a) Fa"),
        "ball": ("C0r = f0 Z D^2 cos a (ISO 76:2006, 4.1), f0 from its Hertz basis: 4200 MPa "
                 "at the load 5 Fr / (Z cos a), grooves 0.52 D and 0.53 D",
                 "ISO 76:2006, 4.2: the larger of Fr and X0 Fr + Y0 Fa, X0 = 0.6 and Y0 = 0.5 "
                 "at a = 0, X0 = 0.5 and Y0 of the contact angle from 15 to 45 deg; NaN under "
                 "a moment or with an axial load at other angles"),
    }[kind]
    return pressure + (
        Output("static_load_rating", "kN", f"basic static radial load rating {rating}",
               label="static load rating C0r"),
        Output("static_equivalent_load", "N", f"static equivalent radial load P0r ({equivalent})",
               label="static equivalent load P0r"),
        Output("static_safety_factor", "1", "static safety factor s0 = C0r / P0r, as "
               "catalogues form it (infinite without load)", label="static safety s0"),
    )


#: ISO 76:2006, 4.2: Y0 of single-row angular contact ball bearings by nominal contact angle
#: [deg, -], with X0 = 0.5.
_BALL_Y0 = np.array([[15.0, 0.46], [20.0, 0.42], [25.0, 0.38], [30.0, 0.33], [35.0, 0.29],
                     [40.0, 0.26], [45.0, 0.22]])
#: The groove radii over the ball diameter behind ISO 76's f0 of radial and angular contact
#: groove ball bearings (inner, outer).
_ISO_GROOVES = (0.52, 0.53)
#: The load share of the most loaded rolling element behind ISO 76's ratings, Q_max Z cos a / F
#: (Stribeck's 5; ISO/TR 10657).
_STRIBECK = 5.0


def ball_rating(ball_count, ball_diameter, pitch_diameter, contact_angle, radial_load,
                axial_load, moment_load):
    """ISO 76's static load rating, equivalent load and safety of a single-row radial or
    angular contact groove ball bearing.

    ``C0r = f0 Z D^2 cos a`` with ``f0`` from the basis of ISO 76's Table 1: the radial load
    at which the most loaded ball, carrying ``5 F_r / (Z cos a)``, reaches 4200 MPa at the
    more curved of its contacts, with grooves of 0.52 D (inner) and 0.53 D (outer) and steel
    (E = 207 GPa, nu = 0.3). It reproduces the table's f0 to its printed 0.1 (e.g. 14.7 at
    ``D cos a / dm = 0``, 16.5 at 0.09, 14.0 at 0.2).

    Parameters
    ----------
    ball_count : int
        ``Z``.
    ball_diameter, pitch_diameter : array_like
        ``D_w``, ``D_pw`` [m].
    contact_angle : array_like
        Nominal contact angle ``a`` [rad].
    radial_load, axial_load, moment_load : array_like
        ``F_r``, ``F_a`` [N] and the magnitude of a tilting moment [N m].

    Returns
    -------
    dict of numpy.ndarray
        :data:`RATING_OUTPUT_NAMES`: ``C0r`` [N], ``P0r`` [N] and ``s0`` [-].

    References
    ----------
    .. [1] ISO 76:2006, Rolling bearings - Static load ratings, 4.1 (C0r and its Table 1)
       and 4.2 (P0r).
    .. [2] ISO/TR 10657:1991, Explanatory notes on ISO 76.
    """
    from .contact import hertz_point  # the roller models need no point contact

    diameter = np.asarray(ball_diameter, dtype=float)
    cos_angle = np.cos(contact_angle)
    gamma = diameter * cos_angle / pitch_diameter
    ball = 2.0 / diameter
    unit = np.maximum(*(hertz_point(1.0, ball, ball, rolling, -1.0 / (groove * diameter))[
        "max_pressure"] for rolling, groove in ((ball * gamma / (1.0 - gamma), _ISO_GROOVES[0]),
                                                (-ball * gamma / (1.0 + gamma), _ISO_GROOVES[1]))))
    most_loaded = (BALL_PRESSURE_LIMIT / unit) ** 3  # p0 grows as Q^(1/3)
    rating = most_loaded * ball_count * cos_angle / _STRIBECK
    radial, axial = np.abs(np.asarray(radial_load, dtype=float)), np.abs(axial_load)
    degrees = np.degrees(np.asarray(contact_angle, dtype=float))
    angles, factors = _BALL_Y0.T
    combined = np.where(degrees == 0.0, 0.6 * radial + 0.5 * axial,
                        0.5 * radial + np.interp(degrees, angles, factors) * axial)
    known = (((degrees == 0.0) | ((degrees >= angles[0] - 1e-9) & (degrees <= angles[-1] + 1e-9))
              | (axial == 0.0)) & (np.asarray(moment_load, dtype=float) == 0.0))
    load = np.where(known, np.maximum(radial, combined), np.nan)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        safety = rating / load
    return {"static_load_rating": rating, "static_equivalent_load": load,
            "static_safety_factor": safety}


def roller_rating(roller_count, effective_length, roller_diameter, pitch_diameter,
                  contact_angle, radial_load, axial_load):
    """ISO 76's static load rating, equivalent load and safety of a single-row radial roller
    bearing.

    Parameters
    ----------
    roller_count : int
        ``Z``.
    effective_length, roller_diameter, pitch_diameter : array_like
        ``L_we``, ``D_we`` (a tapered roller's mean diameter), ``D_pw`` [m].
    contact_angle : array_like
        Nominal contact angle ``a`` [rad] (0: a cylindrical roller bearing).
    radial_load, axial_load : array_like
        ``F_r``, ``F_a`` [N].

    Returns
    -------
    dict of numpy.ndarray
        :data:`RATING_OUTPUT_NAMES`: ``C0r = 44 (1 - D_we cos a / D_pw) Z L_we D_we cos a``
        [N] (the constant in N/mm^2), ``P0r`` [N] and ``s0 = C0r / P0r`` [-].

    References
    ----------
    .. [1] ISO 76:2006, Rolling bearings - Static load ratings, 5.1 (C0r of radial roller
       bearings) and 5.2 (P0r: X0 = 0.5, Y0 = 0.22 cot a for single-row bearings with
       a != 0, and P0r = Fr where that is larger).
    """
    cos_angle = np.cos(contact_angle)
    rating = (_ROLLER_RATING_FACTOR * (1.0 - roller_diameter * cos_angle / pitch_diameter)
              * roller_count * effective_length * roller_diameter * cos_angle)
    radial, axial = np.asarray(radial_load, dtype=float), np.abs(axial_load)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        combined = 0.5 * radial + 0.22 * axial / np.tan(contact_angle)
        load = np.where(np.asarray(contact_angle) == 0, radial, np.maximum(radial, combined))
        safety = rating / load
    return {"static_load_rating": rating, "static_equivalent_load": load,
            "static_safety_factor": safety}


def static_safety(largest_pressure, kind, minimum_static_safety):
    """The static safety outputs, and where they fall below the required minimum.

    Parameters
    ----------
    largest_pressure : array_like
        The model's largest contact pressure ``p_max`` [Pa].
    kind : {'ball', 'roller'}
    minimum_static_safety : array_like or None
        The smallest factor the application needs [-]; None: no check.

    Returns
    -------
    outputs : dict of numpy.ndarray
        ``pressure_safety_factor`` ``(p_ref / p_max)^n`` [-] (infinite without load).
    below : numpy.ndarray of bool
        Where the factor lies below ``minimum_static_safety`` (False without one).

    References
    ----------
    .. [1] ISO 76:2006, Rolling bearings - Static load ratings, 3.1 (the reference
       stresses).
    """
    reference, exponent = _REFERENCES[kind]
    with np.errstate(divide="ignore", over="ignore"):
        factor = (reference / np.asarray(largest_pressure, dtype=float)) ** exponent
    required = np.nan if minimum_static_safety is None else minimum_static_safety
    with np.errstate(invalid="ignore"):
        below = factor < np.asarray(required, dtype=float)
    return {"pressure_safety_factor": factor}, below
