"""The clearance of a bearing as mounted and running: press fits on the shaft and in the
housing, temperatures, and the centrifugal expansion of the rotating inner ring.

The inputs and outputs every rolling-element model declares alike, and the one function that
turns a bearing's unmounted clearance into its operating clearance. Rings and rolling
elements are bearing steel; shaft and housing of any elastic material. All parts are long
cylinders in plane stress (Lame), which the rings' shoulders and the housing's shape make
stiffer in reality: the raceway diameters stand for the rings' outer (inner ring) and inner
(outer ring) surfaces, so the share of an interference that reaches the raceway is an upper
bound (on a solid shaft of the ring's material, d / d_i of it).
"""
from __future__ import annotations

import numpy as np

from .contact import STIFFEST_SOLID
from .limits import SOFTEST_BEARING_SOLID
from .lubrication import CELSIUS
from .registry import Constraint, Input, Output

#: Temperature at which fits and clearances are stated, ISO 1 [K].
REFERENCE_TEMPERATURE = 20.0 + CELSIUS
#: Linear expansion coefficient of through-hardened bearing steel (100Cr6, AISI 52100) near
#: room temperature [1/K]: 11.5-12.5e-6 in the steelmakers' data sheets.
BEARING_STEEL_EXPANSION = 12e-6
#: Density of bearing steel [kg/m^3].
BEARING_STEEL_DENSITY = 7850.0

_EXPANSIONS = (1e-6, 50e-6)  # [1/K]: invar-like alloys to polymers' low end
_GPA = dict(minimum=SOFTEST_BEARING_SOLID, maximum=STIFFEST_SOLID)

#: Declared after the model's other inputs, in this order (the function's last parameters).
OPERATING_INPUTS = (
    Input("shaft_fit", "um", "diametral interference of inner ring and shaft at 20 degC "
          "(negative: a loose fit); needs bore", default=0.0, minimum=-1000.0, maximum=1000.0,
          label="shaft fit"),
    Input("housing_fit", "um", "diametral interference of outer ring and housing at 20 degC "
          "(negative: a loose fit); needs outside_diameter", default=0.0, minimum=-1000.0,
          maximum=1000.0, label="housing fit"),
    Input("bore", "mm", "bore d of the inner ring, for the shaft fit, the ring's "
          "centrifugal expansion and SKF's friction (its mean diameter (d + D) / 2, "
          "replenishment and drag); default: none (NaN; the pitch diameter for the "
          "friction)", default=None, minimum=0.0, exclusive_minimum=True, label="bore"),
    Input("outside_diameter", "mm", "outside diameter D of the outer ring, for the housing "
          "fit and SKF's friction; default: none", default=None, minimum=0.0,
          exclusive_minimum=True, label="outside diameter"),
    Input("shaft_bore", "mm", "bore of a hollow shaft (0: solid)", default=0.0, minimum=0.0,
          label="shaft bore"),
    Input("housing_outside_diameter", "mm", "outside diameter of the housing around the outer "
          "ring; default: a housing much larger than the ring", default=None, minimum=0.0,
          exclusive_minimum=True, label="housing outside diameter"),
    Input("inner_ring_temperature", "degC", "temperature of the inner ring", default=20.0,
          minimum=-60.0, maximum=250.0, label="inner ring temperature"),
    Input("outer_ring_temperature", "degC", "temperature of the outer ring", default=20.0,
          minimum=-60.0, maximum=250.0, label="outer ring temperature"),
    Input("shaft_temperature", "degC", "temperature of the shaft; default: the inner ring's",
          default=None, minimum=-60.0, maximum=250.0, label="shaft temperature"),
    Input("housing_temperature", "degC", "temperature of the housing; default: the outer "
          "ring's", default=None, minimum=-60.0, maximum=250.0, label="housing temperature"),
    Input("shaft_youngs_modulus", "GPa", "Young's modulus of the shaft (steel 200-210)",
          default=207.0, **_GPA, label="shaft Young's modulus"),
    Input("shaft_poisson_ratio", "1", "Poisson's ratio of the shaft", default=0.3,
          minimum=0.0, maximum=0.5, label="shaft Poisson's ratio"),
    Input("shaft_expansion", "1/K", "linear expansion coefficient of the shaft (steel about "
          "12e-6)", default=BEARING_STEEL_EXPANSION, minimum=_EXPANSIONS[0],
          maximum=_EXPANSIONS[1], label="shaft expansion coefficient"),
    Input("housing_youngs_modulus", "GPa", "Young's modulus of the housing (steel 200-210, "
          "grey cast iron 90-140, aluminium alloys about 70)", default=207.0, **_GPA,
          label="housing Young's modulus"),
    Input("housing_poisson_ratio", "1", "Poisson's ratio of the housing", default=0.3,
          minimum=0.0, maximum=0.5, label="housing Poisson's ratio"),
    Input("housing_expansion", "1/K", "linear expansion coefficient of the housing (steel "
          "about 12e-6, grey cast iron about 10.5e-6, aluminium alloys about 23e-6)",
          default=BEARING_STEEL_EXPANSION, minimum=_EXPANSIONS[0], maximum=_EXPANSIONS[1],
          label="housing expansion coefficient"),
)

