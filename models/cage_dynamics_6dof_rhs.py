"""Right-hand side of the spatial transient model of a cylindrical roller bearing with circular
pockets (paper 002, sections 1.3-1.5), compiled, and its integrators.

Frames and state, all in the inertial frame ``O-XYZ`` (Z the outer ring's axis, Y up: load
and gravity along -Y):

- inner ring: centre ``x, y`` and velocity (its attitude, axial position and speed given);
- roller ``j``: centre, velocity, axis unit vector ``a`` and angular velocity ``omega`` (a
  roller is a rigid cylinder, symmetric about ``a``: its angle about ``a`` never enters);
- cage: mass centre ``S``, velocity, attitude quaternion ``q`` (body frame: ``x_b`` through
  pocket 1, ``z_b`` its axis) and angular velocity in the body frame ``Omega``; its geometric
  centre is ``O_b = S - e_r x_b - e_a z_b``.

Contacts (each element force acts on both bodies, at one point):

- roller-raceway: slices along the roller, each with its own approach from the roller's
  position and attitude (eqs. 18-21), Palmgren load with Hunt-Crossley damping, Gupta
  traction against the slice's sliding velocity (skew makes it axial);
- roller-pocket arc: a Winkler bed of elements over both arcs (eqs. 1, 2, 8, 9) when any
  element is pressed in, otherwise a short-bearing film per element (eq. 3's role);
- roller end - pocket end face and roller end - inner-ring rib: Winkler elements over the
  roller's end faces (eqs. 1, 2, 10-17), dry when pressed in, otherwise oil shear (eq. 7);
- roller windage (eq. 22), cage windage about its axis, gravity.
"""
from __future__ import annotations

import numpy as np

from .compiled_cache import njit
from .contact_laws import (damped_spring, palmgren_slice, regularised_direction,
                           short_bearing_pressure, traction_coefficient)
from .dormand_prince import FIRST_STEP, SMALLEST_STEP, conclude, stage_argument

(OMEGA_I, LOAD, R_INNER, R_OUTER, RADIUS, LENGTH, PITCH, M_ROLLER, J_AXIAL, J_TRANSVERSE,
 K_SLICE, HUNT, BED_POCKET, BED_RIB, MU_DRY, VISCOSITY, FILM_FLOOR, POCKET_RADIUS,
 POCKET_PLAY, RIB_PLAY, RIB_RADIUS, CAGE_IN, CAGE_OUT, WINDAGE, CAGE_DRAG, M_RING, C_RING,
 M_CAGE, J_CAGE_X, J_CAGE_Z, ECC_RADIAL, ECC_AXIAL, GRAVITY, MISALIGN_X, MISALIGN_Y,
 TRACTION_A, TRACTION_B, TRACTION_C, TRACTION_D, RACEWAYS, POCKETS, ENDS, DRAG,
 SLIP_SMOOTHING, FILM_FILL, END_PRESSURE, FACE_RADIUS, END_FILL, END_FACES,
 END_RIBS) = range(50)
PARAMETERS = 50
#: RACEWAYS, POCKETS, ENDS and DRAG switch their terms on (1.0) or off (0.0); END_FACES and
#: END_RIBS the two parts of the end terms (the pocket end faces, the ribs).
RING, ROLLER_SIZE, CAGE_SIZE = 4, 12, 13
HUB = RING + CAGE_SIZE  # the inner ring's and the cage's entries, the rollers' "hub"


def state_size(count):
    return RING + ROLLER_SIZE * count + CAGE_SIZE


# Vectors are tuples of three floats: they live in registers, where small arrays would be
# allocated on the heap millions of times per run.
@njit(cache=True)
def _add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


@njit(cache=True)
def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


@njit(cache=True)
def _mul(k, a):
    return (k * a[0], k * a[1], k * a[2])


@njit(cache=True)
def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


@njit(cache=True)
def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@njit(cache=True)
def _vector(array, start):
    return (array[start], array[start + 1], array[start + 2])


@njit(cache=True)
def _tangential(v, normal):
    """``v`` less its component along the unit ``normal``, and that part's length."""
    t = _sub(v, _mul(_dot(v, normal), normal))
    return t, np.sqrt(_dot(t, t))


@njit(cache=True)
def rotation(q):
    """Rotation matrix (body to inertial) of a quaternion ``(w, x, y, z)``, normalised."""
    w, x, y, z = q[0], q[1], q[2], q[3]
    n = np.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


@njit(cache=True)
def ring_axis(p):
    """The inner ring's axis: ``e_z`` turned about X by ``misalignment_x``, then about Y."""
    ax, ay = p[MISALIGN_X], p[MISALIGN_Y]
    return (np.sin(ay), -np.sin(ax) * np.cos(ay), np.cos(ax) * np.cos(ay))


@njit(cache=True)
def cage_frame(state, count, p):
    """The cage's rotation matrix (body to inertial), its angular velocity in the body frame,
    and its frame: mass centre [m], velocity [m/s], inertial angular velocity [rad/s], body
    axes ``x_b, y_b, z_b`` and geometric centre [m]."""
    c0 = RING + ROLLER_SIZE * count
    mass_centre = _vector(state, c0)
    cage_velocity = _vector(state, c0 + 3)
    turn = rotation(state[c0 + 6:c0 + 10])
    body_rate = _vector(state, c0 + 10)
    x_b = (turn[0, 0], turn[1, 0], turn[2, 0])
    y_b = (turn[0, 1], turn[1, 1], turn[2, 1])
    z_b = (turn[0, 2], turn[1, 2], turn[2, 2])
    cage_rate = _add(_add(_mul(body_rate[0], x_b), _mul(body_rate[1], y_b)),
                     _mul(body_rate[2], z_b))  # inertial angular velocity
    cage_centre = _sub(mass_centre, _add(_mul(p[ECC_RADIAL], x_b), _mul(p[ECC_AXIAL], z_b)))
    return turn, body_rate, (mass_centre, cage_velocity, cage_rate, x_b, y_b, z_b,
                             cage_centre)


