"""Ball bearing under combined load: 5-DOF equilibrium of the inner ring and its stiffness.

Outer ring fixed; inner ring displaced by ``q = (delta_x, delta_y, delta_z, phi_y, phi_z)``
(paper 001, eq. 2-3); ball ``j`` sits at azimuth ``psi_j = 2 pi j / Z`` from the y axis
towards z. Ball centrifugal force and gyroscopic moments are neglected (a static model, as in
the paper), so a ball's two contacts share one line of action and one approach.

Inside this module the tilts are multiplied by the radius ``R`` of the locus of inner groove
curvature centres and the moments divided by it: all five displacements are then lengths and
all five loads forces, the stiffness matrix is well conditioned and one norm measures the
residual.
"""
from __future__ import annotations

import functools

import numpy as np

from models.contact import (POINT_CONTACT_EXPONENT, curvature_sum_difference,
                            effective_modulus, point_contact_constant)
from models.geometry import elements_fit
from models.registry import (CONVERGED, INFEASIBLE, NOT_CONVERGED, Constraint, Input, Model,
                             Output)
from models.solvers import solve_equilibrium

DOFS = ("axial", "radial_y", "radial_z", "tilt_y", "tilt_z")
GEOMETRIES = ("jones", "fixed_angle")
_LOADS = ("axial_load", "radial_load", "radial_load_z", "moment_y", "moment_z")
_TILTS = slice(3, 5)
_RESIDUAL_TOLERANCE = 1e-10  # relative to the load [-]
_MAX_ITERATIONS = 200
_START_DAMPING = 0.01  # of the preloaded stiffness: a start close to Newton
_SINGULAR = 1e-9  # reciprocal condition number below which the stiffness is singular [-]


def raceway_contact_constants(ball_diameter, pitch_diameter, contact_angle,
                              inner_curvature_ratio, outer_curvature_ratio,
                              youngs_modulus=207e9, poisson_ratio=0.3):
    """Hertz load-deflection constants of a ball on its inner and outer raceways.

    Parameters
    ----------
    ball_diameter, pitch_diameter : array_like
        ``D``, ``d_m`` [m].
    contact_angle : array_like
        ``alpha`` [rad]; the raceway curvature in the rolling direction is taken there.
    inner_curvature_ratio, outer_curvature_ratio : array_like
        ``f_i = r_i / D``, ``f_o = r_o / D`` [-], groove radius over ball diameter (> 0.5).
    youngs_modulus, poisson_ratio : array_like
        Of balls and rings [Pa], [-].

    Returns
    -------
    inner, outer, converged : numpy.ndarray
        ``K_i``, ``K_o`` [N/m^1.5] in ``Q = K delta^1.5``, and whether the ellipticity solves
        converged.

    Notes
    -----
    With ``gamma = D cos(alpha) / d_m``, the ball's curvatures are ``2/D`` in both planes; the
    inner raceway's are ``(2/D) gamma / (1 - gamma)`` (rolling) and ``-1/(f_i D)`` (groove),
    the outer raceway's ``-(2/D) gamma / (1 + gamma)`` and ``-1/(f_o D)`` (Harris and
    Kotzalas, ch. 2). Paper 001 eq. 5 in the same terms.
    """
    ball = 2.0 / np.asarray(ball_diameter)
    gamma = ball_diameter * np.cos(contact_angle) / np.asarray(pitch_diameter)
    modulus = effective_modulus(youngs_modulus, poisson_ratio)
    constants, converged = [], True
    for rolling, groove in ((ball * gamma / (1.0 - gamma), inner_curvature_ratio),
                            (-ball * gamma / (1.0 + gamma), outer_curvature_ratio)):
        total, difference, _ = curvature_sum_difference(
            ball, ball, rolling, -1.0 / (np.asarray(groove) * ball_diameter))
        constant, ok = point_contact_constant(total, difference, modulus)
        constants.append(constant)
        converged = converged & ok
    return constants[0], constants[1], converged


