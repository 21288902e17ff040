"""A roller's spin around its orbit at a trial cage speed, compiled: the inner loop of
:meth:`models.cage_slip._CageBalance.orbit`, which the steady model runs for every trial
cage speed of every point (and the transient models at their start). Imported only when a
cage slip is solved (numba costs half a second to import)."""
from __future__ import annotations

import math

import numpy as np

from .compiled_cache import njit


@njit(cache=True, error_model="numpy")
def _traction(sliding, a, b, c, d):
    """Gupta's traction coefficient ``mu(u) = (A + B u) exp(-C u) + D``, odd in ``u``, and
    its slope ``dmu/du`` (:class:`models.lubrication.TractionCurve`'s law)."""
    speed = abs(sliding)
    decay = math.exp(-c * speed)
    value = (a + b * speed) * decay + d
    slope = decay * (b - c * (a + b * speed))
    return (value if sliding > 0.0 else (-value if sliding < 0.0 else 0.0)), slope


@njit(cache=True, error_model="numpy")
def orbit_spins(inner_load, outer_load, omega_c, omega_i, inertia, pocket_friction,
                pocket_film, end_film, roller_radius, inner_radius, outer_radius, windage,
                curve, orbits, history, pushing, pocket):
    """Each point's roller spin over ``orbits`` orbits at the cage speed ``omega_c``, step
    by step around the orbit's positions: the linearly implicit Euler steps of
    :meth:`models.cage_slip._CageBalance.orbit` (its arguments per point, ``curve`` the
    traction curve's ``A..D`` ``(n, 4)``). Fills ``history`` (the spin), ``pushing`` (the
    forward push on the cage) and ``pocket`` (the pocket's couple on the roller) of the last
    orbit, ``(n, steps)`` each."""
    steps = inner_load.shape[1]
    for n in range(inner_load.shape[0]):
        a, b, c, d = curve[n, 0], curve[n, 1], curve[n, 2], curve[n, 3]
        rr, ri, ro = roller_radius[n], inner_radius[n], outer_radius[n]
        drag = windage[n] * omega_c[n] ** 2
        h = 2.0 * np.pi / steps / omega_c[n] / inertia[n]
        spin = omega_c[n] * ro / rr  # pure rolling at the outer raceway to start
        for step in range(orbits * steps):
            k = step % steps
            q_i, q_o = inner_load[n, k], outer_load[n, k]
            mu_i, slope_i = _traction((omega_i[n] - omega_c[n]) * ri - spin * rr, a, b, c, d)
            mu_o, slope_o = _traction(spin * rr - omega_c[n] * ro, a, b, c, d)
            forward = mu_i * q_i + mu_o * q_o - drag
            # The couple of the pocket's film and friction on the roller, in its spin's sense.
            couple = -pocket_film[n] * spin \
                - pocket_friction[n] * abs(forward) * rr * np.sign(spin)
            torque = rr * (mu_i * q_i - mu_o * q_o) + couple - end_film[n] * spin
            stiffness = rr * rr * (slope_i * q_i + slope_o * q_o) + pocket_film[n] \
                + end_film[n]
            spin = spin + h * torque / (1.0 + h * stiffness)
            history[n, k], pushing[n, k], pocket[n, k] = spin, forward, couple
