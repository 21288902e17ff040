"""A sweep on an external dask.distributed cluster gives the local result."""
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

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


@pytest.mark.slow
def test_sweep_on_a_real_scheduler_and_two_workers(tmp_path):
    (tmp_path / "def.toml").write_text(DEFINITION)
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    dask = str(BIN / "dask")
    processes = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", str(port),
                                   "--no-dashboard"], cwd=tmp_path, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL)]
    try:
        wait_for_port(port)
        processes += [subprocess.Popen([dask, "worker", address, "--nthreads", "1",
                                        "--no-dashboard"], cwd=tmp_path,
                                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                      for _ in range(2)]
        from distributed import Client

        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=60)
        remote = subprocess.run([sys.executable, "-m", "sweeps", "run", "def.toml", "-o",
                                 "remote.nc", "--scheduler", address, "--chunk-size", "7"],
                                cwd=tmp_path, capture_output=True, text=True, timeout=300)
        assert remote.returncode == 0, remote.stderr
        assert f"dask scheduler {address} (2 workers)" in remote.stdout
    finally:
        for process in processes:
            process.terminate()
        for process in processes:
            process.wait(timeout=30)
    local = subprocess.run([sys.executable, "-m", "sweeps", "run", "def.toml", "-o", "local.nc",
                            "--workers", "0"], cwd=tmp_path, capture_output=True, text=True)
    assert local.returncode == 0, local.stderr
    a = xr.open_dataset(tmp_path / "remote.nc")
    b = xr.open_dataset(tmp_path / "local.nc")
    assert a.attrs["scheduler"].startswith("dask scheduler")
    for name in b.data_vars:
        np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)


@pytest.mark.slow
def test_a_worker_killed_on_an_external_cluster_costs_only_a_retry(tmp_path):
    definition = DEFINITION.replace("num = 10", "num = 400").replace("num = 5", "num = 100")
    (tmp_path / "def.toml").write_text(definition)
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    dask = str(BIN / "dask")
    processes = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", str(port),
                                   "--no-dashboard"], cwd=tmp_path, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL)]
    try:
        wait_for_port(port)
        # Without a nanny the process is the worker: killing it loses the worker for good.
        workers = [subprocess.Popen([dask, "worker", address, "--nthreads", "1", "--no-nanny",
                                     "--no-dashboard"], cwd=tmp_path, stdout=subprocess.DEVNULL,
                                    stderr=subprocess.DEVNULL) for _ in range(2)]
        processes += workers
        from distributed import Client

        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=60)
        remote = subprocess.Popen([sys.executable, "-m", "sweeps", "run", "def.toml", "-o",
                                   "remote.nc", "--scheduler", address, "--chunk-size", "1000",
                                   "--quiet"], cwd=tmp_path, stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, text=True)
        parts = tmp_path / "remote.nc.parts"
        end = time.monotonic() + 120
        while len(list(parts.glob("chunk-*.npz"))) < 3 and time.monotonic() < end:
            time.sleep(0.05)
        workers[0].kill()
        out, err = remote.communicate(timeout=300)
        assert remote.returncode == 0, err
        assert len(list(parts.glob("*"))) == 0 and workers[0].poll() is not None
    finally:
        for process in processes:
            process.terminate()
        for process in processes:
            process.wait(timeout=30)
    local = subprocess.run([sys.executable, "-m", "sweeps", "run", "def.toml", "-o", "local.nc",
                            "--workers", "0", "--quiet"], cwd=tmp_path, capture_output=True,
                           text=True)
    assert local.returncode == 0, local.stderr
    a = xr.open_dataset(tmp_path / "remote.nc")
    b = xr.open_dataset(tmp_path / "local.nc")
    for name in b.data_vars:
        np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)
