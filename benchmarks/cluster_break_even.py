"""Where a sweep becomes worth a local cluster: wall time in-process against a fresh
LocalCluster of two, over sweep sizes.

crb_radial sweeps of 4e3 to 1.28e5 points run in-process and on a LocalCluster of two
single-threaded workers started for the run (as the command starts it: in the background,
and closed at the end), in interleaved pairs, each from the parsed definition to the written
file. The cluster's time is nearly a fixed start plus a fraction of the in-process time; where
the medians first cross (interpolated between the two sizes around it) is the break-even, in
seconds of in-process time, which ``executor.IN_PROCESS_SECONDS`` (estimated single-core seconds, from the declared cost)
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
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.executor import IN_PROCESS_SECONDS
from worker_scaling import BUSY, DEFINITION  # the same crb_radial sweep, by its size

SIZES = (4_000, 8_000, 16_000, 32_000, 64_000, 128_000)
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
    print(f"in-process against a fresh LocalCluster of two: crb_radial sweeps of "
          f"{SIZES[0]}-{SIZES[-1]} points, {pairs} interleaved pairs each")
    for size, one, two in zip(SIZES, alone, cluster):
        print(f"  {size:6d} points: in-process {one:6.2f} s, cluster {two:6.2f} s")
    print(f"  load average {before:.2f} before, {os.getloadavg()[0]:.2f} after, on "
          f"{os.cpu_count()} cores" + ("; machine too busy to measure" if before > BUSY else ""))
    break_even = crossing(alone, cluster)
    if break_even is None:
        print(f"  measured baseline: no break-even up to {max(alone):.2f} s of in-process time")
        print(f"  ratio: <{IN_PROCESS_SECONDS / max(alone):.2f}x IN_PROCESS_SECONDS = "
              f"{IN_PROCESS_SECONDS:g} s over the break-even (goal: 0.5x to 2x)")
        return
    print(f"  measured baseline: break-even at {break_even:.2f} s of in-process time")
    print(f"  ratio: {IN_PROCESS_SECONDS / break_even:.2f}x IN_PROCESS_SECONDS = "
          f"{IN_PROCESS_SECONDS:g} s over the break-even (goal: 0.5x to 2x)")


def crossing(alone, cluster):
    """The in-process time at which the cluster first becomes faster, interpolated linearly
    between the sizes around it; None if it never does."""
    gain = np.array(alone) - np.array(cluster)
    later = np.flatnonzero(gain > 0)
    if later.size == 0:
        return None
    i = later[0]
    if i == 0:
        return alone[0]
    return alone[i - 1] + (alone[i] - alone[i - 1]) * -gain[i - 1] / (gain[i] - gain[i - 1])

if __name__ == "__main__":
    main(*(int(argument) for argument in sys.argv[1:2]))
