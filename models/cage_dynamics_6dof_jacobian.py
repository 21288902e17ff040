"""The Jacobian of the spatial cage model's stiff terms
(:mod:`models.cage_dynamics_6dof_rhs`) in closed form, into the blocks of
:func:`models.cage_dynamics_6dof_implicit.factor`: the implicit part ``D`` of the additive
method (:mod:`models.cage_dynamics_6dof_imex`) and the matrix of the Rosenbrock-W method
(:mod:`models.cage_dynamics_6dof_implicit`).

It is built by hand, element by element and slice by slice (:func:`closed_form_jacobian`):

- each pocket element's push on the roller, ``-A p n`` in its film (eq. 3's role; the short
  bearing's pressure ``p``) or ``-k delta (1 + C_n delta') n`` when pressed in (eqs. 1, 2),
  depends on the roller's speed of approach to the wall, its spin relative to the cage, the
  gap and the film's slope round the arc; their gradients over the roller's and the cage's
  positions, attitudes and velocities, summed over the elements, give the forces' and
  moments' derivatives. The cage's attitude columns follow from the terms' covariance:
  turning the cage is turning the roller back about the cage's mass centre;
- each raceway slice's push ``K delta^(10/9) (1 + C_n delta')`` and traction (eqs. 18-21)
  by the approach, the approach speed and the sliding (:func:`_raceway_gradient`), over the
  roller's state and the inner ring's;
- where the end films' pressure is asked for, each end-face element's squeeze damping
  ``6 eta A (s - s_1)(s_2 - s) / h^3`` by the closing speed, on the pocket end faces and the
  ribs (:func:`_squeeze_gradient`, over the roller's velocities and the face's body's).

Left out, as not stiff (the right-hand side keeps them all): the pocket films' shear and
their cavitated elements, the dry contacts' friction, the turning of a force's direction with
the normal and the pocket elements' shift along the roller, the end films' shear and their
dry contacts, the rollers' gyroscopic terms.
"""
from __future__ import annotations

import numpy as np

from .cage_dynamics_6dof_rhs import (BED_POCKET, END_FACES, END_PRESSURE, END_RIBS,
                                     ENDS, FILM_FILL, FILM_FLOOR, HUB, HUNT,
                                     J_AXIAL, J_CAGE_X, J_CAGE_Z, J_TRANSVERSE, K_SLICE,
                                     LENGTH, M_CAGE, M_RING, M_ROLLER, OMEGA_I, POCKETS,
                                     RACEWAYS, RADIUS, RING, ROLLER_SIZE, TRACTION_A,
                                     TRACTION_B, TRACTION_C, TRACTION_D, VISCOSITY, _add,
                                     _cross, _dot, _end_face, _mul, _sub, _tangential,
                                     _vector, arc_element, arc_slope, arc_wall, cage_frame,
                                     end_faces, pocket_frame, pocket_gaps, pocket_motion,
                                     raceway_slice, ring_axis, roller_end)
from .compiled_cache import njit
from .contact_laws import (PALMGREN_EXPONENT, palmgren_slice, traction_coefficient,
                           traction_slope)

# The columns of an element's gradients: the roller's centre, velocity, attitude (a small
# rotation) and angular velocity, the cage's mass centre, velocity and angular velocity (in
# the inertial frame), three each.
_C, _V, _THETA, _OMEGA, _S, _W, _CAGE_OMEGA = 0, 3, 6, 9, 12, 15, 18
_COLUMNS = 21


@njit(cache=True)
def _put(vector, into, start, scale):
    for a in range(3):
        into[start + a] = scale * vector[a]


@njit(cache=True)
def _cross_matrix(v):
    """``[v x]``: the matrix of ``w -> v x w``."""
    matrix = np.empty((3, 3))
    _fill_cross_matrix(v, matrix)
    return matrix


