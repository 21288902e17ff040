"""The engine: chunking and worker-count invariance, failures flagged, netCDF round trip."""
import numpy as np
import pytest
import xarray as xr

import bearing_sweep.models.registry as registry
from bearing_sweep.models.registry import MODEL_ERROR
from bearing_sweep import spec, stores
from bearing_sweep.stores import structure
from bearing_sweep.stores.netcdf import write_netcdf
from bearing_sweep.compute import Executor, Summary, run_sweep
from bearing_sweep.executor import CHUNKS_IN_FLIGHT
from bearing_sweep.grid import Grid

TEXT = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
title = "invariance"
[fixed]
crown = "4 um"
speed = "6000 rpm"
[axes]
radial_load = { start = "4 kN", stop = "12 kN", num = 9 }  # slices enough for the crown
clearance = ["0 mm", "0.02 mm", "0.05 mm"]
slices = [30, 60]
[axes.arrangement]
labels = ["uniform", "paper"]
slice_law = ["uniform", "paper"]
"""


def compute(tmp_path, name, executor=None, chunk_size=None):
    path = tmp_path / f"{name}.nc"
    summary = run_sweep(spec.parse(TEXT, "inv.toml"), path, executor or Executor(workers=0),
                        chunk_size, progress=False)
    return summary, stores.open_result(path)


def assert_same_numbers(a: xr.Dataset, b: xr.Dataset):
    for name in a.data_vars:
        np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)


def test_results_do_not_depend_on_chunking(tmp_path):
    _, whole = compute(tmp_path, "whole", chunk_size=10_000)
    for size in (1, 7, 50):
        _, chunked = compute(tmp_path, f"chunk{size}", chunk_size=size)
        assert_same_numbers(whole, chunked)
    assert (whole.status == 0).all()


@pytest.mark.slow
def test_results_do_not_depend_on_the_number_of_workers(tmp_path):
    _, alone = compute(tmp_path, "alone")
    for workers in (1, 2):
        with Executor(workers=workers) as executor:
            summary, clustered = compute(tmp_path, f"w{workers}", executor, chunk_size=13)
        assert f"{workers} single-threaded worker" in summary.scheduler
        assert_same_numbers(alone, clustered)


def test_netcdf_round_trip_keeps_values_and_attributes(tmp_path):
    summary, data = compute(tmp_path, "trip")
    assert summary.points == 9 * 3 * 2 * 2 and summary.status_counts["converged"] == 108
    for name, variable in {**data.data_vars, **data.coords}.items():
        assert "long_name" in variable.attrs, name
        # strings and flags need no units; everything else has them
        assert ("units" in variable.attrs) == (variable.dtype.kind not in "OUS"
                                               and name != "status"), name
    assert data.radial_stiffness.attrs["units"] == "N/mm"
    assert data.roller_load.dims == ("radial_load", "clearance", "slices", "arrangement", "roller")
    assert data.status.attrs["flag_meanings"] == ("converged not_converged infeasible model_error "
                                                  "out_of_validity no_root_in_range")
    # CF bit fields (3.5): an outcome in bits 0, 1 and 3, out of validity in bit 2
    np.testing.assert_array_equal(data.status.attrs["flag_values"], [0, 1, 2, 3, 4, 8])
    np.testing.assert_array_equal(data.status.attrs["flag_masks"], [11, 11, 11, 11, 4, 11])
    assert data.attrs["Conventions"].startswith("CF-")
    assert data.attrs["definition"] == TEXT
    assert data.attrs["definition_sha256"] == spec.parse(TEXT).sha256
    assert data.attrs["model"] == "crb_radial" and data.attrs["title"] == "invariance"
    assert data.attrs["scheduler"] == "in-process"
    assert data.radial_load.attrs["units"] == "N" and data.radial_load.attrs["written_units"] == "kN"
    assert data.clearance.values.tolist() == [0, 0.02, 0.05]
    assert data.speed.attrs["units"] == "rpm" and float(data.speed) == 6000
    assert "speed" not in data.coords  # a fixed input: kept, but not in every plot's title
    again = tmp_path / "again.nc"
    write_netcdf(data, again)
    xr.testing.assert_identical(stores.open_result(again), data)


def test_atomic_write_leaves_the_previous_file_intact_on_failure(tmp_path, monkeypatch):
    path = tmp_path / "result.nc"
    _, data = compute(tmp_path, "result")
    before = path.read_bytes()

    def broken(self, target, **kwargs):
        open(target, "wb").write(b"half")
        raise OSError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", broken)
    with pytest.raises(OSError):
        write_netcdf(data, path)
    assert path.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir()] == ["result.nc"]


def test_a_model_exception_marks_its_points_and_the_rest_completes(tmp_path,
                                                                   paper_slice_law_fails):
    summary, data = compute(tmp_path, "fragile")
    failed = data.status.sel(arrangement="paper")
    assert (failed == MODEL_ERROR).all() and (data.status.sel(arrangement="uniform") == 0).all()
    assert data.radial_stiffness.sel(arrangement="paper").isnull().all()
    assert summary.status_counts["model_error"] == 54
    assert "RuntimeError: simulated failure" in summary.text()
    assert "simulated failure" in data.attrs["model_errors"]


def test_summary_reads_well():
    summary = Summary("crb_radial", 10, {"converged": 8, "not_converged": 2}, 1.234, "out.nc",
                      "in-process")
    assert summary.text() == ("crb_radial: 10 points (8 converged, 2 not_converged) in 1.2 s "
                              "on in-process -> out.nc")


class Clock:
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


def test_progress_appears_only_after_a_moment(monkeypatch):
    import io

    import bearing_sweep.compute as compute

    clock = Clock()
    monkeypatch.setattr(compute.time, "monotonic", clock)
    stream = io.StringIO()
    bar = compute.Progress(100, "crb_radial", stream=stream)
    bar.advance(10)
    assert stream.getvalue() == ""  # a quick run shows nothing
    clock.now = 2.0
    bar.advance(40)
    clock.now = 30.0
    bar.advance(50)
    bar.close()
    lines = stream.getvalue().splitlines()
    assert lines[0].startswith("crb_radial [###############               ] 50/100 points 2 s")
    assert lines[-1].startswith("crb_radial [##############################] 100/100 points 30 s")


def test_in_a_notebook_the_bar_is_redrawn_in_place(monkeypatch):
    import io

    import bearing_sweep.compute as compute

    class KernelStream(io.StringIO):  # what ipykernel gives a notebook as sys.stderr
        __module__ = "ipykernel.iostream"

        def isatty(self):
            return False

    clock = Clock()
    monkeypatch.setattr(compute.time, "monotonic", clock)
    stream = KernelStream()
    bar = compute.Progress(100, "crb_radial", stream=stream)
    for now in (1.0, 1.2, 1.8, 2.5):  # every half second at most, not every 10 s
        clock.now = now
        bar.advance(10)
    bar.close()
    assert stream.getvalue() == (  # 1.2 s is too soon after 1.0 s
        "\rcrb_radial [###                           ] 10/100 points 1 s"
        "\rcrb_radial [#########                     ] 30/100 points 2 s"
        "\rcrb_radial [############                  ] 40/100 points 2 s\n")
    plain = io.StringIO()  # a file or a pipe: a line every 10 s, as before
    clock.now = 0.0
    bar = compute.Progress(100, "crb_radial", stream=plain)
    for now in (1.0, 1.2, 1.8, 2.5):
        clock.now = now
        bar.advance(10)
    bar.close()
    assert plain.getvalue() == "crb_radial [###                           ] 10/100 points 1 s\n"


def test_points_out_of_validity_keep_their_values_and_failures_are_nan(tmp_path, monkeypatch):
    model = registry.get_model("crb_radial")
    original = model.function

    def judged(**kwargs):
        result = original(**kwargs)
        heavy = np.asarray(kwargs["radial_load"]) > 6e3
        code = registry.OUT_OF_VALIDITY if kwargs["slice_law"] == "paper" \
            else registry.NOT_CONVERGED
        result["status"] = np.where(heavy, code, result["status"]).astype(np.int8)
        return result

    monkeypatch.setitem(registry._MODELS, "crb_radial",
                        registry.Model(**{**model.__dict__, "function": judged}))
    summary, data = compute(tmp_path, "judged")
    heavy = data.radial_load > 6000
    kept = data.radial_stiffness.sel(arrangement="paper").where(heavy)
    assert (data.status.sel(arrangement="paper").where(heavy, -1) != registry.CONVERGED).all()
    assert np.isfinite(kept.values[np.broadcast_to(heavy.values[:, None, None],
                                                   kept.shape)]).all()
    assert data.radial_stiffness.sel(arrangement="uniform").where(heavy).isnull().all()
    assert summary.status_counts["out_of_validity"] == summary.status_counts["not_converged"] > 0
    assert "out_of_validity" in data.status.attrs["flag_meanings"]


def test_statuses_combine_by_severity():
    from bearing_sweep.models.registry import combine_status as combine

    c, nc, inf, err, oov, nr = (registry.CONVERGED, registry.NOT_CONVERGED, registry.INFEASIBLE,
                                registry.MODEL_ERROR, registry.OUT_OF_VALIDITY,
                                registry.NO_ROOT_IN_RANGE)
    # the most severe outcome; out of validity kept beside any outcome
    assert combine([c, oov, nr, c, inf], [oov, c, oov, nc, nc]).tolist() == [oov, oov, nr | oov,
                                                                              nc, nc]
    assert combine(err, [c, nc, inf, oov, nr]).tolist() == [err, err, err, err | oov, err]
    assert combine([nr | oov, nc], [c, oov]).tolist() == [nr | oov, nc | oov]


def test_files_written_in_different_units_combine_into_one_consistent_axis(tmp_path):
    paths = []
    for name, loads in (("newtons", '["1 N", "12 N"]'), ("kilonewtons", '["13 kN", "14 kN"]')):
        text = TEXT.replace('radial_load = { start = "4 kN", stop = "12 kN", num = 9 }',
                            f"radial_load = {loads}")
        paths.append(tmp_path / f"{name}.nc")
        run_sweep(spec.parse(text, f"{name}.toml"), paths[-1], Executor(workers=0),
                  progress=False)
    with xr.open_mfdataset(paths, combine="nested", concat_dim="radial_load",
                           data_vars="minimal", coords="minimal", compat="override") as both:
        assert both.radial_load.values.tolist() == [1, 12, 13000, 14000]
        assert both.radial_load.attrs["units"] == "N"
        stiffness = both.radial_stiffness.sel(clearance=0.02, slices=30, arrangement="uniform")
        assert (np.diff(stiffness.values) > 0).all()  # stiffer with load across both files


def open_files() -> set:
    """The files this process holds open (Linux)."""
    import os

    found = set()
    for descriptor in os.listdir("/proc/self/fd"):
        try:
            found.add(os.readlink(f"/proc/self/fd/{descriptor}"))
        except OSError:
            continue
    return found


@pytest.mark.skipif(not __import__("os").path.isdir("/proc/self/fd"), reason="needs /proc")
def test_writing_a_result_closes_its_file_and_leaves_the_others(tmp_path):
    # xarray caches the files it opens; a sweep must close its own file through xarray's public
    # interface, not by emptying that cache under the feet of whoever else uses it.
    from xarray.backends.file_manager import FILE_CACHE

    write_netcdf(xr.Dataset({"x": ("i", np.arange(3.0))}), tmp_path / "mine.nc")
    mine = xr.open_dataset(tmp_path / "mine.nc")
    mine.x.values  # read: xarray holds the file open in its cache
    cached = dict(FILE_CACHE)
    assert cached and str(tmp_path / "mine.nc") in open_files()
    compute(tmp_path, "sweep")
    assert all(FILE_CACHE.get(key) is file for key, file in cached.items())
    assert not [f for f in open_files() if "sweep.nc" in f]
    np.testing.assert_array_equal(mine.x.values, [0, 1, 2])
    mine.close()


def test_each_chunk_reports_the_versions_it_was_computed_with():
    from bearing_sweep.grid import Grid
    from bearing_sweep.evaluate import evaluate_chunk

    grid = Grid.from_sweep(spec.parse(TEXT))
    result = evaluate_chunk(grid, 0, 5)
    assert result["versions"] == {"package": structure.package_version(),
                                  "model": registry.get_model("crb_radial").version}


def test_chunks_of_another_version_are_refused_and_the_others_kept(tmp_path, capsys,
                                                                  monkeypatch):
    from bearing_sweep import cli, evaluate

    original = evaluate.evaluate_chunk

    def elsewhere(grid, start, stop):  # as a worker with another installation would answer
        result = original(grid, start, stop)
        if start >= 12:  # the chunks of 8, 4, 8, 4 ... points: two computed here
            result["versions"] = dict(result["versions"], package="0.0.1")
        return result

    monkeypatch.setattr(evaluate, "evaluate_chunk", elsewhere)
    definition = tmp_path / "inv.toml"
    definition.write_text(TEXT)
    output = tmp_path / "out.nc"
    code = cli.main(["run", str(definition), "-o", str(output), "--workers", "0",
                     "--chunk-size", "10", "--quiet"])
    err = capsys.readouterr().err
    assert code == 1 and len(err.strip().splitlines()) == 1, err
    assert "runs bearing-sweep 0.0.1 (model version" in err
    assert f"where this run has bearing-sweep {structure.package_version()} (model version" in err
    assert "2 chunks computed so far are kept" in err
    assert not output.exists()
    assert len(list((tmp_path / "out.nc.parts").glob("chunk-*.npz"))) == 2


def test_each_chunk_is_written_into_the_file_before_the_next_is_computed(tmp_path,
                                                                        monkeypatch):
    # Writing while the others compute keeps the file's assembly out of the sweep's end: the
    # file is complete soon after its last chunk.
    import bearing_sweep.evaluate as evaluate_module
    from bearing_sweep.stores.hdf5_chunks import DirectWriter

    events = []
    evaluate, write = evaluate_module.evaluate_chunk, DirectWriter.write

    def evaluated(grid, start, stop):
        events.append(("computed", start))
        return evaluate(grid, start, stop)

    def written(self, start, stop, part):
        events.append(("written", start))
        return write(self, start, stop, part)

    monkeypatch.setattr(evaluate_module, "evaluate_chunk", evaluated)
    monkeypatch.setattr(DirectWriter, "write", written)
    summary, data = compute(tmp_path, "streamed", chunk_size=36)
    starts = range(0, 108, 36)
    assert events == [(event, start) for start in starts for event in ("computed", "written")]
    _, whole = compute(tmp_path, "whole", chunk_size=10_000)
    assert_same_numbers(whole, data)


@pytest.mark.slow
def test_a_cluster_is_given_a_few_chunks_per_worker_at_a_time():
    """The driver and the scheduler hold a bounded number of tasks, each carrying the grid,
    however many chunks a sweep has: the next chunk is submitted as one finishes."""
    grid = Grid.from_sweep(spec.parse(TEXT, "inv.toml"))
    chunks = grid.chunks(5)
    assert len(chunks) > 2 * CHUNKS_IN_FLIGHT
    with Executor(workers=1) as executor:
        client = executor.connect()
        submitted, received, most = [], [], 0
        submit = client.submit
        client.submit = lambda task, grid, start, *rest, **options: (
            submitted.append(start) or submit(task, grid, start, *rest, **options))
        for start, stop, result in executor.map(grid, chunks, parallel=True):
            received.append(start)
            most = max(most, len(submitted) - len(received))
            assert result["status"].size == stop - start
    assert most == CHUNKS_IN_FLIGHT
    assert sorted(received) == sorted(submitted) == [start for start, _ in chunks]


@pytest.mark.parametrize("code", [16, -1, 10])
def test_a_status_code_the_registry_does_not_define_is_a_model_error(tmp_path, monkeypatch,
                                                                      code):
    # 10 is no_root_in_range with infeasible's bit: no outcome; 16 and -1 no bit field at all.
    model = registry.get_model("crb_radial")
    original = model.function

    def garbled(**kwargs):
        result = original(**kwargs)
        result["status"] = np.full(np.shape(result["status"]), code, dtype=np.int8)
        return result

    monkeypatch.setitem(registry._MODELS, "crb_radial",
                        registry.Model(**{**model.__dict__, "function": garbled}))
    summary, data = compute(tmp_path, "garbled")
    assert (data.status == registry.MODEL_ERROR).all()
    assert data.radial_stiffness.isnull().all()
    assert f"returned status {code}" in data.attrs["model_errors"]


def test_the_summary_counts_outcomes_and_then_the_points_out_of_validity(tmp_path,
                                                                        monkeypatch):
    model = registry.get_model("crb_radial")
    original = model.function

    def judged(**kwargs):  # the heavy points out of validity, their outcomes as they are
        result = original(**kwargs)
        heavy = np.asarray(kwargs["radial_load"]) > 6e3
        result["status"] = registry.combine_status(
            result["status"], np.where(heavy, registry.OUT_OF_VALIDITY, registry.CONVERGED))
        return result

    monkeypatch.setitem(registry._MODELS, "crb_radial",
                        registry.Model(**{**model.__dict__, "function": judged}))
    summary, data = compute(tmp_path, "judged")
    heavy = int((data.radial_load > 6000).sum()) * data.status.size // data.radial_load.size
    assert summary.status_counts["converged"] == data.status.size
    assert summary.status_counts["out_of_validity"] == heavy > 0
    assert f"({data.status.size} converged; {heavy} out_of_validity)" in summary.text()
