"""The labelled grid: axes in order, zipped axes, and the inputs of any range of points."""
import dataclasses

import numpy as np
import pytest

from bearing_sweep import spec
from bearing_sweep.grid import Grid
from bearing_sweep.labels import coordinates, fixed_inputs

TEXT = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "4 um"
[axes]
radial_load = ["2 kN", "4 kN", "8 kN"]
slices = [10, 60]
[axes.case]
labels = ["l25", "l28"]
effective_length = ["25 mm", "28 mm"]
roller_count = [14, 12]
"""


def test_shape_follows_the_axes_in_order():
    grid = Grid.from_sweep(spec.parse(TEXT))
    assert grid.dims == ("radial_load", "slices", "case")
    assert grid.shape == (3, 2, 2) and grid.size == 12
    assert grid.dim_sizes == {"roller": 14}  # the largest roller count on the grid


def test_points_are_numbered_in_c_order_and_zipped_inputs_move_together():
    grid = Grid.from_sweep(spec.parse(TEXT))
    varying, index = grid.inputs(0, grid.size)
    loads = np.repeat([2000.0, 4000.0, 8000.0], 4)
    np.testing.assert_array_equal(varying["radial_load"], loads)
    np.testing.assert_array_equal(varying["slices"], np.tile(np.repeat([10, 60], 2), 3))
    np.testing.assert_allclose(varying["effective_length"], np.tile([0.025, 0.028], 6))
    np.testing.assert_array_equal(varying["roller_count"], np.tile([14, 12], 6))
    assert set(index) == {"radial_load", "slices", "case"}
    part, _ = grid.inputs(5, 9)
    np.testing.assert_array_equal(part["radial_load"], loads[5:9])


def test_chunks_cover_the_grid_once():
    grid = Grid.from_sweep(spec.parse(TEXT))
    for size in (1, 5, 12, 100):
        chunks = grid.chunks(size)
        covered = np.concatenate([np.arange(a, b) for a, b in chunks])
        np.testing.assert_array_equal(covered, np.arange(12))


def test_coordinates_hold_each_input_in_its_declared_unit_and_keep_the_written_one():
    sweep = spec.parse(TEXT)
    coords = coordinates(sweep)
    dims, values, attrs = coords["radial_load"]
    assert dims == ("radial_load",) and values.tolist() == [2000, 4000, 8000]
    assert attrs["units"] == "N" and attrs["written_units"] == "kN"
    dims, values, attrs = coords["effective_length"]
    assert dims == ("case",) and values.tolist() == [25, 28] and attrs["units"] == "mm"
    assert "written_units" not in attrs
    assert coords["case"][1].tolist() == ["l25", "l28"]
    assert "crown" not in coords  # fixed inputs are variables, not scalar coordinates
    dims, value, attrs = fixed_inputs(sweep)["crown"]
    assert dims == () and value == 0.004 and attrs["units"] == "mm" and attrs["origin"] == "fixed"
    assert attrs["written_units"] == "um"
    assert fixed_inputs(sweep)["pitch_diameter"][2]["origin"] == "preset paper000-D"
    assert all("long_name" in c[2] for c in coords.values())


def test_converted_values_are_tidy_and_the_same_whatever_unit_was_written():
    def stored(load):
        text = TEXT.replace('["2 kN", "4 kN", "8 kN"]', load)
        return coordinates(spec.parse(text))["radial_load"][1].tolist()

    assert stored('["0.3 kN", "0.7 kN", "1.1 kN"]') == [300, 700, 1100]
    assert stored('["300 N", "0.7 kN", "1100 N"]') == [300, 700, 1100]
    assert stored('{ start = "0.1 kN", stop = "0.3 kN", step = "0.1 kN" }') == [100, 200, 300]


def test_a_cost_given_as_a_function_of_the_inputs_is_its_mean_over_the_points(monkeypatch):
    # A model whose point costs its radial load in kN seconds times its slices, and the
    # crown fixed: the grid's cost per point is the mean over its 12 points.
    grid = Grid.from_sweep(spec.parse(TEXT))
    seen = {}

    def cost(values):
        seen.update(values)
        return values["radial_load"] / 1000 * values["slices"]

    monkeypatch.setattr(grid, "model", dataclasses.replace(grid.model,
                                                           seconds_per_point=cost))
    expected = np.mean([f * n for f in (2, 4, 8) for n in (10, 60) for _ in range(2)])
    assert grid.seconds_per_point == expected
    assert seen["crown"] == 4e-6  # the fixed inputs too, in SI
    many = Grid.from_sweep(spec.parse(TEXT.replace('["2 kN", "4 kN", "8 kN"]',
                                                   '{ start = "1 kN", stop = "2 kN", '
                                                   'step = "0.0001 kN" }')))
    monkeypatch.setattr(many, "model", dataclasses.replace(many.model, seconds_per_point=cost))
    assert many.size > 40_000
    # from 1000 points drawn at random: the mean's standard error is about 2 % here
    assert many.seconds_per_point == pytest.approx(1.5 * 35, rel=0.1)
    assert len(seen["radial_load"]) == 1000


def test_the_spatial_cage_models_cost_follows_its_bearing_time_film_and_integrator():
    base = """
[sweep]
model = "cage_dynamics_6dof"
bearing = "paper002-test"
[fixed]
radial_load = "800 N"
speed = "12000 rpm"
duration = "{duration}"
[axes]
cage_eccentricity = ["0 mm", "2 mm"]
"""
    short, long = (Grid.from_sweep(spec.parse(base.format(duration=d)))
                   for d in ("20 ms", "100 ms"))
    assert long.seconds_per_point == pytest.approx(5 * short.seconds_per_point)

    def cost(fixed):
        return Grid.from_sweep(spec.parse(base.format(duration="20 ms").replace(
            "[axes]", f"{fixed}\n[axes]"))).seconds_per_point

    explicit = cost('end_film = "reynolds"\nintegrator = "adaptive"')
    implicit = cost('end_film = "reynolds"\nintegrator = "rosenbrock"')
    multistep = cost('end_film = "reynolds"\nintegrator = "bdf"')
    # the films' pressure holds the explicit method's steps; the implicit ones' far less
    assert explicit > 10 * implicit > 10 * multistep
    # the default takes the multistep formulas for them, and the additive one for the paper's
    assert cost('end_film = "reynolds"') == multistep
    assert cost("") == cost('integrator = "imex"') < cost('integrator = "adaptive"')
