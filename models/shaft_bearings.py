"""A shaft on rolling bearings: the coupled nonlinear equilibrium of the shaft's beam
elements (:mod:`models.shaft`) and each bearing's own force-displacement law.

A bearing support takes the shaft's displacement and tilt at its position as its inner
ring's (the outer ring held in a rigid housing) and answers with the loads its rolling
elements carry and their tangent stiffness, as its own model computes them; the equilibrium
``K_shaft U + sum_b f_b(U_b) = F`` is solved by Newton's method with that analytic tangent.
The shaft is linear: its degrees of freedom away from the bearings are condensed out
(static condensation), so Newton's method iterates on the bearings' displacements alone, for
many load cases at once.
"""
from __future__ import annotations

import numpy as np

from .ball import (MAX_APPROACH_PER_DIAMETER, MAX_CONTACT_PRESSURE, BallRings,
                   raceway_contacts, series_constant)
from .contact import (APPROACH_LIMIT, ROLLER_PRESSURE_LIMIT, effective_modulus,
                      line_contact_pressure)
from .life import ball_bearing_reference_life, roller_bearing_reference_life
from .shaft import NODE_DOFS, assemble_shaft, banded_solve, node_at, weight_loads

#: Newton's tolerance on the residual, relative to the loads.
_TOLERANCE = 1e-10
_MAX_ITERATIONS = 100
#: Levenberg-Marquardt's damping where Newton's step first fails, and beyond which a case
#: has failed, relative to the shaft's own stiffness.
_FIRST_DAMPING, _LAST_DAMPING = 1e-6, 1e3


def case_rows(displacement, count: int, cases=None):
    """A bearing's ``displacement`` as ``(n, 5)`` and the row of each of its cases among the
    bearing's ``count`` sets of values: the first for all where it has one, else ``cases``
    (by default each case its own)."""
    displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
    if count == 1:
        return displacement, np.zeros(len(displacement), dtype=np.int64)
    if cases is None:
        cases = np.arange(len(displacement))
    return displacement, np.asarray(cases, dtype=np.int64)


