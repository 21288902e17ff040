"""Static safety from the load distribution's largest contact pressure (ISO 76's reference
stresses), and the application's minimum."""
import math

import numpy as np
import pytest

from bearing_sweep.models.ball import ball_5dof
from bearing_sweep.models.contact import hertz_point
from bearing_sweep.models.cylindrical import crb_radial
from bearing_sweep.models.registry import OUT_OF_VALIDITY, out_of_validity
from bearing_sweep.models.tapered import trb_load

#: A cylindrical roller bearing of straight rollers, in mm (crb_radial_throughput's).
Z, D, DM, L = 14, 10.0, 65.0, 9.6


def test_a_roller_bearing_at_its_iso_76_rating_has_the_safety_of_its_load_share():
    """ISO 76:2006: C0r = 44 (1 - D/dm) Z l D is the radial load that gives 4000 MPa at the
    most loaded roller if it carried Q_max = 5 Fr / Z (ISO/TR 10657); without clearance
    rollers share the load better, Q_max = 4.08 Fr / Z (Palmgren; Harris and Kotzalas,
    Rolling Bearing Analysis, ch. 7), so the safety at Fr = C0r is 5 / 4.08 (the pressure
    grows as the load's square root). Tolerance 1 %: 44 is rounded (44.2 for steel) and 4.08
    holds for many rollers (14 here)."""
    rating = 44 * (1 - D / DM) * Z * L * D  # [N], lengths in mm
    result = crb_radial(rating, Z, DM * 1e-3, D * 1e-3, L * 1e-3)
    assert result["pressure_safety_factor"] == pytest.approx(5 / 4.08, rel=1e-2)


def test_the_safety_is_the_load_factor_that_takes_the_pressure_to_the_reference():
    """The most loaded ball's load times the safety gives ISO 76's 4200 MPa at its more
    curved contact, as hertz_point finds it from the curvatures."""
    diameter, pitch = 12.7e-3, 65e-3
    result = ball_5dof(9, diameter, pitch, 0.0, 0.52, 0.53, radial_load=6000.0,
                       fixed_dofs="axial tilt_y tilt_z")
    ball = 2 / diameter
    load = result["ball_load"].max() * result["pressure_safety_factor"][0]
    contact = hertz_point(load, ball, ball, ball * diameter / (pitch - diameter),
                          -1 / (0.52 * diameter))
    assert contact["max_pressure"] == pytest.approx(4200e6, rel=1e-9)


@pytest.mark.parametrize("model", ["crb_radial", "ball_5dof", "trb_load"])
def test_without_clearance_the_safety_falls_as_one_over_the_load(model):
    """Without clearance, and with contact angles that do not follow the load, the load
    distribution keeps its shape as the load grows, so the most loaded element's load, and
    with it 1 / s0, grows in proportion."""
    loads = np.array([1000.0, 2000.0, 5000.0])
    result = {
        "crb_radial": lambda: crb_radial(loads, Z, DM * 1e-3, D * 1e-3, L * 1e-3),
        "ball_5dof": lambda: ball_5dof(9, 12.7e-3, 65e-3, math.radians(25), axial_load=loads,
                                       radial_load=loads / 2, geometry="fixed_angle",
                                       fixed_dofs="tilt_y tilt_z"),
        "trb_load": lambda: trb_load(loads / 2, loads, 17, 15e-3, 8e-3, math.radians(15),
                                     pitch_diameter=60e-3),
    }[model]()
    safety = result["pressure_safety_factor"]
    np.testing.assert_allclose(safety * loads, safety[0] * loads[0], rtol=1e-8)


def test_a_point_below_the_minimum_static_safety_is_out_of_validity_with_its_values():
    loads = np.array([2000.0, 60_000.0])
    free = crb_radial(loads, Z, DM * 1e-3, D * 1e-3, L * 1e-3)
    checked = crb_radial(loads, Z, DM * 1e-3, D * 1e-3, L * 1e-3, minimum_static_safety=2.0)
    assert free["pressure_safety_factor"][0] > 2.0 > free["pressure_safety_factor"][1] > 1.0
    assert not out_of_validity(free["status"]).any()
    assert checked["status"][1] == OUT_OF_VALIDITY and not out_of_validity(checked["status"][0])
    np.testing.assert_array_equal(checked["radial_stiffness"], free["radial_stiffness"])


