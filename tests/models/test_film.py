"""The lubricant film: Hamrock and Dowson's elliptical contact, Pan and Hamrock's line contact,
and the smallest film and film parameter the bearing models report."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_sweep.models.ball import ball_5dof
from bearing_sweep.models.bearing_film import FILM_OUTPUT_NAMES
from bearing_sweep.models.contact import hertz_point
from bearing_sweep.models.cylindrical import crb_radial
from bearing_sweep.models.lubrication import (entrainment_speed, line_contact_film,
                                              point_contact_film, walther_viscosity)
from bearing_sweep.models.registry import CONVERGED, OUT_OF_VALIDITY
from bearing_sweep.models.tapered import trb_load

RPM = 2 * math.pi / 60
#: An ISO VG 68 mineral oil (viscosity index about 100).
VG68 = {"viscosity_40": 68e-6, "viscosity_100": 8.7e-6}


def test_a_steel_ball_on_a_flat_has_the_film_of_hamrock_and_dowsons_formulas():
    """Hamrock and Dowson (1977), eq. for H_c and H_min as printed, with their groups typed
    here from the definitions: a 20 mm steel ball on a steel flat (R_x = R_y = 10 mm, so
    k = 1 exactly), 100 N, u = 2 m/s, eta_0 = 0.05 Pa s, alpha = 2e-8 1/Pa."""
    modulus = 2.0 / (2.0 * (1.0 - 0.3**2) / 207e9)  # E' of two steel bodies
    radius, load, speed, viscosity, alpha = 0.01, 100.0, 2.0, 0.05, 2e-8
    u_group = viscosity * speed / (modulus * radius)
    w_group = load / (modulus * radius**2)
    g_group = alpha * modulus
    central = radius * 2.69 * u_group**0.67 * g_group**0.53 * w_group**-0.067 * (
        1 - 0.61 * math.exp(-0.73))
    minimum = radius * 3.63 * u_group**0.68 * g_group**0.49 * w_group**-0.073 * (
        1 - math.exp(-0.68))
    contact = hertz_point(load, 100.0, 100.0, 0.0, 0.0, 207e9, 0.3, entrainment_speed=speed,
                          viscosity=viscosity, pressure_viscosity=alpha)
    assert contact["ellipticity"] == pytest.approx(1.0, rel=1e-12)
    assert contact["central_film_thickness"] == pytest.approx(central, rel=1e-12)
    assert contact["minimum_film_thickness"] == pytest.approx(minimum, rel=1e-12)
    assert contact["status"] == CONVERGED


@settings(max_examples=40, deadline=None)
@given(factor=st.floats(1.01, 100.0), load=st.floats(1.0, 1e4), speed=st.floats(0.01, 50.0))
def test_the_film_scales_with_the_published_exponents(factor, load, speed):
    """h_min grows as u^0.68 and eta_0^0.68 and falls as Q^-0.073 (Hamrock and Dowson); the
    line contact's as u^0.694 and w^-0.128 (Pan and Hamrock): the exponents, not a fit."""
    args = dict(radius=5e-3, ellipticity=8.0, viscosity=0.02, pressure_viscosity=2e-8,
                reduced_modulus=2.27e11)
    _, base = point_contact_film(load, speed=speed, **args)
    _, faster = point_contact_film(load, speed=factor * speed, **args)
    _, heavier = point_contact_film(factor * load, speed=speed, **args)
    assert faster / base == pytest.approx(factor**0.68, rel=1e-12)
    assert heavier / base == pytest.approx(factor**-0.073, rel=1e-12)
    line = dict(length=0.01, radius=5e-3, viscosity=0.02, pressure_viscosity=2e-8,
                reduced_modulus=2.27e11)
    _, base = line_contact_film(load, speed=speed, **line)
    _, faster = line_contact_film(load, speed=factor * speed, **line)
    _, heavier = line_contact_film(factor * load, speed=speed, **line)
    assert faster / base == pytest.approx(factor**0.694, rel=1e-12)
    assert heavier / base == pytest.approx(factor**-0.128, rel=1e-12)


def test_a_contact_at_rest_has_no_film_and_an_unloaded_one_none_at_all():
    central, minimum = point_contact_film(np.array([100.0, 0.0]), 5e-3, 8.0, np.array(
        [0.0, 1.0]), 0.02, 2e-8, 2.27e11)
    assert central[0] == minimum[0] == 0.0
    assert np.isnan(central[1]) and np.isnan(minimum[1])


