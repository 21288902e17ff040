"""The inner ring's equilibrium of :func:`models.ball.ball_5dof`, one point at a time, compiled.

Across a block of points in numpy, each damped Newton iteration made some forty array calls,
each a pass over ``(points, balls)`` temporaries: the calls' overhead dominated small blocks,
memory traffic large ones. Point by point a step is a few hundred floating-point operations on
arrays of one row of balls, and a point stops iterating when it has converged.

The equations are those of :mod:`models.ball` (module docstring, :func:`ball_contacts`,
:func:`ring_sums`); the iteration is Newton's method damped in the manner of Levenberg and
Marquardt: a step ``(K + mu I)^-1 (F - R)`` is taken where it does not raise the residual
``|F - R|``, and ``mu`` shrinks fivefold then, so that the iteration ends as Newton's; where it
does, the step is refused and ``mu`` grows fivefold. A step that leaves the residual unchanged
is taken: it may cross a clearance, where nothing resists. Each point's balls are summed in
their order and compiled without ``fastmath`` (no reassociation), so a point's numbers depend
neither on the other points of the call nor on the machine's vector width; and with numpy's
error model, so that a division by zero gives an infinity or NaN as the vectorised model did
(that point then does not converge) rather than an exception for the whole block.

Per-point data come as the rows of one ``rings`` array, columns ``DISTANCE..CONSTANT``; the
ball azimuths as ``psi``, rows ``1, cos, sin, cos cos, sin sin, cos sin`` of ``(6, Z)``.

:func:`models.ball._kernels` also runs this same source without numba (:mod:`models.kernels`):
IEEE operations in the same order give the same numbers (a test holds them bitwise equal), in
about 1.6 ms a point against numba's 0.5 s to import and load its cached
code, which a sweep of a few hundred points need not pay.
"""
from __future__ import annotations

import math

import numpy as np

from .contact import POINT_CONTACT_EXPONENT as EXPONENT
from .kernels import compiler

njit = compiler(globals())  # numba's, or none where this source runs interpreted

#: Columns of ``rings``: groove-centre distance ``A`` [m], sine and cosine of the unloaded
#: contact angle, the unloaded centre separation along the axis and the radius [m], the
#: fixed-angle geometry's approach offset [m], the contact constant ``K`` [N/m^1.5].
DISTANCE, SIN0, COS0, AXIAL0, RADIAL0, OFFSET0, CONSTANT = range(7)
COLUMNS = 7
DOFS = 5
JACOBI_SWEEPS = 30  # a 5 x 5 matrix needs five or six


def azimuth_functions(ball_count):
    """``psi``: the functions of the ball azimuths the sums take, ``(6, Z)``."""
    azimuth = 2.0 * np.pi * np.arange(ball_count) / ball_count
    cos, sin = np.cos(azimuth), np.sin(azimuth)
    return np.stack([np.ones(ball_count), cos, sin, cos * cos, sin * sin, cos * sin])


@njit(cache=True, error_model="numpy", inline="always")
def _ball(scaled, ring, jones, cos, sin):
    """One ball's approach, load, load slope, unit normal (axial and radial parts) and centre
    distance (NaN in the fixed-angle geometry) at the scaled displacement ``scaled``.

    A ball of azimuth ``psi`` sees the ring's axial shift ``q_0 + q_3 sin psi - q_4 cos psi``
    and radial shift ``q_1 cos psi + q_2 sin psi``. Jones: its groove centres are then
    ``s = (A sin a0 + axial, A cos a0 - P_d/2 + radial)`` apart, the approach is
    ``|s| - A`` and the normal ``s / |s|``; fixed angle: the approach is the shift projected
    on the unloaded normal, less ``(P_d / 2) cos a0``. ``Q = K delta^1.5``.
    """
    axial_shift = scaled[0] + scaled[3] * sin - scaled[4] * cos
    radial_shift = scaled[1] * cos + scaled[2] * sin
    if jones:
        separation_axial = ring[AXIAL0] + axial_shift
        separation_radial = ring[RADIAL0] + radial_shift
        # np.sqrt: a float64 either way, so a zero length divides as numpy does, interpreted.
        length = np.sqrt(separation_axial * separation_axial
                         + separation_radial * separation_radial)
        reciprocal = 1.0 / length
        normal_axial = separation_axial * reciprocal
        normal_radial = separation_radial * reciprocal
        approach = length - ring[DISTANCE]
    else:
        normal_axial, normal_radial, length = ring[SIN0], ring[COS0], np.nan
        approach = axial_shift * ring[SIN0] + radial_shift * ring[COS0] - ring[OFFSET0]
    # An unloaded ball carries nothing; a NaN approach stays NaN.
    root = math.sqrt(approach) if approach > 0.0 else (0.0 if approach <= 0.0 else approach)
    load = ring[CONSTANT] * (root * root * root)
    return approach, load, EXPONENT * ring[CONSTANT] * root, normal_axial, normal_radial, length


