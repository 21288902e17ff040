"""Costs of the cage slip models, each against a named baseline in the same run.

Steady (`cage_slip`): a Fig. 17 grid (test bearing, 200-1000 N, 6000-12000 r/min) computed in
one vectorised call against the same points called one at a time (the model without its
vectorisation). Goal: at most 50 ms per point. Since cage_slip 3 scans the cage's torque
balance at 50 cage speeds per point for every root (then refines the chosen one), a point
costs about 9 ms in one call of these 51 points on one core; 3-5 ms before, when a bracketed
secant search found one root.

Transient (`cage_dynamics`): 0.1 s of bearing time at 800 N, 12000 r/min with the compiled
Jacobian against LSODA's own difference Jacobian (one call of the right-hand side per
column), both through odeint. Goal: 0.1 s of bearing time in at most 5 s.
"""
import time

import numpy as np

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


def transient():
    kwargs = dict(duration=0.1, output_interval=1e-4)
    dynamics.cage_dynamics(800.0, 12000 * RPM, **TEST, duration=0.001, output_interval=1e-4)
    began = time.perf_counter()
    compiled = dynamics.cage_dynamics(800.0, 12000 * RPM, **TEST, **kwargs)
    compiled_seconds = time.perf_counter() - began
    solve = dynamics.odeint

    def without_jacobian(*args, Dfun=None, **options):
        return solve(*args, **options)  # the solver then differences the right-hand side

    dynamics.odeint = without_jacobian
    try:
        began = time.perf_counter()
        plain = dynamics.cage_dynamics(800.0, 12000 * RPM, **TEST, **kwargs)
        plain_seconds = time.perf_counter() - began
    finally:
        dynamics.odeint = solve
    assert abs(plain["mean_cage_slip"][0] / compiled["mean_cage_slip"][0] - 1) < 0.01
    print("cage_dynamics, 0.1 s of bearing time at 800 N, 12000 r/min")
    print(f"  baseline, LSODA's own difference Jacobian: {plain_seconds:6.2f} s")
    print(f"  compiled Jacobian:                         {compiled_seconds:6.2f} s "
          f"(goal: at most 5 s)")
    print(f"  ratio: {plain_seconds / compiled_seconds:.1f}x (goal: 0.1 s in at most 5 s; "
          f"{compiled_seconds:.1f} s)")


if __name__ == "__main__":
    steady()
    transient()
