"""The spatial cage model's own integrators against the stiff solvers of well-kept libraries.

The test bearing (preset paper002-test) at 800 N, 12000 r/min, from the model's steady start,
relative tolerance 1e-5 (the model's Rosenbrock-W method and multistep formulas working to a
tenth of it, as the model has them) and the model's absolute tolerances, on the same compiled
right-hand side: scipy's BDF and Radau (``solve_ivp``) and, where scikit-sundae is installed
(``pip install scikit-sundae``: it is not one of the project's dependencies), SUNDIALS' CVODE
(BDF, dense linear solver). Each library is given the best Jacobian the model has for
Newton's method: every stiff term's, by forward differences (the Rosenbrock-W method's until
model version 9; :func:`models.cage_dynamics_6dof_implicit.jacobian`), assembled into a dense
matrix.

Cases: the paper's films over the first 2 ms (every method) and over 0.1 s (the default, the
additive method, and the model's multistep formulas against CVODE); the end films with their
pressure over 2 ms and 60 ms (the Rosenbrock-W method and the multistep formulas against
scipy's BDF and CVODE); a thin pocket film (``pocket_film_fill = 0.05``) and 1 deg of
misalignment over 30 ms (the additive method, Dormand-Prince and the multistep formulas
against CVODE). Printed: wall time, the right-hand sides the library reports, and the mean
cage and roller slips over the second half. One core; the load average says how busy the
machine was. About 6 minutes.
"""
import os
import time

import numpy as np
from cage_dynamics_6dof_cost import BEARING, LOAD, SPEED
from scipy.integrate import solve_ivp

import bearing_sweep.models.cage_dynamics_6dof as spatial
from bearing_sweep.models import cage_dynamics_6dof_implicit as implicit
from bearing_sweep.models import cage_dynamics_6dof_rhs as rhs

INTERVAL, TOLERANCE = 1e-4, 1e-5  # [s], [-]
CASES = (("paper's films", {}, 2e-3, ("imex", "adaptive", "bdf", "BDF", "Radau", "cvode")),
         ("paper's films", {}, 0.1, ("imex", "bdf", "cvode")),
         ("end films' pressure", {"end_film": "reynolds"}, 2e-3,
          ("rosenbrock", "bdf", "BDF", "cvode")),
         ("end films' pressure", {"end_film": "reynolds"}, 0.06,
          ("rosenbrock", "bdf", "BDF", "cvode")),
         ("thin pocket film", {"pocket_film_fill": 0.05}, 0.03,
          ("imex", "adaptive", "bdf", "cvode")),
         ("1 deg misalignment", {"misalignment_x": np.radians(1.0)}, 0.03,
          ("imex", "adaptive", "bdf", "cvode")))
NAMES = {"imex": "additive Runge-Kutta (ours)", "adaptive": "Dormand-Prince (ours)",
         "rosenbrock": "Rosenbrock-W (ours)", "bdf": "multistep formulas (ours)",
         "BDF": "scipy BDF", "Radau": "scipy Radau",
         "cvode": "SUNDIALS CVODE BDF"}


def setup(**changes):
    """The model's setup of the benchmark's point with ``changes`` (``run``, ``one``), from a
    short call."""
    seen, original = {}, spatial.integrate

    def capture(run, one):
        seen.update(run=run, one=one)
        return original(run, one)

    spatial.integrate = capture
    try:
        spatial.cage_dynamics_6dof(LOAD, SPEED, **BEARING, duration=INTERVAL,
                                   output_interval=INTERVAL, **changes)
    finally:
        spatial.integrate = original
    return seen["run"], seen["one"]


def problem(run):
    """The right-hand side and the dense stiff Jacobian, as the libraries call them."""
    count, p = run["count"], run["p"]
    geometry = tuple(np.ascontiguousarray(e, dtype=float) for e in run["elements"])
    record = rhs.scratch(count, geometry)
    scale = spatial._absolute_tolerances(count, TOLERANCE) / TOLERANCE
    blocks = implicit.blocks(count)[:4]

    def rate(t, y):
        return rhs.derivatives(y, p, count, *geometry, *record, 0.0)

    def jacobian(t, y):
        implicit.jacobian(y, p, count, geometry, record, scale, *blocks)
        return implicit.dense(*blocks)

    return rate, jacobian


def slips(run, samples, times):
    """Mean cage and roller slip [%] over the second half of the samples."""
    found = spatial.results(samples, dict(run, times=times))
    return 100 * float(found["mean_cage_slip"]), 100 * float(found["mean_roller_slip"])


def ours(run, one, times, integrator):
    spatial.integrate(dict(run, times=times[:2]), dict(one, integrator=integrator))  # compile
    wall = time.perf_counter()
    found = spatial.integrate(dict(run, times=times), dict(one, integrator=integrator))
    return time.perf_counter() - wall, found[0] if found[6] else None


def scipy(run, times, method):
    rate, jacobian = problem(run)
    atol = spatial._absolute_tolerances(run["count"], TOLERANCE)
    wall = time.perf_counter()
    found = solve_ivp(rate, (times[0], times[-1]), run["state"], method=method, t_eval=times,
                      rtol=TOLERANCE, atol=atol, jac=jacobian)
    return time.perf_counter() - wall, found.y.T if found.success else None


def cvode(run, times):
    from sksundae.cvode import CVODE
    rate, jacobian = problem(run)
    atol = spatial._absolute_tolerances(run["count"], TOLERANCE)

    def rhsfn(t, y, yp):
        yp[:] = rate(t, y)

    def jacfn(t, y, yp, matrix):
        matrix[:, :] = jacobian(t, y)

    solver = CVODE(rhsfn, method="BDF", rtol=TOLERANCE, atol=atol, jacfn=jacfn,
                   max_num_steps=1_000_000)
    wall = time.perf_counter()
    found = solver.solve(times, run["state"])
    wall = time.perf_counter() - wall
    print(f"    (CVODE: {found.nfev} right-hand sides, {found.njev} Jacobians)")
    return wall, found.y if found.success else None


def have_cvode():
    try:
        import sksundae.cvode  # noqa: F401
    except ImportError:
        return False
    return True


if __name__ == "__main__":
    print(f"cage_dynamics_6dof at {LOAD:.0f} N, {SPEED * 30 / np.pi:.0f} r/min, tolerance "
          f"{TOLERANCE:g}; load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    if not have_cvode():
        print("  (SUNDIALS left out: scikit-sundae is not installed)")
    for case, changes, duration, methods in CASES:
        run, one = setup(**changes)
        problem(run)[0](0.0, run["state"])  # compile, or load: untimed
        times = np.arange(int(round(duration / INTERVAL)) + 1) * INTERVAL
        print(f"  {case}, {1e3 * duration:g} ms")
        for method in methods:
            if method == "cvode" and not have_cvode():
                continue
            if method in ("BDF", "Radau"):
                scipy(run, times[:3], method)  # untimed: a library's first call costs more
                wall, samples = scipy(run, times, method)
            elif method == "cvode":
                cvode(run, times[:3])
                wall, samples = cvode(run, times)
            else:
                wall, samples = ours(run, one, times, method)
            cage, roller = slips(run, samples, times) if samples is not None else (np.nan,
                                                                                   np.nan)
            print(f"    {NAMES[method]:<30} {wall:>8.2f} s   cage slip {cage:7.4f} %   "
                  f"roller slip {roller:8.4f} %")
