"""Multistep integration of the spatial cage model (:mod:`models.cage_dynamics_6dof_rhs`):
the variable-order numerical differentiation formulas of :mod:`models.bdf`, whose Newton
iterations keep the stiff terms' Jacobian in closed form
(:func:`models.cage_dynamics_6dof_jacobian.closed_form_jacobian`) until they stop converging
with it, and the factors of ``I - c J`` (by the blocks of
:mod:`models.cage_dynamics_6dof_implicit`) until the step or the order changes.

Where the motion is smooth and stiff, as with the end films' pressure (their squeeze damps a
roller's motion relative to the cage near 1e8 /s), a multistep method takes steps of the
motion's own scale with one right-hand side and a Newton iteration or two each, where the
Rosenbrock-W method takes four right-hand sides and a fresh Jacobian per step
(benchmarks/RESULTS.md). Where dry contacts come and go, its Jacobian goes stale at every
contact and the one-step methods are faster.
"""
from __future__ import annotations

import numpy as np

from .bdf import (ALPHA, ERROR_CONSTANT, LEAST_FACTOR, MAX_ORDER, NEWTON_ITERATIONS,
                  accept, change_differences, interpolated, next_order_and_factor, predicted,
                  scaled_norm)
from .cage_dynamics_6dof_implicit import blocks, factor, solve
from .cage_dynamics_6dof_jacobian import closed_form_jacobian
from .cage_dynamics_6dof_rhs import _accumulators, _copy, _normalise, _observe, derivatives
from .compiled_cache import njit
from .dormand_prince import FIRST_STEP, SMALLEST_STEP

_EPSILON = np.finfo(np.float64).eps
#: Newton's iterations have stalled when they have failed more often than this, and than a
#: quarter of the accepted steps: where dry contacts come and go faster than the closed-form
#: Jacobian follows them (a thin pocket film: 100 000 failures in 0.3 ms, the steps shrunk to
#: 0.2 us), against 180 failures in 5 400 steps over 60 ms with flooded pockets.
STALLED_FAILURES = 1000


@njit(cache=True)
def _newton(prediction, psi, c, scale, tolerance, p, count, geometry, record, factors):
    """Newton's iterations for ``y - prediction + psi = c f(y)`` with the factored
    ``I - c J`` (``factors``: :func:`factor`'s ``from_hub``, ``own_inverse``, ``own_to_hub``,
    ``schur_inverse``): whether they converged (their rate's estimate, Hairer and Wanner
    IV.8, eq. 8.10), how many were made, the solution and its correction from the
    prediction."""
    y, correction = prediction.copy(), np.zeros_like(prediction)
    previous = -1.0
    for k in range(NEWTON_ITERATIONS):
        rate_of_change = derivatives(y, p, count, *geometry, *record, 0.0)
        if not np.all(np.isfinite(rate_of_change)):
            return False, k + 1, y, correction
        right = rate_of_change - (psi + correction) / c  # (I / c - J) dy = right
        change = solve(right, count, *factors)
        norm = scaled_norm(change, scale)
        rate = norm / previous if previous > 0.0 else -1.0
        if rate >= 0.0 and (rate >= 1.0 or
                            rate ** (NEWTON_ITERATIONS - k) / (1.0 - rate) * norm > tolerance):
            return False, k + 1, y, correction
        y += change
        correction += change
        if norm == 0.0 or (rate >= 0.0 and rate / (1.0 - rate) * norm < tolerance):
            return True, k + 1, y, correction
        previous = norm
    return False, NEWTON_ITERATIONS, y, correction


