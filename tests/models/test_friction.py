"""Friction torque and power loss: SKF's model of the frictional moment and Palmgren's
M0 + M1, on crb_radial, ball_5dof and trb_load."""
import math

import numpy as np
import pytest

from bearing_sweep.models.ball import ball_5dof
from bearing_sweep.models.cylindrical import crb_radial
from bearing_sweep.models.lubrication import CELSIUS, walther_viscosity
from bearing_sweep.models.tapered import trb_load

RPM = math.pi / 30.0  # [rad/s per r/min]
#: An ISO VG 68 mineral oil at 70 degC (about 20 mm^2/s).
OIL = {"viscosity_40": 68e-6, "viscosity_100": 8.7e-6, "oil_temperature": 70.0 + CELSIUS}
NU = 1e6 * float(walther_viscosity(OIL["oil_temperature"], 68e-6, 8.7e-6))  # [mm^2/s]
#: An NU 208 (d = 40, D = 80 mm) and SKF's constants of its series (N/NU/NJ 2, with cage).
NU208 = {"roller_count": 14, "pitch_diameter": 0.0605, "roller_diameter": 0.011,
         "effective_length": 0.010, "clearance": 30e-6, "crown": 4e-6}
NU2_SERIES = {"skf_rolling_constant_1": 1.09e-6, "skf_sliding_constant_1": 0.16,
              "skf_sliding_constant_2": 0.0015}
#: The 71807AC of paper 001 and SKF's constants of single-row angular contact ball bearings.
ACBB = {"ball_count": 25, "ball_diameter": 3.14e-3, "pitch_diameter": 0.041,
        "contact_angle": math.radians(25.0), "inner_curvature_ratio": 0.52,
        "outer_curvature_ratio": 0.53}
ACBB_SERIES = {"skf_rolling_constant_1": 5.03e-7, "skf_rolling_constant_2": 1.97,
               "skf_rolling_constant_3": 1.90e-12, "skf_sliding_constant_1": 1.30e-2,
               "skf_sliding_constant_2": 0.68, "skf_sliding_constant_3": 1.91e-12}
#: The tapered roller bearing of paper 003 and SKF's constants of "other" tapered series.
TRB = {"roller_count": 16, "effective_length": 0.0215, "roller_mean_diameter": 0.01371,
       "outer_contact_angle": math.radians(28.0), "pitch_diameter": 0.079537}
TRB_SERIES = {"skf_rolling_constant_1": 2.31e-6, "skf_rolling_constant_2": 10.9,
              "skf_sliding_constant_1": 0.019, "skf_sliding_constant_2": 2.0}


