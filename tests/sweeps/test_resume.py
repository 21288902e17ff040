"""Interrupted sweeps resume, a killed worker costs a retry, a busy or broken output is a clear
error that leaves any earlier result intact."""
import errno
import json
import os
import re
import resource
import signal
import subprocess
import sys
import threading
import time
import zlib
from pathlib import Path

import numpy as np
import pytest

from bearing_sweep import cli, spec, stores
from bearing_sweep.stores.netcdf import write_netcdf
from bearing_sweep.stores.durable import OutputBusy, OutputLock
from bearing_sweep.stores.resume import Parts, UnreadablePart
from bearing_sweep.compute import Executor, run_sweep

# About 40 chunks of 0.1 s each in one process: long enough to be killed part-way.
SLOW = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "0.004 mm"
[axes]
radial_load = { start = "1 kN", stop = "12 kN", num = 200 }
clearance = { start = "0 mm", stop = "0.04 mm", num = 200 }
"""


def same_data(first, second):
    for name in first.data_vars:
        np.testing.assert_array_equal(first[name].values, second[name].values)


def wait_for_chunks(parts, count, seconds=120):
    """Until a run has saved ``count`` chunks in ``parts`` (or ``seconds`` passed)."""
    deadline = time.monotonic() + seconds
    while len(list(parts.glob("chunk-*.npz"))) < count and time.monotonic() < deadline:
        time.sleep(0.05)


@pytest.mark.slow
def test_a_killed_run_resumes_where_it_stopped(tmp_path, start_cli):
    (tmp_path / "slow.toml").write_text(SLOW)
    common = ["--workers", "0", "--chunk-size", "1000", "--quiet"]
    first = start_cli("run", "slow.toml", "-o", "out.nc", *common, cwd=tmp_path)
    parts = tmp_path / "out.nc.parts"
    wait_for_chunks(parts, 5)
    first.send_signal(signal.SIGKILL)
    first.wait()
    kept = len(list(parts.glob("chunk-*.npz")))
    assert 5 <= kept < 40 and not (tmp_path / "out.nc").exists()

    second = start_cli("run", "slow.toml", "-o", "out.nc", *common, cwd=tmp_path)
    _, err = second.communicate(timeout=300)
    assert second.returncode == 0, err
    assert re.search(rf"resuming: {kept} chunks? already computed", err)
    assert not parts.exists()
    whole = start_cli("run", "slow.toml", "-o", "whole.nc", *common, cwd=tmp_path)
    whole.communicate(timeout=300)
    same_data(stores.open_result(tmp_path / "out.nc"), stores.open_result(tmp_path / "whole.nc"))


@pytest.mark.slow
@pytest.mark.parametrize("output", ["k.nc", "k.zarr"])
def test_a_killed_run_leaves_nothing_that_the_next_run_does_not_clear(tmp_path, output, start_cli):
    (tmp_path / "slow.toml").write_text(SLOW)
    common = ["--workers", "0", "--chunk-size", "1000", "--quiet"]
    first = start_cli("run", "slow.toml", "-o", output, *common, cwd=tmp_path)
    parts = tmp_path / f"{output}.parts"
    wait_for_chunks(parts, 3)
    first.send_signal(signal.SIGKILL)
    first.wait()
    if output == "k.nc":  # the file being written, beside the output
        assert list(tmp_path.glob(f".k.nc.{first.pid}.tmp"))
    second = start_cli("run", "slow.toml", "-o", output, *common, cwd=tmp_path)
    _, err = second.communicate(timeout=300)
    assert second.returncode == 0, err
    assert sorted(p.name for p in tmp_path.iterdir()) == [output, "slow.toml"]


def test_only_our_stale_temporaries_are_removed(tmp_path, capsys):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    output = tmp_path / "k.nc"
    stale = [tmp_path / ".k.nc.123.tmp", tmp_path / f".k.nc.{os.getpid()}.tmp"]
    others = [tmp_path / name for name in (".k.nc.notes.tmp", ".other.nc.123.tmp",
                                           ".k.nc.123.tmp.bak", "k.nc.123.tmp", ".k.nc.12a.tmp")]
    with OutputLock(output):  # a run writing it: its temporaries are not stale
        for path in stale + others:
            path.write_bytes(b"some bytes")
        (tmp_path / ".k.nc.456.tmp").mkdir()  # a folder: not a file we write
        assert cli.main(["run", str(definition), "-o", str(output), "--workers", "0"]) == 1
        assert all(path.exists() for path in stale)
    assert cli.main(["run", str(definition), "-o", str(output), "--workers", "0"]) == 0
    assert not any(path.exists() for path in stale)
    assert all(path.read_bytes() == b"some bytes" for path in others)
    assert (tmp_path / ".k.nc.456.tmp").is_dir()


def test_writing_an_analysis_removes_its_stale_temporaries_too(tmp_path):
    import xarray as xr

    output = tmp_path / "r_analysis.nc"
    stale = tmp_path / ".r_analysis.nc.99999999.tmp"
    stale.write_bytes(b"half an analysis")
    write_netcdf(xr.Dataset({"x": ("t", [1.0, 2.0])}), output)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r_analysis.nc"]
    with OutputLock(output), pytest.raises(OutputBusy):  # and two writers do not mix
        write_netcdf(xr.Dataset({"x": ("t", [3.0])}), output)


def test_a_changed_definition_discards_old_parts(tmp_path, capsys):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 4"))
    output = tmp_path / "out.nc"
    folder = tmp_path / "out.nc.parts"
    folder.mkdir()
    (folder / "manifest.json").write_text('{"definition_sha256": "old", "model_version": "1", '
                                          '"points": 16, "chunk_size": 4}')
    np.savez(folder / "chunk-000000000000-000000000004.npz", status=np.zeros(4))
    assert cli.main(["run", str(definition), "-o", str(output), "--workers", "0"]) == 0
    assert "the definition, model, package or storage changed: discarding 1 finished chunks" in \
        capsys.readouterr().err
    assert stores.open_result(output).status.size == 16


def test_two_runs_on_one_output_do_not_mix(tmp_path, capsys):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 3"))
    output = tmp_path / "out.nc"
    with OutputLock(output):  # another run holds it
        code = cli.main(["run", str(definition), "-o", str(output), "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 1 and "another bearing-sweep run is writing this output" in err
    assert not output.exists()
    assert cli.main(["run", str(definition), "-o", str(output), "--workers", "0"]) == 0


def test_a_full_disk_leaves_the_earlier_result(tmp_path, capsys, monkeypatch):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 3"))
    output = tmp_path / "out.nc"
    assert cli.main(["run", str(definition), "-o", str(output), "--workers", "0"]) == 0
    before = output.read_bytes()

    def full(*args, **kwargs):  # the disk fills while the values are being written
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(output))

    monkeypatch.setattr("bearing_sweep.stores.blocks.regions", full)
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    code = cli.main(["run", str(definition), "-o", str(output), "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 1 and "No space left on device" in err and "left as it was" in err
    assert output.read_bytes() == before
    assert not list(tmp_path.glob(".out.nc.*.tmp"))


def file_size_limited(limit: int):
    """For a child process: no file of it may grow beyond ``limit`` bytes, writing beyond it
    failing with EFBIG (SIGXFSZ ignored), as a full disk fails the write that meets it."""

    def apply():
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)

    return apply


#: 10 000 points in parts of 1000: each part is written, the whole result is not (netCDF:
#: 1.8 MB compressed, 4.4 MB uncompressed); a zarr chunk of 1000 points uncompressed holds
#: 110 kB of roller loads.
FULL = {"netCDF, compressed": ("out.nc", [], 1_000_000),
        "netCDF, uncompressed": ("out.nc", ["--compression", "none"], 1_000_000),
        "zarr": ("out.zarr", ["--compression", "none"], 50_000)}


@pytest.mark.parametrize("case", [pytest.param(case, marks=[pytest.mark.slow] if i else [])
                                  for i, case in enumerate(FULL)])
def test_a_disk_full_while_writing_is_one_line_and_loses_nothing(tmp_path, case, run_cli):
    output, options, limit = FULL[case]
    (tmp_path / "d.toml").write_text(SLOW.replace("num = 200", "num = 100"))
    common = ["run", "d.toml", "--workers", "0", "--chunk-size", "1000", "--quiet", *options]
    # An earlier result, beside a netCDF output or where it goes (a store is never replaced)
    earlier = run_cli(*common, "-o", "out.nc" if output == "out.zarr" else output, "--fresh",
                      cwd=tmp_path, timeout=300)
    assert earlier.returncode == 0, earlier.stderr
    before = {p.name: p.read_bytes() for p in tmp_path.glob("out.nc")}
    full = run_cli(*common, "-o", output, cwd=tmp_path, timeout=300,
                   preexec_fn=file_size_limited(limit))
    assert full.returncode == 1, full.stderr
    assert full.stderr == (f"error: {output}: File too large; any earlier result is left as it "
                           "was\n")
    assert {p.name: p.read_bytes() for p in tmp_path.glob("out.nc")} == before
    assert not (tmp_path / output).exists() or output == "out.nc"
    assert not list(tmp_path.glob(".*.tmp"))  # the temporary file is removed
    kept = list((tmp_path / f"{output}.parts").glob("chunk-*.npz"))
    # The chunks computed are kept, nothing is lost (a store's first chunk is too large to
    # write: none is finished)
    assert kept or output == "out.zarr"
    again = run_cli(*common, "-o", output, cwd=tmp_path, timeout=300)
    assert again.returncode == 0, again.stderr
    assert not kept or re.search(rf"resuming: {len(kept)} chunks? already computed",
                                 again.stderr)
    whole = run_cli(*common, "-o", "whole.nc", cwd=tmp_path, timeout=300)
    assert whole.returncode == 0, whole.stderr
    same_data(stores.open_result(tmp_path / output), stores.open_result(tmp_path / "whole.nc"))


def test_a_writer_that_cannot_close_after_a_failure_does_not_hide_it(tmp_path):
    # HDF5 flushes a file as it closes it: on a full disk the close fails too, and used to
    # raise its own error ("Can't decrement id ref count") over the one that said why.
    from bearing_sweep.stores.durable import closed_after

    class Unclosable:
        def close(self):
            raise RuntimeError("Can't decrement id ref count (unable to extend file properly, "
                               "errno = 28, error message = 'No space left on device')")

    with pytest.raises(OSError, match="first failure"):
        with closed_after(Unclosable(), tmp_path / "out.nc"):
            raise OSError(errno.ENOSPC, "first failure")
    with pytest.raises(KeyboardInterrupt):
        with closed_after(Unclosable(), tmp_path / "out.nc"):
            raise KeyboardInterrupt
    with pytest.raises(OSError) as failed:  # alone, its failure names the file and the errno
        with closed_after(Unclosable(), tmp_path / "out.nc"):
            pass
    assert (failed.value.errno, failed.value.strerror, failed.value.filename) == (
        errno.ENOSPC, os.strerror(errno.ENOSPC), str(tmp_path / "out.nc"))


def test_an_unwritable_folder_is_one_line(tmp_path, capsys):
    if os.geteuid() == 0:
        pytest.skip("root writes anywhere")
    folder = tmp_path / "locked"
    folder.mkdir()
    folder.chmod(0o500)
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    code = cli.main(["run", str(definition), "-o", str(folder / "out.nc"), "--workers", "0"])
    assert code == 2 and "permission denied" in capsys.readouterr().err


@pytest.mark.slow
def test_a_killed_worker_costs_only_a_retry(tmp_path):
    sweep = spec.parse(SLOW)
    reference = run_sweep(sweep, tmp_path / "reference.nc", Executor(workers=0),
                          chunk_size=1000, progress=False)
    with Executor(workers=2) as executor:
        client = executor.connect()
        victim = list(client.run(os.getpid).values())[0]
        killer = threading.Timer(0.5, os.kill, (victim, signal.SIGKILL))
        killer.start()
        began = time.monotonic()
        summary = run_sweep(sweep, tmp_path / "killed.nc", executor, chunk_size=1000,
                            progress=False)
        killer.join()
        assert time.monotonic() - began > 0.5  # the worker died while the sweep ran
        assert victim not in client.run(os.getpid).values()  # and was replaced
    assert summary.points == reference.points == 40000
    assert summary.status_counts == reference.status_counts
    same_data(stores.open_result(tmp_path / "reference.nc"),
              stores.open_result(tmp_path / "killed.nc"))


def test_an_output_that_cannot_be_a_file_is_one_line(tmp_path, capsys, monkeypatch):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    occupied = tmp_path / "out.nc"
    occupied.mkdir()  # a folder where the file should go

    def computed(*args):
        raise AssertionError("computed before the output was refused")

    monkeypatch.setattr("bearing_sweep.evaluate.evaluate_chunk", computed)
    code = cli.main(["run", str(definition), "-o", str(occupied), "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert occupied.is_dir() and not any(occupied.iterdir())


def test_a_part_emptied_by_a_power_loss_is_computed_again(tmp_path, capsys, monkeypatch):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 20"))
    output = tmp_path / "out.nc"
    arguments = ["run", str(definition), "-o", str(output), "--workers", "0",
                 "--chunk-size", "100", "--quiet"]

    def power_loss(*args):  # every chunk is computed, the file not yet written
        raise KeyboardInterrupt

    monkeypatch.setattr("bearing_sweep.stores.netcdf.ChunkWriter.finish", power_loss)
    assert cli.main(arguments) == 130
    monkeypatch.undo()
    kept = sorted((tmp_path / "out.nc.parts").glob("chunk-*.npz"))
    assert len(kept) == 4
    kept[1].write_bytes(b"")  # renamed, but its bytes never reached the disk
    capsys.readouterr()
    assert cli.main(arguments) == 0
    err = capsys.readouterr().err
    said = [line for line in err.splitlines() if "unreadable" in line]
    assert len(said) == 1 and "chunk-000000000100-000000000200.npz" in said[0]
    assert said[0].endswith("computing it again")
    assert "resuming: 3 chunks already computed" in err
    whole = tmp_path / "whole.nc"
    assert cli.main(["run", str(definition), "-o", str(whole), "--workers", "0"]) == 0
    same_data(stores.open_result(output), stores.open_result(whole))


def interrupted_parts(tmp_path, monkeypatch, capsys):
    """The CLI's arguments of a run of 400 points in 4 chunks, interrupted once every chunk is
    computed, and its parts folder; and the file of the same run uninterrupted."""
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 20"))
    arguments = ["run", str(definition), "-o", str(tmp_path / "out.nc"), "--workers", "0",
                 "--chunk-size", "100", "--quiet"]
    whole = tmp_path / "whole.nc"
    assert cli.main(arguments[:3] + [str(whole)] + arguments[4:]) == 0

    def interrupted(*args):  # every chunk is computed, the file not yet written
        raise KeyboardInterrupt

    with monkeypatch.context() as patched:
        patched.setattr("bearing_sweep.stores.netcdf.ChunkWriter.finish", interrupted)
        assert cli.main(arguments) == 130
    capsys.readouterr()
    parts = tmp_path / "out.nc.parts"
    assert len(list(parts.glob("chunk-*.npz"))) == 4
    return arguments, parts, whole


#: Manifests that no version of the program writes, and what the line says of each.
DAMAGED_MANIFESTS = {
    "a list": (lambda found: [1, 2], "a manifest holding an array, not an object"),
    "chunk_size 0": (lambda found: found | {"chunk_size": 0},
                     "a manifest whose chunk_size is 0, not a positive integer"),
    "chunk_size negative": (lambda found: found | {"chunk_size": -100}, "chunk_size is -100"),
    "chunk_size a string": (lambda found: found | {"chunk_size": "100"}, "chunk_size is '100'"),
    "chunk_size a float": (lambda found: found | {"chunk_size": 100.0}, "chunk_size is 100.0"),
    "chunk_size true": (lambda found: found | {"chunk_size": True}, "chunk_size is True"),
    "no chunk_size": (lambda found: {k: v for k, v in found.items() if k != "chunk_size"},
                      "chunk_size is None"),
    "an empty object": (lambda found: {}, "chunk_size is None"),
    "a number": (lambda found: 100, "a manifest holding a number, not an object"),
    "null": (lambda found: None, "a manifest holding null, not an object"),
    "a string": (lambda found: "manifest", "a manifest holding a string, not an object"),
    "a key of its own": (lambda found: found | {"notes": "mine"},
                         "a manifest with keys this version of bearing-sweep does not write"),
    "no definition": (lambda found: {"chunk_size": 100},
                      "a manifest with keys this version of bearing-sweep does not write"),
    "not JSON": ("{chunk_size: 100", "no readable manifest"),
    "missing": (None, "no readable manifest"),
}


@pytest.mark.parametrize("case", DAMAGED_MANIFESTS)
def test_a_damaged_manifest_discards_the_parts_with_a_line(tmp_path, monkeypatch, capsys, case):
    arguments, parts, whole = interrupted_parts(tmp_path, monkeypatch, capsys)
    manifest = parts / "manifest.json"
    damage, said = DAMAGED_MANIFESTS[case]
    if damage is None:
        manifest.unlink()
    elif isinstance(damage, str):
        manifest.write_text(damage)
    else:
        manifest.write_text(json.dumps(damage(json.loads(manifest.read_text()))))
    assert cli.main(arguments) == 0
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and said in err, err
    assert err.endswith(f" in {parts}: discarding the folder and its 4 finished chunks\n")
    assert not parts.exists()
    same_data(stores.open_result(tmp_path / "out.nc"), stores.open_result(whole))


def test_files_that_are_no_part_of_the_run_are_removed_with_a_line(tmp_path, monkeypatch,
                                                                   capsys):
    arguments, parts, whole = interrupted_parts(tmp_path, monkeypatch, capsys)
    kept = sorted(p.name for p in parts.iterdir())
    np.savez(parts / "chunk-abc.npz", status=np.zeros(4))  # no chunk's name
    np.savez(parts / "chunk-000000000000-000000000050.npz", status=np.zeros(50))  # not a chunk
    np.savez(parts / "chunk-000000000100-000000000100.npz", status=np.zeros(0))  # empty
    (parts / "notes.txt").write_text("a note")
    (parts / "chunk-000000000400-000000000500.npz").mkdir()  # beyond the grid, a folder
    (parts / ".chunk-000000000000-000000000100.npz.1234.tmp").write_bytes(b"half")  # ours
    assert cli.main(arguments) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == [f"a file that is no part of this run, chunk-000000000000-000000000050.npz "
                   f"and 4 more in {parts}: removed them",
                   f"resuming: 4 chunks already computed in {parts}"]
    assert kept == ["chunk-000000000000-000000000100.npz", "chunk-000000000100-000000000200.npz",
                    "chunk-000000000200-000000000300.npz", "chunk-000000000300-000000000400.npz",
                    "manifest.json"]
    assert not parts.exists()
    same_data(stores.open_result(tmp_path / "out.nc"), stores.open_result(whole))


def rewritten(path, change):
    """The part file at ``path`` rewritten with ``change(arrays)`` made to its arrays."""
    with np.load(path) as data:
        arrays = {key: data[key] for key in data.files}
    change(arrays)
    with open(path, "wb") as handle:
        np.savez(handle, **arrays)


def recounted(change):
    """A change of a part's counts (its ``tally``, as JSON)."""
    def changed(arrays):
        tally = json.loads(str(arrays["tally"]))
        change(tally)
        arrays["tally"] = np.array(json.dumps(tally))
    return changed


