"""Cylindrical roller bearing under radial load: load distribution and radial stiffness.

Outer ring fixed, inner ring displaced radially by ``delta_r``; crowned rollers cut into
slices, centrifugal force from the inner-ring speed, diametral clearance (paper 000).
"""
from __future__ import annotations

import numpy as np

from .bearing_film import (FILM_INPUTS, MINERAL_OIL_DENSITY, bearing_film, film_outputs,
                           oil_viscosity)
from .bearing_life import (DEFAULT_CONTAMINATION_FACTOR, LIFE_CONSTRAINTS, LIFE_INPUTS,
                           life_outputs,
                           rating_lives)
from .contact import (APPROACH_LIMIT, LINE_CONTACT_EXPONENT,
                      ROLLER_PRESSURE_LIMIT, SLICE_LAWS, STIFFEST_SOLID, effective_modulus,
                      largest_slice_line_load, line_contact_pressure, palmgren_constant,
                      slice_loads)
from .friction import (bearing_friction, friction_constraints, friction_inputs,
                       friction_outputs)
from .geometry import clearance_below_roller, elements_fit
from .life import roller_bearing_reference_life
from .limits import (CLEARANCE_VALIDITY, OIL_VALIDITY, ROLLING_ELEMENT_DENSITIES,
                     SOFTEST_BEARING_SOLID, SPEED_VALIDITY, STEEL_VALIDITY,
                     clearance_beyond_bearings, not_steel, outside_operation)
from .lubrication import (CELSIUS, MINERAL_OIL_PRESSURE_VISCOSITY, entrainment_speed,
                          line_contact_film, walther_viscosity)
from .operating_clearance import (BEARING_STEEL_EXPANSION, OPERATING_INPUTS,
                                  REFERENCE_TEMPERATURE, mounted_clearance,
                                  operating_constraints, operating_outputs)
from .profiles import PROFILES, crown_shape, distinct_slices, slice_centres
from .registry import (CONVERGED, NOT_CONVERGED, OUT_OF_VALIDITY, Constraint, Input,
                             Model, Output)
from .static_safety import STATIC_INPUTS, roller_rating, static_outputs, static_safety

OUTER_CONTACTS = ("crowned", "paper")

_NO_GAP = np.zeros(1)
_ONE_SLICE = np.ones(1)
# A roller counts as loaded when it carries more than this fraction of the radial load.
_LOADED_FRACTION = 1e-9
_XTOL = 1e-13  # relative tolerance of the displacement solves [-]
#: Iterations of the ring's solve and of a free roller's before they are given up.
_MAX_ITERATIONS = 200
#: Largest error of the forward-difference stiffness, estimated as half the change of the
#: analytic stiffness across its step (the leading term of a forward difference's error), as
#: a share of the stiffness [-]: the step must be small against the displacement over which
#: the stiffness changes. Paper 000's 0.001 mm on bearing C at 4 kN errs by 1 % (section 2.3
#: states 1.3 %).
PERTURBATION_ERROR_LIMIT = 0.02
#: Largest estimated error that the slicing may leave in a crowned or tilted roller's outputs
#: (radial load and stiffness at the solved displacement, contact pressure, the laminae's life
#: sum), as a share of each [-]: :meth:`_RollerSet.slicing_error`. One slice ignores crown and
#: tilt (bearing D at 4 kN and 5 mrad: L10r 80 times, pressure 0.45 times the converged
#: values); paper 000's 60 slices (section 3: "k = 60 suffice for rollers shorter than
#: 100 mm", our study slices_convergence: within 0.5 % of 1000 slices in stiffness) stay below
#: 1.5 % at its crowns and loads and at 5 mrad.
SLICING_ERROR_LIMIT = 0.02
#: Fewest slices of the reference slicing against which the model's are judged: 240 lie
#: within 0.1 % of 1000 in the study slices_convergence.
REFERENCE_SLICES = 240


def cage_speed(speed, roller_diameter, pitch_diameter):
    """Orbital speed of the rollers with the inner ring turning and the outer ring fixed.

    Parameters
    ----------
    speed : array_like
        Inner-ring speed ``omega_i`` [rad/s].
    roller_diameter, pitch_diameter : array_like
        ``D`` and ``d_m`` [m].

    Returns
    -------
    numpy.ndarray
        ``omega_c = omega_i / 2 (1 - D/d_m)`` [rad/s] (eq. 4 of [1], zero contact angle).

    References
    ----------
    .. [1] Paper 000, eq. 4; T. A. Harris, Rolling Bearing Analysis, ch. 8.
    """
    ratio = np.asarray(roller_diameter) / np.asarray(pitch_diameter)
    return 0.5 * np.asarray(speed) * (1.0 - ratio)


def centrifugal_force(roller_diameter, effective_length, pitch_diameter, speed, roller_density):
    """Centrifugal force of one cylindrical roller on its orbit.

    Parameters
    ----------
    roller_diameter, effective_length, pitch_diameter : array_like
        ``D``, ``l``, ``d_m`` [m].
    speed : array_like
        Inner-ring speed [rad/s].
    roller_density : array_like
        ``rho`` [kg/m^3].

    Returns
    -------
    numpy.ndarray
        ``F_c = m omega_c^2 d_m / 2`` with ``m = rho pi D^2 l / 4`` [N]; the same as eq. 3 of
        [1], ``pi^3 rho D^2 l d_m n_m^2 / 7200`` with ``n_m`` in r/min.

    References
    ----------
    .. [1] Paper 000, eq. 3.
    """
    mass = roller_density * np.pi / 4.0 * np.asarray(roller_diameter) ** 2 * effective_length
    orbit = cage_speed(speed, roller_diameter, pitch_diameter)
    return mass * orbit**2 * np.asarray(pitch_diameter) / 2.0


