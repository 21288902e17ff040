"""The shaft as Timoshenko beam elements on linear supports, against the closed forms of
beam theory."""
import math

import numpy as np
import pytest

from bearing_sweep.models.shaft import (bending_element_stiffness, cowper_shear_coefficient,
                                        solve_shaft)

E, NU = 207e9, 0.3
G = E / (2 * (1 + NU))
RIGID = math.inf
#: Simple support: held radially in both planes and (the first one) axially, free to tilt.
PINNED_AXIALLY = [RIGID, RIGID, RIGID, 0.0, 0.0]
PINNED = [0.0, RIGID, RIGID, 0.0, 0.0]
CLAMPED = [RIGID] * 5


def load_y(force, count=1):
    loads = np.zeros((count, 5))
    loads[0, 1] = force
    return loads


def solid(diameter):
    area = math.pi * diameter ** 2 / 4
    return area, math.pi * diameter ** 4 / 64, cowper_shear_coefficient(NU) * G * area


def test_a_simply_supported_shaft_with_a_central_load_puts_half_on_each_support():
    """Statics: by symmetry each support carries half the load, whatever the shaft."""
    result = solve_shaft([0.1, 0.2, 0.1], [0.04, 0.05, 0.04], [0.0, 0.01, 0.0], E, NU,
                         [0.0, 0.4], [PINNED_AXIALLY, PINNED], [0.2], load_y(-5000.0))
    np.testing.assert_allclose(result["support_load"][:, 1], [-2500.0, -2500.0], rtol=1e-9)


def test_an_overhung_load_lifts_the_far_support():
    """Statics: supports at 0 and a, the load P at a + b: the near support carries
    P (a + b) / a, the far one -P b / a."""
    a, b, force = 0.3, 0.1, 1000.0
    result = solve_shaft([a + b], [0.04], [0.0], E, NU, [0.0, a], [PINNED_AXIALLY, PINNED],
                         [a + b], load_y(force))
    np.testing.assert_allclose(result["support_load"][:, 1],
                               [-force * b / a, force * (a + b) / a], rtol=1e-9)


def test_a_continuous_shaft_on_three_supports_shares_a_mid_span_load_13_22_minus_3():
    """Two equal spans, the load P in the middle of the first: the reactions are 13/32 P,
    11/16 P and -3/32 P (AISC Steel Construction Manual, Beam Diagrams and Formulas, case 30,
    continuous beam of two equal spans, concentrated load at the centre of one span; Roark's
    Formulas for Stress and Strain, Table 8.1). Euler-Bernoulli: a slender shaft (span 100
    diameters, Phi = 12 EI / (kappa G A L^2) about 2e-4, which moves the reactions by some
    5e-6 of the load), tolerance 1e-4."""
    span, force = 1.0, 1000.0
    result = solve_shaft([2 * span], [0.01], [0.0], E, NU, [0.0, span, 2 * span],
                         [PINNED_AXIALLY, PINNED, PINNED], [span / 2], load_y(force))
    np.testing.assert_allclose(result["support_load"][:, 1] / force,
                               [13 / 32, 11 / 16, -3 / 32], rtol=1e-4)


@pytest.mark.parametrize("diameter", [0.01, 0.05, 0.2])
def test_the_central_deflection_is_euler_bernoulli_s_plus_timoshenko_s_shear_part(diameter):
    """Simply supported, span L, central load P: P L^3 / (48 EI) + P L / (4 kappa G A)
    (S. P. Timoshenko and J. M. Gere, Mechanics of Materials, sec. 10.3, shear deflection),
    exact for nodes at the load; a stubby shaft's shear part is large."""
    span, force = 0.4, 2000.0
    area, inertia, shear = solid(diameter)
    result = solve_shaft([span], [diameter], [0.0], E, NU, [0.0, span],
                         [PINNED_AXIALLY, PINNED], [span / 2], load_y(force), stations=[span / 2])
    expected = force * span ** 3 / (48 * E * inertia) + force * span / (4 * shear)
    assert result["station_displacement"][0, 1] == pytest.approx(expected, rel=1e-9)