def moved(tally, code, other, count):
    """``count`` points of a tally's ``code`` counted as ``other`` instead."""
    tally["status"][code] -= count
    tally["status"][other] += count


#: What a part of points 100..199 may say of itself that it is not (on the grid of 20 x 20
#: points in chunks of 100: 5 rows), and the reason the run gives.
FALSE_PARTS = {
    "a copy of another chunk's": (None, "it holds points 0..99"),
    "no range (an earlier version's)": (lambda a: a.pop("bounds"), "no range recorded in it"),
    "counts of another size": (recounted(lambda t: t["status"].__setitem__(0, 150)),
                               "counts of 150 points, not 100"),
    "a status no registry defines": (recounted(lambda t: moved(t, 0, 9, 100)),
                                     "status 9, not a code of the registry"),
    "counts that are not its statuses": (recounted(lambda t: moved(t, 0, 1, 1)),
                                         "counts that are not those of its statuses"),
    "statuses of the fill value": (
        lambda a: a.__setitem__("chunk_status", np.frombuffer(
            zlib.compress(np.full(100, -127, np.int8).tobytes(), 1), np.uint8)),
        "status -127, not a code of the registry"),
    "an output's chunk missing": (
        lambda a: (a.pop("chunk_radial_stiffness"), a.pop("offset_radial_stiffness")),
        "chunks of ["),
    "a chunk at another block": (lambda a: a.__setitem__("offset_status", np.array([0])),
                                 "its chunk of status at (0,), not at the block of its points"),
}


