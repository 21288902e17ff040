"""ball_5dof through the engine against a compiled per-point kernel of the same equilibrium.

Kernel (baseline): written here with numba (numpy's error model: no zero-division checks), as a
user would write ball_5dof for one point at a time, in Jones' geometry: the same start (every
ball compressed as ``Z K delta^1.5 = |F|`` would compress it, at its unloaded contact angle),
the same damped Newton iteration (damping 1 % of that start's stiffness, times 0.2 on a step
taken and 5 on one refused), the same tolerance (residual within 1e-10 of the load, tilts times
and moments over the groove radius R) and at most 200 iterations; each ball's force and
stiffness summed onto the ring through the non-zero entries of its rows ``A = (1, 0, 0, sin
psi, -cos psi)`` and ``B = (0, cos psi, sin psi, 0, 0)``, the damped system solved by Gaussian
elimination; then the stiffness matrix, ball loads, contact angles and contact pressures (``p0
= p1 Q^(1/3)`` with the Hertz pressure ``p1`` at 1 N of the bearing, computed once) at the
solution.

Model: ``ball_5dof`` through the engine's chunk evaluation
(``bearing_sweep.evaluate.evaluate_chunk`` on a Grid), in blocks of its declared
``points_per_call``: all a sweep computes (Hertz contacts, status and validity, pressures,
rating lives, units).

Points: the 71807AC of paper 001 (catalogue preset, the paper's contact constant) under axial
500-3500 N, radial 0-3000 N and moments -5..5 N m, all five displacements free: the grid of
ball_5dof_throughput.py, repeated to the declared block. Both on one core, runs interleaved in
pairs; prints the median of the pairs' ratios with the load average. The answers must agree to
1e-8 (largest relative difference printed). A second section times the per-point scipy
baseline of ball_5dof_throughput.py (reused) on the grid's first points against both.
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
from bearing_sweep.models.ball import MODELS, raceway_contacts

sys.path.insert(0, str(Path(__file__).parent))
from ball_5dof_throughput import BEARING, per_point  # noqa: E402  (the scipy baseline)
from declared_costs import repeated  # noqa: E402
from pairs import interleaved, ratio_line  # noqa: E402

DEFINITION = """
[sweep]
model = "ball_5dof"
bearing = "paper001-71807AC"
[axes]
axial_load = { start = "500 N", stop = "3500 N", num = 8 }
radial_load = { start = "0 N", stop = "3000 N", num = 8 }
moment_y = { start = "-5 N*m", stop = "5 N*m", num = 4 }
"""
TOLERANCE = 1e-10  # ball_5dof's residual tolerance, relative to the load
MAX_ITERATIONS = 200
AGREEMENT = 1e-8  # answers: the residual tolerance through the stiffness, with margin


#: Ball j's rows: A has the entries (1, sin psi, -cos psi) at dofs (0, 3, 4), B the entries
#: (cos psi, sin psi) at dofs (1, 2); ``rows`` (Z, 5) holds 1, sin, -cos, cos, sin per ball.
A_DOFS, B_DOFS = (0, 3, 4), (1, 2)


@njit(cache=True, error_model="numpy")
def balls(q, distance, angle, half_clearance, constant, rows, load, slope, normal, length):
    """Each ball's load, slope, normal (axial, radial) and centre distance at the scaled
    ``q``, into the arrays given."""
    for j in range(load.size):
        s_a = distance * math.sin(angle)
        s_b = distance * math.cos(angle) - half_clearance
        for u in range(3):
            s_a += rows[j, u] * q[A_DOFS[u]]
        for v in range(2):
            s_b += rows[j, 3 + v] * q[B_DOFS[v]]
        length[j] = math.sqrt(s_a * s_a + s_b * s_b)
        normal[j, 0], normal[j, 1] = s_a / length[j], s_b / length[j]
        delta = length[j] - distance
        load[j] = constant * delta ** 1.5 if delta > 0.0 else 0.0
        slope[j] = 1.5 * constant * math.sqrt(delta) if delta > 0.0 else 0.0


@njit(cache=True, error_model="numpy")
def ring(rows, load, slope, normal, length, force, matrix):
    """Reaction (5,) and tangent stiffness (5, 5) summed over the balls, into the arrays
    given: ball j adds Q (n_a A + n_b B) and k_aa A A^T + k_bb B B^T + k_ab (A B^T + B A^T),
    on the non-zero entries of A and B only."""
    force[:] = 0.0
    matrix[:, :] = 0.0
    for j in range(load.size):
        n_a, n_b = normal[j, 0], normal[j, 1]
        turning = load[j] / length[j]
        k_aa = slope[j] * n_a * n_a + turning * n_b * n_b
        k_bb = slope[j] * n_b * n_b + turning * n_a * n_a
        k_ab = (slope[j] - turning) * n_a * n_b
        for u in range(3):
            force[A_DOFS[u]] += load[j] * n_a * rows[j, u]
            for v in range(3):
                matrix[A_DOFS[u], A_DOFS[v]] += k_aa * rows[j, u] * rows[j, v]
            for v in range(2):
                cross = k_ab * rows[j, u] * rows[j, 3 + v]
                matrix[A_DOFS[u], B_DOFS[v]] += cross
                matrix[B_DOFS[v], A_DOFS[u]] += cross
        for u in range(2):
            force[B_DOFS[u]] += load[j] * n_b * rows[j, 3 + u]
            for v in range(2):
                matrix[B_DOFS[u], B_DOFS[v]] += k_bb * rows[j, 3 + u] * rows[j, 3 + v]


@njit(cache=True, error_model="numpy")
def solve(matrix, damping, right, work, x):
    """``(matrix + damping I) x = right`` by Gaussian elimination with partial pivoting,
    ``work`` (5, 6) scratch."""
    size = right.size
    for r in range(size):
        for k in range(size):
            work[r, k] = matrix[r, k] + (damping if r == k else 0.0)
        work[r, size] = right[r]
    for p in range(size):
        best = p
        for r in range(p + 1, size):
            if abs(work[r, p]) > abs(work[best, p]):
                best = r
        for k in range(size + 1):
            work[p, k], work[best, k] = work[best, k], work[p, k]
        for r in range(p + 1, size):
            factor = work[r, p] / work[p, p]
            for k in range(p, size + 1):
                work[r, k] -= factor * work[p, k]
    for r in range(size - 1, -1, -1):
        total = work[r, size]
        for k in range(r + 1, size):
            total -= work[r, k] * x[k]
        x[r] = total / work[r, r]


@njit(cache=True, error_model="numpy")
def kernel(loads, ball_count, distance, angle, half_clearance, constant, radius, unit_pressure):
    """Displacement (N, 5), stiffness (N, 5, 5), ball loads, contact angles and pressures
    (N, Z) and convergence of every point, one at a time (loads (N, 5) in SI)."""
    count = loads.shape[0]
    rows = np.zeros((ball_count, 5))
    for j in range(ball_count):
        psi = 2.0 * np.pi * j / ball_count
        rows[j, 0], rows[j, 1], rows[j, 2] = 1.0, math.sin(psi), -math.cos(psi)
        rows[j, 3], rows[j, 4] = math.cos(psi), math.sin(psi)
    scale = np.array([1.0, 1.0, 1.0, radius, radius])
    displacement, stiffness = np.zeros((count, 5)), np.zeros((count, 5, 5))
    ball_load, contact_angle = np.zeros((count, ball_count)), np.zeros((count, ball_count))
    pressure, converged = np.zeros((count, ball_count)), np.zeros(count, dtype=np.bool_)
    load_j, slope, length = np.zeros(ball_count), np.zeros(ball_count), np.zeros(ball_count)
    normal = np.zeros((ball_count, 2))
    load, q, trial, step = np.zeros(5), np.zeros(5), np.zeros(5), np.zeros(5)
    force, residual, trial_residual = np.zeros(5), np.zeros(5), np.zeros(5)
    matrix, trial_matrix, work = np.zeros((5, 5)), np.zeros((5, 5)), np.zeros((5, 6))
    for n in range(count):
        magnitude = 0.0
        for k in range(5):
            load[k] = loads[n, k] / scale[k]
            magnitude += load[k] * load[k]
        magnitude = math.sqrt(magnitude)
        typical = (magnitude / (ball_count * constant)) ** (1.0 / 1.5)
        mu = 0.01 * 1.5 * ball_count * constant * math.sqrt(typical)
        # Start: every ball compressed by `typical` at its unloaded angle.
        q[:] = 0.0
        if magnitude > 0.0:
            load_j[:] = constant * typical ** 1.5
            slope[:] = 1.5 * constant * math.sqrt(typical)
            normal[:, 0], normal[:, 1] = math.sin(angle), math.cos(angle)
            length[:] = distance + typical
            ring(rows, load_j, slope, normal, length, force, matrix)
            solve(matrix, mu, load, work, q)
        balls(q, distance, angle, half_clearance, constant, rows, load_j, slope, normal, length)
        ring(rows, load_j, slope, normal, length, force, matrix)
        norm = 0.0
        for k in range(5):
            residual[k] = load[k] - force[k]
            norm += residual[k] * residual[k]
        norm = math.sqrt(norm)
        for _ in range(MAX_ITERATIONS):
            if not norm > TOLERANCE * magnitude:
                break
            solve(matrix, mu, residual, work, step)
            for k in range(5):
                trial[k] = q[k] + step[k]
            balls(trial, distance, angle, half_clearance, constant, rows, load_j, slope,
                  normal, length)
            ring(rows, load_j, slope, normal, length, force, trial_matrix)
            trial_norm = 0.0
            for k in range(5):
                trial_residual[k] = load[k] - force[k]
                trial_norm += trial_residual[k] * trial_residual[k]
            trial_norm = math.sqrt(trial_norm)
            if trial_norm <= norm:
                q[:], residual[:], matrix[:, :] = trial, trial_residual, trial_matrix
                norm = trial_norm
                mu *= 0.2
            else:
                mu *= 5.0
        converged[n] = norm <= TOLERANCE * magnitude
        balls(q, distance, angle, half_clearance, constant, rows, load_j, slope, normal, length)
        for i in range(5):
            displacement[n, i] = q[i] / scale[i]
            for k in range(5):
                stiffness[n, i, k] = matrix[i, k] * scale[i] * scale[k]
        for j in range(ball_count):
            ball_load[n, j] = load_j[j]
            contact_angle[n, j] = math.atan2(normal[j, 0], normal[j, 1])
            pressure[n, j] = unit_pressure * load_j[j] ** (1.0 / 3.0)
    return displacement, stiffness, ball_load, contact_angle, pressure, converged


def bearing_terms(bearing):
    """The kernel's per-bearing constants, computed once: groove-centre distance, groove
    radius and the larger Hertz pressure at 1 N of the two contacts."""
    inner, outer = raceway_contacts(bearing["ball_diameter"], bearing["pitch_diameter"],
                                    bearing["contact_angle"], bearing["inner_curvature_ratio"],
                                    bearing["outer_curvature_ratio"])
    diameter = bearing["ball_diameter"]
    distance = (bearing["inner_curvature_ratio"] + bearing["outer_curvature_ratio"] - 1.0) \
        * diameter
    radius = 0.5 * bearing["pitch_diameter"] + (bearing["inner_curvature_ratio"] - 0.5) \
        * diameter * math.cos(bearing["contact_angle"])
    return dict(ball_count=bearing["ball_count"], distance=distance,
                angle=bearing["contact_angle"], half_clearance=0.0,
                constant=bearing["contact_constant"], radius=radius,
                unit_pressure=float(np.maximum(inner["max_pressure"], outer["max_pressure"])))


def largest_difference(ours, theirs):
    """Largest difference relative to each column's largest value (per dof, per entry)."""
    ours, theirs = np.asarray(ours, float), np.asarray(theirs, float)
    scale = np.abs(theirs).max(axis=0)
    scale = np.where(scale > 0, scale, 1.0)
    return float(np.max(np.abs(ours - theirs) / scale))