OPERATING_OUTPUT_NAMES = ("operating_clearance", "clearance_change_fit",
                          "clearance_change_temperature", "clearance_change_speed",
                          "shaft_fit_remaining", "housing_fit_remaining")


def operating_outputs():
    """Output declarations of :func:`operating_clearance`'s results."""
    return (
        Output("operating_clearance", "mm", "diametral clearance as mounted and running: the "
               "clearance plus the changes by the fits, the temperatures and the speed "
               "(negative: preload); the load distribution takes it",
               label="operating clearance"),
        Output("clearance_change_fit", "um", "change of the clearance by the press fits at "
               "20 degC and at rest; NaN without bore or outside_diameter where a fit is "
               "given", label="clearance change by the fits"),
        Output("clearance_change_temperature", "um", "further change by the temperatures of "
               "rings, rolling elements (their mean), shaft and housing",
               label="clearance change by temperature"),
        Output("clearance_change_speed", "um", "further change by the inner ring's "
               "centrifugal expansion, which also loosens its fit; NaN without bore",
               label="clearance change by speed"),
        Output("shaft_fit_remaining", "um", "interference of inner ring and shaft at "
               "temperature and speed (zero or less: the fit is lost and the ring may creep); "
               "NaN without bore", label="shaft fit remaining"),
        Output("housing_fit_remaining", "um", "interference of outer ring and housing at "
               "temperature; NaN without outside_diameter", label="housing fit remaining"),
    )


def operating_constraints(element, angle=None):
    """The conditions between the operating inputs, checked on a definition before any
    computing (the model's ``ValueError`` says the same of a direct call): a fit needs its
    ring's dimension, and shaft, rings and housing nest around the raceways ``d_m -+`` the
    rolling element's diameter, the input named ``element`` (times the cosine of the input
    named ``angle``, where given: a tapered roller's raceways at its middle)."""
    around = (element,) + ((angle,) if angle else ())
    extent = f"{element} cos({angle})" if angle else element

    def offset(named):
        return named[element] * (np.cos(named[angle]) if angle else 1.0)

    def nested_inside(bore, shaft_bore, pitch_diameter, **named):
        return ~((bore >= pitch_diameter - offset(named)) | (shaft_bore >= bore))

    def nested_outside(outside_diameter, housing_outside_diameter, pitch_diameter, **named):
        return ~((outside_diameter <= pitch_diameter + offset(named))
                 | (housing_outside_diameter <= outside_diameter))

    return (
        Constraint(("shaft_fit", "bore"), lambda shaft_fit, bore: (shaft_fit == 0)
                   | np.isfinite(bore), "shaft_fit needs bore: the fit's effect on the "
                   "clearance depends on the ring's wall", unset=True),
        Constraint(("housing_fit", "outside_diameter"), lambda housing_fit, outside_diameter:
                   (housing_fit == 0) | np.isfinite(outside_diameter), "housing_fit needs "
                   "outside_diameter: the fit's effect on the clearance depends on the ring's "
                   "wall", unset=True),
        Constraint(("bore", "shaft_bore", "pitch_diameter") + around, nested_inside,
                   f"bore must lie between shaft_bore and the inner raceway's diameter "
                   f"(pitch_diameter - {extent})",
                   unset=True),
        Constraint(("outside_diameter", "housing_outside_diameter", "pitch_diameter") + around,
                   nested_outside, f"outside_diameter must lie between the outer raceway's "
                   f"diameter (pitch_diameter + {extent}) and housing_outside_diameter",
                   unset=True),
    )