@njit(cache=True)
def derivatives(state, p, count, slice_z, arc_theta, arc_z, arc_area, face_r, face_phi,
                face_area, arc_force, end_gap, rib_gap, dry, shares, observe):
    """Time derivative of ``state``, with the elements
    :func:`models.cage_dynamics_6dof.geometry` gives (``arc_area``: each pocket-arc element's
    area [m^2], angle x axial point). Each roller's share of the forces on the other bodies
    is written to ``shares`` (roller x {force on the cage [N], its moment about the cage's
    mass centre [N m], force on the inner ring in X and Y [N]}, 8 columns): the implicit
    integrator's Jacobian takes the rollers apart by them. With ``observe`` nonzero the
    element values of this state are written to ``arc_force`` (dry force per pocket-arc
    element) [N], ``end_gap`` and ``rib_gap`` (gap per end-face element, NaN where the face
    has no counterpart) [m] and ``dry`` (roller x {arc, pocket end, rib}: 1 where in dry
    contact). ``observe`` is a
    number, 0.0 or 1.0: numba compiles a literal True or False as a type of its own, which
    would compile this large function three times instead of once."""
    out = np.zeros_like(state)
    g = p[GRAVITY]
    radius, length = p[RADIUS], p[LENGTH]
    zero = (0.0, 0.0, 0.0)
    # Inner ring
    ring_centre = (state[0], state[1], 0.0)
    ring_velocity = (state[2], state[3], 0.0)
    z_ring = ring_axis(p)
    ring_spin = _mul(p[OMEGA_I], z_ring)
    ring_force = (0.0, -p[LOAD] * p[RACEWAYS] - p[M_RING] * g, 0.0)
    # Cage
    c0 = RING + ROLLER_SIZE * count
    turn, body_rate, frame = cage_frame(state, count, p)
    mass_centre, cage_velocity, cage_rate, x_b, y_b, z_b, cage_centre = frame
    cage_force = (0.0, -p[M_CAGE] * g, 0.0)
    cage_moment = zero  # about the mass centre, inertial frame
    n_arc, n_axial = arc_theta.size, arc_z.size
    gaps = np.empty((n_arc, n_axial))
    alongs = np.empty((n_arc, n_axial))
    arc_cos, arc_sin = np.cos(arc_theta), np.sin(arc_theta)
    face_cos, face_sin = np.cos(face_phi), np.sin(face_phi)
    for j in range(count):
        cage_force_before, cage_moment_before = cage_force, cage_moment
        ring_force_before = ring_force
        k = RING + ROLLER_SIZE * j
        centre = _vector(state, k)
        velocity = _vector(state, k + 3)
        axis = _vector(state, k + 6)
        axis = _mul(1.0 / np.sqrt(_dot(axis, axis)), axis)
        omega = _vector(state, k + 9)
        force = (0.0, -p[M_ROLLER] * g, 0.0)
        moment = zero
        # -- roller-raceway slices (eqs. 18-21)
        if p[RACEWAYS] > 0.0:
            for z in slice_z:
                middle = _add(centre, _mul(z, axis))
                for inner in (True, False):
                    approach, normal, point, relative = raceway_slice(
                        middle, inner, centre, velocity, omega, ring_centre, ring_velocity,
                        z_ring, ring_spin, p)
                    if approach <= 0.0:
                        continue
                    rate = -_dot(relative, normal)  # approach speed
                    load = palmgren_slice(p[K_SLICE], approach)
                    push = damped_spring(load / approach, approach, rate, p[HUNT])
                    sliding, speed = _tangential(relative, normal)
                    on_roller = _mul(push, normal)
                    if speed > 0.0:
                        mu = traction_coefficient(speed, p[TRACTION_A], p[TRACTION_B],
                                                  p[TRACTION_C], p[TRACTION_D])
                        on_roller = _sub(on_roller, _mul(mu * push / speed, sliding))
                    force = _add(force, on_roller)
                    moment = _add(moment, _cross(_sub(point, centre), on_roller))
                    if inner:
                        ring_force = _sub(ring_force, on_roller)
        # -- pocket j
        x_c, y_c, pocket = pocket_frame(j, count, x_b, y_b, cage_centre, p)
        if p[POCKETS] > 0.0:
            pressed = pocket_gaps(centre, axis, pocket, x_c, y_c, z_b, arc_cos, arc_sin, arc_z,
                                  p, gaps, alongs)
            spin = _dot(_sub(omega, cage_rate), z_b)  # roller relative to the cage
            pocket_force, pocket_moment = zero, zero
            motion = pocket_motion(centre, velocity, axis, omega, pocket, x_c, y_c, z_b,
                                   cage_velocity, cage_rate, mass_centre)
            for m in range(n_arc):
                cos_m, sin_m = arc_cos[m], arc_sin[m]
                u = _add(_mul(cos_m, x_c), _mul(sin_m, y_c))
                u_prime = _sub(_mul(cos_m, y_c), _mul(sin_m, x_c))
                wall, base = arc_wall(u, motion, cage_rate, p)
                for n in range(n_axial):
                    if observe != 0.0:
                        arc_force[j, m, n] = 0.0
                    h = gaps[m, n]
                    if h == np.inf or (pressed and h >= 0.0):
                        continue
                    along = alongs[m, n]
                    arm, normal, relative, closing = arc_element(
                        wall, base, arc_z[n], z_b, along, h, axis, motion, p)
                    if pressed:
                        push = damped_spring(p[BED_POCKET] * arc_area[m, n], -h, closing,
                                             p[HUNT])
                        # the roller's surface at the element less the cage there
                        sliding, speed = _tangential(_add(relative, _cross(
                            omega, _mul(radius, normal))), normal)
                        on_roller = _mul(-push, normal)
                        if speed > 0.0:
                            on_roller = _sub(on_roller, _mul(
                                p[MU_DRY] * push * regularised_direction(
                                    speed, p[SLIP_SMOOTHING]) / speed, sliding))
                        if observe != 0.0:
                            arc_force[j, m, n] = push
                    else:
                        film = max(h, p[FILM_FLOOR])
                        slope = arc_slope(along, motion, cos_m, sin_m)
                        pressure = short_bearing_pressure(p[VISCOSITY], spin * slope, -closing,
                                                          film, along, length)
                        shear = p[VISCOSITY] * spin * radius / film
                        on_roller = _mul(-arc_area[m, n] * p[FILM_FILL], _add(
                            _mul(pressure, normal), _mul(shear, u_prime)))
                    pocket_force = _add(pocket_force, on_roller)
                    pocket_moment = _add(pocket_moment, _cross(arm, on_roller))
            force = _add(force, pocket_force)
            moment = _add(moment, pocket_moment)
            cage_force = _sub(cage_force, pocket_force)  # its moment about the mass centre:
            cage_moment = _sub(cage_moment, _add(pocket_moment, _cross(
                _sub(centre, mass_centre), pocket_force)))
            if observe != 0.0:
                dry[j, 0] = 1.0 if pressed else 0.0
        # -- roller ends: pocket end faces and ribs (eqs. 10-17)
        if p[ENDS] > 0.0:
            pocket_face, rib = end_faces(frame, ring_centre, ring_velocity, z_ring, ring_spin,
                                         p)
            for side in range(2):
                roller = roller_end(centre, velocity, omega, axis, side, length)
                if p[END_FACES] > 0.0:
                    on_roller, turning = _end_face(
                        roller, *pocket_face, face_r, face_cos, face_sin, face_area, p,
                        end_gap[j, side], dry[j], 1, observe)
                    force = _add(force, on_roller)
                    moment = _add(moment, turning)
                    cage_force = _sub(cage_force, on_roller)
                    cage_moment = _sub(cage_moment, _add(turning, _cross(
                        _sub(centre, mass_centre), on_roller)))
                elif observe != 0.0:
                    end_gap[j, side] = np.nan
                if p[END_RIBS] > 0.0:
                    on_roller, turning = _end_face(
                        roller, *rib, face_r, face_cos, face_sin, face_area, p,
                        rib_gap[j, side], dry[j], 2, observe)
                    force = _add(force, on_roller)
                    moment = _add(moment, turning)
                    ring_force = _sub(ring_force, on_roller)
                elif observe != 0.0:
                    rib_gap[j, side] = np.nan
        # -- windage on the roller's orbit (eq. 22)
        if p[DRAG] > 0.0:
            rho2 = centre[0] ** 2 + centre[1] ** 2
            orbit_rate = (centre[0] * velocity[1] - centre[1] * velocity[0]) / rho2
            drag = p[WINDAGE] * orbit_rate * abs(orbit_rate) / np.sqrt(rho2)
            force = _add(force, (drag * centre[1], -drag * centre[0], 0.0))
        for i in range(3):
            shares[j, i] = cage_force[i] - cage_force_before[i]
            shares[j, 3 + i] = cage_moment[i] - cage_moment_before[i]
        shares[j, 6] = ring_force[0] - ring_force_before[0]
        shares[j, 7] = ring_force[1] - ring_force_before[1]
        # -- Newton-Euler for the roller, symmetric about its axis
        acceleration = _symmetric_top(omega, axis, moment, p[J_AXIAL], p[J_TRANSVERSE])
        axis_rate = _cross(omega, axis)
        for i in range(3):
            out[k + i] = velocity[i]
            out[k + 3 + i] = force[i] / p[M_ROLLER]
            out[k + 6 + i] = axis_rate[i]
            out[k + 9 + i] = acceleration[i]
    # Inner ring: free in X and Y
    out[0], out[1] = state[2], state[3]
    out[2] = (ring_force[0] - p[C_RING] * state[2]) / p[M_RING]
    out[3] = (ring_force[1] - p[C_RING] * state[3]) / p[M_RING]
    # Cage: Newton for the mass centre, Euler in the body frame
    if p[DRAG] > 0.0:
        rate = _dot(cage_rate, z_b)
        cage_moment = _sub(cage_moment, _mul(p[CAGE_DRAG] * rate * np.sqrt(abs(rate)), z_b))
    for i in range(3):
        out[c0 + i] = cage_velocity[i]
        out[c0 + 3 + i] = cage_force[i] / p[M_CAGE]
    w, x, y, z = state[c0 + 6], state[c0 + 7], state[c0 + 8], state[c0 + 9]
    a, b, c = body_rate
    out[c0 + 6] = -0.5 * (x * a + y * b + z * c)
    out[c0 + 7] = 0.5 * (w * a + y * c - z * b)
    out[c0 + 8] = 0.5 * (w * b + z * a - x * c)
    out[c0 + 9] = 0.5 * (w * c + x * b - y * a)
    body_moment = (_dot(x_b, cage_moment), _dot(y_b, cage_moment), _dot(z_b, cage_moment))
    jx, jz = p[J_CAGE_X], p[J_CAGE_Z]
    out[c0 + 10] = (body_moment[0] - (jz - jx) * b * c) / jx
    out[c0 + 11] = (body_moment[1] - (jx - jz) * a * c) / jx
    out[c0 + 12] = body_moment[2] / jz
    return out


