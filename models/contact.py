"""Contact mechanics: the sliced line contact of a (crowned) roller on a raceway."""
from __future__ import annotations

import numpy as np

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
