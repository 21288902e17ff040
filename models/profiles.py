"""Roller crowning profiles, evaluated at the centres of the slices of a sliced line contact."""
from __future__ import annotations

import numpy as np

PROFILES = ("logarithmic", "none")


def slice_centres(slices: int) -> np.ndarray:
    """Axial positions of the slice centres, as a fraction of the half length [-].

    Slice ``lambda = 1..k`` of a roller cut into ``k`` equal slices is centred at
    ``x = (2 lambda - 1)/k - 1``, in (-1, 1) (the argument of eq. 8 of [1]).
    """
    # Integer numerator: mirror slices get exactly opposite positions (and equal gaps).
    return (2.0 * np.arange(1, slices + 1) - 1.0 - slices) / slices


def crown_shape(slices: int, profile: str = "logarithmic") -> np.ndarray:
    """Crown drop of each slice per unit crown height ``cmax`` [-].

    Parameters
    ----------
    slices : int
        Number of slices ``k`` [-].
    profile : {'logarithmic', 'none'}
        ``'logarithmic'``: the full-crowned logarithmic profile of eq. 8 of [1],
        ``c_lambda = 0.2 cmax ln(1 / (1.0067 - x^2))``; ``'none'``: a straight roller.

    Returns
    -------
    numpy.ndarray
        Shape ``(slices,)``; multiply by the crown height [m] to get the gap of each slice [m].

    Notes
    -----
    Eq. 8 as printed is slightly negative near the middle (``-0.0013 cmax`` at ``x = 0``),
    which would make the roller stand proud of its nominal diameter and carry load before it
    touches. The nominal diameter is the largest, so the drop is clipped at zero; the
    difference is below 0.2 % of the crown height.

    References
    ----------
    .. [1] Paper 000, "Radial stiffness analysis of cylindrical roller bearing", eq. 8.
    """
    if profile == "none":
        return np.zeros(slices)
    if profile == "logarithmic":
        x = slice_centres(slices)
        return np.maximum(0.2 * np.log(1.0 / (1.0067 - x**2)), 0.0)
    raise ValueError(f"unknown crown profile {profile!r}; expected one of {PROFILES}")


def distinct_slices(slices: int, profile: str = "logarithmic") -> tuple[np.ndarray, np.ndarray]:
    """The distinct values of :func:`crown_shape` and how many slices share each.

    A symmetric profile has each gap twice and a straight roller has one gap ``k`` times;
    summing over distinct gaps with their multiplicities gives the same contact load for a
    fraction of the work.

    Returns
    -------
    shape : numpy.ndarray
        Distinct crown drops per unit crown height [-].
    count : numpy.ndarray
        Number of slices with each drop [-]; sums to ``slices``.
    """
    shape, count = np.unique(crown_shape(slices, profile), return_counts=True)
    return shape, count.astype(float)
