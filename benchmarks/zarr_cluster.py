"""Cluster scale: a crb_radial sweep written to a zarr store on an external ``dask scheduler``.

A ``dask scheduler`` and two ``dask worker`` processes (with their nannies, as on a real
cluster) run on 127.0.0.1 from a temporary folder, with the workers' environment the user guide
recommends (``DASK_CONFIG``: no malloc trim threshold). Two measurements:

1. Time per point: the same sweep to a zarr store on the external cluster, and to a netCDF file
   on a LocalCluster of two workers (the baseline: the default path, every chunk's values
   returned to the driver, kept as a part and written into the file). Both clusters
   are started before any clock runs and the runs alternate in pairs; the median of the pairs'
   ratios is reported.
2. Memory: ``bearing-sweep run -o x.zarr --scheduler ADDRESS`` in its own process, a smaller
   and a 4 times larger sweep; the peak resident memory of the driver (its rusage), of the
   scheduler and of each worker process (their high-water mark, reset before each run).
   Values never pass through the driver, and a worker holds one chunk at a time: no process
   may need more memory for the larger sweep (goal: a ratio of at most 1.1).

Every run is in chunks of 10000 points (half a second's work each; a large sweep's default
chunks are of a second). The projection to 1e8 points takes the timed zarr runs' median time per point (with
the store's fixed costs: an upper bound), and the driver's memory per chunk (the slope between
the two memory runs) for the 1e8 points' chunks.
"""
import contextlib
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import cloudpickle
import numpy as np
import psutil

from bearing_sweep import spec, stores
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.grid import Grid

BIN = Path(sys.executable).parent
DEFINITION = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "0.004 mm"
speed = "5000 rpm"
[axes]
radial_load = {{ start = "0.5 kN", stop = "12 kN", num = {loads} }}
clearance = {{ start = "0 mm", stop = "0.05 mm", num = 200 }}
"""
#: Load steps of the timed pairs, and of the smaller and larger memory runs (x 200 points).
TIMED, SMALL, LARGE = 400, 100, 400
#: Points per chunk of every run: half a second's work at crb_radial's declared cost, as the
#: default chunking makes them in a large sweep (``evaluate.CHUNK_SECONDS``: 20000 points).
CHUNK = 10000
PAIRS = 3
#: What the user guide asks of a cluster's workers: dask's nanny would otherwise set
#: MALLOC_TRIM_THRESHOLD_=65536, which doubles the model's time (see executor.Executor.connect).
WORKER_CONFIG = """
distributed:
  nanny:
    pre-spawn-environ:
      MALLOC_TRIM_THRESHOLD_: null