@njit(cache=True, error_model="numpy")
def ball_contacts(scaled, ring, jones, psi, approach, load, slope, normal_axial, normal_radial,
                  length):
    """:func:`_ball` of every ball, written into the ``(Z,)`` arrays given."""
    for ball in range(psi.shape[1]):
        (approach[ball], load[ball], slope[ball], normal_axial[ball], normal_radial[ball],
         length[ball]) = _ball(scaled, ring, jones, psi[1, ball], psi[2, ball])


@njit(cache=True, error_model="numpy")
def preloaded_contacts(typical, ring, approach, load, slope, normal_axial, normal_radial,
                       length):
    """:func:`ball_contacts` of a preloaded bearing whose balls are all compressed by
    ``typical`` [m] at their unloaded contact angles."""
    root = math.sqrt(typical)
    approach[:] = typical
    load[:] = ring[CONSTANT] * (root * root * root)
    slope[:] = EXPONENT * ring[CONSTANT] * root
    normal_axial[:] = ring[SIN0]
    normal_radial[:] = ring[COS0]
    length[:] = ring[DISTANCE] + typical


@njit(cache=True, error_model="numpy")
def ring_sums(load, slope, normal_axial, normal_radial, length, jones, psi, reaction,
              stiffness):
    """The balls' scaled reaction on the ring (paper 001 eq. 6-7) and its tangent stiffness
    (eq. 9) from their contacts (:func:`ball_contacts`), written into ``reaction`` ``(5,)``
    and ``stiffness`` ``(5, 5)``.

    A ball with an axial force ``f_a`` and a radial force ``f_r`` puts ``f_a A + f_r R`` on the
    five scaled loads, ``A = (1, 0, 0, sin psi, -cos psi)``, ``R = (0, cos psi, sin psi, 0,
    0)``; its stiffness is ``k_aa A A^T + k_rr R R^T + k_ar (A R^T + R A^T)``. Its force
    ``Q(s) s/|s|`` on the centre separation ``s`` has the derivative
    ``Q' n n^T + (Q/|s|)(I - n n^T)``: the second term, the turning of the line of action,
    is what the fixed-angle geometry leaves out. So each load and each stiffness entry is a
    sum over the balls of a force or a ``k`` times one of the functions of ``psi``.
    """
    axial = axial_sin = axial_cos = radial_cos = radial_sin = 0.0
    aa = aa_sin = aa_cos = aa_sin_sin = aa_cos_sin = aa_cos_cos = 0.0
    rr_cos_cos = rr_cos_sin = rr_sin_sin = 0.0
    ar_cos = ar_sin = ar_cos_sin = ar_sin_sin = ar_cos_cos = 0.0
    for ball in range(psi.shape[1]):
        cos, sin = psi[1, ball], psi[2, ball]
        cos_cos, sin_sin, cos_sin = psi[3, ball], psi[4, ball], psi[5, ball]
        along, across = normal_axial[ball], normal_radial[ball]
        axial_force, radial_force = load[ball] * along, load[ball] * across
        axial_axial = slope[ball] * (along * along)
        radial_radial = slope[ball] * (across * across)
        mixed = slope[ball] * along * across
        if jones:
            turning = load[ball] / length[ball]
            axial_axial += turning * (across * across)
            radial_radial += turning * (along * along)
            mixed -= turning * along * across
        axial += axial_force
        axial_sin += axial_force * sin
        axial_cos += axial_force * cos
        radial_cos += radial_force * cos
        radial_sin += radial_force * sin
        aa += axial_axial
        aa_sin += axial_axial * sin
        aa_cos += axial_axial * cos
        aa_sin_sin += axial_axial * sin_sin
        aa_cos_sin += axial_axial * cos_sin
        aa_cos_cos += axial_axial * cos_cos
        rr_cos_cos += radial_radial * cos_cos
        rr_cos_sin += radial_radial * cos_sin
        rr_sin_sin += radial_radial * sin_sin
        ar_cos += mixed * cos
        ar_sin += mixed * sin
        ar_cos_sin += mixed * cos_sin
        ar_sin_sin += mixed * sin_sin
        ar_cos_cos += mixed * cos_cos
    reaction[0], reaction[1], reaction[2] = axial, radial_cos, radial_sin
    reaction[3], reaction[4] = axial_sin, -axial_cos
    stiffness[0, 0], stiffness[0, 3], stiffness[0, 4] = aa, aa_sin, -aa_cos
    stiffness[3, 3], stiffness[3, 4], stiffness[4, 4] = aa_sin_sin, -aa_cos_sin, aa_cos_cos
    stiffness[1, 1], stiffness[1, 2], stiffness[2, 2] = rr_cos_cos, rr_cos_sin, rr_sin_sin
    stiffness[0, 1], stiffness[0, 2], stiffness[1, 3] = ar_cos, ar_sin, ar_cos_sin
    stiffness[2, 3], stiffness[1, 4], stiffness[2, 4] = ar_sin_sin, -ar_cos_cos, -ar_cos_sin
    for row in range(1, DOFS):
        for column in range(row):
            stiffness[row, column] = stiffness[column, row]


