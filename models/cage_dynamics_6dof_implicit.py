"""Linearly implicit integration of the spatial cage model
(:mod:`models.cage_dynamics_6dof_rhs`): the Rosenbrock-W method of :mod:`models.rosenbrock`
with the right-hand side's Jacobian from finite differences, fresh at every step.

The films between a roller and its pocket, its ribs and its pocket's end faces damp the
roller's motion relative to the cage and the inner ring at rates far above those the motion
itself has (a 7.5 um end film's squeeze near 1e8 /s): an explicit method's steps are held by
them, an implicit one's by the accuracy asked for.

The Jacobian's structure makes it cheap. A roller's derivatives depend only on its own state
and on the "hub", the inner ring and the cage, not on the other rollers; the hub's depend on
everything. Perturbing one component of every roller at once gives each roller's own block
(12 x 12) from its rows and, by the rollers' shares of the hub's forces that
:func:`derivatives` reports, each roller's block of the hub's rows; perturbing each of the
hub's 17 components gives its columns. 29 evaluations in all, against 173 column by column.
Each evaluates only the terms its component enters: the inner ring's columns the raceway
contacts (and the ribs), the cage's the pockets and the drag (and the cage's end faces).

The Jacobian holds the stiff terms: the raceway contacts, the pocket films and contacts, and
the end films where their pressure is asked for (``END_PRESSURE``). The end films' shear
alone is left out: it is not stiff (the steps are the same with it and without it, at half
the Jacobian's cost), and a W-method keeps its order whatever matrix it is given
(:mod:`models.rosenbrock`). The linear systems
``(I / (h gamma) - J) u = r`` are then solved by blocks: each roller's block inverted, the
hub's 17 unknowns from the Schur complement.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from .cage_dynamics_6dof_rhs import (CAGE_SIZE, DRAG, END_PRESSURE, ENDS, J_CAGE_X,
                                     J_CAGE_Z, M_CAGE, M_RING, POCKETS, RACEWAYS, RING,
                                     ROLLER_SIZE, _accumulators, _copy, _normalise, _observe,
                                     derivatives, rotation)
from .dormand_prince import FIRST_STEP, SMALLEST_STEP
from .rosenbrock import (GAMMA, STAGES, next_step, solution_and_error, stage_argument,
                         stage_right_side)

HUB = RING + CAGE_SIZE
_RELATIVE_STEP = 1.4901161193847656e-08  # sqrt of the double's epsilon


@njit(cache=True)
def hub_indices(count):
    """The hub's entries in the state: the inner ring's 4, then the cage's 13."""
    first_cage = RING + ROLLER_SIZE * count
    indices = np.empty(HUB, dtype=np.int64)
    for i in range(RING):
        indices[i] = i
    for i in range(CAGE_SIZE):
        indices[RING + i] = first_cage + i
    return indices


@njit(cache=True)
def switched(p, raceways, pockets, ends, drag):
    """``p`` with its terms switched: each switch 1.0 (on) or 0.0 (off)."""
    q = p.copy()
    q[RACEWAYS], q[POCKETS], q[ENDS], q[DRAG] = raceways, pockets, ends, drag
    return q


@njit(cache=True)
def jacobian(y, p, count, geometry, record, scale, own, to_hub, from_hub, hub):
    """The Jacobian of :func:`derivatives`' stiff terms at ``y``, by forward differences of
    steps ``sqrt(eps) max(|y|, scale)``, into the blocks ``own`` ``(count, 12, 12)`` (a
    roller's rows, its columns), ``to_hub`` ``(count, 12, 17)`` (a roller's rows, the hub's
    columns), ``from_hub`` ``(count, 17, 12)`` (the hub's rows, a roller's columns) and
    ``hub`` ``(17, 17)``."""
    ends = p[ENDS] if p[END_PRESSURE] > 0.0 else 0.0
    stiff = switched(p, p[RACEWAYS], p[POCKETS], ends, p[DRAG])
    ring = switched(p, p[RACEWAYS], 0.0, ends, 0.0)
    cage = switched(p, 0.0, p[POCKETS], ends, p[DRAG])
    ring_base = derivatives(y, ring, count, *geometry, *record, 0.0)
    cage_base = derivatives(y, cage, count, *geometry, *record, 0.0)
    indices = hub_indices(count)
    for column in range(HUB):
        terms, base = (ring, ring_base) if column < RING else (cage, cage_base)
        i = indices[column]
        step = _RELATIVE_STEP * max(abs(y[i]), scale[i])
        moved = y.copy()
        moved[i] += step
        change = (derivatives(moved, terms, count, *geometry, *record, 0.0) - base) / step
        for j in range(count):
            k = RING + ROLLER_SIZE * j
            for r in range(ROLLER_SIZE):
                to_hub[j, r, column] = change[k + r]
        for r in range(HUB):
            hub[r, column] = change[indices[r]]
    derivative = derivatives(y, stiff, count, *geometry, *record, 0.0)
    shares = record[4].copy()
    turn = rotation(y[RING + ROLLER_SIZE * count + 6:RING + ROLLER_SIZE * count + 10])
    steps = np.empty(count)
    for column in range(ROLLER_SIZE):
        moved = y.copy()
        for j in range(count):
            i = RING + ROLLER_SIZE * j + column
            steps[j] = _RELATIVE_STEP * max(abs(y[i]), scale[i])
            moved[i] += steps[j]
        change = derivatives(moved, stiff, count, *geometry, *record, 0.0) - derivative
        moved_shares = record[4]
        for j in range(count):
            k = RING + ROLLER_SIZE * j
            for r in range(ROLLER_SIZE):
                own[j, r, column] = change[k + r] / steps[j]
            # The hub's rows, through the roller's share of its forces: the ring's and the
            # cage's accelerations, and the cage's Euler equations in its body frame.
            share = (moved_shares[j] - shares[j]) / steps[j]
            for r in range(HUB):
                from_hub[j, r, column] = 0.0
            from_hub[j, 2, column] = share[6] / p[M_RING]
            from_hub[j, 3, column] = share[7] / p[M_RING]
            for a in range(3):
                from_hub[j, RING + 3 + a, column] = share[a] / p[M_CAGE]
                body = turn[0, a] * share[3] + turn[1, a] * share[4] + turn[2, a] * share[5]
                inertia = p[J_CAGE_Z] if a == 2 else p[J_CAGE_X]
                from_hub[j, RING + 10 + a, column] = body / inertia


