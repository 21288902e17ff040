"""Cage and roller slip (skidding) of a cylindrical roller bearing in steady running
(paper 002).

Outer ring fixed, inner ring at ``omega_i``, roller-guided cage at ``omega_c``. A roller's spin
``omega_R`` is driven by traction at its two raceway contacts and braked by oil films in its
pocket and at its ends, and by friction in its pocket; around the orbit it enters the load zone
slowed by those and is spun up there. The steady state is found by integrating one roller's
spin around the orbit, with the loads of the load zone, for a trial cage speed, and closing the
cage's torque balance: the rollers' push, less the reaction of their pocket films and pocket
friction, against the cage's own drag. That balance can have several roots (a light-load
hysteresis band): they are all found by a scan of the cage-speed range, and one is chosen.

Sign conventions, tangential, positive in the direction of the orbit: sliding speeds
``u_i = (omega_i - omega_c) r_i - omega_R R`` (ring minus roller) and
``u_o = omega_R R - omega_c r_o``; traction on the roller ``mu(u) Q`` forward at both contacts;
spin torque ``R (F_i - F_o)``. A positive spin ``omega_R`` turns opposite to the orbit (a
roller rolling on the fixed outer ring), and a positive spin couple spins it up.
"""
from __future__ import annotations

import inspect

import numpy as np

from .cylindrical import CLEARANCE_BELOW_ROLLER, crb_radial
from .bearing_life import VISCOSITY_ORDER
from .lubrication import (OIL_DENSITIES, VISCOSITY_GRADES, WALTHER_FLOOR, TractionCurve,
                          line_contact_film, walther_viscosity)
from .contact import STIFFEST_SOLID
from .limits import (CLEARANCE_VALIDITY, OIL_VALIDITY, ROLLING_ELEMENT_DENSITIES,
                     SOFTEST_BEARING_SOLID, SPEED_VALIDITY, STEEL_VALIDITY,
                     outside_operation)
from .registry import (CONVERGED, NO_ROOT_IN_RANGE, NOT_CONVERGED, OUT_OF_VALIDITY, Constraint,
                       Input, Model, Output, combine_status)
from .solvers import solve_increasing

AIR_DENSITY = 1.2  # [kg/m^3]
_POSITIONS_PER_PITCH = 20  # cage positions computed per roller pitch: the orbit's resolution
_ORBITS = 2  # orbits integrated per trial cage speed; the load zone resets the spin each time
#: The bearing's terms a roller's spin around the orbit takes, in orbit_spins' order.
_ORBIT_TERMS = ("omega_i", "inertia", "mu_pocket", "pocket_film", "end_film", "radius", "r_i",
                "r_o", "windage")
# The cage-speed range searched, as shares of the kinematic cage speed: from 98 % slip to just
# above the kinematic speed (where the traction turns and the balance is sure to be positive).
_LOWEST_CAGE_SPEED, _HIGHEST_CAGE_SPEED = 0.02, 1.001
# Cage speeds at which the balance is scanned for its roots, evenly over the range (steps of
# 0.02 of the kinematic speed). Two roots closer than a step are missed: that happens only
# within a load of the edge of a hysteresis band where the roots merge (their distance grows
# with the square root of the load's distance from the edge): the bands of the test bearing
# at 9000 and 12000 r/min come out at most 0.5 N narrower than with a ten times finer scan.
_SCAN_SPEEDS = 50
_SPEED_TOLERANCE = 1e-10  # of the kinematic cage speed, for the refined root
# A root is converged when the balance's residual is below this share of the torques it
# balances (the cage's drag plus the magnitudes of the rollers' push and pocket couples).
_RELATIVE_RESIDUAL = 1e-6
BRANCHES = ("high_slip", "low_slip")
#: Largest pocket clearance and end film as a share of the roller radius: the pocket's and
#: the ends' Couette films (Petroff's law) take the film thin against the radius, its
#: curvature neglected (an error of the order of the ratio, Hamrock, Schmid and Jacobson,
#: Fundamentals of Fluid Film Lubrication, 2nd ed. (2004), ch. 8, Petroff's equation) [-].
THIN_FILM_LIMIT = 0.1
#: Smallest pocket clearance and end film [m]: thinner, a film is no thicker than the
#: surfaces' composite roughness (ground roller ends and faces, machined pockets: some
#: 0.1-1 um), and Petroff's full film, whose drag grows as its inverse, no longer forms.
SMALLEST_FILM = 1e-6
#: Largest drag coefficient of the roller windage [-]: a cylinder across a flow has C_D of
#: about 0.3 (beyond the drag crisis) to 1.2 over Reynolds numbers of 1e3-2e5, 3 at 10 and
#: 10 at about 1 (F. M. White, Fluid Mechanics, 7th ed., McGraw-Hill (2011), Fig. 7.16a);
#: below that the drag is viscous, proportional to the speed (Stokes, Lamb), not the
#: quadratic windage F_D = rho_e C_D l h v^2 / 2 this model takes. Paper 002's typical value
#: is about 1 (0.5-2, CAGE_SLIP_PHYSICS.md).
DRAG_COEFFICIENT_LIMIT = 10.0
#: Traction coefficients of a lubricated rolling contact stay below about 0.1 even for
#: traction fluids (K. L. Johnson, J. L. Tevaarwerk, Proc. R. Soc. Lond. A 356 (1977) 215;
#: turbine oils 0.03-0.06), and the boundary friction of steel on steel about 0.1-0.15 in
#: mixed lubrication: 0.2 bounds both the peak and the high-slip limit [-].
TRACTION_LIMIT = 0.2


