"""cage_slip: trends, the cage's torque balance and its several roots, the reaction of the
pocket on the cage, the no-drag limit, traction and viscosity."""
import numpy as np
import pytest

import bearing_sweep.models.cage_slip as steady_module
from bearing_sweep.models.cage_slip import cage_slip, cage_torque_residual, cage_windage, kinematic_cage_speed
from bearing_sweep.models.lubrication import TractionCurve, walther_viscosity
from bearing_sweep.models.registry import CONVERGED, NO_ROOT_IN_RANGE, NOT_CONVERGED, OUT_OF_VALIDITY
from bearing_sweep import compute, spec, stores

MM, RPM = 1e-3, 2 * np.pi / 60
#: The test bearing of paper 002, Table 2 (outer raceway from di + 2D + Pd).
TEST = dict(roller_count=13, inner_raceway_diameter=44 * MM, roller_diameter=10 * MM,
            roller_length=11 * MM, effective_length=7.2 * MM, clearance=0.02 * MM,
            cage_inner_diameter=48.5 * MM, cage_outer_diameter=59 * MM, cage_width=13 * MM)
LOADS = np.array([200.0, 400.0, 600.0, 800.0, 1000.0])


def test_slip_falls_with_load_and_rises_with_speed():
    slips = np.stack([cage_slip(LOADS, n * RPM, **TEST)["cage_slip"] for n in (6000, 9000,
                                                                                12000)])
    assert np.all(np.diff(slips, axis=1) < 0)  # with load
    assert np.all(np.diff(slips, axis=0) > 0)  # with speed
    assert np.all((slips > 0) & (slips < 1))


def test_the_steady_state_balances_the_cage():
    result = cage_slip(LOADS, 12000 * RPM, **TEST)
    assert np.all(result["status"] == 0)
    # Scale: what the rollers' traction could push at most, Z mu_inf Q_max r_m.
    scale = 13 * 0.036 * result["max_roller_load"] * 0.027
    assert np.all(np.abs(result["torque_residual"]) < 1e-6 * scale)


def test_without_drag_the_cage_runs_at_the_kinematic_speed():
    quiet = dict(drag_coefficient=0.0, pocket_film_fill=0.0, end_film_fill=0.0,
                 pocket_friction=0.0, **{**TEST, "cage_width": 0.0})
    result = cage_slip(LOADS, 12000 * RPM, **quiet)
    assert np.abs(result["cage_slip"]).max() < 1e-5
    assert np.abs(result["roller_slip"]).max() < 1e-4
    omega_kin = kinematic_cage_speed(12000 * RPM, 22 * MM, 32.01 * MM)
    assert result["cage_speed"] == pytest.approx(np.full(5, omega_kin), rel=1e-5)


def test_a_roller_leaves_the_load_zone_slowed_by_its_films():
    result = cage_slip(np.array([800.0]), 12000 * RPM, **TEST)
    slip, angle = result["roller_slip"][0], np.degrees(result["orbit_angle"][0])
    # Spun up in the middle of the load zone, it slows on the unloaded side, most at the end.
    middle = (angle < 20) | (angle > 340)
    unloaded = (angle > 90) & (angle < 270)
    assert slip[unloaded].max() > 5 * np.abs(slip[middle]).max()
    assert np.all(np.diff(slip[unloaded]) > 0)


def test_the_traction_curve_has_its_stated_shape():
    curve = TractionCurve(0.05, 2.0, 0.036)
    speeds = np.array([[0.0, 2.0, 50.0, -2.0]])
    value, slope = curve(speeds)
    assert value[0] == pytest.approx([0.0, 0.05, 0.036, -0.05], abs=1e-6)
    assert slope[0, 1] == pytest.approx(0.0, abs=1e-12)  # the peak
    fine = np.linspace(0.01, 10, 2000)[None, :]
    assert np.argmax(curve(fine)[0]) == pytest.approx(np.argmin(np.abs(fine - 2.0)), abs=1)
    step = 1e-6
    numeric = (curve(speeds + step)[0] - curve(speeds - step)[0]) / (2 * step)
    assert slope == pytest.approx(numeric, abs=1e-6)