@njit(cache=True)
def raceway_slice(middle, inner, centre, velocity, omega, ring_centre, ring_velocity, z_ring,
                  ring_spin, p):
    """A raceway slice of a roller at its axis point ``middle`` against the inner (``inner``
    true) or the outer raceway (eqs. 18-21): its approach [m] (not in contact where not
    positive: then the rest is not computed), its unit normal (from the ring's axis to the
    roller at the inner raceway, towards the axis at the outer), its contact point on the
    roller [m] and the roller's velocity there relative to the raceway [m/s]."""
    radius = p[RADIUS]
    if inner:
        d = _sub(middle, ring_centre)
        radial = _sub(d, _mul(_dot(d, z_ring), z_ring))
        rho = np.sqrt(_dot(radial, radial))
        normal = _mul(1.0 / rho, radial)
        approach = p[R_INNER] + radius - rho
    else:
        rho = np.sqrt(middle[0] ** 2 + middle[1] ** 2)
        normal = (-middle[0] / rho, -middle[1] / rho, 0.0)
        approach = rho + radius - p[R_OUTER]
    if approach <= 0.0:
        return approach, normal, middle, normal
    point = _sub(middle, _mul(radius, normal))
    relative = _add(velocity, _cross(omega, _sub(point, centre)))
    if inner:
        relative = _sub(relative, _add(ring_velocity, _cross(ring_spin,
                                                             _sub(point, ring_centre))))
    return approach, normal, point, relative