def series_constant(inner, outer, exponent=POINT_CONTACT_EXPONENT):
    """Constant of two contacts in series that carry the same load (paper 001 eq. 4, corrected).

    ``Q = K_i d_i^n = K_o d_o^n`` and ``d = d_i + d_o`` give
    ``K = [(1/K_i)^(1/n) + (1/K_o)^(1/n)]^(-n)``; the paper prints the exponents swapped.
    """
    return (np.asarray(inner) ** (-1.0 / exponent)
            + np.asarray(outer) ** (-1.0 / exponent)) ** (-exponent)


class _Rings:
    """Ball loads and ring stiffness of one group of points with the same ball count.

    Per point: curvature-centre distance ``A``, unloaded contact angle, half clearance and
    contact constant, all ``(N,)``. ``geometry`` is 'jones' or 'fixed_angle'.
    """

    def __init__(self, ball_count, distance, contact_angle, half_clearance, constant, geometry):
        azimuth = 2.0 * np.pi * np.arange(ball_count) / ball_count
        zero, one = np.zeros(ball_count), np.ones(ball_count)
        # Rows that map the scaled ring displacement to each ball's axial and radial
        # displacement, (Z, 5), and their outer products flattened, (Z, 25): with them the
        # sums over balls are matrix products.
        self.axial = np.stack([one, zero, zero, np.sin(azimuth), -np.cos(azimuth)], axis=-1)
        self.radial = np.stack([zero, np.cos(azimuth), np.sin(azimuth), zero, zero], axis=-1)
        def pair(a, b):
            return (a[:, :, None] * b[:, None, :]).reshape(ball_count, 25)

        self.axial_axial = pair(self.axial, self.axial)
        self.radial_radial = pair(self.radial, self.radial)
        self.mixed = pair(self.axial, self.radial) + pair(self.radial, self.axial)
        self.distance, self.constant = distance, constant
        self.jones = geometry == "jones"
        self.sin0, self.cos0 = np.sin(contact_angle), np.cos(contact_angle)
        self.axial0 = distance * self.sin0
        self.radial0 = distance * self.cos0 - half_clearance
        self.offset0 = half_clearance * self.cos0

    def contacts(self, scaled, index):
        """Each ball's approach, load, load slope, unit normal (axial and radial parts) and
        centre distance at the displacement ``scaled`` (``(N, Z)`` each)."""
        axial_shift, radial_shift = scaled @ self.axial.T, scaled @ self.radial.T
        if self.jones:
            separation_axial = self.axial0[index, None] + axial_shift
            separation_radial = self.radial0[index, None] + radial_shift
            length = np.hypot(separation_axial, separation_radial)
            normal_axial, normal_radial = separation_axial / length, separation_radial / length
            approach = length - self.distance[index, None]
        else:
            sin0, cos0 = self.sin0[index, None], self.cos0[index, None]
            normal_axial = np.broadcast_to(sin0, axial_shift.shape)
            normal_radial = np.broadcast_to(cos0, axial_shift.shape)
            length = None
            approach = axial_shift * sin0 + radial_shift * cos0 - self.offset0[index, None]
        root = np.sqrt(np.maximum(approach, 0.0))
        constant = self.constant[index, None]
        load = constant * root**3  # K delta^1.5
        slope = POINT_CONTACT_EXPONENT * constant * root
        return approach, load, slope, normal_axial, normal_radial, length

    def uniform_stiffness(self, approach, index):
        """Stiffness with every ball at the approach ``approach`` ``(N,)`` and its unloaded
        contact angle: a preloaded bearing's, to start the equilibrium iteration from."""
        shape = (approach.size, self.axial.shape[0])
        approach = np.broadcast_to(approach[:, None], shape)
        root = np.sqrt(approach)
        constant = self.constant[index, None]
        return self.stiffness_of((
            approach, constant * root**3, POINT_CONTACT_EXPONENT * constant * root,
            np.broadcast_to(self.sin0[index, None], shape),
            np.broadcast_to(self.cos0[index, None], shape),
            self.distance[index, None] + approach))

    def reaction(self, scaled, index):
        """Scaled generalised force the balls put on the inner ring (paper eq. 6-7)."""
        return self.reaction_of(self.contacts(scaled, index))

    def reaction_of(self, contacts):
        _, load, _, normal_axial, normal_radial, _ = contacts
        return (load * normal_axial) @ self.axial + (load * normal_radial) @ self.radial

    def stiffness(self, scaled, index):
        """Scaled tangent stiffness d(reaction)/d(displacement), ``(N, 5, 5)`` (eq. 9)."""
        return self.stiffness_of(self.contacts(scaled, index))

    def stiffness_of(self, contacts):
        """The stiffness from :meth:`contacts`' results.

        A ball's force ``Q(s) s/|s|`` on the centre separation ``s`` has the derivative
        ``Q' n n^T + (Q/|s|)(I - n n^T)``: the second term, the turning of the line of
        action, is what the fixed-angle geometry leaves out.
        """
        _, load, slope, normal_axial, normal_radial, length = contacts
        axial_axial = slope * normal_axial**2
        radial_radial = slope * normal_radial**2
        mixed = slope * normal_axial * normal_radial
        if self.jones:
            turning = load / length
            axial_axial = axial_axial + turning * normal_radial**2
            radial_radial = radial_radial + turning * normal_axial**2
            mixed = mixed - turning * normal_axial * normal_radial
        matrix = axial_axial @ self.axial_axial + radial_radial @ self.radial_radial \
            + mixed @ self.mixed
        return matrix.reshape(-1, 5, 5)