class BallSupport:
    """A ball bearing as a shaft's support, from the inputs :func:`models.ball.ball_5dof`
    takes (SI, each one value or one per load case of a batch of ``cases``, the ball count
    and geometry one for all): the loads its balls carry at a displacement of its inner
    ring, and their stiffness (paper 001, eq. 6-9), in the shaft's degrees of freedom."""

    def __init__(self, ball_count, ball_diameter, pitch_diameter, contact_angle,
                 inner_curvature_ratio=0.52, outer_curvature_ratio=0.53, clearance=0.0,
                 youngs_modulus=207e9, poisson_ratio=0.3, contact_constant=None,
                 geometry="jones", pressure_limit=MAX_CONTACT_PRESSURE, cases=1):
        (ball_diameter, pitch_diameter, contact_angle, inner_curvature_ratio,
         outer_curvature_ratio, clearance) = (np.atleast_1d(np.asarray(v, dtype=float)) for v in (
             ball_diameter, pitch_diameter, contact_angle, inner_curvature_ratio,
             outer_curvature_ratio, clearance))
        inner, outer = raceway_contacts(ball_diameter, pitch_diameter, contact_angle,
                                        inner_curvature_ratio, outer_curvature_ratio,
                                        youngs_modulus, poisson_ratio)
        if contact_constant is None:
            contact_constant = series_constant(inner["contact_constant"],
                                               outer["contact_constant"])
        distance = (inner_curvature_ratio + outer_curvature_ratio - 1.0) * ball_diameter
        radius = (0.5 * pitch_diameter
                  + (inner_curvature_ratio - 0.5) * ball_diameter * np.cos(contact_angle))
        # What ball_5dof's validity takes: a ball's pressure per N^(1/3), the limits.
        (self.unit_pressure, self.pressure_limit, self.distance, self.approach_limit,
         self.angled, radius, half_clearance, constant, contact_angle) = np.broadcast_arrays(
            np.maximum(inner["max_pressure"], outer["max_pressure"]), pressure_limit, distance,
            MAX_APPROACH_PER_DIAMETER * ball_diameter, contact_angle > 0.0, radius,
            0.5 * clearance, np.asarray(contact_constant, dtype=float), contact_angle,
            np.zeros(cases))[:-1]
        self.count = self.distance.size
        # What ISO/TS 16281's reference life takes besides the ball loads.
        self.geometry = np.broadcast_arrays(ball_diameter, pitch_diameter, contact_angle,
                                            inner_curvature_ratio, outer_curvature_ratio,
                                            np.zeros(self.count))[:-1]
        # Tilts scaled by the radius of the inner grooves' centres, as ball_5dof solves.
        self.scale = np.stack(np.broadcast_arrays(1.0, 1.0, 1.0, radius, radius), axis=-1)
        self.rings = BallRings(int(ball_count), self.distance, contact_angle, half_clearance,
                               constant, geometry)

    def _rows(self, displacement, cases):
        return case_rows(displacement, self.count, cases)

    def loads(self, displacement, cases=None):
        """Loads ``(n, 5)`` [N, N m] the balls carry at the inner ring's ``displacement``
        ``(n, 5)`` [m, rad] in the load ``cases`` (rows of the bearing's values), and their
        stiffness ``(n, 5, 5)``."""
        displacement, rows = self._rows(displacement, cases)
        scale = self.scale[rows]
        reaction, stiffness = self.rings.reaction_and_stiffness(displacement * scale, rows)
        return reaction * scale, stiffness * scale[:, :, None] * scale[:, None, :]

    def largest_pressure(self, displacement, cases=None):
        """The largest maximum Hertz pressure [Pa] of the balls at each ``displacement``
        ``(n, 5)`` (their larger contact, inner or outer)."""
        displacement, rows = self._rows(displacement, cases)
        load = self.rings.contacts(displacement * self.scale[rows], rows)[1]
        return self.unit_pressure[rows] * np.cbrt(load.max(axis=-1))

    def reference_life(self, displacement, rating, cases=None):
        """ISO/TS 16281's reference rating life L10r [10^6 revolutions] of the inner ring
        rotating under the ball loads at ``displacement`` ``(n, 5)``, with the dynamic load
        ``rating`` [N] (one, or one per case); infinite without load."""
        displacement, rows = self._rows(displacement, cases)
        load = self.rings.contacts(displacement * self.scale[rows], rows)[1]
        diameter, pitch, angle, inner, outer = (value[rows] for value in self.geometry)
        with np.errstate(divide="ignore", invalid="ignore"):
            return ball_bearing_reference_life(load, rating, diameter, pitch, angle, inner,
                                               outer)

    def outside_validity(self, displacement, cases=None):
        """Where ``displacement`` ``(n, 5)`` lies outside :func:`models.ball.ball_5dof`'s
        validity: a ball's pressure above the limit or its approach above 1 % of its
        diameter, the ring moved beyond the grooves' centre distance, or a loaded ball of an
        angular contact bearing that has crossed to the other side of its groove."""
        displacement, rows = self._rows(displacement, cases)
        scaled = displacement * self.scale[rows]
        approach, load, _, normal_axial, normal_radial, _ = self.rings.contacts(scaled, rows)
        crossed = self.angled[rows, None] & (load > 0) & (
            np.arctan2(normal_axial, normal_radial) < 0)
        return ((self.unit_pressure[rows] * np.cbrt(load.max(axis=-1))
                 > self.pressure_limit[rows])
                | (approach.max(axis=-1) > self.approach_limit[rows])
                | (np.abs(scaled).max(axis=-1) > self.distance[rows]) | crossed.any(axis=-1))