@njit(cache=True)
def integrate(state, times, p, count, geometry, record, settled_from, rtol, atol, max_steps):
    """The numerical differentiation formulas of orders 1 to 5 with step and order control
    (:mod:`models.bdf`), the samples their interpolating polynomial gives; the same samples,
    extremes, events, steps (attempted) and success as
    :func:`models.cage_dynamics_6dof_rhs.integrate`. A run whose Newton iterations stall
    (:data:`STALLED_FAILURES`) stops there, unsuccessful."""
    samples, arc_max, end_min, rib_min, last, events = _accumulators(times, state, record)
    n = state.size
    _, arc_theta, arc_z, _, _, _, _ = geometry
    gaps, alongs = np.empty((arc_theta.size, arc_z.size)), np.empty((arc_theta.size,
                                                                     arc_z.size))
    own, to_hub, from_hub, hub, own_inverse, own_to_hub, schur_inverse = blocks(count)
    factors = (from_hub, own_inverse, own_to_hub, schur_inverse)
    newton_tolerance = max(10.0 * _EPSILON / rtol, min(0.03, np.sqrt(rtol)))
    t, step, end, index, steps = times[0], FIRST_STEP, times[-1], 1, 0
    differences = np.zeros((MAX_ORDER + 3, n))
    differences[0] = state
    _normalise(differences[0], count)
    _copy(differences[0], samples[0])
    _observe(differences[0], p, count, geometry, record, t >= settled_from, arc_max, end_min,
             rib_min, last, events)
    differences[1] = step * derivatives(differences[0], p, count, *geometry, *record, 0.0)
    closed_form_jacobian(differences[0], p, count, geometry, gaps, alongs, own, to_hub,
                         from_hub, hub)
    order, equal_steps, current, factored = 1, 0, True, 0.0
    accepted, failures = 0, 0
    sample = np.empty(n)
    while index < times.size:
        if (steps >= max_steps or step < SMALLEST_STEP
                or failures > max(STALLED_FAILURES, accepted // 4)):
            return samples, arc_max, end_min, rib_min, events, steps, False
        if t + step >= end:  # the last step ends on the last sample
            change_differences(differences, order, (end - t) / step)
            step, equal_steps = end - t, 0
        prediction, psi = predicted(differences, order)
        scale = atol + rtol * np.abs(prediction)
        c = step / ALPHA[order]
        while True:
            if factored != c:
                factor(1.0 / c, own, to_hub, from_hub, hub, own_inverse, own_to_hub,
                       schur_inverse)
                factored = c
            converged, iterations, trial, correction = _newton(
                prediction, psi, c, scale, newton_tolerance, p, count, geometry, record,
                factors)
            if converged or current:
                break
            closed_form_jacobian(prediction, p, count, geometry, gaps, alongs, own, to_hub,
                                 from_hub, hub)
            current, factored = True, 0.0
        steps += 1
        if not converged:
            failures += 1
            change_differences(differences, order, 0.5)
            step, equal_steps = 0.5 * step, 0
            continue
        safety = 0.9 * (2 * NEWTON_ITERATIONS + 1) / (2 * NEWTON_ITERATIONS + iterations)
        scale = atol + rtol * np.abs(trial)
        error_norm = scaled_norm(correction, scale, ERROR_CONSTANT[order])
        if not error_norm <= 1.0:
            shrink = LEAST_FACTOR
            if np.isfinite(error_norm):
                shrink = max(LEAST_FACTOR, safety * error_norm ** (-1.0 / (order + 1)))
            change_differences(differences, order, shrink)
            step, equal_steps = shrink * step, 0
            continue
        reached = t + step if t + step < end else end
        accept(differences, order, correction)
        _normalise(differences[0], count)
        while index < times.size and times[index] <= reached:
            if times[index] == reached:
                _copy(differences[0], sample)
            else:
                interpolated(differences, order, reached, step, times[index], sample)
                _normalise(sample, count)
            _copy(sample, samples[index])
            _observe(sample, p, count, geometry, record, times[index] >= settled_from,
                     arc_max, end_min, rib_min, last, events)
            index += 1
        t, current, equal_steps, accepted = reached, False, equal_steps + 1, accepted + 1
        if equal_steps > order:
            order, grow = next_order_and_factor(differences, order, error_norm, scale, safety)
            change_differences(differences, order, grow)
            step, equal_steps = grow * step, 0
    return samples, arc_max, end_min, rib_min, events, steps, True
