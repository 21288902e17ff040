"""Crown profile (paper 000 eq. 8), Palmgren's constant and the sliced line contact."""
import numpy as np
import pytest

from models.contact import LINE_CONTACT_EXPONENT, palmgren_constant, sliced_line_contact
from models.profiles import crown_shape, distinct_slices, slice_centres


def test_slice_centres_are_symmetric_and_evenly_spaced():
    x = slice_centres(6)
    np.testing.assert_allclose(x, [-5 / 6, -3 / 6, -1 / 6, 1 / 6, 3 / 6, 5 / 6])
    assert np.array_equal(x, -x[::-1])


def test_logarithmic_crown_follows_eq8():
    # Paper 000 eq. 8: c = 0.2 cmax ln(1 / (1.0067 - ((2 lambda - 1)/k - 1)^2)).
    k = 10
    expected = [0.2 * np.log(1 / (1.0067 - ((2 * lam - 1) / k - 1) ** 2)) for lam in range(1, k + 1)]
    np.testing.assert_allclose(crown_shape(k), np.maximum(expected, 0.0), rtol=1e-12)


def test_logarithmic_crown_reaches_cmax_at_the_ends_and_zero_in_the_middle():
    shape = crown_shape(100000)  # the end slice's centre approaches x = 1
    assert shape[0] == pytest.approx(1.0, abs=0.01)  # 0.2 ln(1/0.0067) = 1.001 at x = 1
    assert shape.min() == 0.0  # eq. 8's -0.0013 cmax at the middle is clipped


def test_distinct_slices_keep_every_slice():
    for k in (1, 7, 60):
        shape, count = distinct_slices(k)
        assert count.sum() == k
        np.testing.assert_allclose(np.repeat(shape, count.astype(int)), np.sort(crown_shape(k)))
    shape, count = distinct_slices(60, "none")
    assert shape.tolist() == [0.0] and count.tolist() == [60.0]


def test_palmgren_constant_in_si():
    # Q = 8.06e4 l^(8/9) delta^(10/9) with N and mm: l = 10 mm, delta = 0.01 mm.
    q_newton = 8.06e4 * 10 ** (8 / 9) * 0.01 ** (10 / 9)
    assert palmgren_constant(10e-3) * (0.01e-3) ** LINE_CONTACT_EXPONENT == pytest.approx(q_newton)


@pytest.mark.parametrize("law", ["uniform", "paper"])
def test_straight_roller_carries_k_delta_n_at_any_slice_count(law):
    constant = np.array([2.0e9])
    delta = np.array([4e-6])
    for k in (1, 10, 61):
        gaps = np.zeros((1, k))
        load, stiffness = sliced_line_contact(delta, gaps, np.ones(k), constant, law)
        n = LINE_CONTACT_EXPONENT
        assert load[0] == pytest.approx(2.0e9 * 4e-6**n, rel=1e-12)
        assert stiffness[0] == pytest.approx(2.0e9 * n * 4e-6 ** (n - 1), rel=1e-12)


def test_uniform_law_stiffness_is_the_derivative_of_the_load():
    shape, count = distinct_slices(30)
    gaps = 3e-6 * shape[None, :]
    constant = np.array([1.5e9])
    delta = np.array([2.5e-6])
    h = 1e-12
    plus = sliced_line_contact(delta + h, gaps, count, constant)[0]
    minus = sliced_line_contact(delta - h, gaps, count, constant)[0]
    stiffness = sliced_line_contact(delta, gaps, count, constant)[1]
    assert stiffness[0] == pytest.approx((plus - minus)[0] / (2 * h), rel=1e-6)


def test_paper_law_drops_when_a_slice_pair_comes_into_contact():
    # Eq. 9 divides by the loaded slices k_j: just past a gap the load falls (Fig. 9's ripple).
    shape, count = distinct_slices(10)
    gaps = 4e-6 * shape[None, :]
    constant = np.array([1e9])
    second = np.sort(shape)[1] * 4e-6
    before = sliced_line_contact(np.array([second - 1e-12]), gaps, count, constant, "paper")[0]
    after = sliced_line_contact(np.array([second + 1e-12]), gaps, count, constant, "paper")[0]
    assert after[0] < before[0]
