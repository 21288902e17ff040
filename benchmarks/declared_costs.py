"""Declared against measured cost per point of every model that sweeps fast.

The engine chooses its chunk size and whether a sweep is worth a cluster from each model's
declared ``seconds_per_point``; this measures the real cost on one core, through the engine's
own chunk evaluation (inputs built, model called, outputs converted) on the grid of the
model's definition in tests/data/every_model, its first axis repeated to the number of points
the model takes per call (the block sweeps use), and prints
the measured over the declared cost (goal: between 0.5x and 2x). The transient cage models
are measured in their own benchmarks (cage_slip_cost, cage_dynamics_6dof_cost).
"""
import dataclasses
import math
import sys
import time
from pathlib import Path

import numpy as np

from bearing_sweep import spec
from bearing_sweep.compute import evaluate_chunk
from bearing_sweep.grid import Grid

DEFINITIONS = Path(__file__).resolve().parents[1] / "tests" / "data" / "every_model"
MODELS = ("crb_radial", "ball_5dof", "trb_load", "trb_rib", "hertz_point", "crb_runout",
          "cage_slip")
TARGET_SECONDS = 2.0  # of computing per model


def repeated(grid: Grid, points: int) -> Grid:
    """The grid with its first axis repeated until it holds at least ``points`` points."""
    times = math.ceil(points / grid.size)
    values = {name: (position, np.concatenate([values] * times) if position == 0 else values)
              for name, (position, values) in grid.axis_values.items()}
    return dataclasses.replace(grid, shape=(grid.shape[0] * times,) + grid.shape[1:],
                               axis_values=values)


def measured_cost(grid: Grid) -> float:
    """Seconds per point of the whole grid evaluated as one chunk, repeated until
    ``TARGET_SECONDS`` have passed (the first call, which may import or compile, untimed)."""
    evaluate_chunk(grid, 0, grid.size)
    points, start = 0, time.perf_counter()
    while time.perf_counter() - start < TARGET_SECONDS:
        evaluate_chunk(grid, 0, grid.size)
        points += grid.size
    return (time.perf_counter() - start) / points


def main():
    print("declared against measured seconds per point (one core, the engine's chunk path)")
    for name in MODELS:
        sweep = spec.load(DEFINITIONS / f"{name}.toml")
        grid = repeated(Grid.from_sweep(sweep), sweep.model.points_per_call)
        declared = sweep.model.seconds_per_point
        cost = measured_cost(grid)
        ratio = cost / declared
        print(f"{name}: {grid.size} points per call")
        print(f"  declared baseline: {declared:.3g} s/point")
        print(f"  measured: {cost:.3g} s/point")
        print(f"  ratio: {ratio:.2f}x measured over declared (goal: 0.5x to 2x)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