@njit(cache=True)
def _fill_cross_matrix(v, matrix):
    """``[v x]`` into ``matrix``."""
    matrix[0, 0], matrix[0, 1], matrix[0, 2] = 0.0, -v[2], v[1]
    matrix[1, 0], matrix[1, 1], matrix[1, 2] = v[2], 0.0, -v[0]
    matrix[2, 0], matrix[2, 1], matrix[2, 2] = -v[1], v[0], 0.0


@njit(cache=True)
def _roller_wrench_gradient(y, p, j, count, geometry, arc_cos, arc_sin, frame, gaps, alongs,
                            wrench, gradient, d_closing, d_spin, d_gap, d_slope):
    """The pushes of pocket ``j``'s elements on its roller (``wrench``: force [N], moment
    about its centre [N m]) and their gradient over :data:`_COLUMNS` (``gradient``, 6 x 21);
    ``arc_cos`` and ``arc_sin`` are the arc angles' cosines and sines, the other arguments
    work arrays. Returns the roller's centre, velocity, axis and angular velocity."""
    _, arc_theta, arc_z, arc_area, _, _, _ = geometry
    mass_centre, cage_velocity, cage_rate, x_b, y_b, z_b, cage_centre = frame
    k = RING + ROLLER_SIZE * j
    centre, velocity = _vector(y, k), _vector(y, k + 3)
    axis = _vector(y, k + 6)
    axis = _mul(1.0 / np.sqrt(_dot(axis, axis)), axis)
    omega = _vector(y, k + 9)
    wrench[:] = 0.0
    gradient[:, :] = 0.0
    if p[POCKETS] <= 0.0:
        return centre, velocity, axis, omega
    x_c, y_c, pocket = pocket_frame(j, count, x_b, y_b, cage_centre, p)
    pressed = pocket_gaps(centre, axis, pocket, x_c, y_c, z_b, arc_cos, arc_sin, arc_z, p,
                          gaps, alongs)
    spin = _dot(_sub(omega, cage_rate), z_b)
    radius, viscosity = p[RADIUS], p[VISCOSITY]
    d_spin[:] = 0.0
    _put(z_b, d_spin, _OMEGA, 1.0)
    _put(z_b, d_spin, _CAGE_OMEGA, -1.0)
    motion = pocket_motion(centre, velocity, axis, omega, pocket, x_c, y_c, z_b,
                           cage_velocity, cage_rate, mass_centre)
    for m in range(arc_theta.size):
        cos_m, sin_m = arc_cos[m], arc_sin[m]
        u = _add(_mul(cos_m, x_c), _mul(sin_m, y_c))
        u_prime = _sub(_mul(cos_m, y_c), _mul(sin_m, x_c))
        wall, base = arc_wall(u, motion, cage_rate, p)
        for n in range(arc_z.size):
            h = gaps[m, n]
            if h == np.inf or (pressed and h >= 0.0):
                continue
            along = alongs[m, n]
            arm, normal, relative, closing = arc_element(wall, base, arc_z[n], z_b, along, h,
                                                         axis, motion, p)
            # the push on the roller, -push n, and its weights on the closing speed, the
            # spin, the gap and the slope
            if pressed:
                stiffness = p[BED_POCKET] * arc_area[m, n]
                push = stiffness * (-h) * (1.0 + p[HUNT] * closing)
                if push <= 0.0:
                    continue
                on_closing, on_spin = stiffness * (-h) * p[HUNT], 0.0
                on_gap, on_slope = -stiffness * (1.0 + p[HUNT] * closing), 0.0
            else:
                film = max(h, p[FILM_FLOOR])
                slope = arc_slope(along, motion, cos_m, sin_m)
                reach = (along * along - 0.25 * p[LENGTH] ** 2) / (2.0 * film ** 3)
                pressure = (6.0 * viscosity * spin * slope - 12.0 * viscosity * closing) * reach
                if pressure <= 0.0:
                    continue  # cavitated
                area = arc_area[m, n] * p[FILM_FILL]
                push = area * pressure
                on_closing = -12.0 * viscosity * reach * area
                on_spin = 6.0 * viscosity * slope * reach * area
                on_slope = 6.0 * viscosity * spin * reach * area
                # below the floor the film does not thin
                on_gap = -3.0 * push / film if h > p[FILM_FLOOR] else 0.0
            lever = _mul(along, axis)  # the foot from the roller's centre
            across = _sub(relative, _mul(_dot(relative, normal), normal))
            turn = 1.0 / (h + radius)  # the normal turns as the roller moves across it
            lever_normal = _cross(lever, normal)
            _put(across, d_closing, _C, -turn)
            _put(normal, d_closing, _V, 1.0)
            _put(_cross(lever, across), d_closing, _THETA, -turn)
            _put(lever_normal, d_closing, _OMEGA, 1.0)
            _put(across, d_closing, _S, turn)
            _put(normal, d_closing, _W, -1.0)
            _put(_cross(_add(_sub(centre, mass_centre), arm), normal), d_closing, _CAGE_OMEGA,
                 -1.0)
            _put(normal, d_gap, _C, -1.0)
            _put(lever_normal, d_gap, _THETA, -1.0)
            _put(normal, d_gap, _S, 1.0)
            _put(u_prime, d_slope, _C, -1.0)
            _put(_cross(lever, u_prime), d_slope, _THETA, -1.0)
            _put(u_prime, d_slope, _S, 1.0)
            moment_normal = _cross(arm, normal)
            for a in range(3):
                wrench[a] -= push * normal[a]
                wrench[3 + a] -= push * moment_normal[a]
            for c in range(_COLUMNS):
                if _S <= c < _CAGE_OMEGA:
                    continue  # the cage's centre and velocity: below
                change = -(on_closing * d_closing[c] + on_spin * d_spin[c]
                           + on_gap * d_gap[c] + on_slope * d_slope[c])
                for a in range(3):
                    gradient[a, c] += normal[a] * change
                    gradient[3 + a, c] += moment_normal[a] * change
    # The pocket terms see the roller's and the cage's centres and velocities only through
    # their differences: the cage's columns are the roller's, negated.
    for a in range(6):
        for b in range(3):
            gradient[a, _S + b] = -gradient[a, _C + b]
            gradient[a, _W + b] = -gradient[a, _V + b]
    return centre, velocity, axis, omega