@pytest.mark.parametrize("case", FALSE_PARTS)
def test_a_part_that_is_not_what_its_name_says_is_computed_again(tmp_path, monkeypatch, capsys,
                                                                 case):
    # The reproduction: after kill -9, a copy of chunk 0-500 under the name of 500-1000 was
    # resumed, and the file held the fill value at 500..999 under "converged" counts.
    arguments, parts, whole = interrupted_parts(tmp_path, monkeypatch, capsys)
    change, reason = FALSE_PARTS[case]
    false = parts / "chunk-000000000100-000000000200.npz"
    if change is None:
        false.write_bytes((parts / "chunk-000000000000-000000000100.npz").read_bytes())
    else:
        rewritten(false, change)
    assert cli.main(arguments) == 0
    out, err = capsys.readouterr()
    said = (f"a part that does not hold what its name says, {false.name} ({reason}")
    assert err.startswith(said) and err.count("\n") == 2, err
    assert err.endswith(f") in {parts}: computing it again\nresuming: 3 chunks already "
                        f"computed in {parts}\n")
    assert "400 points (400 converged)" in out
    same_data(stores.open_result(tmp_path / "out.nc"), stores.open_result(whole))


#: A one-point sweep: its single chunk kept as arrays (a grid without axes has no HDF5 chunks).
ONE_POINT = SLOW.split("[axes]")[0] + 'radial_load = "4 kN"\nclearance = "0.01 mm"\n'