class _RollerSet:
    """The rollers of ``P`` bearings (one per grid point): geometry and contact laws."""

    def __init__(self, cos_azimuth, half_clearance, crown, constant, centrifugal,
                 slices, crown_profile, slice_law, outer_contact, tilt=None, sliced=False):
        self.cos = cos_azimuth  # (P, Z)
        self.half_clearance, self.crown = half_clearance, crown  # (P,)
        self.constant, self.centrifugal = constant, centrifugal  # (P,)
        # tilt: (P, Z) gap change from the middle to the end of each roller's contacts; kept
        # ``sliced`` (every slice its own, where they lie) even where it is zero.
        self.tilt = tilt if tilt is not None and (sliced or np.any(tilt != 0.0)) else None
        # Approaches are counted at each roller's slice with the smallest gap, so that every
        # gap is >= 0 and a roller touches when its approach does; a tilted roller's deepest
        # slice lies towards an end, 2 * floor nearer the raceways than its middle.
        if self.tilt is None:  # a symmetric roller: its distinct slices with their counts
            self.gap_shape, self.gap_count = distinct_slices(slices, crown_profile)  # (m,)
            self.floor = np.zeros((self.crown.size, 1))  # its smallest gap is its middle's
        else:
            self.gap_shape, self.gap_count = crown_shape(slices, crown_profile), np.ones(slices)
            self.slice_position = slice_centres(slices)
            raw = (self.crown[:, None, None] * self.gap_shape
                   - self.tilt[..., None] * self.slice_position)
            self.floor = raw.min(axis=-1)  # (P, Z): smallest gap
        self.slice_law, self.outer_contact = slice_law, outer_contact
        self.slices, self.crown_profile = slices, crown_profile
        # Each roller's gaps in rising order, as the compiled balance sums the touching ones
        # (``(P, 1, m)`` without tilt, where the distinct gaps already rise); in
        # :meth:`gaps`' order of operations, so that both give the same bits.
        if self.tilt is None:
            self.sorted_gaps = np.ascontiguousarray(self.all_gaps())
        else:
            raw -= self.floor[..., None]
            raw.sort(axis=-1)
            self.sorted_gaps = raw
        self.free_outer_approach, self.free_outer_converged = self._free_outer_approach()

    def tilted(self, points, tilt, sliced=False):
        """The rollers of the bearings ``points``, one bearing per row, tilted by ``tilt``
        ``(p, Z)``: each roller's gap change from the middle to the end of its contacts [m]
        (a ring tilted by ``theta`` across a roller gives ``theta l / 4``: the roller takes
        half). ``sliced``: every slice kept where it lies, even without a tilt (what a
        moment against the tilt sums)."""
        return _RollerSet(self.cos[points], self.half_clearance[points], self.crown[points],
                          self.constant[points], self.centrifugal[points], self.slices,
                          self.crown_profile, self.slice_law, self.outer_contact, tilt,
                          sliced)

    def gaps(self, points, rollers):
        """Gap of every slice of the rollers ``rollers`` of the bearings ``points`` [m],
        ``points.shape + (m,)`` (index arrays broadcast), counted from each roller's
        smallest (so ``>= 0``)."""
        gaps = self.crown[points][..., None] * self.gap_shape
        if self.tilt is None:
            return gaps
        # In this order the smallest gap is exactly zero: the floor is that very difference.
        return (gaps - self.tilt[points, rollers][..., None] * self.slice_position
                - self.floor[points, rollers][..., None])

    def all_gaps(self):
        """:meth:`gaps` of every roller of every bearing, ``(P, Z or 1, m)``."""
        points, rollers = np.arange(self.crown.size)[:, None], np.arange(self.cos.shape[1])
        return self.gaps(points, rollers)

    @property
    def largest_gap(self):
        """Largest slice gap of each bearing [m], ``(P,)``."""
        tilt = 0.0 if self.tilt is None else 2.0 * np.abs(self.tilt).max(axis=-1)
        return self.crown * self.gap_shape.max() + tilt

    def total_approach(self, displacement, points):
        """Approach of both contacts of every roller together at its deepest slice [m],
        ``(p, Z)`` (eq. 1)."""
        total = displacement[:, None] * self.cos[points] - self.half_clearance[points, None]
        return total if self.tilt is None else total - 2.0 * self.floor[points]

    def approaches(self, displacement, inner_deflection):
        """Inner and outer contact approach of every roller [m], ``(P, Z)``, at the solution.

        ``inner_deflection`` is :meth:`loads`' (negative: a gap). A roller the ring does not
        reach presses on the outer raceway with its centrifugal force alone.
        """
        total = self.total_approach(displacement, np.arange(displacement.size))
        free = self.free_outer_approach
        loaded = total - free > 0.0
        return np.maximum(inner_deflection, 0.0), np.where(loaded, total - inner_deflection,
                                                           free)

    def largest_line_loads(self, inner_approach, outer_approach, length):
        """Load per unit length of the most loaded slice of each contact [N/m], ``(P, Z)``."""
        constant, length = self.constant[:, None], length[:, None]
        gaps = self.all_gaps()
        inner = largest_slice_line_load(inner_approach, gaps, self.gap_count, constant, length,
                                        self.slice_law)
        if self.outer_contact == "crowned":
            outer = largest_slice_line_load(outer_approach, gaps, self.gap_count, constant,
                                            length, self.slice_law)
        else:
            outer = largest_slice_line_load(outer_approach, _NO_GAP, _ONE_SLICE, constant,
                                            length)
        return inner, outer

    def lamina_loads(self, inner_approach, outer_approach, points):
        """Load of every distinct slice of both contacts of the bearings ``points`` [N],
        ``(p, Z, m)`` each; the slices of a gap number ``gap_count``. The straight outer
        contact of ``'paper'`` is cut into as many equal slices."""
        constant = self.constant[points, None]
        gaps = self.all_gaps()[points]
        inner = slice_loads(inner_approach, gaps, self.gap_count, constant, self.slice_law)
        if self.outer_contact == "paper":
            gaps = np.zeros_like(gaps[:, :1])
        return inner, slice_loads(outer_approach, gaps, self.gap_count, constant,
                                  self.slice_law)

    def slicing_error(self, inner_approach, outer_approach, inner_curvature, outer_curvature,
                      asked=True):
        """Estimated relative error that the slicing leaves in the outputs of each bearing
        ``(P,)`` [-]: the largest of those in its loaded rollers' radial load and stiffness
        (so its displacement and stiffness), its largest contact pressure and its laminae's
        life sums, the ``k`` slices against the same contacts cut into ``max(4 k, 240)``
        (:data:`REFERENCE_SLICES`).

        Load and stiffness are compared at the solved approaches; pressure and life at the
        same roller loads (the finer slicing's approach moved by one Newton step to carry
        the load the ``k`` slices carry), as the ring's balance makes them: a roller whose
        slices carry 1 % too much settles 1 % shallower, and its life sum, which grows as
        the fifth power of the approach, moves by some 4 %. The finer slicing errs by a
        fraction of the coarser's (a quarter where the error falls as 1/k, at a contact's
        edge; a sixteenth where it falls as 1/k^2), so the difference estimates the error of
        the ``k`` slices. A straight, aligned roller's slices are all alike and any ``k``
        gives it exactly: zero. ``inner_curvature``, ``outer_curvature``: ``sum(rho)`` of
        each contact [1/m], ``(P,)``. Only the bearings ``asked`` (``(P,)`` bool) are
        estimated; the others' error is zero.
        """
        from .cylindrical_balance import slice_sums  # numba: only when solving

        error = np.zeros(self.crown.size)
        tilted = False if self.tilt is None else np.any(self.tilt != 0.0, axis=-1)
        profiled = np.flatnonzero(((self.crown > 0.0) | tilted) & asked
                                  & np.all(np.isfinite(inner_approach), axis=-1))
        loaded = inner_approach[profiled] > 0.0  # (p, Z)
        rows, rollers = np.nonzero(loaded)
        if rows.size == 0:
            return error
        points = profiled[rows]
        fine = max(4 * self.slices, REFERENCE_SLICES)
        crown = np.ascontiguousarray(self.crown[points])
        if self.tilt is None:  # symmetric rollers: their distinct slices, rising
            tilt = floor = np.zeros(points.size)
            fine_shape, fine_counts = distinct_slices(fine, self.crown_profile)
            slicings = ((self.gap_shape, np.zeros(self.gap_shape.size), self.gap_count),
                        (fine_shape, np.zeros(fine_shape.size), fine_counts))
        else:
            tilt = np.ascontiguousarray(self.tilt[points, rollers])
            floor = np.ascontiguousarray(self.floor[points, rollers])
            slicings = ((self.gap_shape, self.slice_position, self.gap_count),
                        (crown_shape(fine, self.crown_profile), slice_centres(fine),
                         np.ones(fine)))
        by_loaded = self.slice_law == "paper"

        def per_roller(values):  # (p, Z), zero where a roller is not loaded
            dense = np.zeros(loaded.shape)
            dense[rows, rollers] = values
            return dense

        n, cos = LINE_CONTACT_EXPONENT, per_roller(self.cos[points, rollers])
        departures, stiffness = [], []
        inner_rows = inner_sums = None  # the inner contact's, which the outer one reuses
        for contact, approach, curvature in (("inner", inner_approach, inner_curvature),
                                             ("outer", outer_approach, outer_curvature)):
            approach = np.ascontiguousarray(approach[points, rollers])
            if contact == "outer" and self.outer_contact == "paper":
                # Eq. 6's straight outer contact, K delta^n: exact at any k.
                stiffness.append([per_roller(n * approach ** (n - 1.0))] * 2)
                continue
            sliced, finer = np.empty((2, approach.size, 6))
            fresh = np.ones(approach.size, dtype=bool)
            if contact == "outer":  # without centrifugal force both contacts are alike
                fresh = np.abs(approach - inner_rows) > 1e-9 * inner_rows
                sliced[:], finer[:] = inner_sums
            for sums, (shape, position, counts) in zip((sliced, finer), slicings):
                if fresh.any():
                    part = np.empty((np.count_nonzero(fresh), 6))
                    slice_sums(approach[fresh], crown[fresh], tilt[fresh], floor[fresh], shape,
                               position, counts, by_loaded, self.tilt is None, part)
                    sums[fresh] = part
            inner_rows, inner_sums = approach, (sliced, finer)
            stiffness.append([per_roller(sums[:, 1]) for sums in (sliced, finer)])
            if contact == "inner":  # the ring's load at the solved approaches
                load = [(cos * per_roller(sums[:, 0])).sum(axis=-1) for sums in (sliced, finer)]
            with np.errstate(divide="ignore", invalid="ignore"):
                shift = np.nan_to_num((sliced[:, 0] - finer[:, 0]) / finer[:, 1])
            # A roller's approach lies between the two: set by its load where the ring's
            # balance sets it, by the geometry where a tilt loads both sides of the ring.
            for moved in (np.zeros_like(shift), shift):
                with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
                    line_loads = (sliced[:, 3] * sliced[:, 2] ** n, finer[:, 3] * np.maximum(
                        finer[:, 2] + moved, 0.0) ** n)
                    lives = sliced[:, 4], finer[:, 4] + moved * finer[:, 5]
                    pressure = [per_roller(value).max(axis=-1) for value in line_loads]
                    life = [per_roller(value).sum(axis=-1) for value in lives]
                    departures += [np.abs(np.sqrt(pressure[0] / pressure[1]) - 1.0),
                                   np.abs((life[0] / life[1]) ** (-8.0 / 9.0) - 1.0)]
        # The ring's stiffness: each roller's two contacts in series.
        (inner_sliced, inner_finer), (outer_sliced, outer_finer) = stiffness
        with np.errstate(divide="ignore", invalid="ignore"):
            radial = [(cos**2 * np.nan_to_num(inner * outer / (inner + outer))).sum(axis=-1)
                      for inner, outer in ((inner_sliced, outer_sliced),
                                           (inner_finer, outer_finer))]
            departures += [np.abs(load[0] / load[1] - 1.0),
                           np.abs(radial[0] / radial[1] - 1.0)]
        error[profiled] = np.fmax.reduce(np.stack(departures), axis=0)
        return error

    def _free_outer_approach(self):
        """Outer-contact approach of a roller held by its centrifugal force alone [m],
        ``(P, 1)``, or ``(P, Z)`` with tilt (each roller's own gaps, so that a roller the ring
        begins to load has a bracketed force balance), and whether each point's was found
        ``(P,)``."""
        from .cylindrical_balance import free_outer_approaches  # numba: only when solving

        n = LINE_CONTACT_EXPONENT
        plain = (self.centrifugal / self.constant) ** (1.0 / n)
        if self.outer_contact == "paper":
            return plain[:, None], np.isfinite(plain)
        approach = np.zeros(self.sorted_gaps.shape[:2])
        converged = np.repeat(np.isfinite(plain)[:, None], approach.shape[1], axis=1)
        # Every slice is in contact beyond the largest gap, so Qo >= K (delta - gap)^n.
        free_outer_approaches(self.sorted_gaps, self.gap_count, self.constant, self.centrifugal,
                              self.slice_law == "paper", self.largest_gap + plain, _XTOL,
                              approach, converged, _MAX_ITERATIONS)
        return approach, converged.all(axis=-1)

    def loads(self, displacement, points, split, roller_load, inner_deflection):
        """Roller loads and bearing load and stiffness at given radial displacements.

        Parameters
        ----------
        displacement : numpy.ndarray
            Radial displacement ``delta_r`` of the bearings ``points`` [m], shape ``(p,)``.
        points : numpy.ndarray
            Indices of the bearings evaluated.
        split : numpy.ndarray
            Each roller's last solution, from which its solve starts: inner approach, total
            approach and their derivative (NaN: none yet), shape ``(P, Z, 3)``; its rows
            ``points`` updated in place with the solution.
        roller_load, inner_deflection : numpy.ndarray
            ``(P, Z)``, their rows ``points`` filled: ``Qi_j`` [N] and the inner-contact
            approach [m] (negative: the gap of an unloaded roller).

        Returns
        -------
        radial_load, radial_stiffness : numpy.ndarray
            ``F_r = sum Qi_j cos phi_j`` (eq. 10) [N] and ``dF_r/d delta_r`` [N/m], ``(p,)``.
        converged : numpy.ndarray of bool
            Every roller's force balance converged, ``(p,)``.
        """
        from .cylindrical_balance import roller_balances  # numba: only when solving

        # Roller force balance Qo(total - inner) = Qt(inner) + Fc (eq. 2, 6).
        return roller_balances(
            displacement, points, self.cos, self.half_clearance,
            self.floor, self.free_outer_approach,
            self.sorted_gaps, self.gap_count, self.constant, self.centrifugal,
            self.slice_law == "paper", self.outer_contact == "crowned", _XTOL, split,
            roller_load, inner_deflection)


    def balance(self, load, lower, upper, preloaded, perturbation, split, *filled):
        """The ring's balance of every bearing under ``load`` in its bracket
        ``[lower, upper]`` (widened where ``preloaded``), with the forward difference's state
        where ``perturbation`` is finite: :func:`models.cylindrical_balance.ring_balances`,
        which fills ``filled``."""
        from .cylindrical_balance import ring_balances  # numba: only when solving

        ring_balances(load, lower, upper, preloaded, perturbation, self.cos,
                      self.half_clearance, self.floor, self.free_outer_approach,
                      self.sorted_gaps, self.gap_count, self.constant, self.centrifugal,
                      self.slice_law == "paper", self.outer_contact == "crowned", _XTOL, split,
                      *filled, _MAX_ITERATIONS)