@njit(cache=True, error_model="numpy")
def _damped_step(stiffness, damping, residual, dofs, matrix, step):
    """``step`` on the free ``dofs``: ``(K + mu I) step = residual`` restricted to them, by
    Gaussian elimination with partial pivoting; 0 elsewhere."""
    size = dofs.size
    for row in range(size):
        for column in range(size):
            matrix[row, column] = stiffness[dofs[row], dofs[column]]
        matrix[row, row] += damping
        matrix[row, size] = residual[dofs[row]]
    for pivot in range(size):
        best = pivot
        for row in range(pivot + 1, size):
            if abs(matrix[row, pivot]) > abs(matrix[best, pivot]):
                best = row
        if best != pivot:
            for column in range(pivot, size + 1):
                matrix[pivot, column], matrix[best, column] = \
                    matrix[best, column], matrix[pivot, column]
        for row in range(pivot + 1, size):
            factor = matrix[row, pivot] / matrix[pivot, pivot]
            for column in range(pivot + 1, size + 1):
                matrix[row, column] -= factor * matrix[pivot, column]
    step[:] = 0.0
    for row in range(size - 1, -1, -1):
        value = matrix[row, size]
        for column in range(row + 1, size):
            value -= matrix[row, column] * step[dofs[column]]
        step[dofs[row]] = value / matrix[row, row]


@njit(cache=True, error_model="numpy")
def _residual(load, reaction, free, residual):
    """``load - reaction`` in the free directions (0 in the held ones), and its norm."""
    total = 0.0
    for dof in range(DOFS):
        residual[dof] = load[dof] - reaction[dof] if free[dof] else 0.0
        total += residual[dof] * residual[dof]
    return math.sqrt(total)


