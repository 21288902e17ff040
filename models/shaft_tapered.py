"""A tapered roller bearing as a shaft's support: :func:`models.tapered.trb_load`'s roller law
(paper 003, eq. 13-18) in the shaft's five degrees of freedom.

Roller ``i`` at azimuth ``psi_i`` (from the radial direction y towards z) is compressed along
its contact normal by the inner ring's axial displacement at the pitch circle and its radial
displacement towards the roller,

    delta_i = u_i sin(alpha) + (v cos(psi_i) + w sin(psi_i)) cos(alpha) - (P_d / 2) cos(alpha),
    u_i = u + R (theta_y sin(psi_i) - theta_z cos(psi_i)),

with ``R`` half the pitch diameter, ``(u, v, w, theta_y, theta_z)`` the shaft's degrees of
freedom at the bearing and ``P_d`` the diametral clearance (negative: a preload, as a pair
of bearings set against each other takes it). It carries ``Q_i = K_ne delta_i^1.11`` where
``delta_i > 0`` (eq. 18): an axial part ``Q_i sin(alpha)`` at the pitch circle and a radial
part ``Q_i cos(alpha)``. Their resultant on the inner ring is what the shaft puts on the
bearing, the moments ``M_y = R sum Q_i sin(alpha) sin(psi_i)`` and ``M_z = -R sum Q_i sin(alpha)
cos(psi_i)`` included; its tangent follows from ``dQ_i/d(delta_i) = 1.11 Q_i / delta_i``.
A single row takes thrust one way, along +x as mounted (``axial_direction``). The rollers are
loaded evenly along their length (trb_load has no crown): a tilt moves their load, not its
spread over the roller.
"""
from __future__ import annotations

import numpy as np

from .contact import APPROACH_LIMIT, ROLLER_PRESSURE_LIMIT, effective_modulus, \
    line_contact_pressure
from .life import roller_bearing_reference_life
from .shaft_bearings import case_rows
from .tapered import LOAD_EXPONENT, cone_curvature_sum, paper_contact_constant


class TaperedSupport:
    """A tapered roller bearing, from the inputs :func:`models.tapered.trb_load` takes (SI,
    each one value or one per load case of a batch of ``cases``, the roller count one for
    all), with its ``pitch_diameter`` and ``clearance`` required on the shaft."""

    def __init__(self, roller_count, effective_length, roller_mean_diameter,
                 outer_contact_angle, pitch_diameter, clearance=0.0, contact_constant=None,
                 youngs_modulus=206e9, poisson_ratio=0.3,
                 pressure_limit=ROLLER_PRESSURE_LIMIT, cases=1):
        given = np.nan if contact_constant is None else contact_constant
        (length, diameter, angle, pitch, clearance, given, modulus, self.pressure_limit,
         _) = np.broadcast_arrays(*(np.atleast_1d(np.asarray(v, dtype=float)) for v in (
             effective_length, roller_mean_diameter, outer_contact_angle, pitch_diameter,
             clearance, given, effective_modulus(youngs_modulus, poisson_ratio),
             pressure_limit, np.zeros(cases))))
        self.count = length.size
        self.constant = np.where(np.isnan(given), paper_contact_constant(length, diameter),
                                 given)
        self.sin, self.cos = np.sin(angle), np.cos(angle)
        self.radius, self.gap = 0.5 * pitch, 0.5 * clearance * self.cos
        azimuth = 2.0 * np.pi * np.arange(int(roller_count)) / int(roller_count)
        self.cos_psi, self.sin_psi = np.cos(azimuth), np.sin(azimuth)
        # What trb_load's pressure, life and validity take.
        self.length, self.diameter, self.pitch, self.angle, self.modulus = (
            length, diameter, pitch, angle, modulus)
        self.curvature = cone_curvature_sum(diameter, pitch, angle)

    def _gradient(self, rows):
        """``d(delta_i)/dq`` ``(n, Z, 5)``: each roller's compression per degree of freedom."""
        sin, cos, radius = (value[rows, None] for value in (self.sin, self.cos, self.radius))
        ones = np.ones_like(sin * self.cos_psi)
        return np.stack([sin * ones, cos * self.cos_psi, cos * self.sin_psi,
                         radius * sin * self.sin_psi, -radius * sin * self.cos_psi], axis=-1)

    def _rollers(self, displacement, cases):
        """Each roller's compression and load ``(n, Z)`` [m, N] and the rows of the cases."""
        displacement, rows = case_rows(displacement, self.count, cases)
        gradient = self._gradient(rows)
        compression = np.einsum("nzk,nk->nz", gradient, displacement) - self.gap[rows, None]
        load = self.constant[rows, None] * np.maximum(compression, 0.0) ** LOAD_EXPONENT
        return compression, load, gradient, rows

    def loads(self, displacement, cases=None):
        """Loads ``(n, 5)`` [N, N m] the rollers carry at the inner ring's ``displacement``
        ``(n, 5)`` [m, rad] in the load ``cases``, and their stiffness ``(n, 5, 5)``."""
        compression, load, gradient, _ = self._rollers(displacement, cases)
        with np.errstate(divide="ignore", invalid="ignore"):
            slope = np.where(compression > 0.0, LOAD_EXPONENT * load / compression, 0.0)
        return (np.einsum("nz,nzk->nk", load, gradient),
                np.einsum("nz,nzk,nzl->nkl", slope, gradient, gradient))

    def largest_pressure(self, displacement, cases=None):
        """The largest Hertz line-contact pressure [Pa] on the cone, as trb_load forms it."""
        _, load, _, rows = self._rollers(displacement, cases)
        return self._pressure(load, rows)

    def _pressure(self, load, rows):
        return line_contact_pressure(load.max(axis=-1) / self.length[rows],
                                     self.curvature[rows], self.modulus[rows])

    def reference_life(self, displacement, rating, cases=None):
        """ISO/TS 16281's reference rating life L10r [10^6 revolutions], the inner ring
        rotating, each roller one lamina (as trb_load takes it); infinite without load."""
        _, load, _, rows = self._rollers(displacement, cases)
        with np.errstate(divide="ignore", invalid="ignore"):
            return roller_bearing_reference_life(load[..., None], rating, self.diameter[rows],
                                                 self.pitch[rows], self.angle[rows])

    def outside_validity(self, displacement, cases=None):
        """Where a roller's cone pressure exceeds the limit or its compression 2 % of its
        diameter (trb_load's validity)."""
        compression, load, _, rows = self._rollers(displacement, cases)
        return (self._pressure(load, rows) > self.pressure_limit[rows]) | (
            compression.max(axis=-1) > APPROACH_LIMIT * self.diameter[rows])