def crb_radial(radial_load, roller_count, pitch_diameter, roller_diameter, effective_length,
               clearance=0.0, crown=0.0, crown_profile="logarithmic", slices=60,
               slice_law="uniform", outer_contact="crowned", speed=0.0, roller_density=7850.0,
               contact_constant=None, cage_position=0.0, misalignment=0.0, perturbation=None,
               youngs_modulus=207e9, poisson_ratio=0.3, pressure_limit=ROLLER_PRESSURE_LIMIT,
               dynamic_load_rating=None, fatigue_load_limit=None,
               contamination_factor=DEFAULT_CONTAMINATION_FACTOR,
               oil_temperature=70.0 + CELSIUS, viscosity_40=None, viscosity_100=None,
               oil_density=MINERAL_OIL_DENSITY,
               pressure_viscosity=MINERAL_OIL_PRESSURE_VISCOSITY, composite_roughness=None,
               minimum_static_safety=None, shaft_fit=0.0, housing_fit=0.0, bore=None,
               outside_diameter=None, shaft_bore=0.0, housing_outside_diameter=None,
               inner_ring_temperature=REFERENCE_TEMPERATURE,
               outer_ring_temperature=REFERENCE_TEMPERATURE, shaft_temperature=None,
               housing_temperature=None, shaft_youngs_modulus=207e9, shaft_poisson_ratio=0.3,
               shaft_expansion=BEARING_STEEL_EXPANSION, housing_youngs_modulus=207e9,
               housing_poisson_ratio=0.3, housing_expansion=BEARING_STEEL_EXPANSION,
               friction_method="skf", lubrication_method="oil_bath",
               skf_rolling_constant_1=None, skf_sliding_constant_1=None,
               skf_sliding_constant_2=None, boundary_friction_coefficient=0.15,
               full_film_friction_coefficient=0.02, palmgren_speed_factor=None,
               palmgren_load_factor=None, oil_level=None, drag_loss_factor=None,
               bearing_width=None):
    """Load distribution, radial stiffness, contact pressure, lubricant film, friction and
    rating life of a cylindrical roller bearing.

    Solves the inner ring's radial displacement under a radial load, with crowned rollers
    cut into slices, centrifugal force and clearance, and the radial stiffness by implicit
    differentiation (exact derivative of the solved load-displacement relation). All numeric
    inputs broadcast against each other; counts and choices are scalars.

    Parameters
    ----------
    radial_load : array_like
        Radial load ``F_r`` on the inner ring [N].
    roller_count : int
        Number of rollers ``Z`` [-].
    pitch_diameter, roller_diameter, effective_length : array_like
        ``d_m``, ``D``, ``l`` [m].
    clearance : array_like
        Diametral clearance ``P_d`` [m]; negative for a preloaded bearing.
    crown : array_like
        Crown drop at the roller ends ``c_max`` [m].
    crown_profile : {'logarithmic', 'none'}
        Crown profile, eq. 8.
    slices : int
        Number of slices ``k`` [-].
    slice_law : {'uniform', 'paper'}
        How the slices share the roller's constant; see
        :func:`models.contact.sliced_line_contact`.
    outer_contact : {'crowned', 'paper'}
        ``'crowned'`` (default): both raceway contacts are the crowned roller's and the roller
        is in force balance, ``Qo = Qi + Fc``. ``'paper'``: eq. 6 as printed, a straight outer
        contact loaded by ``Fc + K delta_i^n``; the same as ``'crowned'`` without crown.
    speed : array_like
        Inner-ring speed [rad/s].
    roller_density : array_like
        Roller density ``rho`` [kg/m^3].
    contact_constant : array_like or None
        Whole-roller constant ``K`` of one contact, ``Q = K delta^(10/9)`` [N/m^(10/9)];
        None: Palmgren's ``8.06e4 l^(8/9)`` (N, mm).
    cage_position : array_like
        Azimuth of roller 1 from the load direction [rad]; roller ``j`` sits at
        ``cage_position + 2 pi (j - 1) / Z``.
    misalignment : array_like
        Tilt of the inner ring against the outer ring about the axis across the load
        direction [rad] (a shaft's slope). Each roller is free to tilt and takes half of it,
        so both its contacts see a gap ``c_lambda - (theta / 2) cos(phi_j) x_lambda l / 2``
        that grows linearly along it (exact without centrifugal force, where both contacts
        carry the same load; the roller's moment balance is not solved with it). The ring's
        moment is not balanced: the misalignment is imposed, as a shaft imposes it. Needs
        ``outer_contact='crowned'``.
    perturbation : array_like or None
        Displacement step ``Delta`` of the forward-difference stiffness [m] (section 2.3;
        the paper's is 1e-6); None: no forward-difference stiffness (NaN).
    youngs_modulus, poisson_ratio : array_like
        ``E`` [Pa] and ``nu`` [-] of rollers and rings. They enter the contact pressure only;
        the load-deflection constant is ``contact_constant`` (Palmgren's default is for
        steel: see Validity).
    pressure_limit : array_like
        Contact pressure above which a point is ``out_of_validity`` [Pa] (default 4000 MPa,
        ISO 76's reference stress for roller bearings of through-hardened steel).
    dynamic_load_rating, fatigue_load_limit : array_like or None
        ``C_r``, ``C_u`` [N]; None: no life (no modified life) (NaN).
    contamination_factor : array_like
        ``e_C`` [-] (ISO 281 Table 13).
    oil_temperature, viscosity_40, viscosity_100 : array_like or None
        Oil temperature [K] and kinematic viscosities at 40 and 100 deg C [m^2/s]; None: no
        modified life and no film.
    oil_density, pressure_viscosity : array_like
        Of the oil at its temperature [kg/m^3], [1/Pa], for the film.
    composite_roughness : array_like or None
        ``sigma`` of rollers and raceways [m], for the film parameter; None: NaN.
    minimum_static_safety : array_like or None
        The smallest ``pressure_safety_factor`` the application needs [-]; None: no check.
    shaft_fit, housing_fit, bore, outside_diameter, shaft_bore, housing_outside_diameter,
    inner_ring_temperature, outer_ring_temperature, shaft_temperature, housing_temperature,
    shaft_youngs_modulus, shaft_poisson_ratio, shaft_expansion, housing_youngs_modulus,
    housing_poisson_ratio, housing_expansion : array_like or None
        The bearing as mounted, for its operating clearance
        (:func:`models.operating_clearance.operating_clearance`; lengths [m], temperatures
        [K], moduli [Pa], expansion coefficients [1/K]): the load distribution takes the
        operating clearance in place of ``clearance``, the raceways ``d_m -+ D``.
    friction_method, lubrication_method, skf_rolling_constant_1, skf_sliding_constant_1,
    skf_sliding_constant_2, boundary_friction_coefficient, full_film_friction_coefficient,
    palmgren_speed_factor, palmgren_load_factor, oil_level, drag_loss_factor,
    bearing_width : str or array_like or None
        The friction torque's method and constants (:func:`models.friction.bearing_friction`,
        SKF's in its units; coefficients and factors [-]; level and width [m]); the bearing
        carries no axial load.

    Returns
    -------
    dict of numpy.ndarray
        ``radial_displacement`` [m], ``radial_stiffness`` [N/m], ``perturbation_stiffness``
        ``(F_r(delta_r + Delta) - F_r) / Delta`` [N/m], ``loaded_rollers`` [-],
        ``centrifugal_force`` [N], ``roller_load`` (inner contact, ``(..., Z)``) [N],
        ``inner_contact_deflection`` (``(..., Z)``, negative: gap) [m],
        ``max_contact_pressure`` (``(..., Z)``) [Pa], ``largest_contact_pressure`` [Pa], the
        films of :func:`models.bearing_film.bearing_film` [m, -], the operating clearance and
        its parts of :func:`models.operating_clearance.operating_clearance` [m], ISO 76's
        rating of :func:`models.static_safety.roller_rating` [N, -], the static safety of
        :func:`models.static_safety.static_safety` [-], the lives of
        :func:`models.bearing_life.rating_lives` [rad, s], ``status``.
        Points that did not converge (a NaN anywhere included) are NaN with ``status`` = 1;
        points outside the validity below keep their values with ``status`` =
        ``OUT_OF_VALIDITY``.

    Notes
    -----
    The maximum contact pressure of a roller is the largest over its two raceway contacts of
    the Hertz line-contact pressure of its most loaded slice,
    ``p0 = (w E* sum(rho) / pi)^(1/2)`` (:func:`models.contact.line_contact_pressure`), with
    ``w`` that slice's load per unit length and ``sum(rho) = 2/D + 2/(d_m - D)`` (inner) or
    ``2/D - 2/(d_m + D)`` (outer). A slice's own load sets its pressure, as in the slicing of
    ISO/TS 16281: a crowned roller's middle slice carries more than the mean. Without tilt the
    slices of a straight roller carry equal loads, so the model shows no edge stress (the
    real one has pressure peaks at its ends, which would need the roller's tilt and a
    half-space solution of the slices' interaction).

    Film: the oil film of each loaded contact by Pan and Hamrock's isothermal line-contact
    formulas (:func:`models.lubrication.line_contact_film`), the roller's load spread evenly
    over its effective length (the film varies as ``w^-0.128``: a crowned roller's shorter
    loaded length at light load changes it by a few per cent), ``R_x`` the relative radius
    of roller and raceway, the entrainment speed of pure rolling with the inner ring turning
    (:func:`models.lubrication.entrainment_speed`), the oil's dynamic viscosity at its
    temperature and ``E' = 2 E*``; the outer contacts carry the centrifugal force as well.

    Life: the inner ring rotates under a stationary radial load. ISO/TS 16281's reference
    life is formed from the laminae, the model's slices (5.3): every slice's inner and outer
    contact load enters with the inner ring's exponent 4 and the outer ring's 9/2 over the
    rollers, the outer loads including the centrifugal force; so crown and clearance enter
    the life through the slice loads. ISO 281's equivalent load is ``P = F_r`` (cylindrical
    roller bearings without axial load, 7.2).

    Validity: a solved point is ``out_of_validity`` (values kept) where a roller's maximum
    contact pressure exceeds ``pressure_limit`` (default 4000 MPa, the reference stress of
    ISO 76's static load rating for roller bearings: beyond it the permanent deformation
    exceeds 1e-4 of the roller diameter and the elastic contact laws fail), or a roller's
    approach (both contacts) exceeds ``APPROACH_LIMIT`` (2 %) of the roller diameter, where
    the fixed geometry (azimuths, contacts along the radius line, undeformed rings) fails;
    so does the state the perturbation stiffness evaluates, the ring moved on by
    ``perturbation`` (a step of 1 m gave a stiffness 3.4 times the analytic one). The
    forward difference is the mean of the stiffness over its step, so the step must be small
    against the displacement over which the stiffness changes: a point is out of validity
    where the analytic stiffness changes across the step by more than twice
    ``PERTURBATION_ERROR_LIMIT`` (2 %) of itself, an estimated error above 2 % (0.19 mm at
    4 kN on bearing D gave 1.31 times the analytic stiffness, the paper's 0.001 mm at 1e-12 N
    26 times). A crowned or tilted roller is out of validity where its ``slices`` cannot
    resolve the crown or the tilt: where the error they leave in the radial load and
    stiffness, the largest pressure or the laminae's life sum, estimated against a slicing
    four times finer (at least 240 slices, :meth:`_RollerSet.slicing_error`), exceeds
    ``SLICING_ERROR_LIMIT`` (2 %); one slice sees neither (5 mrad on bearing D at 4 kN: L10r
    80 times the converged). Straight, aligned rollers are exact at any ``slices``. A point
    whose ``pressure_safety_factor`` lies below ``minimum_static_safety`` is out of validity
    too.

    Whatever the outcome, a point is also out of validity where its inputs describe no
    bearing: the default (Palmgren's, steel) contact constant with ``youngs_modulus`` and
    ``poisson_ratio`` whose ``E*`` lies more than 10 % from steel's
    (:func:`models.limits.not_steel`); a clearance beyond the largest of ISO 5753-1 for the
    inner raceway's diameter ``d_m - D`` (:func:`models.limits.clearance_beyond_bearings`);
    a speed factor ``n d_m`` beyond 4e6 mm r/min, or an oil whose viscosity index no lubricant
    has (:func:`models.limits.outside_operation`). Speed otherwise enters through the
    pressure its centrifugal force causes (1e6 r/min gives bearing D some 16 GPa at the
    outer contact).

    Solution: each point's whole equilibrium in compiled code, one point after the other
    (:mod:`models.cylindrical_balance`, numba): the ring's displacement by the safeguarded
    Newton of :func:`models.solvers.solve_increasing`; at each displacement tried, every
    roller's force balance, started from a first-order prediction of its split from its last
    solution and summing only the slices that touch. A point's results do not depend on the
    other points of the call.

    References
    ----------
    .. [1] Paper 000, "Radial stiffness analysis of cylindrical roller bearing", eq. 1-16.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), eq. 4.45.
    .. [3] ISO 76:2006, Rolling bearings - Static load ratings, 3.1 (4000 MPa for roller
       bearings).
    .. [4] ISO/TS 16281:2008, 5.3; ISO 281:2007, 7 and 9.3.
    """
    roller_count, slices = int(roller_count), int(slices)
    default_constant = contact_constant is None
    if default_constant:
        contact_constant = palmgren_constant(effective_length)
    life = (dynamic_load_rating, fatigue_load_limit, contamination_factor, oil_temperature,
            viscosity_40, viscosity_100)
    arrays = np.broadcast_arrays(*(np.asarray(np.nan if a is None else a, dtype=float) for a in (
        radial_load, pitch_diameter, roller_diameter, effective_length, clearance, crown,
        speed, roller_density, contact_constant, cage_position, misalignment, perturbation,
        effective_modulus(youngs_modulus, poisson_ratio), pressure_limit) + life
        + (oil_density, pressure_viscosity, composite_roughness, minimum_static_safety,
           youngs_modulus, poisson_ratio, shaft_fit, housing_fit, bore, outside_diameter,
           shaft_bore, housing_outside_diameter, inner_ring_temperature,
           outer_ring_temperature, shaft_temperature, housing_temperature,
           shaft_youngs_modulus, shaft_poisson_ratio, shaft_expansion, housing_youngs_modulus,
           housing_poisson_ratio, housing_expansion, skf_rolling_constant_1,
           skf_sliding_constant_1, skf_sliding_constant_2, boundary_friction_coefficient,
           full_film_friction_coefficient, palmgren_speed_factor, palmgren_load_factor,
           oil_level, drag_loss_factor, bearing_width)))
    shape = arrays[0].shape
    (load, pitch, diameter, length, clearance, crown, speed, density, constant, cage_position,
     misalignment, perturbation, modulus, pressure_limit) = (
        np.array(a.ravel()) for a in arrays[:14])  # owned: numba warns of broadcast views
    life = [a.ravel() for a in arrays[14:20]]
    oil_density, pressure_viscosity, roughness, minimum_safety, ring_modulus, ring_poisson = (
        a.ravel() for a in arrays[20:26])
    mounted = mounted_clearance(clearance, pitch - diameter, pitch + diameter, diameter, speed,
                                ring_modulus, ring_poisson, *(a.ravel() for a in arrays[26:42]))
    friction = [a.ravel() for a in arrays[42:]]
    azimuth = cage_position[:, None] + 2.0 * np.pi * np.arange(roller_count) / roller_count
    if outer_contact not in OUTER_CONTACTS:
        raise ValueError(f"unknown outer_contact {outer_contact!r}; expected {OUTER_CONTACTS}")
    if slice_law not in SLICE_LAWS:
        raise ValueError(f"unknown slice_law {slice_law!r}; expected {SLICE_LAWS}")
    if outer_contact == "paper" and np.any(misalignment != 0.0):
        raise ValueError("misalignment needs outer_contact 'crowned' (the paper's straight "
                         "outer contact has no tilt)")
    tilt = np.where((misalignment == 0.0)[:, None], 0.0,
                    0.25 * (misalignment * length)[:, None] * np.cos(azimuth))
    rollers = _RollerSet(np.cos(azimuth), 0.5 * mounted["operating_clearance"], crown, constant,
                         centrifugal_force(diameter, length, pitch, speed, density), slices,
                         crown_profile, slice_law, outer_contact, tilt)
    outputs = _solve(rollers, load, perturbation)
    fit_lost = mounted.pop("fit_lost")
    outputs.update(mounted)
    # The stiffness the forward difference averages changes across its step: by how much.
    perturbation_error = outputs.pop("stiffness_change") / 2.0
    inner, outer = rollers.approaches(outputs["radial_displacement"],
                                      outputs["inner_contact_deflection"])
    inner_load, outer_load = rollers.largest_line_loads(inner, outer, length)
    inner_curvature = 2.0 / diameter + 2.0 / (pitch - diameter)
    outer_curvature = 2.0 / diameter - 2.0 / (pitch + diameter)
    pressure = np.maximum(
        line_contact_pressure(inner_load, inner_curvature[:, None], modulus[:, None]),
        line_contact_pressure(outer_load, outer_curvature[:, None], modulus[:, None]))
    outputs["max_contact_pressure"] = pressure  # NaN where the point failed
    outputs["largest_contact_pressure"] = pressure.max(axis=-1)
    static, unsafe = static_safety(outputs["largest_contact_pressure"], "roller",
                                   minimum_safety)
    outputs.update(static)
    outputs.update(roller_rating(roller_count, length, diameter, pitch, 0.0, load, 0.0))
    # Each roller's load spread over its effective length, on both raceways.
    films = [line_contact_film(
        contact_load, length[:, None], 1.0 / curvature[:, None],
        entrainment_speed(speed, pitch, diameter)[:, None],
        oil_viscosity(life[3], *life[4:], oil_density)[:, None], pressure_viscosity[:, None],
        2.0 * modulus[:, None])
        for contact_load, curvature in (
            (outputs["roller_load"], inner_curvature),
            (outputs["roller_load"] + outputs["centrifugal_force"][:, None], outer_curvature))]
    outputs.update(bearing_film(np.concatenate([films[0][0], films[1][0]], axis=-1),
                                np.concatenate([films[0][1], films[1][1]], axis=-1),
                                roughness))
    outputs.update(bearing_friction(
        "cylindrical_roller", friction_method, lubrication_method, speed, pitch, load, 0.0,
        walther_viscosity(*life[3:]), dict(zip(("r1", "s1", "s2"), friction[:3])),
        *friction[3:7], outputs["static_equivalent_load"],
        *(a.ravel() for a in arrays[28:30]), oil_level=friction[7],
        drag_loss_factor=friction[8], bearing_width=friction[9]))
    reference_life = np.full(load.size, np.nan)
    rated = np.flatnonzero(np.isfinite(life[0]))  # the laminae cost as much as the solution
    if rated.size:
        inner_laminae, outer_laminae = rollers.lamina_loads(inner[rated], outer[rated], rated)
        with np.errstate(divide="ignore", invalid="ignore"):
            reference_life[rated] = roller_bearing_reference_life(
                inner_laminae, life[0][rated], diameter[rated], pitch[rated],
                outer_lamina_loads=outer_laminae, lamina_weights=rollers.gap_count)
    # P = Fr, of a point that has a load distribution (a failed point's lives are NaN too).
    equivalent_load = np.where(outputs["status"] == CONVERGED, load, np.nan)
    outputs.update(rating_lives(reference_life, equivalent_load, "roller", speed, pitch, *life))
    # The forward difference's step moves the ring on by the perturbation: the state it
    # evaluates must lie within the contact laws' validity too.
    approach_limit = APPROACH_LIMIT * diameter[:, None]
    beyond = ((pressure > pressure_limit[:, None]) | (inner + outer > approach_limit)
              | (inner + outer + perturbation[:, None] > approach_limit)).any(axis=-1)
    with np.errstate(invalid="ignore"):
        beyond |= perturbation_error > PERTURBATION_ERROR_LIMIT
    beyond |= unsafe  # a static safety below the application's
    # Slices too few to resolve the crown or the tilt (an estimate as costly as a third of
    # the solution: made only where it can still change the status).
    beyond |= rollers.slicing_error(inner, outer, inner_curvature, outer_curvature,
                                    ~beyond) > SLICING_ERROR_LIMIT
    # Inputs that describe no bearing, whatever the outcome.
    no_bearing = (clearance_beyond_bearings(clearance, pitch - diameter)
                  | outside_operation(speed, pitch, *life[4:])
                  | (default_constant & np.broadcast_to(
                      not_steel(youngs_modulus, poisson_ratio), shape).ravel()))
    outside = ((outputs["status"] == CONVERGED) & beyond) | no_bearing | fit_lost
    outputs["status"] = np.where(outside, outputs["status"] | OUT_OF_VALIDITY,
                                 outputs["status"]).astype(np.int8)
    return {name: value.reshape(shape + value.shape[1:]) for name, value in outputs.items()}