"""
PROJECTED_POINTS = 1e8


def free_port() -> int:
    with socket.socket() as listener:
        listener.bind(("127.0.0.1", 0))
        return listener.getsockname()[1]


@contextlib.contextmanager
def external_cluster(folder: Path):
    """A ``dask scheduler`` and two ``dask worker`` processes on 127.0.0.1; yields the address,
    the scheduler's process and the worker processes (the nannies' children)."""
    (folder / "dask").mkdir()
    (folder / "dask" / "workers.yaml").write_text(WORKER_CONFIG)
    environment = dict(os.environ, DASK_CONFIG=str(folder / "dask"))
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    quiet = dict(cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                 env=environment)
    dask = str(BIN / "dask")
    processes = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port",
                                   str(port), "--no-dashboard"], **quiet)]
    try:
        from distributed import Client

        processes += [subprocess.Popen([dask, "worker", address, "--nthreads", "1",
                                        "--no-dashboard"], **quiet) for _ in range(2)]
        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=120)
            workers = [psutil.Process(pid) for pid in client.run(os.getpid).values()]
        yield address, psutil.Process(processes[0].pid), workers
    finally:
        for process in reversed(processes):  # workers first, while their scheduler answers
            process.terminate()
        for process in processes:
            try:
                process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


def paired_times(folder: Path, address: str) -> tuple[np.ndarray, np.ndarray]:
    """Wall times [s] of the timed sweep to zarr on the external cluster and to netCDF on a
    LocalCluster of two, in interleaved pairs; both clusters are connected before."""
    sweep = spec.parse(DEFINITION.format(loads=TIMED), "timed.toml")
    times = {"zarr": [], "netcdf": []}
    with Executor(scheduler=address) as external, Executor(workers=2) as local:
        external.connect()
        local.connect()
        for _ in range(PAIRS):
            for kind, executor, output in (("zarr", external, "timed.zarr"),
                                           ("netcdf", local, "timed.nc")):
                if kind == "zarr":  # a store is never replaced: the last pair's goes first
                    shutil.rmtree(folder / output, ignore_errors=True)
                began = time.perf_counter()
                run_sweep(sweep, folder / output, executor, CHUNK, progress=False)
                times[kind].append(time.perf_counter() - began)
    a, b = (stores.open_result(folder / name) for name in ("timed.nc", "timed.zarr"))
    for name in a.data_vars:  # the same numbers, whatever the format and the cluster
        np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)
    return np.array(times["zarr"]), np.array(times["netcdf"])


def high_water_mark(process: psutil.Process) -> int:
    """The process's peak resident memory [B] since its mark was last reset."""
    for line in Path(f"/proc/{process.pid}/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) * 1024
    raise RuntimeError("no VmHWM in /proc: Linux only")


def reset_high_water_mark(process: psutil.Process):
    Path(f"/proc/{process.pid}/clear_refs").write_text("5")


def memory_run(folder: Path, address: str, loads: int, scheduler, workers) -> dict:
    """Run ``bearing-sweep run -o`` a zarr store of ``loads`` x 200 points on the cluster in a
    process of its own; its wall time [s] and every process's peak resident memory [B]."""
    name = f"memory{loads}"
    (folder / f"{name}.toml").write_text(DEFINITION.format(loads=loads))
    for process in [scheduler] + workers:
        reset_high_water_mark(process)
    began = time.perf_counter()
    driver = subprocess.Popen([sys.executable, "-m", "bearing_sweep", "run", f"{name}.toml",
                               "-o", f"{name}.zarr", "--scheduler", address, "--chunk-size",
                               str(CHUNK), "--quiet"],
                              cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(driver.pid, 0)
    seconds = time.perf_counter() - began
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(driver.stderr.read().decode())
    grid = Grid.from_sweep(spec.load(folder / f"{name}.toml"))
    return {"points": grid.size, "seconds": seconds, "chunks": chunk_count(grid),
            "driver": usage.ru_maxrss * 1024, "scheduler": high_water_mark(scheduler),
            **{f"worker {i + 1}": high_water_mark(w) for i, w in enumerate(workers)}}


def chunk_count(grid: Grid) -> int:
    """How many chunks of at most :data:`CHUNK` points a zarr output has."""
    return len(grid.chunks(CHUNK))


def main():
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        with external_cluster(folder) as (address, scheduler, workers):
            zarr_times, netcdf_times = paired_times(folder, address)
            load = os.getloadavg()
            small, large = (memory_run(folder, address, loads, scheduler, workers)
                            for loads in (SMALL, LARGE))
    points = TIMED * 200
    ratios = zarr_times / netcdf_times
    print(f"crb_radial to zarr on an external dask scheduler, 2 workers on 127.0.0.1 "
          f"({points} points in chunks of {CHUNK}, {PAIRS} interleaved pairs, load "
          f"average {load[0]:.1f})")
    print(f"  baseline, netCDF on a LocalCluster of 2 workers: median "
          f"{np.median(netcdf_times) / points * 1e6:.0f} us/point "
          f"({np.median(netcdf_times):.1f} s)")
    print(f"  zarr, external scheduler: median {np.median(zarr_times) / points * 1e6:.0f} "
          f"us/point ({np.median(zarr_times):.1f} s); identical numbers")
    print(f"  ratio: {np.median(ratios):.2f}x time per point (range {ratios.min():.2f}-"
          f"{ratios.max():.2f}; goal: at most 1.1x, values written by the workers)")

    print(f"crb_radial to zarr, peak resident memory per process, {small['points']} and "
          f"{large['points']} points")
    print(f"  baseline, the {small['points']}-point run ({small['chunks']} chunks of {CHUNK}): "
          f"{small['seconds']:.1f} s; the {large['points']}-point run ({large['chunks']} "
          f"chunks): {large['seconds']:.1f} s")
    processes = [key for key in small if key not in ("points", "seconds", "chunks")]
    for key in processes:
        print(f"  {key:<9} {small[key] / 2**20:6.0f} MiB -> {large[key] / 2**20:6.0f} MiB")
    growth = max(large[key] / small[key] for key in processes)
    print(f"  ratio: {growth:.2f}x peak memory of the larger run, worst process (goal: at most "
          f"1.1x: memory bounded)")

    per_point = np.median(zarr_times) / points  # with the store's fixed costs: an upper bound
    projected = Grid.from_sweep(spec.parse(DEFINITION.format(
        loads=round(PROJECTED_POINTS / 200)), "projected.toml"))
    chunks = chunk_count(projected)
    slope = max(0.0, (large["driver"] - small["driver"]) / (large["chunks"] - small["chunks"]))
    print(f"  projection to {PROJECTED_POINTS:.0e} points on these 2 workers: "
          f"{PROJECTED_POINTS * per_point / 3600:.1f} h ({per_point * 1e6:.0f} us/point; "
          f"N workers: x 2/N); {chunks} chunks; driver "
          f"{(large['driver'] + slope * (chunks - large['chunks'])) / 2**20:.0f} MiB at "
          f"{slope / 1024:.1f} KiB per chunk, each other process as measured; but each task "
          f"carries the grid, {len(cloudpickle.dumps(projected)) / 2**20:.1f} MiB pickled "
          f"here, in the driver and the scheduler while it is in flight")


if __name__ == "__main__":
    main()
