"""Right-hand side of the planar transient model of a cylindrical roller bearing with a
roller-guided cage (compiled: it is called hundreds of thousands of times per run).

State: inner ring x, y, vx, vy; per roller orbit angle, orbit speed, spin; cage mass centre
x, y, vx, vy, angle, angular speed. Rollers' radial positions are quasi-static: at each call a
roller's inner and outer contact loads follow from the ring's position and its centrifugal
force (Palmgren line contacts in series). Parameters are packed in one array (indices below).

Angles and the cage's torque count positive with the orbit (counter-clockwise); a roller's
spin counts positive opposite to it (rolling on the fixed outer ring), as in
:mod:`models.cage_slip`. The pocket's film and friction couple a roller's spin to the cage, and
the cage receives their reaction; the end films act against the rings' ribs.
"""
from __future__ import annotations

import numpy as np

from .compiled_cache import njit
from .contact_laws import traction_coefficient
from .dormand_prince import FIRST_STEP, SMALLEST_STEP, conclude, stage_argument

(OMEGA_I, RADIAL_LOAD, R_INNER, R_OUTER, R_ROLLER, R_PITCH, CONTACT, HALF_PLAY, M_ROLLER,
 J_ROLLER, POCKET_FILM, END_FILM, WINDAGE, MU_POCKET, M_RING, C_RING, M_CAGE, J_CAGE,
 ECCENTRICITY, HALF_POCKET, K_POCKET, C_POCKET, GRAVITY, CAGE_DRAG, TRACTION_A, TRACTION_B,
 TRACTION_C, TRACTION_D) = range(28)
PARAMETERS = 28
EXPONENT = 10.0 / 9.0


@njit(cache=True)
def traction(sliding, p):
    """Gupta's traction coefficient with the curve packed in ``p``."""
    return traction_coefficient(sliding, p[TRACTION_A], p[TRACTION_B], p[TRACTION_C],
                                p[TRACTION_D])


@njit(cache=True)
def roller_loads(approach, centrifugal, constant):
    """Inner and outer contact loads of a roller whose contacts share ``approach`` [m]."""
    free = (centrifugal / constant) ** (1.0 / EXPONENT)  # outer approach from F_c alone
    if approach <= free:
        return 0.0, centrifugal
    # Inner approach d: K((s - d)^n - d^n) - F_c = 0, falling in d, by Newton's steps kept
    # in the bracket (bisection where one leaves it); at rest d = s / 2.
    low, high = 0.0, approach - free
    inner = min(0.5 * approach, 0.5 * (low + high))
    for _ in range(60):
        outer = approach - inner
        outer_root, inner_root = outer ** (EXPONENT - 1.0), inner ** (EXPONENT - 1.0)
        residual = constant * (outer * outer_root - inner * inner_root) - centrifugal
        if residual > 0.0:
            low = inner
        else:
            high = inner
        slope = -constant * EXPONENT * (outer_root + inner_root)
        step = inner - residual / slope
        if not (low < step < high):
            step = 0.5 * (low + high)
        if abs(step - inner) < 1e-15 or residual == 0.0:
            inner = step
            break
        inner = step
    return constant * inner ** EXPONENT, constant * inner ** EXPONENT + centrifugal


@njit(cache=True)
def contact_loads(x, y, cos_orbit, sin_orbit, orbit_speed, p):
    """Inner and outer contact loads [N] of a roller at the orbit angle whose cosine and
    sine are given, with the ring's centre at ``(x, y)``: its contacts' shared approach and
    its centrifugal force (:func:`roller_loads`)."""
    approach = x * cos_orbit + y * sin_orbit - p[HALF_PLAY]
    centrifugal = p[M_ROLLER] * p[R_PITCH] * orbit_speed * orbit_speed
    return roller_loads(approach, centrifugal, p[CONTACT])


@njit(cache=True)
def largest_contact_loads(states, p, count):
    """The largest inner and outer contact load [N] of any roller over ``states`` (one per
    row)."""
    largest = np.zeros(2)
    for state in states:
        for j in range(count):
            theta, dtheta = state[4 + 3 * j], state[5 + 3 * j]
            q_inner, q_outer = contact_loads(state[0], state[1], np.cos(theta), np.sin(theta),
                                             dtheta, p)
            largest[0] = max(largest[0], q_inner)
            largest[1] = max(largest[1], q_outer)
    return largest