class RollerSupport:
    """A cylindrical roller bearing as a shaft's support, from the inputs
    :func:`models.cylindrical.crb_radial` takes (SI, each one value or one per load case of a
    batch of ``cases``): the loads and moments its rollers carry at a radial displacement and
    a tilt of the inner ring, and their tangent stiffness; nothing axially (the rings of an NU
    or N bearing slide).

    The rollers are placed from the displacement's direction as crb_radial places them from
    its load's (a roller on that line). The shaft's tilt ``theta = (theta_y, theta_z)`` tilts
    the inner ring across roller ``j`` at azimuth ``psi_j`` by ``m_j = theta_z cos(psi_j) -
    theta_y sin(psi_j)``; each roller takes half of it, as crb_radial's ``misalignment`` has
    it, so both its contacts see a gap falling by ``m_j x / 2`` along it. Roller ``j``'s
    inner contact then carries ``Q_j`` at a moment ``M_j = sum_k q_jk x_k`` of its slices'
    loads, and the bearing the loads ``sum_j Q_j (cos psi_j, sin psi_j)`` and the moments
    ``sum_j M_j (-sin psi_j, cos psi_j)`` about y and z. Its tangent is analytic: each
    roller's two contacts in series (its force balance differentiated), and the rollers'
    turn with the displacement's direction.

    Without a tilt the law is crb_radial's along the displacement ``d`` of length ``delta``:
    the force ``F(delta) d / delta`` derives from a potential, and its tangent ``F' n n^T +
    (F / delta)(I - n n^T)`` is symmetric (``n = d / delta``); the tangent's tilt terms
    are there too, the rollers' resistance to a tilt. With a tilt the rollers' turning with
    ``d`` leaves the tangent unsymmetric. At rest both contacts of a roller are alike and
    carry equal moments; spinning, the roller's own moment balance is not solved (as in
    crb_radial).
    """

    #: Below this radial displacement [m] the direction is taken as y, and the rollers do not
    #: turn with it.
    _CENTRED = 1e-15

    def __init__(self, roller_count, pitch_diameter, roller_diameter, effective_length,
                 clearance=0.0, crown=0.0, crown_profile="logarithmic", slices=60,
                 slice_law="uniform", outer_contact="crowned", speed=0.0,
                 roller_density=7850.0, contact_constant=None, youngs_modulus=207e9,
                 poisson_ratio=0.3, pressure_limit=ROLLER_PRESSURE_LIMIT, cases=1):
        from .cylindrical import roller_set

        (pitch_diameter, roller_diameter, effective_length, clearance, crown,
         self.pressure_limit, modulus, _) = np.broadcast_arrays(
            pitch_diameter, roller_diameter, effective_length, clearance, crown,
            pressure_limit, effective_modulus(youngs_modulus, poisson_ratio), np.zeros(cases))
        self.rollers = roller_set(roller_count, pitch_diameter, roller_diameter,
                                  effective_length, clearance, crown, crown_profile, slices,
                                  slice_law, outer_contact, speed, roller_density,
                                  contact_constant)
        self.count = self.rollers.crown.size
        self.azimuth = 2.0 * np.pi * np.arange(int(roller_count)) / int(roller_count)
        # What crb_radial's pressure and validity take.
        self.length, self.modulus = effective_length, modulus
        self.diameter, self.pitch = roller_diameter, pitch_diameter
        self.curvatures = (2.0 / roller_diameter + 2.0 / (pitch_diameter - roller_diameter),
                           2.0 / roller_diameter - 2.0 / (pitch_diameter + roller_diameter))
        self.approach_limit = APPROACH_LIMIT * roller_diameter
        self._last = None  # the last displacements placed, and what :meth:`_placed` gave

    def _rows(self, count, cases):
        if self.count == 1:
            return np.zeros(count, dtype=np.int64)
        return np.arange(count) if cases is None else np.asarray(cases, dtype=np.int64)

    def _placed(self, displacement, cases, sliced=False):
        """The rollers of each row of ``displacement`` ``(n, 5)`` as it moves and tilts
        their inner ring, solved (``sliced``: every slice kept where it lies, as a moment
        sums them): the roller set (one bearing per row), the rows' cases,
        the radial displacement ``(n,)``, the rollers' azimuths ``psi`` and the ring's tilt
        across them ``m`` ``(n, Z)``, whether every roller converged ``(n,)`` and their
        inner approaches ``(n, Z)`` as :meth:`models.cylindrical._RollerSet.loads` gives
        them."""
        rows = self._rows(len(displacement), cases)
        # A solution's pressure, life and validity are asked at the same displacements.
        key = (displacement.tobytes(), rows.tobytes(), sliced)
        if self._last is not None and self._last[0] == key:
            return self._last[1]
        delta = np.hypot(displacement[:, 1], displacement[:, 2])
        direction = np.where(delta < self._CENTRED, 0.0,
                             np.arctan2(displacement[:, 2], displacement[:, 1]))
        psi = direction[:, None] + self.azimuth
        across = displacement[:, 4, None] * np.cos(psi) - displacement[:, 3, None] * np.sin(psi)
        rollers = self.rollers.tilted(rows, 0.25 * self.length[rows, None] * across, sliced)
        split = np.full(psi.shape + (3,), np.nan)
        roller_load, deflection = np.zeros(psi.shape), np.zeros(psi.shape)
        converged = rollers.loads(np.where(delta < self._CENTRED, 0.0, delta),
                                  np.arange(len(rows)), split, roller_load, deflection)[2]
        placed = rollers, rows, delta, psi, across, converged, deflection
        self._last = key, placed
        return placed

    def _pressures(self, rollers, inner, outer, rows):
        """The largest Hertz line-contact pressure [Pa] of each roller's most loaded slices
        ``(n, Z)``, as :func:`models.cylindrical.crb_radial` forms it."""
        loads = rollers.largest_line_loads(inner, outer, self.length[rows])
        return np.maximum(*(line_contact_pressure(load, curvature[rows, None],
                                                  self.modulus[rows, None])
                            for load, curvature in zip(loads, self.curvatures)))

    def largest_pressure(self, displacement, cases=None):
        """The largest Hertz line-contact pressure [Pa] of the rollers' most loaded slices at
        each ``displacement`` ``(n, 5)``, as :func:`models.cylindrical.crb_radial` forms it."""
        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        rollers, rows, delta, *_, deflection = self._placed(displacement, cases)
        inner, outer = rollers.approaches(delta, deflection)
        return self._pressures(rollers, inner, outer, rows).max(axis=-1)

    def reference_life(self, displacement, rating, cases=None):
        """ISO/TS 16281's reference rating life L10r [10^6 revolutions] of the inner ring
        rotating under the rollers' lamina loads at ``displacement`` ``(n, 5)``, with the
        dynamic load ``rating`` [N], as :func:`models.cylindrical.crb_radial` forms it."""
        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        rollers, rows, delta, *_, deflection = self._placed(displacement, cases)
        inner, outer = rollers.approaches(delta, deflection)
        laminae = rollers.lamina_loads(inner, outer, np.arange(len(rows)))
        with np.errstate(divide="ignore", invalid="ignore"):
            return roller_bearing_reference_life(
                laminae[0], rating, self.diameter[rows], self.pitch[rows],
                outer_lamina_loads=laminae[1], lamina_weights=rollers.gap_count)

    def outside_validity(self, displacement, cases=None):
        """Where ``displacement`` ``(n, 5)`` lies outside crb_radial's validity: a contact's
        pressure above the limit, a roller's approach above APPROACH_LIMIT of its diameter,
        or slices too few to resolve the rollers' crown and tilt."""
        from .cylindrical import SLICING_ERROR_LIMIT

        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        rollers, rows, delta, *_, deflection = self._placed(displacement, cases)
        inner, outer = rollers.approaches(delta, deflection)
        beyond = ((self._pressures(rollers, inner, outer, rows).max(axis=-1)
                   > self.pressure_limit[rows])
                  | ((inner + outer).max(axis=-1) > self.approach_limit[rows]))
        return beyond | (rollers.slicing_error(inner, outer, *(c[rows] for c in self.curvatures),
                                               ~beyond) > SLICING_ERROR_LIMIT)

    def loads(self, displacement, cases=None):
        """Loads ``(n, 5)`` [N, N m] at the inner ring's ``displacement`` ``(n, 5)``, and
        their stiffness ``(n, 5, 5)``: radial forces and tilt moments, and their tangent
        (its tilt terms too where the ring is aligned)."""
        from .cylindrical_balance import tilted_contact_sums  # numba: only when solving

        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        rollers, rows, delta, psi, across, converged, approach = self._placed(
            displacement, cases, sliced=True)
        if rollers.outer_contact != "crowned":
            raise ValueError("a cylindrical roller bearing on a shaft needs outer_contact "
                             "'crowned' (the paper's straight outer contact has no tilt)")
        reach = rollers.total_approach(np.where(delta < self._CENTRED, 0.0, delta),
                                       np.arange(len(rows)))
        sums = np.empty(psi.shape + (2, 6))
        tilted_contact_sums(approach, reach, rollers.crown, rollers.gap_shape, rollers.tilt,
                            rollers.floor, rollers.slice_position, 0.5 * self.length[rows],
                            rollers.constant, rollers.slice_law == "paper", sums)
        (load, inner_slope, inner_tilt, moment, moment_slope, moment_tilt) = np.moveaxis(
            sums[:, :, 0], -1, 0)
        outer_slope, outer_tilt = sums[:, :, 1, 1], sums[:, :, 1, 2]
        # Each roller's force balance Qo(t - a, m) = Qi(a, m) + Fc differentiated along its
        # total approach t and the tilt m across it.
        both = inner_slope + outer_slope
        with np.errstate(divide="ignore", invalid="ignore"):
            share = np.where(both > 0.0, outer_slope / both, 0.0)  # da/dt
            moved = np.where(both > 0.0, (outer_tilt - inner_tilt) / both, 0.0)  # da/dm
        load_by_total, load_by_tilt = inner_slope * share, inner_slope * moved + inner_tilt
        moment_by_total = moment_slope * share
        moment_by_tilt = moment_slope * moved + moment_tilt
        cos, sin = np.cos(psi), np.sin(psi)
        zero = np.zeros_like(cos)
        total_gradient = np.stack([zero, cos, sin, zero, zero], axis=-1)  # dt/dq
        tilt_gradient = np.stack([zero, zero, zero, -sin, cos], axis=-1)  # dm/dq
        loads = (np.einsum("nz,nzi->ni", load, total_gradient)
                 + np.einsum("nz,nzi->ni", moment, tilt_gradient))
        stiffness = (np.einsum("nzi,nzj->nij", total_gradient,
                               load_by_total[..., None] * total_gradient
                               + load_by_tilt[..., None] * tilt_gradient)
                     + np.einsum("nzi,nzj->nij", tilt_gradient,
                                 moment_by_total[..., None] * total_gradient
                                 + moment_by_tilt[..., None] * tilt_gradient))
        # The rollers turn with the displacement's direction (by dpsi = dalpha).
        y, z, theta_y, theta_z = (displacement[:, i, None] for i in range(1, 5))
        total_turn = -y * sin + z * cos
        tilt_turn = -theta_z * sin - theta_y * cos
        turned = (np.einsum("nz,nzi->ni", load_by_total * total_turn + load_by_tilt * tilt_turn,
                            total_gradient)
                  + np.einsum("nz,nzi->ni", load, np.stack([zero, -sin, cos, zero, zero], -1))
                  + np.einsum("nz,nzi->ni",
                              moment_by_total * total_turn + moment_by_tilt * tilt_turn,
                              tilt_gradient)
                  + np.einsum("nz,nzi->ni", moment, np.stack([zero, zero, zero, -cos, -sin],
                                                             -1)))
        off_centre = delta >= self._CENTRED
        with np.errstate(divide="ignore", invalid="ignore"):
            turn = np.where(off_centre[:, None], np.stack(
                [np.zeros_like(delta), -displacement[:, 2], displacement[:, 1],
                 np.zeros_like(delta), np.zeros_like(delta)], axis=-1) / delta[:, None] ** 2, 0.0)
        stiffness += np.einsum("ni,nj->nij", turned, turn)
        failed = ~converged | ~np.isfinite(loads).all(axis=-1)
        loads[failed], stiffness[failed] = np.nan, np.nan
        return loads, stiffness


