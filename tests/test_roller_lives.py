"""Rating lives of the roller bearing models: crb_radial (laminae = slices) and trb_load."""
import numpy as np
import pytest

from bearing_sweep.models import life
from bearing_sweep.models.cylindrical import crb_radial
from bearing_sweep.models.lubrication import CELSIUS
from bearing_sweep.models.registry import CONVERGED, INFEASIBLE
from bearing_sweep.models.tapered import trb_load

from conftest import BEARING_D, MM, RPM

MILLION_TURNS = 2e6 * np.pi  # the models return lives in radians
RATING_D = 48e3  # [N], a dynamic load rating of bearing D's size (assumed for the tests)
TAPERED = dict(roller_count=16, effective_length=21.5 * MM, roller_mean_diameter=13.71 * MM,
               outer_contact_angle=np.radians(28.0), pitch_diameter=79.537 * MM)


def test_straight_rollers_live_as_one_lamina_each_whatever_the_slicing():
    # Straight rollers, no speed: every slice of a roller carries Q/k on both raceways. The
    # standard's lamina ratings (q_c = Q_c k^(-7/9)) make that the life of one lamina per
    # roller carrying Q, which the test forms from the model's roller loads alone.
    load = np.array([2e3, 8e3])
    result = crb_radial(load, clearance=0.01 * MM, slices=24, dynamic_load_rating=RATING_D,
                        **BEARING_D)
    one_lamina = life.roller_bearing_reference_life(
        result["roller_load"][..., None], RATING_D, BEARING_D["roller_diameter"],
        BEARING_D["pitch_diameter"])
    assert result["reference_rating_life"] / MILLION_TURNS == pytest.approx(one_lamina,
                                                                            rel=1e-12)
    assert (result["status"] == CONVERGED).all()


def test_lives_scale_with_the_load_to_the_standards_exponents():
    # Zero clearance, no speed: the distribution keeps its shape as the load grows (every
    # roller load is proportional to F_r), so L10r ~ F_r^-4 (ISO/TS 16281 line contacts) and
    # L10 = (C_r / F_r)^(10/3) (ISO 281, P = F_r for a cylindrical roller bearing).
    load = np.array([1e3, 2e3, 7e3])
    result = crb_radial(load, crown=0.0, slices=10, dynamic_load_rating=RATING_D, **BEARING_D)
    reference = result["reference_rating_life"]
    assert reference / reference[0] == pytest.approx((load / load[0]) ** -4.0, rel=1e-9)
    assert result["basic_rating_life"] / MILLION_TURNS == pytest.approx(
        (RATING_D / load) ** (10.0 / 3.0), rel=1e-12)
    assert result["equivalent_dynamic_load"] == pytest.approx(load)


def test_crown_and_speed_enter_the_reference_life_through_the_slice_loads():
    # A crowned roller's middle slices carry more than a straight one's at the same roller
    # load, so sum q^(9/2) grows and L10r falls; a vanishing crown gives the straight life.
    # The centrifugal force loads only the outer contacts, so L10r falls with speed while
    # ISO 281's L10 (P = F_r) does not see it.
    common = dict(radial_load=5e3, slices=40, dynamic_load_rating=RATING_D, **BEARING_D)
    crowned = crb_radial(crown=np.array([0.0, 1e-12, 5e-6, 15e-6]), **common)
    straight, tiny, moderate, heavy = crowned["reference_rating_life"]
    assert tiny == pytest.approx(straight, rel=1e-6)
    assert straight > moderate > heavy
    spinning = crb_radial(speed=np.array([0.0, 8000.0, 16000.0]) * RPM, **common)
    assert np.all(np.diff(spinning["reference_rating_life"]) < 0)
    assert np.ptp(spinning["basic_rating_life"]) == 0.0