@njit(cache=True)
def deepest_raceway_approaches(samples, first, p, count, slice_z):
    """The largest approach [m] of any roller's raceway slice over ``samples[first:]``
    (states, one per row): at the inner raceway and at the outer (:func:`raceway_slice`)."""
    deepest = np.zeros(2)
    z_ring = ring_axis(p)
    ring_spin = _mul(p[OMEGA_I], z_ring)
    for s in range(first, samples.shape[0]):
        state = samples[s]
        ring_centre, ring_velocity = (state[0], state[1], 0.0), (state[2], state[3], 0.0)
        for j in range(count):
            k = RING + ROLLER_SIZE * j
            centre, velocity = _vector(state, k), _vector(state, k + 3)
            axis = _vector(state, k + 6)
            axis = _mul(1.0 / np.sqrt(_dot(axis, axis)), axis)
            omega = _vector(state, k + 9)
            for z in slice_z:
                middle = _add(centre, _mul(z, axis))
                for side in range(2):
                    approach = raceway_slice(middle, side == 0, centre, velocity, omega,
                                             ring_centre, ring_velocity, z_ring, ring_spin,
                                             p)[0]
                    deepest[side] = max(deepest[side], approach)
    return deepest


@njit(cache=True)
def pocket_frame(j, count, x_b, y_b, cage_centre, p):
    """Pocket ``j``'s radial and tangential unit vectors and its centre [m]."""
    angle = 2.0 * np.pi * j / count
    x_c = _add(_mul(np.cos(angle), x_b), _mul(np.sin(angle), y_b))
    y_c = _add(_mul(-np.sin(angle), x_b), _mul(np.cos(angle), y_b))
    return x_c, y_c, _add(cage_centre, _mul(p[PITCH], x_c))


@njit(cache=True)
def pocket_gaps(centre, axis, pocket, x_c, y_c, z_b, arc_cos, arc_sin, arc_z, p, gaps,
                alongs):
    """Each pocket-arc element's gap to the roller [m] (``inf`` beyond the roller's ends)
    and its position along the roller's axis [m], into ``gaps`` and ``alongs``; whether any
    element is pressed in."""
    pressed = False
    to_pocket = _sub(pocket, centre)
    for m in range(arc_cos.size):
        wall = _add(to_pocket, _mul(p[POCKET_RADIUS], _add(_mul(arc_cos[m], x_c),
                                                           _mul(arc_sin[m], y_c))))
        for n in range(arc_z.size):
            arm = _add(wall, _mul(arc_z[n], z_b))  # roller centre to the element
            along = _dot(arm, axis)
            alongs[m, n] = along
            if abs(along) > 0.5 * p[LENGTH]:
                gaps[m, n] = np.inf  # beyond the roller's end
                continue
            gaps[m, n] = np.sqrt(_dot(arm, arm) - along * along) - p[RADIUS]
            if gaps[m, n] < 0.0:
                pressed = True
    return pressed