def lame_fit_pressure(interference, diameter, inner_bore, outer_diameter, inner_modulus,
                      inner_poisson, outer_modulus, outer_poisson):
    """Contact pressure of a press fit of two thick-walled cylinders (Lame, plane stress).

    ``p = I / (d [(1/E_o)((c^2 + d^2)/(c^2 - d^2) + nu_o) + (1/E_i)((d^2 + a^2)/(d^2 - a^2)
    - nu_i)])`` with ``a``, ``d``, ``c`` the diameters of the inner member's bore, the
    interface and the outer member's outside.

    Parameters
    ----------
    interference : array_like
        Diametral interference ``I`` [m]; a negative one (a gap) gives no pressure.
    diameter : array_like
        Interface diameter ``d`` [m].
    inner_bore, outer_diameter : array_like
        ``a`` (0: solid) and ``c`` (inf: an outer member much larger) [m].
    inner_modulus, inner_poisson, outer_modulus, outer_poisson : array_like
        Young's moduli [Pa] and Poisson's ratios [-] of the inner and outer member.

    Returns
    -------
    numpy.ndarray
        ``p`` [Pa].

    References
    ----------
    .. [1] R. G. Budynas, J. K. Nisbett, Shigley's Mechanical Engineering Design, 10th ed.,
       McGraw-Hill (2015), sec. 3-16 (press and shrink fits).
    """
    d2 = np.square(diameter)
    with np.errstate(divide="ignore", invalid="ignore"):
        outer_ratio = np.where(np.isinf(outer_diameter), 1.0,
                               (np.square(outer_diameter) + d2) / (np.square(outer_diameter) - d2))
        inner_ratio = (d2 + np.square(inner_bore)) / (d2 - np.square(inner_bore))
    compliance = ((outer_ratio + outer_poisson) / outer_modulus
                  + (inner_ratio - inner_poisson) / inner_modulus)
    return np.maximum(interference, 0.0) / (np.asarray(diameter) * compliance)


def ring_growth_by_pressure(pressure, loaded_diameter, free_diameter, modulus):
    """Diametral change of a ring's free surface under a pressure on its other surface
    (Lame, plane stress): ``2 p d_l^2 d_f / (E |d_f^2 - d_l^2|)``, a growth of an inner
    ring's outside under a pressure in its bore, and equally a shrinkage of an outer ring's
    bore under a pressure on its outside [m]."""
    loaded, free = np.square(loaded_diameter), np.asarray(free_diameter)
    return 2.0 * pressure * loaded * free / (modulus * np.abs(np.square(free) - loaded))


def rotating_ring_growth(diameter, bore, outside, speed, density, modulus, poisson):
    """Diametral growth at ``diameter`` of a free ring (``bore`` to ``outside``; ``bore`` 0:
    a solid shaft) turning at ``speed`` [rad/s], plane stress.

    ``u(r) = rho w^2 / (8 E) [(3 + nu)(1 - nu)(a^2 + c^2) r + (3 + nu)(1 + nu) a^2 c^2 / r
    - (1 - nu^2) r^3]`` with ``a``, ``c`` the inner and outer radius (Timoshenko and Goodier,
    Theory of Elasticity, 3rd ed., sec. 32); returns ``2 u`` [m].
    """
    r, a, c = (0.5 * np.asarray(x, dtype=float) for x in (diameter, bore, outside))
    factor = density * np.square(speed) / (8.0 * modulus)
    return 2.0 * factor * ((3.0 + poisson) * (1.0 - poisson) * (a**2 + c**2) * r
                           + (3.0 + poisson) * (1.0 + poisson) * a**2 * c**2 / r
                           - (1.0 - poisson**2) * r**3)


