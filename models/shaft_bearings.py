"""A shaft on rolling bearings: the coupled nonlinear equilibrium of the shaft's beam
elements (:mod:`models.shaft`) and each bearing's own force-displacement law.

A bearing support takes the shaft's displacement and tilt at its position as its inner
ring's (the outer ring held in a rigid housing) and answers with the loads its rolling
elements carry and their tangent stiffness, as its own model computes them; the equilibrium
``K_shaft U + sum_b f_b(U_b) = F`` is solved by Newton's method with that analytic tangent.
"""
from __future__ import annotations

import numpy as np

from .ball import (MAX_APPROACH_PER_DIAMETER, MAX_CONTACT_PRESSURE, BallRings,
                   raceway_contacts, series_constant)
from .shaft import NODE_DOFS, assemble_shaft

#: Newton's tolerance on the residual, relative to the loads.
_TOLERANCE = 1e-10
_MAX_ITERATIONS = 100


class BallSupport:
    """A ball bearing as a shaft's support, from the inputs :func:`models.ball.ball_5dof`
    takes (SI): the loads its balls carry at a displacement of its inner ring, and their
    stiffness (paper 001, eq. 6-9), in the shaft's degrees of freedom."""

    def __init__(self, ball_count, ball_diameter, pitch_diameter, contact_angle,
                 inner_curvature_ratio=0.52, outer_curvature_ratio=0.53, clearance=0.0,
                 youngs_modulus=207e9, poisson_ratio=0.3, contact_constant=None,
                 geometry="jones", pressure_limit=MAX_CONTACT_PRESSURE):
        inner, outer = raceway_contacts(ball_diameter, pitch_diameter, contact_angle,
                                        inner_curvature_ratio, outer_curvature_ratio,
                                        youngs_modulus, poisson_ratio)
        if contact_constant is None:
            contact_constant = series_constant(inner["contact_constant"],
                                               outer["contact_constant"])
        distance = (inner_curvature_ratio + outer_curvature_ratio - 1.0) * ball_diameter
        # What ball_5dof's validity takes: a ball's pressure per N^(1/3), the limits.
        self.unit_pressure = float(np.maximum(inner["max_pressure"], outer["max_pressure"]))
        self.pressure_limit, self.distance = pressure_limit, float(distance)
        self.approach_limit = MAX_APPROACH_PER_DIAMETER * ball_diameter
        self.angled = float(contact_angle) > 0.0
        radius = (0.5 * pitch_diameter
                  + (inner_curvature_ratio - 0.5) * ball_diameter * np.cos(contact_angle))
        # Tilts scaled by the radius of the inner grooves' centres, as ball_5dof solves.
        self.scale = np.array([1.0, 1.0, 1.0, radius, radius])
        self.rings = BallRings(int(ball_count), np.atleast_1d(float(distance)),
                               np.atleast_1d(float(contact_angle)),
                               np.atleast_1d(0.5 * float(clearance)),
                               np.atleast_1d(float(np.asarray(contact_constant))), geometry)

    def loads(self, displacement):
        """Loads ``(n, 5)`` [N, N m] the balls carry at the inner ring's ``displacement``
        ``(n, 5)`` [m, rad], and their stiffness ``(n, 5, 5)``."""
        displacement = np.atleast_2d(np.asarray(displacement, dtype=float))
        scaled = displacement * self.scale
        index = np.zeros(len(scaled), dtype=np.int64)
        load = self.rings.reaction(scaled, index) * self.scale
        stiffness = (self.rings.stiffness(scaled, index) * self.scale[:, None]
                     * self.scale[None, :])
        return load, stiffness

    def largest_pressure(self, displacement):
        """The largest maximum Hertz pressure [Pa] of the balls at each ``displacement``
        ``(n, 5)`` (their larger contact, inner or outer)."""
        scaled = np.atleast_2d(np.asarray(displacement, dtype=float)) * self.scale
        load = self.rings.contacts(scaled, np.zeros(len(scaled), dtype=np.int64))[1]
        return self.unit_pressure * np.cbrt(load.max(axis=-1))

    def outside_validity(self, displacement):
        """Where ``displacement`` ``(n, 5)`` lies outside :func:`models.ball.ball_5dof`'s
        validity: a ball's pressure above the limit or its approach above 1 % of its
        diameter, the ring moved beyond the grooves' centre distance, or a loaded ball of an
        angular contact bearing that has crossed to the other side of its groove."""
        scaled = np.atleast_2d(np.asarray(displacement, dtype=float)) * self.scale
        index = np.zeros(len(scaled), dtype=np.int64)
        approach, load, _, normal_axial, normal_radial, _ = self.rings.contacts(scaled, index)
        crossed = self.angled & (load > 0) & (np.arctan2(normal_axial, normal_radial) < 0)
        return ((self.unit_pressure * np.cbrt(load.max(axis=-1)) > self.pressure_limit)
                | (approach.max(axis=-1) > self.approach_limit)
                | (np.abs(scaled).max(axis=-1) > self.distance) | crossed.any(axis=-1))


