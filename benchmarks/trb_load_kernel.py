"""trb_load through the engine against a compiled per-point kernel and a per-point scipy solve.

Kernel (baseline): written here with numba (numpy's error model: no zero-division checks),
trb_load for one point at a time: roller ``i`` compressed by ``delta_r cos(psi_i) cos(alpha) +
delta_a sin(alpha)``, ``Q_i = K delta_i^1.11`` (paper 003 eq. 13-18), the same start
(``delta_a`` of eq. 15, every roller loaded alike by ``F_a``, with ``delta_r = delta_a
tan(alpha) / 2``), the same damped Newton iteration (damping 1 % of the start's stiffness,
times 0.2 on a step taken and 5 on one refused), the same tolerance (residual within 1e-12 of
the load) and at most 200 iterations; then the roller loads and cone contact pressures at the
solution (``p0 = (Q/l E* sum(rho) / pi)^(1/2)``, the bearing's ``E*`` and curvature sum
computed once).

Scipy baseline: ``scipy.optimize.root`` (MINPACK hybrid method) per point on the same two
equations with the analytic Jacobian, from the same start.

Model: ``trb_load`` through the engine's chunk evaluation on a Grid, in blocks of its
declared ``points_per_call``: all a sweep computes (status, pressures, rating lives, units).

Points: the tapered roller bearing of paper 003 (catalogue preset) under radial 5-40 kN and
axial 27-80 kN, repeated to the declared block. One core, pairs interleaved, the median of the
pairs' ratios with the load average. Answers must agree to 1e-9 (kernel; largest relative
difference printed) and 1e-7 (scipy).
"""
import math
import sys
import time
from pathlib import Path

import numpy as np
from numba import njit
from scipy.optimize import root

from bearing_sweep import spec
from bearing_sweep.evaluate import evaluate_chunk
from bearing_sweep.grid import Grid
from bearing_sweep.models.contact import effective_modulus
from bearing_sweep.models.tapered import (LOAD_EXPONENT, MODELS, cone_curvature_sum,
                                          paper_contact_constant)

sys.path.insert(0, str(Path(__file__).parent))
from ball_5dof_kernel import largest_difference  # noqa: E402
from declared_costs import repeated  # noqa: E402
from pairs import interleaved, ratio_line  # noqa: E402

DEFINITION = """
[sweep]
model = "trb_load"
bearing = "paper003-table1"
[axes]
radial_load = { start = "5 kN", stop = "40 kN", num = 8 }
axial_load = { start = "27 kN", stop = "80 kN", num = 16 }
"""
TOLERANCE = 1e-12  # trb_load's residual tolerance, relative to the load
MAX_ITERATIONS = 200
SCIPY_POINTS = 128


@njit(cache=True, error_model="numpy")
def reaction(x_r, x_a, rows, constant):
    """Force (r, a) and stiffness (rr, ra, aa) the rollers put on the ring at (x_r, x_a)."""
    n = LOAD_EXPONENT
    f_r = f_a = k_rr = k_ra = k_aa = 0.0
    for i in range(rows.shape[0]):
        delta = max(rows[i, 0] * x_r + rows[i, 1] * x_a, 0.0)
        q = constant * delta ** n
        k = n * constant * delta ** (n - 1.0)
        f_r += q * rows[i, 0]
        f_a += q * rows[i, 1]
        k_rr += k * rows[i, 0] * rows[i, 0]
        k_ra += k * rows[i, 0] * rows[i, 1]
        k_aa += k * rows[i, 1] * rows[i, 1]
    return f_r, f_a, k_rr, k_ra, k_aa


@njit(cache=True, error_model="numpy")
def kernel(radial, axial, roller_count, constant, angle, length, curvature, modulus):
    """Displacements (N, 2), roller loads and pressures (N, Z) and convergence per point."""
    count, n = radial.size, LOAD_EXPONENT
    rows = np.empty((roller_count, 2))
    for i in range(roller_count):
        rows[i, 0] = math.cos(angle) * math.cos(2.0 * math.pi * i / roller_count)
        rows[i, 1] = math.sin(angle)
    displacement = np.zeros((count, 2))
    roller_load, pressure = np.zeros((count, roller_count)), np.zeros((count, roller_count))
    converged = np.zeros(count, dtype=np.bool_)
    for p in range(count):
        start_a = (axial[p] / (roller_count * constant * math.sin(angle) ** (n + 1.0))) ** (1 / n)
        x_r, x_a = 0.5 * start_a * math.tan(angle), start_a
        mu = 0.01 * n * roller_count * constant * start_a ** (n - 1.0)
        tolerance = TOLERANCE * math.sqrt(radial[p] ** 2 + axial[p] ** 2)
        f_r, f_a, k_rr, k_ra, k_aa = reaction(x_r, x_a, rows, constant)
        r_r, r_a = radial[p] - f_r, axial[p] - f_a
        norm = math.sqrt(r_r * r_r + r_a * r_a)
        for _ in range(MAX_ITERATIONS):
            if not norm > tolerance:
                break
            a, c = k_rr + mu, k_aa + mu
            det = a * c - k_ra * k_ra
            t_r = x_r + (c * r_r - k_ra * r_a) / det
            t_a = x_a + (a * r_a - k_ra * r_r) / det
            f_r, f_a, t_rr, t_ra, t_aa = reaction(t_r, t_a, rows, constant)
            s_r, s_a = radial[p] - f_r, axial[p] - f_a
            trial_norm = math.sqrt(s_r * s_r + s_a * s_a)
            if trial_norm <= norm:
                x_r, x_a, r_r, r_a, norm = t_r, t_a, s_r, s_a, trial_norm
                k_rr, k_ra, k_aa = t_rr, t_ra, t_aa
                mu *= 0.2
            else:
                mu *= 5.0
        converged[p] = norm <= tolerance
        displacement[p, 0], displacement[p, 1] = x_r, x_a
        for i in range(roller_count):
            q = constant * max(rows[i, 0] * x_r + rows[i, 1] * x_a, 0.0) ** n
            roller_load[p, i] = q
            pressure[p, i] = math.sqrt(q / length * modulus * curvature / math.pi)
    return displacement, roller_load, pressure, converged


