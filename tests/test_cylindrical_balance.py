"""crb_radial's compiled roller balances against the vectorised contact law they compile."""
import numpy as np
import pytest

from bearing_sweep.models.contact import LINE_CONTACT_EXPONENT, sliced_line_contact
from bearing_sweep.models.cylindrical_balance import (ninth_roots, roller_balances,
                                                      sliced_contact)
from bearing_sweep.models.profiles import distinct_slices

N = LINE_CONTACT_EXPONENT
CONSTANT = 6.0e9  # [N/m^(10/9)], about Palmgren's for a 10 mm roller


def test_ninth_roots_are_within_two_ulps():
    values = np.concatenate([np.logspace(-300, 300, 2001),
                             np.random.default_rng(1).uniform(1e-12, 2e-5, 999)])
    roots = np.full(values.size + 3, -1.0)
    ninth_roots(values, roots, values.size)
    # In extended precision: a double's 1/9 is 6e-18 short, which far from 1 moves x^(1/9)
    # by 20 ulps (ln(1e300) 6e-18 = 4e-15).
    exact = (values.astype(np.longdouble) ** (np.longdouble(1) / 9)).astype(float)
    assert np.max(np.abs(roots[:values.size] / exact - 1)) <= 2 * np.finfo(float).eps
    assert np.all(roots[values.size:] == -1.0)  # only ``count`` entries are written


@pytest.mark.parametrize("law", ["uniform", "paper"])
def test_a_compiled_contact_is_the_sliced_line_contact(law):
    # Approaches below the first gap, among the gaps and beyond the largest.
    shape, counts = distinct_slices(60)
    gaps = 4e-6 * shape
    work, roots = np.empty(gaps.size), np.empty(gaps.size)
    for approach in (-1e-6, 0.0, 1e-7, 2.3e-6, 3.999e-6, 9e-6):
        load, stiffness = sliced_contact(approach, gaps, counts, counts.sum(), CONSTANT,
                                         law == "paper", work, roots)
        expected = sliced_line_contact(np.array([approach]), gaps[None], counts,
                                       np.array([CONSTANT]), law)
        # Both sum the same terms; each power is within 2 ulps (above), the sums' order
        # differs: agreement to a few ulps of the load.
        assert load == pytest.approx(expected[0][0], rel=1e-14, abs=1e-300)
        assert stiffness == pytest.approx(expected[1][0], rel=1e-14, abs=1e-300)


def _balances(total, split, centrifugal=40.0, crowned=True):
    shape, counts = distinct_slices(60)
    gaps = np.ascontiguousarray((4e-6 * shape)[None, None, :])
    free = 0.0 if centrifugal == 0 else 2e-7  # below any balance's outer approach
    available = total - free
    outputs = [np.empty(total.shape) for _ in range(3)]
    converged = roller_balances(total, available, np.zeros(total.shape[0], dtype=np.int64),
                                gaps, counts, np.array([CONSTANT]), np.array([centrifugal]),
                                False, crowned, 1e-13, split, *outputs)
    return (*outputs, converged, gaps[0, 0], counts)


@pytest.mark.parametrize("crowned", [True, False])
def test_each_roller_is_in_force_balance_whatever_its_start(crowned):
    total = np.array([[1e-6, 3e-6, 6e-6, 12e-6, -1e-6]])
    cold = np.full(total.shape + (3,), np.nan)
    load, stiffness, inner, converged, gaps, counts = _balances(total, cold, crowned=crowned)
    assert converged.all() and np.all(np.isfinite(cold[0, :4]))
    assert inner[0, 4] == total[0, 4] - 2e-7 and load[0, 4] == 0.0 == stiffness[0, 4]
    # Qo(total - x) = Qt(x) + Fc, by the vectorised law (crowned outer, or the paper's
    # straight outer contact against a straight inner one).
    x, outer = inner[0, :4], total[0, :4] - inner[0, :4]
    constant = np.full(4, CONSTANT)
    if crowned:
        balanced = sliced_line_contact(x, np.tile(gaps, (4, 1)), counts, constant)[0]
        outer_load = sliced_line_contact(outer, np.tile(gaps, (4, 1)), counts, constant)[0]
    else:
        balanced = CONSTANT * x**N
        outer_load = CONSTANT * outer**N
    np.testing.assert_allclose(outer_load, balanced + 40.0, rtol=1e-11)
    # Started from a prediction (the last solution moved along its derivative) or from
    # halfway, the solution is the same within the tolerance 1e-13 of the approach.
    moved = total * 1.01
    predicted = _balances(moved, cold.copy(), crowned=crowned)[2]
    fresh = _balances(moved, np.full(cold.shape, np.nan), crowned=crowned)[2]
    np.testing.assert_allclose(predicted[0, :4], fresh[0, :4], rtol=0, atol=1e-13 * 12e-6)