def test_walther_viscosity_passes_through_its_two_points():
    kelvin = np.array([40.0, 100.0, 25.0]) + 273.15
    nu = walther_viscosity(kelvin, 26e-6, 5.4e-6)
    assert nu[:2] == pytest.approx([26e-6, 5.4e-6], rel=1e-12)
    assert nu[2] > nu[0]


def test_chunking_does_not_change_the_numbers(tmp_path):
    text = ('[sweep]\nmodel = "cage_slip"\nbearing = "paper002-test"\n[axes]\n'
            'radial_load = { start = "200 N", stop = "1000 N", num = 5 }\n'
            'speed = ["6000 rpm", "12000 rpm"]\n')
    sweep = spec.parse(text)
    compute.run_sweep(sweep, tmp_path / "one.nc", compute.Executor(workers=0), progress=False)
    compute.run_sweep(sweep, tmp_path / "many.nc", compute.Executor(workers=0), chunk_size=3,
                  progress=False)
    one, many = stores.open_result(tmp_path / "one.nc"), stores.open_result(tmp_path / "many.nc")
    for name in ("cage_slip", "roller_slip", "cage_speed"):
        np.testing.assert_allclose(one[name].values, many[name].values, rtol=1e-12)


def test_a_cage_the_rollers_cannot_drive_has_no_root():
    # 1 N at 6000 r/min: even at 2 % of its kinematic speed the cage's drag exceeds what the
    # rollers give it, everywhere in the range (an independent scan of the balance says so).
    result = cage_slip(np.array([1.0, 800.0]), 6000 * RPM, **TEST)
    assert result["status"].tolist() == [NO_ROOT_IN_RANGE, CONVERGED]
    assert result["equilibrium_count"].tolist() == [0, 1]
    for name in ("cage_slip", "cage_speed", "roller_spin_ratio", "torque_residual"):
        assert np.isnan(result[name][0]) and np.isfinite(result[name][1])
    assert np.isnan(result["roller_slip"][0]).all()
    omega_kin = kinematic_cage_speed(6000 * RPM, 22 * MM, 32.01 * MM)
    scan = cage_torque_residual(np.linspace(0.02, 1.001, 200) * omega_kin, 1.0, 6000 * RPM,
                                **TEST)
    assert np.all(scan > 0)


def test_a_converged_point_balances_its_own_torques():
    # Light loads, where the torques are small: each residual against the cage's own drag at
    # its speed (the smallest of the torques balanced), from the published disc formula.
    loads = np.array([5.0, 20.0, 100.0, 1000.0])
    result = cage_slip(loads, 6000 * RPM, **TEST)
    assert np.all(result["status"] == CONVERGED)
    kinematic = walther_viscosity(298.15, 26e-6, 5.4e-6)
    drag = cage_windage(result["cage_speed"], 59 * MM, 9 * MM, 0.05 * 1000 + 0.95 * 1.2,
                        kinematic)
    assert np.all(np.abs(result["torque_residual"]) < 1e-5 * drag)


def test_the_cage_windage_uses_one_fluid():
    # Laminar disc, both faces: M = 2 x 3.87 Re^-1/2 rho omega^2 r^5 / 2, Re = omega r^2 / nu
    # (CAGE_SLIP_PHYSICS.md), worked by hand: omega 500 rad/s, r 29.5 mm, nu 50 mm^2/s:
    # Re = 500 x 8.7025e-4 / 5e-5 = 8702.5, C_M = 3.87 / 93.287 = 0.041485; rho_e 51.14 kg/m^3,
    # r^5 = 2.23415e-8 m^5: M = 0.041485 x 51.14 x 2.5e5 x 2.23415e-8 = 0.011850 N m.
    moment = cage_windage(500.0, 59 * MM, 9 * MM, 51.14, 50e-6)
    assert moment == pytest.approx(0.011850, rel=1e-4)
    # The same oil in a wetter mixture: the moment grows as the density, Re staying the same.
    wetter = cage_windage(500.0, 59 * MM, 9 * MM, 2 * 51.14, 50e-6)
    assert wetter / moment == pytest.approx(2.0, rel=1e-12)


