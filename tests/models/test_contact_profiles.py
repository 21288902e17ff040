"""Crown profile (paper 000 eq. 8), Palmgren's constant, the sliced line contact, its pressure."""
import numpy as np
import pytest

from bearing_sweep.models.contact import (LINE_CONTACT_EXPONENT, largest_slice_line_load, line_contact_pressure,
                            palmgren_constant, sliced_line_contact)
from bearing_sweep.models.profiles import crown_shape, distinct_slices, slice_centres


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


def test_the_pressure_at_iso_76s_static_rating_is_4000_mpa():
    # ISO 76:2006: C0r = 44 (1 - D cos a / dm) i Z l D cos a is the radial load that gives
    # 4000 MPa at the centre of the most heavily loaded roller contact, with the load share
    # Q_max = 5 Fr / (i Z cos a) behind ISO 76's factors (ISO/TR 10657). Tolerance 0.5 %:
    # the factor 44 is rounded (E = 207 GPa, nu = 0.3 give 44.2).
    d, dm, length, z = 10e-3, 65e-3, 9.6e-3, 14
    rating = 44 * (1 - d / dm) * z * (length / 1e-3) * (d / 1e-3)  # [N]; lengths in mm
    line_load = 5 * rating / z / length
    pressure = line_contact_pressure(line_load, 2 / d + 2 / (dm - d), 207e9 / (2 * (1 - 0.3**2)))
    assert pressure == pytest.approx(4000e6, rel=5e-3)


def test_the_largest_slice_line_load_is_the_middle_slices_load_over_its_length():
    # Uniform law: slice lambda carries K/k (delta - c_lambda)^n on l/k; 'paper' law: K/k_j.
    k, constant, length, approach = 10, 3e9, 0.012, 1e-6
    shape, count = distinct_slices(k)
    gaps = 5e-6 * shape
    n = LINE_CONTACT_EXPONENT
    loads = constant / k * np.maximum(approach - 5e-6 * crown_shape(k), 0.0) ** n
    uniform = largest_slice_line_load(np.array(approach), gaps, count, constant, length)
    assert uniform == pytest.approx(loads.max() / (length / k), rel=1e-12)
    loaded = np.count_nonzero(approach > 5e-6 * crown_shape(k))
    paper = largest_slice_line_load(np.array(approach), gaps, count, constant, length, "paper")
    assert paper == pytest.approx(loads.max() * k / loaded / (length / k), rel=1e-12)
    assert 0 < loaded < k