def test_a_contact_entrained_along_its_major_axis_is_out_of_validity():
    """Hamrock and Dowson fitted contacts entrained along the minor axis (R_y > R_x); turned
    by 90 degrees the same contact keeps its ellipse but not a film they vouch for."""
    along = hertz_point(200.0, 100.0, 100.0, 0.0, -90.0, viscosity=0.02,
                        entrainment_speed=5.0)
    across = hertz_point(200.0, 100.0, 100.0, -90.0, 0.0, viscosity=0.02,
                         entrainment_speed=5.0)
    assert along["semi_major"] == pytest.approx(across["semi_major"], rel=1e-12)
    assert along["status"] == CONVERGED
    assert across["status"] == OUT_OF_VALIDITY
    no_oil = hertz_point(200.0, 100.0, 100.0, -90.0, 0.0)
    assert no_oil["status"] == CONVERGED and np.isnan(no_oil["minimum_film_thickness"])


def test_the_entrainment_speed_is_the_raceways_speed_relative_to_the_cage():
    """Pure rolling, inner ring turning: the cage turns at omega (1 - gamma) / 2; either
    raceway passes the ball at the same speed."""
    omega, pitch, ball, angle = 400.0, 0.065, 0.0127, math.radians(25)
    gamma = ball * math.cos(angle) / pitch
    cage = omega * (1 - gamma) / 2
    inner = (omega - cage) * (pitch - ball * math.cos(angle)) / 2
    outer = cage * (pitch + ball * math.cos(angle)) / 2
    assert entrainment_speed(omega, pitch, ball, angle) == pytest.approx(inner, rel=1e-14)
    assert inner == pytest.approx(outer, rel=1e-14)


def _ball(**kwargs):
    return ball_5dof(9, 12.7e-3, 64.9985e-3, 0.0, 0.52, 0.52, radial_load=8900.0,
                     fixed_dofs="axial tilt_y tilt_z", speed=400.0, **kwargs)


def test_the_ball_bearings_film_is_its_most_loaded_balls_inner_contact():
    """The smallest film of a radially loaded deep-groove bearing is that of its most loaded
    ball on the inner raceway (smaller R_x, higher load), as hertz_point gives it from the
    curvatures themselves."""
    result = _ball(composite_roughness=0.065e-6, **VG68)
    diameter, pitch = 12.7e-3, 64.9985e-3
    ball = 2 / diameter
    viscosity = walther_viscosity(343.15, **VG68) * 860.0
    contact = hertz_point(result["ball_load"].max(), ball, ball, ball * diameter / (
        pitch - diameter), -1 / (0.52 * diameter), entrainment_speed=entrainment_speed(
            400.0, pitch, diameter), viscosity=viscosity)
    assert result["minimum_film_thickness"][0] == pytest.approx(
        contact["minimum_film_thickness"], rel=1e-9)
    assert result["central_film_thickness"][0] == pytest.approx(
        contact["central_film_thickness"], rel=1e-9)
    assert result["film_parameter"][0] == pytest.approx(
        result["minimum_film_thickness"][0] / 0.065e-6, rel=1e-14)


@pytest.mark.parametrize("model", ["crb_radial", "ball_5dof", "trb_load"])
def test_the_film_rises_with_speed_and_viscosity_and_leaves_the_rest_unchanged(model):
    speeds = np.tile([1000.0 * RPM, 3000.0 * RPM, 9000.0 * RPM], 2)
    temperatures = np.repeat([343.15, 323.15], 3)  # a colder oil is thicker
    run = {
        "crb_radial": lambda **k: crb_radial(5000.0, 14, 60e-3, 11e-3, 12e-3, **k),
        "ball_5dof": lambda **k: ball_5dof(9, 12.7e-3, 64.9985e-3, math.radians(25),
                                           axial_load=3000.0, radial_load=2000.0, **k),
        "trb_load": lambda **k: trb_load(5000.0, 6000.0, 17, 15e-3, 8e-3, math.radians(15),
                                         pitch_diameter=60e-3, **k),
    }[model]
    with_film = run(speed=speeds, oil_temperature=temperatures, **VG68)
    film = with_film["minimum_film_thickness"].reshape(2, 3)
    assert np.all(np.diff(film, axis=-1) > 0) and np.all(film[1] > film[0])
    assert np.all(with_film["central_film_thickness"].reshape(2, 3) > film)
    assert np.isnan(run(speed=speeds)["minimum_film_thickness"]).all()  # no oil given
    other_oil = run(speed=speeds, oil_temperature=temperatures, oil_density=900.0,
                    pressure_viscosity=30e-9, composite_roughness=0.1e-6, **VG68)
    assert np.all(other_oil["minimum_film_thickness"].reshape(2, 3) > film)
    for name, value in other_oil.items():  # the film feeds back into nothing else
        if name not in FILM_OUTPUT_NAMES:
            np.testing.assert_array_equal(value, with_film[name], err_msg=name)