def kinematic_cage_speed(speed, inner_raceway_diameter, outer_raceway_diameter):
    """``omega_c = omega_i r_i / (r_i + r_o)`` [rad/s], outer ring fixed (no slip)."""
    return speed * inner_raceway_diameter / (inner_raceway_diameter + outer_raceway_diameter)


def cage_slip(radial_load, speed, roller_count, inner_raceway_diameter, roller_diameter,
              roller_length, effective_length, clearance, cage_inner_diameter,
              cage_outer_diameter, cage_width, roller_density=7820.0, oil_temperature=298.15,
              viscosity_40=26e-6, viscosity_100=5.4e-6, oil_density=1000.0,
              pressure_viscosity=1.1e-8, youngs_modulus=207e9, poisson_ratio=0.28,
              traction_peak=0.05, traction_peak_speed=2.0, traction_limit=0.036,
              oil_fraction=0.05, drag_coefficient=1.0, pocket_clearance=1e-4,
              pocket_wrap_angle=1.0, pocket_film_fill=1.0, end_film_thickness=1.5e-5,
              end_film_fill=0.25, pocket_friction=0.1, orbit_points=72, branch="high_slip"):
    """Steady cage speed, cage slip and roller slip around the orbit.

    Parameters
    ----------
    radial_load : array_like
        ``F_r`` [N].
    speed : array_like
        Inner-ring speed ``omega_i`` [rad/s].
    roller_count : int
    inner_raceway_diameter, roller_diameter, clearance : array_like
        ``d_i``, ``D``, diametral clearance ``P_d`` [m]; the outer raceway is
        ``d_i + 2 D + P_d``.
    roller_length, effective_length : array_like
        Whole length (mass, pocket film) and raceway contact length [m].
    cage_inner_diameter, cage_outer_diameter, cage_width : array_like
        Cage [m]; the rollers' windage acts on the part of the roller outside the cage
        (paper 002), the cage's on its two faces (:func:`cage_windage`).
    roller_density : array_like
        [kg/m^3].
    oil_temperature : array_like
        [K].
    viscosity_40, viscosity_100 : array_like
        Kinematic viscosity at 40 and 100 deg C [m^2/s] (Walther's law between them).
    oil_density : array_like
        [kg/m^3].
    pressure_viscosity : array_like
        ``alpha`` [1/Pa] (film thickness only).
    youngs_modulus, poisson_ratio : array_like
        Rollers and rings.
    traction_peak, traction_peak_speed, traction_limit : array_like
        The traction curve (:class:`models.lubrication.TractionCurve`): ``mu_m``, ``u_m``
        [m/s], ``mu_inf``.
    oil_fraction : array_like
        Oil's share ``X`` of the cavity, effective density ``X rho_oil + (1 - X) rho_air``.
    drag_coefficient : array_like
        ``C_D`` of a roller's windage ``F_D = rho_e C_D l h (omega_c r_m)^2 / 2`` (paper 002).
    pocket_clearance, pocket_wrap_angle, pocket_film_fill : array_like
        Pocket film ``M_p = phi_p eta omega_R R^3 L theta_w / c_p`` ([m], [rad], [-]), between
        the roller and the cage: the cage receives its reaction.
    end_film_thickness, end_film_fill : array_like
        Films at the two roller ends, ``M_e = 2 phi_e eta omega_R (pi R^4 / 2) / h_e``,
        between the roller's ends and the rings' ribs: the rings receive their reaction, not
        the cage.
    pocket_friction : array_like
        Coulomb coefficient ``mu_p`` of the pocket force on the roller's spin, a couple
        ``mu_p |F_p| R`` between roller and cage: the cage receives its reaction.
    orbit_points : int
        Orbit positions at which the roller slip is returned.
    branch : {"high_slip", "low_slip"}
        Which stable equilibrium to return where the cage's torque balance has several (a
        hysteresis band at light load). ``"high_slip"`` (default): the lowest stable cage
        speed, the one a cage reaches accelerating from rest at this load and speed (from rest
        the rollers' push exceeds the drag, and the cage speeds up until the first speed at
        which the drag overtakes the push). ``"low_slip"``: the highest, the one a cage keeps
        when the load falls into the band from above (or that it reaches slowing down from the
        kinematic speed). Outside a band both are the same.

    Returns
    -------
    dict of numpy.ndarray
        ``cage_slip`` [-] (eq. 27 with the kinematic cage speed), ``cage_speed`` [rad/s],
        ``roller_slip`` ``(N, orbit_points)`` [-] against the kinematic spin, ``orbit_angle``
        [rad] from the load line, ``roller_spin_ratio`` [-] (mean spin / kinematic spin),
        ``torque_residual`` [N m] of the cage's balance, ``film_thickness`` [m] at the most
        loaded inner contact, ``max_roller_load`` [N], ``equilibrium_count`` [-] (stable
        equilibria found between 2 % and 100.1 % of the kinematic cage speed), ``status``:
        ``no_root_in_range`` where there is none (the rollers cannot drive the cage: the
        outputs that need the cage speed are NaN), ``not_converged`` where the residual is not
        small against the torques it balances; the status of the load distribution
        (:func:`models.cylindrical.crb_radial`) is combined in, its validity with it;
        ``out_of_validity`` also where the pocket clearance or the end film exceeds
        :data:`THIN_FILM_LIMIT` of the roller radius (the films' thin-film form) or lies
        below :data:`SMALLEST_FILM` (no full film) and,
        whatever the outcome, where a speed factor ``n d_m`` above 4e6 mm r/min or an oil
        whose viscosity index no lubricant has describe no bearing
        (:func:`models.limits.outside_operation`).

    References
    ----------
    .. [1] Paper 002, eq. 27 and the roller windage of section 1.
    .. [2] T. A. Harris, The effect of misalignment on the fatigue life of cylindrical roller
       bearings having crowned rolling members (skidding analysis), ASLE Trans. 9 (1966) 229.
    .. [3] P. K. Gupta, Advanced Dynamics of Rolling Elements, Springer (1984).
    """
    balance = _CageBalance(roller_count, {k: v for k, v in locals().items()
                                          if k not in ("roller_count", "orbit_points", "branch")})
    terms, points = balance.terms, balance.points
    everything = np.arange(points)
    omega_kin = terms["omega_kin"]
    lower_end, upper_end, count = _bracket_of_branch(balance, branch)
    has_root = np.isfinite(lower_end)
    omega_c = np.where(has_root, omega_kin, np.nan)
    converged = np.zeros(points, dtype=bool)
    if has_root.any():
        found = np.flatnonzero(has_root)
        root, converged[found] = _secant_root(
            lambda x, index: balance.residual(x, found[index]), lower_end[found],
            upper_end[found], _SPEED_TOLERANCE * omega_kin[found])
        omega_c[found] = root
    trial = np.where(has_root, omega_c, omega_kin)  # the kinematic speed stands in for none
    spin, residual, scale = balance.evaluate(trial, everything)
    converged &= np.abs(residual) <= _RELATIVE_RESIDUAL * scale
    status = np.where(has_root, np.where(converged, CONVERGED, NOT_CONVERGED),
                      NO_ROOT_IN_RANGE)
    radius, r_i = terms["radius"], terms["r_i"]
    steps = balance.inner_load.shape[1]
    where = np.linspace(0.0, 2.0 * np.pi, orbit_points, endpoint=False)
    grid = np.arange(steps) * 2.0 * np.pi / steps
    spin_at = np.stack([np.interp(where, grid, s, period=2 * np.pi) for s in spin])
    heaviest = np.argmax(balance.inner_load, axis=1)
    entraining = 0.5 * ((terms["omega_i"] - omega_c) * r_i + spin[everything, heaviest] * radius)
    reduced = terms["modulus"] / (1.0 - terms["poisson"]**2)
    film_thickness, _ = line_contact_film(
        balance.inner_load[everything, heaviest], terms["contact_length"],
        radius * r_i / (radius + r_i), entraining, terms["viscosity"], terms["alpha"], reduced)
    missing = np.where(has_root, 1.0, np.nan)  # NaN where the outputs need the missing root
    # Whatever the outcome: a speed or an oil no bearing runs with (the load distribution
    # flags the speed too, and its own elastic constants and clearance).
    no_bearing = outside_operation(terms["omega_i"], 2.0 * terms["pitch_radius"],
                                   terms["nu_40"], terms["nu_100"])
    return {
        "cage_slip": 1.0 - omega_c / omega_kin,
        "cage_speed": omega_c,
        "roller_slip": (1.0 - spin_at / terms["spin_kin"][:, None]) * missing[:, None],
        "orbit_angle": np.broadcast_to(where, spin_at.shape),
        "roller_spin_ratio": spin.mean(axis=1) / terms["spin_kin"] * missing,
        "torque_residual": -residual * missing,
        "film_thickness": film_thickness * missing,
        "max_roller_load": balance.inner_load.max(axis=1),
        "equilibrium_count": count.astype(float),
        "status": combine_status(status, balance.load_status, np.where(films_out_of_form(
            terms["diameter"], terms["pocket_clearance"], terms["end_film_thickness"])
            | no_bearing, OUT_OF_VALIDITY, CONVERGED)).astype(np.int8),
    }


