"""crb_runout through the engine against a compiled per-point kernel and a per-step scipy solve.

Kernel (baseline): written here with numba (numpy's error model: no zero-division checks),
crb_runout for one bearing at a time and one rotation step after another: the rollers' azimuths
and spins (paper 004 eq. 1-3, spin in the translating frame), each lower roller's room along
its radius line between the raceways (eq. 4-6), and the inner-ring centre at the lowest vertex
of the upper envelope of those lines, found as the model finds it (every falling-rising pair, a
vertex only where no third line lies above it, lines within 1e-13 m meeting); then the runout
(largest minus smallest centre distance) and the vertical runout.

Scipy baseline: crb_runout_throughput.py's per-step ``scipy.optimize.linprog`` (reused), on
the grid's point that has its roller errors, roundness order 4 and phase 0.

Model: ``crb_runout`` through the engine's chunk evaluation on a Grid, in blocks of its
declared ``points_per_call``: all a sweep computes (inputs, units, status).

Points: the NU208 of paper 004 (catalogue preset) with crb_runout_throughput.py's roller size
errors and a roller roundness of 0.5 um, its order 2-5 against four phase draws, one
revolution of 360 steps. One core, pairs interleaved, the median of the pairs' ratios with the
load average. Centres and runouts must agree to 1e-6 um.
"""
import math
import sys
import time
from pathlib import Path

import numpy as np
from numba import njit

from bearing_sweep import spec
from bearing_sweep.evaluate import evaluate_chunk
from bearing_sweep.grid import Grid
from bearing_sweep.models.runout import MODELS

sys.path.insert(0, str(Path(__file__).parent))
from crb_runout_throughput import ERRORS, ROUNDNESS, per_step  # noqa: E402 (scipy baseline)
from pairs import interleaved, ratio_line  # noqa: E402

UM = 1e-6
STEPS = 360
DEFINITION = f"""
[sweep]
model = "crb_runout"
bearing = "paper004-NU208-1"
[fixed]
roller_diameter_error = {{ values = [{", ".join(f"{e / UM:.6g}" for e in ERRORS)}], units = "um" }}
roller_roundness_amplitude = "{ROUNDNESS['amplitude'] / UM} um"
revolutions = 1
steps_per_revolution = {STEPS}
[axes]
roller_roundness_order = [2, 3, 4, 5]
phase_seed = [0, 1, 2, 3]
"""
TIE = 1e-13  # [m], crb_runout's lines that meet
AGREEMENT = 1e-6  # [um]


@njit(cache=True, error_model="numpy")
def kernel(inner, outer, diameter, error, order, amplitude, phase, steps):
    """Centre x, y (N, S) [m], runout and vertical runout (N,) of every bearing."""
    count, rollers = error.shape
    pitch = 0.5 * (inner + outer)
    ratio = diameter / pitch
    centre_x, centre_y = np.zeros((count, steps)), np.zeros((count, steps))
    runout, vertical = np.zeros(count), np.zeros(count)
    slope, intercept = np.zeros(rollers), np.zeros(rollers)
    active = np.zeros(rollers, dtype=np.bool_)
    for p in range(count):
        for s in range(steps):
            rotation = 2.0 * math.pi * s / steps
            orbit = 0.5 * rotation * (1.0 - ratio)
            spin = (1.0 / ratio - ratio) * 0.5 * rotation - orbit
            for j in range(rollers):
                azimuth = 2.0 * math.pi * j / rollers + orbit
                radius_out = 0.5 * (diameter + error[p, j]) + amplitude[p, j] * math.cos(
                    order[p, j] * (azimuth + spin) + phase[p, j])
                radius_in = 0.5 * (diameter + error[p, j]) + amplitude[p, j] * math.cos(
                    order[p, j] * (azimuth + math.pi + spin) + phase[p, j])
                room = 0.5 * outer - radius_out - radius_in - 0.5 * inner
                down = math.sin(azimuth)
                active[j] = down < -1e-9
                slope[j] = -math.cos(azimuth) / down if active[j] else 0.0
                intercept[j] = room / down if active[j] else 0.0
            best_x, best_y = np.nan, np.inf
            for left in range(rollers):
                if not (active[left] and slope[left] <= 0.0):
                    continue
                for right in range(rollers):
                    if not (active[right] and slope[right] >= 0.0
                            and slope[right] > slope[left]):
                        continue
                    x = (intercept[left] - intercept[right]) / (slope[right] - slope[left])
                    envelope = -np.inf
                    for j in range(rollers):
                        if active[j]:
                            envelope = max(envelope, slope[j] * x + intercept[j])
                    if envelope <= slope[left] * x + intercept[left] + TIE \
                            and envelope < best_y:
                        best_x, best_y = x, envelope
            centre_x[p, s], centre_y[p, s] = best_x, best_y
        distance = np.hypot(centre_x[p], centre_y[p])
        runout[p] = distance.max() - distance.min()
        vertical[p] = centre_y[p].max() - centre_y[p].min()
    return centre_x, centre_y, runout, vertical


