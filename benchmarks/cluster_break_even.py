"""Where a sweep becomes worth a local cluster: wall time in-process against a fresh
LocalCluster of two, over sweep sizes.

crb_radial sweeps of 2e3 to 6.4e4 points run in-process and on a LocalCluster of two
single-threaded workers started for the run (as the command starts it: in the background,
and closed at the end), in interleaved pairs, each from the parsed definition to the written
file. The cluster's time is nearly a fixed start plus a fraction of the in-process time; the
line through the medians gives the in-process time at which both are equal: the break-even,
which ``compute.IN_PROCESS_SECONDS`` (estimated single-core seconds, from the declared cost)
should match. Prints the declared threshold over the measured break-even (goal: 0.5x to
2x), with the machine's load average: a busy machine starts and feeds the cluster slower
(it says "machine too busy to measure" when others' load exceeds half a core).
"""
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from bearing_sweep import spec
from bearing_sweep.compute import IN_PROCESS_SECONDS, Executor, run_sweep
from worker_scaling import BUSY, DEFINITION  # the same crb_radial sweep, by its size

SIZES = (2_000, 4_000, 8_000, 16_000, 32_000, 64_000)
PAIRS = 2


def timed(sweep, output: Path, workers: int) -> float:
    began = time.perf_counter()
    with Executor(workers=workers) as executor:
        run_sweep(sweep, output, executor, progress=False)
    return time.perf_counter() - began


def main(pairs: int = PAIRS):
    before = os.getloadavg()[0]
    alone, cluster = [], []
    with tempfile.TemporaryDirectory() as folder:
        for size in SIZES:
            sweep = spec.parse(DEFINITION.format(loads=size // 1000), "break_even.toml")
            times = np.array([(timed(sweep, Path(folder) / "a.nc", 0),
                               timed(sweep, Path(folder) / "c.nc", 2)) for _ in range(pairs)])
            alone.append(np.median(times[:, 0]))
            cluster.append(np.median(times[:, 1]))
    slope, start = np.polyfit(alone, cluster, 1)  # cluster time = start + slope * in-process
    print(f"in-process against a fresh LocalCluster of two: crb_radial sweeps of "
          f"{SIZES[0]}-{SIZES[-1]} points, {pairs} interleaved pairs each")
    for size, one, two in zip(SIZES, alone, cluster):
        print(f"  {size:6d} points: in-process {one:6.2f} s, cluster {two:6.2f} s")
    after = os.getloadavg()[0]
    print(f"  cluster = {start:.2f} s + {slope:.2f} x in-process; load average {before:.2f} "
          f"before, {after:.2f} after, on {os.cpu_count()} cores"
          + ("; machine too busy to measure" if before > BUSY else ""))
    if slope < 1 and start > 0:
        break_even = start / (1.0 - slope)
        print(f"  measured baseline: break-even at {break_even:.2f} s of in-process time")
        print(f"  ratio: {IN_PROCESS_SECONDS / break_even:.2f}x IN_PROCESS_SECONDS = "
              f"{IN_PROCESS_SECONDS:g} s over the break-even (goal: 0.5x to 2x)")
    else:  # the cluster never caught up: the break-even lies beyond the largest size
        print(f"  measured baseline: no break-even up to {max(alone):.2f} s of in-process time")
        print(f"  ratio: <{IN_PROCESS_SECONDS / max(alone):.2f}x IN_PROCESS_SECONDS = "
              f"{IN_PROCESS_SECONDS:g} s over the break-even (goal: 0.5x to 2x)")

if __name__ == "__main__":
    main(*(int(argument) for argument in sys.argv[1:2]))