def operating_clearance(clearance, inner_raceway, outer_raceway, element_diameter, speed,
                        youngs_modulus, poisson_ratio, shaft_fit, housing_fit, bore,
                        outside_diameter, shaft_bore, housing_outside_diameter,
                        inner_ring_temperature, outer_ring_temperature, shaft_temperature,
                        housing_temperature, shaft_youngs_modulus, shaft_poisson_ratio,
                        shaft_expansion, housing_youngs_modulus, housing_poisson_ratio,
                        housing_expansion):
    """A bearing's diametral clearance as mounted and running, and its parts.

    Parameters
    ----------
    clearance : array_like
        Unmounted diametral clearance at 20 deg C ``P_d`` [m].
    inner_raceway, outer_raceway, element_diameter : array_like
        Raceway diameters ``d_i``, ``d_o`` and rolling element diameter ``D_w`` [m].
    speed : array_like
        Inner ring's (and shaft's) speed [rad/s]; the outer ring stands still.
    youngs_modulus, poisson_ratio : array_like
        Of the rings [Pa], [-].
    shaft_fit, housing_fit : array_like
        Diametral interferences at 20 deg C [m] (negative: loose).
    bore, outside_diameter : array_like
        The inner ring's bore ``d`` and the outer ring's outside ``D`` [m]; NaN: unknown.
    shaft_bore, housing_outside_diameter : array_like
        [m]; NaN housing: much larger than the ring.
    inner_ring_temperature, outer_ring_temperature, shaft_temperature, housing_temperature
        [K]; a NaN shaft (housing) temperature is the inner (outer) ring's.
    shaft_youngs_modulus, shaft_poisson_ratio, shaft_expansion, housing_youngs_modulus,
    housing_poisson_ratio, housing_expansion : array_like
        [Pa], [-], [1/K].

    Returns
    -------
    dict of numpy.ndarray
        :data:`OPERATING_OUTPUT_NAMES` [m]; and ``fit_lost``, where a tight shaft or housing
        fit has no interference left (the ring may creep).

    Notes
    -----
    In turn: the fits' interferences at temperature, ``I_s + d (a_s (T_s - 20) - a_r (T_i -
    20))`` and ``I_h + D (a_r (T_o - 20) - a_h (T_h - 20))``; the shaft fit less the
    difference of the free centrifugal growths of ring bore and shaft at speed; the fit
    pressures by Lame (:func:`lame_fit_pressure`) and the raceways' growth or shrinkage
    (:func:`ring_growth_by_pressure`); the free thermal growth of the raceways and rolling
    elements (at the mean of the rings' temperatures); the inner raceway's own centrifugal
    growth. The clearance falls by the inner raceway's growth and the outer's shrinkage and
    twice the rolling elements' growth. The parts are the changes from the unmounted bearing
    to the mounted one at 20 deg C and rest, on to the temperatures, and on to the speed.

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., ch. 3 (clearance
       by interference fits and by temperature).
    .. [2] Shigley's Mechanical Engineering Design, sec. 3-16 (press fits), 3-15 (rotating
       rings).
    """
    ring = BEARING_STEEL_EXPANSION
    shaft_temperature = np.where(np.isnan(shaft_temperature), inner_ring_temperature,
                                 shaft_temperature)
    housing_temperature = np.where(np.isnan(housing_temperature), outer_ring_temperature,
                                   housing_temperature)
    housing = np.where(np.isnan(housing_outside_diameter), np.inf, housing_outside_diameter)
    warm_inner = inner_ring_temperature - REFERENCE_TEMPERATURE
    warm_outer = outer_ring_temperature - REFERENCE_TEMPERATURE

    def clearance_change(hot, turning):
        """Clearance change and remaining fits at temperature (``hot``) and speed."""
        shaft = shaft_fit + hot * bore * (
            shaft_expansion * (shaft_temperature - REFERENCE_TEMPERATURE) - ring * warm_inner)
        housed = housing_fit + hot * outside_diameter * (
            ring * warm_outer - housing_expansion * (housing_temperature - REFERENCE_TEMPERATURE))
        centrifugal = 0.0
        if turning:
            ring_bore = rotating_ring_growth(bore, bore, inner_raceway, speed,
                                             BEARING_STEEL_DENSITY, youngs_modulus, poisson_ratio)
            shaft_surface = rotating_ring_growth(bore, shaft_bore, bore, speed,
                                                 BEARING_STEEL_DENSITY, shaft_youngs_modulus,
                                                 shaft_poisson_ratio)
            shaft = shaft - (ring_bore - shaft_surface)
            centrifugal = rotating_ring_growth(inner_raceway, bore, inner_raceway, speed,
                                               BEARING_STEEL_DENSITY, youngs_modulus,
                                               poisson_ratio)
        inner_pressure = lame_fit_pressure(shaft, bore, shaft_bore, inner_raceway,
                                           shaft_youngs_modulus, shaft_poisson_ratio,
                                           youngs_modulus, poisson_ratio)
        outer_pressure = lame_fit_pressure(housed, outside_diameter, outer_raceway, housing,
                                           youngs_modulus, poisson_ratio,
                                           housing_youngs_modulus, housing_poisson_ratio)
        inner_growth = ring_growth_by_pressure(inner_pressure, bore, inner_raceway,
                                               youngs_modulus)
        outer_shrinkage = ring_growth_by_pressure(outer_pressure, outside_diameter,
                                                  outer_raceway, youngs_modulus)
        # An unknown ring carries no fit (a given one is refused without it).
        inner_growth = np.where(shaft_fit == 0, np.nan_to_num(inner_growth), inner_growth)
        outer_shrinkage = np.where(housing_fit == 0, np.nan_to_num(outer_shrinkage),
                                   outer_shrinkage)
        thermal = hot * ring * (outer_raceway * warm_outer - inner_raceway * warm_inner
                                - element_diameter * (warm_inner + warm_outer))
        return -inner_growth - outer_shrinkage + thermal - centrifugal, shaft, housed

    with np.errstate(all="ignore"):  # IEEE results; an absurd speed is flagged by the model
        mounted, _, _ = clearance_change(0.0, False)
        warm, _, _ = clearance_change(1.0, False)
        running, shaft, housed = clearance_change(1.0, True)
    speed_part = running - warm
    # Without the ring's dimensions the centrifugal growth is unknown: left out, NaN.
    total = np.where(np.isnan(bore), warm, running)
    return {
        "operating_clearance": clearance + total,
        "clearance_change_fit": mounted,
        "clearance_change_temperature": warm - mounted,
        "clearance_change_speed": speed_part,
        "shaft_fit_remaining": shaft,
        "housing_fit_remaining": housed,
        "fit_lost": ((shaft_fit > 0) & ~(shaft > 0)) | ((housing_fit > 0) & ~(housed > 0)),
    }


