"""The rating lives a bearing model reports: the inputs and outputs every model that loads
rolling elements declares alike, and the one function that turns its loads into them.

A model computes its ISO/TS 16281 reference life from its own element loads (balls or
laminae, :mod:`models.life`) and its ISO 281 equivalent dynamic load from its own loads
(the X and Y factors depend on the bearing type); :func:`rating_lives` does the rest: the
modified lives through ``a_ISO`` with the viscosity ratio of the oil at its temperature,
and the lives in hours at the given speed.
"""
from __future__ import annotations

import numpy as np

from .life import (basic_rating_life, equivalent_reference_load, life_duration,
                   life_modification_factor, viscosity_ratio)
from .lubrication import (VISCOSITY_GRADES, WALTHER_FLOOR, viscosities_fall,
                          walther_viscosity)
from .registry import Constraint, Input, Output

#: ISO 281:2007 Table 13 gives 0.6 to 0.5 for "normal cleanliness" of bearings with
#: d_m < 100 mm (filtered oil, sealed and greased for life); the lower end is the default.
DEFAULT_CONTAMINATION_FACTOR = 0.5

SPEED_INPUT = Input("speed", "rpm", "speed of the inner ring, for the lives in hours, the "
                    "viscosity ratio, the film and the friction only (the load distribution is "
                    "static)", default=0.0, minimum=0.0, label="inner-ring speed")

#: Largest equivalent load, as a fraction of Cr, at which ISO 281:2007 vouches for its life
#: equation (5.3.1 and 7.3.1: beyond P = 0.5 Cr, or C0r where that is smaller, heavy loads
#: may deform the most loaded contact plastically; the models flag C0r's contact stress, ISO
#: 76's reference stress, in the point's status). It concerns the lives only, not the loads
#: and stiffness a point's status vouches for: the lives carry it as ``load_rating_ratio``.
HEAVY_LOAD_RATIO = 0.5

#: Declared after a model's own inputs, in this order (the function's last parameters).
LIFE_INPUTS = (
    Input("dynamic_load_rating", "N", "basic dynamic load rating Cr of the bearing "
          "(catalogue); default: no life (NaN)", default=None, minimum=0.0,
          exclusive_minimum=True, label="dynamic load rating"),
    Input("fatigue_load_limit", "N", "fatigue load limit Cu (catalogue, or ISO 281 Annex B); "
          "default: no modified life (NaN)", default=None, minimum=0.0,
          label="fatigue load limit"),
    Input("contamination_factor", "1", "contamination factor eC (ISO 281 Table 13: 1 extreme "
          "cleanliness, 0.6-0.5 normal, 0.3-0.1 typical contamination)",
          default=DEFAULT_CONTAMINATION_FACTOR, minimum=0.0, maximum=1.0,
          label="contamination factor"),
    Input("oil_temperature", "degC", "operating temperature of the oil, for its viscosity in "
          "the viscosity ratio", default=70.0, minimum=-40.0, maximum=200.0,
          label="oil temperature"),
    Input("viscosity_40", "mm^2/s", "kinematic viscosity of the oil at 40 degC (ISO VG "
          "grade: VG 2 to VG 3200, ISO 3448); default: no modified life (NaN)", default=None,
          minimum=VISCOSITY_GRADES[0], maximum=VISCOSITY_GRADES[1],
          label="oil viscosity at 40 degC"),
    Input("viscosity_100", "mm^2/s", "kinematic viscosity of the oil at 100 degC, below that "
          "at 40 degC (Walther's law needs more than 0.3); required with viscosity_40",
          default=None, minimum=WALTHER_FLOOR, exclusive_minimum=True,
          label="oil viscosity at 100 degC"),
)

#: An oil's viscosities at 40 and 100 deg C in the order every oil has them.
VISCOSITY_ORDER = Constraint(
    ("viscosity_40", "viscosity_100"), viscosities_fall,
    "viscosity_100 must be below viscosity_40: an oil thins as it warms (swapped, Walther's "
    "law would make it thicken with temperature)")
#: Conditions between the life inputs, for every model that declares :data:`LIFE_INPUTS`.
LIFE_CONSTRAINTS = (
    VISCOSITY_ORDER,
    Constraint(("fatigue_load_limit", "dynamic_load_rating"),
               lambda fatigue_load_limit, dynamic_load_rating:
               fatigue_load_limit < dynamic_load_rating,
               "fatigue_load_limit must be below dynamic_load_rating: Cu is the load at which "
               "the raceways reach the fatigue limit stress, 1500 MPa (ISO 281 Annex B), Cr "
               "the load of a life of a million revolutions, at far higher stress"),
)

LIFE_OUTPUT_NAMES = ("reference_rating_life", "modified_reference_rating_life",
                     "basic_rating_life", "modified_rating_life", "equivalent_dynamic_load",
                     "viscosity_ratio", "life_modification_factor", "reference_rating_hours",
                     "modified_reference_rating_hours", "load_rating_ratio")


def beyond_life_equation(load_rating_ratio):
    """Where the lives lie beyond ISO 281's life equation: ``P/C_r`` above
    :data:`HEAVY_LOAD_RATIO` (false where there is no rating, NaN)."""
    return np.asarray(load_rating_ratio) > HEAVY_LOAD_RATIO


