"""A zarr run's store is the one xarray's ``to_zarr`` writes of the same result: the same
metadata (every array's and the group's) and the same values, bit for bit."""
import json
import math
from pathlib import Path

import numpy as np
import pytest
import zarr

from bearing_sweep import spec
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.grid import Grid, block_shape
from bearing_sweep.models.registry import all_models
from bearing_sweep.stores.zarr import ZARR_FORMAT

#: Each model's sweep and the other structures test_conventions writes as netCDF.
DEFINITIONS = Path(__file__).parents[1] / "data" / "every_model"
MODELS = sorted(all_models())
STRUCTURES = sorted((Path(__file__).parents[1] / "data" / "structure").glob("*.toml"))


def points_per_chunk(grid) -> int:
    """Several zarr chunks along the grid's axes: three points each, or on a long sample
    axis 16 chunks, the last one partial."""
    return max(3, math.prod(grid.shape) // 16 + 1)


def xarray_store(sweep, executor, path):
    """The sweep computed in memory and written by xarray, each output and the status in the
    zarr chunks, type, fill value and codecs of the store of a run in chunks of
    ``points_per_chunk``."""
    dataset = run_sweep(sweep, None, executor, progress=False).dataset
    grid = Grid.from_sweep(sweep)
    sizes = dict(zip(grid.dims, block_shape(grid.shape, points_per_chunk(grid))))
    for name in [o.name for o in grid.model.outputs] + ["status"]:
        variable = dataset[name]
        kept = {key: value for key, value in variable.encoding.items()
                if key in ("dtype", "_FillValue")}
        stored = np.dtype(kept.get("dtype", variable.dtype))
        variable.encoding = kept | sweep.storage.zarr_codecs(stored.itemsize) | {
            "chunks": tuple(sizes.get(d, n) for d, n in zip(variable.dims, variable.shape))}
    dataset.to_zarr(path, mode="w", zarr_format=ZARR_FORMAT, consolidated=True)
    return path


#: The stores that cost the most to compute twice (the most outputs, or dynamics): the same
#: writer writes them all, and the other models and designs exercise it in the quick tests;
#: these are compared in the slow ones.
COMPARED_SLOWLY = {"ball_5dof", "cage_dynamics", "cage_dynamics_6dof", "zipped_float32"}


@pytest.fixture(scope="module")
def stores(tmp_path_factory):
    """``store(name)``: the definition's store as a run writes it, and as xarray writes it,
    each made once, when a test first asks for it."""
    folder = tmp_path_factory.mktemp("zarr_structure")
    definitions = {p.stem: p for p in [DEFINITIONS / f"{name}.toml" for name in MODELS]
                   + STRUCTURES}
    made = {}

    def store(name):
        if name not in made:
            sweep = spec.load(definitions[name])
            ours = folder / f"{name}.zarr"
            with Executor(workers=0) as executor:
                run_sweep(sweep, ours, executor,
                          chunk_size=points_per_chunk(Grid.from_sweep(sweep)), progress=False)
                made[name] = ours, xarray_store(sweep, executor, folder / f"{name}-xarray.zarr")
        return made[name]
    return store


@pytest.mark.parametrize("name", [
    pytest.param(name, marks=pytest.mark.slow) if name in COMPARED_SLOWLY else name
    for name in MODELS + [p.stem for p in STRUCTURES]])
def test_the_store_a_run_writes_is_the_one_xarray_writes(stores, name):
    ours, theirs = (metadata(path) for path in stores(name))
    assert ours.keys() == theirs.keys()
    for key in ours:
        assert ours[key] == theirs[key], (name, key)
    ours, theirs = (zarr.open_group(path, mode="r") for path in stores(name))
    for key, array in theirs.arrays():
        assert ours[key].dtype == array.dtype, (name, key)
        assert np.asarray(ours[key][...]).tobytes() == np.asarray(array[...]).tobytes(), (
            name, key)


def metadata(path) -> dict:
    """Every metadata file of a store, parsed, the time of writing (``history``) aside."""
    files = {}
    for file in sorted(Path(path).rglob(".z*")):
        content = json.loads(file.read_text())
        for attributes in (content, content.get("metadata", {}).get(".zattrs", {})):
            if file.parent == Path(path):
                attributes.pop("history", None)
        files[str(file.relative_to(path))] = content
    return files
