"""A sweep on an external dask.distributed cluster gives the local result."""
import contextlib
import os
import re
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from bearing_sweep import stores

BIN = Path(sys.executable).parent

DEFINITION = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "0.004 mm"
speed = "5000 rpm"
[axes]
radial_load = { start = "1 kN", stop = "10 kN", num = 10 }
clearance = { start = "0 mm", stop = "0.04 mm", num = 5 }
"""


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for_port(port: int, seconds: float = 60):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        with socket.socket() as s:
            if s.connect_ex(("127.0.0.1", port)) == 0:
                return
        time.sleep(0.2)
    raise TimeoutError(f"nothing listens on port {port}")


@contextlib.contextmanager
def external_cluster(folder, nanny=True):
    """A ``dask scheduler`` and two ``dask worker`` processes; yields the address and the
    worker processes (without a nanny a worker process is the worker itself)."""
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    dask = str(BIN / "dask")
    quiet = dict(cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    processes = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port",
                                   str(port), "--no-dashboard"], **quiet)]
    try:
        wait_for_port(port)
        workers = [subprocess.Popen([dask, "worker", address, "--nthreads", "1",
                                     "--no-dashboard"] + ([] if nanny else ["--no-nanny"]),
                                    **quiet) for _ in range(2)]
        processes += workers
        from distributed import Client

        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=60)
        yield address, workers
    finally:
        # Workers first, while their scheduler still answers: a worker left without one can
        # spend its shutdown retrying it.
        for process in reversed(processes):
            process.terminate()
        for process in processes:
            try:
                process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


def equals_local_run(run_cli, folder, remote_name):
    """The remote result has the data of an in-process run of the same definition."""
    local = run_cli("run", "def.toml", "-o", "local.nc", "--workers", "0", "--quiet", cwd=folder)
    assert local.returncode == 0, local.stderr
    a = stores.open_result(folder / remote_name)
    b = stores.open_result(folder / "local.nc")
    for name in b.data_vars:
        np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)
    return a


def run_on(run_cli, address, folder, *extra, output="remote.nc"):
    began = time.monotonic()
    done = run_cli("run", "def.toml", "-o", output, "--scheduler", address, *extra, cwd=folder,
                   timeout=300)
    return done, time.monotonic() - began


@pytest.mark.slow
def test_sweep_on_a_real_scheduler_and_two_workers(tmp_path, run_cli):
    (tmp_path / "def.toml").write_text(DEFINITION)
    with external_cluster(tmp_path) as (address, _):
        remote = run_cli("run", "def.toml", "-o", "remote.nc", "--scheduler", address,
                         "--chunk-size", "7", cwd=tmp_path, timeout=300)
        assert remote.returncode == 0, remote.stderr
        assert f"dask scheduler {address} (2 workers)" in remote.stdout
        # The workers write a zarr store's chunks themselves, from their own processes.
        stored, _ = run_on(run_cli, address, tmp_path, "--chunk-size", "7", "--quiet",
                           output="remote.zarr")
        assert stored.returncode == 0, stored.stderr
        # the same cluster: it is slow to start
        workers_of_another_version_are_refused(run_cli, address, tmp_path)
    result = equals_local_run(run_cli, tmp_path, "remote.nc")
    assert result.attrs["scheduler"].startswith("dask scheduler")
    assert equals_local_run(run_cli, tmp_path, "remote.zarr").attrs["scheduler"] == \
        result.attrs["scheduler"]


def workers_of_another_version_are_refused(run_cli, address, folder):
    from distributed import Client

    with Client(address, timeout="60s") as client:  # the workers' installation now differs
        client.run(exec, "import bearing_sweep.stores.structure\n"
                         "bearing_sweep.stores.structure.package_version = lambda: '0.0.1'", {})
    done, _ = run_on(run_cli, address, folder, "--chunk-size", "7", "--quiet",
                     output="other.nc")
    assert done.returncode == 1, done.stderr
    assert len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert f"a worker of dask scheduler {address} runs bearing-sweep 0.0.1" in done.stderr
    assert "install the same on every worker" in done.stderr
    # refused before any chunk is computed: no parts folder made
    assert not (folder / "other.nc").exists() and not (folder / "other.nc.parts").exists()


@pytest.mark.slow
def test_a_worker_killed_on_an_external_cluster_costs_only_a_retry(tmp_path, run_cli, start_cli):
    definition = DEFINITION.replace("num = 10", "num = 400").replace("num = 5", "num = 100")
    (tmp_path / "def.toml").write_text(definition)
    # Without a nanny the process is the worker: killing it loses the worker for good.
    with external_cluster(tmp_path, nanny=False) as (address, workers):
        remote = start_cli("run", "def.toml", "-o", "remote.nc", "--scheduler", address,
                           "--chunk-size", "1000", "--quiet", cwd=tmp_path)
        parts = tmp_path / "remote.nc.parts"
        end = time.monotonic() + 120
        while len(list(parts.glob("chunk-*.npz"))) < 3 and time.monotonic() < end:
            time.sleep(0.05)
        workers[0].kill()
        _, err = remote.communicate(timeout=300)
        assert remote.returncode == 0, err
        assert len(list(parts.glob("*"))) == 0 and workers[0].poll() is not None
    equals_local_run(run_cli, tmp_path, "remote.nc")


def test_an_address_that_cannot_be_parsed_is_refused_at_once(tmp_path, run_cli):
    (tmp_path / "def.toml").write_text(DEFINITION)
    for address in ("nonsense", "tcp://127.0.0.1:99999", "carrier-pigeon://loft:1"):
        done, seconds = run_on(run_cli, address, tmp_path)
        assert done.returncode == 2, done.stderr
        assert done.stderr.strip() == (f"error: --scheduler {address}: not a scheduler address "
                                       "(expected tcp://HOST:PORT)")
        assert seconds < 15  # dask's own connection attempts took 20 s or more
    assert sorted(p.name for p in tmp_path.iterdir()) == ["def.toml"]


def test_an_unreachable_scheduler_is_one_line_within_seconds(tmp_path, run_cli):
    (tmp_path / "def.toml").write_text(DEFINITION)
    address = f"tcp://127.0.0.1:{free_port()}"  # nothing listens there
    done, seconds = run_on(run_cli, address, tmp_path)
    assert done.returncode == 1, done.stderr
    assert len(done.stderr.strip().splitlines()) == 1 and "Traceback" not in done.stderr
    assert f"--scheduler {address}: cannot reach it: Connection refused" in done.stderr
    assert seconds < 15
    assert not (tmp_path / "remote.nc").exists()


def test_a_local_cluster_that_cannot_start_is_one_line_with_the_way_out(tmp_path, run_cli):
    # As an unprivileged user whose dask scratch folder cannot be made; here, the temporary
    # folder dask makes it in is a file.
    (tmp_path / "def.toml").write_text(DEFINITION)
    (tmp_path / "scratch").write_text("a file, not a folder")
    done = run_cli("run", "def.toml", "-o", "out.nc", "--workers", "2", "--chunk-size", "25",
                   "--quiet", cwd=tmp_path, timeout=300, env=os.environ |
                   {"DASK_TEMPORARY_DIRECTORY": str(tmp_path / "scratch")})
    assert done.returncode == 1, done.stderr
    assert done.stderr.count("\n") == 1 and "Traceback" not in done.stderr, done.stderr
    assert done.stderr.startswith("error: the local dask cluster of 2 workers could not start (")
    assert "Not a directory" in done.stderr
    assert done.stderr.endswith("--workers 0 (workers=0 in Python) computes in this process\n")
    assert not (tmp_path / "out.nc").exists() and not list(tmp_path.glob(".out.nc.*.tmp"))


def test_any_failure_to_start_the_cluster_is_one_line(tmp_path, capsys, monkeypatch):
    import distributed

    from bearing_sweep import api, cli, spec
    from bearing_sweep.executor import ClusterFailure

    def failing(*args, **kwargs):
        raise TimeoutError("Nanny failed to start in 60 s\nand a second line")

    monkeypatch.setattr(distributed, "LocalCluster", failing)
    (tmp_path / "def.toml").write_text(DEFINITION)
    assert cli.main(["run", str(tmp_path / "def.toml"), "-o", str(tmp_path / "out.nc"),
                     "--workers", "2", "--chunk-size", "25", "--quiet"]) == 1
    assert capsys.readouterr().err == (
        "error: the local dask cluster of 2 workers could not start (Nanny failed to start in "
        "60 s); --workers 0 (workers=0 in Python) computes in this process\n")
    with pytest.raises(ClusterFailure, match="workers=0 in Python"):
        api.run(spec.load(tmp_path / "def.toml").text, workers=1, progress=False)


def test_a_thousand_workers_asked_for_start_no_more_than_the_cores(tmp_path, capsys,
                                                                   monkeypatch):
    # The cluster is not started here: what it would be started with is recorded (a test
    # that failed would otherwise start a thousand processes).
    import distributed

    from bearing_sweep import cli

    started = []

    def recorded(**kwargs):
        started.append(kwargs["n_workers"])
        raise RuntimeError("recorded")

    monkeypatch.setattr(distributed, "LocalCluster", recorded)
    one_load = DEFINITION.replace('{ start = "1 kN", stop = "10 kN", num = 10 }', '["1 kN"]')
    (tmp_path / "def.toml").write_text(one_load.replace("num = 5", "num = 3"))  # 3 points
    monkeypatch.setattr("bearing_sweep.executor.available_cores", lambda: 4)
    # By default, no more workers than seconds of work (the chunks of a second each): one;
    # in chunks of 2 points, two chunks: two workers; of 1 point, three.
    for chunk, expected, why in (
            ([], 1, " and 0.00018 s of work (a worker for each second of it at most)"),
            (["--chunk-size", "2"], 2, " and 2 chunks of 2 points"),
            (["--chunk-size", "1"], 3, " and 3 chunks of 1 point")):
        assert cli.main(["run", str(tmp_path / "def.toml"), "-o", str(tmp_path / "out.nc"),
                         "--workers", "1000", "--quiet", *chunk]) == 1
        err = capsys.readouterr().err.splitlines()
        assert err[0] == (f"1000 workers asked for, 4 cores available to this process{why}: a "
                          f"local cluster of {expected} worker{'s' * (expected != 1)} "
                          "(--scheduler runs on a larger cluster)")
        assert started.pop() == expected
    assert cli.main(["run", str(tmp_path / "def.toml"), "-o", str(tmp_path / "out.nc"),
                     "--workers", "2", "--quiet"]) == 1
    assert started.pop() == 1  # fewer than the cores: said by the summary alone
    assert capsys.readouterr().err.startswith("error: the local dask cluster of 1 worker could")


@pytest.mark.slow
def test_no_more_workers_than_cores_nor_than_chunks(tmp_path, capsys, monkeypatch):
    from bearing_sweep import cli

    (tmp_path / "def.toml").write_text(DEFINITION)  # 50 points
    common = ["run", str(tmp_path / "def.toml"), "--quiet"]
    monkeypatch.setattr("bearing_sweep.executor.available_cores", lambda: 1)
    assert cli.main(common + ["-o", str(tmp_path / "few.nc"), "--workers", "2"]) == 0
    out, err = capsys.readouterr()
    assert err == ("2 workers asked for, 1 core available to this process: a local cluster of "
                   "1 worker (--scheduler runs on a larger cluster)\n")
    assert "on dask LocalCluster (1 single-threaded worker processes)" in out
    monkeypatch.undo()
    # one chunk of 50 points: one worker, whatever the cores
    assert cli.main(common + ["-o", str(tmp_path / "one.nc"), "--workers", "2", "--chunk-size",
                              "100"]) == 0
    out, err = capsys.readouterr()
    assert "on dask LocalCluster (1 single-threaded worker processes)" in out and not err
    np.testing.assert_array_equal(stores.open_result(tmp_path / "one.nc").radial_stiffness,
                                  stores.open_result(tmp_path / "few.nc").radial_stiffness)


def dies(**inputs):
    """A model whose every call kills the process that runs it."""
    os._exit(1)


@pytest.mark.slow
def test_workers_that_keep_dying_are_one_line(tmp_path, capsys, monkeypatch):
    import dask

    import bearing_sweep.models.registry as registry
    from bearing_sweep import cli

    model = registry.get_model("crb_radial")
    monkeypatch.setitem(registry._MODELS, "crb_radial",
                        registry.Model(**{**model.__dict__, "function": dies}))
    (tmp_path / "def.toml").write_text(DEFINITION)
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):  # at the first death
        code = cli.main(["run", str(tmp_path / "def.toml"), "-o", str(tmp_path / "out.nc"),
                         "--workers", "1", "--quiet"])
    err = capsys.readouterr().err
    assert code == 1 and err.count("\n") == 1, err
    assert re.fullmatch(r"error: the workers that computed points \d+\.\.\d+ died doing it, as "
                        r"often as dask retries; the finished chunks are kept: .*\n", err), err
    assert err.endswith("run the same command again, or with --workers 0 to compute in this "
                        "process\n")
    assert not (tmp_path / "out.nc").exists()


@pytest.mark.slow
def test_a_ctrl_c_that_reaches_a_worker_alone_changes_nothing(tmp_path):
    # A worker process that receives SIGINT (kill -INT, a terminal's Ctrl-C reaching the
    # process group before the driver stops the run) neither stops nor fails its chunks: the
    # driver alone decides what a Ctrl-C does.
    import signal
    import threading

    from bearing_sweep import spec
    from bearing_sweep.compute import Executor, run_sweep

    sweep = spec.parse(DEFINITION.replace("num = 10", "num = 200").replace("num = 5", "num = 100"))
    reference = run_sweep(sweep, None, Executor(workers=0), chunk_size=1000, progress=False)
    with Executor(workers=1) as executor:
        client = executor.connect()
        worker = list(client.run(os.getpid).values())[0]
        running, sent = threading.Event(), []

        def pester():  # SIGINT to the worker every 10 ms while the sweep runs
            while not running.wait(0.01):
                os.kill(worker, signal.SIGINT)
                sent.append(1)

        thread = threading.Thread(target=pester)
        thread.start()
        try:
            summary = run_sweep(sweep, None, executor, chunk_size=1000, progress=False)
        finally:
            running.set()
            thread.join()
        assert len(sent) > 10 and list(client.run(os.getpid).values()) == [worker]
    assert summary.status_counts == reference.status_counts and not summary.errors
    for name in reference.dataset.data_vars:
        np.testing.assert_array_equal(summary.dataset[name].values,
                                      reference.dataset[name].values, err_msg=name)


@pytest.mark.slow
def test_a_run_that_starts_a_local_cluster_says_where_its_dashboard_is(tmp_path, monkeypatch):
    import importlib.util

    from bearing_sweep import api, spec

    # dask serves the dashboard where bokeh is installed; it is an optional extra here.
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *args: object() if name == "bokeh" else real(name, *args))
    (tmp_path / "def.toml").write_text(DEFINITION)
    said = []
    api.run(spec.load(tmp_path / "def.toml").text, workers=1, chunk_size=25, log=said.append,
            summary=said.append)
    assert any(re.fullmatch(r"dask dashboard: http://127\.0\.0\.1:\d+/status", str(line))
               for line in said), said
    said.clear()
    api.run(spec.load(tmp_path / "def.toml").text, workers=0, log=said.append,
            summary=said.append)  # in this process: no cluster, no dashboard
    assert not any("dashboard" in str(line) for line in said), said
