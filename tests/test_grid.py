"""The labelled grid: axes in order, zipped axes, and the inputs of any range of points."""
import numpy as np

from sweeps import spec
from sweeps.grid import Grid, coordinates

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


def test_coordinates_keep_the_users_values_and_units():
    coords = coordinates(spec.parse(TEXT))
    dims, values, attrs = coords["radial_load"]
    assert dims == ("radial_load",) and values.tolist() == [2, 4, 8] and attrs["units"] == "kN"
    dims, values, attrs = coords["effective_length"]
    assert dims == ("case",) and values.tolist() == [25, 28] and attrs["units"] == "mm"
    assert coords["case"][1].tolist() == ["l25", "l28"]
    dims, values, attrs = coords["crown"]
    assert dims == () and values == 4 and attrs["units"] == "um" and attrs["origin"] == "fixed"
    assert coords["pitch_diameter"][2]["origin"] == "preset paper000-D"
    assert all("long_name" in c[2] and "units" in c[2] for c in coords.values())