def main():
    model = MODELS[0]
    grid = Grid.from_sweep(spec.parse(DEFINITION, "crb_runout_kernel.toml"))
    points, _ = grid.inputs(0, grid.size)
    fixed = grid.fixed
    rollers = int(fixed["roller_count"])
    seeds = points["phase_seed"]
    phase = np.array([np.random.default_rng(seed).uniform(0.0, 2.0 * np.pi, rollers)
                      if seed else np.zeros(rollers) for seed in seeds])
    order = np.broadcast_to(points["roller_roundness_order"], (grid.size, rollers))
    arrays = dict(error=np.tile(fixed["roller_diameter_error"], (grid.size, 1)),
                  order=np.ascontiguousarray(order, dtype=float),
                  amplitude=np.full((grid.size, rollers), ROUNDNESS["amplitude"]), phase=phase)
    bearing = dict(inner=float(fixed["inner_raceway_diameter"]),
                   outer=float(fixed["outer_raceway_diameter"]),
                   diameter=float(fixed["roller_diameter"]), steps=STEPS)

    def run_model():
        return evaluate_chunk(grid, 0, grid.size)

    def run_kernel():
        return kernel(**bearing, **arrays)

    result, compiled = run_model(), run_kernel()  # first calls: imports, compilation
    outputs = result["outputs"]
    assert np.all(result["status"] == 0)
    worst = max(np.abs(outputs["center_x"] - compiled[0] / UM).max(),
                np.abs(outputs["center_y"] - compiled[1] / UM).max(),
                np.abs(outputs["runout"] - compiled[2] / UM).max(),
                np.abs(outputs["vertical_runout"] - compiled[3] / UM).max())
    assert worst < AGREEMENT, f"model and kernel differ by {worst:.1e} um"

    timing = interleaved(run_model, run_kernel)
    model_seconds, kernel_seconds = timing[3] / grid.size, timing[4] / grid.size
    print(f"crb_runout against a compiled per-point kernel ({grid.size} bearings of {STEPS} "
          f"steps, {model.points_per_call} per call, NU208)")
    print(f"  baseline, numba kernel per bearing: {1e3 * kernel_seconds:7.2f} ms")
    print(f"  crb_runout through the engine:      {1e3 * model_seconds:7.2f} ms; "
          f"largest difference {worst:.1e} um")
    print(ratio_line(timing, "measured"))

    chosen = np.flatnonzero((order[:, 0] == ROUNDNESS["order"])
                            & (seeds == 0))[0]
    rotation = 2 * np.pi * np.arange(STEPS) / STEPS
    began = time.perf_counter()
    baseline = np.array([per_step(angle) for angle in rotation])
    scipy_seconds = time.perf_counter() - began
    scipy_worst = np.abs(baseline[:, 1] - compiled[1][chosen] / UM).max()
    assert scipy_worst < 1e-4, f"kernel and scipy heights differ by {scipy_worst:.1e} um"
    print(f"crb_runout and its kernel against the per-step scipy baseline (one bearing of "
          f"{STEPS} steps)")
    print(f"  baseline, scipy.optimize.linprog per step: {1e3 * scipy_seconds:7.1f} ms")
    print(f"  kernel {scipy_seconds / kernel_seconds:.0f}x faster; largest height difference "
          f"{scipy_worst:.1e} um")
    print(f"  ratio: {scipy_seconds / model_seconds:.0f}x scipy over crb_runout (goal: measured)")


if __name__ == "__main__":
    main()