def roller_set(roller_count, pitch_diameter, roller_diameter, effective_length,
               clearance=0.0, crown=0.0, crown_profile="logarithmic", slices=60,
               slice_law="uniform", outer_contact="crowned", speed=0.0,
               roller_density=7850.0, contact_constant=None):
    """The rollers of :func:`crb_radial`'s bearings (each argument one value or one per
    bearing, SI, the counts and choices one for all), aligned, for a model that moves their
    ring itself: ``roller_set(...).loads(displacement, points, ...)`` gives the radial load and
    stiffness of the bearings ``points`` at a radial displacement (eq. 1-10), the rollers
    placed from the displacement's direction as :func:`crb_radial` places them from its load's
    (a roller on that line)."""
    if contact_constant is None:
        contact_constant = palmgren_constant(effective_length)
    pitch, diameter, length, clearance, crown, speed, density, constant = (
        np.array(a, dtype=float) for a in np.broadcast_arrays(*(np.atleast_1d(np.asarray(
            v, dtype=float)) for v in (pitch_diameter, roller_diameter, effective_length,
                                       clearance, crown, speed, roller_density,
                                       contact_constant))))
    azimuth = 2.0 * np.pi * np.arange(int(roller_count)) / int(roller_count)
    return _RollerSet(np.broadcast_to(np.cos(azimuth), (pitch.size, azimuth.size)).copy(),
                      0.5 * clearance, crown, constant,
                      centrifugal_force(diameter, length, pitch, speed, density), int(slices),
                      crown_profile, slice_law, outer_contact)