def solve_shaft_on_bearings(section_lengths, outside_diameters, bores, youngs_modulus,
                            poisson_ratio, bearing_positions, bearings, load_positions, loads,
                            spring_positions=(), spring_stiffness=(), stations=(),
                            typical_displacement=1e-6):
    """The shaft's equilibrium on its bearings (and linear supports) under one load case.

    Parameters
    ----------
    section_lengths, outside_diameters, bores, youngs_modulus, poisson_ratio
        The shaft, as :func:`models.shaft.solve_shaft` takes it.
    bearing_positions : array_like
        ``(B,)`` axial positions of the bearings [m].
    bearings : sequence
        ``B`` supports with a method ``loads(displacement) -> (load, stiffness)``, such as
        :class:`BallSupport`.
    load_positions, loads : array_like
        ``(L,)`` positions [m] and ``(L, 5)`` forces and moments [N, N m].
    spring_positions, spring_stiffness : array_like
        Linear supports, as :func:`models.shaft.solve_shaft` takes them.
    stations : array_like
        Where the deflection line is reported [m].
    typical_displacement : float
        The bearings' displacement [m] in every direction whose stiffness starts Newton's
        iteration (from the shaft on springs that stiff).

    Returns
    -------
    dict
        ``bearing_displacement`` ``(B, 5)`` [m, rad]; ``bearing_load`` ``(B, 5)`` [N, N m],
        what the shaft puts on each bearing; ``spring_load`` and ``spring_displacement``
        ``(S, 5)``;
        ``station_displacement`` ``(P, 5)``; ``nodes`` the nodes' positions [m] and
        ``node_displacement`` ``(n, 5)``; ``bearing_outside_validity`` ``(B,)``, where a
        bearing's solution lies outside its own model's validity (values kept, as that
        model keeps them); ``stiffness``, the system's tangent matrix on its
        free degrees of freedom, those of ``free`` ``(5 n,)`` (the ones no rigid support
        holds), in their order; ``converged``: the residual below 1e-10 of the loads (else
        the values are NaN).
    """
    springs = np.asarray(spring_stiffness, dtype=float).reshape(-1, NODE_DOFS)
    count = len(bearings)
    shaft = assemble_shaft(section_lengths, outside_diameters, bores, youngs_modulus,
                           poisson_ratio,
                           np.concatenate([np.atleast_1d(spring_positions),
                                           np.atleast_1d(bearing_positions)]),
                           np.concatenate([springs, np.zeros((count, NODE_DOFS))]),
                           load_positions, np.asarray(loads, dtype=float)[None], stations)
    free = ~shaft.held
    shaft_matrix = shaft.matrix[np.ix_(free, free)]
    force = shaft.force[0, free]
    # Each bearing's degrees of freedom, and their rows among the free ones.
    bearing_dofs = NODE_DOFS * shaft.support_nodes[len(springs):, None] + np.arange(NODE_DOFS)
    row_of = np.cumsum(free) - 1

    def full(free_displacement):
        whole = np.zeros(shaft.matrix.shape[0])
        whole[free] = free_displacement
        return whole

    def system(free_displacement):
        """Residual, tangent and each bearing's loads at a displacement."""
        whole = full(free_displacement)
        residual = shaft_matrix @ free_displacement - force
        tangent = shaft_matrix.copy()
        carried = np.zeros((count, NODE_DOFS))
        for index, (bearing, dofs) in enumerate(zip(bearings, bearing_dofs)):
            load, stiffness = bearing.loads(whole[dofs][None, :])
            carried[index] = load[0]
            take = free[dofs]
            rows = row_of[dofs[take]]
            residual[rows] += load[0][take]
            tangent[np.ix_(rows, rows)] += stiffness[0][np.ix_(take, take)]
        return residual, tangent, carried

    start_matrix = shaft_matrix.copy()
    for bearing, dofs in zip(bearings, bearing_dofs):
        _, stiffness = bearing.loads(np.full((1, NODE_DOFS), typical_displacement))
        take = free[dofs]
        rows = row_of[dofs[take]]
        start_matrix[np.ix_(rows, rows)] += stiffness[0][np.ix_(take, take)]
    try:
        displacement = np.linalg.solve(start_matrix, force)
    except np.linalg.LinAlgError:
        displacement = np.zeros_like(force)
    scale = max(float(np.abs(force).max(initial=0.0)), 1.0)
    residual, tangent, carried = system(displacement)
    converged = False
    for _ in range(_MAX_ITERATIONS):
        norm = np.linalg.norm(residual)
        if norm <= _TOLERANCE * scale:
            converged = True
            break
        try:
            step = np.linalg.solve(tangent, -residual)
        except np.linalg.LinAlgError:
            break
        factor = 1.0
        while factor > 1e-6:  # halve the step until the residual falls
            trial = displacement + factor * step
            trial_state = system(trial)
            if np.linalg.norm(trial_state[0]) < norm:
                break
            factor *= 0.5
        else:
            break
        displacement = trial
        residual, tangent, carried = trial_state
    whole = full(displacement)
    if not converged:
        whole[:], carried[:] = np.nan, np.nan
    by_node = whole.reshape(-1, NODE_DOFS)
    at_bearings = by_node[shaft.support_nodes[len(springs):]]
    outside = np.array([bool(bearing.outside_validity(place[None])[0]) if converged else False
                        for bearing, place in zip(bearings, at_bearings)], dtype=bool)
    return {"bearing_displacement": at_bearings, "bearing_outside_validity": outside,
            "bearing_load": carried,
            "spring_load": shaft.support_loads(whole)[:len(springs)],
            "spring_displacement": by_node[shaft.support_nodes[:len(springs)]],
            "station_displacement": by_node[shaft.station_nodes], "nodes": shaft.nodes,
            "node_displacement": by_node, "stiffness": tangent, "free": free,
            "converged": converged}
