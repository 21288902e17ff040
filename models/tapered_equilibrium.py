"""The inner ring's equilibrium of :func:`models.tapered.trb_load`, one point at a time, compiled.

Across a block of points in numpy, each damped Newton iteration made a dozen array calls over
``(points, rollers)`` temporaries, half of them einsums: their overhead and the powers of every
roller of every point, converged or not, dominated. Point by point an iteration is a loop over
one row of rollers, and a point stops iterating when it has converged.

The equations are those of :func:`models.tapered.trb_load` (paper 003 eq. 13-18): roller ``i``
is compressed by ``delta_r cos(alpha) cos(psi_i) + delta_a sin(alpha)`` and carries
``Q_i = K delta_i^1.11``. The iteration is Newton's method damped in the manner of Levenberg and
Marquardt, as :func:`models.ball_equilibrium.equilibria`'s: a step ``(K + mu I)^-1 (F - R)`` is
taken where it does not raise the residual ``|F - R|``, and ``mu`` shrinks fivefold then;
where it does, the step is refused and ``mu`` grows fivefold. Each point's rollers are summed in
their order, compiled with numpy's error model and without ``fastmath``
(:mod:`models.kernels`), and :func:`models.tapered.trb_load` runs this same source interpreted
for a process's first points, with the same numbers to the bit.
"""
from __future__ import annotations

import numpy as np

from .kernels import compiler
from .tapered import LOAD_EXPONENT as EXPONENT

njit = compiler(globals())  # numba's, or none where this source runs interpreted


@njit(cache=True, error_model="numpy", inline="always")
def _sums(radial, axial, along, across, constant):
    """The rollers' force on the ring (radial, axial) and its stiffness (rr, ra, aa) at the
    displacement ``(radial, axial)``; roller ``i``'s compression is ``radial along[i] + axial
    across``."""
    force_r = force_a = k_rr = k_ra = k_aa = 0.0 * constant
    for roller in range(along.size):
        compression = along[roller] * radial + across * axial
        if compression > 0.0:
            power = compression ** (EXPONENT - 1.0)
            load = constant * compression * power
            slope = EXPONENT * constant * power
            force_r += load * along[roller]
            force_a += load * across
            k_rr += slope * along[roller] * along[roller]
            k_ra += slope * along[roller] * across
            k_aa += slope * across * across
        elif not compression <= 0.0:  # NaN: stays
            force_r += compression
            force_a += compression
            k_rr += compression
            k_ra += compression
            k_aa += compression
    return force_r, force_a, k_rr, k_ra, k_aa


@njit(cache=True, error_model="numpy", nogil=True)  # a threaded worker runs blocks side by side
def equilibria(radial, axial, start_radial, start_axial, damping, tolerance, cos_angle,
               sin_angle, constant, cos_azimuth, max_iterations):
    """Each point's displacements where the rollers balance ``(radial, axial)``, and every
    roller's compression and load there.

    Parameters
    ----------
    radial, axial : numpy.ndarray
        ``(N,)`` loads ``F_r``, ``F_a`` [N].
    start_radial, start_axial : numpy.ndarray
        ``(N,)`` first displacements [m].
    damping : numpy.ndarray
        ``(N,)`` first damping ``mu`` [N/m].
    tolerance : numpy.ndarray
        ``(N,)`` residual norm at which a point is done [N].
    cos_angle, sin_angle, constant : numpy.ndarray
        ``(N,)`` cosine and sine of the cup's contact angle, ``K_ne`` [N/m^1.11].
    cos_azimuth : numpy.ndarray
        ``(Z,)`` cosines of the roller azimuths.
    max_iterations : int

    Returns
    -------
    displacement : numpy.ndarray
        ``(N, 2)`` ``delta_r``, ``delta_a`` [m].
    converged : numpy.ndarray of bool
        Residual norm within ``tolerance``.
    compression : numpy.ndarray
        ``(N, Z)`` each roller's compression there [m] (negative: a gap).
    roller_load : numpy.ndarray
        ``(N, Z)`` [N].
    """
    count, rollers = radial.size, cos_azimuth.size
    displacement = np.empty((count, 2))
    converged = np.zeros(count, dtype=np.bool_)
    compression = np.empty((count, rollers))
    roller_load = np.empty((count, rollers))
    along = np.empty(rollers)
    for point in range(count):
        for roller in range(rollers):
            along[roller] = cos_angle[point] * cos_azimuth[roller]
        across, scale = sin_angle[point], constant[point]
        x_r, x_a = start_radial[point], start_axial[point]
        force_r, force_a, k_rr, k_ra, k_aa = _sums(x_r, x_a, along, across, scale)
        r_r, r_a = radial[point] - force_r, axial[point] - force_a
        norm = np.sqrt(r_r * r_r + r_a * r_a)
        mu = damping[point]
        for _ in range(max_iterations):
            if not norm > tolerance[point]:
                break
            # (K + mu I) step = residual, by elimination with partial pivoting.
            a, b, c = k_rr + mu, k_ra, k_aa + mu
            if abs(b) > abs(a):  # the second row pivots
                factor = a / b
                step_a = (r_r - factor * r_a) / (b - factor * c)
                step_r = (r_a - c * step_a) / b
            else:
                factor = b / a
                step_a = (r_a - factor * r_r) / (c - factor * b)
                step_r = (r_r - b * step_a) / a
            t_r, t_a = x_r + step_r, x_a + step_a
            force_r, force_a, t_rr, t_ra, t_aa = _sums(t_r, t_a, along, across, scale)
            s_r, s_a = radial[point] - force_r, axial[point] - force_a
            trial_norm = np.sqrt(s_r * s_r + s_a * s_a)
            if trial_norm <= norm:
                x_r, x_a, r_r, r_a, norm = t_r, t_a, s_r, s_a, trial_norm
                k_rr, k_ra, k_aa = t_rr, t_ra, t_aa
                mu *= 0.2
            else:
                mu *= 5.0
        converged[point] = norm <= tolerance[point]
        displacement[point, 0], displacement[point, 1] = x_r, x_a
        for roller in range(rollers):
            compressed = along[roller] * x_r + across * x_a
            compression[point, roller] = compressed
            loaded = 0.0 if compressed <= 0.0 else compressed  # NaN stays
            roller_load[point, roller] = scale * loaded ** EXPONENT
    return displacement, converged, compression, roller_load
