"""A duty cycle in a definition: a zipped axis with a ``time_share`` column, whose rating lives
the result combines beside each load case's (``bearing_sweep.duty_cycle``)."""
import numpy as np
import pytest
import xarray as xr

from bearing_sweep import api, spec
from bearing_sweep.duty_cycle import cycle_variables
from bearing_sweep.grid import Grid
from bearing_sweep.models.registry import CONVERGED, NOT_CONVERGED, OUT_OF_VALIDITY

#: A cylindrical roller bearing over three load cases, one at rest.
ROLLER_CYCLE = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
dynamic_load_rating = "48.4 kN"
[axes]
clearance = ["0 mm", "0.02 mm"]
[axes.case]
labels = ["heavy", "light", "standstill"]
time_share = [1, 3, 2]
radial_load = ["8 kN", "2 kN", "5 kN"]
speed = ["1500 rpm", "3000 rpm", "0 rpm"]
"""

#: The spindle of the spindle study: two angular contact ball bearings and a roller bearing.
SPINDLE_CYCLE = """
[sweep]
model = "shaft_system"
[shaft]
sections = [{ length = "62.5 mm", diameter = "35 mm", bore = "12 mm" },
            { length = "437.5 mm", diameter = "55 mm", bore = "12 mm" }]
[supports.front_a]
model = "ball_5dof"
bearing = "paper001-71807AC"
position = "40 mm"
clearance = "-5 um"
[supports.front_b]
model = "ball_5dof"
bearing = "paper001-71807AC"
position = "55 mm"
axial_direction = "negative"
clearance = "-5 um"
[supports.rear]
model = "crb_radial"
bearing = "paper000-D"
position = "300 mm"
[loads.cutting]
position = "0 mm"
[fixed]
station_count = 5
[axes.case]
labels = ["roughing", "finishing", "idling"]
time_share = [0.2, 0.5, 0.3]
"loads.cutting.force_y" = ["2 kN", "600 N", "100 N"]
"loads.cutting.force_x" = ["-600 N", "-150 N", "0 N"]
"""


def test_lives_in_revolutions_combine_over_the_revolutions_and_hours_over_the_time():
    data = api.run(ROLLER_CYCLE, workers=0, progress=False)
    shares = np.array([1, 3, 2]) / 6
    speed = np.array([1500.0, 3000.0, 0.0])  # r/min
    lives = data.reference_rating_life.transpose("clearance", "case").values  # 10^6 rev
    hours = data.reference_rating_hours.transpose("clearance", "case").values
    # Palmgren-Miner (Palmgren 1924; Miner 1945, doi:10.1115/1.4009458): each case uses up
    # its share of the revolutions over its own life; the case at rest, none.
    revolutions = shares * speed / np.sum(shares * speed)
    expected = 1.0 / np.sum(revolutions / lives, axis=1)
    np.testing.assert_allclose(data.reference_rating_life_over_duty_cycle.values, expected,
                               rtol=1e-13)
    expected_hours = 1.0 / np.sum(shares / hours, axis=1)  # the case at rest: infinite
    np.testing.assert_allclose(data.reference_rating_hours_over_duty_cycle.values,
                               expected_hours, rtol=1e-13)
    # One life, two units: revolutions = hours x the cycle's mean speed.
    mean_speed = np.sum(shares * speed) * 60.0  # rev/h
    np.testing.assert_allclose(data.reference_rating_life_over_duty_cycle.values * 1e6,
                               data.reference_rating_hours_over_duty_cycle.values * mean_speed,
                               rtol=1e-12)
    assert data.reference_rating_life_over_duty_cycle.dims == ("clearance",)
    assert data.reference_rating_life_over_duty_cycle.attrs["units"] == "Mturn"
    np.testing.assert_allclose(data.time_share.values, shares, rtol=1e-15)
    assert (data.status_over_duty_cycle.values == CONVERGED).all()


def test_a_systems_life_over_the_cycle_is_the_weibull_combination_of_its_bearings():
    data = api.run(SPINDLE_CYCLE, workers=0, progress=False)
    shares = np.array([0.2, 0.5, 0.3])
    lives = data.reference_rating_life.transpose("support", "case").values
    over = data.reference_rating_life_over_duty_cycle.values
    np.testing.assert_allclose(over, 1.0 / np.sum(shares / lives, axis=1), rtol=1e-13)
    # The system survives while every bearing does (Lundberg and Palmgren; Harris and
    # Kotzalas, Rolling Bearing Analysis, 5th ed., ch. 11): sum (L / L_i)^e_i = 1, with
    # e = 10/9 for the two ball bearings and 9/8 for the roller bearing.
    system = float(data.system_reference_life_over_duty_cycle)
    slopes = np.array([10 / 9, 10 / 9, 9 / 8])
    assert np.sum((system / over) ** slopes) == pytest.approx(1.0, rel=1e-12)
    assert system < over.min()
    # Each case's system life stays beside it.
    assert data.system_reference_life.dims == ("case",)


def test_the_lives_over_a_cycle_do_not_depend_on_the_store_or_the_chunks(tmp_path):
    held = api.run(SPINDLE_CYCLE, workers=0, progress=False)
    api.run(SPINDLE_CYCLE, output=tmp_path / "one.nc", workers=0, chunk_size=1,
            progress=False, open_output=False)
    api.run(SPINDLE_CYCLE, output=tmp_path / "one.zarr", workers=0, chunk_size=2,
            progress=False, open_output=False)
    names = [name for name in held.data_vars if name.endswith("_over_duty_cycle")]
    assert names == ["reference_rating_life_over_duty_cycle",
                     "system_reference_life_over_duty_cycle", "status_over_duty_cycle"]
    for path in ("one.nc", "one.zarr"):
        with xr.open_dataset(tmp_path / path) as stored:
            for name in names:
                np.testing.assert_array_equal(stored[name].values, held[name].values)


def _cycle(statuses, lives):
    """The variables of the roller cycle from given statuses and lives (three cases, at one
    clearance)."""
    sweep = spec.parse(ROLLER_CYCLE.replace('["0 mm", "0.02 mm"]', '["0 mm"]'))
    grid = Grid.from_sweep(sweep)
    outputs = {o.name: np.full((grid.size,), 100.0) for o in grid.model.outputs if o.cycle}
    outputs["reference_rating_life"] = np.asarray(lives, dtype=float)
    return cycle_variables(sweep, grid, outputs, np.asarray(statuses, dtype=np.int8))


def test_a_case_out_of_validity_flags_the_cycle_and_a_failed_one_voids_it():
    variables = _cycle([CONVERGED, OUT_OF_VALIDITY, CONVERGED], [1e3, 4e3, 9e3])
    assert variables["status_over_duty_cycle"][1][0] == OUT_OF_VALIDITY
    assert np.isfinite(variables["reference_rating_life_over_duty_cycle"][1][0])
    variables = _cycle([CONVERGED, NOT_CONVERGED, CONVERGED], [1e3, np.nan, 9e3])
    assert variables["status_over_duty_cycle"][1][0] == NOT_CONVERGED
    assert np.isnan(variables["reference_rating_life_over_duty_cycle"][1][0])


def test_a_case_without_a_share_of_the_time_takes_no_part():
    text = ROLLER_CYCLE.replace("time_share = [1, 3, 2]", "time_share = [1, 3, 0]")
    sweep = spec.parse(text.replace('["0 mm", "0.02 mm"]', '["0 mm"]'))
    grid = Grid.from_sweep(sweep)
    outputs = {o.name: np.full((grid.size,), 100.0) for o in grid.model.outputs if o.cycle}
    outputs["reference_rating_life"] = np.array([1e3, 4e3, np.nan])
    variables = cycle_variables(sweep, grid, outputs, np.array(
        [CONVERGED, CONVERGED, NOT_CONVERGED], dtype=np.int8))
    assert variables["status_over_duty_cycle"][1][0] == CONVERGED
    revolutions = np.array([1 * 1500.0, 3 * 3000.0]) / (1 * 1500.0 + 3 * 3000.0)
    assert variables["reference_rating_life_over_duty_cycle"][1][0] == pytest.approx(
        1.0 / (revolutions[0] / 1e3 + revolutions[1] / 4e3), rel=1e-14)


def test_a_case_at_rest_uses_up_no_life_even_where_its_modified_life_is_unknown():
    # At rest there is no film: the modified life's kappa is 0 and the model gives it no
    # value. The case uses up none of it, as it uses up no revolutions.
    text = ROLLER_CYCLE.replace('dynamic_load_rating = "48.4 kN"', 'dynamic_load_rating = '
                                '"48.4 kN"\nfatigue_load_limit = "6 kN"\nviscosity_40 = '
                                '"68 mm^2/s"\nviscosity_100 = "8.5 mm^2/s"')
    data = api.run(text, workers=0, progress=False)
    hours = data.modified_reference_rating_hours.transpose("clearance", "case").values
    assert np.isnan(hours[:, 2]).all() and np.isfinite(hours[:, :2]).all()
    shares = np.array([1, 3, 2]) / 6  # the time at rest counts in the cycle's hours
    np.testing.assert_allclose(data.modified_reference_rating_hours_over_duty_cycle.values,
                               1.0 / np.sum(shares[:2] / hours[:, :2], axis=1), rtol=1e-13)
    revolutions = data.modified_reference_rating_life_over_duty_cycle.values * 1e6
    mean_speed = (1 * 1500 + 3 * 3000) / 6 * 60.0  # rev/h over the whole cycle
    np.testing.assert_allclose(revolutions, data.modified_reference_rating_hours_over_duty_cycle
                               .values * mean_speed, rtol=1e-12)