@njit(cache=True)
def _raceway_gradient(p, slice_z, centre, velocity, axis, omega, ring_centre, ring_velocity,
                      z_ring, ring_spin, gradient, ring_gradient):
    """The gradient of a roller's raceway contacts (eqs. 18-21): of the force on it and their
    moment about its centre (``gradient``, 6 x 18), and of the force of the inner contacts on
    the ring (``ring_gradient``, 3 x 18), over the roller's centre, velocity, attitude (a
    small rotation) and angular velocity and the ring's centre and velocity (the columns
    :data:`_C` to :data:`_W`, the ring in the cage's places). Each slice's push
    ``K delta^(10/9) (1 + C_n delta')`` by its approach and approach speed, and its traction
    ``-mu(s) push s / |s|`` by its push and its sliding ``s``, and the moment's arm turning
    with the roller; left out, as not stiff: the turning of the normal with a move, the ring's
    spin carried with it."""
    gradient[:, :] = 0.0
    ring_gradient[:, :] = 0.0
    force = np.empty((3, _W + 3))  # a slice's force on the roller over the columns
    traction, arm_matrix = np.empty((3, 3)), np.empty((3, 3))
    for z in slice_z:
        middle = _add(centre, _mul(z, axis))
        for inner in (True, False):
            approach, normal, point, relative = raceway_slice(
                middle, inner, centre, velocity, omega, ring_centre, ring_velocity, z_ring,
                ring_spin, p)
            if approach <= 0.0:
                continue
            arm = _sub(point, centre)
            rate = -_dot(relative, normal)
            load = palmgren_slice(p[K_SLICE], approach)
            push = load * (1.0 + p[HUNT] * rate)
            if push <= 0.0:
                continue
            on_approach = PALMGREN_EXPONENT * push / approach
            on_rate = load * p[HUNT]
            sliding, speed = _tangential(relative, normal)
            if speed > 0.0:
                mu = traction_coefficient(speed, p[TRACTION_A], p[TRACTION_B], p[TRACTION_C],
                                          p[TRACTION_D])
                ratio = mu / speed
                bend = traction_slope(speed, p[TRACTION_A], p[TRACTION_B], p[TRACTION_C],
                                      p[TRACTION_D]) - ratio
            else:
                mu, ratio, bend = 0.0, 0.0, 0.0
            direction = _mul(1.0 / speed, sliding) if speed > 0.0 else (0.0, 0.0, 0.0)
            per_push = _sub(normal, _mul(mu, direction))  # the force per unit push
            # the traction's gradient over the relative velocity, push T (T on the tangent
            # plane: the ratio mu/s across the sliding, the slope along it)
            for r in range(3):
                for c in range(3):
                    across = (1.0 if r == c else 0.0) - normal[r] * normal[c]
                    traction[r, c] = push * (ratio * across + bend * direction[r]
                                             * direction[c])
            lever_normal = _cross(_mul(z, axis), normal)  # the approach's turn by a tilt
            _fill_cross_matrix(arm, arm_matrix)  # the relative velocity by omega: -[arm x]
            for r in range(3):
                for c in range(3):
                    spin = 0.0
                    for k in range(3):
                        spin += traction[r, k] * arm_matrix[k, c]
                    force[r, _C + c] = -on_approach * per_push[r] * normal[c]
                    force[r, _THETA + c] = -on_approach * per_push[r] * lever_normal[c]
                    force[r, _V + c] = -on_rate * per_push[r] * normal[c] - traction[r, c]
                    force[r, _OMEGA + c] = -on_rate * per_push[r] * lever_normal[c] + spin
                    if inner:
                        force[r, _S + c] = -force[r, _C + c]
                        force[r, _W + c] = on_rate * per_push[r] * normal[c] + traction[r, c]
            # A tilt moves the contact point (z t x a) under the roller's spin and, at the
            # inner ring, the ring's: the relative velocity changes by -z [(w - W) x][a x] t.
            carried = _sub(omega, ring_spin) if inner else omega
            for c in range(3):
                moved = _mul(-z, _cross(carried, _cross(axis, (
                    1.0 if c == 0 else 0.0, 1.0 if c == 1 else 0.0, 1.0 if c == 2 else 0.0))))
                by_rate = -on_rate * _dot(normal, moved)
                for r in range(3):
                    force[r, _THETA + c] += by_rate * per_push[r] - (
                        traction[r, 0] * moved[0] + traction[r, 1] * moved[1]
                        + traction[r, 2] * moved[2])
            for c in range(_W + 3 if inner else _S):
                column = (force[0, c], force[1, c], force[2, c])
                turning = _cross(arm, column)
                if _THETA <= c < _THETA + 3:  # the arm turns with the roller: z (t x a) x F
                    unit = (1.0 if c == _THETA else 0.0, 1.0 if c == _THETA + 1 else 0.0,
                            1.0 if c == _THETA + 2 else 0.0)
                    turning = _add(turning, _mul(z, _cross(_cross(unit, axis), _mul(
                        push, per_push))))
                for r in range(3):
                    gradient[r, c] += column[r]
                    gradient[3 + r, c] += turning[r]
                    if inner:
                        ring_gradient[r, c] += column[r]


