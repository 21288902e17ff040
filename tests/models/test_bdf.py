"""The multistep formulas' arithmetic (models/bdf.py) against what a polynomial's backward
differences must do: a formula of order q is exact for a solution that is a polynomial of
degree q (Shampine and Reichelt, The MATLAB ODE suite, 1997, sec. 2.1), and the differences of
a polynomial rescale and interpolate exactly."""
import numpy as np
import pytest

from bearing_sweep.models import bdf

#: Two components, each a polynomial of degree 6 in t (coefficients from t^0 up).
COEFFICIENTS = np.array([[0.7, -1.3, 0.4, 2.1, -0.6, 0.25, 0.9],
                         [3.0, 0.5, -2.0, 0.0, 1.1, -0.3, -0.4]])


def polynomial(t, degree):
    return COEFFICIENTS[:, :degree + 1] @ t ** np.arange(degree + 1)


def slope(t, degree):
    powers = np.arange(1, degree + 1)
    return COEFFICIENTS[:, 1:degree + 1] @ (powers * t ** (powers - 1))


def backward_differences(t, step, degree, rows=bdf.MAX_ORDER + 3):
    """``D[k]``, the k-th backward difference at ``t`` over points ``step`` apart, from the
    values themselves (numpy's forward differences of the points in time order)."""
    values = np.array([polynomial(t - i * step, degree) for i in range(rows)])[::-1]
    differences = np.zeros((rows, values.shape[1]))
    for k in range(rows - 1):
        differences[k] = np.diff(values, n=k, axis=0)[-1]
    return differences


@pytest.mark.parametrize("order", range(1, bdf.MAX_ORDER + 1))
def test_a_formula_of_order_q_is_exact_for_a_polynomial_of_degree_q(order):
    t, step = 0.3, 0.05
    differences = backward_differences(t, step, order)
    prediction, psi = bdf.predicted(differences, order)
    c = step / bdf.ALPHA[order]
    # y - y_p + psi = c f(y), with f(y) the polynomial's slope at t + step
    solution = prediction - psi + c * slope(t + step, order)
    np.testing.assert_allclose(solution, polynomial(t + step, order), rtol=1e-12)
    # one degree higher it is not: its leading term's error is what the formula estimates
    one_more = bdf.predicted(backward_differences(t, step, order + 1), order)
    higher = one_more[0] - one_more[1] + c * slope(t + step, order + 1)
    assert np.abs(higher - polynomial(t + step, order + 1)).max() > 1e-9


def test_the_fifth_order_formula_is_the_bdf_and_the_others_are_not():
    # Shampine and Reichelt's Table 1: kappa 0 at order 5; the error constants of the BDFs
    # are 1 / (q + 1), the NDFs' smaller.
    assert bdf.KAPPA[5] == 0.0
    assert bdf.ERROR_CONSTANT[5] == pytest.approx(1 / 6, rel=1e-15)
    for order in range(1, 5):
        assert 0 < bdf.ERROR_CONSTANT[order] < 1 / (order + 1)


@pytest.mark.parametrize("order", range(1, bdf.MAX_ORDER + 1))
@pytest.mark.parametrize("factor", [0.2, 0.5, 1.7, 10.0])
def test_rescaled_differences_are_those_at_the_new_step(order, factor):
    t, step = 1.1, 0.02
    differences = backward_differences(t, step, order)
    bdf.change_differences(differences, order, factor)
    expected = backward_differences(t, factor * step, order)
    # the differences of the points themselves lose digits to cancellation, most at high
    # orders and factors
    np.testing.assert_allclose(differences[:order + 1], expected[:order + 1], rtol=1e-9,
                               atol=1e-9 * np.abs(expected).max())


@pytest.mark.parametrize("order", range(1, bdf.MAX_ORDER + 1))
def test_the_differences_interpolate_their_polynomial(order):
    t, step = 0.8, 0.04
    differences = backward_differences(t, step, order)
    found = np.empty(2)
    for at in (t, t - 0.3 * step, t - step, t - 2.5 * step):
        bdf.interpolated(differences, order, t, step, at, found)
        np.testing.assert_allclose(found, polynomial(at, order), rtol=1e-11)


def test_a_step_updates_the_differences_to_the_new_point():
    # After a step of order q to t + h whose correction is the solution less the prediction,
    # D[0] is the new solution and D[1..q] its backward differences.
    order, t, step = 3, 0.5, 0.1
    differences = backward_differences(t, step, order + 1)
    prediction, _ = bdf.predicted(differences, order)
    solution = polynomial(t + step, order + 1)
    bdf.accept(differences, order, solution - prediction)
    expected = backward_differences(t + step, step, order + 1)
    np.testing.assert_allclose(differences[:order + 2], expected[:order + 2], rtol=1e-10,
                               atol=1e-12)


def test_the_order_moves_to_the_one_that_allows_the_longest_step():
    differences = np.zeros((bdf.MAX_ORDER + 3, 1))
    scale = np.ones(1)
    # the lower order's estimate far below the present one's: the order falls
    differences[2] = 1e-12 / bdf.ERROR_CONSTANT[1]
    differences[4] = 1.0 / bdf.ERROR_CONSTANT[3]
    order, factor = bdf.next_order_and_factor(differences, 2, 0.5, scale, 0.9)
    assert order == 1 and factor == bdf.MOST_FACTOR
    # the higher order's far below: it rises, by the factor its estimate allows
    differences[2] = 1.0 / bdf.ERROR_CONSTANT[1]
    differences[4] = 1e-2 / bdf.ERROR_CONSTANT[3]
    order, factor = bdf.next_order_and_factor(differences, 2, 0.5, scale, 0.9)
    assert order == 3 and factor == pytest.approx(0.9 * 1e-2 ** -0.25)
    # neither: it stays
    differences[4] = 1.0 / bdf.ERROR_CONSTANT[3]
    order, factor = bdf.next_order_and_factor(differences, 2, 0.5, scale, 0.9)
    assert order == 2 and factor == pytest.approx(0.9 * 0.5 ** (-1 / 3))
