"""Geometry shared by the bearing models."""
from __future__ import annotations

import numpy as np


def elements_fit(count, pitch_diameter, element_diameter):
    """Whether ``count`` rolling elements of ``element_diameter`` fit on the pitch circle.

    Neighbouring centres are a chord ``d_m sin(pi / Z)`` apart; the elements fit without
    touching each other when that chord exceeds their diameter. Any consistent length unit.
    """
    return np.asarray(pitch_diameter) * np.sin(np.pi / np.asarray(count)) > element_diameter


def clearance_below_roller(clearance, roller_diameter):
    """Whether a diametral clearance (or interference, negative) is smaller than the rollers:
    a gap between the raceways as large as a roller lets rollers pass one another or drop out
    of their raceways, which no bearing can."""
    return np.abs(np.asarray(clearance)) < np.asarray(roller_diameter)
