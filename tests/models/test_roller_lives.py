"""Rating lives of the roller bearing models: crb_radial (laminae = slices) and trb_load."""
import numpy as np
import pytest

from bearing_sweep.models import life
from bearing_sweep.models.cylindrical import crb_radial
from bearing_sweep.models.lubrication import CELSIUS
from bearing_sweep.models.registry import CONVERGED, INFEASIBLE
from bearing_sweep.models.tapered import trb_load

MM = 1e-3  # m
RPM = 2.0 * np.pi / 60.0  # rad/s
MILLION_TURNS = 2e6 * np.pi  # the models return lives in radians
RATING_D = 48e3  # [N], a dynamic load rating of bearing D's size (assumed for the tests)
TAPERED = dict(roller_count=16, effective_length=21.5 * MM, roller_mean_diameter=13.71 * MM,
               outer_contact_angle=np.radians(28.0), pitch_diameter=79.537 * MM)


def test_straight_rollers_live_as_one_lamina_each_whatever_the_slicing(bearing_d):
    # Straight rollers, no speed: every slice of a roller carries Q/k on both raceways. The
    # standard's lamina ratings (q_c = Q_c k^(-7/9)) make that the life of one lamina per
    # roller carrying Q, which the test forms from the model's roller loads alone.
    load = np.array([2e3, 8e3])
    result = crb_radial(load, clearance=0.01 * MM, slices=24, dynamic_load_rating=RATING_D,
                        **bearing_d)
    one_lamina = life.roller_bearing_reference_life(
        result["roller_load"][..., None], RATING_D, bearing_d["roller_diameter"],
        bearing_d["pitch_diameter"])
    assert result["reference_rating_life"] / MILLION_TURNS == pytest.approx(one_lamina,
                                                                            rel=1e-12)
    assert (result["status"] == CONVERGED).all()


def test_lives_scale_with_the_load_to_the_standards_exponents(bearing_d):
    # Zero clearance, no speed: the distribution keeps its shape as the load grows (every
    # roller load is proportional to F_r), so L10r ~ F_r^-4 (ISO/TS 16281 line contacts) and
    # L10 = (C_r / F_r)^(10/3) (ISO 281, P = F_r for a cylindrical roller bearing).
    load = np.array([1e3, 2e3, 7e3])
    result = crb_radial(load, crown=0.0, slices=10, dynamic_load_rating=RATING_D, **bearing_d)
    reference = result["reference_rating_life"]
    assert reference / reference[0] == pytest.approx((load / load[0]) ** -4.0, rel=1e-9)
    assert result["basic_rating_life"] / MILLION_TURNS == pytest.approx(
        (RATING_D / load) ** (10.0 / 3.0), rel=1e-12)
    assert result["equivalent_dynamic_load"] == pytest.approx(load)


def test_crown_and_speed_enter_the_reference_life_through_the_slice_loads(bearing_d):
    # A crowned roller's middle slices carry more than a straight one's at the same roller
    # load, so sum q^(9/2) grows and L10r falls; a vanishing crown gives the straight life.
    # The centrifugal force loads only the outer contacts, so L10r falls with speed while
    # ISO 281's L10 (P = F_r) does not see it.
    common = dict(radial_load=5e3, slices=40, dynamic_load_rating=RATING_D, **bearing_d)
    crowned = crb_radial(crown=np.array([0.0, 1e-12, 5e-6, 15e-6]), **common)
    straight, tiny, moderate, heavy = crowned["reference_rating_life"]
    assert tiny == pytest.approx(straight, rel=1e-6)
    assert straight > moderate > heavy
    spinning = crb_radial(speed=np.array([0.0, 8000.0, 16000.0]) * RPM, **common)
    assert np.all(np.diff(spinning["reference_rating_life"]) < 0)
    assert np.ptp(spinning["basic_rating_life"]) == 0.0


def test_modified_reference_life_and_hours_against_hand_evaluated_iso281(bearing_d):
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
                        viscosity_100=8.7e-6, **bearing_d)
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