@njit(cache=True, error_model="numpy")
def reciprocal_condition(stiffness, dofs, matrix):
    """Smallest over largest singular value of the stiffness restricted to the free ``dofs``
    (0 for a zero matrix), by cyclic Jacobi rotations in ``matrix``.

    The stiffness is symmetric: its singular values are its eigenvalues' magnitudes. Jacobi
    rotations find them to about ``1e-16`` of the largest (G. H. Golub, C. F. Van Loan, Matrix
    Computations, 4th ed., 2013, sec. 8.5), well within the ``1e-9`` threshold of
    :data:`models.ball._SINGULAR`.
    """
    size = dofs.size
    for row in range(size):
        for column in range(size):
            matrix[row, column] = stiffness[dofs[row], dofs[column]]
    for _ in range(JACOBI_SWEEPS):
        off = diagonal = 0.0
        for p in range(size):
            diagonal += matrix[p, p] * matrix[p, p]
            for q in range(p + 1, size):
                off += matrix[p, q] * matrix[p, q]
        if off <= 1e-32 * (diagonal + 2.0 * off):
            break
        for p in range(size - 1):
            for q in range(p + 1, size):
                pq = matrix[p, q]
                if pq == 0.0:
                    continue
                theta = (matrix[q, q] - matrix[p, p]) / (2.0 * pq)
                tangent = 1.0 / (abs(theta) + math.sqrt(theta * theta + 1.0))
                if theta < 0.0:
                    tangent = -tangent
                cos = 1.0 / math.sqrt(tangent * tangent + 1.0)
                sin = tangent * cos
                for r in range(size):
                    if r != p and r != q:
                        rp, rq = matrix[r, p], matrix[r, q]
                        matrix[r, p] = matrix[p, r] = cos * rp - sin * rq
                        matrix[r, q] = matrix[q, r] = sin * rp + cos * rq
                matrix[p, p] -= tangent * pq
                matrix[q, q] += tangent * pq
                matrix[p, q] = matrix[q, p] = 0.0
    smallest, largest = np.inf, 0.0
    for p in range(size):
        value = abs(matrix[p, p])
        if not value >= smallest:  # NaN: stays
            smallest = value
        if not value <= largest:
            largest = value
    return smallest / largest if largest > 0.0 else (0.0 if largest == 0.0 else largest)