@njit(cache=True)
def roller_terms(state, j, p, count, geometric, rates):
    """Roller ``j``'s own rates (its orbit angle, orbit speed and spin, into ``rates``) and
    what it puts on the ring and the cage: the inner contact's load components, the pocket's
    push on the roller and the cage's torques from it (the push's lever and the pocket's
    film and friction couple). ``geometric``: the cage's geometric centre and its velocity."""
    k = 4 + 3 * j
    x, y = state[0], state[1]
    cage = 4 + 3 * count
    cx, cy, phi, dphi = state[cage], state[cage + 1], state[cage + 4], state[cage + 5]
    geometric_x, geometric_y, geometric_vx, geometric_vy = (geometric[0], geometric[1],
                                                            geometric[2], geometric[3])
    theta, dtheta, spin = state[k], state[k + 1], state[k + 2]
    c, s = np.cos(theta), np.sin(theta)
    q_inner, q_outer = contact_loads(x, y, c, s, dtheta, p)
    f_inner = traction((p[OMEGA_I] - dtheta) * p[R_INNER] - spin * p[R_ROLLER], p) * q_inner
    f_outer = traction(spin * p[R_ROLLER] - dtheta * p[R_OUTER], p) * q_outer
    # Pocket j: a circle of radius R + c_p/2 around its centre on the cage.
    angle = phi + 2.0 * np.pi * j / count
    pocket_x = geometric_x + p[R_PITCH] * np.cos(angle)
    pocket_y = geometric_y + p[R_PITCH] * np.sin(angle)
    dx, dy = p[R_PITCH] * c - pocket_x, p[R_PITCH] * s - pocket_y
    distance = np.sqrt(dx * dx + dy * dy)
    push_x = push_y = pocket_force = lever = 0.0
    if distance > p[HALF_POCKET]:
        nx, ny = dx / distance, dy / distance
        roller_vx, roller_vy = -p[R_PITCH] * dtheta * s, p[R_PITCH] * dtheta * c
        pocket_vx = geometric_vx - p[R_PITCH] * dphi * np.sin(angle)
        pocket_vy = geometric_vy + p[R_PITCH] * dphi * np.cos(angle)
        closing = (roller_vx - pocket_vx) * nx + (roller_vy - pocket_vy) * ny
        normal = p[K_POCKET] * (distance - p[HALF_POCKET]) + p[C_POCKET] * closing
        if normal > 0.0:
            pocket_force = normal
            push_x, push_y = -normal * nx, -normal * ny  # on the roller
            lever = (pocket_x - cx) * push_y - (pocket_y - cy) * push_x
    tangential = -push_x * s + push_y * c
    drag = p[WINDAGE] * dtheta * abs(dtheta)
    rates[0] = dtheta
    rates[1] = (f_inner + f_outer - drag + tangential) / (p[M_ROLLER] * p[R_PITCH])
    # The pocket's film and friction couple on the roller, in its spin's sense; the cage
    # receives the same number counted with the orbit, the opposite sense: the reaction
    # (see models.cage_slip._CageBalance.orbit for the friction force's lever).
    pocket_couple = -p[POCKET_FILM] * spin \
        - p[MU_POCKET] * pocket_force * p[R_ROLLER] * np.sign(spin)
    rates[2] = (p[R_ROLLER] * (f_inner - f_outer) + pocket_couple
                - p[END_FILM] * spin) / p[J_ROLLER]
    return q_inner * c, q_inner * s, push_x, push_y, lever, pocket_couple


@njit(cache=True)
def _geometric(state, p, count):
    """The cage's geometric centre and its velocity, from its mass centre's state."""
    cage = 4 + 3 * count
    cvx, cvy, phi, dphi = state[cage + 2], state[cage + 3], state[cage + 4], state[cage + 5]
    geometric = np.empty(4)
    geometric[0] = state[cage] - p[ECCENTRICITY] * np.cos(phi)
    geometric[1] = state[cage + 1] - p[ECCENTRICITY] * np.sin(phi)
    geometric[2] = cvx + p[ECCENTRICITY] * dphi * np.sin(phi)
    geometric[3] = cvy - p[ECCENTRICITY] * dphi * np.cos(phi)
    return geometric


@njit(cache=True)
def derivatives(t, state, p, count):
    out = np.zeros_like(state)
    vx, vy = state[2], state[3]
    cage = 4 + 3 * count
    cvx, cvy, dphi = state[cage + 2], state[cage + 3], state[cage + 5]
    ring_fx, ring_fy = 0.0, -p[RADIAL_LOAD] - p[M_RING] * p[GRAVITY]
    cage_fx, cage_fy, cage_torque = 0.0, -p[M_CAGE] * p[GRAVITY], 0.0
    geometric = _geometric(state, p, count)
    rates = np.empty(3)
    for j in range(count):
        load_x, load_y, push_x, push_y, lever, couple = roller_terms(state, j, p, count,
                                                                     geometric, rates)
        ring_fx -= load_x
        ring_fy -= load_y
        cage_fx -= push_x
        cage_fy -= push_y
        cage_torque -= lever
        cage_torque += couple
        k = 4 + 3 * j
        out[k], out[k + 1], out[k + 2] = rates[0], rates[1], rates[2]
    out[0], out[1] = vx, vy
    out[2] = (ring_fx - p[C_RING] * vx) / p[M_RING]
    out[3] = (ring_fy - p[C_RING] * vy) / p[M_RING]
    out[cage], out[cage + 1] = cvx, cvy
    out[cage + 2], out[cage + 3] = cage_fx / p[M_CAGE], cage_fy / p[M_CAGE]
    out[cage + 4] = dphi
    out[cage + 5] = (cage_torque - p[CAGE_DRAG] * dphi * np.sqrt(abs(dphi))) / p[J_CAGE]
    return out


@njit(cache=True)
def integrate(state, times, p, count, rtol, atol, max_steps):
    """Dormand-Prince 5(4) with a PI step-size controller (:mod:`models.dormand_prince`),
    each sample time hit by a step. Returns the samples ``(times, state)`` and whether the
    integration reached the end within ``max_steps`` steps."""
    samples = np.full((times.size, state.size), np.nan)
    y = state.copy()
    stages = np.empty((7, y.size))
    stages[0] = derivatives(times[0], y, p, count)
    t, h, steps, last_norm = times[0], FIRST_STEP, 0, 1e-4
    samples[0] = y
    for index in range(1, times.size):
        while t < times[index]:
            if steps >= max_steps or h < SMALLEST_STEP:
                return samples, False
            step = min(h, times[index] - t)
            for s in range(1, 7):
                trial = stage_argument(y, stages, s, step)
                stages[s] = derivatives(t, trial, p, count)
            steps += 1
            accepted, h, last_norm, t = conclude(y, trial, stages, step, rtol, atol, last_norm,
                                                 t, times[index])
            if accepted:
                y = trial
                stages[0] = stages[6]
        samples[index] = y
    return samples, True
