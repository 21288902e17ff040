"""What real rolling bearings are made of, how fast they run and how much play they have: the
limits beyond which the models' inputs describe no bearing, shared by the models.

Each limit says where it comes from. A single input beyond what any bearing has is refused
by its declared range; a point whose inputs together describe no bearing (a speed factor,
a clearance for its size, a steel contact constant for another material) is flagged
``out_of_validity``.
"""
from __future__ import annotations

import numpy as np

from .lubrication import implausible_viscosity_index

#: Densities of the materials rolling elements are made of [kg/m^3]: from polypropylene
#: (900-910; polymer balls and rollers of polypropylene, polyethylene, polyamide and acetal lie
#: at 900-1420) to tungsten carbide (15 630 for pure WC, 14 500-15 000 with a cobalt binder),
#: the densest; steel is 7800-7850, silicon nitride 3200, zirconia 6000 (CRC Handbook of
#: Chemistry and Physics). A hollow roller weighs less than a solid one of its size, but
#: hollowness of more than half the diameter is rare: its mean density stays above 900.
ROLLING_ELEMENT_DENSITIES = (900.0, 15700.0)
#: Densities of cage materials [kg/m^3]: from polyamide 66 (1140; phenolic resin and PEEK
#: about 1300, light alloys 2700) to the copper alloys of machined cages (brass 8400-8730,
#: bronze up to 8900), below copper itself (8960).
CAGE_DENSITIES = (900.0, 9000.0)

#: The softest material rolling elements, rings and cages are made of, PTFE (E of 0.4-0.55
#: GPa; polyamide 2-3, acetal 3, PEEK 3.6): a bearing of softer solids is a slip of units
#: (1e-6 GPa was taken) [GPa, the unit the models declare].
SOFTEST_BEARING_SOLID = 0.4

#: The speed factor n dm [mm r/min] of the fastest rolling bearings, with room above it:
#: main-shaft bearings of jet engines ran at 3e6 DN (bore in mm times r/min) in NASA's
#: endurance tests (120-mm bore, 25 000 r/min: E. N. Bamberger, E. V. Zaretsky, H. Signer,
#: J. Lubr. Technol. 98 (1976) 580-585), about 3.6e6 as n dm; oil-air lubricated hybrid
#: spindle bearings reach about 3.5e6. Beyond 4e6 no bearing has run: its cage, its rollers'
#: centrifugal force and its lubrication are outside what the models take.
SPEED_FACTOR_LIMIT = 4e6


def beyond_speed_factor(speed, pitch_diameter):
    """Where ``n d_m`` exceeds :data:`SPEED_FACTOR_LIMIT` (``speed`` [rad/s] of the rotating
    ring, ``pitch_diameter`` [m]; False where either is NaN)."""
    factor = np.abs(np.asarray(speed, dtype=float)) * 30.0 / np.pi * 1e3 * np.asarray(
        pitch_diameter, dtype=float)
    return factor > SPEED_FACTOR_LIMIT


def outside_operation(speed, pitch_diameter, viscosity_40, viscosity_100):
    """Where a bearing runs as no bearing does: a speed factor beyond
    :data:`SPEED_FACTOR_LIMIT`, or an oil whose viscosities give a viscosity index no
    lubricant has (:func:`models.lubrication.implausible_viscosity_index`; None: no oil)."""
    oil = np.zeros(1, dtype=bool) if viscosity_40 is None or viscosity_100 is None else \
        implausible_viscosity_index(viscosity_40, viscosity_100)
    return beyond_speed_factor(speed, pitch_diameter) | oil


#: The elastic constants of the steel the default contact constants are for: Palmgren's line
#: contact (8.06e4 l^(8/9), T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
#: ch. 6) and paper 003's eq. 14 (its Table 1: 206 GPa, 0.3) were fitted to steel rollers on
#: steel rings.
STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO = 207e9, 0.3
#: Largest relative departure of E* = E / (2 (1 - nu^2)) from the steel's (113.7 GPa) with
#: which a steel contact constant holds: bearing steels (52100 / 100Cr6, M50, 440C,
#: case-carburising grades) have E of 190-215 GPa and nu of 0.27-0.30 (ASM Handbook vol. 1),
#: within -9 % and +3 % of it; silicon nitride (310 GPa) is 19 % stiffer in a hybrid contact.
STEEL_MODULUS_BAND = 0.1