def life_outputs(elements, equivalent_load):
    """Output declarations of :func:`rating_lives`' results.

    Parameters
    ----------
    elements : str
        How the model's reference life is found, e.g. "ball loads, inner ring rotating".
    equivalent_load : str
        How the model forms ISO 281's equivalent dynamic load P.
    """
    missing = "NaN without dynamic_load_rating"
    modified = ("NaN without dynamic_load_rating, fatigue_load_limit, oil viscosities or "
                "speed, or with kappa < 0.1")
    return (
        Output("reference_rating_life", "Mturn", f"basic reference rating life L10r, ISO/TS "
               f"16281, from the {elements}; millions of revolutions, {missing}",
               label="reference rating life L10r", cycle="revolutions"),
        Output("modified_reference_rating_life", "Mturn", "modified reference rating life "
               f"L10rm = aISO L10r (ISO/TS 16281, 90 % reliability); {modified}",
               label="modified reference rating life L10rm", cycle="revolutions"),
        Output("basic_rating_life", "Mturn", "basic rating life L10 = (Cr/P)^p, ISO 281, "
               f"from the equivalent dynamic load; {missing}", label="basic rating life L10",
               cycle="revolutions"),
        Output("modified_rating_life", "Mturn", "modified rating life L10m = aISO L10 (ISO "
               f"281); {modified}", label="modified rating life L10m",
               cycle="revolutions"),
        Output("equivalent_dynamic_load", "N", f"ISO 281 dynamic equivalent load P: "
               f"{equivalent_load}", label="equivalent dynamic load P"),
        Output("viscosity_ratio", "1", "viscosity ratio kappa = nu / nu1 (ISO 281 9.3.3); "
               "NaN without oil viscosities, zero at rest", label="viscosity ratio kappa",
               depends_on=("speed", "pitch_diameter", "oil_temperature", "viscosity_40",
                           "viscosity_100")),
        Output("life_modification_factor", "1", "life modification factor aISO of L10rm "
               "(ISO 281 9.3.3, with the reference load of ISO/TS 16281)",
               label="life modification factor aISO"),
        Output("reference_rating_hours", "h", "L10r in hours at the given speed (infinite "
               "at rest)", label="reference rating life L10rh", cycle="time"),
        Output("modified_reference_rating_hours", "h", "L10rm in hours at the given speed",
               label="modified reference rating life L10rmh", cycle="time"),
        Output("load_rating_ratio", "1", "P/Cr: above 0.5 the lives are beyond ISO 281's "
               "life equation (ISO 281:2007 5.3.1, 7.3.1: such loads may deform the most "
               f"loaded contact plastically); {missing}", label="load ratio P/Cr",
               counted=("points whose lives lie beyond ISO 281's life equation (P > 0.5 Cr)",
                        beyond_life_equation)),
    )


def _given(value):
    return np.nan if value is None else value


def rating_lives(reference_life, equivalent_load, kind, speed, pitch_diameter,
                 dynamic_load_rating, fatigue_load_limit, contamination_factor,
                 oil_temperature, viscosity_40, viscosity_100):
    """Every life output from a model's reference life and equivalent load.

    Parameters
    ----------
    reference_life : array_like
        ISO/TS 16281 ``L10r`` [10^6 revolutions] from the model's element loads.
    equivalent_load : array_like
        ISO 281 dynamic equivalent load ``P`` [N] from the model's loads.
    kind : {'ball', 'roller'}
    speed : array_like
        Speed of the rotating ring [rad/s].
    pitch_diameter : array_like
        ``d_m`` [m], for the reference viscosity ``nu_1``.
    dynamic_load_rating, fatigue_load_limit, contamination_factor : array_like or None
        ``C_r``, ``C_u`` [N], ``e_C`` [-]; None: NaN.
    oil_temperature : array_like
        [K].
    viscosity_40, viscosity_100 : array_like or None
        Kinematic viscosity at 40 and 100 deg C [m^2/s] (Walther's law between them).

    Returns
    -------
    dict of numpy.ndarray
        :data:`LIFE_OUTPUT_NAMES`, lives in SI [rad] (10^6 revolutions of ``2 pi`` each)
        and [s], loads [N], ratios [-].

    References
    ----------
    .. [1] ISO 281:2007, 5.3 and 7.3 (L10), 9.1 and 9.3 (L10m, a_ISO, kappa).
    .. [2] ISO/TS 16281:2008, 4.3.5 and 5.3.6 (L10rm).
    """
    rating = np.asarray(_given(dynamic_load_rating), dtype=float)
    reference_life = np.asarray(reference_life, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = viscosity_ratio(walther_viscosity(
            oil_temperature, _given(viscosity_40), _given(viscosity_100)), speed,
            pitch_diameter)
        factor_terms = (kappa, _given(contamination_factor), _given(fatigue_load_limit))
        reference_factor = life_modification_factor(
            *factor_terms, equivalent_reference_load(rating, reference_life, kind), kind)
        basic = basic_rating_life(rating, equivalent_load, kind)
        basic_factor = life_modification_factor(*factor_terms, equivalent_load, kind)
        modified_reference = reference_factor * reference_life
        turns = 2e6 * np.pi  # 10^6 revolutions [rad]
        lives = {
            "reference_rating_life": reference_life * turns,
            "modified_reference_rating_life": modified_reference * turns,
            "basic_rating_life": basic * turns,
            "modified_rating_life": basic_factor * basic * turns,
            "equivalent_dynamic_load": np.asarray(equivalent_load, dtype=float),
            "viscosity_ratio": kappa,
            "life_modification_factor": reference_factor,
            "reference_rating_hours": life_duration(reference_life, speed),
            "modified_reference_rating_hours": life_duration(modified_reference, speed),
            "load_rating_ratio": np.asarray(equivalent_load, dtype=float) / rating,
        }
    return dict(zip(lives, (np.array(value) for value in np.broadcast_arrays(*lives.values()))))
