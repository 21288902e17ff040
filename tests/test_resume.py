"""Interrupted sweeps resume, a killed worker costs a retry, a busy or broken output is a clear
error that leaves any earlier result intact."""
import errno
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

from sweeps import cli, spec, store
from sweeps.parts import OutputLock
from sweeps.run import Executor, run_sweep

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
    return subprocess.Popen([sys.executable, "-m", "sweeps", "run", *map(str, arguments)],
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
    assert f"resuming: {kept} chunks already computed" in err
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
    assert "the definition or model changed: discarding 1 finished chunks" in \
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

    monkeypatch.setattr("sweeps.store._regions", full)
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
    assert code == 1 and "Permission denied" in capsys.readouterr().err


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


def test_an_output_that_cannot_be_a_file_is_one_line(tmp_path, capsys):
    definition = tmp_path / "d.toml"
    definition.write_text(SLOW.replace("num = 200", "num = 2"))
    occupied = tmp_path / "out.nc"
    occupied.mkdir()  # a folder where the file should go
    code = cli.main(["run", str(definition), "-o", str(occupied), "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 1 and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert occupied.is_dir() and not any(occupied.iterdir())