@njit(cache=True, error_model="numpy", nogil=True)  # a threaded worker runs blocks side by side
def equilibria(rings, load, typical, damping, tolerance, free, jones, max_iterations, psi):
    """Each point's scaled displacement where the balls balance ``load`` in the ``free``
    directions, by the damped Newton iteration (module docstring).

    Parameters
    ----------
    rings : numpy.ndarray
        ``(N, COLUMNS)`` per-point geometry and contact constant (module docstring).
    load : numpy.ndarray
        ``(N, 5)`` scaled loads [N].
    typical : numpy.ndarray
        ``(N,)`` approach [m] of the preloaded bearing that gives the start: every ball at it
        and at its unloaded contact angle; 0: the point starts centred.
    damping : numpy.ndarray
        ``(N,)`` first Levenberg-Marquardt damping [N/m].
    tolerance : numpy.ndarray
        ``(N,)`` residual norm at which a point is done [N].
    free : numpy.ndarray of bool
        ``(5,)`` the displacements that may move.
    jones : bool
        Jones' geometry, else the fixed-angle one.
    max_iterations : int
    psi : numpy.ndarray
        ``(6, Z)`` :func:`azimuth_functions`.

    Returns
    -------
    scaled : numpy.ndarray
        ``(N, 5)`` displacements (tilts times ``R``) [m].
    converged : numpy.ndarray of bool
        Residual norm within ``tolerance``.
    stiffness : numpy.ndarray
        ``(N, 5, 5)`` scaled tangent stiffness there [N/m].
    condition : numpy.ndarray
        ``(N,)`` its :func:`reciprocal_condition` in the free directions.
    contacts : list of numpy.ndarray
        The six ``(N, Z)`` arrays of :func:`ball_contacts` there.
    """
    count, balls = load.shape[0], psi.shape[1]
    scaled = np.zeros((count, DOFS))
    converged = np.zeros(count, dtype=np.bool_)
    stiffness = np.zeros((count, DOFS, DOFS))
    condition = np.empty(count)
    contacts = [np.empty((count, balls)) for _ in range(6)]
    dofs = np.flatnonzero(free)
    approach, ball_load, slope, normal_axial, normal_radial, length = [
        np.empty(balls) for _ in range(6)]
    reaction, residual, step = np.empty(DOFS), np.empty(DOFS), np.empty(DOFS)
    trial, trial_residual = np.empty(DOFS), np.empty(DOFS)
    trial_stiffness = np.empty((DOFS, DOFS))
    matrix = np.empty((dofs.size, dofs.size + 1))
    for point in range(count):
        ring, applied, x, here = rings[point], load[point], scaled[point], stiffness[point]
        if typical[point] > 0.0:
            # The start: the displacement the load gives a bearing whose balls are all
            # compressed by ``typical`` at their unloaded angles, damped as the iteration.
            preloaded_contacts(typical[point], ring, approach, ball_load, slope, normal_axial,
                               normal_radial, length)
            ring_sums(ball_load, slope, normal_axial, normal_radial, length, jones, psi,
                      reaction, here)
            _damped_step(here, damping[point], applied, dofs, matrix, x)
        ball_contacts(x, ring, jones, psi, approach, ball_load, slope, normal_axial,
                      normal_radial, length)
        ring_sums(ball_load, slope, normal_axial, normal_radial, length, jones, psi, reaction,
                  here)
        norm = _residual(applied, reaction, free, residual)
        mu = damping[point]
        for _ in range(max_iterations):
            if not norm > tolerance[point]:
                break
            _damped_step(here, mu, residual, dofs, matrix, step)
            for dof in range(DOFS):
                trial[dof] = x[dof] + step[dof]
            ball_contacts(trial, ring, jones, psi, approach, ball_load, slope, normal_axial,
                          normal_radial, length)
            ring_sums(ball_load, slope, normal_axial, normal_radial, length, jones, psi,
                      reaction, trial_stiffness)
            trial_norm = _residual(applied, reaction, free, trial_residual)
            if trial_norm <= norm:
                x[:], residual[:], here[:, :] = trial, trial_residual, trial_stiffness
                norm = trial_norm
                mu *= 0.2
            else:
                mu *= 5.0
        converged[point] = norm <= tolerance[point]
        condition[point] = reciprocal_condition(here, dofs, matrix)
        ball_contacts(x, ring, jones, psi, contacts[0][point], contacts[1][point],
                      contacts[2][point], contacts[3][point], contacts[4][point],
                      contacts[5][point])
    return scaled, converged, stiffness, condition, contacts


@njit(cache=True, error_model="numpy")
def contacts_at(scaled, index, rings, jones, psi):
    """:func:`ball_contacts` of the points ``index`` at ``scaled``: six ``(n, Z)`` arrays."""
    count, balls = scaled.shape[0], psi.shape[1]
    found = [np.empty((count, balls)) for _ in range(6)]
    for point in range(count):
        ball_contacts(scaled[point], rings[index[point]], jones, psi, found[0][point],
                      found[1][point], found[2][point], found[3][point], found[4][point],
                      found[5][point])
    return found


@njit(cache=True, error_model="numpy")
def sums_at(scaled, index, rings, jones, psi):
    """:func:`ring_sums` of the points ``index`` at ``scaled``: the scaled reactions
    ``(n, 5)`` and tangent stiffnesses ``(n, 5, 5)``."""
    reaction = np.empty((scaled.shape[0], DOFS))
    stiffness = np.empty((scaled.shape[0], DOFS, DOFS))
    approach, load, slope, normal_axial, normal_radial, length = [
        np.empty(psi.shape[1]) for _ in range(6)]
    for point in range(scaled.shape[0]):
        ball_contacts(scaled[point], rings[index[point]], jones, psi, approach, load, slope,
                      normal_axial, normal_radial, length)
        ring_sums(load, slope, normal_axial, normal_radial, length, jones, psi,
                  reaction[point], stiffness[point])
    return reaction, stiffness

