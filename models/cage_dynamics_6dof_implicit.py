"""Linearly implicit integration of the spatial cage model
(:mod:`models.cage_dynamics_6dof_rhs`): the Rosenbrock-W method of :mod:`models.rosenbrock`
with the stiff terms' Jacobian in closed form
(:func:`models.cage_dynamics_6dof_jacobian.closed_form_jacobian`), fresh after every
accepted step, and the block solution its structure allows; its samples interpolated between
steps (:func:`between`).

The films between a roller and its pocket, its ribs and its pocket's end faces damp the
roller's motion relative to the cage and the inner ring at rates far above those the motion
itself has (a 7.5 um end film's squeeze near 1e8 /s): an explicit method's steps are held by
them, an implicit one's by the accuracy asked for. A W-method keeps its order whatever matrix
it is given (:mod:`models.rosenbrock`): the closed form holds the stiff terms (the raceway
contacts, the pocket films and contacts, the end films' squeeze where their pressure is
asked for) and leaves out the rest, at a tenth of the cost of finite differences and with
up to half as many steps again (benchmarks/RESULTS.md).

A roller's derivatives depend only on its own state and on the "hub", the inner ring and the
cage, not on the other rollers; the hub's depend on everything. The linear systems
``(I / (h gamma) - J) u = r`` are solved by blocks (:func:`factor`, :func:`solve`): each
roller's block inverted, the hub's 17 unknowns from the Schur complement.

:func:`jacobian` gives the whole Jacobian by forward differences, cheaply by the same
structure: perturbing one component of every roller at once gives each roller's own block
(12 x 12) from its rows and, by the rollers' shares of the hub's forces that
:func:`derivatives` reports, each roller's block of the hub's rows. The terms between a roller
and the cage (its pocket's arcs and end faces) depend on their positions and velocities only
through their differences: differenced apart from the roller's other terms, the roller's
columns give the cage's position and velocity columns too. The cage's attitude and rate and
the inner ring's state are perturbed one by one, each with only the terms it enters: the
ring's columns with the raceway contacts (and the ribs), the cage's with the pockets and the
drag (and the pocket end faces). 11 perturbed columns of the hub, against 173 column by
column. It is the reference the closed form is tested against, and the Jacobian the
libraries' stiff integrators are given (benchmarks/cage_dynamics_6dof_libraries.py).
"""
from __future__ import annotations

import numpy as np

from .cage_dynamics_6dof_rhs import (CAGE_SIZE, DRAG, END_FACES, END_PRESSURE, END_RIBS,
                                     ENDS, HUB, J_CAGE_X, J_CAGE_Z, M_CAGE, M_RING, POCKETS,
                                     RACEWAYS, RING, ROLLER_SIZE, _accumulators, _copy,
                                     _normalise, _observe, derivatives, rotation)
from .cage_dynamics_6dof_jacobian import closed_form_jacobian
from .compiled_cache import njit
from .dormand_prince import FIRST_STEP, SMALLEST_STEP
from .rosenbrock import (GAMMA, STAGES, next_step, solution_and_error, stage_argument,
                         stage_right_side)

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
def blocks(count):
    """The Jacobian's blocks for ``count`` rollers (see :func:`jacobian`) and the factors
    :func:`factor` writes, zeroed."""
    own = np.zeros((count, ROLLER_SIZE, ROLLER_SIZE))
    to_hub = np.zeros((count, ROLLER_SIZE, HUB))
    from_hub = np.zeros((count, HUB, ROLLER_SIZE))
    hub = np.zeros((HUB, HUB))
    return (own, to_hub, from_hub, hub, np.zeros_like(own), np.zeros_like(to_hub),
            np.zeros_like(hub))


def dense(own, to_hub, from_hub, hub):
    """The matrix the blocks stand for, dense: the state's size square."""
    count = own.shape[0]
    hub_rows = hub_indices(count)
    matrix = np.zeros((RING + ROLLER_SIZE * count + CAGE_SIZE,) * 2)
    matrix[np.ix_(hub_rows, hub_rows)] = hub
    for j in range(count):
        rows = np.arange(RING + ROLLER_SIZE * j, RING + ROLLER_SIZE * (j + 1))
        matrix[np.ix_(rows, rows)] = own[j]
        matrix[np.ix_(rows, hub_rows)] = to_hub[j]
        matrix[np.ix_(hub_rows, rows)] = from_hub[j]
    return matrix


@njit(cache=True)
def switched(p, raceways, pockets, faces, ribs, drag):
    """``p`` with its terms switched, each 1.0 (on) or 0.0 (off): the raceway contacts, the
    pockets' arcs, the end terms against the pocket end faces and against the ribs, the
    windage."""
    q = p.copy()
    q[RACEWAYS], q[POCKETS], q[DRAG] = raceways, pockets, drag
    q[END_FACES], q[END_RIBS] = faces, ribs
    q[ENDS] = 1.0 if faces > 0.0 or ribs > 0.0 else 0.0
    return q