def solve_shaft_on_bearings(section_lengths, outside_diameters, bores, youngs_modulus,
                            poisson_ratio, bearing_positions, bearings, load_positions, loads,
                            spring_positions=(), spring_stiffness=(), stations=(),
                            typical_displacement=1e-6, compliance_at=(), own_weight=None):
    """The shaft's equilibrium on its bearings (and linear supports), in one load case or in
    a batch of them.

    Parameters
    ----------
    section_lengths, outside_diameters, bores, youngs_modulus, poisson_ratio
        The shaft, as :func:`models.shaft.solve_shaft` takes it.
    bearing_positions : array_like
        ``(B,)`` axial positions of the bearings [m].
    bearings : sequence
        ``B`` supports with a method ``loads(displacement, cases) -> (load, stiffness)`` and
        ``outside_validity(displacement, cases)``, such as :class:`BallSupport` (whose
        values may differ from one load case to the next).
    load_positions, loads : array_like
        ``(L,)`` positions [m] and ``(L, 5)`` forces and moments [N, N m], or ``(n, L, 5)``
        for ``n`` load cases.
    spring_positions, spring_stiffness : array_like
        Linear supports, as :func:`models.shaft.solve_shaft` takes them.
    stations : array_like
        Where the deflection line is reported [m].
    typical_displacement : float
        The bearings' displacement [m] in every direction whose stiffness starts Newton's
        iteration (from the shaft on springs that stiff).
    compliance_at : array_like
        Positions [m] (each a node: a load's, a support's or a station's) where the system's
        compliance is wanted.
    own_weight : tuple or None
        ``(density, gravity)``: the shaft's density [kg/m^3] and the acceleration of gravity
        along x, y, z [m/s^2], each one for all cases or one per case (``(n,)``, ``(n, 3)``);
        the shaft's weight is then a load too (:func:`models.shaft.weight_loads`).

    Returns
    -------
    dict
        With a leading axis of load cases where ``loads`` has one:
        ``bearing_displacement`` ``(B, 5)`` [m, rad]; ``bearing_load`` ``(B, 5)`` [N, N m],
        what the shaft puts on each bearing; ``spring_load`` and ``spring_displacement``
        ``(S, 5)``; ``station_displacement`` ``(P, 5)``; ``nodes`` the nodes' positions [m]
        (one set for all cases) and ``node_displacement`` ``(n, 5)``;
        ``bearing_outside_validity`` ``(B,)``, where a bearing's solution lies outside its
        own model's validity (values kept, as that model keeps them); ``compliance``
        ``(5 C, 5 C)`` [m/N, ...], the tangent compliance among the degrees of freedom of the
        positions ``compliance_at``, five each in order (NaN where a rigid support holds one
        of them); ``converged``: the residual below 1e-10 of the loads (else the values are
        NaN). For one load case also ``stiffness``, the system's tangent matrix on its free
        degrees of freedom, those of ``free`` ``(5 n,)`` (the ones no rigid support holds),
        in their order.
    """
    loads = np.asarray(loads, dtype=float)
    single = loads.ndim == 2
    cases = 1 if single else len(loads)
    loads = loads.reshape((cases,) + loads.shape[-2:])
    springs = np.asarray(spring_stiffness, dtype=float).reshape(-1, NODE_DOFS)
    count = len(bearings)
    shaft = assemble_shaft(section_lengths, outside_diameters, bores, youngs_modulus,
                           poisson_ratio,
                           np.concatenate([np.atleast_1d(spring_positions),
                                           np.atleast_1d(bearing_positions)]),
                           np.concatenate([springs, np.zeros((count, NODE_DOFS))]),
                           load_positions, loads, stations)
    if own_weight is not None:
        density, gravity = own_weight
        shaft.force[...] += weight_loads(section_lengths, outside_diameters, bores,
                                         shaft.nodes, np.broadcast_to(density, (cases,)),
                                         np.broadcast_to(gravity, (cases, 3)))
    free = ~shaft.held
    matrix = shaft.matrix[np.ix_(free, free)]
    force = shaft.force[:, free]
    # Each bearing's free degrees of freedom, and their rows among the free ones.
    row_of = np.cumsum(free) - 1
    dofs = NODE_DOFS * shaft.support_nodes[len(springs):, None] + np.arange(NODE_DOFS)
    taken = free[dofs]  # (B, 5)
    bearing_rows = [row_of[d[t]] for d, t in zip(dofs, taken)]
    inner = np.concatenate(bearing_rows + [np.zeros(0, dtype=np.int64)]).astype(np.int64)
    outer = np.setdiff1d(np.arange(matrix.shape[0]), inner)
    spans = np.cumsum([0] + [len(r) for r in bearing_rows])
    everything = np.arange(cases)

    def bearing_terms(moved, which):
        """What the bearings carry at the condensed displacement ``moved`` of the cases
        ``which``: their force and tangent in the condensed rows, and their loads."""
        carried = np.zeros((len(which), count, NODE_DOFS))
        pushed = np.zeros_like(moved)
        tangent = np.zeros(moved.shape + moved.shape[-1:])
        for index, bearing in enumerate(bearings):
            span, take = slice(spans[index], spans[index + 1]), taken[index]
            whole = np.zeros((len(which), NODE_DOFS))
            whole[:, take] = moved[:, span]
            load, stiffness = bearing.loads(whole, which)
            carried[:, index] = load
            pushed[:, span] = load[:, take]
            tangent[:, span, span] = stiffness[:, take][:, :, take]
        return pushed, tangent, carried

    # Static condensation: the shaft's other degrees of freedom follow the bearings' linearly.
    held_still = matrix[np.ix_(outer, outer)]
    if np.linalg.cond(held_still) < 1e-3 / np.finfo(float).eps:
        follow = banded_solve(held_still, matrix[np.ix_(outer, inner)])
        rest = banded_solve(held_still, force[:, outer].T).T
    else:  # the springs leave the shaft free to move (with its bearings held still)
        follow = np.full((len(outer), len(inner)), np.nan)
        rest = np.full((cases, len(outer)), np.nan)
    condensed = matrix[np.ix_(inner, inner)] - np.einsum("ij,jk->ik",
                                                         matrix[np.ix_(inner, outer)], follow)
    target = force[:, inner] - _each(rest, matrix[np.ix_(inner, outer)])

    def residual(moved, which):
        pushed, tangent, carried = bearing_terms(moved, which)
        return (_each(moved, condensed) + pushed - target[which], condensed + tangent,
                carried)

    scale = np.maximum(np.abs(force).max(axis=1, initial=0.0), 1.0)
    moved = np.full((cases, len(inner)), np.nan) if len(inner) else np.zeros((cases, 0))
    # Start from the shaft on the bearings' stiffness at a typical displacement; a bearing
    # that carries nothing there (its clearance, or its rollers thrown out at speed) at a
    # larger one.
    for typical in typical_displacement * np.array([1.0, 10.0, 100.0]):
        unset = np.flatnonzero(~np.isfinite(moved).all(axis=1))
        if not unset.size:
            break
        _, start, _ = bearing_terms(np.full((unset.size, len(inner)), typical), unset)
        moved[unset] = _solved(condensed + start, target[unset])
    converged = np.zeros(cases, dtype=bool)
    failed = ~np.isfinite(moved).all(axis=1) | ~np.isfinite(rest).all(axis=1)
    # Levenberg-Marquardt's damping of each case's step, raised where Newton's step fails (a
    # bearing that carries nothing gives the shaft no stiffness there), lowered where it
    # succeeds: the diagonal of the shaft's condensed stiffness times it.
    damping = np.zeros(cases)
    diagonal = np.abs(np.diagonal(condensed))
    for _ in range(_MAX_ITERATIONS + 1):
        which = np.flatnonzero(~converged & ~failed)
        if not which.size:
            break
        remaining, tangent, _ = residual(moved[which], which)
        norm = np.linalg.norm(remaining, axis=1)
        done = norm <= _TOLERANCE * scale[which]
        converged[which[done]] = True
        which, remaining, tangent, norm = (v[~done] for v in (which, remaining, tangent, norm))
        step = _solved(tangent + damping[which, None, None] * np.diag(diagonal), -remaining)
        pending = np.isfinite(step).all(axis=1)
        factor = np.ones(len(which))
        for _ in range(20):  # halve each case's step until its residual falls
            if not pending.any():
                break
            trying = np.flatnonzero(pending)
            trial = moved[which[trying]] + factor[trying, None] * step[trying]
            better = np.linalg.norm(residual(trial, which[trying])[0], axis=1) < norm[trying]
            moved[which[trying[better]]] = trial[better]
            pending[trying[better]] = False
            factor[pending] *= 0.5
        stuck = pending | ~np.isfinite(step).all(axis=1)
        previous = damping[which]
        damping[which] = np.where(stuck, np.maximum(10.0 * previous, _FIRST_DAMPING),
                                  0.1 * previous)
        failed[which[stuck & (damping[which] > _LAST_DAMPING)]] = True
    _, tangent, carried = residual(moved, everything)
    displacement = np.zeros((cases, matrix.shape[0]))
    displacement[:, inner] = moved
    displacement[:, outer] = rest - _each(moved, follow)
    whole = np.zeros((cases, shaft.matrix.shape[0]))
    whole[:, free] = displacement
    whole[~converged], carried[~converged] = np.nan, np.nan
    compliance = _compliance(shaft, free, row_of, inner, outer, held_still, follow, tangent,
                             compliance_at)
    compliance[~converged] = np.nan
    by_node = whole.reshape(cases, -1, NODE_DOFS)
    at_bearings = by_node[:, shaft.support_nodes[len(springs):]]
    outside = np.zeros((cases, count), dtype=bool)
    for index, bearing in enumerate(bearings):
        fine = np.flatnonzero(converged)
        if fine.size:
            outside[fine, index] = bearing.outside_validity(at_bearings[fine, index], fine)
    result = {"bearing_displacement": at_bearings, "bearing_outside_validity": outside,
              "bearing_load": carried,
              "spring_load": shaft.support_loads(whole)[:, :len(springs)],
              "spring_displacement": by_node[:, shaft.support_nodes[:len(springs)]],
              "station_displacement": by_node[:, shaft.station_nodes],
              "node_displacement": by_node, "compliance": compliance, "converged": converged}
    if single:
        result = {key: value[0] for key, value in result.items()}
        result["converged"] = bool(result["converged"])
        result["stiffness"] = matrix.copy()
        result["stiffness"][np.ix_(inner, inner)] += tangent[0] - condensed
    return result | {"nodes": shaft.nodes, "free": free}


