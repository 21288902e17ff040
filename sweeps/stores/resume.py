"""Resume state: the finished chunks kept on disk beside a sweep's output, so that an
interrupted sweep resumes.

``<output>.parts/`` holds a manifest (what the parts belong to: the definition's sha256, the
model's and the package's versions, the grid's size, the chunk size and what the parts hold:
a netCDF file's encoded chunks, :mod:`hdf5_chunks`, for one storage) and one ``.npz`` file per
finished chunk, each written atomically and flushed to the disk before it is renamed into
place (a zarr output keeps its chunks' values in its store instead: :mod:`.zarr`). Parts of
another definition, model, package version or storage are discarded, with a message, and so
is a folder whose manifest is not one this program writes; a part that cannot be read (a power
loss before it reached the disk) or that does not hold what its name says (each records its
range; :meth:`Parts.damage`) is computed again, and a file in the folder that is no part of
the run is removed, with a message. Nothing changes in the folder before :meth:`Parts.begin`.
"""
from __future__ import annotations

import json
import re
import shutil
import zipfile
from pathlib import Path

import numpy as np

from ..models.registry import known_status
from .blocks import STATUS_CODES
from .durable import TEMPORARY, write_durably
from .paths import PARTS_SUFFIX, UnsafeOutput


class UnreadablePart(OSError):
    """A part file that cannot be read; the message is for the user."""


