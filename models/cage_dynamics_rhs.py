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
from numba import njit

from .contact_laws import traction_coefficient

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
    low, high = 0.0, approach - free  # inner approach: K(s - d)^n - K d^n - F_c = 0
    for _ in range(60):
        middle = 0.5 * (low + high)
        if constant * ((approach - middle) ** EXPONENT - middle ** EXPONENT) > centrifugal:
            low = middle
        else:
            high = middle
        if high - low < 1e-15:
            break
    inner = constant * (0.5 * (low + high)) ** EXPONENT
    return inner, inner + centrifugal


@njit(cache=True)
def derivatives(t, state, p, count):
    out = np.zeros_like(state)
    x, y, vx, vy = state[0], state[1], state[2], state[3]
    cage = 4 + 3 * count
    cx, cy, cvx, cvy, phi, dphi = (state[cage], state[cage + 1], state[cage + 2],
                                   state[cage + 3], state[cage + 4], state[cage + 5])
    ring_fx, ring_fy = 0.0, -p[RADIAL_LOAD] - p[M_RING] * p[GRAVITY]
    cage_fx, cage_fy, cage_torque = 0.0, -p[M_CAGE] * p[GRAVITY], 0.0
    geometric_x = cx - p[ECCENTRICITY] * np.cos(phi)
    geometric_y = cy - p[ECCENTRICITY] * np.sin(phi)
    geometric_vx = cvx + p[ECCENTRICITY] * dphi * np.sin(phi)
    geometric_vy = cvy - p[ECCENTRICITY] * dphi * np.cos(phi)
    for j in range(count):
        k = 4 + 3 * j
        theta, dtheta, spin = state[k], state[k + 1], state[k + 2]
        c, s = np.cos(theta), np.sin(theta)
        approach = x * c + y * s - p[HALF_PLAY]
        centrifugal = p[M_ROLLER] * p[R_PITCH] * dtheta * dtheta
        q_inner, q_outer = roller_loads(approach, centrifugal, p[CONTACT])
        ring_fx -= q_inner * c
        ring_fy -= q_inner * s
        f_inner = traction((p[OMEGA_I] - dtheta) * p[R_INNER] - spin * p[R_ROLLER], p) * q_inner
        f_outer = traction(spin * p[R_ROLLER] - dtheta * p[R_OUTER], p) * q_outer
        # Pocket j: a circle of radius R + c_p/2 around its centre on the cage.
        angle = phi + 2.0 * np.pi * j / count
        pocket_x = geometric_x + p[R_PITCH] * np.cos(angle)
        pocket_y = geometric_y + p[R_PITCH] * np.sin(angle)
        dx, dy = p[R_PITCH] * c - pocket_x, p[R_PITCH] * s - pocket_y
        distance = np.sqrt(dx * dx + dy * dy)
        push_x = push_y = pocket_force = 0.0
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
                cage_fx -= push_x
                cage_fy -= push_y
                cage_torque -= (pocket_x - cx) * push_y - (pocket_y - cy) * push_x
        tangential = -push_x * s + push_y * c
        drag = p[WINDAGE] * dtheta * abs(dtheta)
        out[k] = dtheta
        out[k + 1] = (f_inner + f_outer - drag + tangential) / (p[M_ROLLER] * p[R_PITCH])
        # The pocket's film and friction couple on the roller, in its spin's sense; the cage
        # receives the same number counted with the orbit, the opposite sense: the reaction
        # (see models.cage_slip._CageBalance.orbit for the friction force's lever).
        pocket_couple = -p[POCKET_FILM] * spin \
            - p[MU_POCKET] * pocket_force * p[R_ROLLER] * np.sign(spin)
        cage_torque += pocket_couple
        out[k + 2] = (p[R_ROLLER] * (f_inner - f_outer) + pocket_couple
                      - p[END_FILM] * spin) / p[J_ROLLER]
    out[0], out[1] = vx, vy
    out[2] = (ring_fx - p[C_RING] * vx) / p[M_RING]
    out[3] = (ring_fy - p[C_RING] * vy) / p[M_RING]
    out[cage], out[cage + 1] = cvx, cvy
    out[cage + 2], out[cage + 3] = cage_fx / p[M_CAGE], cage_fy / p[M_CAGE]
    out[cage + 4] = dphi
    out[cage + 5] = (cage_torque - p[CAGE_DRAG] * dphi * np.sqrt(abs(dphi))) / p[J_CAGE]
    return out


@njit(cache=True)
def jacobian(t, state, p, count, scale):
    """Forward-difference Jacobian of :func:`derivatives`, compiled: the stiff solver needs
    it often, and one compiled call costs less than the solver's own difference loop."""
    size = state.size
    base = derivatives(t, state, p, count)
    matrix = np.empty((size, size))
    shifted = state.copy()
    for i in range(size):
        step = 1.5e-8 * max(abs(state[i]), scale[i])
        shifted[i] = state[i] + step
        column = derivatives(t, shifted, p, count)
        for row in range(size):  # element by element: array arithmetic compiles slower
            matrix[row, i] = (column[row] - base[row]) / step
        shifted[i] = state[i]
    return matrix
