"""Speed-up of a large crb_radial sweep from one to two local dask workers.

The same sweep runs on a LocalCluster of one single-threaded worker process and on one of two;
each cluster is started before the clock starts, so the ratio measures the sweep itself
(scatter, tasks, gathering, writing the netCDF file). The machine's speed drifts by tens of
percent, so the runs alternate and the median of the pairs' ratios is reported (goal: at least
1.7).
"""
import tempfile
import time
from pathlib import Path

import numpy as np

from bearing_sweep import spec, store
from bearing_sweep.compute import Executor, run_sweep

DEFINITION = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "0.004 mm"
speed = "5000 rpm"
[axes]
radial_load = { start = "0.5 kN", stop = "12 kN", num = 400 }
clearance = { start = "0 mm", stop = "0.05 mm", num = 200 }
"""


def paired_times(folder: Path, pairs: int = 9):
    """Wall times on one and on two workers, run in interleaved pairs so that the machine's
    passing load falls on both alike; the clusters are started before any clock runs."""
    sweep = spec.parse(DEFINITION, "scaling.toml")
    times = {1: [], 2: []}
    with Executor(workers=1) as one, Executor(workers=2) as two:
        executors = {1: one, 2: two}
        for executor in executors.values():
            executor.connect()
        for _ in range(pairs):
            for workers, executor in executors.items():
                began = time.perf_counter()
                run_sweep(sweep, folder / f"w{workers}.nc", executor, progress=False)
                times[workers].append(time.perf_counter() - began)
    return np.array(times[1]), np.array(times[2])


def main():
    with tempfile.TemporaryDirectory() as folder:
        one, two = paired_times(Path(folder))
        a, b = (store.open_result(Path(folder) / f"w{w}.nc") for w in (1, 2))
    for name in a.data_vars:
        np.testing.assert_array_equal(a[name].values, b[name].values)
    ratios = one / two
    print(f"crb_radial sweep of {a.status.size} points, default chunking, LocalCluster, "
          f"{ratios.size} interleaved pairs")
    print(f"  1 worker:  median {np.median(one):5.2f} s (range {one.min():.2f}-{one.max():.2f})")
    print(f"  2 workers: median {np.median(two):5.2f} s (range {two.min():.2f}-{two.max():.2f})")
    print(f"  speed-up: median of pairs {np.median(ratios):.2f}x (range {ratios.min():.2f}-"
          f"{ratios.max():.2f}; goal 1.7x); identical results")


if __name__ == "__main__":
    main()
