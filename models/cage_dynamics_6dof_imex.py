"""Implicit-explicit integration of the spatial cage model
(:mod:`models.cage_dynamics_6dof_rhs`): the additive Runge-Kutta method of
:mod:`models.additive_runge_kutta`, its implicit part the Jacobian of the stiff terms in
closed form (:func:`models.cage_dynamics_6dof_jacobian.closed_form_jacobian`: the pocket
films and contacts, the raceway contacts, the end films' squeeze).

The films between a roller and its pocket damp the roller's motion relative to the cage at
rates far above those of the motion itself: an explicit method's steps are held near 1 us by
them (about 900 steps per ms of bearing time at 800 N, 12000 r/min; about 220 with the pocket
arcs switched off, held then by the raceway contacts). The additive method takes these
terms' linearisation ``D`` implicitly and everything else explicitly; the splitting
``f = (f - D y) + D y`` is exact, so its order holds whatever ``D`` is, and ``D`` need only
hold the rates that matter. What then holds its steps is accuracy: the rollers outside the
load zone, pressed on the outer raceway by their centrifugal force alone, vibrate on that
contact near 28 kHz, lightly damped (Hunt-Crossley damping at a light load), and the rollers'
mean slip depends on that motion being resolved.

With the end films' pressure its steps are held again: the films cavitate where they open
(Guembel's condition), so an element's squeeze damping, near 1e8 /s, is there or not by the
sign of a closing speed near zero, and what ``D`` holds of it one step is wrong the next; the
explicit part cannot take the difference. The Rosenbrock-W method can
(:mod:`models.cage_dynamics_6dof_implicit`), and is the default there.

``D`` is evaluated at each accepted step's end (a rejected step is tried again with the
same), and ``I - h gamma D`` factored at every step. Keeping ``D`` over several steps,
which the exact splitting allows, saves Jacobians but costs steps where the stiff terms
change fast (a thin pocket film touching dry, a light load: a third more steps and five
times the rejections, benchmarks/RESULTS.md). The steps do not stop at the output times:
a sample between two steps is the cubic Hermite interpolant of their ends' states and
derivatives, of the third order as the step's error estimate is ([2]_, II.6;
:func:`models.cage_dynamics_6dof_implicit.between`), so the output's interval does not
shorten the steps.

References
----------
.. [1] C. A. Kennedy and M. H. Carpenter, Additive Runge-Kutta schemes for
   convection-diffusion-reaction equations, Applied Numerical Mathematics 44 (2003)
   139-181, doi:10.1016/S0168-9274(02)00138-1.
.. [2] E. Hairer, S. P. Norsett and G. Wanner, Solving Ordinary Differential Equations I,
   2nd ed., Springer (1993), doi:10.1007/978-3-540-78862-1.
"""
from __future__ import annotations

import numpy as np

from .additive_runge_kutta import ERROR, EXPLICIT, GAMMA, IMPLICIT, STAGES, WEIGHTS
from .cage_dynamics_6dof_implicit import blocks, factor, samples_through, solve
from .cage_dynamics_6dof_jacobian import closed_form_jacobian
from .cage_dynamics_6dof_rhs import (_accumulators, _copy, _normalise, _observe,
                                     derivatives)
from .compiled_cache import njit
from .dormand_prince import FIRST_STEP, SMALLEST_STEP
from .rosenbrock import next_step


@njit(cache=True)
def integrate(state, times, p, count, geometry, record, settled_from, rtol, atol, max_steps):
    """The additive Runge-Kutta method, the implicit part's Jacobian at each step's start,
    the samples interpolated between steps
    (:func:`models.cage_dynamics_6dof_implicit.samples_through`); the same samples, extremes,
    events, steps and success as :func:`models.cage_dynamics_6dof_rhs.integrate`."""
    samples, arc_max, end_min, rib_min, last, events = _accumulators(times, state, record)
    y = state.copy()
    n = y.size
    _, arc_theta, arc_z, _, _, _, _ = geometry
    gaps, alongs = np.empty((arc_theta.size, arc_z.size)), np.empty((arc_theta.size,
                                                                     arc_z.size))
    own, to_hub, from_hub, hub, own_inverse, own_to_hub, schur_inverse = blocks(count)
    rates = np.empty((STAGES, n))  # f at each stage
    implicit_rates = np.empty((STAGES, n))  # D z at each stage
    right, sample = np.empty(n), np.empty(n)
    t, h, steps, end, index, fresh = times[0], FIRST_STEP, 0, times[-1], 1, True
    _copy(y, samples[0])
    _observe(y, p, count, geometry, record, t >= settled_from, arc_max, end_min, rib_min,
             last, events)
    _copy(derivatives(y, p, count, *geometry, *record, 0.0), rates[0])
    implicit_rates[0, :] = 0.0
    while index < times.size:
        if steps >= max_steps or h < SMALLEST_STEP:
            return samples, arc_max, end_min, rib_min, events, steps, False
        step = min(h, end - t)
        if fresh:  # the Jacobian at y
            closed_form_jacobian(y, p, count, geometry, gaps, alongs, own, to_hub, from_hub,
                                 hub)
            fresh = False
        shift = 1.0 / (step * GAMMA)
        factor(shift, own, to_hub, from_hub, hub, own_inverse, own_to_hub, schur_inverse)
        for s in range(1, STAGES):
            right[:] = 0.0
            for k in range(s):
                explicit, implicit = step * EXPLICIT[s, k], step * IMPLICIT[s, k]
                for i in range(n):
                    right[i] += (explicit * (rates[k, i] - implicit_rates[k, i])
                                 + implicit * implicit_rates[k, i])
            # (I - h gamma D) z = right, as (I / (h gamma) - D) z = right / (h gamma)
            z = solve(right * shift, count, from_hub, own_inverse, own_to_hub, schur_inverse)
            for i in range(n):
                implicit_rates[s, i] = (z[i] - right[i]) * shift
            _copy(derivatives(y + z, p, count, *geometry, *record, 0.0), rates[s])
        steps += 1
        trial, norm = _solution_and_error(y, rates, step, rtol, atol)
        accepted, h = next_step(step, norm, 4)
        if not accepted:
            continue
        reached = t + step if step < end - t else end
        _normalise(trial, count)
        slope = derivatives(trial, p, count, *geometry, *record, 0.0)
        index = samples_through(reached, index, (y, rates[0], trial, slope, t, step),
                                times, samples, sample, p, count, geometry, record,
                                settled_from, (arc_max, end_min, rib_min, last, events))
        t, y, fresh = reached, trial, True
        _copy(slope, rates[0])
    return samples, arc_max, end_min, rib_min, events, steps, True


@njit(cache=True)
def _solution_and_error(y, rates, step, rtol, atol):
    """The step's fourth-order solution and the root-mean-square of its difference from the
    third-order one against ``atol + rtol max(|y|, |solution|)``: at most 1 accepts it."""
    solution = y.copy()
    squares = 0.0
    for i in range(y.size):
        error = 0.0
        for s in range(STAGES):
            solution[i] += step * WEIGHTS[s] * rates[s, i]
            error += step * ERROR[s] * rates[s, i]
        scaled = error / (atol[i] + rtol * max(abs(y[i]), abs(solution[i])))
        squares += scaled * scaled
    return solution, np.sqrt(squares / y.size)
