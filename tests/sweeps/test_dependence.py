"""Outputs that depend on fewer inputs than the grid (``Output.depends_on``) are stored on the
axes of those inputs only, the same whatever the chunking, in memory and in the file; a model
whose declaration is wrong stops the sweep with one clear line."""
import numpy as np
import pytest
import xarray as xr

import bearing_sweep.models.registry as registry
from bearing_sweep import analyze, cli, run, spec, stores
from bearing_sweep.evaluate import evaluate_chunk
from bearing_sweep.dependence import InconsistentOutput, Reduction, on_grid
from bearing_sweep.grid import Grid
from bearing_sweep.models.registry import Model, Output
from bearing_sweep.testing import assert_chunking_invariant


def test_an_output_depending_on_one_axis_is_stored_on_it(toy):
    data = run(toy, workers=0, progress=False)
    assert data["total"].dims == ("a", "b")
    assert data["product"].dims == ("b",)
    assert data["whole_b"].dims == ("b",)
    # b c with c = 2 at b = 1, 2, 3; b = -2 failed at every a: no value.
    np.testing.assert_array_equal(data["product"].values, [np.nan, 2.0, 4.0, 6.0])
    np.testing.assert_array_equal(data["whole_b"].values, [np.nan, 1.0, 2.0, 3.0])
    assert data["product"].attrs["long_name"] == "b c"


def test_the_file_holds_the_same_on_the_same_dims_whatever_the_chunks(toy, tmp_path):
    # The first row (a = -1) fails: chunks of one point take each value from a later chunk.
    assert_chunking_invariant(toy, tmp_path, chunk_size=1)
    assert_chunking_invariant(toy, tmp_path, chunk_size=5)
    in_file = stores.open_result(tmp_path / "chunked.nc")
    assert in_file["product"].dims == ("b",)
    np.testing.assert_array_equal(in_file["product"].values,
                                  run(toy, workers=0, progress=False)["product"].values)


def test_chunks_in_any_order_give_each_cell_its_first_held_point(toy):
    grid = Grid.from_sweep(spec.parse(toy))
    chunks = [(start, stop, evaluate_chunk(grid, start, stop)) for start, stop in grid.chunks(5)]
    in_order, reversed_order = Reduction(grid, grid.model.outputs[1]), \
        Reduction(grid, grid.model.outputs[1])
    for start, stop, part in chunks:
        in_order.add(start, stop, part["outputs"]["product"], part["status"])
    for start, stop, part in reversed(chunks):
        reversed_order.add(start, stop, part["outputs"]["product"], part["status"])
    # Points 4 to 7 (a = 1) hold first; b = -2 (point 4) fails everywhere.
    np.testing.assert_array_equal(in_order.source[1:], [5, 6, 7])
    np.testing.assert_array_equal(reversed_order.source, in_order.source)
    np.testing.assert_array_equal(reversed_order.values, in_order.values)


def test_a_fixed_input_holds_no_dim_and_an_axis_of_it_one(toy):
    fixed = run('[sweep]\nmodel = "toy"\n[fixed]\nb = 3\n[axes]\na = [1, 2]\n', workers=0,
                progress=False)
    assert fixed["product"].dims == ()
    assert fixed["product"].item() == 6.0  # 3 x the default c = 2
    both = run('[sweep]\nmodel = "toy"\n[axes]\na = [1, 2]\nb = [1, 3]\nc = [1, 10]\n',
               workers=0, progress=False)
    assert both["product"].dims == ("b", "c")
    np.testing.assert_array_equal(both["product"].values, [[1.0, 10.0], [3.0, 30.0]])


def test_a_zipped_axis_holding_an_input_is_kept_whole(toy):
    data = run('[sweep]\nmodel = "toy"\n[axes]\nc = [1, 10]\n'
               '[axes.case]\nlabels = ["x", "y", "z"]\na = [1, 2, 3]\nb = [4, 5, 6]\n',
               workers=0, progress=False)
    assert data["product"].dims == ("c", "case")
    np.testing.assert_array_equal(data["product"].values, [[4.0, 5.0, 6.0],
                                                           [40.0, 50.0, 60.0]])


def test_a_sampled_input_keeps_the_sample_dim_and_the_analysis_sees_every_sample(toy):
    sample = '[sample]\nmethod = "random"\nn = 8\n'
    drawn = run('[sweep]\nmodel = "toy"\n[axes]\na = [1, -1]\n' + sample
                + 'b = { distribution = "uniform", low = 1, high = 2 }\n', workers=0,
                progress=False)
    assert drawn["product"].dims == ("sample",)
    np.testing.assert_array_equal(drawn["product"].values, 2.0 * drawn["b"].values)
    fixed_b = run('[sweep]\nmodel = "toy"\n[fixed]\nb = 3\n' + sample
                  + 'a = { distribution = "uniform", low = -1, high = 1 }\n', workers=0,
                  progress=False)
    assert fixed_b["product"].dims == ()
    analysis = analyze(fixed_b)  # over the samples whose values hold, as for the others
    held = (fixed_b["a"] >= 0).sum().item()
    assert 0 < held < 8
    assert analysis["product"].sel(statistic="mean").item() == 6.0
    assert analysis["product"].sel(statistic="std").item() == 0.0
    assert analysis["valid_samples"].item() == held


