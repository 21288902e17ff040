"""CF labelling of a sweep's dataset: every coordinate, input and output with its units
(UDUNITS), ``long_name`` and ``comment``; the status flags; the global attributes.

Inputs are stored in the unit the model declares for them (the same in every file of a model,
so that files combine safely), outputs in their customary units, and a unit UDUNITS cannot
write (a fractional power) in SI, named in the ``comment``.
"""
from __future__ import annotations

from dataclasses import dataclass
from datetime import datetime, timezone
from typing import TYPE_CHECKING

import numpy as np

from .models.registry import STATUS_DESCRIPTIONS, STATUS_MASKS, STATUS_MEANINGS, STATUS_VALUES
from . import units
from .dependence import stored_dims, stored_shape
from .duty_cycle import STATUS as CYCLE_STATUS, cycle_names, cycle_variables, \
    time_share_coordinate
from .grid import Grid
from .sample import saltelli_rows
from .definition.axes import TIME_SHARE
from .definition.values import Value, convert_written
from .spec import Sweep

if TYPE_CHECKING:
    import xarray as xr

CONVENTIONS = "CF-1.10"
#: The ``comment`` of the status variable: how to read its flags, and each meaning.
STATUS_COMMENT = (
    "a meaning holds where status & flag_masks == flag_values (CF 3.5): each point has one "
    "outcome (converged, not_converged, infeasible, model_error, no_root_in_range) and may "
    "also be out_of_validity; 0 is converged within validity. " + "; ".join(
        f"{name}: {text}" for name, text in STATUS_DESCRIPTIONS.items()))


@dataclass
class Labelled:
    """A labelled dataset as plain data, for xarray (:meth:`dataset`) or for writing without
    it (:mod:`stores.structure`): ``data_vars`` and ``coords`` map names to ``(dims, values,
    attrs)`` in the dataset's order, ``encodings`` names to how the file stores them."""

    data_vars: dict
    coords: dict
    attrs: dict
    encodings: dict

    def dataset(self) -> xr.Dataset:
        """The xarray dataset, each variable with its encoding."""
        import xarray as xr

        dataset = xr.Dataset(self.data_vars, self.coords, self.attrs)
        for name, encoding in self.encodings.items():
            dataset[name].encoding.update(encoding)
        return dataset


def labelled_dataset(sweep: Sweep, grid: Grid, outputs: dict, status: np.ndarray,
                     provenance: dict, errors=()) -> xr.Dataset:
    """The labelled dataset of a finished sweep (:func:`labelled` in xarray)."""
    return labelled(sweep, grid, outputs, status, provenance, errors).dataset()


