"""What a sweep will take, said before it starts: the size of its result on the disk and its
time, and a result the disk cannot hold refused (:class:`InsufficientSpace`).

The size is exact before compression: every variable of the result in the type it is stored
in (``[output]`` encoding, integral outputs as 32-bit integers, ``status`` one byte), on the
dimensions it is stored on. How much zlib or zstd save depends on the values (0.41 on the
crb_radial benchmark of docs/user-guide/output-size.md, nearly nothing on smooth scalars), so before
computing that size is an upper bound; once chunks are stored, the bytes they took per point
give an estimate of the rest (:meth:`Footprint.check`). A netCDF result needs its size twice
until it is complete: the finished chunks are kept as parts beside the file being written (so
that an interrupted run resumes). The time is the model's declared cost per point on one core
(``Grid.seconds_per_point``: the model's ``seconds_per_point``, a constant or a function of
the points' inputs; it also sizes the chunks) over the workers.
"""
from __future__ import annotations

import math
import os
import shutil
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .structure import stored_as, structure

#: A run that the estimate says takes longer [s], or writes more [bytes], says so as it starts.
ANNOUNCED_SECONDS = 10.0
ANNOUNCED_BYTES = 1e9


class InsufficientSpace(OSError):
    """The disk cannot hold the result; the message (one line) is for the user."""


def result_bytes(sweep, grid) -> int:
    """The size of the sweep's result uncompressed [bytes]: every variable's values in the
    type it is stored in (what compression can shrink, never grow but by a few bytes a
    chunk)."""

    labelled = structure(sweep, grid, {"scheduler": "", "package_version": "",
                                       "git_commit": None})
    total = 0
    for name, (_, values, _) in {**labelled.data_vars, **labelled.coords}.items():
        values = np.asarray(values)
        stored, _ = stored_as(values, labelled.encodings.get(name, {}))
        total += math.prod(values.shape) * stored.itemsize
    return total


def free_bytes(output) -> tuple[int, Path]:
    """The free space of the filesystem ``output`` will be on, and the folder measured (the
    nearest that exists)."""
    folder = Path(os.path.abspath(output)).parent
    while not folder.exists() and folder != folder.parent:
        folder = folder.parent
    return shutil.disk_usage(folder).free, folder


def in_words(count: float) -> str:
    """A size in bytes in decimal units, to three significant digits: "437 GB"."""
    for unit, size in (("PB", 1e15), ("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if count >= size:
            return f"{count / size:.3g} {unit}"
    return f"{count:.0f} bytes"


def duration(seconds: float) -> str:
    """A duration in words, to two significant digits: "11 h", "25 min", "40 s"."""
    for unit, size in (("days", 86400), ("h", 3600), ("min", 60)):
        if seconds >= 2 * size:
            return f"{seconds / size:.2g} {unit}"
    return f"{seconds:.2g} s"


@dataclass
class Footprint:
    """A run's needs: ``points`` to compute of ``total`` (the rest resumed), the result's size
    uncompressed (``upper``, bytes), how many ``copies`` of it the disk holds until it is
    complete (2 for a netCDF file and its parts, 1 for a zarr store), whether ``compressed``,
    the estimated wall time (``seconds``), and the output's filesystem (``free`` bytes, in
    ``folder``)."""

    output: str
    points: int
    total: int
    upper: int
    copies: int
    compressed: bool
    seconds: float
    free: int
    folder: Path
    measured: list = field(default_factory=lambda: [0, 0])  # points and bytes stored so far

    @classmethod
    def of(cls, sweep, grid, output, points: int, workers: int, netcdf: bool) -> "Footprint":
        free, folder = free_bytes(output)
        return cls(str(output), points, grid.size, result_bytes(sweep, grid), 2 if netcdf else 1,
                   sweep.storage.compression != "none",
                   points * grid.seconds_per_point / max(1, workers), free, folder)

    @property
    def needed(self) -> int:
        """The space the rest of the run needs at most [bytes]: a netCDF file is written
        whole (its resumed chunks too), its parts for the chunks still to compute; a zarr
        store holds the resumed chunks already."""
        remaining = self.upper * self.points / max(1, self.total)
        return round(self.upper + remaining if self.copies == 2 else remaining)

    def text(self, model: str, workers: str) -> str:
        """The line that announces the run."""
        line = (f"{model}: {self.points} points to compute, about {duration(self.seconds)} on "
                f"{workers}; the result up to {in_words(self.upper)}")
        if self.compressed:
            line += " (before compression)"
        if self.copies == 2:
            line += ", and its finished chunks as much until it is written"
        return line + f"; {in_words(self.free)} free in {self.folder}"

    def announced(self) -> bool:
        """Whether the run is long or large enough to say so as it starts."""
        return self.seconds >= ANNOUNCED_SECONDS or self.upper >= ANNOUNCED_BYTES

    def refuse_if_too_large(self):
        """Refuse, before any computing, a result stored uncompressed that the disk cannot
        hold: the only storage whose size is known before the values are."""
        if self.compressed or self.needed <= self.free:
            return
        what = (f"the file {in_words(self.upper)} and its finished chunks as much until it is "
                "written" if self.copies == 2 else f"the store {in_words(self.upper)}")
        raise InsufficientSpace(
            f"{self.output}: needs {in_words(self.needed)} of disk ({what}; about "
            f"{duration(self.seconds)} of computing) and {self.folder} has "
            f"{in_words(self.free)} free: free some space, store float32 (--encoding float32) "
            "or compress (--compression zlib), or choose another output")

    def check(self, points: int, stored: int, kept: int):
        """Refuse to go on when the chunks stored so far (``points`` more points in
        ``stored`` more bytes) say the rest cannot fit in what is free now; ``kept``: the
        finished chunks, for the message."""
        self.measured[0] += points
        self.measured[1] += stored
        done, written = self.measured
        left = self.points - done
        if not done or left <= 0:
            return
        per_point = written / done
        needed = per_point * left * self.copies
        free, _ = free_bytes(self.output)
        if needed <= free:
            return
        raise InsufficientSpace(
            f"{self.output}: needs about {in_words(needed)} more of disk (at the "
            f"{per_point:.3g} bytes a point the {done} points stored so far took"
            + (", twice: the file and its finished chunks" if self.copies == 2 else "")
            + f") and {self.folder} has {in_words(free)} free; "
            + (f"the {kept} finished chunks are kept" if kept != 1 else
               "the finished chunk is kept")
            + ": free some space and run the same command again")
