"""The additive Runge-Kutta method's coefficients (ARK4(3)6L[2]SA) against the order
conditions they must meet: a transcription error in any of them breaks one."""
import itertools

import numpy as np
import pytest

from bearing_sweep.models import additive_runge_kutta as ark

#: The implicit part's full matrix: the diagonal GAMMA but for the explicit first stage.
IMPLICIT = ark.IMPLICIT + np.diag([0.0] + [ark.GAMMA] * (ark.STAGES - 1))
NODES = ark.EXPLICIT.sum(axis=1)


def test_both_parts_share_their_nodes():
    np.testing.assert_allclose(IMPLICIT.sum(axis=1), NODES, rtol=0, atol=1e-14)


@pytest.mark.parametrize("weights, order", [(ark.WEIGHTS, 4), (ark.EMBEDDED, 3)])
def test_the_solutions_meet_the_order_conditions_of_their_order(weights, order):
    # The conditions of an additive method (Kennedy and Carpenter, 2003, sec. 2.2): every
    # rooted tree up to the order, with either part's matrix at each of its inner nodes.
    c = NODES
    conditions = [(weights.sum(), 1.0), (weights @ c, 1 / 2)]
    if order >= 3:
        conditions.append((weights @ c**2, 1 / 3))
        conditions += [(weights @ a @ c, 1 / 6) for a in (ark.EXPLICIT, IMPLICIT)]
    if order >= 4:
        conditions.append((weights @ c**3, 1 / 4))
        for a in (ark.EXPLICIT, IMPLICIT):
            conditions += [(weights @ (c * (a @ c)), 1 / 8), (weights @ a @ c**2, 1 / 12)]
        conditions += [(weights @ a1 @ a2 @ c, 1 / 24)
                       for a1, a2 in itertools.product((ark.EXPLICIT, IMPLICIT), repeat=2)]
    for value, expected in conditions:
        assert value == pytest.approx(expected, abs=1e-12)


def test_the_embedded_solution_is_not_of_fourth_order():
    # Else its difference from the main solution would not estimate the error.
    assert ark.EMBEDDED @ NODES**3 != pytest.approx(1 / 4, abs=1e-6)


def test_the_implicit_part_is_stiffly_accurate_and_l_stable():
    # Its last row is the weights; its stability function R(z) = 1 + z b (I - z A)^-1 1
    # vanishes as z -> -inf.
    np.testing.assert_array_equal(IMPLICIT[-1], ark.WEIGHTS)
    ones = np.ones(ark.STAGES)
    for z in (-1e6, -1e9):
        stability = 1 + z * ark.WEIGHTS @ np.linalg.solve(np.eye(ark.STAGES) - z * IMPLICIT,
                                                          ones)
        assert abs(stability) < 1e-5
