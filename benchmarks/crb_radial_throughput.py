"""crb_radial grid throughput against a plain per-point scipy.optimize implementation.

Baseline: for each grid point, brentq on the radial displacement, with brentq per roller for the
split of its approach between the inner and outer contacts, and the slice sums in numpy; this is
how the model is written without vectorising across points, solved to the model's tolerance
(1e-13 relative). Both run on one core, on the same grid (bearing D of paper 000, crowned
rollers, 60 slices, speed, clearance); the answers must agree to 1e-6. Prints the time per
point of each and their ratio (goal: at least 50).

Then the command end to end: ``bearing-sweep run`` on two local workers over 200 000 points of
the same bearing (wall time from the command's start to its finished netCDF file, the
cluster's start included) against the scalar baseline's CPU time per point on a sample of
them, scaled to the whole grid (goal: at least 30x). ``python
benchmarks/crb_radial_throughput.py POINTS`` runs the command on another size.
"""
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.optimize import brentq

from bearing_sweep.models.contact import palmgren_constant
from bearing_sweep.models.cylindrical import centrifugal_force, crb_radial
from bearing_sweep.models.profiles import crown_shape

MM, RPM, N = 1e-3, 2 * np.pi / 60, 10 / 9
XTOL = 1e-13  # relative tolerance of every solve, as the model's
CLI_POINTS, CLI_WORKERS, CLI_LOADS = 200_000, 2, 25_000
CLI_SAMPLE = 16  # points of the command's grid the scalar baseline solves
CLI_DEFINITION = """[sweep]
model = "crb_radial"
[fixed]
roller_count = 14
pitch_diameter = "65 mm"
roller_diameter = "10 mm"
effective_length = "9.6 mm"
crown = "4 um"
speed = "5000 rpm"
slices = 60
[axes]
radial_load = {{ start = "1 kN", stop = "12 kN", num = {loads} }}
clearance = {{ start = "0 mm", stop = "0.04 mm", num = {clearances} }}
"""
GEOMETRY = dict(roller_count=14, pitch_diameter=65 * MM, roller_diameter=10 * MM,
                effective_length=9.6 * MM)


def per_point(load, clearance, crown, speed, slices, roller_count, pitch_diameter,
              roller_diameter, effective_length):
    """Radial displacement and stiffness of one bearing, point by point with scipy."""
    constant = palmgren_constant(effective_length)
    gaps = crown * crown_shape(slices)
    fc = centrifugal_force(roller_diameter, effective_length, pitch_diameter, speed, 7850.0)
    phi = 2 * np.pi * np.arange(roller_count) / roller_count

    def q(d):
        return constant / slices * np.sum(np.maximum(d - gaps, 0) ** N)

    def dq(d):
        return constant * N / slices * np.sum(np.maximum(d - gaps, 0) ** (N - 1))

    free = brentq(lambda y: q(y) - fc, 0, 1e-3, xtol=1e-20, rtol=XTOL) if fc > 0 else 0.0

    def roller(total):
        if total <= free:
            return 0.0, 0.0
        x = brentq(lambda x: q(x) + fc - q(total - x), 0, total - free, xtol=1e-20, rtol=XTOL)
        ki, ko = dq(x), dq(total - x)
        return q(x), ki * ko / (ki + ko)

    def radial_load(d):
        return sum(roller(d * np.cos(p) - clearance / 2)[0] * np.cos(p) for p in phi)

    upper = clearance / 2 + 1e-6
    while radial_load(upper) < load:
        upper *= 2
    d = brentq(lambda d: radial_load(d) - load, max(clearance / 2, 0), upper, xtol=1e-20,
               rtol=XTOL)
    return d, sum(roller(d * np.cos(p) - clearance / 2)[1] * np.cos(p) ** 2 for p in phi)


