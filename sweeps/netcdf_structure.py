"""A labelled dataset (:class:`labels.Labelled`) written into a netCDF4 file without xarray, as
xarray writes it: the same dimensions, variables, types, fill values, filters and attributes,
in the same order (``tests/test_conventions.py`` compares the two files).

A sweep's run writes its file's structure so, then each chunk's values into it
(:class:`store.ChunkWriter`): importing xarray (and the dask.array xarray imports as soon as
it makes a variable, when dask is installed) costs more than half a second, more than a small
sweep computes. What xarray does on writing that matters here (``xarray.conventions``):
a float variable without a ``_FillValue`` in its encoding gets NaN as its fill value, the
values are stored in the encoding's ``dtype``, and coordinates that are not dimensions are
listed in the ``coordinates`` attribute of each variable that spans their dimensions (the
others in a global ``coordinates`` attribute).
"""
from __future__ import annotations

import numpy as np

#: The netCDF4 encodings a sweep's variables use, passed to ``createVariable`` as they are.
_FILTERS = ("compression", "complevel", "shuffle", "chunksizes")


def write_structure(labelled, target, placeholders=frozenset()):
    """Write ``labelled`` into the open, empty ``netCDF4.Dataset`` ``target``, the values of
    the variables named in ``placeholders`` aside: those are created empty, for their values
    to be written later (and the global attributes rewritten: :func:`write_attributes`)."""
    variables = {**labelled.data_vars, **labelled.coords}  # xarray's order
    sizes = {}
    for dims, values, _ in variables.values():
        for dim, size in zip(dims, np.shape(values)):
            sizes.setdefault(dim, size)
    for dim, size in sizes.items():
        target.createDimension(dim, size)
    listed = coordinate_lists(labelled)
    for name, (dims, values, attrs) in variables.items():
        encoding = labelled.encodings.get(name, {})
        values = np.asarray(values)
        stored, fill = stored_as(values, encoding)
        variable = target.createVariable(
            name, str if stored.kind in "OU" else stored, dims, fill_value=fill,
            **{key: encoding[key] for key in _FILTERS if key in encoding})
        attrs = dict(attrs)
        if name in listed:
            attrs["coordinates"] = listed[name]
        variable.setncatts(attrs)
        if name not in placeholders:
            variable[...] = values.astype(stored) if stored.kind != "U" else values
    write_attributes(labelled, target)


def stored_as(values: np.ndarray, encoding: dict) -> tuple:
    """The type a variable's ``values`` are stored in and their fill value (None: none), as
    xarray stores them: the ``encoding``'s ``dtype`` and ``_FillValue``, and NaN for
    floating-point values without one."""
    stored = np.dtype(encoding.get("dtype", values.dtype))
    if "_FillValue" in encoding:
        fill = encoding["_FillValue"]
    else:
        fill = np.nan if stored.kind == "f" else None
    return stored, None if fill is None else stored.type(fill)


def write_attributes(labelled, target):
    """Set ``target``'s global attributes to ``labelled``'s (:func:`global_attributes`)."""
    for name in target.ncattrs():
        target.delncattr(name)
    for name, value in global_attributes(labelled).items():
        target.setncattr(name, value)


def global_attributes(labelled) -> dict:
    """``labelled``'s global attributes, in their order, with xarray's global
    ``coordinates`` where a coordinate spans no variable."""
    attributes = dict(labelled.attrs)
    unlisted = _non_dimension_coordinates(labelled) - {
        name for text in coordinate_lists(labelled).values() for name in text.split()}
    if unlisted:
        attributes["coordinates"] = " ".join(sorted(unlisted))
    return attributes


def coordinate_lists(labelled) -> dict:
    """The ``coordinates`` attribute of each variable that has one: the coordinates that are
    not dimensions and span some of its dimensions (CF's auxiliary coordinates), sorted."""
    variables = {**labelled.data_vars, **labelled.coords}
    auxiliary = _non_dimension_coordinates(labelled)
    lists = {}
    for name, (dims, _, _) in variables.items():
        if name in auxiliary or name in dims:
            continue
        spanned = sorted(c for c in auxiliary if set(labelled.coords[c][0]) <= set(dims))
        if spanned:
            lists[name] = " ".join(spanned)
    return lists


def _non_dimension_coordinates(labelled) -> set:
    dimensions = {d for dims, _, _ in {**labelled.data_vars, **labelled.coords}.values()
                  for d in dims}
    return set(labelled.coords) - dimensions
