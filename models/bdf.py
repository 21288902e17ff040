"""The arithmetic of the variable-order, quasi-constant-step numerical differentiation
formulas (NDF, orders 1 to 5) of Shampine and Reichelt, compiled: the multistep method for
stiff problems whose Newton iterations can keep one Jacobian over many steps.

The method keeps the backward differences of its solution at equally spaced points in an
array ``D`` (``D[0]`` the solution, ``D[k]`` its ``k``-th backward difference at the step
``h``); a step of order ``q`` predicts ``y_p = sum_{k<=q} D[k]`` and solves

``y - y_p + psi = c f(y)``, ``c = h / alpha_q``, ``psi = sum_{1<=k<=q} gamma_k D[k] / alpha_q``

by Newton's method with the matrix ``I - c J``; its error is ``error_const_q`` times the
correction ``y - y_p``. A change of the step rescales the differences
(:func:`change_differences`); the order moves by at most one after ``q + 1`` steps of the
same size, to the one whose error estimate allows the largest next step. The same scheme as
scipy's ``BDF`` (``scipy.integrate``), in the form of Shampine and Reichelt and of Hairer and
Wanner's quasi-constant step-size implementation.

References
----------
.. [1] L. F. Shampine and M. W. Reichelt, The MATLAB ODE suite, SIAM Journal on Scientific
   Computing 18 (1997) 1-22, doi:10.1137/S1064827594276424 (the NDFs, their ``kappa``, the
   differences' rescaling).
.. [2] E. Hairer and G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
   Springer (1996), doi:10.1007/978-3-642-05221-7, III.5 and IV.8 (backward differentiation
   formulas, Newton's iterations and their convergence test).
"""
from __future__ import annotations

import numpy as np

from .compiled_cache import njit

MAX_ORDER = 5
#: Newton's iterations at most per step, and the steps' change at most and least per step.
NEWTON_ITERATIONS, LEAST_FACTOR, MOST_FACTOR = 4, 0.2, 10.0
#: The NDFs' ``kappa`` (Shampine and Reichelt, Table 1; order 5 is the BDF).
KAPPA = np.array([0.0, -0.1850, -1 / 9, -0.0823, -0.0415, 0.0])
GAMMA = np.concatenate(([0.0], np.cumsum(1.0 / np.arange(1, MAX_ORDER + 1))))
ALPHA = (1.0 - KAPPA) * GAMMA
ERROR_CONSTANT = KAPPA * GAMMA + 1.0 / np.arange(1, MAX_ORDER + 2)


@njit(cache=True)
def _rescaling(order, factor):
    """The matrix that takes the differences at step ``h`` to those at ``factor h``
    (Shampine and Reichelt, eq. 2.5), ``(order + 1)`` square."""
    matrix = np.zeros((order + 1, order + 1))
    matrix[0, :] = 1.0
    for i in range(1, order + 1):
        for j in range(1, order + 1):
            matrix[i, j] = matrix[i - 1, j] * (i - 1 - factor * j) / i
    return matrix


@njit(cache=True)
def change_differences(differences, order, factor):
    """Rescale ``differences`` ``(MAX_ORDER + 3, n)`` in place to a step ``factor`` times
    the present one."""
    product = _rescaling(order, factor) @ _rescaling(order, 1.0)
    head = differences[:order + 1].copy()
    for i in range(order + 1):
        for k in range(differences.shape[1]):
            total = 0.0
            for j in range(order + 1):
                total += product[j, i] * head[j, k]
            differences[i, k] = total


@njit(cache=True)
def predicted(differences, order):
    """The predicted solution ``sum_{k<=order} D[k]`` and ``psi`` of a step of ``order``."""
    n = differences.shape[1]
    prediction, psi = np.zeros(n), np.zeros(n)
    for k in range(order + 1):
        for i in range(n):
            prediction[i] += differences[k, i]
            if k > 0:
                psi[i] += GAMMA[k] * differences[k, i]
    for i in range(n):
        psi[i] /= ALPHA[order]
    return prediction, psi


@njit(cache=True)
def scaled_norm(values, scale, weight=1.0):
    """The root mean square of ``weight values / scale``."""
    squares = 0.0
    for i in range(values.size):
        x = weight * values[i] / scale[i]
        squares += x * x
    return np.sqrt(squares / values.size)


@njit(cache=True)
def accept(differences, order, correction):
    """Update the differences after a step of ``order`` whose Newton correction
    (``y - y_p``) is ``correction``: ``D[0]`` becomes the new solution."""
    for i in range(differences.shape[1]):
        differences[order + 2, i] = correction[i] - differences[order + 1, i]
        differences[order + 1, i] = correction[i]
    for k in range(order, -1, -1):
        for i in range(differences.shape[1]):
            differences[k, i] += differences[k + 1, i]


@njit(cache=True)
def next_order_and_factor(differences, order, error_norm, scale, safety):
    """After ``order + 1`` steps of one size: the order of the next (``order`` or one either
    side of it), the one whose error estimate allows the largest step, and that step's
    factor over the present one."""
    lower = np.inf
    if order > 1:
        lower = scaled_norm(differences[order], scale, ERROR_CONSTANT[order - 1])
    higher = np.inf
    if order < MAX_ORDER:
        higher = scaled_norm(differences[order + 2], scale, ERROR_CONSTANT[order + 1])
    best, chosen = -1.0, order
    for change, norm in ((-1, lower), (0, error_norm), (1, higher)):
        factor = np.inf if norm == 0.0 else norm ** (-1.0 / (order + change + 1))
        if factor > best:
            best, chosen = factor, order + change
    return chosen, min(MOST_FACTOR, safety * best)


@njit(cache=True)
def interpolated(differences, order, t, step, at, out):
    """The solution at time ``at`` from the differences at ``t`` (spacing ``step``, of
    ``order``): their interpolating polynomial, in Newton's backward form, into ``out``."""
    for i in range(out.size):
        out[i] = differences[0, i]
    weight = 1.0
    for k in range(1, order + 1):
        weight *= (at - (t - (k - 1) * step)) / (k * step)
        for i in range(out.size):
            out[i] += weight * differences[k, i]