def _solve(rollers, load, perturbation):
    """Solve a flat batch of bearings; see :func:`crb_radial`."""
    cos_azimuth, half_clearance = rollers.cos, rollers.half_clearance
    constant, centrifugal = rollers.constant, rollers.centrifugal
    count, n = load.size, LINE_CONTACT_EXPONENT
    split = np.full(cos_azimuth.shape + (3,), np.nan)  # no roller solved yet
    # Where each solve's roller loads and approaches go, and where those of other calls do.
    cache = {"load": np.empty(count), "stiffness": np.empty(count),
             "roller_load": np.empty(cos_azimuth.shape),
             "deflection": np.empty(cos_azimuth.shape)}
    # Bracket: no roller touches below max(Pd/2, 0); at the upper bound the best-placed roller
    # (at cos_max) alone carries F / cos_max through both contacts, each needing at most the
    # largest gap plus ((F / cos_max + Fc)/K)^(1/n) of approach. With preload, rollers opposite
    # the load push back, so there the bound is checked and doubled until it holds.
    cos_max = cos_azimuth.max(axis=-1)
    # A tilted roller's end touches before its middle would: the play that counts is smaller.
    play = half_clearance + (0.0 if rollers.tilt is None else 2.0 * rollers.floor.min(axis=-1))
    lower = np.maximum(play, 0.0)
    reach = (half_clearance + 2.0 * rollers.largest_gap
             + 2.0 * ((load / cos_max + centrifugal) / constant) ** (1.0 / n))
    upper = np.maximum(1.001 * reach / cos_max, lower) + 1e-12
    # At zero load the ring of a bearing with clearance may sit anywhere in its play: take the
    # limit of a vanishing load, resting on the best-placed roller, which carries nothing.
    resting = (load == 0.0) & (play >= 0.0)
    touch = (play + rollers.free_outer_approach.max(axis=-1)) / cos_max
    lower = np.where(resting, touch, lower)
    upper = np.where(resting, touch, upper)
    displacement, converged = np.empty(count), np.empty(count, dtype=bool)
    rollers_converged = np.empty(count, dtype=bool)
    perturbed, perturbed_stiffness = np.full(count, np.nan), np.full(count, np.nan)
    # Each point's whole balance compiled, one point after the other.
    rollers.balance(load, lower, upper, play < 0.0, perturbation, split, displacement,
                    cache["load"], cache["stiffness"], converged, rollers_converged,
                    cache["roller_load"], cache["deflection"], perturbed, perturbed_stiffness)
    # The limit itself: the best-placed roller just touches and carries nothing (evaluated
    # there, rounding in the displacement leaves it a few mN with spinning rollers).
    for name in ("roller_load", "stiffness", "load"):
        cache[name][resting] = 0.0
    cache["converged"] = rollers_converged | resting
    balanced = np.abs(cache["load"] - load) <= 1e-9 * load + 1e-6
    ok = converged & cache["converged"] & balanced & rollers.free_outer_converged
    outputs = {
        "radial_displacement": displacement,
        "radial_stiffness": cache["stiffness"],
        "perturbation_stiffness": (perturbed - cache["load"]) / perturbation,
        "loaded_rollers": (cache["roller_load"] > _LOADED_FRACTION * load[:, None]).sum(axis=-1),
        "centrifugal_force": centrifugal,
        "roller_load": cache["roller_load"],
        "inner_contact_deflection": cache["deflection"],
    }
    # A NaN anywhere (an input, an overflow) fails the point rather than hiding in one output;
    # the forward difference is NaN where it was not asked for.
    for name, value in outputs.items():
        finite = np.isfinite(value).reshape(count, -1).all(axis=-1)
        ok &= finite | ((name == "perturbation_stiffness") & np.isnan(perturbation))
    outputs = {name: np.where(ok.reshape((-1,) + (1,) * (value.ndim - 1)), value, np.nan)
               for name, value in outputs.items()}
    outputs["status"] = np.where(ok, CONVERGED, NOT_CONVERGED).astype(np.int8)
    with np.errstate(divide="ignore", invalid="ignore"):
        outputs["stiffness_change"] = np.abs(perturbed_stiffness / cache["stiffness"] - 1.0)
    return outputs


