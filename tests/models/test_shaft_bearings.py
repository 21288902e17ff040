"""A shaft on ball bearings: the coupled equilibrium against each bearing's own model and the
closed forms of statics."""
import math

import numpy as np
import pytest

from bearing_sweep.models.ball import ball_5dof
from bearing_sweep.models.registry import OUT_OF_VALIDITY
from bearing_sweep.models.shaft_bearings import BallSupport, solve_shaft_on_bearings

E, NU = 207e9, 0.3
#: The 71807AC of paper 001 with its Hertz constant (SI).
ACBB = dict(ball_count=25, ball_diameter=3.14e-3, pitch_diameter=0.041,
            contact_angle=math.radians(25.0), inner_curvature_ratio=0.52,
            outer_curvature_ratio=0.53)
#: A deep groove ball bearing (contact angle 0) of an even ball count: each ball has one
#: opposite, so the bearing answers a tilt and its opposite alike.
DEEP_GROOVE = dict(ball_count=10, ball_diameter=12.7e-3, pitch_diameter=0.06,
                   contact_angle=0.0, inner_curvature_ratio=0.52, outer_curvature_ratio=0.53,
                   clearance=10e-6)


def _loads(force=(0.0, 0.0, 0.0, 0.0, 0.0)):
    return np.array([force], dtype=float)


def test_a_stiff_shaft_on_one_bearing_is_that_bearing_s_own_model():
    """Loads at the bearing: its displacement is ball_5dof's for the same loads (a shaft on
    one bearing alone rests on its five directions)."""
    loads = (1000.0, 300.0, -150.0, 0.4, -0.2)
    result = solve_shaft_on_bearings([0.05], [0.03], [0.0], E, NU, [0.025],
                                     [BallSupport(**ACBB)], [0.025], _loads(loads))
    alone = ball_5dof(**ACBB, axial_load=loads[0], radial_load=loads[1],
                      radial_load_z=loads[2], moment_y=loads[3], moment_z=loads[4])
    assert result["converged"]
    np.testing.assert_allclose(result["bearing_displacement"][0], alone["displacement"][0],
                               rtol=1e-7, atol=1e-13)
    np.testing.assert_allclose(result["bearing_load"][0], loads, rtol=1e-9, atol=1e-9)


