"""CF-style netCDF datasets: labelled results, units, status flags, provenance, atomic writes."""
from __future__ import annotations

import os
import subprocess
from datetime import datetime, timezone
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import numpy as np
import xarray as xr

from .models.registry import STATUS_DESCRIPTIONS, STATUS_MEANINGS
from . import units
from .grid import Grid, coordinates, described, fixed_inputs
from .parts import replace_durably
from .spec import Sweep

CONVENTIONS = "CF-1.10"


def package_version() -> str:
    try:
        return version("bearing-sweep")
    except PackageNotFoundError:
        return "unknown"


def git_commit() -> str | None:
    """The project's commit (``-dirty`` when it has uncommitted changes), if it is a checkout."""
    root = Path(__file__).resolve().parents[1]
    try:
        commit = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True,
                                text=True, timeout=10, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain",
                                "--untracked-files=no"], capture_output=True, text=True,
                               timeout=10, check=True).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return None
    return commit + ("-dirty" if dirty else "")


def build_dataset(sweep: Sweep, grid: Grid, outputs: dict, status: np.ndarray,
                  scheduler: str, errors=()) -> xr.Dataset:
    """The labelled dataset of a finished sweep (outputs flat over points, as computed)."""
    model = grid.model
    data_vars = {}
    for spec in model.outputs:
        values = outputs[spec.name].reshape(grid.shape + outputs[spec.name].shape[1:])
        attrs = described(spec.short, spec.meaning, None if spec.entry_units else spec.unit)
        attrs["coverage_content_type"] = "modelResult"
        if spec.entry_units:
            # CF has one unit per variable: entries of different kinds carry theirs in a
            # companion (strings need no units), and the variable no units attribute.
            attrs["ancillary_variables"] = f"{spec.name}_units"
            attrs["comment"] = attrs.get("comment", spec.short) + (
                f"; each entry in its own unit, given by {spec.name}_units")
            data_vars[f"{spec.name}_units"] = (spec.dims, np.array(spec.entry_units), {
                "long_name": f"unit of each entry of {spec.name}"})
        data_vars[spec.name] = (grid.dims + spec.dims, values, attrs)
    data_vars["status"] = (grid.dims, status.reshape(grid.shape), {
        "long_name": "solver status of the grid point",
        "flag_values": np.arange(len(STATUS_MEANINGS), dtype=np.int8),
        "flag_meanings": " ".join(STATUS_MEANINGS),
        "comment": "; ".join(f"{name}: {text}" for name, text in STATUS_DESCRIPTIONS.items()),
        "coverage_content_type": "qualityInformation",
    })
    data_vars.update(fixed_inputs(sweep))
    coords = coordinates(sweep)
    for dim in {d for o in model.outputs for d in o.dims}:
        coords[dim] = _dimension(model, grid, sweep, dim)
    attrs = {
        "Conventions": CONVENTIONS,
        "title": sweep.title,
        "source": f"bearing-sweep {package_version()}, model {model.name} version {model.version}",
        "history": f"{datetime.now(timezone.utc).isoformat(timespec='seconds')} "
                   f"bearing-sweep run {sweep.path}",
        "references": model.reference,
        "model": model.name,
        "model_version": model.version,
        "package_version": package_version(),
        "definition": sweep.text,
        "definition_file": str(sweep.path),
        "definition_sha256": sweep.sha256,
        "scheduler": scheduler,
    }
    if sweep.bearing:
        attrs["bearing"] = sweep.bearing
    commit = git_commit()
    if commit:
        attrs["git_commit"] = commit
    if errors:
        attrs["model_errors"] = "\n".join(sorted(set(errors)))
    attrs["fixed_inputs"] = " ".join(n for n, v in sweep.fixed.items() if v is not None)
    dataset = xr.Dataset(data_vars, coords, attrs)
    for name in list(dataset.coords) + attrs["fixed_inputs"].split():
        dataset[name].encoding["_FillValue"] = None  # CF: no fill values on coordinates
    return dataset


def _dimension(model, grid: Grid, sweep: Sweep, dim: str) -> tuple:
    """The coordinate of an output dimension: labels, values the inputs fix (a time, an
    angle), or numbers from 1."""
    size = grid.dim_sizes[dim]
    labels = model.dim_sizes[dim]
    if not (isinstance(labels, str) or callable(labels)):
        return (dim,), np.array(labels), {"long_name": dim.replace("_", " ")}
    numbered = {"long_name": f"{dim} number", "units": "1"}
    coordinate = model.dim_coordinates.get(dim)
    if coordinate is None:
        return (dim,), np.arange(1, size + 1), numbered
    single = {name: sweep.fixed[name].si for name in coordinate.inputs
              if sweep.fixed.get(name) is not None}
    if len(single) < len(coordinate.inputs):
        return (dim,), np.arange(1, size + 1), numbered | {
            "comment": f"{coordinate.meaning} varies along the grid here: see the outputs"}
    values = units.from_si(coordinate.values(size, **single), coordinate.unit)
    return (dim,), values, described(coordinate.meaning, coordinate.meaning, coordinate.unit)