@njit(cache=True)
def _roller_columns(y, base, shares, p, count, geometry, record, scale, column):
    """Forward differences of :func:`derivatives` (with ``p``; ``base`` and ``shares`` its
    value and the rollers' shares at ``y``) for one component ``column`` of every roller at
    once: the changes per unit step, each roller's by its own step."""
    moved = y.copy()
    steps = np.empty(count)
    for j in range(count):
        i = RING + ROLLER_SIZE * j + column
        steps[j] = _RELATIVE_STEP * max(abs(y[i]), scale[i])
        moved[i] += steps[j]
    change = derivatives(moved, p, count, *geometry, *record, 0.0) - base
    share_change = record[4] - shares
    for j in range(count):
        k = RING + ROLLER_SIZE * j
        change[k:k + ROLLER_SIZE] /= steps[j]
        share_change[j] /= steps[j]
    return change, share_change


@njit(cache=True)
def _hub_rows(share, turn, p, rows):
    """The hub's rows of a roller's column from its share of the hub's forces: the ring's and
    the cage's accelerations, and the cage's Euler equations in its body frame."""
    rows[:] = 0.0
    rows[2], rows[3] = share[6] / p[M_RING], share[7] / p[M_RING]
    for a in range(3):
        rows[RING + 3 + a] = share[a] / p[M_CAGE]
        body = turn[0, a] * share[3] + turn[1, a] * share[4] + turn[2, a] * share[5]
        rows[RING + 10 + a] = body / (p[J_CAGE_Z] if a == 2 else p[J_CAGE_X])


@njit(cache=True)
def jacobian(y, p, count, geometry, record, scale, own, to_hub, from_hub, hub):
    """The Jacobian of :func:`derivatives`' stiff terms at ``y``, by forward differences of
    steps ``sqrt(eps) max(|y|, scale)``, into the blocks ``own`` ``(count, 12, 12)`` (a
    roller's rows, its columns), ``to_hub`` ``(count, 12, 17)`` (a roller's rows, the hub's
    columns), ``from_hub`` ``(count, 17, 12)`` (the hub's rows, a roller's columns) and
    ``hub`` ``(17, 17)``.

    A roller's columns difference its terms with the cage (the pocket arcs and end faces)
    apart from the others (raceways, ribs, windage): the terms with the cage depend on the
    roller's and the cage's positions and velocities only through their differences, so the
    cage's columns of position and velocity follow from the roller's. The cage's attitude and
    rate, and the ring's columns, are differenced with the terms they enter."""
    ends = 1.0 if p[END_PRESSURE] > 0.0 and p[ENDS] > 0.0 else 0.0
    with_cage = switched(p, 0.0, p[POCKETS], ends * p[END_FACES], 0.0, 0.0)
    others = switched(p, p[RACEWAYS], 0.0, 0.0, ends * p[END_RIBS], p[DRAG])
    bare = switched(p, 0.0, 0.0, 0.0, 0.0, 0.0)
    ring = switched(p, p[RACEWAYS], 0.0, 0.0, ends * p[END_RIBS], 0.0)
    cage = switched(p, 0.0, p[POCKETS], ends * p[END_FACES], 0.0, p[DRAG])
    indices = hub_indices(count)
    hub[:, :] = 0.0
    turn = rotation(y[RING + ROLLER_SIZE * count + 6:RING + ROLLER_SIZE * count + 10])
    rows, cage_rows = np.empty(HUB), np.empty(HUB)
    bases = []
    for terms in (with_cage, others, bare):
        bases.append((derivatives(y, terms, count, *geometry, *record, 0.0),
                      record[4].copy()))
    for column in range(ROLLER_SIZE):
        change, share = _roller_columns(y, *bases[0], with_cage, count, geometry, record,
                                        scale, column)
        other_change, other_share = _roller_columns(y, *bases[1], others, count, geometry,
                                                    record, scale, column)
        # The kinematics and the rollers' gyroscopic terms are in every evaluation.
        bare_change, _ = _roller_columns(y, *bases[2], bare, count, geometry, record, scale,
                                         column)
        translation = column < 6  # a roller's centre or velocity: the cage's likewise
        for j in range(count):
            k = RING + ROLLER_SIZE * j
            _hub_rows(share[j] + other_share[j], turn, p, rows)
            from_hub[j, :, column] = rows
            for r in range(ROLLER_SIZE):
                own[j, r, column] = change[k + r] + other_change[k + r] - bare_change[k + r]
                if translation:
                    to_hub[j, r, RING + column] = -(change[k + r] - bare_change[k + r])
            if translation:
                _hub_rows(share[j], turn, p, cage_rows)
                hub[:, RING + column] -= cage_rows
    for a in range(3):  # the cage's position moves at its velocity
        hub[RING + a, RING + 3 + a] = 1.0
    ring_base = derivatives(y, ring, count, *geometry, *record, 0.0)
    cage_base = derivatives(y, cage, count, *geometry, *record, 0.0)
    for column in range(HUB):
        if RING <= column < RING + 6:
            continue  # from the rollers' columns, above
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


