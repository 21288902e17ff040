"""A zarr output (``-o result.zarr``): the netCDF file's data and attributes whatever the
chunking and the workers, each chunk written by its worker, resumable, never left half."""
import json
import math
import shutil
from pathlib import Path

import cf_units
import numpy as np
import pytest
import xarray as xr
import zarr

import bearing_sweep
from bearing_sweep import cli, spec, stores
from bearing_sweep.compute import Executor, WorkerMismatch, run_sweep
from bearing_sweep.dependence import InconsistentOutput
from bearing_sweep.grid import Grid
from bearing_sweep.stores.paths import is_zarr
from bearing_sweep.stores.blocks import regions
from bearing_sweep.grid import block_chunks, block_shape

# 3 x 4 x 2 points: chunks of 3 points are blocks of (1, 1, 2), of 16 points (2, 4, 2).
DEFINITION = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "0.004 mm"
[axes]
radial_load = { start = "2 kN", stop = "6 kN", num = 3 }
clearance = { start = "0 mm", stop = "0.03 mm", num = 4 }
speed = { values = [0, 5000], units = "rpm" }
"""
#: Attributes that say when and where a result was made, not what it holds.
PROVENANCE = ("history", "scheduler")


def without_provenance(dataset):
    dataset = dataset.copy()
    for name in PROVENANCE:
        dataset.attrs.pop(name)
    return dataset


def assert_same_result(netcdf, zarr_store):
    """Identical data, dtypes, coordinates and attributes, provenance aside."""
    a, b = stores.open_result(netcdf), stores.open_result(zarr_store)
    xr.testing.assert_identical(without_provenance(a), without_provenance(b))
    for name, variable in a.variables.items():
        assert variable.dtype == b[name].dtype, name
    return b


@pytest.mark.parametrize("shape, size", [((3, 4, 2), 3), ((3, 4, 2), 16), ((1001,), 1000),
                                         ((7, 5, 3), 4), ((2, 3), 100), ((), 5)])
def test_each_chunk_is_one_whole_zarr_chunk(shape, size):
    block = block_shape(shape, size)
    chunks = block_chunks(shape, block)
    assert chunks[0][0] == 0 and chunks[-1][1] == math.prod(shape)
    assert all(a[1] == b[0] for a, b in zip(chunks, chunks[1:]))  # in order, no gap
    assert max(stop - start for start, stop in chunks) <= size
    for start, stop in chunks:
        (index, low, high), = regions(shape, start, stop)  # one rectangle
        assert (low, high) == (start, stop)
        # ... that is one block of the grid of zarr chunks
        assert all(s.start % b == 0 and s.stop - s.start == min(b, n - s.start)
                   for s, b, n in zip(index, block, shape))


def test_a_row_just_longer_than_a_chunk_is_split_evenly():
    assert block_shape((10, 1001), 1000) == (1, 501)


def test_zarr_holds_the_netcdf_data_whatever_the_chunking_and_the_workers(tmp_path,
                                                                          assert_cf_labelled):
    sweep = spec.parse(DEFINITION, "three_axes.toml")
    run_sweep(sweep, tmp_path / "whole.nc", Executor(workers=0), progress=False)
    run_sweep(sweep, tmp_path / "small.zarr", Executor(workers=0), chunk_size=3,
              progress=False)
    with Executor(workers=2) as executor:
        summary = run_sweep(sweep, tmp_path / "cluster.zarr", executor, chunk_size=16,
                            progress=False)
    assert summary.status_counts["converged"] == 24 and "LocalCluster" in summary.scheduler
    for name in ("small.zarr", "cluster.zarr"):
        result = assert_same_result(tmp_path / "whole.nc", tmp_path / name)
    stored = zarr.open_group(tmp_path / "cluster.zarr", mode="r")
    assert stored["roller_load"].chunks == (2, 4, 2, 14)  # 16 points, with every roller
    assert_cf_labelled(result)
    assert not list(tmp_path.glob("*.parts")) and not list(tmp_path.glob(".*"))


def test_the_output_table_stores_alike_in_both_formats(tmp_path):
    sweep = spec.parse(DEFINITION + '[output]\nencoding = "float32"\ncompression = "zstd:5"\n',
                       "float32.toml")
    run_sweep(sweep, tmp_path / "f.nc", Executor(workers=0), progress=False)
    run_sweep(sweep, tmp_path / "f.zarr", Executor(workers=0), chunk_size=5, progress=False)
    result = assert_same_result(tmp_path / "f.nc", tmp_path / "f.zarr")
    assert result.radial_stiffness.encoding["dtype"] == np.float32
    stored = json.loads((tmp_path / "f.zarr" / "radial_stiffness" / ".zarray").read_text())
    assert (stored["compressor"]["id"], stored["compressor"]["level"]) == ("zstd", 5)


def interrupted_store(monkeypatch, sweep, output, computed: list):
    """Run ``sweep`` into the store ``output`` in chunks of 3 points, interrupted when 3 are
    computed (their sizes in ``computed``); its parts folder."""
    import bearing_sweep.evaluate as evaluate

    original = evaluate.evaluate_chunk

    def interrupted(grid, start, stop):
        if len(computed) == 3:
            raise KeyboardInterrupt
        computed.append(stop - start)
        return original(grid, start, stop)

    with monkeypatch.context() as patched, pytest.raises(KeyboardInterrupt):
        patched.setattr(evaluate, "evaluate_chunk", interrupted)
        run_sweep(sweep, output, Executor(workers=0), chunk_size=3, progress=False)
    return Path(f"{output}.parts")


def test_an_interrupted_zarr_run_resumes_with_only_what_is_missing(tmp_path, monkeypatch):
    sweep = spec.parse(DEFINITION, "three_axes.toml")
    output = tmp_path / "out.zarr"
    import bearing_sweep.evaluate as evaluate

    original = evaluate.evaluate_chunk
    computed = []
    parts = interrupted_store(monkeypatch, sweep, output, computed)
    assert not output.exists() and (parts / "store.zarr").is_dir()
    assert len(list(parts.glob("chunk-*.npz"))) == 3

    damaged = sorted(parts.glob("chunk-*.npz"))[-1]
    damaged.write_bytes(damaged.read_bytes()[:40])  # cut short by a power loss: computed again
    computed.clear()
    messages = []
    monkeypatch.setattr(evaluate, "evaluate_chunk", lambda grid, start, stop: (
        computed.append(stop - start), original(grid, start, stop))[1])
    summary = run_sweep(sweep, output, Executor(workers=0), chunk_size=99, progress=False,
                        log=messages.append)  # the interrupted run's chunking is kept
    assert messages == [f"unreadable part {damaged.name} (incomplete) in {parts}: computing it "
                        "again", f"resuming: 2 chunks already computed in {parts}"]
    assert sum(computed) == 24 - 2 * 2 and set(computed) == {2}
    assert summary.status_counts["converged"] == 24 and not parts.exists()
    run_sweep(sweep, tmp_path / "whole.nc", Executor(workers=0), progress=False)
    assert_same_result(tmp_path / "whole.nc", output)


def test_a_store_s_parts_keep_the_store_and_lose_what_is_not_theirs(tmp_path, monkeypatch):
    sweep = spec.parse(DEFINITION, "three_axes.toml")
    output = tmp_path / "out.zarr"
    parts = interrupted_store(monkeypatch, sweep, output, [])
    (parts / "chunk-abc.npz").write_bytes(b"not a mark")
    (parts / "notes.txt").write_text("a note")
    messages = []
    run_sweep(sweep, output, Executor(workers=0), progress=False, log=messages.append)
    assert messages == [f"a file that is no part of this run, chunk-abc.npz and 1 more in "
                        f"{parts}: removed them", f"resuming: 3 chunks already computed in "
                        f"{parts}"]
    run_sweep(sweep, tmp_path / "whole.nc", Executor(workers=0), progress=False)
    assert_same_result(tmp_path / "whole.nc", output)
    # a damaged manifest: the folder, its store with it, is discarded
    again = interrupted_store(monkeypatch, sweep, tmp_path / "again.zarr", [])
    (again / "manifest.json").write_text('{"chunk_size": 0}')
    messages.clear()
    run_sweep(sweep, tmp_path / "again.zarr", Executor(workers=0), progress=False,
              log=messages.append)
    assert messages == ["a manifest whose chunk_size is 0, not a positive integer in "
                        f"{again}: discarding the folder and its 3 finished chunks"]
    assert_same_result(tmp_path / "whole.nc", tmp_path / "again.zarr")


def resumed(tmp_path, sweep, output) -> list:
    """Run ``sweep`` into ``output`` again, check that it gives the uninterrupted result, and
    return what it said."""
    messages = []
    summary = run_sweep(sweep, output, Executor(workers=0), progress=False, log=messages.append)
    assert summary.status_counts["converged"] == summary.points
    run_sweep(sweep, tmp_path / "whole.nc", Executor(workers=0), progress=False)
    assert_same_result(tmp_path / "whole.nc", output)
    return messages


def test_a_mark_that_is_not_its_chunks_is_computed_again(tmp_path, monkeypatch):
    # A mark says its chunk's values are in the store: one copied under another chunk's name
    # would leave that chunk's fill values in the store under counts of "converged".
    sweep = spec.parse(DEFINITION, "three_axes.toml")
    parts = interrupted_store(monkeypatch, sweep, tmp_path / "out.zarr", [])
    first, *_ = marks = sorted(parts.glob("chunk-*.npz"))
    copied = parts / "chunk-000000000010-000000000012.npz"
    assert copied not in marks
    copied.write_bytes(first.read_bytes())
    assert resumed(tmp_path, sweep, tmp_path / "out.zarr") == [
        f"a part that does not hold what its name says, {copied.name} (it holds points 0..1) "
        f"in {parts}: computing it again", f"resuming: 3 chunks already computed in {parts}"]


def test_marks_without_their_store_are_computed_again(tmp_path, monkeypatch):
    sweep = spec.parse(DEFINITION, "three_axes.toml")
    parts = interrupted_store(monkeypatch, sweep, tmp_path / "out.zarr", [])
    shutil.rmtree(parts / "store.zarr")
    assert resumed(tmp_path, sweep, tmp_path / "out.zarr") == [
        "a part that does not hold what its name says, chunk-000000000000-000000000002.npz (no "
        f"store beside it) and 2 more in {parts}: computing them again"]


def test_values_of_another_version_are_never_written(tmp_path, monkeypatch):
    sweep = spec.parse(DEFINITION, "three_axes.toml")
    import bearing_sweep.evaluate as evaluate

    original = evaluate.evaluate_chunk

    def elsewhere(grid, start, stop):  # a worker with another installation
        return original(grid, start, stop) | {"versions": {"package": "0.0.1", "model": "1"}}

    monkeypatch.setattr(evaluate, "evaluate_chunk", elsewhere)
    with pytest.raises(WorkerMismatch, match="runs bearing-sweep 0.0.1"):
        run_sweep(sweep, tmp_path / "out.zarr", Executor(workers=0), progress=False)
    written = tmp_path / "out.zarr.parts" / "store.zarr"
    for output in Grid.from_sweep(sweep).model.outputs:
        assert sorted(p.name for p in (written / output.name).iterdir()) == [".zarray",
                                                                             ".zattrs"]
    assert not list((tmp_path / "out.zarr.parts").glob("chunk-*"))


def test_the_command_and_the_api_write_a_store(tmp_path, capsys):
    definition = tmp_path / "d.toml"
    definition.write_text(DEFINITION)
    output = tmp_path / "out.zarr"
    assert cli.main(["run", str(definition), "-o", str(output), "--workers", "0",
                     "--quiet"]) == 0
    assert f"-> {output}" in capsys.readouterr().out
    by_command = stores.open_result(output)
    assert by_command.status.shape == (3, 4, 2)
    with bearing_sweep.run(definition, output=tmp_path / "api.zarr", workers=0,
                           progress=False) as by_api:  # returned opened from the store
        xr.testing.assert_identical(without_provenance(by_api.load()),
                                    without_provenance(by_command))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["api.zarr", "d.toml", "out.zarr"]


def test_a_store_open_in_a_reader_is_never_replaced_under_it(tmp_path, monkeypatch, refused):
    # A reader reads a store's chunks by their paths when it needs them, and a chunk that
    # is not there as the fill value (NaN, and "converged" for status): replaced by any
    # means, the store would give the reader the new run's values (or fill values) under
    # the coordinates it read from the old one.
    definition = tmp_path / "def.toml"
    definition.write_text(DEFINITION)
    output = tmp_path / "r.zarr"
    run_sweep(spec.load(definition), output, Executor(workers=0), progress=False)
    reader = xr.open_dataset(output, engine="zarr")
    expected = stores.open_result(output)
    monkeypatch.setattr("bearing_sweep.evaluate.evaluate_chunk", None)  # refused before it
    definition.write_text(DEFINITION.replace('stop = "6 kN"', 'stop = "9 kN"'))
    err = refused(output, definition)
    assert "holds an earlier zarr store of bearing-sweep, which is never replaced" in err
    assert "remove it first (close its readers, then rm -r it) or choose another output" in err
    xr.testing.assert_identical(reader.load(), expected)  # coordinates and values of one run
    reader.close()
    with pytest.raises(spec.SpecError, match="never replaced"):
        bearing_sweep.run(definition, output=output, workers=0, progress=False)


def test_a_folder_that_is_not_our_store_is_refused(tmp_path, no_computing, refused):
    folder = tmp_path / "data.zarr"
    folder.mkdir()
    (folder / "notes.txt").write_text("someone's data")
    err = refused(folder)
    assert "data.zarr: exists and is not a zarr store written by bearing-sweep (no zarr " \
           "group of format 2 in it)" in err
    other = tmp_path / "other.zarr"
    xr.Dataset({"x": ("t", [1.0])}, attrs={"source": "another program"}).to_zarr(
        other, zarr_format=2)
    err = refused(other)
    assert "its attributes do not name bearing-sweep" in err


def test_outputs_on_fewer_axes_are_the_files_and_a_wrong_declaration_stops(toy,
                                                                            tmp_path):
    # Chunks of one point: each cell's value comes from its first held point, a later chunk
    # where the first row fails, as in the netCDF file.
    sweep = spec.parse(toy)
    run_sweep(sweep, tmp_path / "toy.nc", Executor(workers=0), chunk_size=1, progress=False)
    run_sweep(sweep, tmp_path / "toy.zarr", Executor(workers=0), chunk_size=1, progress=False)
    assert assert_same_result(tmp_path / "toy.nc", tmp_path / "toy.zarr")["product"].dims == (
        "b",)
    lying = spec.parse(toy.replace('"toy"', '"liar"'))
    with pytest.raises(InconsistentOutput, match="output 'product': declared to depend on b, c "
                                                 "only"):
        run_sweep(lying, tmp_path / "liar.zarr", Executor(workers=0), progress=False)
    assert not (tmp_path / "liar.zarr").exists()


def test_analyze_and_plot_take_a_store(tmp_path, capsys, saved_figures):
    definition = tmp_path / "sampled.toml"
    definition.write_text(DEFINITION.split("[axes]")[0] + '[axes]\nspeed = ["0 rpm"]\n'
                          '[sample]\nmethod = "random"\nn = 4\nseed = 1\nradial_load = '
                          '{ distribution = "uniform", low = "2 kN", high = "6 kN" }\n')
    result = tmp_path / "sampled.zarr"
    assert cli.main(["run", str(definition), "-o", str(result), "--workers", "0",
                     "--quiet"]) == 0
    assert cli.main(["analyze", str(result)]) == 0
    assert stores.open_result(tmp_path / "sampled_analysis.nc").attrs["sample_size"] == 4
    assert cli.main(["plot", str(result), "radial_stiffness"]) == 0
    assert (tmp_path / "sampled.png").is_file()  # beside the store
    [figure] = saved_figures
    [axis] = figure.axes
    [points] = [line for line in axis.lines  # not the marks of failed points
                if line.get_label() not in ("_out of validity", "_no value")]
    with xr.open_zarr(result) as stored:  # read apart from the plotting code
        # a point per sample against the drawn load, in the units the labels name
        for drawn, variable, label in ((points.get_xdata(), stored.radial_load,
                                        axis.get_xlabel()),
                                       (points.get_ydata(), stored.radial_stiffness,
                                        axis.get_ylabel())):
            shown = cf_units.Unit(label.rsplit("[", 1)[1].rstrip("]"))
            np.testing.assert_allclose(drawn, cf_units.Unit(variable.attrs["units"]).convert(
                variable.squeeze(drop=True).values, shown))


def test_a_store_is_named_by_its_suffix_in_any_case():
    assert is_zarr("runs/result.zarr") and is_zarr("runs/Result.ZARR")
    assert not is_zarr("runs/result.zarr.nc") and not is_zarr("runs/zarr") and not is_zarr(None)
