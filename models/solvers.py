"""Vectorised root finding for many independent one-dimensional problems at once."""
from __future__ import annotations

import numpy as np


def solve_increasing(residual, lower, upper, start, xtol, max_iter=200):
    """Roots of many non-decreasing functions by Newton steps safeguarded with bisection.

    Each entry ``e`` has its own function ``f_e`` with ``f_e(lower) <= 0 <= f_e(upper)``.
    A Newton step that leaves the current bracket (or has a zero or undefined slope) is
    replaced by bisection, so every entry converges, to a continuous crossing even where
    ``f_e`` has downward jumps. Only the entries not yet converged are evaluated.

    An entry has not converged where that promise fails: where its residual is NaN or
    infinite (the entry stops there, with ``x`` NaN), and where it ends at an end of its
    bracket with the residual's sign saying that the root lies beyond that end (the bracket
    did not hold a root). Before an entry ends on a bracket end it has not evaluated, that
    end is evaluated, so a root within ``xtol`` of an end is still found.

    Parameters
    ----------
    residual : callable
        ``residual(x, index) -> (value, slope)`` for the entries ``index`` at ``x``
        (both 1-D). Called once per iteration; the last call made for an entry was at the
        ``x`` returned for it, so a residual that caches its intermediate results per entry
        leaves them consistent with the solution.
    lower, upper, start : numpy.ndarray
        Bracket and initial point of each entry, 1-D. A bracket narrower than ``xtol`` fixes
        the entry's ``x``: it is evaluated once and converged if its residual is finite.
    xtol : numpy.ndarray or float
        Absolute tolerance on ``x`` per entry: an entry is done when its next step is smaller.
    max_iter : int
        Iterations before giving up.

    Returns
    -------
    x : numpy.ndarray
        The roots (the last evaluated point of each entry; NaN where the residual was not
        finite).
    converged : numpy.ndarray of bool
        False where ``max_iter`` was reached, the residual was not finite, or the root was
        not in the bracket.
    """
    lower = np.array(lower, dtype=float)
    upper = np.array(upper, dtype=float)
    x = np.clip(np.array(start, dtype=float), lower, upper)
    xtol = np.broadcast_to(np.asarray(xtol, dtype=float), x.shape)
    pinned = ~(upper - lower > xtol)  # the caller fixed x (or gave a NaN bracket)
    # Whether each bracket end has been evaluated: the root is only known to lie inside the
    # bracket once a residual <= 0 was seen at its lower end and >= 0 at its upper end.
    lower_seen = np.zeros(x.shape, dtype=bool)
    upper_seen = np.zeros(x.shape, dtype=bool)
    first_lower, first_upper = lower.copy(), upper.copy()
    converged = np.zeros(x.shape, dtype=bool)
    active = np.arange(x.size)
    for _ in range(max_iter):
        if active.size == 0:
            break
        xa = x[active]
        value, slope = residual(xa, active)
        finite = np.isfinite(value)
        low = np.where(value <= 0.0, xa, lower[active])
        high = np.where(value >= 0.0, xa, upper[active])
        lower_seen[active] |= value <= 0.0
        upper_seen[active] |= value >= 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = xa - value / slope
        inside = (newton > low) & (newton < high)  # False for NaN and infinite steps
        step_to = np.where(inside, newton, 0.5 * (low + high))
        tolerance = xtol[active]
        small_newton = np.abs(newton - xa) <= tolerance
        # A Newton step below tolerance ends the entry even when rounding puts it on the
        # bracket's edge; so does a bracket narrower than the tolerance.
        done = small_newton | (np.abs(step_to - xa) <= tolerance) | (value == 0.0)
        # Ending beside an end never evaluated: evaluate that end first.
        probe_lower = done & ~small_newton & (value > 0.0) & ~lower_seen[active]
        probe_upper = done & ~small_newton & (value < 0.0) & ~upper_seen[active]
        # At an evaluated end with the residual's sign pointing beyond it: no root inside.
        outside = ((probe_lower & (xa <= first_lower[active]))
                   | (probe_upper & (xa >= first_upper[active])))
        probe = (probe_lower | probe_upper) & ~outside & ~pinned[active]
        step_to = np.where(probe_lower, first_lower[active], step_to)
        step_to = np.where(probe_upper, first_upper[active], step_to)
        done = (done & ~probe) | ~finite
        lower[active], upper[active] = low, high
        x[active] = np.where(done, np.where(finite, xa, np.nan), step_to)
        converged[active[done]] = (finite & (~outside | pinned[active]))[done]
        active = active[~done]
    return x, converged