@pytest.mark.parametrize("change, reason", [
    (lambda a: a.__setitem__("status", np.array([9], np.int8)), "status 9, not a code"),
    (lambda a: a.__setitem__("status", np.zeros(2, np.int8)), "2 statuses of type int8, not 1"),
    (lambda a: a.__setitem__("bounds", np.array([0, 2])), "it holds points 0..1"),
    (lambda a: a.pop("output_roller_load"), "outputs ["),
    (lambda a: a.__setitem__("output_roller_load", a["output_roller_load"][:, :3]),
     "output roller_load of shape (1, 3)"),
    (lambda a: a.__setitem__("output_radial_stiffness", np.zeros(1, np.float32)),
     "type float32")])
def test_a_part_of_arrays_is_checked_alike(tmp_path, monkeypatch, capsys, change, reason):
    definition = tmp_path / "one.toml"
    definition.write_text(ONE_POINT)
    arguments = ["run", str(definition), "-o", str(tmp_path / "one.nc"), "--workers", "0",
                 "--quiet"]
    assert cli.main(arguments[:3] + [str(tmp_path / "whole.nc")] + arguments[4:]) == 0
    with monkeypatch.context() as patched:
        patched.setattr("bearing_sweep.stores.netcdf.ChunkWriter.finish", interrupt_now)
        assert cli.main(arguments) == 130
    capsys.readouterr()
    part, = (tmp_path / "one.nc.parts").glob("chunk-*.npz")
    rewritten(part, change)
    assert cli.main(arguments) == 0
    err = capsys.readouterr().err
    assert err.startswith(f"a part that does not hold what its name says, {part.name} "
                          f"(") and reason in err and err.count("\n") == 1, err
    same_data(stores.open_result(tmp_path / "one.nc"), stores.open_result(tmp_path / "whole.nc"))