def labelled(sweep: Sweep, grid: Grid, outputs: dict, status: np.ndarray,
             provenance: dict, errors=()) -> Labelled:
    """The labelled dataset of a finished sweep, as plain data.

    ``outputs``: each flat over the cells of the grid's dimensions it is stored on (the
    points, as computed, or fewer for an output that depends on fewer inputs:
    :func:`dependence.stored_dims`), then its own dimensions.

    ``provenance`` says how it was made: ``scheduler``, ``package_version`` and
    ``git_commit`` (None outside a checkout).
    """
    model = grid.model
    data_vars = {}
    for spec in model.outputs:
        dims = stored_dims(grid, spec)
        values = outputs[spec.name].reshape(stored_shape(grid, spec)
                                            + outputs[spec.name].shape[1:])
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
        note = stored_note(spec.dtype == "int", sweep.storage)
        if note:
            attrs["comment"] = attrs.get("comment", spec.short) + "; " + note
        data_vars[spec.name] = (dims + spec.dims, values, attrs)
    data_vars["status"] = (grid.dims, status.reshape(grid.shape), {
        "long_name": "solver status of the grid point",
        # CF bit fields: an outcome and, apart from it, whether the point is out of validity
        "flag_masks": np.array(STATUS_MASKS, dtype=np.int8),
        "flag_values": np.array(STATUS_VALUES, dtype=np.int8),
        "flag_meanings": " ".join(STATUS_MEANINGS),
        "comment": STATUS_COMMENT,
        "coverage_content_type": "qualityInformation",
    })
    data_vars.update(cycle_variables(sweep, grid, outputs, status))
    data_vars.update(fixed_inputs(sweep))
    coords = coordinates(sweep)
    for dim in dict.fromkeys(d for o in model.outputs for d in o.dims):  # in declared order
        coords[dim] = dimension_coordinate(model, grid, sweep, dim)
    attrs = {
        "Conventions": CONVENTIONS,
        "title": sweep.title,
        "source": f"bearing-sweep {provenance['package_version']}, model {model.name} "
                  f"version {model.version}",
        "history": f"{datetime.now(timezone.utc).isoformat(timespec='seconds')} "
                   f"bearing-sweep run {sweep.path}",
        "references": model.reference,
        "model": model.name,
        "model_version": model.version,
        "package_version": provenance["package_version"],
        "definition": sweep.text,
        "definition_file": str(sweep.path),
        "definition_sha256": sweep.sha256,
        "values_sha256": grid.values_sha256,
        "scheduler": provenance["scheduler"],
        "output_encoding": sweep.storage.text(),
    }
    if sweep.bearing:
        attrs["bearing"] = sweep.bearing
    if sweep.sampling is not None:
        attrs.update(sample_method=sweep.sampling.method, sample_size=sweep.sampling.n,
                     sample_seed=sweep.sampling.seed,
                     sample_inputs=" ".join(sweep.sampling.distributions))
        if sweep.sampling.blocks:
            attrs["sample_replicates"] = sweep.sampling.replicates
    if provenance.get("git_commit"):
        attrs["git_commit"] = provenance["git_commit"]
    if errors:
        attrs["model_errors"] = "\n".join(sorted(set(errors)))
    attrs["fixed_inputs"] = " ".join(n for n, v in sweep.fixed.items() if v is not None)
    # CF: no fill values on coordinates
    encodings = {name: {"_FillValue": None} for name in list(coords)
                 + attrs["fixed_inputs"].split()}
    for spec in model.outputs:  # how the file stores them (in memory: float64 and NaN)
        encodings[spec.name] = sweep.storage.variable_encoding(spec.dtype == "int")
    encodings["status"] = {**sweep.storage.variable_encoding(integral=True),
                           "dtype": np.int8, "_FillValue": None}  # every point has one
    for name in cycle_names(sweep):
        encodings[name] = dict(encodings["status"]) if name == CYCLE_STATUS \
            else sweep.storage.variable_encoding()
    return Labelled(data_vars, coords, attrs, encodings)


def stored_note(integral: bool, storage) -> str:
    """What an output's ``comment`` says of how the file stores it, if not as float64."""
    if integral:
        return "stored as integers, the _FillValue where a point has no value"
    if storage.encoding == "float32":
        return "computed in float64, stored as float32 (about 7 significant digits)"
    return ""


def dimension_coordinate(model, grid: Grid, sweep: Sweep, dim: str) -> tuple:
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


def coordinates(sweep: Sweep) -> dict:
    """xarray coordinates of the grid, each input in the unit the model declares for it.

    Returns ``{name: (dims, values, attrs)}``: one dimension coordinate per axis (a zipped
    axis' labels) and a coordinate along its axis for each zipped parameter. Every file of a
    model stores an input in the same unit, so files combine safely; the unit the user wrote
    is kept in the attribute ``written_units``.
    """
    coords = {}
    for axis in sweep.axes:
        if axis.labels is None:
            name, values = next(iter(axis.values.items()))
            coords[name] = ((name,), declared_values(sweep, name, values),
                            input_attrs(sweep, name, values[0].unit))
            continue
        labels = np.array(axis.labels)
        sampling = sweep.sampling if axis.name == "sample" else None
        comment = "labels of a zipped axis" if sampling is None else (
            f"number of the sample in a {sampling.method} design of seed {sampling.seed}")
        coords[axis.name] = ((axis.name,), labels, {"long_name": axis.name.replace("_", " "),
                                                    "comment": comment}
                             | ({"units": "1"} if labels.dtype.kind in "iu" else {}))
        for name, values in axis.values.items():
            extra = sweep.model.input(name).dims if any(np.ndim(v.shown) for v in values) else ()
            attrs = input_attrs(sweep, name, values[0].unit)
            if sampling is not None:
                attrs["distribution"] = sampling.distributions[name]
            coords[name] = ((axis.name,) + extra, declared_values(sweep, name, values), attrs)
        if sampling is not None and sampling.blocks:
            coords.update(saltelli_coordinates(sampling))
        if axis.time_shares is not None:
            coords[TIME_SHARE] = time_share_coordinate(axis)
    return coords