def ball_5dof(ball_count, ball_diameter, pitch_diameter, contact_angle,
              inner_curvature_ratio=0.52, outer_curvature_ratio=0.53, clearance=0.0,
              youngs_modulus=207e9, poisson_ratio=0.3, contact_constant=None, axial_load=0.0,
              radial_load=0.0, radial_load_z=0.0, moment_y=0.0, moment_z=0.0,
              geometry="jones", fixed_dofs=""):
    """Equilibrium and 5 x 5 stiffness matrix of a ball bearing's inner ring.

    Parameters
    ----------
    ball_count : int
        Number of balls ``Z``.
    ball_diameter, pitch_diameter : array_like
        ``D``, ``d_m`` [m].
    contact_angle : array_like
        Unloaded contact angle ``alpha_0`` [rad]: the direction of the line between the groove
        curvature centres with the rings centred.
    inner_curvature_ratio, outer_curvature_ratio : array_like
        ``f_i``, ``f_o`` [-]: groove radius over ball diameter.
    clearance : array_like
        Diametral clearance ``P_d`` [m] in addition to the contact at ``alpha_0``: the outer
        groove centres lie ``P_d / 2`` further out (negative: preload).
    youngs_modulus, poisson_ratio : array_like
        [Pa], [-], for the Hertz constant.
    contact_constant : array_like or None
        ``K`` [N/m^1.5] of ball and both raceways in series, ``Q = K delta^1.5``; None: from
        Hertz theory and the curvature ratios (:func:`raceway_contact_constants`).
    axial_load, radial_load, radial_load_z : array_like
        Loads on the inner ring along x, y, z [N].
    moment_y, moment_z : array_like
        Moments on the inner ring about y and z [N m].
    geometry : {'jones', 'fixed_angle'}
        'jones': each ball's line of action joins its groove centres as displaced, so contact
        angles follow the load [2]; 'fixed_angle': the approach is the displacement projected
        on the unloaded contact angle, paper 001 eq. 2-7 as printed.
    fixed_dofs : str or sequence of str
        Displacements held at zero (names from ``DOFS``; a string separates them by spaces).

    Returns
    -------
    dict of numpy.ndarray
        ``displacement`` ``(N, 5)`` [m, m, m, rad, rad]; ``axial_displacement``,
        ``radial_displacement`` (magnitude in the y-z plane) [m]; ``stiffness_matrix``
        ``(N, 5, 5)`` ``K_ij = dF_i/dq_j`` [N/m, N, N m/m, N m/rad]; ``axial_stiffness``
        ``K_11``, ``radial_stiffness`` ``K_22`` [N/m], ``tilt_stiffness`` ``K_44`` [N m/rad]
        (eq. 10, the diagonal); ``ball_load`` ``(N, Z)`` [N]; ``ball_contact_angle``
        ``(N, Z)`` [rad]; ``loaded_balls``; ``hertz_contact_constant`` [N/m^1.5] (whether or
        not ``contact_constant`` replaces it); ``status``: not converged
        (1), or infeasible (2) where the free displacements' stiffness is singular under load
        (the load cannot be carried, or not by a unique displacement).

    References
    ----------
    .. [1] Paper 001, eq. 1-10.
    .. [2] A. B. Jones, A general theory for elastically constrained ball and radial roller
       bearings under arbitrary load and speed conditions, J. Basic Eng. 82 (1960) 309-320.
    """
    names = fixed_dofs.split() if isinstance(fixed_dofs, str) else list(fixed_dofs)
    unknown = [name for name in names if name not in DOFS]
    if unknown or geometry not in GEOMETRIES:
        raise ValueError(f"fixed_dofs must name {DOFS}, geometry one of {GEOMETRIES}")
    free = np.array([dof not in names for dof in DOFS])
    arrays = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float)) for a in (
        ball_diameter, pitch_diameter, contact_angle, inner_curvature_ratio,
        outer_curvature_ratio, clearance, youngs_modulus, poisson_ratio, axial_load,
        radial_load, radial_load_z, moment_y, moment_z,
        np.nan if contact_constant is None else contact_constant)))
    (diameter, pitch, angle, inner_ratio, outer_ratio, clearance, modulus, poisson,
     *loads, given) = arrays
    inner, outer, hertz_ok = raceway_contact_constants(diameter, pitch, angle, inner_ratio,
                                                       outer_ratio, modulus, poisson)
    constant = np.where(np.isnan(given), series_constant(inner, outer), given)
    distance = (inner_ratio + outer_ratio - 1.0) * diameter
    radius = 0.5 * pitch + (inner_ratio - 0.5) * diameter * np.cos(angle)
    scale = np.stack([np.ones_like(radius)] * 3 + [radius] * 2, -1)  # length per unit dof
    load = np.stack(loads, -1) / scale
    load[:, ~free] = 0.0
    rings = _Rings(ball_count, distance, angle, 0.5 * clearance, constant, geometry)
    scaled, converged = _equilibrium(rings, load, free, ball_count)

    everything = np.arange(load.shape[0])
    stiffness = rings.stiffness(scaled, everything)
    reduced = stiffness[:, free][:, :, free]
    singular = _reciprocal_condition(reduced) < _SINGULAR
    loaded = np.linalg.norm(load, axis=-1) > 0
    status = np.select([~hertz_ok, ~converged & singular, ~converged, singular & loaded],
                       [NOT_CONVERGED, INFEASIBLE, NOT_CONVERGED, INFEASIBLE], CONVERGED)
    approach, ball_load, _, normal_axial, normal_radial, _ = rings.contacts(scaled, everything)
    displacement = scaled / scale
    matrix = stiffness * scale[:, :, None] * scale[:, None, :]
    outputs = {
        "displacement": displacement,
        "axial_displacement": displacement[:, 0],
        "radial_displacement": np.hypot(displacement[:, 1], displacement[:, 2]),
        "stiffness_matrix": matrix,
        "axial_stiffness": matrix[:, 0, 0],
        "radial_stiffness": matrix[:, 1, 1],
        "tilt_stiffness": matrix[:, 3, 3],
        "ball_load": ball_load,
        "ball_contact_angle": np.arctan2(normal_axial, normal_radial),
        "loaded_balls": np.count_nonzero(approach > 0, axis=-1).astype(float),
        "hertz_contact_constant": series_constant(inner, outer),
    }
    outputs["status"] = status.astype(np.int8)
    return outputs