@njit(cache=True)
def factor(diagonal, own, to_hub, from_hub, hub, own_inverse, own_to_hub, schur_inverse):
    """The blocks of ``(diagonal I - J)^-1`` the stages' solutions need (``diagonal`` =
    ``1 / (h gamma)``): each roller's block inverted, its product with the roller's hub
    columns, the Schur complement's inverse. The products pass over the rows of ``to_hub``
    and ``from_hub`` that are zero (a roller's positions and axis, and the hub's, follow
    from velocities alone)."""
    schur = -hub.copy()
    for r in range(HUB):
        schur[r, r] += diagonal
    block = np.empty((ROLLER_SIZE, ROLLER_SIZE))
    for j in range(own.shape[0]):
        for r in range(ROLLER_SIZE):
            for c in range(ROLLER_SIZE):
                block[r, c] = -own[j, r, c]
            block[r, r] += diagonal
        _invert(block, own_inverse[j])
        own_to_hub[j] = 0.0
        for r in range(ROLLER_SIZE):
            if _zero_row(to_hub[j], r):
                continue
            for a in range(ROLLER_SIZE):
                weight = own_inverse[j, a, r]
                for c in range(HUB):
                    own_to_hub[j, a, c] -= weight * to_hub[j, r, c]
        for r in range(HUB):
            if _zero_row(from_hub[j], r):
                continue
            for a in range(ROLLER_SIZE):
                weight = from_hub[j, r, a]
                for c in range(HUB):
                    schur[r, c] += weight * own_to_hub[j, a, c]
    _invert(schur, schur_inverse)


@njit(cache=True, error_model="numpy")  # 1 / 0 is inf, not an error
def _invert(matrix, inverse):
    """``matrix``'s inverse into ``inverse`` by Gauss-Jordan elimination with partial
    pivoting; ``matrix`` is overwritten. In place and without LAPACK's call, whose overhead
    is most of the cost at these sizes (12 and 17 rows). A pivot of exactly zero gives
    infinities, and the step they enter is rejected; a nearly singular matrix gives large
    entries, as LAPACK's inverse does."""
    n = matrix.shape[0]
    inverse[:, :] = 0.0
    for r in range(n):
        inverse[r, r] = 1.0
    for column in range(n):
        pivot = column
        for r in range(column + 1, n):
            if abs(matrix[r, column]) > abs(matrix[pivot, column]):
                pivot = r
        if pivot != column:
            for c in range(n):
                matrix[column, c], matrix[pivot, c] = matrix[pivot, c], matrix[column, c]
                inverse[column, c], inverse[pivot, c] = inverse[pivot, c], inverse[column, c]
        scale = 1.0 / matrix[column, column]
        for c in range(n):
            matrix[column, c] *= scale
            inverse[column, c] *= scale
        for r in range(n):
            weight = matrix[r, column]
            if r == column or weight == 0.0:
                continue
            for c in range(n):
                matrix[r, c] -= weight * matrix[column, c]
                inverse[r, c] -= weight * inverse[column, c]


@njit(cache=True)
def _zero_row(matrix, row):
    for c in range(matrix.shape[1]):
        if matrix[row, c] != 0.0:
            return False
    return True


@njit(cache=True)
def solve(right, count, from_hub, own_inverse, own_to_hub, schur_inverse):
    """``u`` of ``(diagonal I - J) u = right`` from :func:`factor`'s blocks."""
    indices = hub_indices(count)
    solution = np.empty_like(right)
    hub_right = np.empty(HUB)
    for r in range(HUB):
        hub_right[r] = right[indices[r]]
    for j in range(count):
        k = RING + ROLLER_SIZE * j
        for a in range(ROLLER_SIZE):
            total = 0.0
            for b in range(ROLLER_SIZE):
                total += own_inverse[j, a, b] * right[k + b]
            solution[k + a] = total  # the roller's part before the hub's
        for r in range(HUB):
            total = 0.0
            for a in range(ROLLER_SIZE):
                total += from_hub[j, r, a] * solution[k + a]
            hub_right[r] += total  # minus (-from_hub)
    for r in range(HUB):
        total = 0.0
        for c in range(HUB):
            total += schur_inverse[r, c] * hub_right[c]
        solution[indices[r]] = total
    for j in range(count):
        k = RING + ROLLER_SIZE * j
        for a in range(ROLLER_SIZE):
            total = 0.0
            for c in range(HUB):
                total += own_to_hub[j, a, c] * solution[indices[c]]
            solution[k + a] -= total
    return solution