def _films(radius=5 * MM, length=11 * MM, wrap=1.0, pocket_clearance=0.1 * MM,
           end_film=0.015 * MM):
    """Drag per spin speed over viscosity of a full pocket film and of full end films, from
    the forms in the docstring: R^3 L theta_w / c_p and pi R^4 / h_e [m^3]."""
    return radius**3 * length * wrap / pocket_clearance, np.pi * radius**4 / end_film


def test_the_cage_receives_the_pocket_films_reaction():
    # The same drag on the rollers' spin, once in the pocket (against the cage) and once at
    # the roller ends (against the ribs): the rollers turn alike at a given cage speed, but
    # only the pocket's film brakes the cage, by Z c_p times the mean spin.
    pocket, ends = _films()
    in_pocket = dict(TEST, pocket_film_fill=1.0, end_film_fill=0.0, pocket_friction=0.0)
    at_ends = dict(TEST, pocket_film_fill=0.0, end_film_fill=pocket / ends,
                   pocket_friction=0.0)
    loads = np.array([400.0, 800.0])
    braked = cage_slip(loads, 12000 * RPM, **in_pocket)
    free = cage_slip(loads, 12000 * RPM, **at_ends)
    assert np.all(braked["cage_slip"] > 1.05 * free["cage_slip"])
    viscosity = 1000.0 * walther_viscosity(298.15, 26e-6, 5.4e-6)
    omega_kin = kinematic_cage_speed(12000 * RPM, 22 * MM, 32.01 * MM)
    mean_spin = braked["roller_spin_ratio"] * (12000 * RPM - omega_kin) * 22 * MM / (5 * MM)
    # At the braked cage's speed the balance without the pocket's reaction lacks just that.
    lacking = cage_torque_residual(braked["cage_speed"], loads, 12000 * RPM, **at_ends)
    assert lacking == pytest.approx(-13 * viscosity * pocket * mean_spin, rel=1e-6)


def test_pocket_friction_slows_the_cage():
    result = cage_slip(800.0, 12000 * RPM, **{**TEST, "pocket_friction": np.array([0.0, 0.2])})
    assert result["cage_slip"][1] > result["cage_slip"][0]


BAND = dict(load=165.0, speed=9000 * RPM)  # inside the hysteresis band at 9000 r/min


def test_a_load_inside_the_hysteresis_band_has_three_equilibria():
    omega_kin = kinematic_cage_speed(BAND["speed"], 22 * MM, 32.01 * MM)
    shares = np.linspace(0.02, 1.001, 982)  # ten times the model's scan resolution
    balance = cage_torque_residual(shares * omega_kin, BAND["load"], BAND["speed"], **TEST)
    rising = np.flatnonzero((balance[:-1] <= 0) & (balance[1:] > 0))
    falling = np.flatnonzero((balance[:-1] > 0) & (balance[1:] <= 0))
    assert len(rising) == 2 and len(falling) == 1  # stable, unstable, stable
    assert rising[0] < falling[0] < rising[1]
    high, low = (cage_slip(BAND["load"], BAND["speed"], **TEST, branch=b)
                 for b in ("high_slip", "low_slip"))
    for result, crossing in ((high, rising[0]), (low, rising[1])):
        assert result["status"][0] == CONVERGED
        assert result["equilibrium_count"][0] == 2
        share = result["cage_speed"][0] / omega_kin
        assert shares[crossing] <= share <= shares[crossing + 1]
    assert high["cage_slip"][0] > 2 * low["cage_slip"][0]


def test_outside_the_band_both_branches_agree():
    loads = np.array([100.0, 200.0, 800.0])
    high = cage_slip(loads, 9000 * RPM, **TEST)
    low = cage_slip(loads, 9000 * RPM, **TEST, branch="low_slip")
    assert np.all(high["equilibrium_count"] == 1)
    np.testing.assert_allclose(high["cage_speed"], low["cage_speed"], rtol=1e-9)


@pytest.mark.parametrize("upstream", [NOT_CONVERGED, OUT_OF_VALIDITY])
def test_the_load_distributions_status_reaches_the_point(monkeypatch, upstream):
    original = steady_module.crb_radial

    def marked(*args, **kwargs):
        result = original(*args, **kwargs)
        result["status"] = np.array(result["status"])
        result["status"][3] = upstream  # one cage position of the first point
        return result

    monkeypatch.setattr(steady_module, "crb_radial", marked)
    result = cage_slip(np.array([800.0, 800.0]), 12000 * RPM, **TEST)
    assert result["status"].tolist() == [upstream, CONVERGED]