def interrupt_now(*args):
    raise KeyboardInterrupt


def test_a_folder_without_a_manifest_that_holds_someone_s_files_is_refused(tmp_path, capsys):
    # Named as the parts of -o out.nc, but holding what no run writes: never removed.
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    parts = tmp_path / "out.nc.parts"
    parts.mkdir()
    (parts / "thesis.tex").write_text("someone's work")
    code = cli.main(["run", str(definition), "-o", str(tmp_path / "out.nc"), "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 2 and err == (f"error: {parts}: holds thesis.tex and no manifest.json: not "
                                 "the folder of an interrupted run's parts; refusing to use it "
                                 "(move it away or choose another output)\n")
    assert (parts / "thesis.tex").read_text() == "someone's work"
    assert not (tmp_path / "out.nc").exists()


@pytest.mark.parametrize("kind", ["a file", "a link to a folder"])
def test_a_parts_folder_that_is_not_a_folder_is_refused(tmp_path, capsys, kind):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    parts = tmp_path / "out.nc.parts"
    if kind == "a file":
        parts.write_text("someone's notes")
    else:
        (tmp_path / "theirs").mkdir()
        (tmp_path / "theirs" / "data.txt").write_text("someone's data")
        parts.symlink_to(tmp_path / "theirs")
    before = sorted(str(p) for p in tmp_path.rglob("*"))
    code = cli.main(["run", str(definition), "-o", str(tmp_path / "out.nc"), "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1, err
    assert f"{parts}: exists and is {'a file' if kind == 'a file' else 'a symbolic link'}"\
        f", not the folder of an interrupted run's parts of out.nc" in err
    assert sorted(str(p) for p in tmp_path.rglob("*")) == before


def test_parts_and_the_result_reach_the_disk_before_they_are_renamed(tmp_path, monkeypatch):
    events = []
    real_fsync, real_replace = os.fsync, os.replace

    def fsync(descriptor):
        events.append(("fsync", os.fstat(descriptor).st_ino))
        real_fsync(descriptor)

    def replace(source, destination):
        events.append(("replace", os.stat(source).st_ino, str(destination)))
        real_replace(source, destination)

    monkeypatch.setattr(os, "fsync", fsync)
    monkeypatch.setattr(os, "replace", replace)
    run_sweep(spec.parse(SLOW.replace("num = 200", "num = 4")), tmp_path / "out.nc",
              Executor(workers=0), chunk_size=5, progress=False)
    folder = (tmp_path / "out.nc.parts").as_posix()
    renamed = [i for i, event in enumerate(events)
               if event[0] == "replace" and event[2].startswith(folder)]
    assert len(renamed) == 5  # the manifest and four chunks
    renamed += [i for i, event in enumerate(events)
                if event[0] == "replace" and event[2] == str(tmp_path / "out.nc")]
    assert len(renamed) == 6  # and the result itself
    for i in renamed:
        assert ("fsync", events[i][1]) in events[:i]  # the file's bytes, before the rename
        assert events[i + 1][0] == "fsync"  # then its folder, for the rename itself


def test_the_output_lock_is_never_held_twice(tmp_path):
    # The former lock removed its file before unlocking it: a run that had opened the old file
    # and one that created a new one could then both hold "the" lock.
    output = tmp_path / "out.nc"
    holders, overlaps, acquired, refused = [0], [0], [0], [0]
    guard = threading.Lock()

    def contend():
        for _ in range(300):
            try:
                with OutputLock(output):
                    with guard:
                        holders[0] += 1
                        overlaps[0] += holders[0] > 1
                        acquired[0] += 1
                    time.sleep(0.0002)
                    with guard:
                        holders[0] -= 1
            except OutputBusy:
                with guard:
                    refused[0] += 1

    threads = [threading.Thread(target=contend) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert overlaps[0] == 0
    assert acquired[0] > 20 and refused[0] > 20  # it was contended, and served


@pytest.mark.slow
def test_two_runs_started_at_once_one_computes_the_other_is_refused(tmp_path, start_cli):
    (tmp_path / "slow.toml").write_text(SLOW)
    common = ["slow.toml", "-o", "out.nc", "--workers", "0", "--chunk-size", "1000", "--quiet"]
    runs = [start_cli("run", *common, cwd=tmp_path) for _ in range(2)]
    finished = [(run.returncode, *run.communicate(timeout=300)) for run in runs]
    finished = [(run.returncode, out, err) for run, (_, out, err) in zip(runs, finished)]
    assert sorted(code for code, _, _ in finished) == [0, 1], finished
    (_, out, _), = [f for f in finished if f[0] == 0]
    (_, _, refusal), = [f for f in finished if f[0] == 1]
    assert "crb_radial: 40000 points (40000 converged)" in out
    assert len(refusal.strip().splitlines()) == 1
    assert "another bearing-sweep run is writing this output" in refusal
    result = stores.open_result(tmp_path / "out.nc")
    assert result.status.size == 40000 and int(result.status.max()) == 0
    assert not (tmp_path / "out.nc.parts").exists()


def test_the_command_line_imports_without_fcntl():
    # As on Windows, which has no fcntl module.
    done = subprocess.run([sys.executable, "-c", "import sys; sys.modules['fcntl'] = None; "
                           "import bearing_sweep.cli, bearing_sweep.stores.durable"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


@pytest.mark.slow
def test_ctrl_c_on_the_local_cluster_is_one_line_and_resumes(tmp_path, start_cli):
    # A terminal's Ctrl-C reaches the whole foreground process group: the workers too.
    # 160 000 points: enough left to compute after the first chunk is saved that the signal
    # always lands mid-run (at 90 000 a quick machine sometimes finished first).
    (tmp_path / "slow.toml").write_text(SLOW.replace("num = 200", "num = 400"))
    run = start_cli("run", "slow.toml", "-o", "out.nc", "--quiet", cwd=tmp_path,
                    start_new_session=True)
    parts = tmp_path / "out.nc.parts"
    wait_for_chunks(parts, 1)
    os.killpg(run.pid, signal.SIGINT)
    _, err = run.communicate(timeout=120)
    assert run.returncode == 130, err
    assert "Traceback" not in err
    assert len(err.strip().splitlines()) == 1 and "interrupted" in err
    kept = len(list(parts.glob("chunk-*.npz")))
    assert kept and not (tmp_path / "out.nc").exists()
    again = start_cli("run", "slow.toml", "-o", "out.nc", "--quiet", cwd=tmp_path)
    out, err = again.communicate(timeout=300)
    assert again.returncode == 0, err
    assert re.search(rf"resuming: {kept} chunks? already computed", err)
    assert "on dask LocalCluster (2 single-threaded worker processes)" in out


def interrupt():
    """A Ctrl-C: SIGINT to this process, handled as it would be from the terminal."""
    os.kill(os.getpid(), signal.SIGINT)


def interrupted_in(monkeypatch, target: str, when=lambda *args: True):
    """Send SIGINT from within ``target`` (a dotted name), before it does its work, when
    ``when(*its arguments)``."""
    module, name = target.rsplit(".", 1)
    import importlib

    try:
        owner = importlib.import_module(module)
    except ModuleNotFoundError:  # a method: module.Class.name
        module, cls = module.rsplit(".", 1)
        owner = getattr(importlib.import_module(module), cls)
    original = getattr(owner, name)

    def patched(*args, **kwargs):
        if when(*args):
            interrupt()
        return original(*args, **kwargs)

    monkeypatch.setattr(owner, name, patched)


#: Where a Ctrl-C may come once the result has its name: the folder's fsync that makes the
#: rename durable, the parts' removal, the cluster's closing, the summary.
AFTER_THE_RENAME = {
    "netCDF, the rename's fsync": ("k.nc", "bearing_sweep.stores.durable.fsync_path",
                                   lambda tmp_path: lambda path: Path(path) == tmp_path),
    "zarr, the rename's fsync": ("k.zarr", "bearing_sweep.stores.zarr.fsync_path",
                                 lambda tmp_path: lambda path: Path(path) == tmp_path),
    "the parts removed": ("k.nc", "bearing_sweep.stores.resume.Parts.remove", None),
    "zarr, the parts removed": ("k.zarr", "bearing_sweep.stores.resume.Parts.remove", None),
    "the cluster closed": ("k.nc", "bearing_sweep.compute.Executor.close", None),
    "the summary": ("k.nc", "bearing_sweep.compute.Summary.text", None),
}


@pytest.mark.parametrize("case", AFTER_THE_RENAME)
def test_ctrl_c_once_the_result_is_in_place_says_it_is_complete(tmp_path, capsys, monkeypatch,
                                                                case):
    output, target, when = AFTER_THE_RENAME[case]
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 3"))
    interrupted_in(monkeypatch, target, *([when(tmp_path)] if when else []))
    code = cli.main(["run", str(definition), "-o", str(tmp_path / output), "--workers", "0",
                     "--chunk-size", "3", "--quiet"])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert err == "interrupt ignored: the result was already complete\n"
    assert "9 points (9 converged)" in out
    assert stores.open_result(tmp_path / output).status.shape == (3, 3)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["d.toml", output]
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_ctrl_c_before_the_rename_still_keeps_the_chunks(tmp_path, capsys, monkeypatch):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 3"))
    interrupted_in(monkeypatch, "bearing_sweep.stores.netcdf.ChunkWriter.finish")
    code = cli.main(["run", str(definition), "-o", str(tmp_path / "k.nc"), "--workers", "0",
                     "--chunk-size", "3", "--quiet"])
    assert code == 130
    assert capsys.readouterr().err == ("interrupted: the finished chunks are kept; run the same "
                                       "command again to resume\n")
    assert len(list((tmp_path / "k.nc.parts").glob("chunk-*.npz"))) == 3
    assert not (tmp_path / "k.nc").exists()


def test_the_api_too_finishes_a_run_whose_result_is_in_place(tmp_path, capsys, monkeypatch):
    import bearing_sweep

    interrupted_in(monkeypatch, "bearing_sweep.stores.resume.Parts.remove")
    with bearing_sweep.run(SLOW.replace("num = 200", "num = 3"), output=tmp_path / "k.nc",
                           workers=0) as data:
        assert data.status.shape == (3, 3)
    assert capsys.readouterr().err.endswith("interrupt ignored: the result was already "
                                            "complete\n")
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_part_damaged_after_the_run_began_is_removed_with_one_clear_error(tmp_path):
    chunks = Parts(tmp_path / "out.nc", {"definition_sha256": "x"})
    chunks.open(4, False)
    chunks.begin(print)
    chunks.save(0, 4, {"outputs": {}, "status": np.zeros(4, np.int8), "errors": []})
    assert chunks.finished() == {(0, 4)}
    assert chunks.load(0, 4)["status"].tolist() == [0] * 4
    chunks.path(0, 4).write_bytes(b"PK\x03\x04" + bytes(40))  # the zip's start, then zeros
    with pytest.raises(UnreadablePart, match="run the same command again to compute it"):
        chunks.load(0, 4)
    assert not chunks.path(0, 4).exists()


def test_parts_of_another_package_version_are_discarded(tmp_path, capsys, monkeypatch):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 4"))
    arguments = ["run", str(definition), "-o", str(tmp_path / "out.nc"), "--workers", "0",
                 "--chunk-size", "4"]

    def interrupted(*args):  # every chunk computed, the file not yet written
        raise KeyboardInterrupt

    monkeypatch.setattr("bearing_sweep.stores.netcdf.ChunkWriter.finish", interrupted)
    monkeypatch.setattr("bearing_sweep.stores.structure.package_version", lambda: "0.0.1")
    assert cli.main(arguments) == 130
    monkeypatch.undo()  # the package is upgraded before the run is resumed
    capsys.readouterr()
    assert cli.main(arguments) == 0
    assert "the definition, model, package or storage changed: discarding 4 finished chunks" in \
        capsys.readouterr().err


def test_parts_of_other_input_values_are_not_resumed(tmp_path):
    # The parts are keyed on the grid's values, not only on the definition's text: a sample
    # drawn differently (another library version) or a preset that changed gives other
    # values from the same text, and its parts must not be mixed in.
    from bearing_sweep import spec
    from bearing_sweep.grid import Grid

    text = ('[sweep]\nmodel = "crb_radial"\nbearing = "paper000-D"\n'
            '[axes]\nradial_load = ["1 kN", "2 kN"]\n')
    grid = Grid.from_sweep(spec.parse(text))
    same = Grid.from_sweep(spec.parse(text))
    other = Grid.from_sweep(spec.parse(text.replace('"2 kN"', '"3 kN"')))
    assert grid.values_sha256 == same.values_sha256 != other.values_sha256
    moved = Grid.from_sweep(spec.parse(text))
    moved.axis_values["radial_load"] = (0, moved.axis_values["radial_load"][1] * (1 + 1e-15))
    assert moved.values_sha256 != grid.values_sha256


def test_an_analysis_store_left_half_written_is_removed_by_the_next_writer(tmp_path):
    import xarray as xr

    from bearing_sweep.stores import zarr as zarr_store

    output = tmp_path / "r_analysis.zarr"
    stale = tmp_path / ".r_analysis.zarr.99999999.tmp"
    (stale / "x").mkdir(parents=True)
    (stale / "x" / "0").write_bytes(b"half a chunk")
    zarr_store.write_dataset(xr.Dataset({"x": ("t", [1.0, 2.0])}), output)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r_analysis.zarr"]
    with xr.open_dataset(output, engine="zarr") as written:
        assert list(written.x.values) == [1.0, 2.0]
    with OutputLock(output), pytest.raises(OutputBusy):  # and two writers do not mix
        zarr_store.write_dataset(xr.Dataset({"x": ("t", [3.0])}), tmp_path / "r_analysis.zarr")


@pytest.mark.parametrize("workers", ["0", pytest.param("2", marks=pytest.mark.slow)])
def test_a_sigterm_stops_the_run_as_ctrl_c_does_and_it_resumes(tmp_path, workers, start_cli):
    # kill, or a batch system's time limit, sends SIGTERM to the program alone: it stops as
    # a Ctrl-C does, in one line, exit 143 (128 + 15), its workers stopped, the finished
    # chunks kept and no temporary file left; the same command resumes.
    (tmp_path / "slow.toml").write_text(SLOW)
    common = ["--workers", workers, "--chunk-size", "1000", "--quiet"]
    first = start_cli("run", "slow.toml", "-o", "out.nc", *common, cwd=tmp_path)
    parts = tmp_path / "out.nc.parts"
    wait_for_chunks(parts, 3)
    first.send_signal(signal.SIGTERM)
    _, err = first.communicate(timeout=120)
    assert first.returncode == 143, err
    assert err.strip() == ("terminated: the finished chunks are kept; run the same command "
                           "again to resume")
    kept = len(list(parts.glob("chunk-*.npz")))
    assert 3 <= kept < 40 and not (tmp_path / "out.nc").exists()
    assert not list(tmp_path.glob(".*.tmp")) and not list(parts.glob("*.tmp"))
    second = start_cli("run", "slow.toml", "-o", "out.nc", *common, cwd=tmp_path)
    _, err = second.communicate(timeout=300)
    assert second.returncode == 0, err
    assert re.search(rf"resuming: {kept} chunks? already computed", err)
    assert stores.open_result(tmp_path / "out.nc").status.size == 40000
