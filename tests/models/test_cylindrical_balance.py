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
    """One bearing whose rollers' total approaches are ``total`` (``(Z,)``)."""
    shape, counts = distinct_slices(60)
    gaps = np.ascontiguousarray((4e-6 * shape)[None, None, :])
    displacement = 12e-6  # the largest total: every cos(phi) within [-1, 1]
    cos = (total / displacement)[None, :]
    free = np.full((1, 1), 2e-7)  # below any balance's outer approach
    roller_load, inner = np.empty(cos.shape), np.empty(cos.shape)
    radial, stiffness, converged = roller_balances(
        np.array([displacement]), np.array([0]), cos, np.zeros(1), np.zeros((1, 1)), free,
        gaps, counts, np.array([CONSTANT]), np.array([centrifugal]), False, crowned, 1e-13,
        split, roller_load, inner)
    assert radial[0] == pytest.approx((roller_load * cos).sum(), rel=1e-14)
    return roller_load[0], inner[0], converged[0], gaps[0, 0], counts


@pytest.mark.parametrize("crowned", [True, False])
def test_each_roller_is_in_force_balance_whatever_its_start(crowned):
    total = np.array([1e-6, 3e-6, 6e-6, 12e-6, -1e-6])
    cold = np.full((1, total.size, 3), np.nan)
    load, inner, converged, gaps, counts = _balances(total, cold, crowned=crowned)
    assert converged and np.all(np.isfinite(cold[0, :4]))
    assert inner[4] == pytest.approx(total[4] - 2e-7, rel=1e-15) and load[4] == 0.0
    # Qo(total - x) = Qt(x) + Fc, by the vectorised law (crowned outer, or the paper's
    # straight outer contact against a straight inner one).
    x, outer = inner[:4], total[:4] - inner[:4]
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
    predicted = _balances(moved, cold.copy(), crowned=crowned)[1]
    fresh = _balances(moved, np.full(cold.shape, np.nan), crowned=crowned)[1]
    np.testing.assert_allclose(predicted[:4], fresh[:4], rtol=0, atol=1e-13 * 12e-6)