class Parts:
    """The part files of one output (of ``grid``, when given: what its parts must hold is
    checked against it).

    :meth:`open` only looks at the folder; nothing in it changes until :meth:`begin`, called
    once every refusal that may come before computing has passed (a disk too small, a
    cluster that cannot start, workers of another version): a run refused leaves an earlier
    run's parts as they were, even those it would have discarded.
    """

    #: The suffix of a finished chunk's file.
    suffix = ".npz"
    #: What the folder holds besides the finished chunks' files.
    own_entries = ("manifest.json",)

    def __init__(self, output, key: dict, grid=None, storage=None):
        output = Path(output)
        self.folder = output.with_name(output.name + PARTS_SUFFIX)
        self.key, self.grid, self.storage = key, grid, storage
        self.size = None
        self.plan = None  # what begin() does: "create", "discard" (then create) or "resume"
        self.usable, self.unusable, self.discarding = set(), {}, None

    def open(self, chunk_size: int, fresh: bool, chunks_of=None) -> int:
        """Look at the folder (nothing changes: :meth:`begin` does it); return the chunk size
        to use (a resumed sweep keeps its own).

        ``chunks_of(size)`` gives the ``(start, stop)`` of every chunk of the sweep in chunks
        of ``size`` points: a file in the folder that is none of them is to be removed, as is
        a part that cannot be read or does not hold what its name says (:meth:`damage`); the
        others are :meth:`finished`. Parts of another definition, model, package or storage,
        or with a manifest this program does not write, are to be discarded; a folder without
        a manifest that holds what no run writes is refused (:class:`UnsafeOutput`).
        """
        self.size, self.plan = chunk_size, "create"
        self.usable, self.unusable, self.discarding = set(), {}, None
        if not self.folder.exists():
            return chunk_size
        manifest = self.folder / "manifest.json"
        found, damage = _read_manifest(manifest, self.key)
        if not manifest.exists():
            self._refuse_if_not_ours()
        count = self.count_on_disk()
        if fresh or damage or found != {**self.key, "chunk_size": found["chunk_size"]}:
            self.plan = "discard"
            if damage:
                self.discarding = (f"{damage} in {self.folder}: discarding the folder"
                                   + (f" and its {count} finished chunks" if count else ""))
            elif count:
                why = "--fresh" if fresh else "the definition, model, package or storage changed"
                self.discarding = f"{why}: discarding {count} finished chunks in {self.folder}"
            return chunk_size
        self.plan, self.size = "resume", found["chunk_size"]
        self._survey(set(chunks_of(self.size)) if chunks_of else None)
        return self.size

    def _refuse_if_not_ours(self):
        """A folder without a manifest holds only what a run writes (its manifest is written
        first, durably): anything else is someone's, and refused rather than removed."""
        for entry in sorted(self.folder.iterdir()):
            if not (entry.name in self.own_entries or TEMPORARY.fullmatch(entry.name)
                    or self.bounds(entry.name)):
                raise UnsafeOutput(f"{self.folder}: holds {entry.name} and no manifest.json: "
                                   "not the folder of an interrupted run's parts; refusing to "
                                   "use it (move it away or choose another output)")

    def _survey(self, chunks: set | None):
        """Sort the folder's entries: the finished chunks of this run (``chunks``: the
        ``(start, stop)`` of each, None: any) that can be used, and what :meth:`begin` is to
        remove: ``{"unreadable": [...], "wrong": [...], "stray": [...], "temporary": [...]}``
        (a temporary file a killed run left: the run holds the output's lock, no other run
        writes it)."""
        self.unusable = {"unreadable": [], "wrong": [], "stray": [], "temporary": []}
        for entry in sorted(self.folder.iterdir()):
            if entry.name in self.own_entries:
                continue
            bounds = self.bounds(entry.name)
            if bounds is None or (chunks is not None and bounds not in chunks):
                kind = "temporary" if TEMPORARY.fullmatch(entry.name) else "stray"
                self.unusable[kind].append((entry, None))
                continue
            found = self.unusable_part(entry, *bounds)
            if found:
                self.unusable[found[0]].append((entry, found[1]))
            else:
                self.usable.add(bounds)

    def begin(self, log):
        """Make the folder this run's, saying so to ``log``: discard it, make it, or remove
        from it what :meth:`open` found unusable."""
        plan, self.plan = self.plan, None
        if plan == "resume":
            lines = (("unreadable", "unreadable part", "computing {} again"),
                     ("wrong", "a part that does not hold what its name says,",
                      "computing {} again"),
                     ("stray", "a file that is no part of this run,", "removed {}"))
            for kind, what, then in lines:
                found = self.unusable[kind]
                if found:
                    entry, reason = found[0]
                    more = f" and {len(found) - 1} more" if len(found) > 1 else ""
                    log(f"{what} {entry.name}{f' ({reason})' if reason else ''}{more} in "
                        f"{self.folder}: " + then.format("them" if more else "it"))
            for entry, _ in (one for found in self.unusable.values() for one in found):
                _remove(entry)
            if self.usable:
                count = len(self.usable)
                log(f"resuming: {count} chunk{'s' * (count != 1)} already computed in "
                    f"{self.folder}")
            return
        if plan == "discard":
            if self.discarding:
                log(self.discarding)
            shutil.rmtree(self.folder)
        if plan in ("discard", "create"):
            self.folder.mkdir(parents=True)
            text = json.dumps({**self.key, "chunk_size": self.size}).encode()
            write_durably(self.folder / "manifest.json", lambda handle: handle.write(text))

    def bounds(self, name: str) -> tuple[int, int] | None:
        """The ``(start, stop)`` of the finished chunk whose file is named ``name``, or None
        for a name :meth:`path` does not give."""
        found = re.fullmatch(rf"chunk-(\d{{12}})-(\d{{12}}){re.escape(self.suffix)}", name)
        if found is None or int(found[1]) >= int(found[2]):
            return None
        return int(found[1]), int(found[2])

    def unusable_part(self, path: Path, start: int, stop: int) -> tuple[str, str] | None:
        """Why the part at ``path`` cannot be used as the chunk of points ``start..stop-1``:
        ``("unreadable", reason)`` or ``("wrong", reason)`` (:meth:`damage`), or None."""
        try:
            with np.load(path) as data:
                reason = self.damage(data, start, stop)
        except (EOFError, KeyError, zipfile.BadZipFile):  # cut short, or an array missing
            return "unreadable", "incomplete"
        except (OSError, ValueError) as error:
            return "unreadable", (str(error).splitlines()[0] if str(error)
                                  else type(error).__name__)
        return None if reason is None else ("wrong", reason)

    def damage(self, data, start: int, stop: int) -> str | None:
        """What the open part ``data`` says of itself that is not what the chunk of points
        ``start..stop-1`` holds, in words, or None: its range, its statuses (as many as the
        chunk has points, each a code of the registry) and, when the grid is known, the
        model's outputs (names, shapes, type). ``KeyError`` for an array it lacks."""
        reason = range_damage(data, start, stop) or status_damage(data["status"], stop - start)
        if reason:
            return reason
        errors = data["errors"]
        if errors.ndim != 1 or errors.dtype.kind not in "US":
            return "its error messages unreadable"
        found = {key[len("output_"):]: data[key] for key in data.files
                 if key.startswith("output_")}
        if self.grid is None:
            return None
        declared = {o.name: (stop - start,) + tuple(self.grid.dim_sizes[d] for d in o.dims)
                    for o in self.grid.model.outputs}
        if set(found) != set(declared):
            return f"outputs {sorted(found)}, not the model's {sorted(declared)}"
        for name, values in found.items():
            if values.shape != declared[name] or values.dtype != np.float64:
                return (f"output {name} of shape {values.shape} and type {values.dtype}, not "
                        f"{declared[name]} float64")
        return None

    def count(self) -> int:
        """How many finished chunks this run has (:meth:`finished`)."""
        return len(self.finished())

    def count_on_disk(self) -> int:
        """How many files in the folder are named as finished chunks."""
        return len(self._on_disk())

    def finished(self) -> set:
        """``(start, stop)`` of every finished chunk: before :meth:`begin`, those :meth:`open`
        found usable; then every one on disk."""
        return set(self.usable) if self.plan is not None else self._on_disk()

    def _on_disk(self) -> set:
        found = (self.bounds(path.name) for path in self.folder.glob(f"chunk-*{self.suffix}"))
        return {bounds for bounds in found if bounds is not None}

    def path(self, start: int, stop: int) -> Path:
        return self.folder / f"chunk-{start:012d}-{stop:012d}{self.suffix}"

    def save(self, start: int, stop: int, result: dict):
        """Keep the finished chunk of points ``start..stop-1``: :meth:`arrays` and its range."""
        arrays = self.arrays(result)
        arrays["bounds"] = np.array([start, stop], dtype=np.int64)
        write_durably(self.path(start, stop), lambda handle: np.savez(handle, **arrays))

    def arrays(self, result: dict) -> dict:
        """What a part file holds of a computed chunk (as ``evaluate.evaluate_chunk`` returns
        it): its outputs, statuses and error messages."""
        arrays = {f"output_{name}": values for name, values in result["outputs"].items()}
        arrays["status"] = result["status"]
        arrays["errors"] = np.array(result["errors"], dtype=str)
        return arrays

    def load(self, start: int, stop: int) -> dict:
        path = self.path(start, stop)
        try:
            with np.load(path) as data:
                reason = self.damage(data, start, stop)
                if reason is None:
                    return self.read(data)
        except (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile) as error:
            reason = f"unreadable: {type(error).__name__}"
        # Found usable when the run began, damaged since: removed, so that the next run
        # computes it again.
        path.unlink(missing_ok=True)
        raise UnreadablePart(f"{path}: unusable part ({reason}); it is removed: run the same "
                             "command again to compute it")

    def read(self, data) -> dict:
        """A finished chunk from its open part file ``data`` (as :meth:`save` wrote it)."""
        return {"outputs": {key[len("output_"):]: data[key] for key in data.files
                            if key.startswith("output_")},
                "status": data["status"], "errors": data["errors"].tolist()}

    def remove(self):
        shutil.rmtree(self.folder, ignore_errors=True)