@njit(cache=True)
def closed_form_jacobian(y, p, count, geometry, gaps, alongs, own, to_hub, from_hub, hub):
    """The Jacobian of the stiff terms of :func:`models.cage_dynamics_6dof_rhs.derivatives`
    at ``y`` in closed form (the module's text), with the kinematics that couple positions
    to velocities, into the blocks of :func:`models.cage_dynamics_6dof_implicit.factor`
    (``own``, ``to_hub``, ``from_hub``, ``hub``); ``gaps`` and ``alongs`` are work arrays of
    the pocket arcs' shape."""
    own[:, :, :] = 0.0
    to_hub[:, :, :] = 0.0
    from_hub[:, :, :] = 0.0
    hub[:, :] = 0.0
    c0 = RING + ROLLER_SIZE * count
    turn, _, frame = cage_frame(y, count, p)
    mass_centre, cage_velocity = frame[0], frame[1]
    # a small turn of the cage (rotation vector) as quaternion columns: phi = 2 vec(dq q*)
    q = y[c0 + 6:c0 + 10] / np.sqrt(np.sum(y[c0 + 6:c0 + 10] ** 2))
    to_quaternion = np.zeros((3, 4))
    vector_part = _cross_matrix((q[1], q[2], q[3]))
    for a in range(3):
        to_quaternion[a, 0] = -2.0 * q[1 + a]
        for b in range(3):
            to_quaternion[a, 1 + b] = 2.0 * ((q[0] if a == b else 0.0) + vector_part[a, b])
    body_inertia = (p[J_CAGE_X], p[J_CAGE_X], p[J_CAGE_Z])
    wrench, gradient = np.empty(6), np.empty((6, _COLUMNS))
    # every element writes all of d_closing and the same blocks of d_gap and d_slope
    d_closing, d_spin = np.empty(_COLUMNS), np.empty(_COLUMNS)
    d_gap, d_slope = np.zeros(_COLUMNS), np.zeros(_COLUMNS)
    rows, forces = np.empty((12, _COLUMNS)), np.empty(12)
    turned, by_state = np.empty((12, 3)), np.empty((12, ROLLER_SIZE + HUB))
    inverse = np.empty((3, 3))
    race, ring_race = np.empty((6, _W + 3)), np.empty((3, _W + 3))
    ring_centre, ring_velocity = (y[0], y[1], 0.0), (y[2], y[3], 0.0)
    z_ring = ring_axis(p)
    ring_spin = _mul(p[OMEGA_I], z_ring)
    squeezed = p[ENDS] > 0.0 and p[END_PRESSURE] > 0.0
    faces = end_faces(frame, ring_centre, ring_velocity, z_ring, ring_spin, p)
    face_cos, face_sin = np.cos(geometry[5]), np.sin(geometry[5])
    arc_cos, arc_sin = np.cos(geometry[1]), np.sin(geometry[1])  # once, not per roller
    work = np.empty((1, 10))
    for j in range(count):
        centre, velocity, axis, omega = _roller_wrench_gradient(
            y, p, j, count, geometry, arc_cos, arc_sin, frame, gaps, alongs, wrench, gradient,
            d_closing, d_spin, d_gap, d_slope)
        if squeezed and p[END_FACES] > 0.0:
            for side in range(2):
                _squeeze_gradient(roller_end(centre, velocity, omega, axis, side, p[LENGTH]),
                                  *faces[0], face_cos, face_sin, geometry, p, work,
                                  gradient, None, _W, _CAGE_OMEGA)
        _outputs(gradient, wrench, _sub(centre, mass_centre), rows, forces)
        _cage_turned(rows, forces, centre, velocity, omega, mass_centre, cage_velocity,
                     turned)
        _by_state(rows, turned, axis, turn, to_quaternion, by_state)
        # rows: the roller's acceleration F / m and angular acceleration (J^-1 M, symmetric
        # about the axis), the cage's acceleration and its Euler equations' body moment
        for a in range(3):
            for b in range(3):
                inverse[a, b] = ((1.0 if a == b else 0.0) - axis[a] * axis[b]) \
                    / p[J_TRANSVERSE] + axis[a] * axis[b] / p[J_AXIAL]
        for column in range(ROLLER_SIZE + HUB):
            hub_column = column - ROLLER_SIZE
            for a in range(3):
                accelerations = (by_state[a, column] / p[M_ROLLER],
                                 inverse[a, 0] * by_state[3, column]
                                 + inverse[a, 1] * by_state[4, column]
                                 + inverse[a, 2] * by_state[5, column],
                                 by_state[6 + a, column] / p[M_CAGE],
                                 (turn[0, a] * by_state[9, column]
                                  + turn[1, a] * by_state[10, column]
                                  + turn[2, a] * by_state[11, column]) / body_inertia[a])
                if hub_column < 0:
                    own[j, 3 + a, column] += accelerations[0]
                    own[j, 9 + a, column] += accelerations[1]
                    from_hub[j, RING + 3 + a, column] += accelerations[2]
                    from_hub[j, RING + 10 + a, column] += accelerations[3]
                else:
                    to_hub[j, 3 + a, hub_column] += accelerations[0]
                    to_hub[j, 9 + a, hub_column] += accelerations[1]
                    hub[RING + 3 + a, hub_column] += accelerations[2]
                    hub[RING + 10 + a, hub_column] += accelerations[3]
        race[:, :] = 0.0
        ring_race[:, :] = 0.0
        if p[RACEWAYS] > 0.0:
            _raceway_gradient(p, geometry[0], centre, velocity, axis, omega, ring_centre,
                              ring_velocity, z_ring, ring_spin, race, ring_race)
        if squeezed and p[END_RIBS] > 0.0:  # the ring's spin is no unknown: no rate column
            for side in range(2):
                _squeeze_gradient(roller_end(centre, velocity, omega, axis, side, p[LENGTH]),
                                  *faces[1], face_cos, face_sin, geometry, p, work, race,
                                  ring_race, _W, -1)
        if p[RACEWAYS] > 0.0 or (squeezed and p[END_RIBS] > 0.0):
            _add_raceways(j, race, ring_race, axis, inverse, p, own, to_hub, from_hub, hub)
        # the roller's centre moves at its velocity, its axis with omega: d(w x a)/dw = -[a x]
        own[j, 0, 3] = own[j, 1, 4] = own[j, 2, 5] = 1.0
        own[j, 6, 10], own[j, 6, 11] = axis[2], -axis[1]
        own[j, 7, 9], own[j, 7, 11] = -axis[2], axis[0]
        own[j, 8, 9], own[j, 8, 10] = axis[1], -axis[0]
    hub[0, 2] = hub[1, 3] = 1.0  # the ring's and the cage's centres move at their velocities
    for a in range(3):
        hub[RING + a, RING + 3 + a] = 1.0
    w, x, yq, z = y[c0 + 6], y[c0 + 7], y[c0 + 8], y[c0 + 9]
    hub[RING + 6:RING + 10, RING + 10:RING + 13] = 0.5 * np.array(
        [[-x, -yq, -z], [w, -z, yq], [z, w, -x], [-yq, x, w]])


