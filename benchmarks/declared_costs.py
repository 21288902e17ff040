"""Declared against measured cost per point of every model that sweeps fast, on the studies'
own sweeps made large.

The engine chooses its chunk size and whether a sweep is worth a cluster from each model's
declared ``seconds_per_point``: the choice matters for sweeps of thousands of points and
more, so that is what is measured. Each sweep of the studies (studies/*/*.toml) that runs the
model has its first axis repeated until it holds at least one block of the model's
``points_per_call`` (a study's sweep of a few dozen points would measure the call's fixed
cost, and a compiled model's first points in a process run interpreted); a model no study
runs (hertz_point) gets its definition in tests/data/every_model so. The model is warmed up by
one such grid, untimed (imports, loading compiled code), then every grid is evaluated whole
through the engine's own chunk evaluation (inputs built, model called in blocks of its
``points_per_call``, outputs converted), on one core, in CPU time; the cost per point is the
total time over the total points. It prints the declared over the measured cost (goal:
between 0.5x and 2x). The transient cage models, whose points cost seconds, are measured
one point each: the first point of their definition in tests/data/every_model at the model's
default bearing time, which their declaration is for (loading their compiled code, once, is
within the measurement: a few hundredths of it).
"""
import dataclasses
import math
import os
import sys
import time
import tomllib
from pathlib import Path

import numpy as np

from bearing_sweep import spec
from bearing_sweep.evaluate import evaluate_chunk
from bearing_sweep.grid import Grid

ROOT = Path(__file__).resolve().parents[1]
MODELS = ("crb_radial", "ball_5dof", "trb_load", "trb_rib", "hertz_point", "crb_runout",
          "cage_slip")
TRANSIENT = ("cage_dynamics", "cage_dynamics_6dof")


def study_grids() -> tuple[dict, set]:
    """The grids of the studies' sweeps, by model (every_model's definition for a model no
    study runs), each repeated to a block of the model's points, and the models the studies
    run."""
    grids = {name: [] for name in MODELS}
    for path in sorted(ROOT.glob("studies/*/*.toml")):
        if path.name == "claims.toml":
            continue
        sweep = spec.load(path)
        grid = Grid.from_sweep(sweep)
        if sweep.model.name in grids and grid.shape:  # one point alone is no sweep to repeat
            grids[sweep.model.name].append(repeated(grid, sweep.model.points_per_call))
    studied = {name for name, found in grids.items() if found}
    for name, found in grids.items():
        if not found:
            sweep = spec.load(ROOT / "tests/data/every_model" / f"{name}.toml")
            found.append(repeated(Grid.from_sweep(sweep), sweep.model.points_per_call))
    return grids, studied


def repeated(grid: Grid, points: int) -> Grid:
    """The grid with its first axis repeated until it holds at least ``points`` points."""
    times = math.ceil(points / grid.size)
    values = {name: (position, np.concatenate([values] * times) if position == 0 else values)
              for name, (position, values) in grid.axis_values.items()}
    return dataclasses.replace(grid, shape=(grid.shape[0] * times,) + grid.shape[1:],
                               axis_values=values)


def measured_cost(grids) -> tuple[float, int]:
    """Seconds of this process's CPU per point over ``grids``, each evaluated whole once (the
    first once more before, untimed: it may import or load compiled code), and the number of
    points. CPU time, not wall time: on a shared machine the others' load would count as the
    model's."""
    evaluate_chunk(grids[0], 0, grids[0].size)
    seconds = points = 0
    for grid in grids:
        began = time.process_time()
        evaluate_chunk(grid, 0, grid.size)
        seconds += time.process_time() - began
        points += grid.size
    return seconds / points, points


def one_transient_point(name: str) -> Grid:
    """The first point of the model's definition in tests/data/every_model, at the model's
    default bearing time and output interval."""
    document = tomllib.loads((ROOT / "tests/data/every_model" / f"{name}.toml").read_text())
    for key in ("duration", "output_interval"):
        document["fixed"].pop(key, None)
    document["axes"] = {axis: values[:1] for axis, values in document["axes"].items()}
    return Grid.from_sweep(spec.from_dict(document, f"{name} (one point)"))


def report(name: str, found: str, declared: float, cost: float, points: int):
    print(f"{name}: {found}, {points} points, one core")
    print(f"  measured baseline: {cost:.3g} s/point")
    print(f"  declared: {declared:.3g} s/point")
    print(f"  ratio: {declared / cost:.2f}x declared over measured (goal: 0.5x to 2x)")


def main():
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    grids, studied = study_grids()
    for name in MODELS:
        cost, points = measured_cost(grids[name])
        report(name, f"the studies' {len(grids[name])} sweeps, repeated" if name in studied
               else "its definition in tests/data/every_model, repeated",
               grids[name][0].seconds_per_point, cost, points)
    for name in TRANSIENT:
        grid = one_transient_point(name)
        began = time.process_time()
        evaluate_chunk(grid, 0, 1)
        report(name, "one point at its default bearing time",
               grid.seconds_per_point, time.process_time() - began, 1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
