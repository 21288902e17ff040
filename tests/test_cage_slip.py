"""cage_slip: trends, the cage's torque balance, the no-drag limit, traction and viscosity."""
import numpy as np
import pytest

from models.cage_slip import cage_slip, kinematic_cage_speed
from models.lubrication import TractionCurve, walther_viscosity
from sweeps import run, spec, store

MM, RPM = 1e-3, 2 * np.pi / 60
#: The test bearing of paper 002, Table 2 (outer raceway from di + 2D + Pd).
TEST = dict(roller_count=13, inner_raceway_diameter=44 * MM, roller_diameter=10 * MM,
            roller_length=11 * MM, effective_length=7.2 * MM, clearance=0.02 * MM,
            cage_inner_diameter=48.5 * MM, cage_outer_diameter=59 * MM, cage_width=9 * MM)
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
    run.run_sweep(sweep, tmp_path / "one.nc", run.Executor(workers=0), progress=False)
    run.run_sweep(sweep, tmp_path / "many.nc", run.Executor(workers=0), chunk_size=3,
                  progress=False)
    one, many = store.open_result(tmp_path / "one.nc"), store.open_result(tmp_path / "many.nc")
    for name in ("cage_slip", "roller_slip", "cage_speed"):
        np.testing.assert_allclose(one[name].values, many[name].values, rtol=1e-12)