@njit(cache=True)
def _squeeze_gradient(roller, face, body, face_cos, face_sin, geometry, p, work, gradient,
                      ring_rows, velocity_column, rate_column):
    """Add to ``gradient`` (the force on the roller and its moment about its centre, 6 rows)
    the end film's squeeze damping between a roller's end and a flat face (the film's
    pressure ``c`` times the closing speed ``-(v_roller - v_face) . n`` at each element, with
    ``n`` the face's normal), over the roller's velocity and angular velocity and the face
    body's velocity (``velocity_column``) and angular velocity (``rate_column``, negative
    for a body whose rate is fixed); the force's rows to ``ring_rows`` too when given;
    ``work`` is a work array of 1 x 10.
    ``roller``, ``face`` and ``body`` are :func:`models.cage_dynamics_6dof_rhs._end_face`'s,
    whose ``squeeze`` sums give it: the element's force ``c closing n`` and moment
    ``c closing m`` (``m = arm x n``) by ``closing``'s gradient ``(-n, -m, n, r x n)``, with
    ``r`` the element from the body's reference point. Left out, as not stiff: the wedge
    term's part (the sliding's along the roller's lean), the gap's change with a move."""
    _, _, _, _, face_r, _, face_area = geometry
    sums = work[0]
    sums[:] = 0.0
    # with nothing observed, the element records (an empty array, the sums) are not written
    _end_face(roller, face, body, face_r, face_cos, face_sin, face_area, p, work[:0], sums,
              0, 0.0, sums)
    if sums[0] == 0.0:
        return
    centre, sign = roller[0], roller[7]
    normal = _mul(-sign, face[1])
    lever = (sums[1], sums[2], sums[3])
    square = ((sums[4], sums[5], sums[6]), (sums[5], sums[7], sums[8]),
              (sums[6], sums[8], sums[9]))
    offset_normal = _cross(_sub(centre, body[0]), normal)  # r x n = offset x n + m
    for a in range(3):
        for b in range(3):
            by_velocity = sums[0] * normal[a] * normal[b]
            by_rate = normal[a] * lever[b]
            moment_by_velocity = lever[a] * normal[b]
            gradient[a, _V + b] -= by_velocity
            gradient[a, _OMEGA + b] -= by_rate
            gradient[a, velocity_column + b] += by_velocity
            gradient[3 + a, _V + b] -= moment_by_velocity
            gradient[3 + a, _OMEGA + b] -= square[a][b]
            gradient[3 + a, velocity_column + b] += moment_by_velocity
            if rate_column >= 0:
                gradient[a, rate_column + b] += sums[0] * normal[a] * offset_normal[b] \
                    + by_rate
                gradient[3 + a, rate_column + b] += lever[a] * offset_normal[b] \
                    + square[a][b]
            if ring_rows is not None:
                ring_rows[a, _V + b] -= by_velocity
                ring_rows[a, _OMEGA + b] -= by_rate
                ring_rows[a, velocity_column + b] += by_velocity


