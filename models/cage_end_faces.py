"""A roller end face's elements in the spatial cage model, and how well they stand for the
faces the end meets.

The end face is the disc of radius ``R_f = D/2 - chamfer`` at the roller's end. It meets two
flat faces, each an annulus about the bearing's axis: the pocket's end face on the cage (from
the cage's bore to its outside diameter) and the inner ring's rib (from the raceway to the
rib's top). The model's elements are fixed on the end disc, rings of equal area times equal
angles (:func:`face_elements`); an element carries a face's film or contact where it lies
within the face's annulus. A face that covers a thin sliver of the disc (a low rib, a thin
cage rim) meets few elements or none, and the contact the elements give is wrong without a
sign of it. :func:`element_coverage` measures, for a centred roller, the area of the elements
facing an annulus against the area of the disc within it, and the elements' centroid
against the overlap's, so that the model can refuse a discretisation that does not resolve
the faces (:data:`COVERAGE_TOLERANCE`).
"""
from __future__ import annotations

import numpy as np

#: Largest relative error allowed of the elements' area facing a face, and of their centroid
#: (as a share of the overlap's radial width): the contact's stiffness and its centre each
#: within a quarter. The model's defaults hold both within 3 % on its test bearing.
COVERAGE_TOLERANCE = 0.25


def face_elements(face_radius, rings, angles):
    """The end face's elements: ring radii [m] (rings of equal area, each element at the
    radius halving its ring's area), angles from the radial direction [rad] and each
    element's area [m^2] (``(rings,)``, ``(angles,)``, ``(rings,)``)."""
    radii = face_radius * np.sqrt((np.arange(rings) + 0.5) / rings)
    phi = 2 * np.pi * (np.arange(angles) + 0.5) / angles
    return radii, phi, np.full(rings, np.pi * face_radius**2 / (rings * angles))


def _segment(radius, cut):
    """Area [m^2] and first moment [m^3] along the cut's normal, about the circle's centre,
    of the part of a disc of ``radius`` beyond a straight cut ``cut`` from its centre
    (``-radius <= cut <= radius``)."""
    half_chord = np.sqrt(np.maximum(radius**2 - cut**2, 0.0))
    area = radius**2 * np.arccos(np.clip(cut / radius, -1.0, 1.0)) - cut * half_chord
    return area, 2.0 * half_chord**3 / 3.0


def disc_within(face_radius, distance, reach):
    """Area [m^2] and first moment [m^3] (along the line from the bearing's axis to the
    disc's centre, about the disc's centre) of the part of a disc of ``face_radius`` whose
    centre lies ``distance`` from the bearing's axis, within ``reach`` of that axis.

    Two circles meet on their radical line, ``x0 = (reach^2 - R^2 - d^2) / (2 d)`` from the
    disc's centre: the lens is the disc's segment short of it (toward the axis) and the
    reach circle's segment beyond it."""
    radius, d = np.asarray(face_radius, float), np.asarray(distance, float)
    reach = np.asarray(reach, float)
    x0 = np.clip((reach**2 - radius**2 - d**2) / (2.0 * d), -radius, radius)
    near, near_moment = _segment(radius, -x0)  # the disc's cap toward the axis
    cut = np.clip(x0 + d, -reach, reach)  # the radical line in the reach circle's frame
    far, far_moment = _segment(reach, cut)
    area = near + far
    moment = -near_moment + far_moment - d * far
    whole = reach >= d + radius
    none = reach <= d - radius
    area = np.where(whole, np.pi * radius**2, np.where(none, 0.0, area))
    return area, np.where(whole | none, 0.0, moment)


def element_coverage(face_radius, distance, low, high, rings, angles):
    """How well a centred roller's end-face elements stand for the part of the end face
    within the annulus ``low`` to ``high`` about the bearing's axis (the end's centre
    ``distance`` from it): the elements' area facing it over the true area [-] (1: exact),
    and the shift of their centroid from the true one, radially, over the overlap's radial
    width [-] (0: exact). NaN where the annulus misses the end face. Broadcasts over its
    arguments."""
    def one(face_radius, distance, low, high, rings, angles):
        outer, outer_moment = disc_within(face_radius, distance, high)
        inner, inner_moment = disc_within(face_radius, distance, low)
        area, moment = outer - inner, outer_moment - inner_moment
        width = min(high, distance + face_radius) - max(low, distance - face_radius)
        if not (area > 0.0 and width > 0.0):
            return np.nan, np.nan
        radii, phi, element_area = face_elements(face_radius, int(rings), int(angles))
        across = radii[:, None] * np.cos(phi)
        reach = np.hypot(distance + across, radii[:, None] * np.sin(phi))
        facing = (reach >= low) & (reach <= high)
        if not facing.any():
            return 0.0, np.nan
        share = facing.sum() * element_area[0] / area
        return share, (across[facing].mean() - moment / area) / width
    share, shift = np.vectorize(one, otypes=[float, float])(
        face_radius, distance, low, high, rings, angles)
    return share, shift


def coverage_holds(share, shift):
    """Whether :func:`element_coverage`'s share and shift lie within
    :data:`COVERAGE_TOLERANCE`."""
    return (np.abs(share - 1.0) <= COVERAGE_TOLERANCE) & (np.abs(shift) <= COVERAGE_TOLERANCE)
