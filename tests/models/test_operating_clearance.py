"""The operating clearance: press fits (Lame), temperatures and the inner ring's centrifugal
expansion, alone and in the models' load distributions."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_sweep.models.ball import ball_5dof
from bearing_sweep.models.cylindrical import crb_radial
from bearing_sweep.models.operating_clearance import (BEARING_STEEL_DENSITY,
                                                      BEARING_STEEL_EXPANSION,
                                                      OPERATING_INPUTS, mounted_clearance)
from bearing_sweep.models.registry import OUT_OF_VALIDITY, out_of_validity

CELSIUS = 273.15
E, NU = 207e9, 0.3
#: An NU 208-like cylindrical roller bearing [m]: bore 40, outside 80, dm 60.5, rollers 11.
BORE, OUTSIDE, PITCH, ROLLER = 40e-3, 80e-3, 60.5e-3, 11e-3
INNER, OUTER = PITCH - ROLLER, PITCH + ROLLER


def _mounted(clearance=30e-6, speed=0.0, **given_inputs):
    values = {item.name: given_inputs.get(item.name, item.default) for item in OPERATING_INPUTS}
    values.update(bore=given_inputs.get("bore", BORE),
                  outside_diameter=given_inputs.get("outside_diameter", OUTSIDE))
    for name, value in values.items():  # the declared defaults, in SI
        if name.endswith("temperature") and value is not None:
            values[name] = value + CELSIUS if value < 200 else value
        elif name.endswith("fit") and name in given_inputs:
            values[name] = given_inputs[name]
        elif name.endswith("fit"):
            values[name] = 0.0
        elif name.endswith("youngs_modulus") and name not in given_inputs:
            values[name] = value * 1e9
    shape = np.shape(clearance)
    return mounted_clearance(np.asarray(clearance, float), np.full(shape, INNER),
                             np.full(shape, OUTER), np.full(shape, ROLLER),
                             np.asarray(speed, float), E, NU,
                             *(values[item.name] for item in OPERATING_INPUTS))


@pytest.mark.parametrize("shaft_bore", [0.0, 20e-3, 35e-3])
def test_a_fit_of_like_materials_widens_the_raceway_by_lames_closed_form(shaft_bore):
    """Ring and shaft of one material: the raceway grows by I (d/d_i) (1 - (a/d)^2) /
    (1 - (a/d_i)^2) (Lame's solution for two cylinders; Harris and Kotzalas, Rolling Bearing
    Analysis, ch. 3), 81 % of a 12 um interference here on a solid shaft."""
    interference = 12e-6
    result = _mounted(shaft_fit=interference, shaft_bore=shaft_bore)
    expected = interference * (BORE / INNER) * (1 - (shaft_bore / BORE) ** 2) / (
        1 - (shaft_bore / INNER) ** 2)
    assert -result["clearance_change_fit"] == pytest.approx(expected, rel=1e-12)
    assert result["shaft_fit_remaining"] == pytest.approx(interference, rel=1e-15)


def test_an_unmounted_bearing_at_20_degc_and_at_rest_keeps_its_clearance_exactly():
    clearance = np.array([-5e-6, 0.0, 1e-6, 30e-6, 0.1e-3])
    result = _mounted(clearance)
    np.testing.assert_array_equal(result["operating_clearance"], clearance)
    assert not result["fit_lost"].any()


@settings(max_examples=30, deadline=None)
@given(st.lists(st.integers(-30_000, 60_000), min_size=2, max_size=8, unique=True))
def test_the_clearance_falls_as_the_interference_grows(nanometres):
    fits = np.sort(np.array(nanometres)) * 1e-9
    for fit in ("shaft_fit", "housing_fit"):
        clearance = _mounted(np.full(fits.shape, 30e-6), **{fit: fits})["operating_clearance"]
        assert np.all(np.diff(clearance) <= 0), fit
        assert np.all(np.diff(clearance[fits > 0]) < 0), fit


def test_a_steel_bearing_on_steel_warmed_evenly_keeps_its_clearance_and_its_fits():
    result = _mounted(shaft_fit=10e-6, housing_fit=5e-6, inner_ring_temperature=90.0,
                      outer_ring_temperature=90.0)
    cold = _mounted(shaft_fit=10e-6, housing_fit=5e-6)
    assert result["operating_clearance"] == pytest.approx(cold["operating_clearance"],
                                                          abs=1e-12)
    assert result["shaft_fit_remaining"] == pytest.approx(10e-6, abs=1e-12)


def test_an_inner_ring_warmer_than_the_outer_takes_alpha_dt_dm_of_clearance():
    """Inner ring (and shaft) 10 K above the outer ring, rolling elements at the mean: the
    clearance falls by alpha dT (d_i + D_w) = alpha dT d_m."""
    result = _mounted(inner_ring_temperature=30.0, outer_ring_temperature=20.0)
    expected = -BEARING_STEEL_EXPANSION * 10.0 * PITCH
    assert result["clearance_change_temperature"] == pytest.approx(expected, rel=1e-12)


def test_speed_loosens_the_fit_by_the_rotating_rings_closed_form_and_then_loses_it():
    """Free ring bore and solid shaft surface turning at w (Timoshenko and Goodier, Theory of
    Elasticity, sec. 32): u_bore = rho w^2 a ((3 + nu) c^2 + (1 - nu) a^2) / (4 E) and
    u_shaft = rho w^2 a^3 (1 - nu) / (4 E), so the fit loses (3 + nu) rho w^2 d d_i^2 /
    (16 E) of its interference, and is lost at the speed where that equals it."""
    interference = 10e-6
    speeds = np.array([0.0, 1000.0, 2000.0])
    result = _mounted(np.full(3, 30e-6), speed=speeds, shaft_fit=interference)
    loss = (3 + NU) * BEARING_STEEL_DENSITY * speeds**2 * BORE * INNER**2 / (16 * E)
    np.testing.assert_allclose(result["shaft_fit_remaining"], interference - loss, rtol=1e-12)
    lost_at = math.sqrt(16 * E * interference / ((3 + NU) * BEARING_STEEL_DENSITY * BORE
                                                   * INNER**2))
    around = _mounted(np.full(2, 30e-6), speed=np.array([0.99, 1.01]) * lost_at,
                      shaft_fit=interference)
    assert list(around["fit_lost"]) == [False, True]


def test_a_tight_fit_lost_in_a_warm_aluminium_housing_is_out_of_validity_with_its_values():
    aluminium = dict(housing_youngs_modulus=70e9, housing_expansion=23e-6, bore=BORE,
                     outside_diameter=OUTSIDE)
    kwargs = dict(radial_load=np.array([5000.0, 5000.0]), roller_count=14,
                  pitch_diameter=PITCH, roller_diameter=ROLLER, effective_length=12e-3,
                  clearance=30e-6, housing_fit=15e-6, **aluminium)
    result = crb_radial(outer_ring_temperature=np.array([20.0, 80.0]) + CELSIUS, **kwargs)
    assert result["housing_fit_remaining"][0] > 0 > result["housing_fit_remaining"][1]
    assert not out_of_validity(result["status"][0])
    assert result["status"][1] == OUT_OF_VALIDITY
    assert np.isfinite(result["radial_stiffness"]).all()


@pytest.mark.parametrize("model", ["crb_radial", "ball_5dof"])
def test_the_load_distribution_takes_the_operating_clearance(model):
    """A fit that takes 9.7 um of clearance gives the load distribution of a bearing whose
    clearance is 9.7 um smaller."""
    run = {
        "crb_radial": lambda **k: crb_radial(5000.0, 14, PITCH, ROLLER, 12e-3, **k),
        "ball_5dof": lambda **k: ball_5dof(12, 12.7e-3, PITCH, 0.0, radial_load=5000.0,
                                           fixed_dofs="axial tilt_y tilt_z", **k),
    }[model]
    fitted = run(clearance=30e-6, shaft_fit=12e-6, bore=BORE)
    plain = run(clearance=fitted["operating_clearance"])
    for name in ("radial_displacement", "radial_stiffness", "largest_contact_pressure"):
        assert fitted[name] == pytest.approx(plain[name], rel=1e-12), name


def test_a_fit_without_its_ring_is_refused_in_one_line():
    with pytest.raises(ValueError, match="shaft_fit needs bore"):
        crb_radial(5000.0, 14, PITCH, ROLLER, 12e-3, shaft_fit=10e-6)
    with pytest.raises(ValueError, match="do not nest"):
        crb_radial(5000.0, 14, PITCH, ROLLER, 12e-3, bore=55e-3)


#: The tapered roller bearing of paper 003 (its Table 1), with assumed rings [m].
TRB = {"roller_count": 16, "effective_length": 0.0215, "roller_mean_diameter": 0.01371,
       "outer_contact_angle": math.radians(28.0), "pitch_diameter": 0.079537,
       "radial_load": 12e3, "axial_load": 20e3}


def test_a_single_tapered_bearing_s_clearance_moves_its_cone_and_leaves_its_loads():
    """Every roller's gap along its contact normal is (P_d / 2) cos(alpha): the cone moves
    on axially by (P_d / 2) cot(alpha) and the rollers carry the same loads."""
    from bearing_sweep.models.tapered import trb_load

    tight = trb_load(**TRB)
    loose = trb_load(**TRB, clearance=60e-6)
    np.testing.assert_allclose(loose["roller_load"], tight["roller_load"], rtol=1e-12)
    assert loose["radial_displacement"] == pytest.approx(tight["radial_displacement"],
                                                         rel=1e-12)
    assert loose["axial_displacement"] - tight["axial_displacement"] == pytest.approx(
        30e-6 / math.tan(math.radians(28.0)), rel=1e-9)
    assert loose["operating_clearance"] == 60e-6


def test_a_tapered_bearing_s_fit_takes_lames_share_of_its_clearance():
    """A cone of bore 55 mm pressed on a solid steel shaft: its raceway at the rollers'
    middle, d_m - D cos(alpha), grows by d / d_i of the fit (Lame, like materials: the
    shaft's modulus is trb_load's ring modulus, 206 GPa)."""
    from bearing_sweep.models.tapered import trb_load

    result = trb_load(**TRB, clearance=60e-6, shaft_fit=20e-6, bore=0.055,
                      shaft_youngs_modulus=206e9)
    raceway = TRB["pitch_diameter"] - TRB["roller_mean_diameter"] * math.cos(math.radians(28))
    assert result["clearance_change_fit"] == pytest.approx(-20e-6 * 0.055 / raceway,
                                                           rel=1e-9)
    assert result["operating_clearance"] == pytest.approx(
        60e-6 + result["clearance_change_fit"], rel=1e-12)


def test_a_tapered_bearing_s_operating_clearance_needs_its_pitch_diameter():
    from bearing_sweep.models.tapered import trb_load

    without_pitch = {**TRB, "pitch_diameter": None}
    assert trb_load(**without_pitch, clearance=40e-6)["operating_clearance"] == 40e-6
    with pytest.raises(ValueError, match="needs pitch_diameter"):
        trb_load(**without_pitch, inner_ring_temperature=60 + CELSIUS)