@njit(cache=True)
def factor(step, own, to_hub, from_hub, hub, own_inverse, own_to_hub, schur_inverse):
    """The blocks of ``(I / (h gamma) - J)^-1`` the stages' solutions need: each roller's
    block inverted, its product with the roller's hub columns, the Schur complement's
    inverse."""
    diagonal = 1.0 / (step * GAMMA)
    schur = -hub.copy()
    for r in range(HUB):
        schur[r, r] += diagonal
    for j in range(own.shape[0]):
        block = -own[j]
        for r in range(ROLLER_SIZE):
            block[r, r] += diagonal
        own_inverse[j] = np.linalg.inv(block)
        own_to_hub[j] = own_inverse[j] @ (-to_hub[j])
        schur -= (-from_hub[j]) @ own_to_hub[j]
    schur_inverse[:, :] = np.linalg.inv(schur)


@njit(cache=True)
def solve(right, count, from_hub, own_inverse, own_to_hub, schur_inverse):
    """``u`` of ``(I / (h gamma) - J) u = right`` from :func:`factor`'s blocks."""
    indices = hub_indices(count)
    solution = np.empty_like(right)
    hub_right = np.empty(HUB)
    for r in range(HUB):
        hub_right[r] = right[indices[r]]
    partial = np.empty((count, ROLLER_SIZE))
    for j in range(count):
        k = RING + ROLLER_SIZE * j
        partial[j] = own_inverse[j] @ right[k:k + ROLLER_SIZE]
        hub_right += from_hub[j] @ partial[j]  # minus (-from_hub)
    hub_solution = schur_inverse @ hub_right
    for r in range(HUB):
        solution[indices[r]] = hub_solution[r]
    for j in range(count):
        k = RING + ROLLER_SIZE * j
        solution[k:k + ROLLER_SIZE] = partial[j] - own_to_hub[j] @ hub_solution
    return solution


@njit(cache=True)
def integrate(state, times, p, count, geometry, record, settled_from, rtol, atol, max_steps):
    """The Rosenbrock-W method with the Jacobian fresh at every step, each sample time hit
    by a step; the same samples, extremes, events, steps and success as
    :func:`models.cage_dynamics_6dof_rhs.integrate`."""
    samples, arc_max, end_min, rib_min, last, events = _accumulators(times, state, record)
    y = state.copy()
    n = y.size
    scale = atol / rtol
    own = np.zeros((count, ROLLER_SIZE, ROLLER_SIZE))
    to_hub = np.zeros((count, ROLLER_SIZE, HUB))
    from_hub = np.zeros((count, HUB, ROLLER_SIZE))
    hub = np.zeros((HUB, HUB))
    own_inverse = np.zeros_like(own)
    own_to_hub = np.zeros_like(to_hub)
    schur_inverse = np.zeros_like(hub)
    stages = np.empty((STAGES, n))
    t, h, steps = times[0], FIRST_STEP, 0
    _copy(y, samples[0])
    _observe(y, p, count, geometry, record, t >= settled_from, arc_max, end_min, rib_min,
             last, events)
    derivative = derivatives(y, p, count, *geometry, *record, 0.0)
    jacobian(y, p, count, geometry, record, scale, own, to_hub, from_hub, hub)
    for index in range(1, times.size):
        while t < times[index]:
            if steps >= max_steps or h < SMALLEST_STEP:
                return samples, arc_max, end_min, rib_min, events, steps, False
            step = min(h, times[index] - t)
            factor(step, own, to_hub, from_hub, hub, own_inverse, own_to_hub, schur_inverse)
            for s in range(STAGES):
                value = derivative if s == 0 else derivatives(
                    stage_argument(y, stages, s), p, count, *geometry, *record, 0.0)
                stages[s] = solve(stage_right_side(value, stages, s, step), count, from_hub,
                                  own_inverse, own_to_hub, schur_inverse)
            steps += 1
            trial, norm = solution_and_error(y, stages, rtol, atol)
            accepted, h = next_step(step, norm)
            if accepted:
                t = t + step if step < times[index] - t else times[index]
                y = trial
                _normalise(y, count)
                derivative = derivatives(y, p, count, *geometry, *record, 0.0)
                jacobian(y, p, count, geometry, record, scale, own, to_hub, from_hub, hub)
        _copy(y, samples[index])
        _observe(y, p, count, geometry, record, t >= settled_from, arc_max, end_min,
                 rib_min, last, events)
    return samples, arc_max, end_min, rib_min, events, steps, True