def test_lives_are_nan_without_their_data(bearing_d):
    plain = crb_radial(5e3, slices=10, **bearing_d)
    assert np.isnan([plain[name] for name in ("reference_rating_life", "basic_rating_life",
                                              "modified_reference_rating_life")]).all()
    rated = crb_radial(5e3, slices=10, dynamic_load_rating=RATING_D, speed=3000 * RPM,
                       **bearing_d)  # no oil, no fatigue load limit
    assert np.isfinite(rated["reference_rating_life"]) and np.isfinite(
        rated["reference_rating_hours"])
    assert np.isnan(rated["modified_reference_rating_life"])
    unloaded = crb_radial(0.0, slices=10, dynamic_load_rating=RATING_D, **bearing_d)
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


# Cross-check against a commercial tool's report: Romax DT 2021.0.0, report "RxD5C58.htm" of
# the model "CRB_Testing.rnx" (a cylindrical roller bearing, 13 rollers, inner ring at
# 50 r/min, misaligned), in the public repository
# https://github.com/shiva01910/BearingLifeCalculation16281 (file RxD5C58.htm, commit
# eb14c5e7). The report gives loads and lives but not the geometry; the inputs that are not
# printed are read back from its own figures, as noted at each.
ROMAX_LOAD = 15138.2  # [N] radial load, = P ("Equivalent dynamic bearing load")
ROMAX_RATING = 32500.0  # [N] C_r = P / (P/C) = 15138.2 / 0.46579 = 32500.05
ROMAX_ROLLERS = 13  # roller positions every 27.692 deg
# gamma = D_we / d_m from the Hertz line contacts of the 0-deg roller's middle slice
# (4.250 mm): p0 / b = E* sum(rho) / 2 on each raceway, and sum(rho) is 2 / (D (1 - gamma))
# inner, 2 / (D (1 + gamma)) outer, so their ratio is (1 + gamma) / (1 - gamma).
# Inner 2970.988069 MPa, 159.77 um; outer 2446.736777 MPa, 194.23 um.
_RATIO = (2970.988069 / 159.77) / (2446.736777 / 194.23)
ROMAX_GAMMA = (_RATIO - 1.0) / (_RATIO + 1.0)  # 0.192299


def test_roller_contact_ratings_reproduce_romax():
    # Romax's "Raceway dynamic load rating": Q_ci = 8165.4 N, Q_ce = 13681.3 N (whole
    # roller). Both are reproduced with lambda nu = 0.83 divided out of the ratings (the
    # default); kept in (reduction_factor=1) they would be 6777.3 N and 11355.5 N, 17 % low.
    # Tolerance 2e-4: the report prints five figures (<= 6e-6); the half widths, printed to
    # 0.01 um, leave gamma uncertain by 1.5e-4, which moves Q_ce by 7e-5 and Q_ci by 1e-5;
    # C_r from the printed P/C by 1e-5.
    inner, outer = life.roller_contact_load_ratings(ROMAX_RATING, ROMAX_ROLLERS, ROMAX_GAMMA,
                                                    1.0)
    assert inner == pytest.approx(8165.4, rel=2e-4)
    assert outer == pytest.approx(13681.3, rel=2e-4)


def test_reference_life_and_its_load_from_romax_roller_ratings_and_loads():
    # Romax's whole-roller ratings and "Raceway dynamic equivalent load" Q_ei = 4331.1 N,
    # Q_ee = 4523.2 N give its L10r = 11.430 (10^6 rev) by ISO/TS 16281 eq. (65) with one
    # lamina per roller; P_ref = C_r / L10r^0.3 = 15648.4 N; L10rh = 3810.0123 h at
    # 50 r/min. Tolerances: four five-figure inputs enter L10r to the 4th power (<= 1e-4
    # together) and it is printed to 4.4e-5: 2e-4; P_ref takes 0.3 of that: 1e-4.
    reference = life.roller_reference_rating_life(8165.4, 13681.3, [4331.1], [4523.2])
    assert reference == pytest.approx(11.430, rel=2e-4)
    assert life.equivalent_reference_load(ROMAX_RATING, 11.430, "roller") == pytest.approx(
        15648.4, rel=1e-4)
    assert life.life_duration(11.430, 50.0 * RPM) / 3600.0 == pytest.approx(3810.0123,
                                                                          rel=1e-4)