def test_the_run_summary_counts_the_points_with_several_equilibria(tmp_path):
    from bearing_sweep import spec
    from bearing_sweep.compute import Executor, run_sweep

    text = """
    [sweep]
    model = "cage_slip"
    bearing = "paper002-test"
    [fixed]
    speed = "9000 rpm"
    orbit_points = 12
    [axes]
    radial_load = ["150 N", "165 N", "180 N"]
    """.replace("\n    ", "\n")
    summary = run_sweep(spec.parse(text), tmp_path / "band.nc", Executor(workers=0),
                        progress=False)
    assert summary.noted == {"points with several stable equilibria": 1}
    assert "; 1 points with several stable equilibria" in summary.text()


def _steady(**fixed):
    lines = "\n".join(f'{name} = "{value}"' for name, value in fixed.items())
    return spec.parse('[sweep]\nmodel = "cage_slip"\nbearing = "paper002-test"\n'
                      f'[fixed]\nspeed = "9000 rpm"\n{lines}\n'
                      '[axes]\nradial_load = ["400 N", "800 N"]\n')


@pytest.mark.parametrize("fixed, words", [
    # the reproductions: a contact longer than the 11 mm roller, a 1 m pocket clearance, an
    # oil a billionth as dense as air, and the oil's viscosities swapped
    (dict(effective_length="100 mm"), "part of the roller"),
    (dict(pocket_clearance="1 m"), "pockets do not fit"),
    (dict(oil_density="1e-9 kg/m^3"), "oil_density"),
    (dict(viscosity_40="8 mm^2/s", viscosity_100="68 mm^2/s"), "thins as it warms"),
    (dict(clearance="12 mm"), "smaller than the roller diameter"),
    (dict(cage_outer_diameter="70 mm"), "between the raceways"),
    (dict(cage_inner_diameter="40 mm"), "between the raceways"),
    (dict(roller_density="7.8e6 kg/m^3"), "roller_density"),
    # the reproductions: 1 kg/m^3 gave a roller spin ratio of -36.9 % and a film of 6.56 um,
    # converged; 100 kg/m^3 did not converge; a drag coefficient of 1e6 gave 97.7 % slip
    (dict(roller_density="1 kg/m^3"), "roller_density"),
    (dict(roller_density="100 kg/m^3"), "roller_density"),
    (dict(roller_density="16000 kg/m^3"), "roller_density"),
    (dict(drag_coefficient="1e6"), "drag_coefficient"),
    (dict(drag_coefficient="11"), "drag_coefficient"),
    (dict(youngs_modulus="1e-6 GPa"), "youngs_modulus"),
])
def test_impossible_inputs_are_refused_before_computing(fixed, words):
    with pytest.raises(spec.SpecError, match=words):
        _steady(**fixed)


def test_thick_films_are_out_of_validity_beside_the_other_status():
    # A pocket clearance of 0.6 mm is 12 % of the 5 mm roller radius, beyond the thin
    # Couette film's 10 %; at 1 N the rollers cannot drive the cage (no root): both show.
    thick = dict(TEST, pocket_clearance=0.6 * MM)
    result = cage_slip(np.array([1.0, 800.0]), 6000 * RPM, **thick)
    assert result["status"].tolist() == [NO_ROOT_IN_RANGE | OUT_OF_VALIDITY,
                                         CONVERGED | OUT_OF_VALIDITY]
    assert np.isfinite(result["cage_slip"][1])
    thin = cage_slip(np.array([800.0]), 6000 * RPM, **dict(TEST, pocket_clearance=0.4 * MM))
    assert thin["status"].tolist() == [CONVERGED]


@pytest.mark.parametrize("film, flagged", [
    ({"end_film_thickness": 1e-9}, True), ({"end_film_thickness": 0.99e-6}, True),
    ({"end_film_thickness": 1.01e-6}, False), ({"pocket_clearance": 0.5e-6}, True),
    ({"pocket_clearance": 2e-6}, False)])