def mounted_clearance(clearance, inner_raceway, outer_raceway, element_diameter, speed,
                      youngs_modulus, poisson_ratio, *operating):
    """:func:`operating_clearance` of a model's flat ``(N,)`` arrays and its own
    :data:`OPERATING_INPUTS` (``operating``, in their order, each an array or None), with
    the checks a model makes of them: a fit needs the ring it presses on, and the ring must
    hold the raceway (a ``ValueError`` names what is wrong)."""
    values = [np.broadcast_to(np.asarray(np.nan if value is None else value, dtype=float),
                              np.shape(clearance)) for value in operating]
    named = dict(zip((item.name for item in OPERATING_INPUTS), values))
    for fit, ring in (("shaft_fit", "bore"), ("housing_fit", "outside_diameter")):
        if np.any((named[fit] != 0) & np.isnan(named[ring])):
            raise ValueError(f"{fit} needs {ring}: the fit's effect on the clearance depends "
                             "on the ring's wall")
    with np.errstate(invalid="ignore"):
        walls = ((named["bore"] >= inner_raceway) | (named["outside_diameter"] <= outer_raceway)
                 | (named["shaft_bore"] >= named["bore"])
                 | (named["housing_outside_diameter"] <= named["outside_diameter"]))
    if np.any(walls):
        raise ValueError("the rings and their seats do not nest: shaft_bore < bore < the inner "
                         "raceway's diameter and the outer raceway's < outside_diameter < "
                         "housing_outside_diameter")
    return operating_clearance(clearance, inner_raceway, outer_raceway, element_diameter, speed,
                               youngs_modulus, poisson_ratio, *values)
