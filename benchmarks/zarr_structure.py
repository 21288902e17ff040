"""A zarr run's structure written without xarray, against xarray writing it.

A run with ``-o result.zarr`` writes its store's structure (coordinates, attributes, the
outputs and status without values) before any chunk is computed (``stores.zarr``). We write
it with zarr alone; xarray could write the same with ``to_zarr(compute=False)`` over dask
placeholders, at the cost of importing xarray and dask.array. Each side runs in a new process
(interpreter, imports, the structure of a 20 000-point ``crb_radial`` sweep in chunks of 2 000
points), in interleaved pairs; the ratio is of CPU time (this process's children: others'
load disturbs it less than wall time). The ratio says what our own writer saves each zarr
run; ``python benchmarks/zarr_structure.py PAIRS`` takes another number of pairs.
"""
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

PAIRS = 5
SIDE = r'''
import sys
from pathlib import Path
from bearing_sweep import spec
from bearing_sweep.grid import Grid, block_shape
sweep = spec.parse("""
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[axes]
radial_load = { start = "0.5 kN", stop = "12 kN", num = 100 }
clearance = { start = "0 mm", stop = "0.04 mm", num = 200 }
""")
grid = Grid.from_sweep(sweep)
block = block_shape(grid.shape, 2000)
out = Path(sys.argv[2])
if sys.argv[1] == "ours":
    from bearing_sweep.stores.zarr import write_structure
    write_structure(sweep, grid, block, "benchmark", out)
else:
    import dask.array
    import xarray
    from bearing_sweep.stores.structure import provenance, structure
    from bearing_sweep.stores.zarr import ZARR_FORMAT
    labelled = structure(sweep, grid, provenance("benchmark"))
    sizes = dict(zip(grid.dims, block))
    placeholders = {
        name: (dims, dask.array.zeros(values.shape, dtype=values.dtype,
                                      chunks=tuple(sizes.get(d, n)
                                                   for d, n in zip(dims, values.shape))), attrs)
        for name, (dims, values, attrs) in labelled.data_vars.items()}
    dataset = xarray.Dataset(placeholders, labelled.coords, labelled.attrs)
    for name, encoding in labelled.encodings.items():
        if name in dataset.variables:
            dataset[name].encoding = dict(encoding)
    dataset.to_zarr(out, mode="w", zarr_format=ZARR_FORMAT, consolidated=True, compute=False)
'''


def cpu_seconds(side: str, folder: Path) -> float:
    """CPU seconds of a new process writing the structure ``side`` ("ours" or "xarray")."""
    out = folder / f"{side}.zarr"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, "-c", SIDE, side, str(out)], check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    shutil.rmtree(out)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main(pairs: int = PAIRS):
    load = os.getloadavg()
    with tempfile.TemporaryDirectory() as folder:
        cpu_seconds("ours", Path(folder))  # compiled files written once, outside the pairs
        times = [(cpu_seconds("xarray", Path(folder)), cpu_seconds("ours", Path(folder)))
                 for _ in range(pairs)]
    ratios = [theirs / ours for theirs, ours in times]
    print("zarr run's structure written without xarray (20 000 points of crb_radial)")
    print(f"  baseline: xarray's to_zarr(compute=False), {statistics.median(t for t, _ in times):.2f}"
          f" s CPU; ours {statistics.median(o for _, o in times):.2f} s CPU, each in a new process")
    print(f"  ratio: {statistics.median(ratios):.2f}x xarray's CPU over ours (goal: above 1); "
          f"pairs {min(ratios):.2f}-{max(ratios):.2f}x, load average {load[0]:.2f}")


if __name__ == "__main__":
    main(*(int(arg) for arg in sys.argv[1:]))