def test_films_thinner_than_the_surfaces_roughness_are_out_of_validity(film, flagged):
    # A 1 nm end film took 98 % of the cage's speed away, within validity: Petroff's drag
    # grows as the film's inverse, and a film below a micrometre is no full film.
    result = cage_slip(np.array([800.0]), 6000 * RPM, **dict(TEST, **film))
    assert bool(result["status"][0] & OUT_OF_VALIDITY) == flagged


def test_describe_states_the_validity_it_inherits_from_the_load_distribution():
    from bearing_sweep import describe

    validity = describe("cage_slip")["validity"]
    assert "crb_radial" in validity and "4000 MPa" in validity and "10 %" in validity
    for transient in ("cage_dynamics", "cage_dynamics_6dof"):
        assert validity in describe(transient)["validity"]


def test_materials_within_reach_are_accepted():
    for fixed in (dict(roller_density="900 kg/m^3"), dict(roller_density="3200 kg/m^3"),
                  dict(roller_density="15700 kg/m^3"), dict(drag_coefficient="10"),
                  dict(drag_coefficient="0")):
        assert _steady(**fixed).model.name == "cage_slip"


def test_an_oil_speed_or_material_no_bearing_has_is_out_of_validity():
    # The reproductions at 1 kN, 3000 r/min: 3520 and 3519 mm^2/s (a viscosity index of 811)
    # and 1e-6 GPa rollers and rings came out converged; 1e300 r/min not converged without
    # a word of validity. Each is flagged beside its outcome, values kept where they are.
    oils = cage_slip(1000.0, 3000 * RPM, **{**TEST, "viscosity_40": np.array([26e-6, 3520e-6]),
                                            "viscosity_100": np.array([5.4e-6, 3519e-6])})
    assert oils["status"].tolist() == [CONVERGED, CONVERGED | OUT_OF_VALIDITY]
    assert np.isfinite(oils["cage_slip"]).all()
    soft = cage_slip(1000.0, 3000 * RPM, **{**TEST, "youngs_modulus": np.array([207e9, 1e3])})
    assert soft["status"].tolist() == [CONVERGED, CONVERGED | OUT_OF_VALIDITY]
    with np.errstate(over="ignore", invalid="ignore"):  # 1e300 r/min overflows, as it should
        fast = cage_slip(1000.0, np.array([3000.0, 1e5, 1e300]) * RPM, **TEST)
    assert fast["status"][0] == CONVERGED
    assert all(s & OUT_OF_VALIDITY for s in fast["status"][1:])
    assert fast["status"][2] & ~OUT_OF_VALIDITY == NOT_CONVERGED


def test_the_transient_models_carry_the_flag_of_a_speed_no_bearing_runs_at():
    from bearing_sweep.models.cage_dynamics import cage_dynamics
    from bearing_sweep.models.cage_dynamics_6dof import cage_dynamics_6dof

    with np.errstate(over="ignore", invalid="ignore"):
        planar = cage_dynamics(1000.0, 1e300 * RPM, **TEST, duration=1e-3,
                               output_interval=5e-4)
        spatial = cage_dynamics_6dof(1000.0, 1e300 * RPM, **TEST, duration=1e-3,
                                     output_interval=5e-4)
    for result in (planar, spatial):
        assert result["status"].tolist() == [NOT_CONVERGED | OUT_OF_VALIDITY]


def test_a_cage_narrower_than_its_rollers_is_refused():
    # Each pocket holds a whole roller: the cage is at least as wide as the rollers are long
    # (11 mm on paper 002's test bearing); 0 stands for no cage windage.
    from bearing_sweep import spec

    text = ('[sweep]\nmodel = "cage_slip"\nbearing = "paper002-test"\n[fixed]\n'
            'speed = "9000 rpm"\nradial_load = "800 N"\ncage_width = "{}"\n')
    with pytest.raises(spec.SpecError, match="cage_width must be at least roller_length"):
        spec.parse(text.format("10.9 mm"))
    for width in ("11 mm", "0 mm"):
        assert spec.parse(text.format(width)).fixed["cage_width"] is not None
