"""A stepped shaft as Timoshenko beam finite elements, on supports and under loads.

The shaft lies along x. Each node has the five degrees of freedom of a bearing's inner ring,
in the order of :data:`models.ball.DOFS`: axial displacement ``u``, radial displacements ``v``
(y) and ``w`` (z), and tilts ``theta_y``, ``theta_z`` about y and z (right-handed, so that the
slopes of the deflection line are ``dv/dx = theta_z`` and ``dw/dx = -theta_y``); torsion is
left out. Each element is a prismatic stretch of one section between two nodes: a bar for the
axial displacement and a Timoshenko beam in each bending plane, whose cubic deflection and
linear rotation make it exact for loads at its nodes [1]_. Nodes sit at the ends of the
sections, at every support and load, and at the stations where the deflection line is
reported, so the solution is exact for point loads on a linear shaft (no mesh to refine).

Supports here are linear springs, one stiffness per degree of freedom (rigid as a limit);
the loads are forces and moments at positions.

References
----------
.. [1] J. S. Przemieniecki, Theory of Matrix Structural Analysis, McGraw-Hill (1968),
   sec. 5.6; Z. Friedman and J. B. Kosmatka, "An improved two-node Timoshenko beam finite
   element", Computers & Structures 47 (1993) 473-481, doi:10.1016/0045-7949(93)90243-7.
.. [2] G. R. Cowper, "The shear coefficient in Timoshenko's beam theory", Journal of Applied
   Mechanics 33 (1966) 335-340, doi:10.1115/1.3625046.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Degrees of freedom per node, as :data:`models.ball.DOFS` names them.
NODE_DOFS = 5
#: Nodes closer than this fraction of the shaft's length are one node.
_MERGE = 1e-12


def cowper_shear_coefficient(poisson_ratio, bore_ratio=0.0):
    """Shear coefficient ``kappa`` of a circular tube [2]_, Table 1:
    ``6 (1 + nu) (1 + m^2)^2 / ((7 + 6 nu) (1 + m^2)^2 + (20 + 12 nu) m^2)`` with ``m`` the
    bore over the outside diameter (a solid shaft: ``6 (1 + nu) / (7 + 6 nu)``)."""
    m2 = np.asarray(bore_ratio, dtype=float) ** 2
    nu = np.asarray(poisson_ratio, dtype=float)
    return 6 * (1 + nu) * (1 + m2) ** 2 / ((7 + 6 * nu) * (1 + m2) ** 2 + (20 + 12 * nu) * m2)


def bending_element_stiffness(length, bending_stiffness, shear_stiffness):
    """Stiffness matrix ``(..., 4, 4)`` of a Timoshenko beam element in one plane [1]_, for
    the deflections and slopes ``(v1, v1', v2, v2')`` of its ends.

    ``EI / ((1 + Phi) L^3) [[12, 6L, -12, 6L], [6L, (4 + Phi) L^2, -6L, (2 - Phi) L^2], ...]``
    with ``Phi = 12 EI / (kappa G A L^2)``; ``Phi = 0`` is Euler-Bernoulli's.

    Parameters
    ----------
    length : array_like
        ``L`` [m].
    bending_stiffness : array_like
        ``EI`` [N m^2].
    shear_stiffness : array_like
        ``kappa G A`` [N]; ``inf`` for a beam rigid in shear.
    """
    length, ei, shear = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (
        length, bending_stiffness, shear_stiffness)))
    phi = 12.0 * ei / (shear * length ** 2)
    s = ei / ((1.0 + phi) * length ** 3)
    L = length
    rows = [[12.0 + 0 * L, 6 * L, -12.0 + 0 * L, 6 * L],
            [6 * L, (4 + phi) * L ** 2, -6 * L, (2 - phi) * L ** 2],
            [-12.0 + 0 * L, -6 * L, 12.0 + 0 * L, -6 * L],
            [6 * L, (2 - phi) * L ** 2, -6 * L, (4 + phi) * L ** 2]]
    return s[..., None, None] * np.moveaxis(np.array(rows), (0, 1), (-2, -1))


def shaft_nodes(section_lengths, positions=()):
    """The nodes' axial positions [m]: both ends, every section boundary and ``positions``
    (supports, loads, stations), sorted, coincident ones merged. A position off the shaft is
    a ``ValueError``."""
    ends = np.concatenate([[0.0], np.cumsum(np.asarray(section_lengths, dtype=float))])
    positions = np.asarray(positions, dtype=float).ravel()
    total = ends[-1]
    if positions.size and ((positions < -_MERGE * total).any()
                           or (positions > total * (1 + _MERGE)).any()):
        raise ValueError(f"a position lies off the shaft (0 to {total * 1e3:g} mm)")
    candidates = np.sort(np.concatenate([ends, np.clip(positions, 0.0, total)]))
    keep = np.concatenate([[True], np.diff(candidates) > _MERGE * total])
    return candidates[keep]


def node_at(nodes, positions):
    """Index of the node at each of ``positions`` (the nearest)."""
    return np.abs(np.asarray(nodes)[:, None] - np.atleast_1d(positions)[None, :]).argmin(0)


def shaft_stiffness(section_lengths, outside_diameters, bores, youngs_modulus, poisson_ratio,
                    nodes):
    """The free shaft's stiffness matrix ``(5 n, 5 n)`` on ``nodes`` [N/m, N, N m/rad].

    Parameters
    ----------
    section_lengths, outside_diameters, bores : array_like
        Per section [m] (a bore of 0: solid).
    youngs_modulus, poisson_ratio : float
        ``E`` [Pa] and ``nu`` [-] of the shaft.
    nodes : array_like
        Axial positions of the nodes [m], from :func:`shaft_nodes`.
    """
    nodes = np.asarray(nodes, dtype=float)
    ends = np.concatenate([[0.0], np.cumsum(section_lengths)])
    outside = np.asarray(outside_diameters, dtype=float)
    bore = np.asarray(bores, dtype=float)
    # Each element lies in the section that holds its middle.
    middle = 0.5 * (nodes[:-1] + nodes[1:])
    section = np.clip(np.searchsorted(ends, middle) - 1, 0, len(outside) - 1)
    d, di = outside[section], bore[section]
    area = np.pi / 4 * (d ** 2 - di ** 2)
    inertia = np.pi / 64 * (d ** 4 - di ** 4)
    shear_modulus = youngs_modulus / (2 * (1 + poisson_ratio))
    shear = cowper_shear_coefficient(poisson_ratio, di / d) * shear_modulus * area
    length = np.diff(nodes)
    bending = bending_element_stiffness(length, youngs_modulus * inertia, shear)
    axial = youngs_modulus * area / length
    size = NODE_DOFS * len(nodes)
    matrix = np.zeros((size, size))
    # x-y plane: (v, theta_z); x-z plane: (w, -theta_y), the slope's sign turned.
    planes = ((1, 4, 1.0), (2, 3, -1.0))
    for element in range(len(length)):
        first, second = NODE_DOFS * element, NODE_DOFS * (element + 1)
        bar = np.array([first, second])
        matrix[np.ix_(bar, bar)] += axial[element] * np.array([[1.0, -1.0], [-1.0, 1.0]])
        for deflection, tilt, sign in planes:
            index = np.array([first + deflection, first + tilt, second + deflection,
                              second + tilt])
            turn = np.array([1.0, sign, 1.0, sign])
            matrix[np.ix_(index, index)] += turn[:, None] * bending[element] * turn[None, :]
    return matrix


def weight_loads(section_lengths, outside_diameters, bores, nodes, density, gravity):
    """The shaft's own weight as loads on its nodes ``(..., 5 n)`` [N, N m]: each element's
    ``q = rho A g`` per unit length spread as a uniform load, ``q h / 2`` on each of its
    nodes and the moments ``+-q h^2 / 12`` that go with them (the consistent loads, with which
    the nodes' displacements are exact for a uniform load, shear included [1]_).

    Parameters
    ----------
    section_lengths, outside_diameters, bores, nodes
        As :func:`shaft_stiffness` takes them.
    density : array_like
        ``rho`` [kg/m^3], one per load case ``...``.
    gravity : array_like
        ``(..., 3)`` the acceleration of gravity along x, y and z [m/s^2].
    """
    nodes = np.asarray(nodes, dtype=float)
    ends = np.concatenate([[0.0], np.cumsum(section_lengths)])
    outside, bore = (np.asarray(v, dtype=float) for v in (outside_diameters, bores))
    section = np.clip(np.searchsorted(ends, 0.5 * (nodes[:-1] + nodes[1:])) - 1, 0,
                      len(outside) - 1)
    area = np.pi / 4 * (outside[section] ** 2 - bore[section] ** 2)
    length = np.diff(nodes)
    gravity = np.asarray(gravity, dtype=float)
    per_length = (np.asarray(density, dtype=float)[..., None, None] * area[:, None]
                  * gravity[..., None, :])  # (..., elements, 3)
    loads = np.zeros(gravity.shape[:-1] + (len(nodes), NODE_DOFS))
    half = per_length * length[:, None] / 2
    loads[..., :-1, :3] += half
    loads[..., 1:, :3] += half
    # x-y plane: the slope dv/dx is theta_z; x-z plane: dw/dx is -theta_y.
    for axis, tilt, sign in ((1, 4, 1.0), (2, 3, -1.0)):
        moment = per_length[..., axis] * length ** 2 / 12
        loads[..., :-1, tilt] += sign * moment
        loads[..., 1:, tilt] -= sign * moment
    return loads.reshape(gravity.shape[:-1] + (-1,))


@dataclass(frozen=True)
class AssembledShaft:
    """A shaft's finite-element system on its supports and under its loads."""

    nodes: np.ndarray  #: axial positions of the nodes [m]
    matrix: np.ndarray  #: stiffness ``(5 n, 5 n)``, the finite springs included
    held: np.ndarray  #: the degrees of freedom rigid supports hold ``(5 n,)``
    force: np.ndarray  #: ``(..., 5 n)`` the loads on the nodes, per load case
    support_nodes: np.ndarray  #: each support's node
    support_stiffness: np.ndarray  #: ``(B, 5)`` as given
    station_nodes: np.ndarray  #: each station's node

    def support_loads(self, displacement):
        """What the shaft puts on each support ``(..., B, 5)`` [N, N m] at ``displacement``
        ``(..., 5 n)``: a spring's stiffness times its displacement; on a rigid support's
        held directions, the loads there less what the shaft carries on."""
        at = displacement.reshape(displacement.shape[:-1] + (-1, NODE_DOFS))
        # Each case's sums in one order, whatever the batch (einsum, not a matrix product).
        carried = (self.force - np.einsum("ij,...j->...i", self.matrix, displacement)
                   ).reshape(at.shape)
        springs = self.support_stiffness
        return np.where(np.isinf(springs), carried[..., self.support_nodes, :],
                        np.where(np.isinf(springs), 0.0, springs)
                        * at[..., self.support_nodes, :])


def assemble_shaft(section_lengths, outside_diameters, bores, youngs_modulus, poisson_ratio,
                   support_positions, support_stiffness, load_positions, loads, stations=()):
    """The shaft's system (:class:`AssembledShaft`) from the arguments of
    :func:`solve_shaft`."""
    support_positions = np.atleast_1d(np.asarray(support_positions, dtype=float))
    load_positions = np.atleast_1d(np.asarray(load_positions, dtype=float))
    stations = np.atleast_1d(np.asarray(stations, dtype=float))
    nodes = shaft_nodes(section_lengths,
                        np.concatenate([support_positions, load_positions, stations]))
    matrix = shaft_stiffness(section_lengths, outside_diameters, bores, youngs_modulus,
                             poisson_ratio, nodes)
    springs = np.array(np.broadcast_to(np.asarray(support_stiffness, dtype=float),
                                       (support_positions.size, NODE_DOFS)))
    at_support = node_at(nodes, support_positions)
    if len(set(at_support)) < len(at_support):
        raise ValueError("two supports at one position: give one support its stiffnesses")
    held = np.zeros(matrix.shape[0], dtype=bool)
    for node, stiffness in zip(at_support, springs):
        dofs = NODE_DOFS * node + np.arange(NODE_DOFS)
        rigid = np.isinf(stiffness)
        matrix[dofs[~rigid], dofs[~rigid]] += stiffness[~rigid]
        held[dofs[rigid]] = True
    loads = np.asarray(loads, dtype=float)
    force = np.zeros(loads.shape[:-2] + (matrix.shape[0],))
    for index, node in enumerate(node_at(nodes, load_positions)):
        force[..., NODE_DOFS * node + np.arange(NODE_DOFS)] += loads[..., index, :]
    return AssembledShaft(nodes, matrix, held, force, at_support, springs,
                          node_at(nodes, stations))


def banded_solve(matrix, right):
    """``matrix^-1 right`` for a shaft's matrix, whose nodes couple their neighbours only:
    LAPACK's band solver, in O(n b^2) for a band of ``b``. Its arithmetic, unlike a dense
    solver's blocked factorisation, does not depend on how many threads BLAS runs, and each
    column of ``right`` is solved alike whatever the others: a point's numbers are the same
    in any process and any chunk. ``numpy.linalg.LinAlgError`` where it is singular."""
    from scipy.linalg import solve_banded  # here: a shaft's model needs it, no other

    matrix = np.asarray(matrix, dtype=float)
    rows, columns = np.nonzero(matrix)
    lower = int(max((rows - columns).max(initial=0), 0))
    upper = int(max((columns - rows).max(initial=0), 0))
    size = matrix.shape[0]
    band = np.zeros((lower + upper + 1, size))
    for offset in range(-lower, upper + 1):  # band[upper + i - j, j] = matrix[i, j]
        diagonal = np.diagonal(matrix, offset)
        if offset >= 0:
            band[upper - offset, offset:] = diagonal
        else:
            band[upper - offset, :size + offset] = diagonal
    return solve_banded((lower, upper), band, right, check_finite=False)


def solve_shaft(section_lengths, outside_diameters, bores, youngs_modulus, poisson_ratio,
                support_positions, support_stiffness, load_positions, loads, stations=()):
    """A shaft on linear supports under loads: the displacements and what each support
    carries.

    Parameters
    ----------
    section_lengths, outside_diameters, bores : array_like
        ``(S,)`` per section, from the shaft's left end [m].
    youngs_modulus, poisson_ratio : float
        The shaft's ``E`` [Pa], ``nu`` [-].
    support_positions : array_like
        ``(B,)`` axial positions of the supports [m].
    support_stiffness : array_like
        ``(B, 5)`` each support's stiffness per degree of freedom [N/m, N m/rad] (0: free
        in that direction, ``inf``: rigid).
    load_positions : array_like
        ``(L,)`` axial positions of the loads [m].
    loads : array_like
        ``(..., L, 5)`` forces and moments ``(F_x, F_y, F_z, M_y, M_z)`` [N, N m] of each
        load, for any number of load cases ``...``.
    stations : array_like
        ``(P,)`` axial positions where the deflection line is reported [m].

    Returns
    -------
    dict of numpy.ndarray
        ``support_displacement`` ``(..., B, 5)`` [m, rad]; ``support_load`` ``(..., B, 5)``
        the forces and moments the shaft puts on each support [N, N m] (they balance the
        loads); ``station_displacement`` ``(..., P, 5)`` [m, rad]; ``solvable``: False where
        the supports leave the shaft free to move (all values NaN then).
    """
    shaft = assemble_shaft(section_lengths, outside_diameters, bores, youngs_modulus,
                           poisson_ratio, support_positions, support_stiffness,
                           load_positions, loads, stations)
    free = ~shaft.held
    reduced = shaft.matrix[np.ix_(free, free)]
    solvable = bool(np.linalg.cond(reduced) < 1e-3 / np.finfo(float).eps)
    displacement = np.zeros_like(shaft.force)
    if solvable:
        cases = shaft.force[..., free].reshape(-1, reduced.shape[0])
        displacement[..., free] = banded_solve(reduced, cases.T).T.reshape(
            shaft.force[..., free].shape)
    else:
        displacement[..., free] = np.nan
    by_node = displacement.reshape(displacement.shape[:-1] + (-1, NODE_DOFS))
    return {"support_displacement": by_node[..., shaft.support_nodes, :],
            "support_load": shaft.support_loads(displacement),
            "station_displacement": by_node[..., shaft.station_nodes, :],
            "solvable": solvable}