def cage_torque_residual(cage_speed, radial_load, speed, roller_count, **bearing):
    """The cage's torque balance at trial cage speeds: its drag less what the rollers give it
    [N m] (positive: the cage slows down). Its roots are :func:`cage_slip`'s equilibria; a
    root where it rises is stable.

    Parameters
    ----------
    cage_speed : array_like
        Trial cage speeds ``omega_c`` [rad/s], broadcast with the points.
    radial_load, speed, roller_count, **bearing
        As :func:`cage_slip` (``orbit_points`` and ``branch`` excepted).

    Returns
    -------
    numpy.ndarray
        ``M_cage(omega_c) - Z (r_m F_push + M_pocket)`` [N m].
    """
    defaults = {k: p.default for k, p in inspect.signature(cage_slip).parameters.items()
                if p.default is not inspect.Parameter.empty
                and k not in ("orbit_points", "branch")}
    balance = _CageBalance(roller_count, {**defaults, **bearing, "radial_load": radial_load,
                                          "speed": speed})
    shape = np.broadcast_shapes(np.shape(cage_speed), (balance.points,))
    points = np.broadcast_to(np.arange(balance.points), shape).ravel()
    trial = np.broadcast_to(np.asarray(cage_speed, dtype=float), shape).ravel()
    return balance.evaluate(trial, points)[1].reshape(shape)


