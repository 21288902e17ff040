"""The spatial cage model's end-face elements and the check that they resolve the faces a
roller's end meets (the cage's pocket face, the rib); the refusals it gives are with the
model's others in test_cage_dynamics_6dof_validity."""
import numpy as np
import pytest

from bearing_sweep.models import cage_end_faces as faces

MM = 1e-3
# paper002-test: a 10 mm roller (0.5 mm chamfer) on a 44 mm inner raceway, clearance 0.02 mm
FACE, PITCH = 4.5 * MM, 0.5 * (44 + 10 + 0.01) * MM
RACEWAY = 22 * MM


def lens_area(r, big_r, d):
    """The area common to two circles of radii r and R, centres d apart (the textbook formula
    by the circles' angles, E. W. Weisstein, 'Circle-circle intersection', MathWorld)."""
    return (r**2 * np.arccos((d**2 + r**2 - big_r**2) / (2 * d * r))
            + big_r**2 * np.arccos((d**2 + big_r**2 - r**2) / (2 * d * big_r))
            - 0.5 * np.sqrt((-d + r + big_r) * (d + r - big_r) * (d - r + big_r)
                            * (d + r + big_r)))


def sampled(low, high, points=1500):
    """Area and radial centroid of the end disc within low..high of the bearing's axis, by
    counting the points of a fine square grid."""
    x = np.linspace(-FACE, FACE, points)
    across, along = np.meshgrid(x, x, indexing="ij")
    reach = np.hypot(PITCH + across, along)
    inside = (across**2 + along**2 <= FACE**2) & (reach >= low) & (reach <= high)
    cell = (x[1] - x[0]) ** 2
    return inside.sum() * cell, across[inside].mean()


@pytest.mark.parametrize("reach_mm", [22.6, 24.0, 27.0, 29.5, 31.4])
def test_the_part_of_an_end_face_within_a_radius_is_the_two_circles_lens(reach_mm):
    area, moment = faces.disc_within(FACE, PITCH, reach_mm * MM)
    assert area == pytest.approx(lens_area(FACE, reach_mm * MM, PITCH), rel=1e-9)
    grid_area, grid_centroid = sampled(0.0, reach_mm * MM)
    assert area == pytest.approx(grid_area, abs=1e-3 * np.pi * FACE**2)
    assert moment / area == pytest.approx(grid_centroid, abs=2e-3 * FACE)


def test_an_end_face_wholly_within_or_beyond_a_radius():
    area, moment = faces.disc_within(FACE, PITCH, [PITCH + 2 * FACE, PITCH - 2 * FACE])
    np.testing.assert_allclose(area, [np.pi * FACE**2, 0.0])
    np.testing.assert_allclose(moment, [0.0, 0.0])


def test_finer_elements_converge_on_the_faces_area_and_centroid():
    for low, high in ((24.25 * MM, 29.5 * MM), (RACEWAY, RACEWAY + 2 * MM)):
        share, shift = faces.element_coverage(FACE, PITCH, low, high, 40, 96)
        assert share == pytest.approx(1.0, abs=0.01)
        assert shift == pytest.approx(0.0, abs=0.01)


def test_a_low_rib_meets_two_of_the_default_elements():
    # A 1 mm rib: the outer ring's elements (radius 4.5 sqrt(0.9) mm) at 165 and 195 deg
    # reach 27.005 - 4.27 cos(15 deg) = 22.88 mm from the axis, below the rib's top at
    # 23 mm; every other element lies above it.
    true_area = lens_area(FACE, 23 * MM, PITCH)
    share, _ = faces.element_coverage(FACE, PITCH, RACEWAY, 23 * MM, 5, 12)
    assert share == pytest.approx(2 * np.pi * FACE**2 / 60 / true_area, rel=1e-9)
    assert not faces.coverage_holds(share, 0.0)


def test_a_thin_cage_rim_meets_no_element_and_is_not_resolved():
    share, shift = faces.element_coverage(FACE, PITCH, 26.975 * MM, 27.075 * MM, 5, 12)
    assert share == 0.0 and not faces.coverage_holds(share, shift)


def test_the_defaults_resolve_the_test_bearings_faces():
    for low, high in ((24.25 * MM, 29.5 * MM), (RACEWAY, RACEWAY + 2 * MM)):
        share, shift = faces.element_coverage(FACE, PITCH, low, high, 5, 12)
        assert abs(share - 1) < 0.03 and abs(shift) < 0.03