@njit(cache=True)
def _add_raceways(j, gradient, ring_gradient, axis, inverse, p, own, to_hub, from_hub, hub):
    """:func:`_raceway_gradient`'s into the blocks: the roller's accelerations (``inverse``
    its inertia's inverse) and the ring's, over the roller's state and the ring's x, y and
    their velocities."""
    outputs = np.empty((9, _W + 3))  # the roller's force and moment, the ring's force
    outputs[:6] = gradient
    outputs[6:] = -ring_gradient
    axis_turn = _cross_matrix(axis)  # d theta = a x d a
    by_state = np.empty(9)
    for column in range(ROLLER_SIZE + RING):
        for r in range(9):
            if _THETA <= column < _THETA + 3:
                b = column - _THETA
                by_state[r] = (outputs[r, _THETA] * axis_turn[0, b]
                               + outputs[r, _THETA + 1] * axis_turn[1, b]
                               + outputs[r, _THETA + 2] * axis_turn[2, b])
            elif column < ROLLER_SIZE:
                by_state[r] = outputs[r, column]
            else:
                ring_column = column - ROLLER_SIZE
                by_state[r] = outputs[r, (_S if ring_column < 2 else _W) + ring_column % 2]
        for a in range(3):
            linear = by_state[a] / p[M_ROLLER]
            angular = (inverse[a, 0] * by_state[3] + inverse[a, 1] * by_state[4]
                       + inverse[a, 2] * by_state[5])
            if column < ROLLER_SIZE:
                own[j, 3 + a, column] += linear
                own[j, 9 + a, column] += angular
            else:
                to_hub[j, 3 + a, column - ROLLER_SIZE] += linear
                to_hub[j, 9 + a, column - ROLLER_SIZE] += angular
        for r in range(2):
            if column < ROLLER_SIZE:
                from_hub[j, 2 + r, column] += by_state[6 + r] / p[M_RING]
            else:
                hub[2 + r, column - ROLLER_SIZE] += by_state[6 + r] / p[M_RING]


