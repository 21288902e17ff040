"""Lives over a duty cycle (Palmgren-Miner) and of a system of bearings (Weibull), by hand."""
import numpy as np
import pytest

from bearing_sweep.models.life_combination import (WEIBULL_SLOPES, duty_cycle_life,
                                                   system_life)


def test_miner_s_rule_by_hand():
    """Half the time at a life of 1000 h, half at 4000 h: 1 / (0.5/1000 + 0.5/4000) = 1600 h;
    shares are scaled to sum to one, and a case that uses up nothing adds nothing."""
    assert duty_cycle_life([1000.0, 4000.0], [0.5, 0.5]) == pytest.approx(1600.0, rel=1e-15)
    assert duty_cycle_life([1000.0, 4000.0], [1.0, 1.0]) == pytest.approx(1600.0, rel=1e-15)
    assert duty_cycle_life([1000.0, np.inf], [0.25, 0.75]) == pytest.approx(4000.0, rel=1e-15)
    assert np.isnan(duty_cycle_life([1000.0, np.nan], [0.5, 0.5]))


def test_a_system_of_alike_bearings_by_the_closed_form():
    """Two bearings of life L and slope e: L 2^(-1/e); ball bearings, e = 10/9: 0.5359 L."""
    life = system_life([5000.0, 5000.0], WEIBULL_SLOPES["ball"])
    assert life == pytest.approx(5000.0 * 2 ** (-0.9), rel=1e-14)
    assert life / 5000.0 == pytest.approx(0.5359, abs=1e-4)
    assert system_life([5000.0, np.inf], 9 / 8) == pytest.approx(5000.0, rel=1e-14)
    assert system_life([np.inf, np.inf], 9 / 8) == np.inf
    assert system_life([np.inf, np.inf], [10 / 9, 9 / 8]) == np.inf


def test_a_system_of_ball_and_roller_bearings_survives_as_the_product_of_their_survivals():
    """At the system's life, the product of the Weibull survivals 0.9^((L / L_i)^e_i) is 0.9
    (Lundberg and Palmgren); with one slope the result is the closed form's."""
    lives = np.array([[3000.0, 8000.0, 20000.0], [1.0, 1.0, 1.0]])
    slopes = [WEIBULL_SLOPES["ball"], WEIBULL_SLOPES["ball"], WEIBULL_SLOPES["roller"]]
    found = system_life(lives, slopes)
    survival = np.prod(0.9 ** ((found[:, None] / lives) ** np.array(slopes)), axis=-1)
    np.testing.assert_allclose(survival, 0.9, rtol=1e-14)
    assert found[0] < 3000.0
    mixed = system_life([[3000.0, 8000.0]], [[10 / 9, 9 / 8]])[0]
    assert system_life([3000.0, 8000.0], 10 / 9) < mixed < system_life([3000.0, 8000.0], 9 / 8)


def test_the_lives_combine_along_any_axis():
    lives = np.array([[1000.0, 2000.0], [4000.0, 8000.0]])
    np.testing.assert_allclose(duty_cycle_life(lives, [[0.5], [0.5]], axis=0),
                               [1600.0, 3200.0], rtol=1e-15)
    np.testing.assert_allclose(system_life(lives, 10 / 9, axis=0),
                               system_life(lives.T, 10 / 9), rtol=1e-15)
