"""The arithmetic of one step of a Rosenbrock-W method, compiled: the third-order,
four-stage, stiffly accurate and L-stable RA34PW2 of Rang and Angermann with its embedded
second-order solution.

A step of size ``h`` from ``y`` solves, for its stages ``u_i``,

``(I / (h gamma) - J) u_i = f(y + sum_j a_ij u_j) + sum_j c_ij u_j / h``

(the form of Hairer and Wanner, IV.7, eq. 7.25, which needs no product with ``J``) and takes
``y + sum_i m_i u_i``; ``J`` is the right-hand side's Jacobian, or an approximation of it: a
W-method keeps its order whatever matrix it is given, only its stability depends on it.

References
----------
.. [1] J. Rang and L. Angermann, New Rosenbrock W-methods of order 3 for partial
   differential algebraic equations of index 1, BIT Numerical Mathematics 45 (2005)
   761-787, doi:10.1007/s10543-005-0035-y (RA34PW2's coefficients).
.. [2] E. Hairer and G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
   Springer (1996), doi:10.1007/978-3-642-05221-7, IV.7 (Rosenbrock methods and their
   implementation).
"""
from __future__ import annotations

import numpy as np

from .compiled_cache import njit

#: RA34PW2 as published: the diagonal ``gamma``, the stages' arguments ``alpha``, the
#: Jacobian's weights ``Gamma`` (lower triangular, ``gamma`` on its diagonal), the weights
#: of the third-order solution and of the embedded second-order one.
GAMMA = 0.43586652150845900
_ALPHA = np.array([
    [0.0, 0.0, 0.0, 0.0],
    [0.87173304301691801, 0.0, 0.0, 0.0],
    [0.84457060015369423, -0.11299064236484185, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0]])
_GAMMAS = np.array([
    [GAMMA, 0.0, 0.0, 0.0],
    [-0.87173304301691801, GAMMA, 0.0, 0.0],
    [-0.90338057013044082, 0.054180672388095326, GAMMA, 0.0],
    [0.24212380706095346, -1.2232505839045147, 0.54526025533510214, GAMMA]])
_WEIGHTS = np.array([0.24212380706095346, -1.2232505839045147, 1.5452602553351020, GAMMA])
_EMBEDDED = np.array([0.37810903145819369, -0.096042292212423178, 0.5, 0.21793326075422950])

_INVERSE = np.linalg.inv(_GAMMAS)
#: The coefficients of the transformed stages (Hairer and Wanner, IV.7, eq. 7.25).
A = _ALPHA @ _INVERSE
C = np.diag(np.diag(_INVERSE)) - _INVERSE
M = _WEIGHTS @ _INVERSE
ERROR = (_WEIGHTS - _EMBEDDED) @ _INVERSE
STAGES = 4


@njit(cache=True)
def stage_argument(y, stages, stage):
    """``y + sum_j a_ij u_j`` of stage ``stage`` (0 to 3), from the earlier stages
    ``stages`` ``(4, n)``."""
    trial = y.copy()
    for j in range(stage):
        if A[stage, j] != 0.0:
            for i in range(y.size):
                trial[i] += A[stage, j] * stages[j, i]
    return trial


@njit(cache=True)
def stage_right_side(derivative, stages, stage, step):
    """``f(...) + sum_j c_ij u_j / h`` of stage ``stage``, ``derivative`` being ``f`` at its
    argument."""
    right = derivative.copy()
    for j in range(stage):
        if C[stage, j] != 0.0:
            weight = C[stage, j] / step
            for i in range(right.size):
                right[i] += weight * stages[j, i]
    return right


@njit(cache=True)
def solution_and_error(y, stages, rtol, atol):
    """The step's third-order solution and the root-mean-square of its difference from the
    second-order one against ``atol + rtol max(|y|, |solution|)``: at most 1 accepts it."""
    solution = y.copy()
    squares = 0.0
    for i in range(y.size):
        error = 0.0
        for s in range(STAGES):
            solution[i] += M[s] * stages[s, i]
            error += ERROR[s] * stages[s, i]
        scaled = error / (atol[i] + rtol * max(abs(y[i]), abs(solution[i])))
        squares += scaled * scaled
    return solution, np.sqrt(squares / y.size)


@njit(cache=True)
def next_step(step, norm, order=3):
    """Whether a step ``step`` of error ``norm`` is accepted, and the next step's size
    (``h err^(-1/order)``, ``order`` that of the embedded solution's error: 3 here, its
    embedded solution being of second order); a step whose error is not finite is retried at
    a tenth of its size."""
    if not np.isfinite(norm):
        return False, 0.1 * step
    if norm <= 1.0:
        return True, step * min(5.0, max(0.2, 0.9 * max(norm, 1e-4) ** (-1.0 / order)))
    return False, step * max(0.2, 0.9 * norm ** (-1.0 / order))
