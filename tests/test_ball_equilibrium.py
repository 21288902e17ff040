"""ball_5dof's compiled equilibrium: the singularity measure and the one-row Hertz contacts."""
import numpy as np
import pytest

from bearing_sweep.models import ball_equilibrium
from bearing_sweep.models.ball import ball_5dof

MM = 1e-3


@pytest.mark.parametrize("rank", [5, 4, 2, 0])
@pytest.mark.parametrize("free", [(True,) * 5, (True, True, True, False, False),
                                  (False, True, False, True, True)])
def test_the_reciprocal_condition_is_the_singular_values_ratio(rank, free):
    # Against numpy's SVD (LAPACK), which ball_5dof used before: the Jacobi eigenvalues of a
    # symmetric matrix agree with its singular values to rounding, about 1e-16 of the
    # largest; the threshold they are compared with is 1e-9.
    rng = np.random.default_rng(rank)
    free = np.array(free)
    scale = np.array([1e8, 3e7, 3e7, 2e6, 2e6])  # stiffness entries of unlike sizes [N/m]
    for _ in range(20):
        factor = rng.normal(size=(5, rank)) * np.sqrt(scale)[:, None]
        stiffness = factor @ factor.T
        reduced = stiffness[np.ix_(free, free)]
        values = np.linalg.svd(reduced, compute_uv=False)
        expected = values[-1] / values[0] if values[0] > 0 else 0.0
        found = ball_equilibrium.reciprocal_condition(
            stiffness, np.flatnonzero(free), np.empty((free.sum(), free.sum() + 1)))
        assert found == pytest.approx(expected, rel=1e-9, abs=1e-14)


def test_a_bearing_of_several_geometries_gives_each_points_own_numbers():
    # The Hertz contacts are computed once per distinct geometry: a point's numbers are those
    # it has alone, whatever other geometries share its call.
    angles = np.radians([15.0, 25.0, 15.0, 40.0, 25.0])
    bearing = dict(ball_count=12, ball_diameter=8 * MM, pitch_diameter=50 * MM,
                   axial_load=1500.0, radial_load=np.linspace(0.0, 2000.0, 5))
    together = ball_5dof(contact_angle=angles, **bearing)
    for point, angle in enumerate(angles):
        alone = ball_5dof(contact_angle=angle, **{**bearing, "radial_load": bearing[
            "radial_load"][point]})
        for name, values in alone.items():
            assert values.tobytes() == together[name][point:point + 1].tobytes(), name
    assert np.unique(together["hertz_contact_constant"]).size == 3