def _compliance(shaft, free, row_of, inner, outer, held_still, follow, tangent, positions):
    """The tangent compliance ``(n, 5 C, 5 C)`` among the degrees of freedom at
    ``positions``, from the condensed system: a unit force there moves the bearings by
    ``S^-1 (e_b - F^T e_o)`` (``S``, each case's condensed tangent; ``F``, how the shaft
    follows its bearings) and the rest of the shaft by ``K_oo^-1 e_o - F u_b``."""
    cases = len(tangent)
    nodes = node_at(shaft.nodes, np.atleast_1d(np.asarray(positions, dtype=float)))
    dofs = (NODE_DOFS * nodes[:, None] + np.arange(NODE_DOFS)).ravel()
    compliance = np.full((cases, dofs.size, dofs.size), np.nan)
    if not dofs.size or not free[dofs].all() or not np.isfinite(follow).all():
        return compliance  # a rigid support's node has no finite compliance
    rows = row_of[dofs]
    unit = np.zeros((free.sum(), rows.size))
    unit[rows, np.arange(rows.size)] = 1.0
    moved = np.zeros((cases, free.sum(), rows.size))
    if inner.size:
        pushed = unit[inner] - np.einsum("ji,jk->ik", follow, unit[outer])
        moved[:, inner] = np.linalg.solve(tangent, np.broadcast_to(
            pushed, (cases,) + pushed.shape))
    moved[:, outer] = banded_solve(held_still, unit[outer])[None] - np.einsum(
        "ij,njk->nik", follow, moved[:, inner])
    compliance[:] = moved[:, rows]
    return compliance


def _each(vectors, matrix):
    """``matrix`` times each of ``vectors`` ``(n, k)``, each case's sums in one order
    whatever the batch (a matrix product's blocking would depend on ``n``)."""
    return np.einsum("ij,nj->ni", matrix, vectors)


def _solved(matrices, vectors):
    """``matrices`` ``(n, m, m)`` solved for ``vectors`` ``(n, m)``, NaN where a matrix is
    singular."""
    try:
        return np.linalg.solve(matrices, vectors[..., None])[..., 0]
    except np.linalg.LinAlgError:  # one singular matrix: each case on its own
        solved = np.full(vectors.shape, np.nan)
        for case, (matrix, vector) in enumerate(zip(matrices, vectors)):
            try:
                solved[case] = np.linalg.solve(matrix, vector)
            except np.linalg.LinAlgError:
                pass
        return solved
