"""cage_dynamics: the transient settles on the steady state where their assumptions meet."""
import numpy as np
import pytest

from models.cage_dynamics import cage_dynamics
from models.cage_slip import cage_slip

MM, RPM = 1e-3, 2 * np.pi / 60
TEST = dict(roller_count=13, inner_raceway_diameter=44 * MM, roller_diameter=10 * MM,
            roller_length=11 * MM, effective_length=7.2 * MM, clearance=0.02 * MM,
            cage_inner_diameter=48.5 * MM, cage_outer_diameter=59 * MM, cage_width=9 * MM,
            pocket_friction=0.0)


def test_a_rigidly_guided_cage_settles_on_the_steady_slip():
    # The steady model moves every roller with the cage and lets the cage neither whirl nor
    # play in its pockets: a very heavy cage with tight pockets does the same.
    tight = dict(TEST, pocket_clearance=0.01 * MM)
    steady = cage_slip(800.0, 12000 * RPM, **tight)["cage_slip"][0]
    transient = cage_dynamics(800.0, 12000 * RPM, **tight, cage_density=8.6e6,
                              duration=0.04, output_interval=2e-4)
    assert transient["status"][0] == 0
    assert transient["mean_cage_slip"][0] == pytest.approx(steady, rel=0.02)


def test_a_whirling_cage_slips_somewhat_more_than_the_steady_estimate():
    # With the real cage and pocket play the cage whirls and the rollers rattle in their
    # pockets; that costs traction, so the transient slip is higher, but of the same order.
    steady = cage_slip(800.0, 12000 * RPM, **TEST)["cage_slip"][0]
    transient = cage_dynamics(800.0, 12000 * RPM, **TEST, duration=0.04,
                              output_interval=2e-4)
    assert steady < transient["mean_cage_slip"][0] < 1.5 * steady
    slip = transient["cage_slip"][0]
    assert np.isfinite(slip).all() and slip.shape == (201,)
    assert transient["roller_slip"].shape == (1, 201, 13)


def test_radial_eccentricity_steadies_the_whirl():
    # Paper 002, section 3 (Fig. 18): 2 mm radial eccentricity of the cage's mass makes the
    # whirl regular, its centre's speed nearly constant.
    runs = cage_dynamics(800.0, 12000 * RPM, **TEST, cage_eccentricity=np.array([0.0, 2 * MM]),
                         duration=0.04, output_interval=2e-4)
    free, eccentric = runs["whirl_deviation_ratio"]
    assert eccentric < 0.2 * free
