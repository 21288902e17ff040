"""A labelled dataset (:class:`labels.Labelled`) written into a zarr store without xarray, as
xarray's ``to_zarr`` writes it: the same arrays (type, shape, chunks, compressor, filters, fill
value), attributes and consolidated metadata (``tests/test_zarr_structure.py`` compares the
two stores).

A zarr run writes its store's structure so, its workers the values: importing xarray and the
dask.array it needs for values not yet computed costs more than half a second. What xarray
does on writing zarr format 2 that matters here, beside what it does for netCDF
(:mod:`netcdf_structure`): the fill value is the array's (``.zarray``), not an attribute; each
array's dimensions are its attribute ``_ARRAY_DIMENSIONS``; arrays without an encoding get
zarr's default chunks and compressor; attribute values are plain JSON (an array a list).
"""
from __future__ import annotations

import numpy as np

from .netcdf_structure import coordinate_lists, global_attributes, stored_as


def write_structure(labelled, path, layouts: dict, zarr_format: int):
    """Write ``labelled`` as a new zarr group at ``path``, its metadata consolidated. The
    arrays named in ``layouts`` (``{name: {"chunks": ..., "compressors": ..., "filters":
    ...}}``, as xarray's encoding gives them) are created so and left without values, for
    them to be written later; the others get zarr's defaults and their values."""
    import zarr

    group = zarr.open_group(path, mode="w", zarr_format=zarr_format)
    group.attrs.put(attribute_values(global_attributes(labelled)))
    listed = coordinate_lists(labelled)
    for name, (dims, values, attrs) in {**labelled.data_vars, **labelled.coords}.items():
        values = np.asarray(values)
        stored, fill = stored_as(values, labelled.encodings.get(name, {}))
        array = group.create(name, shape=values.shape, dtype=stored, fill_value=fill,
                             overwrite=True, **layouts.get(name, {"chunks": "auto"}))
        attrs = dict(attrs) | ({"coordinates": listed[name]} if name in listed else {})
        array.attrs.put(attribute_values(attrs | {"_ARRAY_DIMENSIONS": list(dims)}))
        if name not in layouts:
            array[...] = values.astype(stored)
    zarr.consolidate_metadata(str(path), zarr_format=zarr_format)


def attribute_values(attributes: dict) -> dict:
    """``attributes`` as JSON holds them, as xarray stores them: an array as a list, a numpy
    number as a Python one."""
    return {key: value.tolist() if isinstance(value, (np.ndarray, np.generic)) else value
            for key, value in attributes.items()}
