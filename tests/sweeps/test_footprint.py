"""What a run says it will take as it starts (the size of its result, its time), and a result
the disk cannot hold refused in one line (exit status 1) before it fills the disk."""
import re
import shutil

import netCDF4
import numpy as np
import pytest

import bearing_sweep
import bearing_sweep.models.registry as registry
from bearing_sweep import cli, spec
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.stores.footprint import InsufficientSpace, result_bytes
from bearing_sweep.grid import Grid

#: 1000 x 1000 x 1000 points; crown, load and clearance vary, so every output but the
#: centrifugal force and the viscosity ratio (on the speed alone: a single value) is stored
#: on every point.
HUGE = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
speed = "5000 rpm"
[axes]
radial_load = { start = "1 kN", stop = "12 kN", num = 1000 }
clearance = { start = "0 mm", stop = "0.04 mm", num = 1000 }
crown = { start = "0 mm", stop = "0.01 mm", num = 1000 }
"""
SMALL = HUGE.replace("num = 1000 }", "num = 3 }")
UNCOMPRESSED = '[output]\ncompression = "none"\n'
FREE = 71e9  # the disk: 71 GB free


def bytes_a_point(tmp_path) -> float:
    """The bytes each point adds to a result stored uncompressed, counted from a small file
    as netCDF4 reads it: the variables on every axis of the grid."""
    path = tmp_path / "small.nc"
    run_sweep(spec.parse(SMALL + UNCOMPRESSED), path, Executor(workers=0), progress=False)
    with netCDF4.Dataset(path) as data:
        grid = data["status"].dimensions
        per_point = [v.size * v.dtype.itemsize / data["status"].size
                     for v in data.variables.values() if v.dimensions[:len(grid)] == grid]
    path.unlink()
    return sum(per_point)


@pytest.fixture
def disk(monkeypatch):
    """The output's filesystem with ``free`` bytes free."""

    def free(count: float):
        usage = shutil.disk_usage(".")
        monkeypatch.setattr("bearing_sweep.stores.footprint.shutil.disk_usage",
                            lambda path: usage._replace(free=int(count)))

    return free


def stated(pattern: str, text: str) -> float:
    """The number ``pattern`` finds in ``text``, scaled by its unit."""
    value, unit = re.search(pattern, text).groups()
    return float(value) * {"kB": 1e3, "MB": 1e6, "GB": 1e9, "TB": 1e12, "h": 3600}[unit]


def test_the_size_before_compression_is_every_value_in_its_stored_type(tmp_path):
    per_point = bytes_a_point(tmp_path)
    assert per_point > 14 * 8  # a load per roller, at least, in float64
    for text, points, axes in ((SMALL, 27, 9), (HUGE, 1e9, 3000)):
        sweep = spec.parse(text + UNCOMPRESSED)
        found = result_bytes(sweep, Grid.from_sweep(sweep))
        # the per-point variables, the axes' coordinates (float64), and a few kB of fixed
        # inputs, labels and the rollers' numbers
        assert 0 <= found - points * per_point - 8 * axes < 5e3
    # float32 halves the float outputs; the integers and status keep their size
    sweep = spec.parse(HUGE + '[output]\nencoding = "float32"\n')
    assert 0.5 < result_bytes(sweep, Grid.from_sweep(sweep)) / (1e9 * per_point) < 0.52