class _CageBalance:
    """The cage's torque balance of a chunk of points: one roller's spin integrated around the
    orbit at trial cage speeds, and what the rollers give the cage."""

    def __init__(self, roller_count, inputs):
        self.terms = terms = bearing_terms(roller_count=roller_count, **inputs)
        self.roller_count = roller_count
        self.points = terms["load"].size
        # crb_radial weighs a roller over its contact length: give it the whole roller's mass.
        whole_roller_density = terms["mass"] / (np.pi * terms["radius"]**2
                                                * terms["contact_length"])
        self.inner_load, centrifugal, self.load_status = _orbit_loads(
            terms["load"], terms["omega_i"], roller_count, 2 * terms["pitch_radius"],
            terms["diameter"], terms["contact_length"], terms["play"], whole_roller_density,
            terms["modulus"], terms["poisson"])
        self.outer_load = self.inner_load + centrifugal[:, None]

    def orbit(self, omega_c, index):
        """Spin around the orbit ``(n, steps)``, the rollers' mean forward push on the cage
        [N] and the mean couple the cage receives from a roller's pocket [N m], at cage speeds
        ``omega_c`` for the points ``index`` (which may repeat)."""
        from .cage_slip_orbit import orbit_spins  # numba: only when solving

        t = self.terms
        q_i, q_o = self.inner_load[index], self.outer_load[index]
        history, pushing, pocket = (np.empty(q_i.shape) for _ in range(3))
        curve = t["traction"]
        omega_c, index = np.broadcast_arrays(np.asarray(omega_c, dtype=float), index)
        orbit_spins(np.ascontiguousarray(q_i), np.ascontiguousarray(q_o),
                    np.ascontiguousarray(omega_c), *(np.ascontiguousarray(t[name][index])
                                                     for name in _ORBIT_TERMS),
                    np.stack([curve.a[index], curve.b[index], curve.c[index],
                              curve.d[index]], axis=-1), _ORBITS, history, pushing, pocket)
        # Reaction: the cage receives minus the roller's pocket couple about the axis. The
        # roller's couple is counted positive opposite to the orbit, the cage's with it: the
        # same number, so a film braking a roller's (positive) spin brakes the cage too. The
        # film's shear on the two facing arcs is a pure couple; the friction force is radial at
        # the pocket wall, a lever R off the roller's centre, so it also gives the cage the
        # couple mu_p |F_p| R about the bearing axis (its radial part goes to the raceways).
        return history, pushing.mean(axis=1), pocket.mean(axis=1)

    def evaluate(self, omega_c, index):
        """Spin around the orbit, the balance's residual (drag less the rollers' drive: it
        rises with the cage speed at a stable root) [N m] and the torques it balances."""
        t = self.terms
        spin, push, pocket = self.orbit(omega_c, index)
        drag = cage_windage(omega_c, t["cage_out"][index], t["width"][index],
                            t["effective_density"][index], t["kinematic_viscosity"][index])
        drive = self.roller_count * (push * t["pitch_radius"][index] + pocket)
        scale = drag + self.roller_count * (np.abs(push) * t["pitch_radius"][index]
                                            + np.abs(pocket))
        return spin, drag - drive, scale

    def residual(self, omega_c, index):
        return self.evaluate(omega_c, index)[1]


def _bracket_of_branch(balance, branch):
    """The bracket of each point's chosen stable root, from the balance scanned at
    ``_SCAN_SPEEDS`` cage speeds, and the count of stable roots (NaN brackets: none).

    A stable root is where the residual turns from not positive to positive with rising
    cage speed (a faster cage meets more drag than drive); the first is ``"high_slip"``'s,
    the last ``"low_slip"``'s."""
    if branch not in BRANCHES:
        raise ValueError(f"branch must be one of {BRANCHES}, not {branch!r}")
    points = balance.points
    shares = np.linspace(_LOWEST_CAGE_SPEED, _HIGHEST_CAGE_SPEED, _SCAN_SPEEDS)
    speeds = shares[None, :] * balance.terms["omega_kin"][:, None]
    index = np.repeat(np.arange(points), _SCAN_SPEEDS)
    values = balance.residual(speeds.ravel(), index).reshape(points, _SCAN_SPEEDS)
    rising = (values[:, :-1] <= 0.0) & (values[:, 1:] > 0.0)
    count = rising.sum(axis=1)
    chosen = np.argmax(rising, axis=1) if branch == "high_slip" else \
        _SCAN_SPEEDS - 2 - np.argmax(rising[:, ::-1], axis=1)
    rows = np.arange(points)
    lower = np.where(count > 0, speeds[rows, chosen], np.nan)
    upper = np.where(count > 0, speeds[rows, chosen + 1], np.nan)
    return lower, upper, count


