"""ball_5dof grid throughput against a plain per-point scipy.optimize implementation.

Baseline: for each grid point, scipy.optimize.root (MINPACK hybrid method) on the five
equilibrium equations in Jones' geometry, the balls summed with numpy and the analytic
Jacobian supplied, then the stiffness matrix at the solution; this is how the model is written
without vectorising across points. Both run on one core, on the same grid (the 71807AC of
paper 001 under axial, radial and moment loads, all five displacements free); the answers must
agree to 1e-6. Prints the time per point of each and their ratio (goal: at least 30).
"""
import time

import numpy as np
from scipy.optimize import root

from bearing_sweep.models.ball import ball_5dof

MM = 1e-3
BEARING = dict(ball_count=25, ball_diameter=3.14 * MM, pitch_diameter=41 * MM,
               contact_angle=np.radians(25), inner_curvature_ratio=0.52,
               outer_curvature_ratio=0.53, contact_constant=1.0649e10)


def per_point(loads, ball_count, ball_diameter, pitch_diameter, contact_angle,
              inner_curvature_ratio, outer_curvature_ratio, contact_constant):
    """Displacement and stiffness matrix of one bearing, solved on its own with scipy."""
    distance = (inner_curvature_ratio + outer_curvature_ratio - 1) * ball_diameter
    radius = pitch_diameter / 2 + (inner_curvature_ratio - 0.5) * ball_diameter * np.cos(
        contact_angle)
    psi = 2 * np.pi * np.arange(ball_count) / ball_count
    one, zero = np.ones_like(psi), np.zeros_like(psi)
    axial_row = np.stack([one, zero, zero, radius * np.sin(psi), -radius * np.cos(psi)], 1)
    radial_row = np.stack([zero, np.cos(psi), np.sin(psi), zero, zero], 1)

    def balls(q):
        sa = distance * np.sin(contact_angle) + axial_row @ q
        sr = distance * np.cos(contact_angle) + radial_row @ q
        length = np.hypot(sa, sr)
        compressed = np.maximum(length - distance, 0)
        return sa / length, sr / length, length, contact_constant * compressed**1.5, \
            1.5 * contact_constant * np.sqrt(compressed)

    def residual(q):
        na, nr, _, load, _ = balls(q)
        return axial_row.T @ (load * na) + radial_row.T @ (load * nr) - loads

    def jacobian(q):
        na, nr, length, load, slope = balls(q)
        transverse = load / length
        kaa = slope * na**2 + transverse * nr**2
        krr = slope * nr**2 + transverse * na**2
        kar = (slope - transverse) * na * nr
        return (axial_row.T * kaa) @ axial_row + (radial_row.T * krr) @ radial_row \
            + (axial_row.T * kar) @ radial_row + (radial_row.T * kar) @ axial_row

    start = np.array([1e-6, 0, 0, 0, 0])
    solution = root(residual, start, jac=jacobian, method="hybr", options={"xtol": 1e-13})
    if not solution.success:
        return np.full(5, np.nan), np.full((5, 5), np.nan)
    return solution.x, jacobian(solution.x)


def main():
    axial, radial, moment = np.meshgrid(np.linspace(500, 3500, 8), np.linspace(0, 3000, 8),
                                        np.linspace(-5, 5, 4), indexing="ij")
    axial, radial, moment = axial.ravel(), radial.ravel(), moment.ravel()

    began = time.perf_counter()
    baseline = [per_point(np.array([a, r, 0, m, 0]), **BEARING)
                for a, r, m in zip(axial, radial, moment)]
    baseline_seconds = (time.perf_counter() - began) / axial.size
    baseline_displacement = np.array([b[0] for b in baseline])

    repeats = 40
    grid = dict(axial_load=np.tile(axial, repeats), radial_load=np.tile(radial, repeats),
                moment_y=np.tile(moment, repeats))
    best = np.inf
    for _ in range(3):
        began = time.perf_counter()
        result = ball_5dof(**BEARING, **grid)
        best = min(best, (time.perf_counter() - began) / axial.size / repeats)

    assert np.all(result["status"] == 0)
    failed = np.isnan(baseline_displacement[:, 0])
    ours = result["displacement"][:axial.size]
    scale = np.abs(ours).max(axis=0)  # per dof: compare translations and tilts each
    worst = np.max(np.abs(ours[~failed] - baseline_displacement[~failed]) / scale)
    assert worst < 1e-6, f"answers differ by {worst:.2e} of the largest displacement"
    print(f"ball_5dof throughput, {axial.size} points (71807AC, Jones, five free displacements)")
    print(f"  baseline, scipy.optimize.root per point: {1e3 * baseline_seconds:8.3f} ms/point"
          f" ({failed.sum()} of {axial.size} points not solved by the baseline)")
    print(f"  ball_5dof, vectorised over {grid['axial_load'].size} points:"
          f" {1e3 * best:8.3f} ms/point")
    print(f"  ratio: {baseline_seconds / best:.0f}x (goal: at least 30x)")


if __name__ == "__main__":
    main()
