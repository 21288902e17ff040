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
    batch of ``cases``): in each radial direction the load and stiffness that model gives at
    the inner ring's radial displacement, as a vector along it; nothing axially (the rings of
    an NU or N bearing slide) nor against a tilt (crb_radial takes a misalignment, but gives
    no moment for it).

    The radial law ``F(delta)`` is the bearing's along the displacement ``d`` of length
    ``delta``, the rollers placed from its direction as crb_radial places them from its
    load's: the force ``F(delta) d / delta`` derives from a potential, and its tangent
    ``F' n n^T + (F / delta)(I - n n^T)`` is symmetric (``n = d / delta``).
    """

    #: Below this radial displacement [m] the direction is taken as y and F / delta as F'.
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
        # What crb_radial's pressure and validity take.
        self.length, self.modulus = effective_length, modulus
        self.diameter, self.pitch = roller_diameter, pitch_diameter
        self.curvatures = (2.0 / roller_diameter + 2.0 / (pitch_diameter - roller_diameter),
                           2.0 / roller_diameter - 2.0 / (pitch_diameter + roller_diameter))
        self.approach_limit = APPROACH_LIMIT * roller_diameter

    def _rows(self, count, cases):
        if self.count == 1:
            return np.zeros(count, dtype=np.int64)
        return np.arange(count) if cases is None else np.asarray(cases, dtype=np.int64)

    def radial(self, displacement, cases=None):
        """The radial load [N] and stiffness [N/m] at each radial ``displacement`` [m] of
        the load ``cases``, where every roller's balance converged, and each roller's inner
        approach (``(count, Z)``, the rows of those cases filled)."""
        rows = self._rows(len(displacement), cases)
        shape = self.rollers.cos.shape
        split = np.full(shape + (3,), np.nan)
        roller_load, deflection = np.zeros(shape), np.zeros(shape)
        force, slope, converged = self.rollers.loads(
            np.ascontiguousarray(displacement, dtype=float), np.ascontiguousarray(rows), split,
            roller_load, deflection)
        return force, slope, converged, deflection

    def _contacts(self, displacement, cases):
        """Each contact's approaches at the radial displacements of the load ``cases``, as
        crb_radial forms its pressure and validity from them (one case at a time where the
        bearing has one set of values for several)."""
        delta = np.hypot(displacement[:, 1], displacement[:, 2])
        if self.count == 1 and len(delta) > 1:
            parts = [self._contacts(row[None], None) for row in displacement]
            return tuple(np.concatenate(part) for part in zip(*parts))
        rows = self._rows(len(delta), cases)
        every = np.zeros(self.count)
        every[rows] = delta
        deflection = self.radial(every, np.arange(self.count))[3]
        inner, outer = self.rollers.approaches(every, deflection)
        return inner[rows], outer[rows], rows

    def largest_pressure(self, displacement, cases=None):
        """The largest Hertz line-contact pressure [Pa] of the rollers' most loaded slices at
        each ``displacement`` ``(n, 5)``, as :func:`models.cylindrical.crb_radial` forms it."""
        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        inner, outer, rows = self._contacts(displacement, cases)
        every = tuple(np.zeros((self.count,) + inner.shape[1:]) for _ in range(2))
        every[0][rows], every[1][rows] = inner, outer
        loads = self.rollers.largest_line_loads(*every, self.length)
        return np.maximum(*(line_contact_pressure(load[rows], curvature[rows, None],
                                                  self.modulus[rows, None]).max(axis=-1)
                            for load, curvature in zip(loads, self.curvatures)))

    def reference_life(self, displacement, rating, cases=None):
        """ISO/TS 16281's reference rating life L10r [10^6 revolutions] of the inner ring
        rotating under the rollers' lamina loads at ``displacement`` ``(n, 5)``, with the
        dynamic load ``rating`` [N], as :func:`models.cylindrical.crb_radial` forms it."""
        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        inner, outer, rows = self._contacts(displacement, cases)
        laminae = self.rollers.lamina_loads(inner, outer, rows)
        with np.errstate(divide="ignore", invalid="ignore"):
            return roller_bearing_reference_life(
                laminae[0], rating, self.diameter[rows], self.pitch[rows],
                outer_lamina_loads=laminae[1], lamina_weights=self.rollers.gap_count)

    def outside_validity(self, displacement, cases=None):
        """Where ``displacement`` ``(n, 5)`` lies outside crb_radial's validity: a contact's
        pressure above the limit, or a roller's approach above APPROACH_LIMIT of its
        diameter."""
        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        inner, outer, rows = self._contacts(displacement, cases)
        return ((self.largest_pressure(displacement, cases) > self.pressure_limit[rows])
                | ((inner + outer).max(axis=-1) > self.approach_limit[rows]))

    def loads(self, displacement, cases=None):
        """Loads ``(n, 5)`` [N, N m] at the inner ring's ``displacement`` ``(n, 5)``, and
        their stiffness ``(n, 5, 5)``: radial terms only."""
        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        radial = displacement[:, 1:3]
        delta = np.hypot(radial[:, 0], radial[:, 1])
        centred = delta < self._CENTRED
        direction = np.where(centred[:, None], [1.0, 0.0],
                             radial / np.where(centred, 1.0, delta)[:, None])
        force, slope, converged, _ = self.radial(np.where(centred, 0.0, delta), cases)
        secant = np.where(centred, slope, force / np.where(centred, 1.0, delta))
        along = np.einsum("ni,nj->nij", direction, direction)
        load = np.zeros_like(displacement)
        stiffness = np.zeros(displacement.shape + (5,))
        load[:, 1:3] = force[:, None] * direction
        stiffness[:, 1:3, 1:3] = (slope[:, None, None] * along
                                  + secant[:, None, None] * (np.eye(2) - along))
        load[~converged], stiffness[~converged] = np.nan, np.nan
        return load, stiffness


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
