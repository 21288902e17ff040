"""crb_runout against a per-step scipy.optimize implementation of the same model.

One 14-roller NU208 (paper 004, Table 1) with roller size errors and an even roundness
order, 3 revolutions at 3600 steps each. Baseline: for each step, scipy.optimize.linprog
(HiGHS) finds the lowest inner-ring centre under the same linear no-penetration conditions
of the lower rollers; this is how the model is written one step at a time. Both run on one
core; the heights must agree to 1e-4 um and the runout to 1e-3 um. Prints the time of each
and their ratio (goal: at least 50).
"""
import time

import numpy as np
from scipy.optimize import linprog

from bearing_sweep.models.runout import crb_runout, roller_angles

MM, UM = 1e-3, 1e-6
BEARING = dict(inner_raceway_diameter=49.481 * MM, outer_raceway_diameter=71.555 * MM,
               roller_diameter=10.9985 * MM, roller_count=14)
ERRORS = np.array([0.1, 1.4, 0.2, 1.3, 0.3, 1.2, 0.4, 1.1, 0.5, 1.0, 0.6, 0.9, 0.7, 0.8]) * UM
ROUNDNESS = dict(order=4, amplitude=0.5 * UM, phase=0.0)
REVOLUTIONS, STEPS = 3, 3600


def per_step(rotation):
    """Lowest centre at one rotation step by linear programming, in micrometres."""
    di, de, d = (BEARING[k] for k in ("inner_raceway_diameter", "outer_raceway_diameter",
                                      "roller_diameter"))
    azimuth, spin = roller_angles(rotation, 14, d, 0.5 * (di + de))
    harmonic = ROUNDNESS["amplitude"] * (
        np.cos(ROUNDNESS["order"] * (azimuth + spin) + ROUNDNESS["phase"])
        + np.cos(ROUNDNESS["order"] * (azimuth + np.pi + spin) + ROUNDNESS["phase"]))
    room = 0.5 * (de - di) - d - ERRORS - harmonic
    lower = np.sin(azimuth) < -1e-9
    bounds = np.column_stack([np.cos(azimuth), np.sin(azimuth)])[lower]
    solution = linprog([0.0, 1.0], A_ub=bounds, b_ub=room[lower] / UM,
                       bounds=[(None, None), (None, None)], method="highs")
    return solution.x


def main():
    rotation = 2 * np.pi * np.arange(REVOLUTIONS * STEPS) / STEPS
    began = time.perf_counter()
    baseline = np.array([per_step(angle) for angle in rotation])
    baseline_seconds = time.perf_counter() - began

    best = np.inf
    for _ in range(3):
        began = time.perf_counter()
        result = crb_runout(**BEARING, roller_diameter_error=ERRORS,
                            roller_roundness_order=ROUNDNESS["order"],
                            roller_roundness_amplitude=ROUNDNESS["amplitude"],
                            roller_roundness_phase=ROUNDNESS["phase"],
                            revolutions=REVOLUTIONS, steps_per_revolution=STEPS)
        best = min(best, time.perf_counter() - began)

    assert result["status"][0] == 0
    height = result["center_y"][0] / UM
    assert np.abs(height - baseline[:, 1]).max() < 1e-4, "heights differ"
    distance = np.hypot(*baseline.T)
    assert abs(result["runout"][0] / UM - (distance.max() - distance.min())) < 1e-3
    steps = rotation.size
    print(f"crb_runout, one NU208 over {REVOLUTIONS} revolutions of {STEPS} steps "
          f"({steps} steps)")
    print(f"  baseline, scipy.optimize.linprog per step: {baseline_seconds:7.2f} s "
          f"({1e3 * baseline_seconds / steps:.3f} ms/step)")
    print(f"  crb_runout, all steps at once:             {best:7.3f} s")
    print(f"  ratio: {baseline_seconds / best:.0f}x (goal: at least 50x)")


if __name__ == "__main__":
    main()