#: A diametral clearance (or interference) smaller than the rollers.
CLEARANCE_BELOW_ROLLER = Constraint(("clearance", "roller_diameter"), clearance_below_roller,
                                    "the clearance must be smaller than the roller diameter")


def _rolling_element_density(roller_density):
    # 0 switches the centrifugal force off; any other density is a material's.
    return (roller_density == 0) | (roller_density >= ROLLING_ELEMENT_DENSITIES[0])


MODELS = [Model(
    name="crb_radial",
    function=crb_radial,
    summary="Cylindrical roller bearing under radial load: load distribution and radial stiffness "
            "with crowned rollers (slices), centrifugal force and clearance; lubricant film.",
    reference="Paper 000, Radial stiffness analysis of cylindrical roller bearing, eq. 1-16",
    version="11",
    inputs=(
        Input("radial_load", "N", "radial load Fr on the inner ring", minimum=0.0),
        Input("roller_count", "1", "number of rollers Z", kind="count", minimum=3, maximum=1000),
        Input("pitch_diameter", "mm", "pitch diameter dm", minimum=0.0, exclusive_minimum=True),
        Input("roller_diameter", "mm", "roller diameter D", minimum=0.0, exclusive_minimum=True),
        Input("effective_length", "mm", "effective contact length l of a roller",
              minimum=0.0, exclusive_minimum=True),
        Input("clearance", "mm", "diametral clearance Pd (negative: preload)", default=0.0),
        Input("crown", "mm", "crown drop at the roller ends cmax", default=0.0, minimum=0.0),
        Input("crown_profile", "", "roller crown profile (eq. 8)", default="logarithmic",
              kind="choice", choices=PROFILES),
        Input("slices", "1", "number of slices k per roller", default=60, kind="count",
              minimum=1, maximum=100000),
        Input("slice_law", "", "uniform: each slice carries K/k (delta - c)^n; paper: eq. 9, "
              "divided by the number of loaded slices", default="uniform", kind="choice",
              choices=SLICE_LAWS),
        Input("outer_contact", "", "crowned: both contacts crowned, roller in force balance; "
              "paper: eq. 6 as printed (straight outer contact)", default="crowned",
              kind="choice", choices=OUTER_CONTACTS),
        Input("speed", "rpm", "inner-ring speed ni", default=0.0, minimum=0.0),
        Input("roller_density", "kg/m^3", "roller density rho (0: no centrifugal force; "
              "rolling elements: 900 for polymers to 15700 for tungsten carbide)",
              default=7850.0, minimum=0.0, maximum=ROLLING_ELEMENT_DENSITIES[1]),
        Input("contact_constant", "N/mm^(10/9)", "load-deflection constant K of one contact, "
              "Q = K delta^(10/9); default Palmgren 8.06e4 l^(8/9) (N, mm)", default=None,
              minimum=0.0, exclusive_minimum=True,
              label="load-deflection constant K"),
        Input("cage_position", "deg", "azimuth of roller 1 from the load direction",
              default=0.0, minimum=-360.0, maximum=360.0,
              label="azimuth of roller 1"),
        Input("misalignment", "mrad", "tilt of the inner ring against the outer ring across "
              "the load direction; each roller takes half", default=0.0, minimum=-20.0,
              maximum=20.0, label="misalignment"),
        Input("perturbation", "mm", "displacement step of the forward-difference stiffness "
              "(section 2.3; the paper's: 0.001 mm); default: none (NaN)", default=None,
              minimum=0.0, exclusive_minimum=True,
              label="perturbation step"),
        Input("youngs_modulus", "GPa", "Young's modulus of rollers and rings (contact pressure "
              "only)", default=207.0, minimum=SOFTEST_BEARING_SOLID, maximum=STIFFEST_SOLID),
        Input("poisson_ratio", "1", "Poisson's ratio of rollers and rings (contact pressure "
              "only)", default=0.3, minimum=0.0, maximum=0.5),
        Input("pressure_limit", "MPa", "contact pressure above which a point is out of "
              "validity (ISO 76: 4000 for roller bearings of through-hardened steel)",
              default=4000.0, minimum=0.0, exclusive_minimum=True,
              label="contact pressure limit"),
    ) + LIFE_INPUTS + FILM_INPUTS + STATIC_INPUTS + OPERATING_INPUTS
    + friction_inputs("cylindrical_roller"),
    outputs=(
        Output("radial_displacement", "mm", "radial displacement of the inner ring"),
        Output("radial_stiffness", "N/mm", "radial stiffness dFr/d(delta_r), implicit "
               "differentiation (eq. 12-16)"),
        Output("perturbation_stiffness", "N/mm", "forward-difference radial stiffness with the "
               "displacement step 'perturbation'; NaN without it",
               label="perturbation stiffness"),
        Output("loaded_rollers", "1", "number of rollers carrying load", dtype="int"),
        Output("centrifugal_force", "N", "centrifugal force of one roller (eq. 3)",
               depends_on=("pitch_diameter", "roller_diameter", "effective_length", "speed",
                           "roller_density")),
        Output("roller_load", "N", "inner-raceway contact load of each roller (eq. 9)",
               dims=("roller",),
               label="roller load"),
        Output("inner_contact_deflection", "mm", "inner-raceway contact approach of each roller; "
               "negative: its gap", dims=("roller",),
               label="inner contact approach"),
        Output("max_contact_pressure", "MPa", "largest Hertz line-contact pressure of each "
               "roller's slices, inner or outer raceway", dims=("roller",),
               label="maximum contact pressure"),
        Output("largest_contact_pressure", "MPa", "largest maximum contact pressure of all "
               "rollers", label="largest contact pressure"),
    ) + film_outputs("every loaded roller's inner and outer contact (Pan and Hamrock's "
                     "line contact)") + static_outputs("roller") + operating_outputs()
    + friction_outputs() + life_outputs(
        "slice loads of both raceways (laminae), inner ring rotating",
        "P = Fr (ISO 281 7.2, no axial load)"),
    dim_sizes={"roller": "roller_count"},
    constraints=(
        Constraint(("crown", "roller_diameter"), lambda crown, roller_diameter:
                   crown < roller_diameter / 2, "the crown must be smaller than the roller radius"),
        Constraint(("misalignment", "outer_contact"), lambda misalignment, outer_contact:
                   (misalignment == 0) | (outer_contact != "paper"),
                   "misalignment needs outer_contact 'crowned' (the paper's straight outer "
                   "contact has no tilt)"),
        CLEARANCE_BELOW_ROLLER,
        Constraint(("roller_density",), _rolling_element_density,
                   "roller_density must be 0 (no centrifugal force) or at least 900 kg/m^3: "
                   "no rolling element is lighter than polymers (polypropylene, 900)"),
        Constraint(("roller_count", "pitch_diameter", "roller_diameter"),
                   lambda roller_count, pitch_diameter, roller_diameter:
                   elements_fit(roller_count, pitch_diameter, roller_diameter),
                   "the rollers do not fit on the pitch circle: pitch_diameter * sin(180 deg / "
                   "roller_count) must exceed roller_diameter"),
    ) + LIFE_CONSTRAINTS + operating_constraints("roller_diameter")
    + friction_constraints("cylindrical_roller"),
    # Measured by benchmarks/declared_costs.py on the studies' sweeps, misaligned and
    # many-sliced rollers and rating lives included (an aligned unrated point costs less).
    seconds_per_point=6e-5,
    # Each point's equilibrium is compiled and solved point by point, so a block's
    # temporaries are a few (points, rollers) arrays: large blocks share the numpy parts'
    # overhead (benchmarks/RESULTS.md).
    points_per_call=2000,
    validity="a roller's maximum contact pressure above pressure_limit (default 4000 MPa, "
             "ISO 76's reference stress for roller bearings) or its approach (both contacts) "
             "above 2 % of the roller diameter, also with the ring moved on by the "
             "perturbation step (the forward difference's state); a perturbation step not "
             "small against the displacement over which the stiffness changes (the analytic "
             "stiffness changing across it by more than 4 %: the forward difference, its mean "
             "over the step, then errs by about 2 %); slices too few for the crown or the "
             "tilt: an error above 2 % in the rollers' radial load or stiffness, the largest "
             "pressure or the laminae's life sum, against four times as many slices (at least "
             "240; paper 000's 60 resolve its crowns, loads and 5 mrad; straight, aligned "
             "rollers are exact at any count); a pressure_safety_factor below "
             "minimum_static_safety, where given; a tight fit lost at temperature and speed "
             "(the ring may creep); whatever the outcome, inputs that "
             f"describe no bearing: {STEEL_VALIDITY}; {CLEARANCE_VALIDITY}; {SPEED_VALIDITY}; "
             f"{OIL_VALIDITY}",
)]