def test_iso281_lives_reproduce_romax():
    # Romax's ISO 281 section: L10 = 12.765 (10^6 rev) from C/P; a_ISO = 0.21049 from
    # kappa = 0.56941, e_C = 0.36808, C_u = 3400.0 N, P = 15138.2 N (roller bearing,
    # 0.4 <= kappa < 1); L10m = 2.687. Tolerances: each printed input moves a_ISO by at most
    # 8.5e-6 (2e-5 together) and it is printed to 2.4e-5: 1e-4; L10 1e-4 (C_r 1e-5 to the
    # 10/3, printed to 4e-5); L10m printed to four figures: 3e-4.
    assert life.basic_rating_life(ROMAX_RATING, ROMAX_LOAD, "roller") == pytest.approx(
        12.765, rel=1e-4)
    assert life.life_modification_factor(0.56941, 0.36808, 3400.0, ROMAX_LOAD,
                                         "roller") == pytest.approx(0.21049, rel=1e-4)
    assert life.modified_rating_life(ROMAX_RATING, ROMAX_LOAD, 0.56941, 0.36808, 3400.0,
                                     "roller") == pytest.approx(2.687, rel=3e-4)


def test_crb_radial_load_distribution_against_romax():
    # Inputs read back from the report:
    # - d_m from its nu_1 = 276.613 mm^2/s at 50 r/min, ISO 281 eq. (28):
    #   d_m = (45000 n^-0.83 / nu_1)^2 = 40.030 mm; D_we = gamma d_m = 7.698 mm.
    # - 35 slices with centres from 0.49057 to 8.009 mm: 0.22113 mm each, l = 7.7396 mm.
    # - Crown: eq. 8's logarithmic shape with c_max = 16.58 um fits the report's "conjugate
    #   contact profile" (9.11 um at the end slices, zero in the middle) within 0.06 um at
    #   every slice (least squares).
    # - Diametral clearance 32.7 um: each roller's two contacts share its approach, so the
    #   printed contact deflection is (delta_r cos(psi) - P_d/2) / 2 with delta_r = 54.30 um;
    #   18.95, 15.86, 7.27 and -34.55 um at 0, 27.7, 55.4 and 166.2 deg give P_d = 32.80,
    #   32.72, 32.61, 32.76 um.
    # - Misalignment 3.675 mrad (inner ring against outer, about the axis across the load);
    #   the report's "raceway contact tilt" of the 0-deg roller, 1.837 mrad, is half of it,
    #   as the model assumes.
    # Romax: roller loads 5478.0, 4401.6, 1641.5 N at 0, +-27.7, +-55.4 deg, none beyond;
    # delta_r = 54.30 um. Tolerances: the report does not state its load-deflection constant;
    # its slice loads and deflections imply 1.2 % above Palmgren's (used here), which moves
    # the 55-deg roller by 0.5 % and delta_r by 0.6 %; the least loaded roller is the most
    # sensitive to the clearance read back (1.4 % per um). Hence 1 % for the two most loaded
    # rollers, 2.5 % for the 55-deg one, 1.5 % for the displacement (found: +0.3, +0.1,
    # -1.2, +0.7 %).
    pitch = (45000.0 * 50.0**-0.83 / 276.613) ** 2 * MM
    result = crb_radial(ROMAX_LOAD, ROMAX_ROLLERS, pitch, ROMAX_GAMMA * pitch,
                        35 * 0.221130294 * MM, clearance=32.7e-6, crown=16.58e-6, slices=35,
                        misalignment=3.675e-3)
    assert result["status"] == CONVERGED
    loads = result["roller_load"]
    assert loads[[0, 1, 12]] == pytest.approx([5478.0, 4401.6, 4401.6], rel=1e-2)
    assert loads[[2, 11]] == pytest.approx([1641.5, 1641.5], rel=2.5e-2)
    assert np.all(loads[3:11] == 0.0)
    assert result["radial_displacement"] == pytest.approx(54.30e-6, rel=1.5e-2)