def skf_by_hand(kind, n, dm, fr, fa, nu, mu_ehl, c, d=None, outside=None, k_rs=3e-8, y=None):
    """SKF's rolling and sliding moments [N mm] as its catalogue prints them (Rolling
    bearings, PUB BU/P1 10000/1 EN, 2013, "Friction", Table 2a; n [r/min], lengths [mm],
    loads [N], nu [mm^2/s]), with mu_bl = 0.15."""
    if kind == "ball":
        rolling = c["r1"] * dm ** 1.97 * (fr + c["r3"] * dm ** 4 * n ** 2 + c["r2"] * fa) ** 0.54
        sliding = c["s1"] * dm ** 0.26 * ((fr + c["s3"] * dm ** 4 * n ** 2) ** (4 / 3)
                                          + c["s2"] * fa ** (4 / 3))
        k_z = 4.4
    elif kind == "cylindrical":
        rolling = c["r1"] * dm ** 2.41 * fr ** 0.31
        sliding = c["s1"] * dm ** 0.9 * fa + c["s2"] * dm * fr
        k_z = 5.1
    else:
        rolling = c["r1"] * dm ** 2.38 * (fr + c["r2"] * y * fa) ** 0.31
        sliding = c["s1"] * dm ** 0.82 * (fr + c["s2"] * y * fa)
        k_z = 6.0
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)
    phi_rs = 1.0 if d is None else 1 / math.exp(
        k_rs * nu * n * (d + outside) * math.sqrt(k_z / (2 * (outside - d))))
    phi_bl = 1 / math.exp(2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * 0.15 + (1 - phi_bl) * mu_ehl
    return phi_ish * phi_rs * rolling * (nu * n) ** 0.6, sliding * mu_sl


def constants(series):
    return {f"{'r' if 'rolling' in name else 's'}{name[-1]}": value
            for name, value in series.items()}


@pytest.mark.parametrize("rpm", [300.0, 1500.0, 6000.0])
def test_skfs_moments_of_a_cylindrical_roller_bearing_are_its_catalogues_formulas(rpm):
    """Rolling and sliding moments, with the inlet-shear, replenishment (oil bath, K_rs =
    3e-8) and boundary weighting factors, against SKF's formulas in its own units; SKF's
    mean diameter (d + D) / 2 where the rings are given."""
    result = crb_radial(radial_load=5000.0, speed=rpm * RPM, bore=0.04, outside_diameter=0.08,
                        **NU208, **NU2_SERIES, **OIL)
    rolling, sliding = skf_by_hand("cylindrical", rpm, 60.0, 5000.0, 0.0, NU, 0.02,
                                   constants(NU2_SERIES), d=40.0, outside=80.0)
    assert 1e3 * result["rolling_friction_torque"] == pytest.approx(rolling, rel=1e-12)
    assert 1e3 * result["sliding_friction_torque"] == pytest.approx(sliding, rel=1e-12)
    assert result["friction_torque"] == pytest.approx(1e-3 * (rolling + sliding), rel=1e-12)
    assert result["power_loss"] == pytest.approx(result["friction_torque"] * rpm * RPM,
                                                 rel=1e-12)


@pytest.mark.parametrize("rpm", [0.0, 2000.0, 12000.0])
def test_skfs_moments_of_an_angular_contact_ball_bearing_take_the_balls_centrifugal_load(rpm):
    """The pitch diameter as the mean diameter without rings, and phi_rs = 1; grease: no
    change without rings (K_rs enters phi_rs only)."""
    result = ball_5dof(radial_load=300.0, axial_load=800.0, speed=rpm * RPM,
                       lubrication_method="grease", **ACBB, **ACBB_SERIES, **OIL)
    rolling, sliding = skf_by_hand("ball", rpm, 41.0, 300.0, 800.0, NU, 0.05,
                                   constants(ACBB_SERIES))
    assert 1e3 * result["rolling_friction_torque"] == pytest.approx(rolling, rel=1e-12, abs=0)
    assert 1e3 * result["sliding_friction_torque"] == pytest.approx(sliding, rel=1e-12)


def test_skfs_moments_of_a_tapered_roller_bearing_take_y_of_iso_281():
    """Y = 0.4 cot(alpha) for the axial load's share (ISO 281:2007, Table 8, the Y of
    single-row tapered roller bearings' product tables)."""
    result = trb_load(radial_load=12000.0, axial_load=8000.0, speed=1500 * RPM, **TRB,
                      **TRB_SERIES, **OIL)
    y = 0.4 / math.tan(math.radians(28.0))
    rolling, sliding = skf_by_hand("tapered", 1500.0, 79.537, 12000.0, 8000.0, NU, 0.002,
                                   constants(TRB_SERIES), y=y)
    assert 1e3 * result["rolling_friction_torque"] == pytest.approx(rolling, rel=1e-12)
    assert 1e3 * result["sliding_friction_torque"] == pytest.approx(sliding, rel=1e-12)


def test_at_rest_nothing_rolls_and_the_sliding_coefficient_is_the_boundary_one():
    result = crb_radial(radial_load=5000.0, speed=0.0, boundary_friction_coefficient=0.1,
                        **NU208, **NU2_SERIES, **OIL)
    assert result["rolling_friction_torque"] == 0.0
    assert result["power_loss"] == 0.0
    assert 1e3 * result["sliding_friction_torque"] == pytest.approx(
        0.0015 * 60.5 * 5000.0 * 0.1, rel=1e-12)


def test_at_thick_films_the_sliding_coefficient_is_the_full_film_one():
    """phi_bl = exp(-2.6e-8 (n nu)^1.4 dm) vanishes at nu n of some 1e6 (1e6^1.4 2.6e-8 60 =
    4e3)."""
    result = crb_radial(radial_load=5000.0, speed=20000 * RPM, viscosity_40=1000e-6,
                        viscosity_100=50e-6, oil_temperature=40 + CELSIUS, **NU208,
                        **NU2_SERIES)
    assert 1e3 * result["sliding_friction_torque"] == pytest.approx(
        0.0015 * 60.5 * 5000.0 * 0.02, rel=1e-12)


def test_a_cylindrical_roller_bearing_near_a_tenth_of_its_rating_has_skfs_constant_coefficient():
    """SKF, Rolling bearings (2013), "Friction", Table 1: where the load is about 0.1 C and
    the lubrication good, M = 0.5 mu P d with mu = 0.0011 for cylindrical roller bearings
    with a cage. An NU 208 (C about 62 kN) under 6.2 kN, VG 68 at 70 degC, at 500 and
    1500 r/min. Tolerance 30 %: the constant coefficient is SKF's rough estimate, which other
    makers give as a range (Koyo: 0.0008-0.0012, +-20 %), and ours moves with speed."""
    result = crb_radial(radial_load=6200.0, speed=np.array([500.0, 1500.0]) * RPM, bore=0.04,
                        outside_diameter=0.08, **NU208, **NU2_SERIES, **OIL)
    coefficient = 2 * 1e3 * result["friction_torque"] / (6200.0 * 40.0)
    assert coefficient == pytest.approx([0.0011, 0.0011], rel=0.3)


def test_replenishment_and_inlet_heating_lower_only_the_rolling_moment():
    """phi_rs falls with K_rs nu n: grease and oil-air (6e-8) below oil bath (3e-8), both
    below no rings (phi_rs = 1, a fully flooded bearing), the sliding moment untouched."""
    rings = {"bore": 0.04, "outside_diameter": 0.08}
    base = dict(radial_load=5000.0, speed=3000 * RPM, **NU208, **NU2_SERIES, **OIL)
    flooded = crb_radial(**base)
    bath = crb_radial(**base, **rings)
    grease = crb_radial(**base, **rings, lubrication_method="grease")
    flooded_mean = crb_radial(**{**base, "pitch_diameter": 0.06})  # (d + D) / 2 = 60 mm
    assert grease["rolling_friction_torque"] < bath["rolling_friction_torque"] \
        < flooded_mean["rolling_friction_torque"]
    assert grease["sliding_friction_torque"] == bath["sliding_friction_torque"]
    assert bath["sliding_friction_torque"] == pytest.approx(
        flooded_mean["sliding_friction_torque"], rel=1e-12)
    assert flooded["friction_torque"] > 0


@pytest.mark.parametrize("model, geometry, series, loads", [
    (crb_radial, NU208, NU2_SERIES, {"radial_load": np.array([1e3, 3e3, 1e4, 3e4])}),
    (ball_5dof, ACBB, ACBB_SERIES, {"axial_load": np.array([200.0, 500.0, 1e3, 2e3]),
                                    "radial_load": 100.0}),
    (trb_load, TRB, TRB_SERIES, {"axial_load": np.array([1e4, 2e4, 4e4, 8e4]),
                                 "radial_load": 1e4}),
])
def test_the_friction_torque_grows_with_the_load(model, geometry, series, loads):
    result = model(speed=1500 * RPM, **geometry, **series, **loads, **OIL)
    assert (np.diff(result["friction_torque"]) > 0).all()
    assert (np.diff(result["rolling_friction_torque"]) > 0).all()


def test_palmgrens_m0_grows_as_nu_n_to_two_thirds_and_levels_off_below_2000():
    """M0 = 1e-7 f0 (nu n)^(2/3) dm^3 for nu n >= 2000, 160e-7 f0 dm^3 below (N mm, mm^2/s,
    r/min, mm): 2000^(2/3) = 158.7, so the torque steps up by 0.8 % below."""
    rpm = np.array([10.0, 50.0, 1000.0, 8000.0])
    result = crb_radial(radial_load=5000.0, speed=rpm * RPM, friction_method="palmgren",
                        palmgren_speed_factor=2.0, palmgren_load_factor=3e-4, **NU208, **OIL)
    dm = 60.5
    expected = 2.0 * dm ** 3 * np.where(NU * rpm < 2000, 160e-7,
                                        1e-7 * (NU * rpm) ** (2 / 3))
    assert 1e3 * result["viscous_friction_torque"] == pytest.approx(expected, rel=1e-12)
    assert NU * 50.0 < 2000 < NU * 1000.0
    assert np.isnan(result["rolling_friction_torque"]).all()


def test_palmgrens_m1_is_f1_times_the_static_equivalent_load_and_the_pitch_diameter():
    """A cylindrical roller bearing under a radial load: P1 = P0r = Fr (ISO 76, 5.2)."""
    result = crb_radial(radial_load=5000.0, speed=1500 * RPM, friction_method="palmgren",
                        palmgren_speed_factor=2.0, palmgren_load_factor=3e-4, **NU208, **OIL)
    assert 1e3 * result["load_friction_torque"] == pytest.approx(3e-4 * 5000.0 * 60.5,
                                                                 rel=1e-12)
    assert result["friction_torque"] == pytest.approx(
        result["viscous_friction_torque"] + result["load_friction_torque"], rel=1e-12)


def test_without_constants_or_oil_there_is_no_friction_and_the_rest_is_unchanged():
    base = dict(radial_load=5000.0, speed=1500 * RPM, **NU208)
    without = crb_radial(**base, **OIL)
    with_constants = crb_radial(**base, **NU2_SERIES, **OIL)
    without_oil = crb_radial(**base, **NU2_SERIES)
    assert np.isnan(without["friction_torque"]) and np.isnan(without_oil["friction_torque"])
    assert np.isnan(without["power_loss"])
    for name, value in without.items():
        if "friction" not in name and name != "power_loss":
            np.testing.assert_array_equal(value, with_constants[name], err_msg=name)


def test_a_point_without_a_solution_has_no_friction():
    """trb_load: no axial load, the rollers cannot carry the radial load (infeasible)."""
    result = trb_load(radial_load=12000.0, axial_load=0.0, speed=1500 * RPM, **TRB,
                      **TRB_SERIES, **OIL)
    assert np.isnan(result["friction_torque"]).all()


def skf_drag_by_hand(roller, n, dm, nu, level, v_m, d, outside, k_z, width=None, k_l=None):
    """SKF's drag loss of an oil bath [N mm] as its catalogue (2013, "Drag losses") prints it:
    the rolling elements' part and the bath's viscous part."""
    h = min(level, 1.2 * dm)
    t = 2 * math.acos((0.6 * dm - h) / (0.6 * dm))
    f_t = math.sin(0.5 * t) if t <= math.pi else 1.0
    f_a = 0.05 * k_z * (outside + d) / (outside - d)
    r_s = 0.36 * dm ** 2 * (t - math.sin(t)) * f_a
    bath = 1.093e-7 * n ** 2 * dm ** 3 * (n * dm ** 2 * f_t / nu) ** -1.379 * r_s if r_s else 0.0
    if not roller:
        k_ball = k_z * (d + outside) / (outside - d) * 1e-12
        return 0.4 * v_m * k_ball * dm ** 5 * n ** 2 + bath
    k_roll = k_l * k_z * (d + outside) / (outside - d) * 1e-12
    l_d = 5 * k_l * width / dm
    c_w = 2.789e-10 * l_d ** 3 - 2.786e-4 * l_d ** 2 + 0.0195 * l_d + 0.6439
    return 4 * v_m * k_roll * c_w * width * dm ** 4 * n ** 2 + bath


@pytest.mark.parametrize("level", [5.0, 30.0, 80.0])
def test_skfs_drag_of_a_cylindrical_roller_bearing_in_an_oil_bath(level):
    """K_Z = 5.1, K_L = 0.65 (cylindrical roller bearings with a cage); an NU 208 is 18 mm
    wide; V_M as a user reads it off SKF's diagram. At 80 mm the bearing is submerged (the
    level counts up to 1.2 dm)."""
    result = crb_radial(radial_load=5000.0, speed=3000 * RPM, bore=0.04, outside_diameter=0.08,
                        oil_level=level * 1e-3, drag_loss_factor=3e-4, bearing_width=0.018,
                        **NU208, **NU2_SERIES, **OIL)
    drag = skf_drag_by_hand(True, 3000.0, 60.0, NU, level, 3e-4, 40.0, 80.0, 5.1, 18.0, 0.65)
    assert 1e3 * result["drag_friction_torque"] == pytest.approx(drag, rel=1e-12)
    assert result["friction_torque"] == pytest.approx(
        result["rolling_friction_torque"] + result["sliding_friction_torque"]
        + result["drag_friction_torque"], rel=1e-12)


def test_skfs_drag_of_an_angular_contact_ball_bearing_and_a_tapered_one():
    ball = ball_5dof(radial_load=300.0, axial_load=800.0, speed=6000 * RPM, bore=0.035,
                     outside_diameter=0.047, oil_level=0.008, drag_loss_factor=2e-4, **ACBB,
                     **ACBB_SERIES, **OIL)
    assert 1e3 * ball["drag_friction_torque"] == pytest.approx(
        skf_drag_by_hand(False, 6000.0, 41.0, NU, 8.0, 2e-4, 35.0, 47.0, 4.4), rel=1e-12)
    tapered = trb_load(radial_load=12000.0, axial_load=8000.0, speed=1500 * RPM, bore=0.055,
                       outside_diameter=0.1, oil_level=0.02, drag_loss_factor=3e-4,
                       bearing_width=0.023, **TRB, **TRB_SERIES, **OIL)
    assert 1e3 * tapered["drag_friction_torque"] == pytest.approx(
        skf_drag_by_hand(True, 1500.0, 77.5, NU, 20.0, 3e-4, 55.0, 100.0, 6.0, 23.0, 0.7),
        rel=1e-12)


def test_the_drag_grows_with_the_oil_level_and_speed_and_vanishes_without_oil_or_motion():
    """With one V_M: at level 0 the bath's part vanishes and the rolling elements' is left
    (SKF's diagram gives V_M = 0 there)."""
    rings = {"bore": 0.04, "outside_diameter": 0.08, "drag_loss_factor": 3e-4,
             "bearing_width": 0.018}
    levels = crb_radial(radial_load=5000.0, speed=3000 * RPM,
                        oil_level=np.array([0.0, 0.01, 0.03, 0.06]), **rings, **NU208,
                        **NU2_SERIES, **OIL)["drag_friction_torque"]
    speeds = crb_radial(radial_load=5000.0, speed=np.array([0.0, 1e3, 3e3, 6e3]) * RPM,
                        oil_level=0.03, **rings, **NU208, **NU2_SERIES,
                        **OIL)["drag_friction_torque"]
    assert 1e3 * levels[0] == pytest.approx(skf_drag_by_hand(
        True, 3000.0, 60.0, NU, 0.0, 3e-4, 40.0, 80.0, 5.1, 18.0, 0.65), rel=1e-12)
    assert speeds[0] == 0.0
    assert (np.diff(levels) > 0).all() and (np.diff(speeds) > 0).all()
    without = crb_radial(radial_load=5000.0, speed=3000 * RPM, **NU208, **NU2_SERIES, **OIL)
    assert without["drag_friction_torque"] == 0.0


def test_an_oil_level_without_what_the_drag_needs_is_refused():
    with pytest.raises(ValueError, match="oil_level needs drag_loss_factor, bore, "
                                         "outside_diameter and bearing_width"):
        crb_radial(radial_load=5000.0, speed=3000 * RPM, oil_level=0.03, bore=0.04,
                   outside_diameter=0.08, drag_loss_factor=3e-4, **NU208, **OIL)


@pytest.mark.parametrize("varied", [{"axes": {"drag_loss_factor": [1e-4, 2e-4]}},
                                    {"axes": {"bore": ["45 mm", "50 mm"]}},
                                    {"sample": {"n": 4, "method": "latin_hypercube", "seed": 1,
                                                "oil_level": {"distribution": "uniform",
                                                              "low": "0 mm", "high": "20 mm"},
                                                "drag_loss_factor": {
                                                    "distribution": "uniform", "low": 1e-4,
                                                    "high": 3e-4}}}])
def test_a_definition_with_what_the_drag_needs_on_axes_or_drawn_is_taken(varied):
    """The check that an oil level comes with what the drag takes holds across axes."""
    from bearing_sweep import spec

    fixed = {"radial_load": "4 kN", "bore": "50 mm", "outside_diameter": "80 mm",
             "bearing_width": "16 mm", "drag_loss_factor": 2e-4, "oil_level": "10 mm"}
    for name in [*varied.get("axes", {}), *varied.get("sample", {})]:  # settings: no-ops
        fixed.pop(name, None)
    document = {"sweep": {"model": "crb_radial", "bearing": "paper000-D"}, "fixed": fixed,
                **varied}
    sweep = spec.from_dict(document)
    assert sweep.model.name == "crb_radial"


def test_friction_of_a_direct_call_with_plain_numbers_is_real_and_its_parts_distinct():
    from bearing_sweep.models.friction import bearing_friction

    result = bearing_friction("cylindrical_roller", "skf", "oil_bath", 100.0, 0.06, -5000.0,
                              0.0, 2e-5, {"r1": 1.09e-6, "s1": 0.16, "s2": 0.0015}, 0.15, 0.02,
                              None, None, 5000.0)
    assert np.isnan(result["friction_torque"]) and not np.iscomplexobj(result["friction_torque"])
    result["viscous_friction_torque"][...] = 1.0
    assert np.isnan(result["load_friction_torque"])
