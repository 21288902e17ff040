"""How a sweep's outputs are stored in its netCDF file or zarr store: in float64 or float32,
compressed or not (the ``[output]`` table of a definition, ``bearing-sweep run --encoding
--compression``), and the outputs a model declares integral as integers.

The default, float64 with zlib at level 1 and no shuffle filter, came from
``benchmarks/output_encoding.py`` (its figures in ``benchmarks/RESULTS.md``): on a crb_radial
result it keeps every value bit for bit in well under half the uncompressed size, for little
more than the uncompressed writing time (level 1 is deflated by ISA-L: ``stores.hdf5_chunks``).
The per-roller arrays, most of the file, hold many zeros (unloaded rollers) that compress
better without shuffle; higher levels save little for much more time.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

ENCODINGS = ("float64", "float32")
#: Each compression and its levels (HDF5's zlib filter: 1-9; zstd: 1-22).
COMPRESSIONS = {"none": None, "zlib": range(1, 10), "zstd": range(1, 23)}
#: The level of a compression named without one ("zlib"): zlib's from the benchmark, zstd's
#: own default.
DEFAULT_LEVELS = {"zlib": 1, "zstd": 3}
#: The type of an output declared integral (``Output.dtype == "int"``): int32 reads back as
#: float64 in xarray (a smaller integer would read back as float32), the type the same
#: output has in memory.
INTEGER_TYPE = np.int32
#: The fill value of an integer output where a point has no value: netCDF's default for its
#: int type (``NC_FILL_INT``), which every netCDF reader already treats as missing.
INTEGER_FILL = np.int32(-2147483647)


@dataclass(frozen=True)
class Storage:
    """How the outputs are written: ``encoding`` (``"float64"`` or ``"float32"``) for the
    outputs that are not integral, and their ``compression`` (``"none"``, ``"zlib"`` or
    ``"zstd"``) at ``level``, with zlib the ``shuffle`` filter (bytes grouped by significance
    before compressing: smooth values then compress better, runs of zeros worse)."""

    encoding: str = "float64"
    compression: str = "zlib"
    level: int = DEFAULT_LEVELS["zlib"]
    shuffle: bool = False

    def text(self) -> str:
        """The settings in words, for the file's attributes: "float64, zlib level 1, shuffle"."""
        if self.compression == "none":
            return f"{self.encoding}, uncompressed"
        return f"{self.encoding}, {self.compression} level {self.level}" + (
            ", shuffle" if self.shuffles else "")

    @property
    def shuffles(self) -> bool:
        """Whether the shuffle filter is used: netCDF4 applies it before zlib only."""
        return self.shuffle and self.compression == "zlib"

    def variable_encoding(self, integral: bool = False) -> dict:
        """xarray's netCDF4 encoding of one output (``integral``: declared an integer)."""
        encoding = {}
        if integral:
            encoding.update(dtype=INTEGER_TYPE, _FillValue=INTEGER_FILL)
        elif self.encoding == "float32":
            encoding["dtype"] = np.float32
        if self.compression != "none":
            encoding.update(compression=self.compression, complevel=self.level,
                            shuffle=self.shuffles)
        return encoding

    def zarr_codecs(self, itemsize: int) -> dict:
        """xarray's zarr encoding of the same compression (zarr format 2): numcodecs' Zlib or
        Zstd at the same level, with zlib the shuffle filter on items of ``itemsize`` bytes
        (the stored type's); nothing for ``"none"``."""
        import numcodecs

        if self.compression == "none":
            return {"compressors": None, "filters": None}
        codec = {"zlib": numcodecs.Zlib, "zstd": numcodecs.Zstd}[self.compression]
        return {"compressors": (codec(level=self.level),),
                "filters": (numcodecs.Shuffle(elementsize=itemsize),) if self.shuffles else None}


def integral_values(values: np.ndarray, name: str) -> np.ndarray:
    """An integral output's values as stored: integers, with the fill value where NaN.

    A value that is not an integer is a fault of the model's declaration, not a point to
    store rounded: it raises ``ValueError`` naming the output.
    """
    missing = np.isnan(values)
    filled = np.where(missing, 0.0, values)
    if not np.array_equal(filled, np.rint(filled)):
        raise ValueError(f"output {name!r} is declared an integer but holds "
                         f"{float(filled[filled != np.rint(filled)].flat[0])!r}")
    return np.where(missing, INTEGER_FILL, filled).astype(INTEGER_TYPE)
