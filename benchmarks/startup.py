"""Start-up: a 100-point sweep run from the command line, from a new process to its file.

For each of four models, ``bearing-sweep run sweep.toml -o out.nc --quiet`` in a new process
(interpreter, imports, definition, computing in-process, the netCDF file), timed by the wall
clock, alternating with the baseline: a new interpreter that imports numpy, the least any run
pays. The goal is the run itself under a second. crb_radial loads its compiled roller
balances (numba, about half a second); the others compute their first points without numba
(:mod:`models.kernels`). ``python benchmarks/startup.py PAIRS`` takes another number of pairs.
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PAIRS = 7
GOAL_SECONDS = 1.0
SWEEPS = {
    "hertz_point": """
[sweep]
model = "hertz_point"
[fixed]
curvature_1x = "0.2 1/mm"
curvature_1y = "0.2 1/mm"
curvature_2x = "-0.19 1/mm"
[axes]
load = { start = "10 N", stop = "3 kN", num = 50 }
curvature_2y = ["0 1/mm", "0.05 1/mm"]
""",
    "ball_5dof": """
[sweep]
model = "ball_5dof"
bearing = "paper001-71807AC"
[axes]
axial_load = { start = "300 N", stop = "3 kN", num = 25 }
radial_load = ["0 N", "400 N", "1 kN", "1.5 kN"]
""",
    "trb_load": """
[sweep]
model = "trb_load"
bearing = "paper003-table1"
[axes]
radial_load = { start = "10 kN", stop = "40 kN", num = 25 }
axial_load = ["27 kN", "35 kN", "42 kN", "50 kN"]
""",
    "crb_radial": """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "4 um"
speed = "6000 rpm"
[axes]
radial_load = { start = "0.5 kN", stop = "12 kN", num = 50 }
clearance = ["0 mm", "0.03 mm"]
""",
}


def wall(command, folder: Path) -> float:
    """Wall time [s] of ``command`` run in a new process in ``folder``."""
    began = time.perf_counter()
    subprocess.run(command, cwd=folder, check=True, capture_output=True)
    return time.perf_counter() - began


def main(pairs: int = PAIRS):
    baseline = [sys.executable, "-c", "import numpy"]
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        for model, text in SWEEPS.items():
            (folder / f"{model}.toml").write_text(text)
            run = [sys.executable, "-m", "bearing_sweep", "run", f"{model}.toml", "-o",
                   f"{model}.nc", "--quiet"]
            wall(run, folder)  # the first run on a machine compiles or caches what it may
            load = os.getloadavg()
            ours, theirs = [], []
            for _ in range(pairs):
                ours.append(wall(run, folder))
                theirs.append(wall(baseline, folder))
            ratios = [a / b for a, b in zip(ours, theirs)]
            seconds = statistics.median(ours)
            print(f"start-up, 100-point {model} sweep from the command line, in-process")
            print(f"  baseline: a new interpreter importing numpy, "
                  f"{statistics.median(theirs):.3f} s")
            print(f"  ratio: {statistics.median(ratios):.2f}x (goal: the run under "
                  f"{GOAL_SECONDS:.0f} s: {seconds:.2f} s, runs {min(ours):.2f}-{max(ours):.2f} "
                  f"s, {'met' if seconds < GOAL_SECONDS else 'not met'}); load average "
                  f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:2]))
