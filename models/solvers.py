"""Vectorised root finding for many independent one-dimensional problems at once."""
from __future__ import annotations

import numpy as np


def solve_increasing(residual, lower, upper, start, xtol, max_iter=200):
    """Roots of many non-decreasing functions by Newton steps safeguarded with bisection.

    Each entry ``e`` has its own function ``f_e`` with ``f_e(lower) <= 0 <= f_e(upper)``.
    A Newton step that leaves the current bracket (or has a zero or undefined slope) is
    replaced by bisection, so every entry converges, to a continuous crossing even where
    ``f_e`` has downward jumps. Only the entries not yet converged are evaluated.

    Parameters
    ----------
    residual : callable
        ``residual(x, index) -> (value, slope)`` for the entries ``index`` at ``x``
        (both 1-D). Called once per iteration; the last call made for an entry was at the
        ``x`` returned for it, so a residual that caches its intermediate results per entry
        leaves them consistent with the solution.
    lower, upper, start : numpy.ndarray
        Bracket and initial point of each entry, 1-D.
    xtol : numpy.ndarray or float
        Absolute tolerance on ``x`` per entry: an entry is done when its next step is smaller.
    max_iter : int
        Iterations before giving up.

    Returns
    -------
    x : numpy.ndarray
        The roots (the last evaluated point of each entry).
    converged : numpy.ndarray of bool
        False where ``max_iter`` was reached.
    """
    lower = np.array(lower, dtype=float)
    upper = np.array(upper, dtype=float)
    x = np.clip(np.array(start, dtype=float), lower, upper)
    xtol = np.broadcast_to(np.asarray(xtol, dtype=float), x.shape)
    converged = np.zeros(x.shape, dtype=bool)
    active = np.arange(x.size)
    for _ in range(max_iter):
        if active.size == 0:
            break
        xa = x[active]
        value, slope = residual(xa, active)
        low = np.where(value <= 0.0, xa, lower[active])
        high = np.where(value >= 0.0, xa, upper[active])
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = xa - value / slope
        inside = (newton > low) & (newton < high)  # False for NaN and infinite steps
        step_to = np.where(inside, newton, 0.5 * (low + high))
        # A Newton step below tolerance ends the entry even when rounding puts it on the
        # bracket's edge; so does a bracket narrower than the tolerance.
        done = ((np.abs(newton - xa) <= xtol[active]) | (np.abs(step_to - xa) <= xtol[active])
                | (value == 0.0))
        lower[active], upper[active] = low, high
        x[active] = np.where(done, xa, step_to)
        converged[active[done]] = True
        active = active[~done]
    return x, converged