def not_steel(youngs_modulus, poisson_ratio):
    """Where rollers and rings of ``youngs_modulus`` [Pa] and ``poisson_ratio`` are too far
    from steel for a steel contact constant: their E* beyond :data:`STEEL_MODULUS_BAND`.

    The load that gives an approach scales with E* (elastic similarity: the same geometry
    with E* times k carries k times the load at the same approach), so a contact constant
    fitted to steel holds for another material times E* / E*_steel; the models take the
    constant as given and flag the point rather than scale a fit outside its data.
    """
    modulus = np.asarray(youngs_modulus, dtype=float) / (
        1.0 - np.asarray(poisson_ratio, dtype=float) ** 2)
    steel = STEEL_YOUNGS_MODULUS / (1.0 - STEEL_POISSON_RATIO**2)
    return np.abs(modulus / steel - 1.0) > STEEL_MODULUS_BAND


#: The largest radial internal clearance of cylindrical roller bearings with a cylindrical
#: bore, group 5 (C5) of ISO 5753-1:2009 (as the makers' catalogues reprint it), for bores up
#: to each of these diameters [mm] and its upper value [um]. The table's last rows grow in
#: proportion to the bore (1.265 mm at 900 mm, 1.405 mm at 1000 mm): beyond it the limit
#: grows so.
_C5_BORES = np.array([24, 30, 40, 50, 65, 80, 100, 120, 140, 160, 180, 200, 225, 250, 280,
                      315, 355, 400, 450, 500, 560, 630, 710, 800, 900, 1000], dtype=float)
_C5_LARGEST = np.array([90, 95, 105, 125, 140, 165, 190, 220, 245, 275, 300, 330, 365, 395,
                        440, 485, 535, 600, 665, 735, 810, 900, 1005, 1135, 1265, 1405],
                       dtype=float)


def largest_clearance(bore):
    """The largest radial internal clearance ISO 5753-1 gives a cylindrical roller bearing of
    ``bore`` [m] (group 5, the largest group), [m]; NaN where ``bore`` is.

    A model that knows the inner raceway diameter rather than the bore passes that: it
    exceeds the bore, so the row it finds is the bearing's or a larger one, never a smaller.
    """
    bore = np.asarray(bore, dtype=float) * 1e3
    row = np.minimum(np.searchsorted(_C5_BORES, np.where(np.isnan(bore), 0.0, bore)),
                     _C5_BORES.size - 1)
    beyond = _C5_LARGEST[-1] * bore / _C5_BORES[-1]
    largest = np.where(bore > _C5_BORES[-1], beyond, _C5_LARGEST[row])
    return np.where(np.isnan(bore), np.nan, largest) * 1e-6


def clearance_beyond_bearings(clearance, inner_raceway_diameter):
    """Where a diametral clearance [m] exceeds any that ISO 5753-1 gives a bearing whose inner
    raceway has ``inner_raceway_diameter`` [m] (:func:`largest_clearance`)."""
    return np.asarray(clearance, dtype=float) > largest_clearance(inner_raceway_diameter)


#: The limits above in words, for the models' ``validity``.
SPEED_VALIDITY = ("a speed factor n dm above 4e6 mm r/min (the fastest rolling bearings: "
                  "3e6 DN in NASA's tests of jet-engine main-shaft bearings)")
OIL_VALIDITY = ("an oil whose viscosity index (ISO 2909) lies outside -100 to 500 "
                "(lubricants: from naphthenic oils, about 0, to silicone fluids, about 400)")
STEEL_VALIDITY = ("the default contact constant, fitted to steel, with E* = E / (2 (1 - nu^2)) "
                  "more than 10 % from steel's (207 GPa, 0.3; bearing steels lie within it)")
CLEARANCE_VALIDITY = ("a diametral clearance above the largest ISO 5753-1 gives a cylindrical "
                      "roller bearing of its size (group 5, looked up at the inner raceway's "
                      "diameter: 0.125 mm for 40-50 mm)")
