import numpy as np
from hypothesis import given, settings, strategies as st

from models.solvers import solve_increasing


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
