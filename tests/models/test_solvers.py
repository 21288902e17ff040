import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from bearing_sweep.models.solvers import solve_increasing


@settings(max_examples=50, deadline=None)
@given(st.lists(st.floats(0.01, 1000.0), min_size=1, max_size=20))
def test_cube_roots(targets):
    targets = np.array(targets)

    def residual(x, index):
        return x**3 - targets[index], 3 * x**2

    x, ok = solve_increasing(residual, np.zeros(targets.size), np.full(targets.size, 11.0),
                             np.full(targets.size, 11.0), 1e-14)
    assert ok.all()
    np.testing.assert_allclose(x, np.cbrt(targets), rtol=1e-12)


def test_downward_jumps_end_at_a_continuous_crossing():
    # f rises with slope 1 and drops by 0.5 at every integer: f(x) = x - 0.5 floor(x).
    def residual(x, index):
        return x - 0.5 * np.floor(x) - 2.2, np.ones_like(x)

    x, ok = solve_increasing(residual, np.zeros(1), np.full(1, 10.0), np.full(1, 9.0), 1e-13)
    assert ok.all()
    assert abs(x[0] - 0.5 * np.floor(x[0]) - 2.2) < 1e-12


def test_unconverged_entries_are_reported():
    def residual(x, index):
        return x - 0.3, np.zeros_like(x)  # no slope: bisection only

    x, ok = solve_increasing(residual, np.zeros(1), np.ones(1), np.ones(1), 1e-15, max_iter=5)
    assert not ok[0]


def test_a_nan_residual_is_not_converged_and_gives_nan():
    # An all-NaN residual used to end mid-bracket by bisection and be reported converged.
    def residual(x, index):
        return np.full_like(x, np.nan), np.full_like(x, np.nan)

    x, ok = solve_increasing(residual, np.zeros(3), np.ones(3), np.full(3, 0.5), 1e-12)
    assert not ok.any()
    assert np.isnan(x).all()


def test_only_the_entries_with_a_nan_residual_fail():
    targets = np.array([0.2, np.nan, 0.7])

    def residual(x, index):
        return x - targets[index], np.ones_like(x)

    x, ok = solve_increasing(residual, np.zeros(3), np.ones(3), np.full(3, 0.5), 1e-12)
    assert ok.tolist() == [True, False, True]
    assert x[0] == pytest.approx(0.2, abs=1e-12) and np.isnan(x[1])


@pytest.mark.parametrize("target", [-1.0, 20.0])
def test_a_root_outside_the_bracket_is_not_converged(target):
    # x - target on [0, 10]: the residual keeps one sign over the bracket; bisection (no
    # slope) used to end on the bracket's end and call it a root.
    def residual(x, index):
        return x - target, np.zeros_like(x)

    x, ok = solve_increasing(residual, np.zeros(1), np.full(1, 10.0), np.full(1, 5.0), 1e-12)
    assert not ok[0]
    assert x[0] == (0.0 if target < 0 else 10.0)


def test_a_root_within_tolerance_of_a_bracket_end_is_found():
    # Bisection alone towards a root 2e-13 above the lower end, with a tolerance of 1e-9: the
    # bracket end is evaluated before the entry ends there.
    def residual(x, index):
        return x - 2e-13, np.zeros_like(x)

    x, ok = solve_increasing(residual, np.zeros(1), np.ones(1), np.ones(1), 1e-9)
    assert ok[0]
    assert abs(x[0] - 2e-13) <= 1e-9


def test_a_bracket_narrower_than_the_tolerance_fixes_the_root():
    def residual(x, index):
        return x - 3.0, np.ones_like(x)

    x, ok = solve_increasing(residual, np.full(1, 2.0), np.full(1, 2.0), np.full(1, 2.0), 1e-9)
    assert ok[0] and x[0] == 2.0
