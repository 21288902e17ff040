"""Size, writing and reading time of a crb_radial result in each storage setting.

Baseline: the same result written as the engine wrote every file before the [output] table,
float64 and uncompressed. The result, 1e5 points of bearing D of paper 000 (load x clearance x
crown x speed, 60 slices, 14 rollers), is computed once; each setting then writes it through
the engine's own path (``stores.netcdf.result_file``, one chunk at a time, each encoded as a worker
encodes it) and reads it back whole
(``stores.open_result``). Times are the best of three; float64 settings must read back bit for
bit, float32 within its rounding. Prints one row per setting, as ratios against the baseline,
and the chosen default's size ratio (goal: at most 0.5, with writing under a tenth of the
computing time and float64 kept).

A second section: the size of the same result with the outputs that declare ``depends_on``
(the centrifugal force, the viscosity ratio) on the speed axis alone, against every output on
every point (baseline, the files before ``depends_on``), uncompressed and as the default
stores them.
"""
import dataclasses
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from bearing_sweep import spec, stores
from bearing_sweep.evaluate import choose_chunk_size, evaluate_chunk
from bearing_sweep.dependence import on_grid, stored_dims
from bearing_sweep.grid import Grid
from bearing_sweep.stores.blocks import chunk_tally
from bearing_sweep.stores.memory import HeldChunks
from bearing_sweep.stores.netcdf import result_file
from bearing_sweep.stores.structure import provenance
from bearing_sweep.storage import Storage

DEFINITION = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
slices = 60
[axes]
radial_load = { start = "0.5 kN", stop = "12 kN", num = 50 }
clearance = { start = "0 mm", stop = "0.05 mm", num = 20 }
crown = { start = "0 um", stop = "8 um", num = 10 }
speed = { start = "0 rpm", stop = "9000 rpm", num = 10 }
"""
SETTINGS = [Storage("float64", "none")] + [
    Storage("float64", "zlib", level, shuffle) for shuffle in (False, True)
    for level in (1, 4, 9)] + [
    Storage("float64", "zstd", level) for level in (1, 3)] + [
    Storage("float32", "none"), Storage("float32", "zlib", 1, shuffle=False),
    Storage("float32", "zlib", 1, shuffle=True)]
REPEATS = 3


def write(sweep, grid, parts, chunks, path: Path):
    """Write the result at ``path`` through the engine's own path, one chunk at a time: each
    encoded as a worker encodes it, its bytes then written (``hdf5_chunks``)."""
    size = chunks[0][1] - chunks[0][0]
    with result_file(sweep, grid, path, provenance("benchmark"), size,
                           direct=True) as writer:
        for start, stop in chunks:
            part = parts.load(start, stop)
            writer.write(start, stop, {"tally": chunk_tally(grid.model, part),
                                       **writer.encoder.write(grid, start, stop, part)})


def measure(sweep, grid, parts, chunks, path: Path):
    """Best writing and reading times [s] of ``sweep``'s file, its size [B] and its data."""
    writing = reading = np.inf
    for _ in range(REPEATS):
        began = time.perf_counter()
        write(sweep, grid, parts, chunks, path)
        writing = min(writing, time.perf_counter() - began)
        began = time.perf_counter()
        data = stores.open_result(path)
        reading = min(reading, time.perf_counter() - began)
    return writing, reading, path.stat().st_size, data


def main():
    sweep = spec.parse(DEFINITION, "<benchmark>")
    grid = Grid.from_sweep(sweep)
    chunks = grid.chunks(choose_chunk_size(grid, 2))
    parts = HeldChunks()
    began = time.perf_counter()
    for start, stop in chunks:
        parts.save(start, stop, evaluate_chunk(grid, start, stop))
    computing = time.perf_counter() - began
    print(f"output encoding of a crb_radial result, {grid.size} points in {len(chunks)} chunks "
          f"(computed in {computing:.1f} s on one core)")
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for storage in SETTINGS:
            sweep.storage = storage
            rows.append((storage,) + measure(sweep, grid, parts, chunks,
                                             Path(folder) / "result.nc"))
    _, base_write, base_read, base_size, reference = rows[0]
    print(f"  baseline: {rows[0][0].text()}: {base_size / 1e6:.1f} MB, writing "
          f"{base_write:.2f} s, reading {base_read:.2f} s")
    print(f"  {'setting':<30} {'size':>6} {'write':>6} {'read':>6} {'write/compute':>14}  values")
    for storage, writing, reading, size, data in rows:
        print(f"  {storage.text():<30} {size / base_size:6.3f} {writing / base_write:6.2f} "
              f"{reading / base_read:6.2f} {writing / computing:14.3f}  "
              f"{same_values(reference, data, storage)}")
    default = next(row for row in rows if row[0] == Storage())
    print(f"  ratio: {default[3] / base_size:.3f}x the size with the default "
          f"({Storage().text()}; goal: at most 0.5)")
    with tempfile.TemporaryDirectory() as folder:
        folded_sizes(sweep, grid, parts, chunks, Path(folder) / "result.nc")


def folded_sizes(sweep, grid, parts, chunks, path: Path):
    """The file's size with the outputs that declare ``depends_on`` on the axes of their
    inputs, against every output on every point, uncompressed and as the default stores
    them; the folded outputs spread back over the grid must equal the per-point ones."""
    every_point = dataclasses.replace(grid, model=dataclasses.replace(grid.model, outputs=tuple(
        dataclasses.replace(o, depends_on=None) for o in grid.model.outputs)))
    folded = [o.name for o in grid.model.outputs if stored_dims(grid, o) != grid.dims]
    print(f"outputs on the axes of the inputs they depend on ({', '.join(folded)}), the same "
          "result")
    print("  baseline: every output on every point (the files before depends_on)")
    for storage in (Storage("float64", "none"), Storage()):
        sweep.storage = storage
        sizes, results = [], []
        for layout in (every_point, grid):
            write(sweep, layout, parts, chunks, path)
            sizes.append(path.stat().st_size)
            results.append(on_grid(stores.open_result(path)))
        for name in folded:
            assert np.array_equal(results[0][name], results[1][name], equal_nan=True), name
        print(f"  {storage.text()}: {sizes[0] / 1e6:.3f} MB -> {sizes[1] / 1e6:.3f} MB, "
              "values bit for bit")
    print(f"  ratio: {sizes[1] / sizes[0]:.4f}x the size with the default (goal: below 1)")


def same_values(reference, data, storage) -> str:
    """How the outputs read back compare with the uncompressed float64 file's."""
    worst = 0.0
    for name in reference.data_vars:
        expected, found = reference[name].values, data[name].values
        if expected.dtype.kind != "f":
            assert np.array_equal(expected, found), name
            continue
        if storage.encoding == "float64" or found.dtype != np.float32:
            assert np.array_equal(expected, found, equal_nan=True), name
            continue
        # float32 rounds to nearest: half a unit in the last of its 24 bits, relative
        kept = np.isfinite(expected) & (expected != 0)
        relative = np.abs(found[kept].astype(float) / expected[kept] - 1)
        worst = max(worst, float(relative.max(initial=0.0)))
        assert worst <= 2.0 ** -24, (name, worst)
    return "bit for bit" if worst == 0 else f"within {worst:.1e} (float32 rounding)"


if __name__ == "__main__":
    sys.exit(main())
