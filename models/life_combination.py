"""Rating lives combined: one bearing's over a duty cycle, and a system's of several
bearings that must all survive.

A duty cycle's load cases each use up a share of a bearing's life in proportion to the time
spent in them (Palmgren [1]_, Miner [2]_): ``L = 1 / sum(U_i / L_i)`` with ``U_i`` the cases'
time shares. A system fails when its first bearing does; with each bearing's survival the
two-parameter Weibull law of Lundberg and Palmgren [3]_, ``S_i(L) = 0.9^((L / L_i)^e_i)``,
the system survives as their product, and its life at 90 % reliability is the ``L`` where
``sum((L / L_i)^e_i) = 1``: ``L = (sum(L_i^-e))^(-1/e)`` where all share one slope ``e``.
The slopes are 10/9 for ball and 9/8 for roller bearings [4]_.

References
----------
.. [1] A. Palmgren, "Die Lebensdauer von Kugellagern", Zeitschrift des VDI 68 (1924) 339-341.
.. [2] M. A. Miner, "Cumulative damage in fatigue", Journal of Applied Mechanics 12 (1945)
   A159-A164, doi:10.1115/1.4009458.
.. [3] G. Lundberg and A. Palmgren, "Dynamic capacity of rolling bearings", Acta
   Polytechnica, Mechanical Engineering Series 1 (3), Stockholm (1947).
.. [4] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis: Essential Concepts of
   Bearing Technology, 5th ed., CRC Press (2007), doi:10.1201/9781420006582, ch. 11 (the
   Weibull distribution of bearing lives).
"""
from __future__ import annotations

import numpy as np

#: The Weibull slope of rating lives by bearing kind (Harris and Kotzalas, ch. 11).
WEIBULL_SLOPES = {"ball": 10.0 / 9.0, "roller": 9.0 / 8.0}
_ITERATIONS = 60


def duty_cycle_life(lives, time_shares, axis=-1):
    """A bearing's life over a duty cycle by Palmgren and Miner: ``1 / sum(U_i / L_i)``.

    Parameters
    ----------
    lives : array_like
        The life ``L_i`` of each load case along ``axis`` (any unit; infinite: a case that
        uses up none).
    time_shares : array_like
        ``U_i``, each case's share of the time along ``axis`` [-]; scaled to sum to 1.
    axis : int

    Returns
    -------
    numpy.ndarray
        The life over the cycle, in the unit of ``lives``; NaN where a life or share is.
    """
    lives = np.asarray(lives, dtype=float)
    shares = np.asarray(time_shares, dtype=float)
    shares = shares / np.sum(shares, axis=axis, keepdims=True)
    with np.errstate(divide="ignore"):
        return 1.0 / np.sum(shares / lives, axis=axis)


def system_life(lives, slopes, axis=-1):
    """The life at 90 % reliability of a system that survives while all its bearings do.

    Parameters
    ----------
    lives : array_like
        Each bearing's rating life ``L_i`` along ``axis`` (at 90 % reliability, any unit;
        infinite: a bearing that does not fail).
    slopes : array_like
        Each bearing's Weibull slope ``e_i`` (:data:`WEIBULL_SLOPES`), broadcast along
        ``axis``.
    axis : int

    Returns
    -------
    numpy.ndarray
        The ``L`` with ``sum((L / L_i)^e_i) = 1``, in the unit of ``lives``: the closed form
        ``(sum(L_i^-e))^(-1/e)`` where the slopes are one, else found by Newton's method in
        ``log L`` (the sum grows monotonically in it), to round-off.
    """
    lives = np.moveaxis(np.asarray(lives, dtype=float), axis, -1)
    slopes = np.moveaxis(np.broadcast_to(np.asarray(slopes, dtype=float),
                                         np.moveaxis(lives, -1, axis).shape), axis, -1)
    with np.errstate(divide="ignore"):
        inverse = 1.0 / lives  # 0 for a bearing that does not fail
    if np.all(slopes == slopes[..., :1]):
        e = slopes[..., 0]
        with np.errstate(divide="ignore"):
            return np.sum(inverse ** e[..., None], axis=-1) ** (-1.0 / e)
    # In x = log L: f(x) = sum(exp(e_i (x - log L_i))) - 1 is convex and increasing; Newton
    # from the smallest life (where f >= 0) descends to its root without overshooting.
    with np.errstate(divide="ignore", invalid="ignore"):
        logs = -np.log(inverse)
        x = np.min(logs, axis=-1)
        for _ in range(_ITERATIONS):
            terms = np.exp(slopes * (x[..., None] - logs))
            value, slope = terms.sum(axis=-1) - 1.0, (slopes * terms).sum(axis=-1)
            x = x - np.where(value > 0.0, value / slope, 0.0)
    return np.where(np.all(inverse == 0.0, axis=-1), np.inf, np.exp(x))