@njit(cache=True)
def _outputs(gradient, wrench, offset, rows, forces):
    """The force and moment on the roller and on the cage (about its mass centre: ``-F``,
    ``-(M + offset x F)``, ``offset`` the roller's centre from it), and their gradients."""
    for c in range(_COLUMNS + 1):
        column = gradient[:, c] if c < _COLUMNS else wrench
        force = (column[0], column[1], column[2])
        arm = _cross(offset, force)
        values = rows[:, c] if c < _COLUMNS else forces
        for a in range(3):
            values[a], values[3 + a] = column[a], column[3 + a]
            values[6 + a], values[9 + a] = -column[a], -(column[3 + a] + arm[a])


@njit(cache=True)
def _cage_turned(rows, forces, centre, velocity, omega, mass_centre, cage_velocity, turned):
    """The outputs' derivatives over a small turn of the cage about its mass centre
    (``turned``, 12 x 3): the same as turning the roller back, the outputs turning with the
    cage; the cage's Euler equations, in its body frame, see their moment turned back."""
    turned[:, :] = 0.0
    for k in range(3):
        e = (1.0 if k == 0 else 0.0, 1.0 if k == 1 else 0.0, 1.0 if k == 2 else 0.0)
        for block in range(3):  # the roller's force and moment and the cage's force turn
            ex = _cross(e, (forces[3 * block], forces[3 * block + 1], forces[3 * block + 2]))
            for a in range(3):
                turned[3 * block + a, k] += ex[a]
        moved = (_cross(e, _sub(centre, mass_centre)), _cross(e, velocity), e,
                 _cross(e, omega), (0.0, 0.0, 0.0), _cross(e, cage_velocity),
                 (0.0, 0.0, 0.0))
        for block in range(7):
            for r in range(12):
                turned[r, k] -= (rows[r, 3 * block] * moved[block][0]
                                 + rows[r, 3 * block + 1] * moved[block][1]
                                 + rows[r, 3 * block + 2] * moved[block][2])