def assemble(sweep: Sweep, grid: Grid, parts, chunks, path, scheduler: str) -> tuple:
    """Write the sweep's dataset from its part files, one chunk in memory at a time.

    The file's structure (coordinates, attributes, empty variables) is written by xarray,
    the chunks' values then into it, region by region, and the finished file renamed into
    place: an existing file at ``path`` stays intact until then. Returns the count of points
    by status, the models' error messages and the counts of the outputs a model declares
    ``counted``.
    """
    import dask.array
    import netCDF4

    model = grid.model
    counts = np.zeros(len(STATUS_MEANINGS), dtype=np.int64)
    errors = set()
    noted = {o.counted[0]: 0 for o in model.outputs if o.counted}
    for start, stop in chunks:  # first pass: what the attributes and the summary must say
        part = parts.load(start, stop)
        counts += np.bincount(part["status"], minlength=len(STATUS_MEANINGS))
        errors.update(part["errors"])
        for output in (o for o in model.outputs if o.counted):
            text, where = output.counted
            noted[text] += int(np.count_nonzero(where(part["outputs"][output.name])))
    lazy = {o.name: dask.array.full((grid.size,) + tuple(grid.dim_sizes[d] for d in o.dims),
                                    np.nan, chunks=-1)  # never computed: one chunk
            for o in model.outputs}
    status = dask.array.zeros(grid.size, dtype=np.int8, chunks=-1)
    skeleton = build_dataset(sweep, grid, lazy, status, scheduler, sorted(errors))
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        # The structure only: dump_to_store queues the lazy values for a write that is never
        # made (the parts fill them in below), and closing the store closes the file.
        skeleton_store = xr.backends.NetCDF4DataStore.open(temporary, mode="w")
        try:
            skeleton.dump_to_store(skeleton_store)
        finally:
            skeleton_store.close()
        del skeleton
        with netCDF4.Dataset(temporary, "r+") as target:
            for start, stop in chunks:
                part = parts.load(start, stop)
                values = dict(part["outputs"], status=part["status"])
                for name, data in values.items():
                    variable = target.variables[name]
                    for index, low, high in _regions(grid.shape, start, stop):
                        block = data[low - start:high - start]
                        variable[index or ...] = block.reshape(
                            tuple(s.stop - s.start for s in index) + block.shape[1:])
        replace_durably(temporary, path)
    finally:
        if temporary.exists():
            temporary.unlink()
    return dict(zip(STATUS_MEANINGS, counts.tolist())), sorted(errors), noted


def _regions(shape: tuple, start: int, stop: int, offset: int = 0):
    """Split points ``start..stop-1`` of a C-ordered grid into rectangular regions.

    Yields ``(index, low, high)``: a tuple of slices (one per axis) and the range of point
    numbers it holds, in order; at most two regions per axis.
    """
    if start >= stop:
        return
    if not shape:
        yield (), offset + start, offset + stop
        return
    inner = int(np.prod(shape[1:], dtype=np.int64))
    first, head = divmod(start, inner)
    last, tail = divmod(stop, inner)
    if first == last:
        for index, low, high in _regions(shape[1:], head, tail, offset + first * inner):
            yield (slice(first, first + 1),) + index, low, high
        return
    if head:
        for index, low, high in _regions(shape[1:], head, inner, offset + first * inner):
            yield (slice(first, first + 1),) + index, low, high
        first += 1
    if last > first:
        yield ((slice(first, last),) + tuple(slice(0, n) for n in shape[1:]),
               offset + first * inner, offset + last * inner)
    if tail:
        for index, low, high in _regions(shape[1:], 0, tail, offset + last * inner):
            yield (slice(last, last + 1),) + index, low, high


def write_netcdf(dataset: xr.Dataset, path) -> Path:
    """Write ``dataset`` to ``path`` atomically: a temporary file in the same folder, renamed.

    An existing file at ``path`` stays intact until the new one is complete.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        # Uncompressed: zlib would make writing ten times slower for half the size; a user who
        # wants it smaller can run `nccopy -d 1`.
        dataset.to_netcdf(temporary, engine="netcdf4")
        replace_durably(temporary, path)
    finally:
        if temporary.exists():
            temporary.unlink()
    return path


def open_result(path) -> xr.Dataset:
    """Open a sweep's netCDF file fully into memory (the file is closed afterwards)."""
    with xr.open_dataset(path, engine="netcdf4") as dataset:
        return dataset.load()