def per_point(radial, axial, roller_count, constant, angle):
    """Displacements of one bearing by scipy.optimize.root, from trb_load's start."""
    n = LOAD_EXPONENT
    rows = np.stack([np.cos(angle) * np.cos(2 * np.pi * np.arange(roller_count) / roller_count),
                     np.full(roller_count, np.sin(angle))], 1)

    def residual(x):
        return rows.T @ (constant * np.maximum(rows @ x, 0.0) ** n) - [radial, axial]

    def jacobian(x):
        return (rows.T * (n * constant * np.maximum(rows @ x, 0.0) ** (n - 1.0))) @ rows

    start_a = (axial / (roller_count * constant * np.sin(angle) ** (n + 1.0))) ** (1 / n)
    solution = root(residual, [0.5 * start_a * np.tan(angle), start_a], jac=jacobian,
                    method="hybr", options={"xtol": 1e-12})
    return solution.x if solution.success else np.full(2, np.nan)


def main():
    model = MODELS[0]
    grid = repeated(Grid.from_sweep(spec.parse(DEFINITION, "trb_load_kernel.toml")),
                    model.points_per_call)
    points, _ = grid.inputs(0, grid.size)
    fixed = grid.fixed
    bearing = dict(roller_count=fixed["roller_count"],
                   constant=float(paper_contact_constant(fixed["effective_length"],
                                                         fixed["roller_mean_diameter"])),
                   angle=fixed["outer_contact_angle"])
    terms = dict(**bearing, length=fixed["effective_length"],
                 curvature=float(cone_curvature_sum(fixed["roller_mean_diameter"],
                                                    fixed["pitch_diameter"],
                                                    fixed["outer_contact_angle"])),
                 modulus=float(effective_modulus(fixed["youngs_modulus"],
                                                 fixed["poisson_ratio"])))
    radial, axial = points["radial_load"], points["axial_load"]

    def run_model():
        return evaluate_chunk(grid, 0, grid.size)

    def run_kernel():
        return kernel(radial, axial, **terms)

    result, compiled = run_model(), run_kernel()  # first calls: imports, compilation
    outputs = result["outputs"]
    assert np.all(result["status"] == 0) and compiled[-1].all()
    ours = np.stack([outputs["radial_displacement"], outputs["axial_displacement"]], 1) * 1e-3
    worst = max(largest_difference(ours, compiled[0]),
                largest_difference(outputs["roller_load"], compiled[1]),
                largest_difference(outputs["max_contact_pressure"] * 1e6, compiled[2]))
    assert worst < 1e-9, f"model and kernel differ by {worst:.1e}"

    timing = interleaved(run_model, run_kernel)
    model_seconds, kernel_seconds = timing[3] / grid.size, timing[4] / grid.size
    print(f"trb_load against a compiled per-point kernel ({grid.size} points per call, "
          "paper 003's bearing)")
    print(f"  baseline, numba kernel per point: {1e6 * kernel_seconds:7.2f} us/point")
    print(f"  trb_load through the engine:      {1e6 * model_seconds:7.2f} us/point; "
          f"largest relative difference {worst:.1e}")
    print(ratio_line(timing, "within 1.5x"))

    began = time.perf_counter()
    baseline = np.array([per_point(radial[i], axial[i], **bearing)
                         for i in range(SCIPY_POINTS)])
    scipy_seconds = (time.perf_counter() - began) / SCIPY_POINTS
    solved = np.isfinite(baseline[:, 0])
    scipy_worst = largest_difference(compiled[0][:SCIPY_POINTS][solved], baseline[solved])
    assert scipy_worst < 1e-7, f"kernel and scipy differ by {scipy_worst:.1e}"
    print(f"trb_load and its kernel against a per-point scipy baseline ({SCIPY_POINTS} points)")
    print(f"  baseline, scipy.optimize.root per point: {1e6 * scipy_seconds:9.1f} us/point "
          f"({np.count_nonzero(~solved)} of {SCIPY_POINTS} points not solved by it)")
    print(f"  kernel {scipy_seconds / kernel_seconds:.0f}x faster; "
          f"largest relative difference {scipy_worst:.1e}")
    print(f"  ratio: {scipy_seconds / model_seconds:.0f}x scipy over trb_load (goal: measured)")


if __name__ == "__main__":
    main()
