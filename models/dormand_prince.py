"""The arithmetic of one adaptive Dormand-Prince 5(4) step, compiled, shared by the transient
cage models' integrators (each calls its own right-hand side between these: numba cannot
cache a compiled function that takes another as an argument).

A step from ``y`` of size ``h``: the stages' arguments (:func:`stage_argument`), the error of
the fourth-order solution against the fifth (:func:`error_norm`), and the next step's size
from a PI controller (:func:`next_step`, ``h ~ err^-0.17 err_last^0.04`` as Hairer's DOPRI5),
which keeps steps near the stability limit of stiff terms without the rejections a plain
controller makes there. The seventh stage is evaluated at the fifth-order solution: it is the
next step's first (first same as last).

References
----------
.. [1] J. R. Dormand and P. J. Prince, A family of embedded Runge-Kutta formulae, Journal of
   Computational and Applied Mathematics 6 (1980) 19-26, doi:10.1016/0771-050X(80)90013-3.
.. [2] E. Hairer, S. P. Norsett and G. Wanner, Solving Ordinary Differential Equations I,
   2nd ed., Springer (1993), doi:10.1007/978-3-540-78862-1, II.4-5 (DOPRI5) and IV.2.
"""
from __future__ import annotations

import numpy as np

from .compiled_cache import njit

#: The stages' coefficients (Butcher tableau) and the error weights, fifth minus fourth order.
A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1 / 5, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3 / 40, 9 / 40, 0.0, 0.0, 0.0, 0.0],
    [44 / 45, -56 / 15, 32 / 9, 0.0, 0.0, 0.0],
    [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0.0, 0.0],
    [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0.0],
    [35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]])
ERROR = np.array([71 / 57600, 0.0, -71 / 16695, 71 / 1920, -17253 / 339200, 22 / 525,
                  -1 / 40])
#: The first step tried [s], and the smallest step before an integration gives up.
FIRST_STEP, SMALLEST_STEP = 1e-7, 1e-15


@njit(cache=True)
def stage_argument(y, stages, stage, step):
    """The argument of stage ``stage`` (1 to 6) of a step ``step`` from ``y``, from the
    earlier stages' derivatives ``stages`` ``(7, n)``; stage 6's is the fifth-order
    solution."""
    trial = y.copy()
    for r in range(stage):
        if A[stage, r] != 0.0:
            weight = step * A[stage, r]
            for i in range(y.size):
                trial[i] += weight * stages[r, i]
    return trial


@njit(cache=True)
def error_norm(y, trial, stages, step, rtol, atol):
    """The root-mean-square error of the step from ``y`` to ``trial`` against the tolerance
    ``atol + rtol max(|y|, |trial|)``, element by element: at most 1 accepts the step."""
    squares = 0.0
    for i in range(y.size):
        error = 0.0
        for s in range(7):
            error += step * ERROR[s] * stages[s, i]
        scaled = error / (atol[i] + rtol * np.maximum(abs(y[i]), abs(trial[i])))
        squares += scaled * scaled
    return np.sqrt(squares / y.size)


@njit(cache=True)
def next_step(step, norm, last_norm):
    """After a step ``step`` of error ``norm``: whether it is accepted, the next step's size
    and the error the controller keeps for the one after (``last_norm`` where the step is
    rejected). A step whose error is not finite is retried at a tenth of its size."""
    if not np.isfinite(norm):
        return False, 0.1 * step, last_norm
    if norm <= 1.0:
        norm = max(norm, 1e-4)
        return True, step * min(5.0, max(0.2, 0.9 * norm ** -0.17 * last_norm ** 0.04)), norm
    return False, step * max(0.2, 0.9 * norm ** -0.17), last_norm


@njit(cache=True)
def conclude(y, trial, stages, step, rtol, atol, last_norm, t, target):
    """The end of a step ``step`` from ``y`` at ``t`` to ``trial``, its stages evaluated:
    whether it is accepted, the next step's size, the controller's kept error and the time
    reached (``target`` itself where the step was cut to reach it; ``t`` if rejected)."""
    accepted, h, last_norm = next_step(step, error_norm(y, trial, stages, step, rtol, atol),
                                       last_norm)
    if accepted:
        t = t + step if step < target - t else target
    return accepted, h, last_norm, t
