"""Costs of the cage slip models, each against a named baseline in the same run.

Steady (`cage_slip`): a Fig. 17 grid (test bearing, 200-1000 N, 6000-12000 r/min) computed in
one vectorised call against the same points called one at a time (the model without its
vectorisation). Goal: at most 50 ms per point. Since cage_slip 3 scans the cage's torque
balance at 50 cage speeds per point for every root (then refines the chosen one), a point
costs about 9 ms in one call of these 51 points on one core; 3-5 ms before, when a bracketed
secant search found one root.

Transient (`cage_dynamics`): 0.1 s of bearing time at 800 N, 12000 r/min and at 2 kN,
6000 r/min, the model end to end with its compiled Dormand-Prince integration against the
same model integrated by scipy's LSODA (``solve_ivp``, its own difference Jacobian) on the
same compiled right-hand side. Goal: 0.1 s of bearing time in at most 5 s.
"""
import time

import numpy as np
from scipy.integrate import solve_ivp

import bearing_sweep.models.cage_dynamics as dynamics
from bearing_sweep.models.cage_slip import cage_slip

MM, RPM = 1e-3, 2 * np.pi / 60
TEST = dict(roller_count=13, inner_raceway_diameter=44 * MM, roller_diameter=10 * MM,
            roller_length=11 * MM, effective_length=7.2 * MM, clearance=0.02 * MM,
            cage_inner_diameter=48.5 * MM, cage_outer_diameter=59 * MM, cage_width=9 * MM)


def steady():
    load, speed = np.meshgrid(np.linspace(200, 1000, 17), np.array([6000, 9000, 12000]) * RPM)
    load, speed = load.ravel(), speed.ravel()
    began = time.perf_counter()
    single = np.array([cage_slip(f, n, **TEST)["cage_slip"][0] for f, n in zip(load, speed)])
    one_at_a_time = (time.perf_counter() - began) / load.size
    began = time.perf_counter()
    together = cage_slip(load, speed, **TEST)["cage_slip"]
    vectorised = (time.perf_counter() - began) / load.size
    assert np.allclose(single, together, rtol=1e-9)
    print(f"cage_slip, {load.size} points of Fig. 17")
    print(f"  baseline, one point per call: {1e3 * one_at_a_time:7.2f} ms/point")
    print(f"  vectorised call:              {1e3 * vectorised:7.2f} ms/point "
          f"(goal: at most 50 ms)")
    print(f"  ratio: {one_at_a_time / vectorised:.1f}x (goal: at most 50 ms per point; "
          f"{1e3 * vectorised:.1f} ms)")


def _lsoda(state, times, p, count, rtol, atol, max_steps):
    """The baseline: scipy's LSODA on the same compiled right-hand side, its Jacobian by its
    own differences, as :func:`bearing_sweep.models.cage_dynamics_rhs.integrate` is called."""
    solution = solve_ivp(dynamics.rhs.derivatives, (times[0], times[-1]), state,
                         method="LSODA", t_eval=times, args=(p, count), rtol=rtol, atol=atol)
    return solution.y.T, solution.success


def transient():
    kwargs = dict(duration=0.1, output_interval=1e-4)
    compiled = dynamics.rhs.integrate
    rows = []
    for load, rpm in ((800.0, 12000), (2000.0, 6000)):
        dynamics.cage_dynamics(load, rpm * RPM, **TEST, duration=0.001, output_interval=1e-4)
        began = time.perf_counter()
        ours = dynamics.cage_dynamics(load, rpm * RPM, **TEST, **kwargs)
        ours_seconds = time.perf_counter() - began
        dynamics.rhs.integrate = _lsoda
        try:
            began = time.perf_counter()
            theirs = dynamics.cage_dynamics(load, rpm * RPM, **TEST, **kwargs)
            theirs_seconds = time.perf_counter() - began
        finally:
            dynamics.rhs.integrate = compiled
        deviation = ours["mean_cage_slip"][0] / theirs["mean_cage_slip"][0] - 1
        assert abs(deviation) < 0.01
        rows.append((load, rpm, ours_seconds, theirs_seconds, deviation))
    print("cage_dynamics, 0.1 s of bearing time, end to end (the steady start included)")
    for load, rpm, ours_seconds, theirs_seconds, deviation in rows:
        print(f"  {load:.0f} N, {rpm} r/min: compiled Dormand-Prince {ours_seconds:5.2f} s, "
              f"baseline scipy LSODA {theirs_seconds:5.2f} s; ratio "
              f"{theirs_seconds / ours_seconds:.1f}x (goal: 0.1 s in at most 5 s); mean cage "
              f"slips {100 * deviation:+.2f} % apart")


if __name__ == "__main__":
    steady()
    transient()