def _equilibrium(rings: _Rings, load, free, ball_count):
    """Displacements where the balls' reaction balances ``load`` in the free directions.

    An unloaded bearing has no stiffness, so the damped Newton iteration starts from the
    displacement the load gives a bearing whose balls are all compressed as much as the load
    would compress them (``Z K delta^1.5 = |F|``), with a damping of a hundredth of that
    bearing's stiffness.
    """
    # Force scale: the load, or the balls' preload from a negative clearance if larger.
    preload = ball_count * rings.constant * np.maximum(-rings.offset0, 0.0) ** 1.5
    magnitude = np.linalg.norm(load, axis=-1) + preload
    typical = (magnitude / (ball_count * rings.constant)) ** (1.0 / POINT_CONTACT_EXPONENT)
    damping = _START_DAMPING * POINT_CONTACT_EXPONENT * ball_count * rings.constant * np.sqrt(
        typical)
    active = np.flatnonzero(magnitude > 0)  # unloaded points without preload stay centred
    start = np.zeros_like(load)
    preloaded = rings.uniform_stiffness(typical[active], active)[:, free][:, :, free]
    start[active[:, None], free] = np.linalg.solve(
        preloaded + damping[active, None, None] * np.eye(int(free.sum())),
        load[active][:, free, None])[..., 0]

    def evaluate(scaled, index):
        contacts = rings.contacts(scaled, index)
        return rings.reaction_of(contacts), rings.stiffness_of(contacts)

    return solve_equilibrium(evaluate, start, load, damping,
                             _RESIDUAL_TOLERANCE * magnitude, free, _MAX_ITERATIONS)