@pytest.mark.parametrize("output, copies", [("huge.nc", 2), ("huge.zarr", 1)])
def test_an_uncompressed_result_larger_than_the_disk_is_refused_before_computing(
        tmp_path, capsys, monkeypatch, disk, output, copies):
    per_point = bytes_a_point(tmp_path)
    (tmp_path / "huge.toml").write_text(HUGE + UNCOMPRESSED)
    disk(FREE)
    monkeypatch.setattr("bearing_sweep.evaluate.evaluate_chunk", None)  # refused before it
    code = cli.main(["run", str(tmp_path / "huge.toml"), "-o", str(tmp_path / output),
                     "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 1 and err.count("\n") == 1 and err.startswith(f"error: {tmp_path / output}"
                                                                  ": needs "), err
    assert stated(r"needs ([\d.]+) (GB|TB) of disk", err) == pytest.approx(
        copies * 1e9 * per_point, rel=5e-3)
    assert f"and {tmp_path} has 71 GB free: free some space" in err
    declared = registry.get_model("crb_radial").seconds_per_point * 1e9
    assert stated(r"about ([\d.]+) (h) of computing", err) == pytest.approx(declared, rel=0.05)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["huge.toml"]  # nothing written
    with pytest.raises(InsufficientSpace, match="71 GB free"):
        bearing_sweep.run(HUGE + UNCOMPRESSED, output=tmp_path / output, workers=0,
                          progress=False)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["huge.toml"]


def test_a_compressed_result_is_refused_once_its_first_chunk_shows_it_cannot_fit(
        tmp_path, capsys, disk):
    # How much zlib saves is known only from the values: the first chunk stored says.
    (tmp_path / "huge.toml").write_text(HUGE)
    disk(FREE)
    code = cli.main(["run", str(tmp_path / "huge.toml"), "-o", str(tmp_path / "huge.nc"),
                     "--workers", "0", "--quiet"])
    err = capsys.readouterr().err
    assert code == 1 and err.count("\n") == 1, err
    kept = list((tmp_path / "huge.nc.parts").glob("chunk-*.npz"))
    assert len(kept) == 1 and "the finished chunk is kept: free some space and run the same " \
                              "command again" in err
    per_point = float(re.search(r"at the ([\d.]+) bytes a point", err)[1])
    assert 0 < per_point < bytes_a_point(tmp_path)  # compressed
    assert stated(r"needs about ([\d.]+) (GB|TB) more", err) == pytest.approx(
        2 * per_point * 1e9, rel=5e-3)  # twice: the file, and its parts until it is complete
    assert sorted(p.name for p in tmp_path.iterdir()) == ["huge.nc.parts", "huge.toml"]


def test_a_long_or_large_run_says_what_it_will_take_unless_quiet(tmp_path, capsys,
                                                                  monkeypatch, disk):
    (tmp_path / "huge.toml").write_text(HUGE)
    disk(1e15)

    def stop(*args):
        raise KeyboardInterrupt

    monkeypatch.setattr("bearing_sweep.evaluate.evaluate_chunk", stop)
    arguments = ["run", str(tmp_path / "huge.toml"), "-o", str(tmp_path / "huge.nc"),
                 "--workers", "0"]
    assert cli.main(arguments) == 130
    said = capsys.readouterr().err.splitlines()[0]
    assert said.startswith("crb_radial: 1000000000 points to compute, about ")
    assert stated(r"about ([\d.]+) (h) on one core", said) == pytest.approx(
        registry.get_model("crb_radial").seconds_per_point * 1e9, rel=0.05)
    assert said.endswith(" (before compression), and its finished chunks as much until it is "
                         f"written; 1 PB free in {tmp_path}")
    assert cli.main(arguments + ["--quiet"]) == 130
    assert "points to compute" not in capsys.readouterr().err
    small = tmp_path / "small.toml"
    small.write_text(SMALL)
    monkeypatch.undo()
    assert cli.main(["run", str(small), "-o", str(tmp_path / "small.nc"), "--workers", "0"]) == 0
    assert capsys.readouterr().err == ""  # a moment's run says nothing before its summary


def interrupted_run(tmp_path, monkeypatch):
    """The arguments of a run of SMALL (27 points, compressed) into ``r.nc`` in chunks of 9,
    interrupted once two are kept; its parts folder."""
    import bearing_sweep.evaluate as evaluate

    (tmp_path / "small.toml").write_text(SMALL)
    arguments = ["run", str(tmp_path / "small.toml"), "-o", str(tmp_path / "r.nc"),
                 "--chunk-size", "9", "--quiet"]
    original, calls = evaluate.evaluate_chunk, []

    def interrupted(grid, start, stop):
        calls.append(start)
        if len(calls) == 3:
            raise KeyboardInterrupt
        return original(grid, start, stop)

    with monkeypatch.context() as patched:
        patched.setattr(evaluate, "evaluate_chunk", interrupted)
        assert cli.main(arguments + ["--workers", "0"]) == 130
    return arguments, tmp_path / "r.nc.parts"


def contents(folder):
    return {path.name: path.read_bytes() for path in sorted(folder.iterdir())}


class OtherVersionClient:
    """A cluster's client whose workers run another bearing-sweep."""

    def run(self, function, *args):
        return {"tcp://10.0.0.1:4000": {"package": "0.0.1", "model": 1}}

    def close(self):
        pass


def refused_by(case, monkeypatch, disk):
    """Make the rerun's ``case`` refuse it; the options the rerun is given."""
    import distributed

    import bearing_sweep.compute as compute

    if case == "a disk too small":
        disk(1e3)  # the uncompressed result: 27 points of about a kilobyte, twice
        return ["--workers", "0"]

    def failing(**kwargs):
        raise OSError("Nanny failed to start")

    monkeypatch.setattr(distributed, "LocalCluster", failing)
    if case == "workers of another version":
        monkeypatch.setattr(compute.Executor, "start", lambda self: None)
        monkeypatch.setattr(compute.Executor, "connect", lambda self: OtherVersionClient())
    return ["--workers", "2"]


@pytest.mark.parametrize("case", ["a disk too small", "a cluster that cannot start",
                                  "workers of another version"])
def test_a_refused_rerun_leaves_the_earlier_runs_parts_as_they_were(tmp_path, capsys,
                                                                   monkeypatch, disk, case):
    # The reproduction: a --compression none rerun refused for lack of space first
    # discarded the earlier (compressed) run's finished chunks.
    arguments, parts = interrupted_run(tmp_path, monkeypatch)
    before = contents(parts)
    assert len([name for name in before if name.startswith("chunk-")]) == 2
    capsys.readouterr()
    with monkeypatch.context() as patched:
        options = refused_by(case, patched, disk)
        assert cli.main(arguments + ["--compression", "none"] + options) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: "), err
    assert "discarding" not in err
    assert contents(parts) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.nc.parts", "small.toml"]
    assert cli.main(arguments + ["--workers", "0"]) == 0  # as before: resumed
    assert capsys.readouterr().err == f"resuming: 2 chunks already computed in {parts}\n"
    whole = tmp_path / "whole.nc"
    run_sweep(spec.parse(SMALL), whole, Executor(workers=0), progress=False)
    for name, values in bearing_sweep.stores.open_result(whole).data_vars.items():
        np.testing.assert_array_equal(
            bearing_sweep.stores.open_result(tmp_path / "r.nc")[name].values, values.values)