def main():
    model = MODELS[0]
    grid = Grid.from_sweep(spec.parse(DEFINITION, "ball_5dof_kernel.toml"))
    grid = repeated(grid, model.points_per_call)
    points, _ = grid.inputs(0, grid.size)
    loads = np.zeros((grid.size, 5))
    for column, name in ((0, "axial_load"), (1, "radial_load"), (3, "moment_y")):
        loads[:, column] = points[name]
    terms = bearing_terms(BEARING)
    assert BEARING["contact_constant"] == grid.fixed["contact_constant"]

    def run_model():
        return evaluate_chunk(grid, 0, grid.size)

    def run_kernel():
        return kernel(loads, **terms)

    result, compiled = run_model(), run_kernel()  # first calls: imports, compilation
    outputs = result["outputs"]
    assert np.all(result["status"] == 0) and compiled[-1].all()
    worst = max(largest_difference(outputs["displacement"], compiled[0]),
                largest_difference(outputs["stiffness_matrix"].reshape(-1, 25),
                                   compiled[1].reshape(-1, 25)),
                largest_difference(outputs["ball_load"], compiled[2]),
                largest_difference(np.radians(outputs["ball_contact_angle"]), compiled[3]),
                largest_difference(outputs["max_contact_pressure"] * 1e6, compiled[4]))
    assert worst < AGREEMENT, f"model and kernel differ by {worst:.1e}"

    result = interleaved(run_model, run_kernel)
    model_seconds, kernel_seconds = result[3] / grid.size, result[4] / grid.size
    print(f"ball_5dof against a compiled per-point kernel ({grid.size} points per call, "
          "71807AC, Jones, five free displacements)")
    print(f"  baseline, numba kernel per point: {1e6 * kernel_seconds:7.2f} us/point")
    print(f"  ball_5dof through the engine:     {1e6 * model_seconds:7.2f} us/point; "
          f"largest relative difference {worst:.1e}")
    print(ratio_line(result, "within 1.5x"))

    first = min(256, grid.size)  # the grid before its repetition
    began = time.perf_counter()
    baseline = [per_point(loads[i], **BEARING) for i in range(first)]
    scipy_seconds = (time.perf_counter() - began) / first
    solved = np.array([np.isfinite(b[0][0]) for b in baseline])
    scipy_worst = largest_difference(compiled[0][:first][solved],
                                     np.array([b[0] for b in baseline])[solved])
    assert scipy_worst < 1e-6, f"kernel and scipy differ by {scipy_worst:.1e}"
    print(f"ball_5dof and its kernel against the per-point scipy baseline ({first} points)")
    print(f"  baseline, scipy.optimize.root per point: {1e6 * scipy_seconds:9.1f} us/point")
    print(f"  kernel {scipy_seconds / kernel_seconds:.0f}x faster; "
          f"largest relative difference {scipy_worst:.1e}")
    print(f"  ratio: {scipy_seconds / model_seconds:.0f}x scipy over ball_5dof (goal: measured)")


if __name__ == "__main__":
    main()