def _reciprocal_condition(matrices):
    """Smallest over largest singular value of each matrix (0 for a zero matrix)."""
    values = np.linalg.svd(matrices, compute_uv=False)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(values[:, 0] > 0, values[:, -1] / values[:, 0], 0.0)


def _fits(ball_count, pitch_diameter, ball_diameter):
    return elements_fit(ball_count, pitch_diameter, ball_diameter)


def _clearance_fits(clearance, ball_diameter, inner_curvature_ratio, outer_curvature_ratio,
                    contact_angle):
    distance = (inner_curvature_ratio + outer_curvature_ratio - 1.0) * ball_diameter
    return np.abs(clearance) < 2.0 * distance * np.cos(contact_angle)


def _no_load_on_held(fixed_dofs, axial_load, radial_load, radial_load_z, moment_y, moment_z):
    held = np.vectorize(lambda text: tuple(d in text.split() for d in DOFS), otypes=[bool] * 5)(
        np.asarray(fixed_dofs, dtype=object))
    loads = (axial_load, radial_load, radial_load_z, moment_y, moment_z)
    return functools.reduce(np.logical_and, [~h | (np.asarray(f) == 0)
                                             for h, f in zip(held, loads)])


_DOF_UNITS = ("mm", "mm", "mm", "rad", "rad")
_LOAD_UNITS = ("N", "N", "N", "N*m", "N*m")