@njit(cache=True)
def _by_state(rows, turned, axis, turn, to_quaternion, by_state):
    """The outputs' derivatives over the state's entries (``by_state``, 12 x 29): the
    roller's 12 (its axis' components from a small turn, ``d theta = a x d a``), then the
    hub's 17 (the cage's quaternion from a small turn, its body rate from the inertial)."""
    by_state[:, :] = 0.0
    axis_turn = _cross_matrix(axis)
    for r in range(12):
        for b in range(3):
            by_state[r, b] = rows[r, _C + b]
            by_state[r, 3 + b] = rows[r, _V + b]
            by_state[r, 9 + b] = rows[r, _OMEGA + b]
            by_state[r, ROLLER_SIZE + RING + b] = rows[r, _S + b]
            by_state[r, ROLLER_SIZE + RING + 3 + b] = rows[r, _W + b]
            by_axis, by_rate = 0.0, 0.0
            for a in range(3):
                by_axis += rows[r, _THETA + a] * axis_turn[a, b]
                by_rate += rows[r, _CAGE_OMEGA + a] * turn[a, b]
            by_state[r, 6 + b] = by_axis
            by_state[r, ROLLER_SIZE + RING + 10 + b] = by_rate
        for b in range(4):
            by_state[r, ROLLER_SIZE + RING + 6 + b] = (turned[r, 0] * to_quaternion[0, b]
                                                       + turned[r, 1] * to_quaternion[1, b]
                                                       + turned[r, 2] * to_quaternion[2, b])