def test_a_cantilever_of_two_sections_bends_as_the_moment_area_method_says():
    """Tip load P on a cantilever of sections a (I1) and b (I2) from the clamp:
    P / E ((L^3 - b^3) / (3 I1) + b^3 / (3 I2)) plus the shear parts P a / (kappa G A1) +
    P b / (kappa G A2); the tip's slope P / E ((L^2 - b^2) / (2 I1) + b^2 / (2 I2))."""
    a, b, force = 0.2, 0.1, 500.0
    (_, i1, s1), (_, i2, s2) = solid(0.03), solid(0.02)
    length = a + b
    result = solve_shaft([a, b], [0.03, 0.02], [0.0, 0.0], E, NU, [0.0], [CLAMPED],
                         [length], load_y(force), stations=[length])
    tip = result["station_displacement"][0]
    assert tip[1] == pytest.approx(force / E * ((length ** 3 - b ** 3) / (3 * i1)
                                                + b ** 3 / (3 * i2))
                                   + force * a / s1 + force * b / s2, rel=1e-9)
    assert tip[4] == pytest.approx(force / E * ((length ** 2 - b ** 2) / (2 * i1)
                                                + b ** 2 / (2 * i2)), rel=1e-9)


def test_the_two_bending_planes_and_the_axial_bar_are_alike():
    """A load along z bends the shaft as the same load along y does, with the tilt about y
    of the opposite sign (right-handed: dw/dx = -theta_y); an axial load stretches it by
    F L / (E A) up to a support held axially."""
    length = 0.3
    loads = np.zeros((2, 1, 5))
    loads[0, 0, 1] = loads[1, 0, 2] = 800.0
    result = solve_shaft([length], [0.03], [0.0], E, NU, [0.0], [CLAMPED], [length], loads,
                         stations=[length])["station_displacement"][:, 0]
    assert result[1, 2] == pytest.approx(result[0, 1], rel=1e-12)
    assert result[1, 3] == pytest.approx(-result[0, 4], rel=1e-12)
    axial = np.zeros((1, 5))
    axial[0, 0] = 1e4
    stretch = solve_shaft([length], [0.03], [0.0], E, NU, [0.0], [CLAMPED], [length], axial,
                          stations=[length])["station_displacement"][0, 0]
    assert stretch == pytest.approx(1e4 * length / (E * solid(0.03)[0]), rel=1e-12)


def test_springs_carry_what_their_stiffness_and_displacement_say_and_balance_the_loads():
    loads = np.zeros((1, 5))
    loads[0, 1:3] = [3000.0, -1000.0]
    result = solve_shaft([0.25, 0.15], [0.04, 0.035], [0.0, 0.0], E, NU, [0.02, 0.38],
                         [[1e8, 2e8, 2e8, 1e4, 1e4], [0.0, 5e8, 5e8, 0.0, 0.0]], [0.2], loads)
    carried = result["support_load"]
    np.testing.assert_allclose(carried.sum(axis=0)[1:3], [3000.0, -1000.0], rtol=1e-9)
    assert carried[1, 1] == pytest.approx(5e8 * result["support_displacement"][1, 1],
                                          rel=1e-12)


def test_a_shaft_free_to_move_is_not_solvable():
    result = solve_shaft([0.3], [0.03], [0.0], E, NU, [0.1], [PINNED_AXIALLY], [0.2],
                         load_y(100.0))
    assert not result["solvable"] and np.isnan(result["support_load"]).all()


def test_the_element_is_euler_bernoulli_s_when_rigid_in_shear():
    """Phi = 0: the cubic beam element, 12 EI / L^3 ... (Przemieniecki, eq. 5.112)."""
    matrix = bending_element_stiffness(2.0, 8.0, math.inf)
    np.testing.assert_allclose(matrix, [[12, 12, -12, 12], [12, 16, -12, 8],
                                        [-12, -12, 12, -12], [12, 8, -12, 16]])


def test_cowper_s_coefficient_of_a_solid_shaft_and_a_thin_tube():
    """Cowper (1966), Table 1: 6 (1 + nu) / (7 + 6 nu) = 0.886 for a solid circle at nu =
    0.3; a thin-walled tube (m -> 1): 2 (1 + nu) / (4 + 3 nu) = 0.531."""
    assert cowper_shear_coefficient(0.3) == pytest.approx(6 * 1.3 / 8.8, rel=1e-12)
    assert cowper_shear_coefficient(0.3, 1.0) == pytest.approx(2 * 1.3 / 4.9, rel=1e-12)