def test_a_load_beside_the_bearing_reaches_it_with_its_moment():
    """A radial force F_y at a distance a along x from the bearing is F_y with a moment
    M_z = a F_y about the bearing (right-handed); the shaft between bends, so the bearing's
    displacement is ball_5dof's under that force and moment."""
    a, force = 0.02, 400.0
    result = solve_shaft_on_bearings([0.06], [0.03], [0.0], E, NU, [0.02],
                                     [BallSupport(**ACBB)], [0.02 + a],
                                     _loads((800.0, force, 0.0, 0.0, 0.0)))
    alone = ball_5dof(**ACBB, axial_load=800.0, radial_load=force, moment_z=a * force)
    np.testing.assert_allclose(result["bearing_load"][0], [800.0, force, 0, 0, a * force],
                               rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(result["bearing_displacement"][0], alone["displacement"][0],
                               rtol=1e-7, atol=1e-13)


@pytest.mark.parametrize("position", [0.1, 0.15, 0.22])
def test_a_shaft_on_two_deep_groove_bearings_shares_its_load_by_statics(position):
    """Two deep groove ball bearings at 0.05 and 0.25 m, a rigid axial stop at the left end:
    the bearings' radial loads are the simply supported beam's reactions P (b / L) and
    P (a / L) to within the moments the bearings' tilt stiffness takes (small against the
    load times the span)."""
    force, left, right = 5000.0, 0.05, 0.25
    result = solve_shaft_on_bearings(
        [0.3], [0.04], [0.0], E, NU, [left, right],
        [BallSupport(**DEEP_GROOVE), BallSupport(**DEEP_GROOVE)], [position],
        _loads((0.0, force, 0.0, 0.0, 0.0)), spring_positions=[0.0],
        spring_stiffness=[[math.inf, 0, 0, 0, 0]])
    span = right - left
    carried = result["bearing_load"][:, 1]
    assert result["converged"]
    assert carried.sum() == pytest.approx(force, rel=1e-9)
    np.testing.assert_allclose(carried, [force * (right - position) / span,
                                         force * (position - left) / span], rtol=2e-2)
    # What the moments change: the reactions balance the load's moment with them exactly.
    moments = result["bearing_load"][:, 4]
    assert (carried[1] * span - force * (position - left) + moments.sum()
            == pytest.approx(0.0, abs=1e-6 * force * span))


def test_a_central_load_on_a_symmetric_shaft_gives_each_bearing_half():
    """By symmetry, whatever the bearings: two alike bearings symmetric about a central load
    each carry half of it (bearings that answer a tilt and its opposite alike: with an odd
    ball count, they differ by some 4e-6 of the load). The shaft's axial stop is in the
    middle too: tilted, the bearings push axially on the shaft, which a stop at one end would
    take unevenly through the shaft's stretch."""
    result = solve_shaft_on_bearings(
        [0.3], [0.04], [0.0], E, NU, [0.05, 0.25],
        [BallSupport(**DEEP_GROOVE), BallSupport(**DEEP_GROOVE)], [0.15],
        _loads((0.0, 3000.0, -1000.0, 0.0, 0.0)), spring_positions=[0.15],
        spring_stiffness=[[math.inf, 0, 0, 0, 0]])
    np.testing.assert_allclose(result["bearing_load"][:, 1:3], [[1500.0, -500.0]] * 2,
                               rtol=1e-9)


def test_the_system_s_stiffness_is_the_derivative_of_its_equilibrium():
    """The compliance the system's tangent gives at the load's node against the change of
    the equilibrium under a small change of each load component (central differences)."""
    bearings = [BallSupport(**ACBB), BallSupport(**ACBB)]
    arguments = ([0.12], [0.03], [0.0], E, NU, [0.02, 0.1], bearings, [0.06])
    loads = np.array([600.0, 500.0, 200.0, 1.0, -2.0])
    result = solve_shaft_on_bearings(*arguments, _loads(loads))
    assert result["converged"]
    node = int(np.argmin(np.abs(result["nodes"] - 0.06)))
    rows = np.cumsum(result["free"])[5 * node + np.arange(5)] - 1
    compliance = np.linalg.inv(result["stiffness"])[np.ix_(rows, rows)]
    for column, step in enumerate([1.0, 1.0, 1.0, 0.01, 0.01]):
        change = np.zeros(5)
        change[column] = step
        moved = [solve_shaft_on_bearings(*arguments, _loads(loads + sign * change))
                 ["node_displacement"][node] for sign in (1, -1)]
        np.testing.assert_allclose((moved[0] - moved[1]) / (2 * step), compliance[:, column],
                                   rtol=1e-4, atol=1e-4 * np.abs(compliance).max())


def test_a_bearing_s_tangent_is_the_derivative_of_its_loads():
    """Each bearing's stiffness at the solution against central differences of its loads."""
    bearings = [BallSupport(**ACBB), BallSupport(**ACBB)]
    arguments = ([0.12], [0.03], [0.0], E, NU, [0.02, 0.1], bearings, [0.06])
    result = solve_shaft_on_bearings(*arguments, _loads((600.0, 500.0, 200.0, 0.0, 0.0)))
    assert result["converged"]
    for bearing, displacement in zip(bearings, result["bearing_displacement"]):
        _, tangent = bearing.loads(displacement[None])
        for column in range(5):
            step = np.zeros(5)
            step[column] = 1e-9 if column < 3 else 1e-7
            plus, _ = bearing.loads((displacement + step)[None])
            minus, _ = bearing.loads((displacement - step)[None])
            np.testing.assert_allclose(tangent[0][:, column],
                                       (plus[0] - minus[0]) / (2 * step[column]),
                                       rtol=1e-4, atol=1e-3 * np.abs(tangent[0]).max())



def test_a_bearing_outside_its_model_s_validity_is_flagged_as_its_model_flags_it():
    """An angular contact bearing pulled against its contact angle carries the pull on the
    other side of its grooves: ball_5dof solves it and marks it out of validity; so does the
    shaft's equilibrium, with the same displacement."""
    loads = (-1000.0, 100.0, 0.0, 0.0, 0.0)
    result = solve_shaft_on_bearings([0.05], [0.03], [0.0], E, NU, [0.025],
                                     [BallSupport(**ACBB)], [0.025], _loads(loads))
    alone = ball_5dof(**ACBB, axial_load=loads[0], radial_load=loads[1])
    assert alone["status"][0] & OUT_OF_VALIDITY
    assert result["converged"] and result["bearing_outside_validity"].tolist() == [True]
    np.testing.assert_allclose(result["bearing_displacement"][0], alone["displacement"][0],
                               rtol=1e-7, atol=1e-13)
    within = solve_shaft_on_bearings([0.05], [0.03], [0.0], E, NU, [0.025],
                                     [BallSupport(**ACBB)], [0.025],
                                     _loads((1000.0, 100.0, 0.0, 0.0, 0.0)))
    assert within["bearing_outside_validity"].tolist() == [False]


@pytest.mark.parametrize("loads", [(500.0, 200.0, 0.0, 0.0, 0.0), (3e4, 0.0, 0.0, 0.0, 0.0),
                                   (2000.0, 1500.0, 0.0, 0.0, 5.0)])
def test_the_flag_is_ball_5dof_s_at_the_same_loads(loads):
    """Heavy loads take a ball above 4200 MPa (ISO 76's reference stress)."""
    result = solve_shaft_on_bearings([0.05], [0.03], [0.0], E, NU, [0.025],
                                     [BallSupport(**ACBB)], [0.025], _loads(loads))
    alone = ball_5dof(**ACBB, axial_load=loads[0], radial_load=loads[1], moment_z=loads[4])
    assert result["bearing_outside_validity"][0] == bool(alone["status"][0] & OUT_OF_VALIDITY)