@njit(cache=True)
def integrate(state, times, p, count, geometry, record, settled_from, rtol, atol, max_steps):
    """The Rosenbrock-W method with the closed-form Jacobian
    (:func:`models.cage_dynamics_6dof_jacobian.closed_form_jacobian`) after every accepted
    step, the samples interpolated between steps (:func:`samples_through`); the same samples,
    extremes, events, steps and success as :func:`models.cage_dynamics_6dof_rhs.integrate`."""
    samples, arc_max, end_min, rib_min, last, events = _accumulators(times, state, record)
    y = state.copy()
    n = y.size
    _, arc_theta, arc_z, _, _, _, _ = geometry
    gaps, alongs = np.empty((arc_theta.size, arc_z.size)), np.empty((arc_theta.size,
                                                                     arc_z.size))
    own, to_hub, from_hub, hub, own_inverse, own_to_hub, schur_inverse = blocks(count)
    stages, sample = np.empty((STAGES, n)), np.empty(n)
    t, h, steps, end, index = times[0], FIRST_STEP, 0, times[-1], 1
    _copy(y, samples[0])
    _observe(y, p, count, geometry, record, t >= settled_from, arc_max, end_min, rib_min,
             last, events)
    derivative = derivatives(y, p, count, *geometry, *record, 0.0)
    fresh = True  # the Jacobian is to be evaluated at y
    while index < times.size:
        if steps >= max_steps or h < SMALLEST_STEP:
            return samples, arc_max, end_min, rib_min, events, steps, False
        step = min(h, end - t)
        if fresh:
            closed_form_jacobian(y, p, count, geometry, gaps, alongs, own, to_hub, from_hub,
                                 hub)
            fresh = False
        factor(1.0 / (step * GAMMA), own, to_hub, from_hub, hub, own_inverse, own_to_hub,
               schur_inverse)
        for s in range(STAGES):
            value = derivative if s == 0 else derivatives(
                stage_argument(y, stages, s), p, count, *geometry, *record, 0.0)
            stages[s] = solve(stage_right_side(value, stages, s, step), count, from_hub,
                              own_inverse, own_to_hub, schur_inverse)
        steps += 1
        trial, norm = solution_and_error(y, stages, rtol, atol)
        accepted, h = next_step(step, norm)
        if not accepted:
            continue
        reached = t + step if step < end - t else end
        _normalise(trial, count)
        slope = derivatives(trial, p, count, *geometry, *record, 0.0)
        index = samples_through(reached, index, (y, derivative, trial, slope, t, step), times,
                                samples, sample, p, count, geometry, record, settled_from,
                                (arc_max, end_min, rib_min, last, events))
        t, y, derivative, fresh = reached, trial, slope, True
    return samples, arc_max, end_min, rib_min, events, steps, True


@njit(cache=True)
def samples_through(reached, index, step_ends, times, samples, sample, p, count, geometry,
                    record, settled_from, observed):
    """Write the samples from ``times[index]`` through ``reached`` [s], the end of a step
    (``step_ends``: its states and derivatives at both ends, its start and size [s]), each
    by :func:`between`, and observe them (:func:`_observe`, into ``observed``); returns the
    next sample's index."""
    y0, f0, y1, f1, t, step = step_ends
    arc_max, end_min, rib_min, last, events = observed
    while index < times.size and times[index] <= reached:
        if times[index] == reached:
            _copy(y1, sample)
        else:
            between(y0, f0, y1, f1, step, (times[index] - t) / step, sample)
            _normalise(sample, count)
        _copy(sample, samples[index])
        _observe(sample, p, count, geometry, record, times[index] >= settled_from, arc_max,
                 end_min, rib_min, last, events)
        index += 1
    return index


@njit(cache=True)
def between(y0, f0, y1, f1, step, theta, out):
    """The state a fraction ``theta`` of the way through a step of size ``step`` [s] from
    ``y0`` to ``y1`` (their derivatives ``f0``, ``f1``), into ``out``: the cubic Hermite
    interpolant, of the third order, as the integrators' error estimates are.

    References
    ----------
    .. [1] E. Hairer, S. P. Norsett and G. Wanner, Solving Ordinary Differential Equations I,
       2nd ed., Springer (1993), doi:10.1007/978-3-540-78862-1, II.6 (dense output).
    """
    theta2 = theta * theta
    theta3 = theta2 * theta
    start, end = 2.0 * theta3 - 3.0 * theta2 + 1.0, 3.0 * theta2 - 2.0 * theta3
    start_slope, end_slope = step * (theta3 - 2.0 * theta2 + theta), step * (theta3 - theta2)
    for i in range(y0.size):
        out[i] = start * y0[i] + start_slope * f0[i] + end * y1[i] + end_slope * f1[i]