def test_on_grid_gives_every_point_its_value_and_failed_points_nan(toy):
    data = run(toy, workers=0, progress=False)
    spread = on_grid(data)["product"]
    assert spread.dims == ("a", "b")
    expected = xr.where((data["a"] < 0) | (data["b"] < 0), np.nan,
                        data["b"] * 2.0).transpose("a", "b")
    np.testing.assert_array_equal(spread.values, expected.values)
    # xarray alone restores the shape (without the failed points' NaN).
    assert set(xr.broadcast(data["product"], data["status"])[0].dims) == {"a", "b"}


def test_a_model_whose_output_varies_along_a_dropped_axis_stops_the_sweep(toy, tmp_path,
                                                                          capsys):
    lying = toy.replace('"toy"', '"liar"')
    with pytest.raises(InconsistentOutput, match=r"model 'liar', output 'product': declared "
                       r"to depend on b, c only .* it differs between points that share "
                       r"those: 3 at point a\[1\], b\[1\] and 4 at point a\[2\], b\[1\]"):
        run(lying, workers=0, progress=False)
    path = tmp_path / "liar.toml"
    path.write_text(lying)
    result = tmp_path / "liar.nc"
    # Chunks of one row of a each: the rows disagree, each alone does not (a chunk whose own
    # points disagree is refused where it is computed, and not kept).
    assert cli.main(["run", str(path), "-o", str(result), "--workers", "0", "--chunk-size", "4",
                     "--quiet"]) == 1
    error = capsys.readouterr().err
    assert error.startswith("error: model 'liar', output 'product'") and error.count("\n") == 1
    assert "the computed chunks are kept" in error
    assert not result.exists()
    assert list((tmp_path / "liar.nc.parts").glob("chunk-*.npz"))  # a fixed model resumes


def test_depends_on_names_declared_inputs(toy_model):
    model = toy_model("toy")
    wrong = Model(**{**model.__dict__, "outputs": (Output("product", "1", "b c",
                                                          depends_on=("b", "speed")),)})
    assert registry.declaration_problems(model) == []
    assert registry.declaration_problems(wrong) == [
        "output 'product': depends_on (b, speed) must name declared inputs, once each; not "
        "inputs: speed"]


def test_crb_radial_stores_its_centrifugal_force_and_kappa_on_the_speed_axis():
    data = run('[sweep]\nmodel = "crb_radial"\nbearing = "paper000-D"\n[fixed]\nslices = 4\n'
               'viscosity_40 = "68 mm^2/s"\nviscosity_100 = "8.5 mm^2/s"\n'
               '[axes]\nradial_load = ["2 kN", "4 kN"]\nspeed = ["0 rpm", "3000 rpm"]\n',
               workers=0, progress=False)
    assert data["centrifugal_force"].dims == ("speed",)
    assert data["viscosity_ratio"].dims == ("speed",)
    assert data["radial_displacement"].dims == ("radial_load", "speed")
    assert data["centrifugal_force"].values[0] == 0.0  # at rest
    assert data["centrifugal_force"].values[1] > 0.0


def test_the_quick_look_draws_an_output_stored_on_fewer_axes_at_every_point(toy):
    from bearing_sweep.quicklook import plot

    figure = plot(run(toy, workers=0, progress=False), "product", x="b")
    lines = [line for line in figure.axes[0].lines if not line.get_label().startswith("_")]
    assert len(lines) == 3  # one per a; a = -1 failed everywhere: no value on its line
    np.testing.assert_array_equal(lines[0].get_ydata(), [np.nan] * 4)
    np.testing.assert_array_equal(lines[1].get_ydata(), [np.nan, 2.0, 4.0, 6.0])


@pytest.mark.parametrize("attrs, codes, held", [
    # a file of this version: bit fields (out_of_validity beside any outcome)
    ({"flag_masks": np.array([11, 11, 11, 11, 4, 11], np.int8),
      "flag_values": np.array([0, 1, 2, 3, 4, 8], np.int8)},
     [0, 4, 8, 12, 1, 5, 2, 3], [True, True, True, True, False, False, False, False]),
    # a file written before: one code each, out_of_validity keeping its values
    ({"flag_values": np.arange(6, dtype=np.int8)},
     [0, 4, 5, 1, 2, 3], [True, True, True, False, False, False]),
])
def test_held_points_read_the_status_flags_of_either_format(attrs, codes, held):
    from bearing_sweep.dependence import flag_holds, held_points

    status = xr.DataArray(np.array(codes, np.int8), dims="point", attrs={
        **attrs, "flag_meanings": "converged not_converged infeasible model_error "
                                  "out_of_validity no_root_in_range"})
    assert held_points(status).values.tolist() == held
    outside = [c in (4, 12, 5) if "flag_masks" in attrs else c == 4 for c in codes]
    assert flag_holds(status, "out_of_validity").values.tolist() == outside