def _read_manifest(path: Path, key: dict) -> tuple:
    """A parts folder's manifest at ``path`` and what makes it other than a manifest this
    program writes with ``key``, in words (None for one it writes, of this run or of
    another)."""
    try:
        found = json.loads(path.read_text())
    except (OSError, ValueError):
        return None, "no readable manifest"
    return found, _manifest_damage(found, key)


def _manifest_damage(found, key: dict) -> str | None:
    if not isinstance(found, dict):
        kind = {list: "an array", str: "a string", type(None): "null", bool: "a boolean"}.get(
            type(found), "a number")
        return f"a manifest holding {kind}, not an object"
    size = found.get("chunk_size")
    if isinstance(size, bool) or not isinstance(size, int) or size < 1:
        return f"a manifest whose chunk_size is {size!r}, not a positive integer"
    if "definition_sha256" not in found or not set(found) <= set(key) | {"chunk_size"}:
        return "a manifest with keys this version of bearing-sweep does not write"
    return None


def _remove(path: Path):
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    else:
        path.unlink(missing_ok=True)


def range_damage(data, start: int, stop: int) -> str | None:
    """What the open part ``data`` says of its range (its ``bounds``) that is not
    ``start..stop-1``, or None."""
    if "bounds" not in data.files:
        return "no range recorded in it"
    bounds = data["bounds"]
    if bounds.shape != (2,) or bounds.dtype.kind not in "iu":
        return "its range unreadable"
    low, high = (int(bound) for bound in bounds)
    return None if (low, high) == (start, stop) else f"it holds points {low}..{high - 1}"