@njit(cache=True)
def pocket_motion(centre, velocity, axis, omega, pocket, x_c, y_c, z_b, cage_velocity,
                  cage_rate, mass_centre):
    """What a roller's pocket-arc elements share: the pocket's centre from the roller's
    [m], the roller's velocity less the cage's at the roller's centre [m/s], the roller's
    ``omega x a`` and the cage's ``Omega x z_b`` [rad/s], the roller's axis and the pocket's
    centre in the pocket's radial and tangential directions (``a . x_c``, ``a . y_c``
    [-], ``(pocket - centre) . x_c``, ``. y_c`` [m])."""
    to_pocket = _sub(pocket, centre)
    shift = _sub(_sub(velocity, cage_velocity), _cross(cage_rate, _sub(centre, mass_centre)))
    return (to_pocket, shift, _cross(omega, axis), _cross(cage_rate, z_b), _dot(axis, x_c),
            _dot(axis, y_c), _dot(to_pocket, x_c), _dot(to_pocket, y_c))


@njit(cache=True)
def arc_wall(u, motion, cage_rate, p):
    """The pocket wall's line at ``u`` round the arc: its point on the pocket's mid-plane
    from the roller's centre [m], and the roller's velocity less the cage's there [m/s]
    (:func:`pocket_motion`'s ``motion``)."""
    wall = _add(motion[0], _mul(p[POCKET_RADIUS], u))
    return wall, _sub(motion[1], _cross(cage_rate, wall))


@njit(cache=True)
def arc_element(wall, base, z, z_b, along, h, axis, motion, p):
    """A pocket-arc element on the wall line ``wall`` (:func:`arc_wall`, with ``base``) at
    ``z`` along the pocket, facing the roller across the gap ``h``, ``along`` the roller's
    axis from its centre: its position from the roller's centre [m], the unit normal from
    the roller's axis to the wall, the roller's velocity at the foot on its axis less the
    cage's at the element, and its normal part, the speed of approach [m/s]."""
    arm = _add(wall, _mul(z, z_b))
    normal = _mul(1.0 / (h + p[RADIUS]), _sub(arm, _mul(along, axis)))  # axis to wall
    relative = _add(base, _sub(_mul(along, motion[2]), _mul(z, motion[3])))
    return arm, normal, relative, _dot(relative, normal)


@njit(cache=True)
def arc_slope(along, motion, cos_m, sin_m):
    """The pocket film's slope round the arc, ``dh/dtheta`` [m], at the element at
    ``(cos_m, sin_m)``, ``along`` the roller's axis: the roller's offset from the pocket's
    centre across it (:func:`pocket_motion`'s ``motion``)."""
    return ((along * motion[4] - motion[6]) * sin_m
            - (along * motion[5] - motion[7]) * cos_m)


@njit(cache=True)
def roller_end(centre, velocity, omega, axis, side, length):
    """A roller's end (``side`` 0 at ``-length/2`` along its axis, 1 at ``+length/2``) as
    :func:`_end_face` takes it: (centre, velocity, angular velocity, axis, the end disc's
    axes ``first`` (radial) and ``second``, the end's centre, the side's sign)."""
    first, size = _tangential((centre[0], centre[1], 0.0), axis)
    first = _mul(1.0 / size, first)
    sign = -1.0 if side == 0 else 1.0
    return (centre, velocity, omega, axis, first, _cross(axis, first),
            _add(centre, _mul(sign * 0.5 * length, axis)), sign)


@njit(cache=True)
def end_faces(frame, ring_centre, ring_velocity, z_ring, ring_spin, p):
    """The flat faces a roller's ends meet, each as :func:`_end_face`'s ``(face, body)``:
    its pocket's end faces on the cage (:func:`cage_frame`'s ``frame``), the inner ring's
    ribs."""
    mass_centre, cage_velocity, cage_rate, _, _, z_b, cage_centre = frame
    return (((cage_centre, z_b, p[POCKET_PLAY], p[CAGE_IN], p[CAGE_OUT], p[BED_POCKET]),
             (mass_centre, cage_velocity, cage_rate)),
            ((ring_centre, z_ring, p[RIB_PLAY], p[R_INNER], p[RIB_RADIUS], p[BED_RIB]),
             (ring_centre, ring_velocity, ring_spin)))