def bearing_terms(radial_load, speed, roller_count, inner_raceway_diameter, roller_diameter,
                  roller_length, effective_length, clearance, cage_inner_diameter,
                  cage_outer_diameter, cage_width, roller_density, oil_temperature,
                  viscosity_40, viscosity_100, oil_density, pressure_viscosity, youngs_modulus,
                  poisson_ratio, traction_peak, traction_peak_speed, traction_limit,
                  oil_fraction, drag_coefficient, pocket_clearance, pocket_wrap_angle,
                  pocket_film_fill, end_film_thickness, end_film_fill, pocket_friction):
    """The bearing's derived quantities, shared by the steady and the transient model (the
    parameters are :func:`cage_slip`'s, as arrays of the points)."""
    arrays = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float)) for a in (
        radial_load, speed, inner_raceway_diameter, roller_diameter, roller_length,
        effective_length, clearance, cage_inner_diameter, cage_outer_diameter, cage_width,
        roller_density, oil_temperature, viscosity_40, viscosity_100, oil_density,
        pressure_viscosity, youngs_modulus, poisson_ratio, traction_peak,
        traction_peak_speed, traction_limit, oil_fraction, drag_coefficient,
        pocket_clearance, pocket_wrap_angle, pocket_film_fill, end_film_thickness,
        end_film_fill, pocket_friction)))
    (load, omega_i, d_i, diameter, length, contact_length, play, cage_in, cage_out, width,
     density, temperature, nu_40, nu_100, rho_oil, alpha, modulus, poisson, mu_peak, u_peak,
     mu_limit, fraction, c_drag, c_pocket, wrap, fill_pocket, h_end, fill_end,
     mu_pocket) = arrays
    radius, r_i = 0.5 * diameter, 0.5 * d_i
    r_o = r_i + diameter + 0.5 * play
    pitch_radius = 0.5 * (r_i + r_o)
    omega_kin = kinematic_cage_speed(omega_i, r_i, r_o)
    kinematic_viscosity = walther_viscosity(temperature, nu_40, nu_100)
    viscosity = rho_oil * kinematic_viscosity
    mass = density * np.pi * radius**2 * length
    effective_density = fraction * rho_oil + (1.0 - fraction) * AIR_DENSITY
    # roller height outside the cage (none where the cage fills the space between the rings)
    exposed = np.maximum(diameter - 0.5 * (cage_out - cage_in), 0.0)
    return {
        "load": load, "omega_i": omega_i, "diameter": diameter,
        "contact_length": contact_length, "play": play, "density": density, "alpha": alpha,
        "modulus": modulus, "poisson": poisson, "radius": radius, "r_i": r_i, "r_o": r_o,
        "pitch_radius": pitch_radius, "omega_kin": omega_kin,
        "spin_kin": (omega_i - omega_kin) * r_i / radius, "viscosity": viscosity,
        "kinematic_viscosity": kinematic_viscosity,
        "mass": mass, "inertia": 0.5 * mass * radius**2,
        # Film torques per spin speed [N m s]: the pocket arc (roller against cage) and both
        # ends (roller against the rings' ribs).
        "pocket_film": viscosity * fill_pocket * radius**3 * length * wrap / c_pocket,
        "end_film": viscosity * fill_end * np.pi * radius**4 / h_end,
        # roller windage per (orbit speed)^2 [N s^2], paper 002's form
        "windage": 0.5 * effective_density * c_drag * contact_length * exposed
        * pitch_radius**2,
        "effective_density": effective_density, "cage_in": cage_in, "cage_out": cage_out,
        "width": width, "pocket_clearance": c_pocket, "end_film_thickness": h_end,
        "mu_pocket": mu_pocket, "nu_40": nu_40, "nu_100": nu_100,
        "traction": TractionCurve(mu_peak, u_peak, mu_limit),
    }


def cage_windage(omega_c, cage_outer_diameter, cage_width, effective_density,
                 kinematic_viscosity):
    """Windage moment of the cage's two faces in the cavity's oil-air mixture [N m].

    Disc churning ``M = 2 C_M rho_e omega^2 r^5 / 2`` with ``C_M = 3.87 Re^-1/2`` (laminar)
    or ``0.146 Re^-1/5`` (turbulent), ``Re = omega r^2 / nu``; none when the cage has no
    width. The fluid is one and the same in both: the oil-air mixture, of effective density
    ``rho_e = X rho_oil + (1 - X) rho_air`` and a mixture viscosity ``eta_e = rho_e nu_oil``,
    whose kinematic viscosity is the oil's, as in the treatment of an oil-air mixture's drag
    on rolling elements by Harris and Kotzalas [1] (its chapter and equation not checked
    against the book). Mixing the oil's dynamic viscosity with the mixture's density would put
    ``Re`` a factor ``rho_e / rho_oil`` too low (0.05 at the default oil fraction).

    Parameters
    ----------
    omega_c : array_like
        Cage speed [rad/s].
    cage_outer_diameter, cage_width : array_like
        [m].
    effective_density : array_like
        ``rho_e`` [kg/m^3].
    kinematic_viscosity : array_like
        The oil's ``nu_oil`` [m^2/s].

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis: Advanced Concepts of
       Bearing Technology, 5th ed., CRC Press (2007), drag of rolling elements in an oil-air
       mixture.
    .. [2] CAGE_SLIP_PHYSICS.md (project notes): the disc churning coefficients.
    """
    outer = 0.5 * cage_outer_diameter
    reynolds = omega_c * outer**2 / kinematic_viscosity
    coefficient = np.where(reynolds < 3e5, 3.87 / np.sqrt(reynolds), 0.146 * reynolds**-0.2)
    faces = np.where(cage_width > 0, 2.0, 0.0)
    return faces * coefficient * 0.5 * effective_density * omega_c**2 * outer**5


