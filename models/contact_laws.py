"""Contact laws of the transient roller-bearing models, compiled: one function per law, shared
by the planar (:mod:`models.cage_dynamics_rhs`) and the spatial
(:mod:`models.cage_dynamics_6dof_rhs`) right-hand sides, which call them millions of times.
"""
from __future__ import annotations

import numpy as np

from .compiled_cache import njit

PALMGREN_EXPONENT = 10.0 / 9.0


@njit(cache=True)
def traction_coefficient(sliding, a, b, c, d):
    """Gupta's traction curve ``mu(u) = (A + B u) exp(-C u) + D``, odd in the sliding speed
    ``u`` [m/s] (:class:`models.lubrication.TractionCurve` derives ``A..D``).

    References
    ----------
    .. [1] P. K. Gupta, Advanced Dynamics of Rolling Elements, Springer (1984), ch. 3.
    """
    speed = abs(sliding)
    value = (a + b * speed) * np.exp(-c * speed) + d
    return value if sliding >= 0.0 else -value


@njit(cache=True)
def traction_slope(sliding, a, b, c, d):
    """The slope ``d mu / d u`` [s/m] of :func:`traction_coefficient` at the sliding speed
    ``u`` [m/s], even in ``u``."""
    speed = abs(sliding)
    return (b - c * (a + b * speed)) * np.exp(-c * speed)


def qin_damping_coefficient(restitution, impact_speed):
    """Qin's hysteresis damping coefficient ``C_n = 3 (1 - e^2) exp(2 (1 - e)) / (4 v-)``
    [s/m] of a contact force ``N = k delta (1 + C_n delta')`` (paper 002, eq. 1).

    Parameters
    ----------
    restitution : array_like
        Coefficient of restitution ``e`` [-].
    impact_speed : array_like
        Approach speed at the start of the impact ``v-`` [m/s].

    References
    ----------
    .. [1] Z. Qin, Q. Lu, Analysis of impact process model based on restitution coefficient,
       J. Dynamics and Control 4 (2006) 294-298 (in Chinese), as used in paper 002.
    .. [2] K. H. Hunt, F. R. E. Crossley, Coefficient of restitution interpreted as damping in
       vibroimpact, J. Appl. Mech. 42 (1975) 440-445.
    """
    e = np.asarray(restitution, dtype=float)
    return 3.0 * (1.0 - e**2) * np.exp(2.0 * (1.0 - e)) / (4.0 * np.asarray(impact_speed))


def winkler_modulus(youngs_modulus, poisson_ratio, depth):
    """Pressure per unit approach of an elastic layer of depth ``H`` on a rigid base
    ``(1 - nu) E / ((1 + nu)(1 - 2 nu) H)`` [Pa/m] (paper 002, eq. 1, per unit area).

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section 5.9
       (the elastic foundation of a thin layer, laterally constrained).
    """
    nu = np.asarray(poisson_ratio, dtype=float)
    return (1.0 - nu) * np.asarray(youngs_modulus) / ((1.0 + nu) * (1.0 - 2.0 * nu)
                                                      * np.asarray(depth))


@njit(cache=True)
def damped_spring(stiffness, approach, approach_rate, damping):
    """Normal force of a spring ``k delta (1 + C_n delta')`` that only pushes [N]: a Winkler
    element (paper 002, eq. 1, ``k = modulus x area``) or a roller slice (``k delta`` from
    :func:`palmgren_slice` as ``stiffness x approach``)."""
    if approach <= 0.0:
        return 0.0
    force = stiffness * approach * (1.0 + damping * approach_rate)
    return force if force > 0.0 else 0.0


@njit(cache=True)
def palmgren_slice(constant, approach):
    """Load of a line-contact slice ``K delta^(10/9)`` [N] (Palmgren; ``K`` of the slice's
    length from :func:`models.contact.palmgren_constant`)."""
    if approach <= 0.0:
        return 0.0
    return constant * approach ** PALMGREN_EXPONENT


@njit(cache=True)
def regularised_direction(speed, smoothing):
    """Share of the full Coulomb force at sliding ``speed`` [m/s]: ``speed / max(speed, v_s)``,
    so that friction is continuous through zero sliding (a linear ramp below ``v_s``)."""
    return 1.0 if speed >= smoothing else speed / smoothing


@njit(cache=True)
def short_bearing_pressure(viscosity, surface_speed_gradient, squeeze, film, axial, length):
    """Film pressure of a short journal bearing (Ocvirk), cavitated below ambient (Guembel)
    [Pa].

    ``p = (6 eta omega dh/dtheta + 12 eta dh/dt) (z^2 - L^2/4) / (2 h^3)``, from Reynolds'
    equation without circumferential pressure flow, ``p = 0`` at the ends ``z = +-L/2``.

    Parameters
    ----------
    viscosity : float
        ``eta`` [Pa s].
    surface_speed_gradient : float
        ``omega dh/dtheta`` [m/s]: the journal's speed relative to the bearing times the film's
        slope along the circumference.
    squeeze : float
        ``dh/dt`` [m/s].
    film, axial, length : float
        Film ``h`` [m], axial position ``z`` [m] from the middle, length ``L`` [m].

    References
    ----------
    .. [1] F. W. Ocvirk, Short-bearing approximation for full journal bearings, NACA TN 2808
       (1952).
    .. [2] D. Childs, Turbomachinery Rotordynamics, Wiley (1993), ch. 3 (short-bearing forces
       with squeeze, Guembel's half film).
    """
    pressure = (6.0 * viscosity * surface_speed_gradient + 12.0 * viscosity * squeeze) \
        * (axial * axial - 0.25 * length * length) / (2.0 * film * film * film)
    return pressure if pressure > 0.0 else 0.0
