"""A duty cycle's lives: a zipped axis whose ``time_share`` column gives each load case's
share of the time (``[axes.case] time_share = [...]``) makes the sweep store, beside each
case's results, the model's rating lives combined over the cycle, on the grid's other axes.

A life in revolutions is combined by Palmgren and Miner over the cases' shares of the
revolutions, ``t_i n_i / sum(t n)`` with ``n`` the speed where it is a column of the axis (at
one speed for all, the shares of the time); a life in hours over the shares of the time
(:func:`bearing_sweep.models.life_combination.duty_cycle_life`; ``Output.cycle`` says
which). A case at rest uses up no life, whatever the model says of its life there (a
modified life needs a film, and at rest there is none); its time still counts in the
cycle's. A model may combine an output otherwise (a system's life: the Weibull combination
of its bearings' lives over the cycle, ``Model.cycle_combinations``). The cases without a share
of the time take no part. ``status_over_duty_cycle`` is the most severe status of the cases
that do, out of validity where any of them is; a combined life is NaN where it keeps no
values.
"""
from __future__ import annotations

import numpy as np

from .models.life_combination import duty_cycle_life
from .models.registry import STATUS_MASKS, STATUS_MEANINGS, STATUS_VALUES, combine_status, \
    values_kept
from .units import cf_units

#: The name of an output's combination over the duty cycle: the output's, with this after it.
SUFFIX = "_over_duty_cycle"
#: The variable of the status over the duty cycle.
STATUS = "status" + SUFFIX


def combined_outputs(model) -> list:
    """The outputs of ``model`` a duty cycle combines, in the model's order."""
    return [o for o in model.outputs if o.cycle or o.name in model.cycle_combinations]


def cycle_names(sweep) -> list[str]:
    """The variables of the duty cycle of ``sweep`` (none without one)."""
    if sweep.duty_cycle is None:
        return []
    return [o.name + SUFFIX for o in combined_outputs(sweep.model)] + [STATUS]


def shares(axis) -> np.ndarray:
    """The duty cycle's time shares, summing to 1 (scaled by the largest first: shares near
    the largest float would overflow their sum)."""
    given = np.asarray(axis.time_shares, dtype=float)
    given = given / given.max()
    return given / given.sum()


def cycle_variables(sweep, grid, outputs: dict, status: np.ndarray) -> dict:
    """The variables of the duty cycle of ``sweep`` (none without one): each combined output
    and :data:`STATUS`, ``{name: (dims, values, attrs)}`` on the grid's dimensions but the
    cycle's, then the output's own. ``outputs``: each output's values flat over the grid's
    points, then its own dimensions, in its declared unit; ``status``: flat over the points."""
    axis = sweep.duty_cycle
    if axis is None:
        return {}
    at = grid.dims.index(axis.name)
    taken = np.flatnonzero(shares(axis) > 0)  # the cases that take time
    status = np.take(status.reshape(grid.shape), taken, axis=at)
    combined_status = combine_status(*np.moveaxis(status, at, 0))
    held = values_kept(combined_status)
    dims = tuple(d for d in grid.dims if d != axis.name)
    weights = {"time": shares(axis)[taken]}
    speed = axis.si.get("speed")
    resting = np.zeros(taken.size, dtype=bool)
    weights["revolutions"] = weights["time"]
    if speed is not None:
        resting = np.asarray(speed, dtype=float)[taken] == 0
        weights["revolutions"] = weights["time"] * np.asarray(speed, dtype=float)[taken]
    variables, combined = {}, {}
    for spec in combined_outputs(grid.model):
        if spec.name in grid.model.cycle_combinations:
            continue
        values = np.take(outputs[spec.name].reshape(grid.shape + np.shape(
            outputs[spec.name])[1:]), taken, axis=at)
        if sweep.storage.encoding == "float32":  # from the lives as every store holds them
            values = values.astype(np.float32).astype(float)
        shape = [1] * values.ndim
        shape[at] = -1
        # A case at rest uses up no life, whatever its value there; its time still counts.
        values = np.where(resting.reshape(shape), np.inf, values)
        life = duty_cycle_life(values, weights[spec.cycle].reshape(shape), axis=at)
        combined[spec.name] = np.where(_along(held, life), life, np.nan)
    for name, combine in grid.model.cycle_combinations.items():
        life = np.asarray(combine(combined), dtype=float)
        combined[name] = np.where(_along(held, life), life, np.nan)
    for spec in combined_outputs(grid.model):
        how = (f"by Palmgren and Miner over the load cases' shares of the {spec.cycle}"
               if spec.cycle else "from the lives over the duty cycle, as in one load case")
        variables[spec.name + SUFFIX] = (dims + spec.dims, combined[spec.name], {
            "long_name": f"{spec.short} over the duty cycle",
            "units": cf_units(spec.unit),
            "comment": f"{spec.meaning}; over the duty cycle of axis {axis.name!r}, {how} "
                       f"(time_share), where {STATUS} keeps values",
            "coverage_content_type": "modelResult"})
    variables[STATUS] = (dims, combined_status, {
        "long_name": "solver status over the duty cycle",
        "flag_masks": np.array(STATUS_MASKS, dtype=np.int8),
        "flag_values": np.array(STATUS_VALUES, dtype=np.int8),
        "flag_meanings": " ".join(STATUS_MEANINGS),
        "comment": f"the most severe status of the load cases along {axis.name!r} with a "
                   "share of the time, out_of_validity where any of them is",
        "coverage_content_type": "qualityInformation"})
    return variables


def time_share_coordinate(axis) -> tuple:
    """The coordinate of the duty cycle's time shares along its axis."""
    return ((axis.name,), shares(axis), {
        "long_name": "share of the duty cycle's time", "units": "1",
        "comment": "each load case's share of the time, as the definition gives them in "
                   "proportion, summing to 1"})


def _along(held: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``held`` (over the grid's other dimensions) broadcast over ``values``' own."""
    return held.reshape(held.shape + (1,) * (values.ndim - held.ndim))


def stored_cycle(sweep, grid, read) -> dict:
    """:func:`cycle_variables` of a finished result in a store, ``read(name)`` giving an
    output's or the status' values there (as stored: NaN where a point has none):
    ``{name: values}``."""
    if sweep.duty_cycle is None:
        return {}
    outputs = {}
    for spec in combined_outputs(grid.model):
        if spec.name not in grid.model.cycle_combinations:
            values = np.asarray(read(spec.name), dtype=float)
            outputs[spec.name] = values.reshape((grid.size,) + values.shape[len(grid.shape):])
    status = np.asarray(read("status")).reshape(grid.size)
    return {name: values for name, (_, values, _) in
            cycle_variables(sweep, grid, outputs, status).items()}