def _orbit_loads(load, omega_i, roller_count, pitch_diameter, diameter, contact_length,
                 clearance, density, modulus, poisson):
    """Inner-raceway load at ``Z x 20`` orbit positions from the load line, the centrifugal
    force and the load distribution's status per point (the most severe over its cage
    positions), from the load distribution at 20 cage positions per roller pitch
    (``crb_radial``, straight rollers, whose validity the status carries: the contact
    pressure with these elastic constants, the rollers' approach)."""
    points = load.size
    positions = 2.0 * np.pi / roller_count * np.arange(_POSITIONS_PER_PITCH) / \
        _POSITIONS_PER_PITCH

    def repeat(a):
        return np.repeat(a, _POSITIONS_PER_PITCH)

    result = crb_radial(repeat(load), roller_count, repeat(pitch_diameter), repeat(diameter),
                        repeat(contact_length), clearance=repeat(clearance), slices=1,
                        speed=repeat(omega_i), roller_density=repeat(density),
                        cage_position=np.tile(positions, points),
                        youngs_modulus=repeat(modulus), poisson_ratio=repeat(poisson))
    # Roller j at cage position m sits at m + 2 pi j / Z: interleave to orbit order.
    per_roller = result["roller_load"].reshape(points, _POSITIONS_PER_PITCH, roller_count)
    inner = np.swapaxes(per_roller, 1, 2).reshape(points, -1)
    centrifugal = result["centrifugal_force"].reshape(points, _POSITIONS_PER_PITCH)[:, 0]
    status = combine_status(*np.reshape(result["status"], (points, -1)).T)
    return inner, centrifugal, status


def _secant_root(residual, lower, upper, tolerance):
    """Roots of increasing functions by secant steps kept inside a shrinking bracket: the
    slope is that through each entry's last two evaluations (bisection until there are two).
    ``residual(x, index)`` returns the values only."""
    last_x = np.full(np.size(lower), np.nan)
    last_value = np.full(np.size(lower), np.nan)

    def with_secant(x, index):
        value = residual(x, index)
        with np.errstate(divide="ignore", invalid="ignore"):
            slope = (value - last_value[index]) / (x - last_x[index])
        last_x[index], last_value[index] = x, value
        return value, slope

    return solve_increasing(with_secant, lower, upper, 0.5 * (lower + upper), tolerance)


def _several(equilibrium_count):
    return equilibrium_count >= 2


def _rollers_fit(roller_count, inner_raceway_diameter, roller_diameter):
    return (inner_raceway_diameter + roller_diameter) * np.sin(np.pi / roller_count) \
        > roller_diameter


def _cage_between(cage_inner_diameter, cage_outer_diameter):
    return cage_outer_diameter > cage_inner_diameter


def _traction_peaks(traction_peak, traction_limit):
    return traction_peak > traction_limit


def _contact_on_roller(effective_length, roller_length):
    return effective_length <= roller_length


def _pockets_hold_rollers(cage_width, roller_length):
    return (cage_width == 0) | (cage_width >= roller_length)


def _outer_raceway_diameter(inner_raceway_diameter, roller_diameter, clearance):
    return inner_raceway_diameter + 2.0 * roller_diameter + clearance


def _cage_between_raceways(cage_inner_diameter, cage_outer_diameter, inner_raceway_diameter,
                           roller_diameter, clearance):
    return (cage_inner_diameter >= inner_raceway_diameter) & (
        cage_outer_diameter <= _outer_raceway_diameter(inner_raceway_diameter, roller_diameter,
                                                       clearance))


def _pitch_diameter(inner_raceway_diameter, roller_diameter, clearance):
    return 0.5 * (inner_raceway_diameter + _outer_raceway_diameter(
        inner_raceway_diameter, roller_diameter, clearance))


def _cage_across_pitch_circle(cage_inner_diameter, cage_outer_diameter,
                              inner_raceway_diameter, roller_diameter, clearance):
    pitch = _pitch_diameter(inner_raceway_diameter, roller_diameter, clearance)
    return (cage_inner_diameter < pitch) & (pitch < cage_outer_diameter)


def _pockets_fit(pocket_clearance, roller_count, inner_raceway_diameter, roller_diameter,
                 clearance):
    pitch = _pitch_diameter(inner_raceway_diameter, roller_diameter, clearance)
    return roller_diameter + 2.0 * pocket_clearance < pitch * np.sin(np.pi / roller_count)


def films_out_of_form(roller_diameter, pocket_clearance, end_film_thickness):
    """Where the pocket clearance or the end film exceeds :data:`THIN_FILM_LIMIT` of the
    roller radius (outside the thin films' form) or lies below :data:`SMALLEST_FILM` (no
    full film)."""
    radius = 0.5 * np.asarray(roller_diameter)
    films = np.asarray(pocket_clearance), np.asarray(end_film_thickness)
    return ((films[0] > THIN_FILM_LIMIT * radius) | (films[1] > THIN_FILM_LIMIT * radius)
            | (films[0] < SMALLEST_FILM) | (films[1] < SMALLEST_FILM))