def test_modified_reference_life_and_hours_against_hand_evaluated_iso281():
    # Oil at 40 degC: its viscosity is viscosity_40 = 68 mm^2/s (Walther's line passes
    # through its points). nu_1 = 4500 n^-0.5 d_m^-0.5 = 4500 / (sqrt(3000) sqrt(65))
    # = 10.19049 mm^2/s (ISO 281 eq. (29), n >= 1000 r/min), kappa = 6.6729, taken as 4.
    # Roller bearings, 1 <= kappa <= 4 (ISO 281 eq. (36)): a_ISO = 0.1 [1 - (1.5859 -
    # 1.2348 / kappa^0.071739) x^0.4]^-9.185 with x = e_C C_u / P_ref, P_ref = C_r /
    # L10r^(3/10) (ISO/TS 16281 5.3.5); 1.2348 / 4^0.071739 = 1.1179064.
    speed, rating, fatigue, contamination = 3000.0, RATING_D, 6000.0, 0.5
    result = crb_radial(6e3, speed=speed * RPM, slices=10, dynamic_load_rating=rating,
                        fatigue_load_limit=fatigue, contamination_factor=contamination,
                        oil_temperature=40.0 + CELSIUS, viscosity_40=68e-6,
                        viscosity_100=8.7e-6, **BEARING_D)
    assert result["viscosity_ratio"][()] == pytest.approx(68.0 / 10.19049, rel=1e-6)
    reference = result["reference_rating_life"][()] / MILLION_TURNS
    reference_load = rating / reference ** 0.3
    bracket = 1.0 - (1.5859 - 1.1179064) * (contamination * fatigue / reference_load) ** 0.4
    factor = 0.1 * bracket**-9.185
    assert result["life_modification_factor"][()] == pytest.approx(factor, rel=1e-5)
    modified = result["modified_reference_rating_life"][()] / MILLION_TURNS
    assert modified == pytest.approx(factor * reference, rel=1e-5)
    # Hours at n r/min: L 1e6 / (60 n).
    assert result["reference_rating_hours"][()] == pytest.approx(
        reference * 1e6 / (60.0 * speed) * 3600.0, rel=1e-12)  # returned in seconds
    assert result["modified_reference_rating_hours"][()] == pytest.approx(
        modified * 1e6 / (60.0 * speed) * 3600.0, rel=1e-12)


def test_lives_are_nan_without_their_data():
    plain = crb_radial(5e3, slices=10, **BEARING_D)
    assert np.isnan([plain[name] for name in ("reference_rating_life", "basic_rating_life",
                                              "modified_reference_rating_life")]).all()
    rated = crb_radial(5e3, slices=10, dynamic_load_rating=RATING_D, speed=3000 * RPM,
                       **BEARING_D)  # no oil, no fatigue load limit
    assert np.isfinite(rated["reference_rating_life"]) and np.isfinite(
        rated["reference_rating_hours"])
    assert np.isnan(rated["modified_reference_rating_life"])
    unloaded = crb_radial(0.0, slices=10, dynamic_load_rating=RATING_D, **BEARING_D)
    assert unloaded["reference_rating_life"] == np.inf


def test_tapered_equivalent_load_against_iso281_table8_by_hand():
    # alpha = 28 deg: e = 1.5 tan(alpha) = 0.797564, Y = 0.4 cot(alpha) = 0.752290.
    # Fa/Fr = 0.675 <= e: P = Fr = 40 kN; Fa/Fr = 1: P = 0.4 * 40 + 0.752290 * 40 =
    # 46.0916 kN; pure axial 30 kN: P = 0.752290 * 30 = 22.5687 kN.
    computed = life.tapered_equivalent_load([40e3, 40e3, 0.0], [27e3, 40e3, 30e3],
                                            np.radians(28.0))
    assert computed == pytest.approx([40e3, 46091.6, 22568.7], rel=2e-6)


def test_tapered_lives_through_the_model():
    # Pure axial load: every roller carries Q = F_a / (Z sin alpha) on one lamina, so
    # L10r ~ F_a^-4, and the ISO 281 life is (C_r / (0.7522906 F_a))^(10/3).
    axial = np.array([10e3, 20e3, 45e3])
    rating = 127e3
    result = trb_load(0.0, axial, dynamic_load_rating=rating, **TAPERED)
    assert (result["status"] == CONVERGED).all()
    assert result["roller_load"] == pytest.approx(
        np.broadcast_to((axial / (16 * np.sin(np.radians(28.0))))[:, None], (3, 16)),
        rel=1e-9)
    reference = result["reference_rating_life"]
    assert reference / reference[0] == pytest.approx((axial / axial[0]) ** -4.0, rel=1e-9)
    assert result["basic_rating_life"] / MILLION_TURNS == pytest.approx(
        (rating / (0.7522906 * axial)) ** (10.0 / 3.0), rel=1e-6)
    # The life needs the pitch diameter (the ratings' gamma); an infeasible point has none.
    no_pitch = trb_load(0.0, 20e3, dynamic_load_rating=rating,
                        **{**TAPERED, "pitch_diameter": None})
    assert np.isnan(no_pitch["reference_rating_life"]).all()
    pulling = trb_load(40e3, 5e3, dynamic_load_rating=rating, **TAPERED)
    assert pulling["status"][0] == INFEASIBLE
    assert np.isnan(pulling["reference_rating_life"]).all()
