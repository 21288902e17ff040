"""A chunk of a sweep: how many points it holds, and its evaluation in whatever process
computes it (the model called on its points' inputs in SI, its outputs converted to their
declared units, its failures flagged)."""
from __future__ import annotations

import math

import numpy as np

from .models.registry import MODEL_ERROR, known_status, values_kept
from . import quiet, units
from .grid import Grid
from .interrupts import interruptions_raised
from .stores import structure


#: Largest chunk, in estimated seconds of work on one core (a task costs a few milliseconds of
#: scheduling; within a chunk the model runs in blocks of its ``points_per_call``).
CHUNK_SECONDS = 1.0


def versions(model) -> dict:
    """What a chunk's numbers depend on besides the definition: the package's and the model's
    versions in the process that computes it."""
    return {"package": structure.package_version(), "model": model.version}


def evaluate_chunk(grid: Grid, start: int, stop: int) -> dict:
    """Run the model on points ``start..stop-1``.

    Returns ``{"outputs": {name: array}, "status": array, "errors": [str], "versions": dict}``
    (the :func:`versions` of the process that computed it); outputs are in their declared
    units, with the grid's largest size on each own dimension (NaN beyond a point's own size).
    Points are grouped by their structural inputs (counts, choices) and the model is called
    once per group. An exception in the model marks that group's points with
    ``model_error`` and records its message; it does not stop the sweep, but a Ctrl-C does,
    whatever exception the model turned it into (:func:`interrupts.interruptions_raised`).
    The model's warnings are not shown (:func:`quiet.silenced`): its statuses say it.
    """
    model = grid.model
    count = stop - start
    varying, axis_index = grid.inputs(start, stop)
    outputs = {o.name: np.full((count,) + tuple(grid.dim_sizes[d] for d in o.dims), np.nan)
               for o in model.outputs}
    status = np.full(count, MODEL_ERROR, dtype=np.int8)
    errors = []
    structural = [i.name for i in model.inputs if i.structural and i.name in varying]
    if structural:
        axes = sorted({grid.axis_values[name][0] for name in structural})
        codes = np.ravel_multi_index([axis_index[grid.dims[a]] for a in axes],
                                     [grid.shape[a] for a in axes])
        groups = [np.flatnonzero(codes == code) for code in np.unique(codes)]
    else:
        groups = [np.arange(count)]
    block = model.points_per_call
    groups = [g[i:i + block] for g in groups for i in range(0, g.size, block)]
    for members in groups:
        arguments = dict(grid.fixed)
        for name, values in varying.items():
            if name in structural:
                value = values[members[0]]
                arguments[name] = value.item() if isinstance(value, np.generic) else value
            else:
                arguments[name] = values[members]
        try:
            # A Ctrl-C that compiled code turns into another exception stops the run; the
            # model's warnings stay off the screen (its points say what went wrong).
            with interruptions_raised(), quiet.silenced():
                result = model.function(**arguments)
        except Exception as error:  # one bad group must not cost the whole sweep
            errors.append(f"{type(error).__name__}: {error}".splitlines()[0])
            continue
        with np.errstate(all="ignore"):  # a huge value in its unit is inf, as it says
            for spec in model.outputs:
                value = _per_point(result[spec.name], members.size, len(spec.dims))
                region = (members,) + tuple(slice(0, n) for n in value.shape[1:])
                outputs[spec.name][region] = _from_si(value, spec)
        returned = _per_point(result["status"], members.size, 0)
        unknown = ~known_status(returned)
        if unknown.any():  # a code no reader could decode: the model is wrong there
            errors.append(f"the model returned status {returned[unknown][0]}, not a code of "
                          "bearing_sweep.models.registry")
        status[members] = np.where(unknown, MODEL_ERROR, returned)
    failed = ~values_kept(status)
    for values in outputs.values():
        values[failed] = np.nan  # whatever a model left there, a failed point is NaN
    return {"outputs": outputs, "status": status, "errors": errors, "versions": versions(model)}


def evaluate_into(writer, expected: dict, grid: Grid, start: int, stop: int) -> dict:
    """Run the model on points ``start..stop-1`` and write or encode them with ``writer`` (a
    :class:`stores.zarr.StoreWriter`, or a :class:`stores.hdf5_chunks.ChunkEncoder`) in the
    process that computed them.

    Returns the :func:`versions` that computed them and what the writer returns: the chunk's
    counts (``tally``, :func:`stores.blocks.chunk_tally`), one value per cell of the outputs
    stored on fewer dimensions (``firsts``), for a netCDF file the encoded HDF5 chunks
    (``chunks``); the values themselves never travel. Values computed by other
    :func:`versions` than ``expected`` are neither written nor encoded (the driver refuses
    the chunk).
    """
    result = evaluate_chunk(grid, start, stop)
    if result["versions"] != expected:
        return {"versions": result["versions"]}
    return {"versions": result["versions"], **writer.write(grid, start, stop, result)}


def _from_si(value: np.ndarray, spec) -> np.ndarray:
    """An output's SI values in its declared unit, or in each entry's own unit."""
    if not spec.entry_units:
        return units.from_si(value, units.stored_unit(spec.unit))
    factors = np.vectorize(lambda unit: float(units.from_si(1.0, unit)))(
        np.array(spec.entry_units))
    return value * factors


def _per_point(value, count: int, own_dims: int) -> np.ndarray:
    """``value`` with one leading entry per point (a model given no per-point array returns
    unbatched results)."""
    value = np.asarray(value)
    own = value.shape[value.ndim - own_dims:]
    return np.broadcast_to(value.reshape((-1,) + own), (count,) + own)


def largest_chunk(grid: Grid) -> int:
    """The most points a chunk holds by default: ``CHUNK_SECONDS`` of work on one core, by
    the model's declared cost."""
    return max(1, int(CHUNK_SECONDS / grid.seconds_per_point))


def choose_chunk_size(grid: Grid, workers: int) -> int:
    """Chunks of at most :func:`largest_chunk` (the progress bar moves, an interruption loses
    little), on a cluster eight per worker to balance uneven points; in-process
    (``workers`` 0) as few as that allows: each chunk costs a model call and a write."""
    largest = largest_chunk(grid)
    return max(1, min(largest, math.ceil(grid.size / (8 * workers)) if workers else grid.size))


def installed_versions(model_name: str) -> dict | None:
    """The :func:`versions` a worker computes ``model_name`` with, or None where its
    installation has no such model (its chunks will say what it does)."""
    from .models.registry import get_model

    try:
        return versions(get_model(model_name))
    except KeyError:
        return None