#: The validity cage_slip applies, and the transient models after it.
VALIDITY = ("the load distribution's (crb_radial at each cage position: a roller's contact "
            "pressure above 4000 MPa, ISO 76's reference stress for roller bearings, or its "
            "approach above 2 % of the roller diameter; whatever the outcome, "
            f"{STEEL_VALIDITY} (Palmgren's), {CLEARANCE_VALIDITY}); a pocket clearance or "
            "end film thicker than 10 % of the roller radius (the pocket and end films are "
            "Petroff's thin Couette films) or thinner than 1 um (no thicker than the "
            "surfaces' roughness: no full film); whatever the outcome, "
            f"{SPEED_VALIDITY}, or {OIL_VALIDITY}")

MODELS = [Model(
    name="cage_slip",
    function=cage_slip,
    summary="Cylindrical roller bearing in steady running: cage slip, roller slip around the "
            "orbit and roller spin from traction, oil films and windage.",
    reference="Paper 002 (eq. 27, roller windage); Harris (1966); Gupta (1984); "
              "CAGE_SLIP_PHYSICS.md for the published forms and typical values",
    version="6",
    inputs=(
        Input("radial_load", "N", "radial load Fr", minimum=0.0, exclusive_minimum=True),
        Input("speed", "rpm", "inner-ring speed", minimum=0.0, exclusive_minimum=True),
        Input("roller_count", "1", "number of rollers Z", kind="count", minimum=3, maximum=200),
        Input("inner_raceway_diameter", "mm", "inner raceway diameter di", minimum=0.0,
              exclusive_minimum=True),
        Input("roller_diameter", "mm", "roller diameter D", minimum=0.0, exclusive_minimum=True),
        Input("roller_length", "mm", "whole roller length (mass, pocket film)", minimum=0.0,
              exclusive_minimum=True),
        Input("effective_length", "mm", "raceway contact length", minimum=0.0,
              exclusive_minimum=True),
        Input("clearance", "mm", "diametral clearance Pd; outer raceway = di + 2D + Pd",
              minimum=0.0),
        Input("cage_inner_diameter", "mm", "cage bore", minimum=0.0, exclusive_minimum=True),
        Input("cage_outer_diameter", "mm", "cage outside diameter", minimum=0.0,
              exclusive_minimum=True),
        Input("cage_width", "mm", "cage width (0: no cage windage)", minimum=0.0),
        Input("roller_density", "kg/m^3", "roller density (rolling elements: 900 for "
              "polymers to 15700 for tungsten carbide)", default=7820.0,
              minimum=ROLLING_ELEMENT_DENSITIES[0], maximum=ROLLING_ELEMENT_DENSITIES[1]),
        Input("oil_temperature", "degC", "oil temperature (largest single influence)",
              default=25.0, minimum=-40.0, maximum=200.0),
        Input("viscosity_40", "mm^2/s", "kinematic viscosity at 40 degC (4050-class turbine "
              "oil: 26; ISO VG 2 to VG 3200, ISO 3448)", default=26.0,
              minimum=VISCOSITY_GRADES[0], maximum=VISCOSITY_GRADES[1]),
        Input("viscosity_100", "mm^2/s", "kinematic viscosity at 100 degC, below that at 40 "
              "degC (4050 class: 5.4)", default=5.4, minimum=WALTHER_FLOOR,
              exclusive_minimum=True),
        Input("oil_density", "kg/m^3", "oil density (lubricants: about 820 for light mineral "
              "oils to 1900 for perfluoropolyethers)", default=1000.0,
              minimum=OIL_DENSITIES[0], maximum=OIL_DENSITIES[1]),
        Input("pressure_viscosity", "1/GPa", "pressure-viscosity coefficient alpha (film "
              "thickness only; 10-13; lubricants: about 5 for water-glycols to 40 for "
              "traction fluids)", default=11.0, minimum=0.0, exclusive_minimum=True,
              maximum=100.0),
        Input("youngs_modulus", "GPa", "Young's modulus of rollers and rings", default=207.0,
              minimum=SOFTEST_BEARING_SOLID, maximum=STIFFEST_SOLID),
        Input("poisson_ratio", "1", "Poisson's ratio of rollers and rings", default=0.28,
              minimum=0.0, maximum=0.5),
        Input("traction_peak", "1", "peak traction coefficient mu_m (typical 0.05)",
              default=0.05, minimum=0.0, exclusive_minimum=True, maximum=TRACTION_LIMIT),
        Input("traction_peak_speed", "m/s", "sliding speed of the traction peak u_m "
              "(0.3-3)", default=2.0, minimum=0.0, exclusive_minimum=True),
        Input("traction_limit", "1", "high-slip traction coefficient mu_inf (typical 0.036)",
              default=0.036, minimum=0.0, maximum=TRACTION_LIMIT),
        # The shares (oil_fraction, the film fills) lie in 0-1 by their definition. The pocket's
        # Coulomb coefficient: steel on brass, steel or polyamide, 0.05-0.2 lubricated, up to
        # 0.5-0.8 dry (steel on steel; F. P. Bowden, D. Tabor, The Friction and Lubrication of
        # Solids, Oxford (1950)): 1 bounds every pair a cage pocket holds.
        Input("oil_fraction", "1", "oil's share of the cavity volume (0.01-0.5)", default=0.05,
              minimum=0.0, maximum=1.0),
        Input("drag_coefficient", "1", "roller windage drag coefficient C_D (0.5-2; a "
              "cylinder's reaches 10 at a Reynolds number of 1, where drag turns viscous)",
              default=1.0, minimum=0.0, maximum=DRAG_COEFFICIENT_LIMIT),
        Input("pocket_clearance", "mm", "pocket clearance c_p", default=0.1, minimum=0.0,
              exclusive_minimum=True),
        Input("pocket_wrap_angle", "rad", "pocket arc wrapped around the roller theta_w "
              "(a pocket closed around it: 2 pi)",
              default=1.0, minimum=0.0, maximum=2 * np.pi,
              label="pocket wrap angle"),
        Input("pocket_film_fill", "1", "share of the pocket arc under oil phi_p (flooded: 1)",
              default=1.0, minimum=0.0, maximum=1.0),
        Input("end_film_thickness", "mm", "film at the roller ends h_e (rib axial play)",
              default=0.015, minimum=0.0, exclusive_minimum=True),
        Input("end_film_fill", "1", "share of the end faces running on the film phi_e "
              "(relieved ends: 0.25)", default=0.25, minimum=0.0, maximum=1.0,
              label="end film fill"),
        Input("pocket_friction", "1", "Coulomb coefficient of pocket contact mu_p (0-0.2)",
              default=0.1, minimum=0.0, maximum=1.0,
              label="pocket friction coefficient"),
        Input("orbit_points", "1", "orbit positions for roller_slip", default=72,
              kind="count", minimum=4, maximum=3600),
        Input("branch", "1", "equilibrium returned where there are several: high_slip (the "
              "lowest stable cage speed, reached from rest) or low_slip (the highest)",
              default="high_slip", kind="choice", choices=BRANCHES),
    ),
    outputs=(
        Output("cage_slip", "percent", "cage slip 1 - omega_c / omega_c,kin (eq. 27)",
               label="cage slip"),
        Output("cage_speed", "rpm", "cage speed"),
        Output("roller_slip", "percent", "roller spin slip against kinematic spin, around the "
               "orbit", dims=("orbit",)),
        Output("orbit_angle", "deg", "orbit position from the load line", dims=("orbit",)),
        Output("roller_spin_ratio", "percent", "mean roller spin over kinematic spin"),
        Output("torque_residual", "N*m", "residual of the cage's torque balance"),
        Output("film_thickness", "um", "central EHL film at the most loaded inner contact",
               label="central film thickness"),
        Output("max_roller_load", "N", "largest roller load at the inner raceway"),
        Output("equilibrium_count", "1", "stable equilibria of the cage's torque balance "
               "found (2 or more: a hysteresis band; 0: the rollers cannot drive the cage)",
               label="stable equilibria", dtype="int",
               counted=("points with several stable equilibria", _several)),
    ),
    dim_sizes={"orbit": "orbit_points"},
    constraints=(
        Constraint(("roller_count", "inner_raceway_diameter", "roller_diameter"), _rollers_fit,
                   "the rollers do not fit on the pitch circle"),
        Constraint(("cage_inner_diameter", "cage_outer_diameter"), _cage_between,
                   "cage_outer_diameter must exceed cage_inner_diameter"),
        Constraint(("traction_peak", "traction_limit"), _traction_peaks,
                   "traction_peak must exceed traction_limit"),
        Constraint(("effective_length", "roller_length"), _contact_on_roller,
                   "effective_length must not exceed roller_length: the raceway contact is "
                   "part of the roller"),
        Constraint(("cage_width", "roller_length"), _pockets_hold_rollers,
                   "cage_width must be at least roller_length (or 0: no cage windage): the "
                   "cage's pockets hold the whole rollers"),
        CLEARANCE_BELOW_ROLLER,  # crb_radial's, whose load distribution this model takes
        Constraint(("cage_inner_diameter", "cage_outer_diameter", "inner_raceway_diameter",
                    "roller_diameter", "clearance"), _cage_between_raceways,
                   "the cage must lie between the raceways: cage_inner_diameter at least "
                   "inner_raceway_diameter, cage_outer_diameter at most the outer raceway "
                   "(inner_raceway_diameter + 2 roller_diameter + clearance)"),
        Constraint(("cage_inner_diameter", "cage_outer_diameter", "inner_raceway_diameter",
                    "roller_diameter", "clearance"), _cage_across_pitch_circle,
                   "the cage must reach across the rollers' pitch circle, whose diameter is "
                   "inner_raceway_diameter + roller_diameter + clearance / 2, to hold their "
                   "centres in its pockets: cage_inner_diameter below it, cage_outer_diameter "
                   "above it"),
        Constraint(("pocket_clearance", "roller_count", "inner_raceway_diameter",
                    "roller_diameter", "clearance"), _pockets_fit,
                   "the pockets do not fit: each, roller_diameter + 2 pocket_clearance wide, "
                   "must leave a cage bar before the next, whose centre lies pitch_diameter * "
                   "sin(180 deg / roller_count) away"),
        VISCOSITY_ORDER,
    ),
    seconds_per_point=1.3e-3,  # measured by benchmarks/declared_costs.py
    points_per_call=64,
    validity=VALIDITY,
)]
