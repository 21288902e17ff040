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


def test_the_interpreted_equilibrium_gives_the_compiled_ones_bits(monkeypatch):
    # A small sweep runs the equilibrium's source uncompiled (no numba to load): its numbers
    # must be the compiled ones to the bit, or results would depend on the sweep's size.
    import importlib

    from bearing_sweep.models import ball

    compiled = importlib.import_module("bearing_sweep.models.ball_equilibrium")
    interpreted = ball._interpreted_kernels()
    assert interpreted is not compiled and interpreted.INTERPRETED
    rng = np.random.default_rng(5)
    count = 12
    points = dict(axial_load=rng.uniform(-500.0, 3000.0, count),
                  radial_load=rng.uniform(-2000.0, 2000.0, count),
                  radial_load_z=rng.uniform(-800.0, 800.0, count),
                  clearance=rng.uniform(-0.004, 0.02, count) * MM,
                  contact_angle=np.radians(rng.uniform(0.0, 40.0, count)))
    points["axial_load"][:2] = 0.0  # unloaded: centred, or held by the preload alone
    points["radial_load"][:2] = points["radial_load_z"][:2] = 0.0
    points["axial_load"][2] = np.nan
    bearing = dict(ball_count=11, ball_diameter=6 * MM, pitch_diameter=40 * MM,
                   dynamic_load_rating=9e3)
    for geometry, held in (("jones", ""), ("jones", "tilt_y tilt_z"),
                           ("fixed_angle", "tilt_y tilt_z"), ("jones", "axial radial_z")):
        if "radial_z" in held:
            points["radial_load_z"] = np.zeros(count)
        results = []
        for module in (compiled, interpreted):
            monkeypatch.setattr(ball, "_kernels", lambda points, module=module: module)
            results.append(ball.ball_5dof(**bearing, **points, geometry=geometry,
                                          fixed_dofs=held))
        assert set(np.unique(results[0]["status"])) > {0}  # failures are compared too
        for name, values in results[0].items():
            assert values.tobytes() == results[1][name].tobytes(), (geometry, held, name)


def test_a_small_ball_sweep_does_not_load_numba(run_loads_numba):
    # Start-up: importing numba and loading the compiled equilibrium costs about 0.5 s, more
    # than a hundred points take uncompiled.
    assert not run_loads_numba('[sweep]\nmodel = "ball_5dof"\nbearing = "paper001-71807AC"\n'
                               '[axes]\naxial_load = { start = "100 N", stop = "2500 N", '
                               'step = "100 N" }\n'
                               'radial_load = ["0 N", "250 N", "500 N", "1000 N"]\n')