def test_the_roller_bearings_static_rating_is_iso_76s_and_gives_4000_mpa_at_its_share():
    """ISO 76:2006, 5.1: C0r = 44 (1 - D cos a / dm) Z l D cos a (N, mm), the radial load at
    which the most loaded roller, carrying 5 Fr / (Z cos a) (ISO/TR 10657), reaches 4000 MPa.
    Tolerance 0.5 %: 44 is rounded (44.2 for steel, E = 207 GPa, nu = 0.3)."""
    from bearing_sweep.models.contact import line_contact_pressure
    result = crb_radial(5000.0, Z, DM * 1e-3, D * 1e-3, L * 1e-3)
    rating = 44 * (1 - D / DM) * Z * L * D
    assert result["static_load_rating"] == pytest.approx(rating, rel=1e-12)
    share = 5 * rating / Z / (L * 1e-3)
    pressure = line_contact_pressure(share, 2 / (D * 1e-3) + 2 / ((DM - D) * 1e-3),
                                     207e9 / (2 * (1 - 0.3**2)))
    assert pressure == pytest.approx(4000e6, rel=5e-3)
    assert result["static_safety_factor"] == pytest.approx(rating / 5000.0, rel=1e-12)


def test_a_tapered_bearings_static_equivalent_load_is_iso_76s():
    """ISO 76:2006, 5.2, single row, a != 0: P0r = 0.5 Fr + 0.22 cot(a) Fa, but not below
    Fr; C0r with the contact angle's cosine."""
    angle = math.radians(15)
    radial, axial = np.array([10e3, 10e3]), np.array([4e3, 40e3])
    result = trb_load(radial, axial, 17, 15e-3, 8e-3, angle, pitch_diameter=60e-3)
    expected = np.maximum(radial, 0.5 * radial + 0.22 / math.tan(angle) * axial)
    assert expected[0] == radial[0] and expected[1] > radial[1]  # both branches
    np.testing.assert_allclose(result["static_equivalent_load"], expected, rtol=1e-12)
    rating = 44 * (1 - 8 * math.cos(angle) / 60) * 17 * 15 * 8 * math.cos(angle)
    np.testing.assert_allclose(result["static_load_rating"], rating, rtol=1e-12)


@pytest.mark.parametrize("ratio, printed", [(0.0, 14.7), (0.02, 15.1), (0.05, 15.7), (0.08, 16.3),
                                            (0.09, 16.5), (0.10, 16.4), (0.12, 15.9),
                                            (0.15, 15.2), (0.20, 14.0)])
def test_the_ball_bearings_static_rating_has_iso_76s_f0(ratio, printed):
    """ISO 76:2006, Table 1: f0 of radial and angular contact groove ball bearings against
    D cos a / dm, as printed (to 0.1); ours from the table's basis (4200 MPa at 5 Fr / (Z cos
    a), grooves 0.52 and 0.53 D). Tolerance 0.06: the table's rounding."""
    diameter, balls = 10e-3, 9
    pitch = diameter / ratio if ratio else 1e3
    result = ball_5dof(balls, diameter, pitch, 0.0, radial_load=100.0,
                       fixed_dofs="axial tilt_y tilt_z")
    factor = result["static_load_rating"][0] / (balls * (diameter * 1e3) ** 2)  # N, mm
    assert factor == pytest.approx(printed, abs=0.06)


def test_a_ball_bearings_static_equivalent_load_is_iso_76s():
    """ISO 76:2006, 4.2: X0 = 0.6, Y0 = 0.5 for a deep-groove bearing, X0 = 0.5, Y0 = 0.38
    at 25 deg; never below Fr; none under a moment."""
    from bearing_sweep.models.static_safety import ball_rating
    radial, axial = np.array([1000.0, 1000.0, 1000.0]), np.array([200.0, 3000.0, 3000.0])
    deep = ball_rating(9, 10e-3, 60e-3, 0.0, radial, axial, np.array([0.0, 0.0, 5.0]))
    np.testing.assert_allclose(deep["static_equivalent_load"][:2], [1000.0, 2100.0])
    assert np.isnan(deep["static_equivalent_load"][2])
    angular = ball_rating(9, 10e-3, 60e-3, math.radians(25), radial, axial, 0.0)
    np.testing.assert_allclose(angular["static_equivalent_load"], [1000.0, 1640.0, 1640.0])