def saltelli_coordinates(sampling) -> dict:
    """The block of Saltelli's design each sample belongs to, as CF flags: A, B, then A
    with one input's values taken from B, for each sampled input (``replicates * n`` samples
    each); and its replicate, an independent scrambling (``sample.saltelli_rows``)."""
    block, replicate = saltelli_rows(sampling.n, len(sampling.blocks) - 2, sampling.replicates)
    return {"saltelli_block": (("sample",), block.astype(np.int8), {
                "long_name": "block of the Saltelli design",
                "flag_values": np.arange(len(sampling.blocks), dtype=np.int8),
                "flag_meanings": " ".join(sampling.blocks),
                "comment": "A and B: independent samples; AB_<input>: A with that input's "
                           "values from B (Saltelli et al. 2010, doi:10.1016/j.cpc.2009.09.018)"}),
            "saltelli_replicate": (("sample",), replicate.astype(np.int8), {
                "long_name": "replicate of the Saltelli design", "units": "1",
                "comment": f"numbered from 0: each of the {sampling.replicates} replicates is an "
                           f"independent scrambling of the Sobol' sequence of the "
                           f"{sampling.n} base samples; the spread of their estimates gives "
                           "the Sobol' indices' intervals"})}


def fixed_inputs(sweep: Sweep) -> dict:
    """The inputs not on an axis, as variables ``{name: (dims, value, attrs)}`` in their
    declared units: kept in the file, but not as scalar coordinates (xarray would print them
    all in every plot's title)."""
    variables = {}
    for name, value in sweep.fixed.items():
        if value is None:
            continue
        attrs = input_attrs(sweep, name, value.unit)
        attrs["origin"] = sweep.origin.get(name, "")
        dims = sweep.model.input(name).dims if np.ndim(value.shown) else ()
        variables[name] = (dims, declared_values(sweep, name, [value])[0], attrs)
    return variables


def declared_values(sweep: Sweep, name: str, values: list[Value]) -> np.ndarray:
    """The values of input ``name`` in its declared unit, stacked (points first)."""
    spec = sweep.model.input(name)
    first = values[0].shown
    if isinstance(first, str):
        return np.array([v.shown for v in values])
    target = units.stored_unit(spec.unit)
    quantity = spec.kind == "quantity"
    if all(np.ndim(value.shown) == 0 for value in values):  # an axis of single values
        stacked = np.array([value.shown for value in values], dtype=float)
        if quantity:
            # Each unit's values converted at once, tidied to 15 digits so that "4 kN" is
            # stored as 4000 N, not 4000.0000000000005 (value by value the same numbers).
            written = np.array([value.unit for value in values], dtype=object)
            for unit in set(written.tolist()) - {target}:
                where = written == unit
                stacked[where] = convert_written(stacked[where], unit, target, tidy=True)
        return stacked.astype(np.int64) if spec.kind == "count" else stacked
    shown = []
    for value in values:  # patterns: an array each
        magnitude = np.asarray(value.shown, dtype=float)
        if quantity and value.unit != target:
            magnitude = convert_written(magnitude, value.unit, target, tidy=True)
        shown.append(magnitude)
    size = max(np.size(a) for a in shown)
    if any(a.ndim for a in shown):  # a single value on a zipped axis of patterns: repeat it
        shown = [np.broadcast_to(a, (size,)) for a in shown]
    stacked = np.stack(shown)
    return stacked.astype(np.int64) if spec.kind == "count" else stacked


def input_attrs(sweep: Sweep, name: str, written: str) -> dict:
    """``long_name``, UDUNITS ``units`` and the unit the user wrote, of input ``name``."""
    spec = sweep.model.input(name)
    if spec.kind in ("choice", "subset"):
        return described(spec.short, spec.meaning, None) | {
            "accepted_values": " ".join(spec.choices)}
    attrs = described(spec.short, spec.meaning, spec.unit)
    if written and written not in ("1", units.stored_unit(spec.unit)):  # unless stored so
        attrs["written_units"] = written
    return attrs


def described(label: str, meaning: str, unit: str | None) -> dict:
    """``long_name``, ``units`` (UDUNITS) and ``comment`` of a variable; a unit UDUNITS
    cannot express is named in the comment instead (with the values in SI)."""
    attrs = {"long_name": label}
    comment = meaning if meaning != label else ""
    if unit is not None:
        cf = units.cf_units(unit or "1")
        if cf is not None:
            attrs["units"] = cf
        else:
            comment += (". " if comment else "") + (
                f"Units: {units.si_text(unit)} (SI); UDUNITS has no fractional powers, so "
                "there is no units attribute")
    if comment:
        attrs["comment"] = comment
    return attrs
