"""Output stores: where a sweep's computed chunks go, behind one interface (:mod:`.base`).

A result at a path ending in ``.zarr`` is a zarr store (:mod:`.zarr`), any other path a netCDF
file (:mod:`.netcdf`, its chunks encoded by the workers where it can: :mod:`.hdf5_chunks`), no
path a dataset in memory (:mod:`.memory`). What they share: which paths may be written
(:mod:`.paths`), locks and atomic, durable writes (:mod:`.durable`), the resume state of an
interrupted run (:mod:`.resume`), a chunk's regions and counts (:mod:`.blocks`), a result's
structure (:mod:`.structure`) and its size on the disk, said before computing
(:mod:`.footprint`). A store is added as one module with a :class:`.base.Store`
and a line in :data:`BACKENDS`.
"""
from __future__ import annotations

import os
from importlib import import_module
from pathlib import Path
from typing import TYPE_CHECKING

from .paths import ZARR_SUFFIX, is_zarr

if TYPE_CHECKING:
    import xarray as xr

#: The store of each output suffix (lower case; any other path is a netCDF file): its module
#: and class, imported when a run asks for it.
BACKENDS = {ZARR_SUFFIX: ("zarr", "ZarrStore")}
#: The store of any other path.
DEFAULT_BACKEND = ("netcdf", "NetcdfStore")


def for_output(output, sweep):
    """The store of a run of ``sweep`` writing ``output`` (None: a dataset in memory); an
    output path that must not be written is refused (``paths.UnsafeOutput``)."""
    if output is None:
        from .memory import MemoryStore
        return MemoryStore(sweep)
    module, name = BACKENDS.get(Path(output).suffix.lower(), DEFAULT_BACKEND)
    return getattr(import_module(f".{module}", __name__), name)(output, sweep)


def open_result(path) -> xr.Dataset:
    """Open a sweep's netCDF file (or zarr store) fully into memory (it is closed afterwards)."""
    import xarray as xr

    with xr.open_dataset(path, engine=result_engine(path)) as dataset:
        return dataset.load()


def is_result(path) -> bool:
    """Whether ``path`` holds something to open as a result: a file, or a zarr store (a
    folder); :func:`open_result` says whether it is one."""
    return os.path.isfile(path) or (is_zarr(path) and os.path.isdir(path))


def result_engine(path) -> str:
    """xarray's engine for a sweep's result at ``path``: zarr for a ``.zarr`` store."""
    return "zarr" if is_zarr(path) else "netcdf4"

