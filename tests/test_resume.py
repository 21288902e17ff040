"""Interrupted sweeps resume, a killed worker costs a retry, a busy or broken output is a clear
error that leaves any earlier result intact."""
import errno
import os
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

from bearing_sweep import cli, spec, store
from bearing_sweep.parts import OutputBusy, OutputLock, Parts, UnreadablePart
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


def cli_run(*arguments, cwd):
    return subprocess.Popen([sys.executable, "-m", "bearing_sweep", "run", *map(str, arguments)],
                            cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def test_a_killed_run_resumes_where_it_stopped(tmp_path):
    (tmp_path / "slow.toml").write_text(SLOW)
    common = ["--workers", "0", "--chunk-size", "1000", "--quiet"]
    first = cli_run("slow.toml", "-o", "out.nc", *common, cwd=tmp_path)
    parts = tmp_path / "out.nc.parts"
    deadline = time.monotonic() + 120
    while len(list(parts.glob("chunk-*.npz"))) < 5 and time.monotonic() < deadline:
        time.sleep(0.05)
    first.send_signal(signal.SIGKILL)
    first.wait()
    kept = len(list(parts.glob("chunk-*.npz")))
    assert 5 <= kept < 40 and not (tmp_path / "out.nc").exists()

    second = cli_run("slow.toml", "-o", "out.nc", *common, cwd=tmp_path)
    _, err = second.communicate(timeout=300)
    assert second.returncode == 0, err
    assert re.search(rf"resuming: {kept} chunks? already computed", err)
    assert not parts.exists()
    whole = cli_run("slow.toml", "-o", "whole.nc", *common, cwd=tmp_path)
    whole.communicate(timeout=300)
    same_data(store.open_result(tmp_path / "out.nc"), store.open_result(tmp_path / "whole.nc"))


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
    assert store.open_result(output).status.size == 16


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

    monkeypatch.setattr("bearing_sweep.store._regions", full)
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    code = cli.main(["run", str(definition), "-o", str(output), "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 1 and "No space left on device" in err and "left as it was" in err
    assert output.read_bytes() == before
    assert not list(tmp_path.glob(".out.nc.*.tmp"))


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
    same_data(store.open_result(tmp_path / "reference.nc"),
              store.open_result(tmp_path / "killed.nc"))


def test_an_output_that_cannot_be_a_file_is_one_line(tmp_path, capsys, monkeypatch):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    occupied = tmp_path / "out.nc"
    occupied.mkdir()  # a folder where the file should go

    def computed(*args):
        raise AssertionError("computed before the output was refused")

    monkeypatch.setattr("bearing_sweep.compute.evaluate_chunk", computed)
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

    monkeypatch.setattr("bearing_sweep.store.ChunkWriter.finish", power_loss)
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
    same_data(store.open_result(output), store.open_result(whole))


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


def test_two_runs_started_at_once_one_computes_the_other_is_refused(tmp_path):
    (tmp_path / "slow.toml").write_text(SLOW)
    common = ["slow.toml", "-o", "out.nc", "--workers", "0", "--chunk-size", "1000", "--quiet"]
    runs = [cli_run(*common, cwd=tmp_path) for _ in range(2)]
    finished = [(run.returncode, *run.communicate(timeout=300)) for run in runs]
    finished = [(run.returncode, out, err) for run, (_, out, err) in zip(runs, finished)]
    assert sorted(code for code, _, _ in finished) == [0, 1], finished
    (_, out, _), = [f for f in finished if f[0] == 0]
    (_, _, refusal), = [f for f in finished if f[0] == 1]
    assert "crb_radial: 40000 points (40000 converged)" in out
    assert len(refusal.strip().splitlines()) == 1
    assert "another bearing-sweep run is writing this output" in refusal
    result = store.open_result(tmp_path / "out.nc")
    assert result.status.size == 40000 and int(result.status.max()) == 0
    assert not (tmp_path / "out.nc.parts").exists()


def test_the_command_line_imports_without_fcntl():
    # As on Windows, which has no fcntl module.
    done = subprocess.run([sys.executable, "-c", "import sys; sys.modules['fcntl'] = None; "
                           "import bearing_sweep.cli, bearing_sweep.parts"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


@pytest.mark.slow
def test_ctrl_c_on_the_local_cluster_is_one_line_and_resumes(tmp_path):
    # A terminal's Ctrl-C reaches the whole foreground process group: the workers too.
    # 160 000 points: enough left to compute after the first chunk is saved that the signal
    # always lands mid-run (at 90 000 a quick machine sometimes finished first).
    (tmp_path / "slow.toml").write_text(SLOW.replace("num = 200", "num = 400"))
    run = subprocess.Popen([sys.executable, "-m", "bearing_sweep", "run", "slow.toml", "-o", "out.nc",
                            "--quiet"], cwd=tmp_path, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True, start_new_session=True)
    parts = tmp_path / "out.nc.parts"
    deadline = time.monotonic() + 120
    while not list(parts.glob("chunk-*.npz")) and time.monotonic() < deadline:
        time.sleep(0.05)
    os.killpg(run.pid, signal.SIGINT)
    _, err = run.communicate(timeout=120)
    assert run.returncode == 130, err
    assert "Traceback" not in err
    assert len(err.strip().splitlines()) == 1 and "interrupted" in err
    kept = len(list(parts.glob("chunk-*.npz")))
    assert kept and not (tmp_path / "out.nc").exists()
    again = cli_run("slow.toml", "-o", "out.nc", "--quiet", cwd=tmp_path)
    out, err = again.communicate(timeout=300)
    assert again.returncode == 0, err
    assert re.search(rf"resuming: {kept} chunks? already computed", err)
    assert "on dask LocalCluster (2 single-threaded worker processes)" in out


def test_a_part_damaged_after_the_run_began_is_removed_with_one_clear_error(tmp_path):
    chunks = Parts(tmp_path / "out.nc", {"definition_sha256": "x"})
    chunks.open(4, False, print)
    chunks.save(0, 4, {"outputs": {}, "status": np.zeros(4, np.int8), "errors": []})
    assert chunks.finished() == {(0, 4)}
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

    monkeypatch.setattr("bearing_sweep.store.ChunkWriter.finish", interrupted)
    monkeypatch.setattr("bearing_sweep.store.package_version", lambda: "0.0.1")
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