MODELS = [Model(
    name="ball_5dof",
    function=ball_5dof,
    summary="Ball bearing under axial, radial and moment loads: 5-DOF equilibrium of the inner "
            "ring, ball loads and contact angles, and the full 5 x 5 stiffness matrix.",
    reference="Paper 001, eq. 1-10; Jones (1960); Harris & Kotzalas, Rolling Bearing Analysis",
    version="1",
    inputs=(
        Input("ball_count", "1", "number of balls Z", kind="count", minimum=3, maximum=1000),
        Input("ball_diameter", "mm", "ball diameter D", minimum=0.0, exclusive_minimum=True),
        Input("pitch_diameter", "mm", "pitch diameter dm", minimum=0.0, exclusive_minimum=True),
        Input("contact_angle", "deg", "unloaded contact angle alpha0", minimum=0.0,
              maximum=80.0),
        Input("inner_curvature_ratio", "1", "inner groove radius / ball diameter fi",
              default=0.52, minimum=0.5, exclusive_minimum=True, maximum=1.0),
        Input("outer_curvature_ratio", "1", "outer groove radius / ball diameter fo",
              default=0.53, minimum=0.5, exclusive_minimum=True, maximum=1.0),
        Input("clearance", "mm", "diametral clearance Pd beyond contact at alpha0 (negative: "
              "preload)", default=0.0),
        Input("youngs_modulus", "GPa", "Young's modulus of balls and rings", default=207.0,
              minimum=0.0, exclusive_minimum=True),
        Input("poisson_ratio", "1", "Poisson's ratio of balls and rings", default=0.3,
              minimum=0.0, maximum=0.5),
        Input("contact_constant", "N/mm^1.5", "load-deflection constant K of a ball and both "
              "raceways, Q = K delta^1.5; default: Hertz, from the curvature ratios",
              default=None, minimum=0.0, exclusive_minimum=True),
        Input("axial_load", "N", "axial load Fx on the inner ring", default=0.0),
        Input("radial_load", "N", "radial load Fy on the inner ring", default=0.0),
        Input("radial_load_z", "N", "radial load Fz on the inner ring", default=0.0),
        Input("moment_y", "N*m", "moment My on the inner ring", default=0.0),
        Input("moment_z", "N*m", "moment Mz on the inner ring", default=0.0),
        Input("geometry", "", "jones: contact angles follow the displacement; fixed_angle: "
              "paper eq. 2-7 as printed", default="jones", kind="choice", choices=GEOMETRIES),
        Input("fixed_dofs", "", "displacements held at zero", default=(), kind="subset",
              choices=DOFS),
    ),
    outputs=(
        Output("displacement", "mm, rad", "displacement of the inner ring", dims=("dof",),
               entry_units=_DOF_UNITS),
        Output("axial_displacement", "mm", "axial displacement of the inner ring"),
        Output("radial_displacement", "mm", "radial displacement of the inner ring (y-z)"),
        Output("stiffness_matrix", "N/mm, N/rad, N*m/mm, N*m/rad", "stiffness matrix "
               "dF_i/dq_j (eq. 9)", dims=("load_dof", "dof"),
               entry_units=tuple(tuple(f"{f}/{q}" for q in _DOF_UNITS) for f in _LOAD_UNITS)),
        Output("axial_stiffness", "N/mm", "axial stiffness dFx/d(delta_x) (eq. 10)"),
        Output("radial_stiffness", "N/mm", "radial stiffness dFy/d(delta_y) (eq. 10)"),
        Output("tilt_stiffness", "N*m/rad", "tilt stiffness dMy/d(phi_y) (eq. 10)"),
        Output("ball_load", "N", "contact load Q of each ball (eq. 1)", dims=("ball",)),
        Output("ball_contact_angle", "deg", "contact angle of each ball (of its line of "
               "groove centres when unloaded)", dims=("ball",)),
        Output("loaded_balls", "1", "number of balls carrying load"),
        Output("hertz_contact_constant", "N/mm^1.5", "load-deflection constant K that Hertz "
               "theory gives for the curvature ratios (eq. 4-5, series law corrected)"),
    ),
    dim_sizes={"ball": "ball_count", "dof": DOFS, "load_dof": DOFS},
    constraints=(
        Constraint(("ball_count", "pitch_diameter", "ball_diameter"), _fits,
                   "the balls do not fit on the pitch circle: pitch_diameter * sin(180 deg / "
                   "ball_count) must exceed ball_diameter"),
        Constraint(("clearance", "ball_diameter", "inner_curvature_ratio",
                    "outer_curvature_ratio", "contact_angle"), _clearance_fits,
                   "|clearance| must be below 2 (fi + fo - 1) D cos(alpha0), or the balls "
                   "leave their grooves"),
        Constraint(("fixed_dofs",) + _LOADS, _no_load_on_held,
                   "a load is given along a displacement held in fixed_dofs (axial_load, "
                   "radial_load, radial_load_z, moment_y, moment_z go with axial, radial_y, "
                   "radial_z, tilt_y, tilt_z)"),
    ),
    seconds_per_point=3e-5,
    points_per_call=500,
)]