def status_damage(status: np.ndarray, points: int) -> str | None:
    """What is wrong with a chunk's ``status`` of ``points`` points, or None: one per point,
    each a code of the registry."""
    if status.shape != (points,) or status.dtype != np.int8:
        return f"{status.size} statuses of type {status.dtype}, not {points} of int8"
    unknown = ~known_status(status)
    return f"status {status[unknown][0]}, not a code of the registry" if unknown.any() else None


def saved_counts(result: dict) -> dict:
    """A finished chunk's counts (``result["tally"]``, as ``store.chunk_tally`` gives them)
    and its values of the outputs stored on fewer dimensions (``result["firsts"]``: ``{name:
    (points, values)}``) as the arrays of a part file; :func:`load_counts` reads them."""
    arrays = {"tally": np.array(json.dumps(result["tally"]))}
    for name, (points, values) in result["firsts"].items():
        arrays[f"points_{name}"], arrays[f"values_{name}"] = points, values
    return arrays


def load_counts(data) -> tuple[dict, dict]:
    """The counts and the ``{name: (points, values)}`` of an open part file (``data``) that
    :func:`saved_counts` filled."""
    firsts = {key[len("points_"):]: (data[key], data["values_" + key[len("points_"):]])
              for key in data.files if key.startswith("points_")}
    return json.loads(str(data["tally"])), firsts


def counts_damage(data, grid, start: int, stop: int) -> str | None:
    """What an open part file holding :func:`saved_counts` (``data``) says of itself that is
    not the chunk of points ``start..stop-1`` of ``grid``: its range, its counts (of as many
    points, each status a code of the registry, the model's counted outputs) and the values
    it gives the outputs stored on fewer dimensions (one per cell, at points of the chunk, of
    the output's own shape); None where it says nothing else. ``KeyError`` or ``ValueError``
    for what cannot be read."""
    from ..dependence import reduced_outputs

    reason = range_damage(data, start, stop)
    if reason:
        return reason
    tally, firsts = load_counts(data)
    status, errors, noted = (tally.get(key) if isinstance(tally, dict) else None
                             for key in ("status", "errors", "noted"))
    if not (isinstance(status, list) and len(status) == STATUS_CODES
            and all(type(n) is int and n >= 0 for n in status)
            and isinstance(errors, list) and all(isinstance(e, str) for e in errors)
            and isinstance(noted, dict) and all(type(n) is int and n >= 0
                                                for n in noted.values())):
        return "its counts unreadable"
    if sum(status) != stop - start:
        return f"counts of {sum(status)} points, not {stop - start}"
    codes = np.flatnonzero(status)
    if not known_status(codes).all():
        return f"status {codes[~known_status(codes)][0]}, not a code of the registry"
    if grid is None:
        return None
    counted = {o.counted[0] for o in grid.model.outputs if o.counted}
    if set(noted) != counted:
        return f"counts of {sorted(noted)}, not of the model's {sorted(counted)}"
    reduced = {o.name: o for o in reduced_outputs(grid)}
    if set(firsts) != set(reduced):
        return f"values of {sorted(firsts)}, not of the outputs on fewer axes {sorted(reduced)}"
    for name, (points, values) in firsts.items():
        own = tuple(grid.dim_sizes[d] for d in reduced[name].dims)
        if (points.ndim != 1 or points.dtype.kind not in "iu"
                or ((points < start) | (points >= stop)).any()
                or values.shape != points.shape + own):
            return f"values of {name} not of points {start}..{stop - 1}"
    return None