@njit(cache=True)
def _end_face(roller, face, body, face_r, face_cos, face_sin, face_area, p, gaps, dry, kind,
              observe, squeeze=None):
    """Force [N] and moment about the roller's centre [N m] on a roller of one flat face at
    its end (the pocket's end face, the inner ring's rib): :func:`_face_force` for each
    end-face element facing the face's annulus.

    ``roller`` is (centre, velocity, angular velocity, axis, end-face axes ``first`` and
    ``second``, end-face centre, side's sign), ``face`` (a point on the face's axis, that
    axis, the axial play, its annulus' inner and outer radii [m], the Winkler modulus) and
    ``body`` (the face body's reference point, its velocity there, its angular velocity).
    With ``observe`` nonzero the gaps go to ``gaps`` (NaN off the annulus) and a dry
    element sets ``dry[kind]``.

    An element's offset on the end face is ``alpha first + beta second``; its gap, and its
    sliding over the face, are affine in ``(alpha, beta)``. The oil's shear on the elements
    in their film, ``-eta A / h`` times the sliding, is summed by its weights' moments over
    ``(alpha, beta)``, to order two for the moment; dry elements and the film's pressure,
    elementwise.

    ``squeeze``, when given (10 entries), receives the film's squeeze damping by the
    closing speed, ``c = 6 eta A (s - s_1)(s_2 - s) / h^3`` (:func:`_face_pressure`), of the
    elements whose pressure is positive, summed: ``sum c``, ``sum c m`` and the upper
    triangle of ``sum c m m^T`` (xx, xy, xz, yy, yz, zz), ``m = arm x n`` the element's
    moment arm crossed with the face's normal (the implicit part's Jacobian,
    :mod:`models.cage_dynamics_6dof_imex`)."""
    centre, velocity, omega, axis, first, second, end, sign = roller
    axis_point, face_axis, play, low, high, bed = face
    low2, high2 = low ** 2, high ** 2
    body_point, body_velocity, body_rate = body
    offset = _sub(end, axis_point)
    along_first, along_second = _dot(offset, first), _dot(offset, second)
    offset_axial, offset_square = _dot(offset, face_axis), _dot(offset, offset)
    first_axial, second_axial = _dot(first, face_axis), _dot(second, face_axis)
    half = 0.5 * (p[LENGTH] + play)
    normal = _mul(-sign, face_axis)  # from the face into the roller
    arm0 = _mul(sign * 0.5 * p[LENGTH], axis)
    relative_rate = _sub(omega, body_rate)
    # the sliding: constant + alpha slide1 + beta slide2, and its part along the face
    slide0 = _sub(_add(velocity, _cross(omega, arm0)), _add(body_velocity, _cross(
        body_rate, _sub(end, body_point))))
    slide1, slide2 = _cross(relative_rate, first), _cross(relative_rate, second)
    flat0 = _tangential(slide0, normal)[0]
    flat1, flat2 = _tangential(slide1, normal)[0], _tangential(slide2, normal)[0]
    shear = -p[VISCOSITY] * p[END_FILL]
    w, wa, wb, waa, wab, wbb = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    force, moment = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    # An element lies within its ring's radius of the end face's centre, and so does its
    # distance from the face's axis from the centre's: rings wholly off the annulus are
    # passed over (a margin for the rounding).
    reach_end = np.sqrt(max(offset_square - offset_axial * offset_axial, 0.0))
    for r in range(face_r.size):
        if (reach_end - face_r[r] > high * (1.0 + 1e-9)
                or reach_end + face_r[r] < low * (1.0 - 1e-9)):
            if observe != 0.0:
                gaps[r, :] = np.nan
            continue
        for s in range(face_cos.size):
            alpha, beta = face_r[r] * face_cos[s], face_r[r] * face_sin[s]
            axial = offset_axial + alpha * first_axial + beta * second_axial
            reach2 = (offset_square + 2.0 * (alpha * along_first + beta * along_second)
                      + face_r[r] ** 2 - axial * axial)
            if not low2 <= reach2 <= high2:
                if observe != 0.0:
                    gaps[r, s] = np.nan
                continue
            h = half - sign * axial
            if observe != 0.0:
                gaps[r, s] = h
                if h < 0.0:
                    dry[kind] = 1.0
            if h >= 0.0 and p[END_PRESSURE] <= 0.0:
                weight = shear * face_area[r] / max(h, p[FILM_FLOOR])
                w += weight
                wa += weight * alpha
                wb += weight * beta
                waa += weight * alpha * alpha
                wab += weight * alpha * beta
                wbb += weight * beta * beta
                continue
            arm = _add(arm0, _add(_mul(alpha, first), _mul(beta, second)))
            sliding = _add(slide0, _add(_mul(alpha, slide1), _mul(beta, slide2)))
            band = _band(np.sqrt(reach2), low, high, alpha, beta, p) if h >= 0.0 else 0.0
            on_roller = _face_force(h, normal, sliding, face_area[r], bed, p, band, axis)
            if squeeze is not None and h >= 0.0 and _dot(on_roller, normal) > 0.0:
                damping = (6.0 * p[VISCOSITY] * band * face_area[r] * p[END_FILL]
                           / max(h, p[FILM_FLOOR]) ** 3)
                _add_squeeze(squeeze, damping, _cross(arm, normal))
            force = _add(force, on_roller)
            moment = _add(moment, _cross(arm, on_roller))
    force = _add(force, _add(_mul(w, flat0), _add(_mul(wa, flat1), _mul(wb, flat2))))
    moment = _add(moment, _add(
        _add(_mul(w, _cross(arm0, flat0)),
             _mul(wa, _add(_cross(arm0, flat1), _cross(first, flat0)))),
        _add(_add(_mul(wb, _add(_cross(arm0, flat2), _cross(second, flat0))),
                  _mul(waa, _cross(first, flat1))),
             _add(_mul(wab, _add(_cross(first, flat2), _cross(second, flat1))),
                  _mul(wbb, _cross(second, flat2))))))
    return force, moment


@njit(cache=True)
def _add_squeeze(sums, damping, lever):
    """Add an element's squeeze damping ``c`` with its ``m`` to :func:`_end_face`'s sums."""
    sums[0] += damping
    k = 4
    for a in range(3):
        sums[1 + a] += damping * lever[a]
        for b in range(a, 3):
            sums[k] += damping * lever[a] * lever[b]
            k += 1