def main():
    load, clearance = np.meshgrid(np.linspace(1000, 12000, 16), np.linspace(0, 0.04, 8) * MM)
    load, clearance = load.ravel(), clearance.ravel()
    common = dict(crown=0.004 * MM, speed=5000 * RPM, slices=60)

    began = time.perf_counter()
    baseline = np.array([per_point(f, c, **common, **GEOMETRY) for f, c in zip(load, clearance)])
    baseline_seconds = (time.perf_counter() - began) / load.size

    repeats = 20
    grid_load, grid_clearance = np.tile(load, repeats), np.tile(clearance, repeats)
    best = np.inf
    for _ in range(3):
        began = time.perf_counter()
        result = crb_radial(grid_load, clearance=grid_clearance, **common, **GEOMETRY)
        best = min(best, (time.perf_counter() - began) / grid_load.size)

    assert np.all(result["status"] == 0)
    displacement = result["radial_displacement"][:load.size]
    stiffness = result["radial_stiffness"][:load.size]
    worst = max(np.max(np.abs(displacement / baseline[:, 0] - 1)),
                np.max(np.abs(stiffness / baseline[:, 1] - 1)))
    assert worst < 1e-6, f"answers differ by {worst:.2e}"
    print(f"crb_radial throughput, {load.size} points (bearing D, k = 60, crown, speed, clearance)")
    print(f"  per-point scipy baseline: {baseline_seconds * 1e3:8.3f} ms/point")
    print(f"  vectorised crb_radial:    {best * 1e3:8.3f} ms/point ({grid_load.size} per call)")
    print(f"  ratio: {baseline_seconds / best:.0f}x (goal 50x); largest difference {worst:.1e}")
    command_end_to_end(int(sys.argv[1]) if len(sys.argv) > 1 else CLI_POINTS, common)


def command_end_to_end(points: int, common: dict):
    """``bearing-sweep run`` on two local workers against the scalar baseline."""
    clearances = max(points // CLI_LOADS, 2)
    loads = points // clearances
    grid_load = np.linspace(1000, 12000, loads)
    grid_clearance = np.linspace(0, 0.04, clearances) * MM
    sample = np.linspace(0, loads * clearances - 1, CLI_SAMPLE).astype(int)
    began = time.process_time()
    for i in sample:
        per_point(grid_load[i // clearances], grid_clearance[i % clearances], **common,
                  **GEOMETRY)
    scalar = (time.process_time() - began) / sample.size
    load = os.getloadavg()
    with tempfile.TemporaryDirectory() as folder:
        definition = os.path.join(folder, "crb.toml")
        with open(definition, "w") as file:
            file.write(CLI_DEFINITION.format(loads=loads, clearances=clearances))
        began, used = time.perf_counter(), _children_seconds()
        subprocess.run([sys.executable, "-m", "bearing_sweep", "run", definition, "-o",
                        os.path.join(folder, "crb.nc"), "--workers", str(CLI_WORKERS),
                        "--quiet"], check=True, capture_output=True)
        wall, cpu = time.perf_counter() - began, _children_seconds() - used
    total = loads * clearances
    print(f"crb_radial through the command on {CLI_WORKERS} local workers, {total} points "
          "(bearing D, k = 60, crown, speed, clearance), against the scalar solver")
    print(f"  per-point scipy baseline: {scalar * 1e3:.2f} ms/point (CPU, {sample.size} of "
          f"the points, scaled to {total}); command: {wall:.1f} s wall, "
          f"{wall / total * 1e6:.1f} us/point, {cpu / total * 1e6:.1f} us/point of CPU (the "
          f"command and its workers; {CLI_WORKERS} idle cores would take about "
          f"{cpu / CLI_WORKERS:.1f} s wall, a ratio of {scalar * total * CLI_WORKERS / cpu:.0f}x)")
    print(f"  ratio: {scalar * total / wall:.0f}x (goal: at least 30x); load average "
          f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")


def _children_seconds() -> float:
    """CPU seconds of this process's finished children and theirs (the workers)."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


if __name__ == "__main__":
    main()