@njit(cache=True)
def _face_force(gap, normal, sliding, area, bed, p, band, axis):
    """Force on the roller of one end-face element [N]: the Winkler bed and Coulomb friction
    when pressed in (eqs. 1, 2); otherwise the oil's shear ``eta v A / h`` (eq. 7) and, unless
    the paper's shear-only film is asked for, the film's pressure (:func:`_face_pressure`),
    both over the share of the face under oil.
    ``normal`` points from the face into the roller; ``sliding`` is the roller's velocity
    less the face's at the element; ``band`` is :func:`_band`'s; ``axis`` the roller's."""
    tangential, speed = _tangential(sliding, normal)
    if gap < 0.0:
        push = damped_spring(bed * area, -gap, -_dot(sliding, normal), p[HUNT])
        force = _mul(push, normal)
        if speed > 0.0:
            force = _sub(force, _mul(p[MU_DRY] * push * regularised_direction(
                speed, p[SLIP_SMOOTHING]) / speed, tangential))
        return force
    film = max(gap, p[FILM_FLOOR])
    area = area * p[END_FILL]  # the share of the face under oil
    force = _mul(-p[VISCOSITY] * area / film, tangential)
    if p[END_PRESSURE] > 0.0:
        # The film's slope along the face, dotted with the sliding: the roller's end plane
        # leans on the flat face by the roller axis' part along the face (a roller turned
        # across the face, in a failed trial step, has no film to speak of).
        lean = _dot(axis, normal)
        wedge = -_dot(tangential, axis) / lean if abs(lean) > 0.5 else 0.0
        pressure = _face_pressure(p[VISCOSITY], -_dot(sliding, normal), wedge, film, band)
        force = _add(force, _mul(pressure * area, normal))
    return force


@njit(cache=True)
def _face_pressure(viscosity, closing, wedge, film, band):
    """Film pressure between a roller end and a flat face, from Reynolds' equation across the
    narrow band where they face each other (no pressure flow along it), cavitated below
    ambient (Guembel) [Pa]:

    ``p = 6 eta (dh/dt_closing + u . grad h / 2) (s - s_1) (s_2 - s) / h^3``

    with ``u`` the roller's sliding over the face and ``s_1 < s < s_2`` the band's edges
    across it (``band`` = ``(s - s_1)(s_2 - s)`` [m^2]): the squeeze of a closing film and the
    wedge of a leaning one, as a short bearing's (:func:`contact_laws.short_bearing_pressure`).

    References
    ----------
    .. [1] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid Film
       Lubrication, 2nd ed., Marcel Dekker (2004), ch. 7 (Reynolds' equation), ch. 8-9
       (squeeze and wedge films), doi:10.1201/9780203021187.
    """
    return max(0.0, 6.0 * viscosity * (closing + 0.5 * wedge) * band / film**3)


@njit(cache=True)
def _band(reach, low, high, across, along, p):
    """``(s - s_1)(s_2 - s)`` [m^2] of an end-face element at distance ``s = reach`` from
    the face's axis, ``across`` and ``along`` its coordinates on the roller's end disc (radial
    and tangential): the band across which the film's pressure falls to ambient is the
    face's annulus ``low`` to ``high`` (the cage rim, the rib), cut where the disc's radial
    chord through the element leaves the disc."""
    chord = np.sqrt(max(p[FACE_RADIUS] ** 2 - along * along, 0.0))
    centre = np.sqrt(max(reach * reach - along * along, 0.0)) - across  # of the chord
    first = max(low, np.sqrt((centre - chord) ** 2 + along * along))
    last = min(high, np.sqrt((centre + chord) ** 2 + along * along))
    return max(0.0, (reach - first) * (last - reach))


@njit(cache=True)
def _symmetric_top(omega, axis, moment, j_axial, j_transverse):
    """Angular acceleration of a rigid body symmetric about ``axis`` (inertial frame): the
    spin ``s = omega . a`` obeys ``J_a s' = M . a``, the transverse momentum
    ``J_t (omega - s a)`` takes the rest of ``M`` (Euler's equations for a symmetric top)."""
    spin = _dot(omega, axis)
    spin_rate = _dot(moment, axis) / j_axial
    axis_rate = _cross(omega, axis)
    transverse = _sub(_sub(moment, _mul(j_axial * spin_rate, axis)),
                      _mul(j_axial * spin, axis_rate))
    return _add(_mul(1.0 / j_transverse, transverse),
                _add(_mul(spin_rate, axis), _mul(spin, axis_rate)))


# Dormand-Prince 5(4) tableau
@njit(cache=True)
def _normalise(state, count):
    """Project the roller axes and the cage's quaternion back to unit length."""
    for j in range(count):
        _unit(state, RING + ROLLER_SIZE * j + 6, 3)
    _unit(state, RING + ROLLER_SIZE * count + 6, 4)


@njit(cache=True)
def _unit(state, start, size):
    """Divide ``state[start:start + size]`` by its length, element by element (see
    :func:`_observe`)."""
    squares = 0.0
    for i in range(start, start + size):
        squares += state[i] * state[i]
    length = np.sqrt(squares)
    for i in range(start, start + size):
        state[i] /= length


@njit(cache=True)
def _observe(state, p, count, geometry, record, settled, arc_max, end_min, rib_min, last,
             events):
    """Element values of one sample: the largest arc force, the smallest end and rib gaps
    over the settled samples, and the dry contacts that began since the last sample."""
    slice_z, arc_theta, arc_z, arc_area, face_r, face_phi, face_area = geometry
    arc_force, end_gap, rib_gap, dry, shares = record
    dry[:, :] = 0.0
    derivatives(state, p, count, slice_z, arc_theta, arc_z, arc_area, face_r, face_phi,
                face_area, arc_force, end_gap, rib_gap, dry, shares, 1.0)
    if not settled:
        _copy(dry, last)
        return
    # element by element: numba compiles a ufunc over arrays with a message for each
    # mismatch of shapes, which costs more to compile than the loop
    for index in np.ndindex(arc_max.shape):
        arc_max[index] = np.maximum(arc_max[index], arc_force[index])
    for index in np.ndindex(end_min.shape):
        end_min[index] = np.fmin(end_min[index], end_gap[index])
    for index in np.ndindex(rib_min.shape):
        rib_min[index] = np.fmin(rib_min[index], rib_gap[index])
    for j in range(count):
        for kind in range(3):
            if dry[j, kind] > 0.0 and last[j, kind] == 0.0:
                events[kind] += 1
    _copy(dry, last)


@njit(cache=True)
def _copy(source, target):
    """``target[...] = source``, element by element (see :func:`_observe`)."""
    for index in np.ndindex(source.shape):
        target[index] = source[index]


def scratch(count, geometry):
    """The arrays :func:`derivatives` writes into (after ``dry``, ``shares``), for
    ``count`` rollers and the elements ``geometry``."""
    _, arc_theta, arc_z, _, face_r, face_phi, _ = geometry
    face = (count, 2, face_r.size, face_phi.size)
    return (np.zeros((count, arc_theta.size, arc_z.size)), np.zeros(face), np.zeros(face),
            np.zeros((count, 3)), np.zeros((count, 8)))


@njit(cache=True)
def _accumulators(times, state, record):
    """The samples and the element extremes of a run, before its first sample."""
    arc_force, end_gap, rib_gap, dry, _ = record
    return (np.full((times.size, state.size), np.nan), np.zeros_like(arc_force),
            np.full(end_gap.shape, np.nan), np.full(rib_gap.shape, np.nan),
            np.zeros_like(dry), np.zeros(3))


@njit(cache=True)
def integrate(state, times, p, count, geometry, record, settled_from, rtol, atol, max_steps):
    """Dormand-Prince 5(4) with a PI step-size controller (:mod:`models.dormand_prince`),
    each sample time hit by a step; the controller keeps steps near the stability limit
    that the stiff pocket films set.

    Returns the samples ``(times, state)``, the settled samples' element extremes (see
    :func:`_observe`), the contact events, the steps taken and whether it reached the end.
    """
    samples, arc_max, end_min, rib_min, last, events = _accumulators(times, state, record)
    y = state.copy()
    stages = np.empty((7, y.size))
    _copy(derivatives(y, p, count, *geometry, *record, 0.0), stages[0])
    t, h, steps, last_norm = times[0], FIRST_STEP, 0, 1e-4
    _copy(y, samples[0])
    _observe(y, p, count, geometry, record, t >= settled_from, arc_max, end_min, rib_min,
             last, events)
    for index in range(1, times.size):
        while t < times[index]:
            if steps >= max_steps or h < SMALLEST_STEP:
                return samples, arc_max, end_min, rib_min, events, steps, False
            step = min(h, times[index] - t)
            for s in range(1, 7):
                trial = stage_argument(y, stages, s, step)
                _copy(derivatives(trial, p, count, *geometry, *record, 0.0), stages[s])
            steps += 1
            accepted, h, last_norm, t = conclude(y, trial, stages, step, rtol, atol, last_norm,
                                                 t, times[index])
            if accepted:
                y = trial
                _normalise(y, count)
                _copy(stages[6], stages[0])
        _copy(y, samples[index])
        _observe(y, p, count, geometry, record, t >= settled_from, arc_max, end_min,
                 rib_min, last, events)
    return samples, arc_max, end_min, rib_min, events, steps, True


@njit(cache=True)
def integrate_fixed(state, times, p, count, geometry, record, settled_from, step):
    """The classical fourth-order Runge-Kutta method at a fixed ``step`` (paper 002's
    method, 1e-7 s); the same samples and extremes as :func:`integrate`."""
    samples, arc_max, end_min, rib_min, last, events = _accumulators(times, state, record)
    y = state.copy()
    _copy(y, samples[0])
    _observe(y, p, count, geometry, record, times[0] >= settled_from, arc_max, end_min,
             rib_min, last, events)
    steps = 0
    for index in range(1, times.size):
        count_steps = max(1, int(np.round((times[index] - times[index - 1]) / step)))
        h = (times[index] - times[index - 1]) / count_steps
        for _ in range(count_steps):
            k1 = derivatives(y, p, count, *geometry, *record, 0.0)
            k2 = derivatives(y + 0.5 * h * k1, p, count, *geometry, *record, 0.0)
            k3 = derivatives(y + 0.5 * h * k2, p, count, *geometry, *record, 0.0)
            k4 = derivatives(y + h * k3, p, count, *geometry, *record, 0.0)
            y = y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
            steps += 1
            if not np.all(np.isfinite(y)):  # unstable at this step: stop before it overflows
                return samples, arc_max, end_min, rib_min, events, steps, False
            _normalise(y, count)
        _copy(y, samples[index])
        _observe(y, p, count, geometry, record, times[index] >= settled_from, arc_max,
                 end_min, rib_min, last, events)
    return samples, arc_max, end_min, rib_min, events, steps, True
