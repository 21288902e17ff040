"""Finished chunks kept on disk beside a sweep's output, so that an interrupted sweep resumes.

``<output>.parts/`` holds a manifest (what the parts belong to: the definition's sha256, the
model's and the package's versions, the grid's size, the chunk size and what the parts hold:
a netCDF file's encoded chunks, ``hdf5_chunks``, for one storage) and one ``.npz`` file per
finished chunk, each written atomically and flushed to the disk before it is renamed into
place (a zarr output keeps its chunks' values in its store instead: ``zarr_store``). Parts of
another definition, model, package version or storage are discarded, with a message, and so
is a folder whose manifest is not one this program writes; a part that cannot be read (a power
loss before it reached the disk) is computed again, and a file in the folder that is no part of
the run is removed, with a message.
A lock on ``.<output>.lock`` keeps two runs from writing the same output; the run that holds it
removes the temporary files that a killed run left (:func:`remove_stale_temporaries`), and
:func:`check_output` refuses an output path that holds something other than an earlier result.
"""
from __future__ import annotations

import errno
import json
import os
import re
import shutil
import stat
import tempfile
import zipfile
from contextlib import contextmanager
from pathlib import Path

import filelock
import numpy as np

from .spec import SpecError


class OutputBusy(OSError):
    """Another run holds the output; the message is for the user."""


class UnsafeOutput(SpecError):
    """An output path that must not be written; the message is for the user."""


class UnreadablePart(OSError):
    """A part file that cannot be read; the message is for the user."""


#: The first bytes of a netCDF file: classic and 64-bit offset formats, and HDF5 (netCDF-4).
NETCDF_SIGNATURES = (b"CDF\x01", b"CDF\x02", b"CDF\x05", b"\x89HDF\r\n\x1a\n")
#: The suffix of an output written as a zarr store (a folder) rather than a netCDF file.
ZARR_SUFFIX = ".zarr"
#: The suffix of the folder beside an output that keeps its run's finished chunks.
PARTS_SUFFIX = ".parts"
#: Names that are only a suffix: a hidden file, not a result with a name.
BARE_SUFFIXES = (ZARR_SUFFIX, ".nc")
#: The errors of a file that cannot be written on (a full disk or quota, a file larger than
#: the process may write, a disk failing or read-only).
WRITING_ERRORS = (errno.ENOSPC, errno.EFBIG, errno.EDQUOT, errno.EIO, errno.EROFS)


def is_zarr(output) -> bool:
    """Whether ``output`` names a zarr store (by its suffix, as ``-o result.zarr``, in any
    case: ``result.ZARR`` must not become a netCDF file under a store's name)."""
    return output is not None and Path(output).suffix.lower() == ZARR_SUFFIX


def path_argument(value, name: str, expected: str = "", optional: bool = True) -> str | None:
    """A path given to a function of the API as its argument ``name``, as a string (None
    stays None where it is ``optional``); anything else is a :class:`SpecError` naming the
    argument."""
    if value is None and optional:
        return None
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if not isinstance(value, str) or not value.strip():
        raise SpecError(f"{name}={value!r}: expected {expected or 'a'} path (a str or "
                        "os.PathLike), not " + ("an empty one" if isinstance(value, str)
                                                else type(value).__name__))
    return value


def check_output(output, definition=None):
    """Refuse, before any computing, an output path that a sweep must not replace.

    Accepted: a path that does not exist yet in a folder that exists or can be made, a
    regular netCDF file that this program wrote (its global attributes name it: only the
    header is read), or for a ``.zarr`` output a zarr store this program wrote (its group
    attributes name it: only they are read). Anything else (the definition itself, another
    folder, a device, a pipe, a symbolic link, another program's file) raises
    :class:`UnsafeOutput`; nothing is opened but a regular file's first bytes and header.
    """
    _check_name(output)
    check_outside_results(output)
    output = Path(output)
    try:
        found = output.lstat()
    except (FileNotFoundError, NotADirectoryError):  # the second: a file on the way to it
        found = None
    except OSError as error:
        raise UnsafeOutput(f"{output}: cannot be the output: {error.strerror}") from None
    if found is None:
        _check_folder(output)
        return
    if definition is not None and _same_file(output, Path(definition)):
        raise UnsafeOutput(f"{output}: is the sweep definition itself; choose another output")
    kind = _file_kind(found.st_mode)
    if kind == "a folder" and is_zarr(output):
        reason = _not_our_store(output)
        if reason:
            raise UnsafeOutput(f"{output}: exists and is not a zarr store written by "
                               f"bearing-sweep ({reason}); refusing to replace it (remove it or "
                               "choose another output)")
        # A reader of a store reads each chunk by its path when asked for it, and a chunk
        # missing reads as the fill value: whatever replaced the store, a reader that has it
        # open would read the new run's values (or fill values) under the coordinates it
        # read from the old one.
        raise UnsafeOutput(f"{output}: holds an earlier zarr store of bearing-sweep, which is "
                           "never replaced (a reader that has it open would read the new "
                           "values under its old coordinates): remove it first (close its "
                           "readers, then rm -r it) or choose another output")
    if kind == "regular file" and is_zarr(output):
        raise UnsafeOutput(f"{output}: exists and is a file; a .zarr output is a zarr store, a "
                           "folder: refusing to replace it (choose another output)")
    if kind != "regular file":
        raise UnsafeOutput(f"{output}: exists and is {kind}, not an earlier result; refusing to "
                           "replace it (choose another output)")
    reason = _not_ours(output)
    if reason:
        raise UnsafeOutput(f"{output}: exists and is not a netCDF file written by bearing-sweep "
                           f"({reason}); refusing to replace it (remove it or choose another "
                           "output)")


def _check_name(output):
    """Refuse an output name that does not say plainly what it is: only a suffix (``.zarr``,
    ``.nc``: a hidden file), a name ending in a dot (which some filesystems drop: ``x.zarr.``
    would be a netCDF file there, a store elsewhere), or a netCDF name ending in a separator
    (a folder, where a netCDF result is a file)."""
    text = os.fspath(output)
    name = Path(text).name
    if name.lower() in BARE_SUFFIXES:
        kind = "store" if is_zarr(f"x{name}") else "file"
        raise UnsafeOutput(f"{text}: is only a suffix; name the {kind}, as result{name}")
    if name.endswith(".") and name.strip("."):
        raise UnsafeOutput(f"{text}: ends in a dot, which some filesystems drop; name it "
                           f"{name.rstrip('.')} (a .zarr store or a netCDF file)")
    separators = (os.sep, os.altsep) if os.altsep else (os.sep,)
    if text.endswith(separators) and name not in ("", ".", "..") and not is_zarr(text):
        raise UnsafeOutput(f"{text}: names a folder (it ends in {text[-1]}), and a netCDF "
                           f"result is a file: name it {name} (a folder is written only as a "
                           "zarr store, a name ending in .zarr)")


def check_outside_results(path):
    """Refuse (:class:`UnsafeOutput`) a path to write inside a zarr store (a folder named
    ``*.zarr``, in any case: a store holds what its run wrote, and is never changed after) or
    inside a parts folder (``*.parts``: the folder of an output's finished chunks, which its
    run removes, with what else is in it), by the path as given or as its links lead."""
    given = Path(os.path.abspath(path))
    for folder in [*given.parents, *Path(os.path.realpath(given.parent)).parents,
                   Path(os.path.realpath(given.parent))]:
        if is_zarr(folder):
            raise UnsafeOutput(f"{path}: is inside {folder}, and a .zarr folder is a zarr "
                               "store, which holds only what its run wrote: choose a path "
                               "outside it")
        if folder.name.endswith(PARTS_SUFFIX):
            owner = folder.name[:-len(PARTS_SUFFIX)] or "an output"
            raise UnsafeOutput(f"{path}: is inside {folder}, the folder where a run keeps the "
                               f"finished chunks of {owner}, and removes with all it holds: "
                               "choose a path outside it")


def check_parts_folder(output):
    """Refuse (:class:`UnsafeOutput`) a run's output whose parts folder (:class:`Parts`: it is
    emptied and removed once the run is complete) exists and is not a folder (a file, a
    link)."""
    output = Path(output)
    folder = output.with_name(output.name + PARTS_SUFFIX)
    try:
        kind = _file_kind(folder.lstat().st_mode)
    except OSError:
        return
    if kind != "a folder":
        kind = "a file" if kind == "regular file" else kind
        raise UnsafeOutput(f"{folder}: exists and is {kind}, not the folder of an interrupted "
                           f"run's parts of {output.name}; refusing to use it (remove it or "
                           "choose another output)")


def _check_folder(output: Path):
    """The output's folder exists, or the nearest existing ancestor is a writable folder."""
    ancestor = output.parent
    while not os.path.lexists(ancestor) and ancestor != ancestor.parent:
        ancestor = ancestor.parent
    if not ancestor.is_dir():
        raise UnsafeOutput(f"{output}: its folder cannot be created: {ancestor} is not a folder")
    if not os.access(ancestor, os.W_OK | os.X_OK):
        raise UnsafeOutput(f"{output}: its folder cannot be written: permission denied on "
                           f"{ancestor}")


def _same_file(first: Path, second: Path) -> bool:
    try:
        return os.path.samefile(first, second)
    except OSError:
        return False


def _file_kind(mode: int) -> str:
    for test, kind in ((stat.S_ISREG, "regular file"), (stat.S_ISDIR, "a folder"),
                       (stat.S_ISLNK, "a symbolic link"), (stat.S_ISFIFO, "a named pipe"),
                       (stat.S_ISCHR, "a device"), (stat.S_ISBLK, "a device"),
                       (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return kind
    return "not a regular file"


def _not_ours(path: Path) -> str | None:
    """Why the regular file at ``path`` is not a result of this program, or None if it is."""
    import netCDF4

    try:
        with open(path, "rb") as handle:
            head = handle.read(8)
    except OSError as error:
        return error.strerror
    if not head.startswith(NETCDF_SIGNATURES):
        return "not a netCDF file"
    try:
        with netCDF4.Dataset(path, "r") as dataset:
            attributes = dataset.__dict__
    except OSError as error:
        return str(error).splitlines()[0]
    return None if _names_us(attributes) else "its attributes do not name bearing-sweep"


def _not_our_store(path: Path) -> str | None:
    """Why the folder at ``path`` is not a zarr store of this program, or None if it is.
    Reads its group attributes only (``.zattrs``, zarr format 2, as this program writes)."""
    if not (path / ".zgroup").is_file():
        return "no zarr group of format 2 in it"
    attributes = _read_json(path / ".zattrs")
    if not isinstance(attributes, dict):
        return "its attributes cannot be read"
    return None if _names_us(attributes) else "its attributes do not name bearing-sweep"


def _names_us(attributes: dict) -> bool:
    """Whether a result's global attributes say this program wrote it."""
    return ("definition_sha256" in attributes
            or str(attributes.get("source", "")).startswith("bearing-sweep"))


class Parts:
    """The part files of one output."""

    #: The suffix of a finished chunk's file.
    suffix = ".npz"
    #: What the folder holds besides the finished chunks' files.
    own_entries = ("manifest.json",)

    def __init__(self, output, key: dict):
        output = Path(output)
        self.folder = output.with_name(output.name + PARTS_SUFFIX)
        self.key = key

    def open(self, chunk_size: int, fresh: bool, log, chunks_of=None) -> int:
        """Prepare the folder; return the chunk size to use (a resumed sweep keeps its own).

        ``chunks_of(size)`` gives the ``(start, stop)`` of every chunk of the sweep in chunks
        of ``size`` points: a file in the folder that is none of them is removed (with a line
        to ``log``), as is a part that cannot be read.
        """
        manifest = self.folder / "manifest.json"
        if self.folder.exists():
            found, damage = _read_manifest(manifest, self.key)
            count = self.count()
            if fresh or damage or found != {**self.key, "chunk_size": found["chunk_size"]}:
                if damage:
                    log(f"{damage} in {self.folder}: discarding the folder"
                        + (f" and its {count} finished chunks" if count else ""))
                elif count:
                    why = "--fresh" if fresh else (
                        "the definition, model, package or storage changed")
                    log(f"{why}: discarding {count} finished chunks in {self.folder}")
                shutil.rmtree(self.folder)
            else:
                size = found["chunk_size"]
                count = self._remove_unusable(log, set(chunks_of(size)) if chunks_of else None)
                if count:
                    log(f"resuming: {count} chunk{'s' * (count != 1)} already computed in "
                        f"{self.folder}")
                return size
        self.folder.mkdir(parents=True)
        text = json.dumps({**self.key, "chunk_size": chunk_size}).encode()
        write_durably(manifest, lambda handle: handle.write(text))
        return chunk_size

    def _remove_unusable(self, log, chunks: set | None) -> int:
        """Remove from the folder what is no finished chunk of this run (``chunks``: the
        ``(start, stop)`` of each, None: any), with one line to ``log`` for the files that
        are neither ours nor readable, and the temporary files a killed run left (the run
        holds the output's lock: no other run writes them), quietly; return how many
        finished chunks are left."""
        unreadable, stray, left = [], [], 0
        for entry in sorted(self.folder.iterdir()):
            if entry.name in self.own_entries:
                continue
            bounds = self.bounds(entry.name)
            if bounds is None or (chunks is not None and bounds not in chunks):
                if not _TEMPORARY.fullmatch(entry.name):
                    stray.append(entry.name)
                _remove(entry)
                continue
            reason = self.unreadable(entry, bounds[1] - bounds[0])
            if reason:
                unreadable.append(f"{entry.name} ({reason})")
                _remove(entry)
            else:
                left += 1
        for found, what, then in ((unreadable, "unreadable part", "computing {} again"),
                                  (stray, "a file that is no part of this run,",
                                   "removed {}")):
            if found:
                more = f" and {len(found) - 1} more" if len(found) > 1 else ""
                log(f"{what} {found[0]}{more} in {self.folder}: "
                    + then.format("them" if more else "it"))
        return left

    def bounds(self, name: str) -> tuple[int, int] | None:
        """The ``(start, stop)`` of the finished chunk whose file is named ``name``, or None
        for a name :meth:`path` does not give."""
        found = re.fullmatch(rf"chunk-(\d{{12}})-(\d{{12}}){re.escape(self.suffix)}", name)
        if found is None or int(found[1]) >= int(found[2]):
            return None
        return int(found[1]), int(found[2])

    def unreadable(self, path: Path, points: int) -> str | None:
        """Why the finished chunk at ``path`` cannot be used, or None."""
        return _unreadable(path, points)

    def count(self) -> int:
        """How many finished chunks are on disk."""
        return len(self.finished())

    def finished(self) -> set:
        """``(start, stop)`` of every chunk on disk."""
        found = (self.bounds(path.name) for path in self.folder.glob(f"chunk-*{self.suffix}"))
        return {bounds for bounds in found if bounds is not None}

    def path(self, start: int, stop: int) -> Path:
        return self.folder / f"chunk-{start:012d}-{stop:012d}{self.suffix}"

    def save(self, start: int, stop: int, result: dict):
        arrays = {f"output_{name}": values for name, values in result["outputs"].items()}
        arrays["status"] = result["status"]
        arrays["errors"] = np.array(result["errors"], dtype=str)
        write_durably(self.path(start, stop), lambda handle: np.savez(handle, **arrays))

    def load(self, start: int, stop: int) -> dict:
        path = self.path(start, stop)
        try:
            with np.load(path) as data:
                return self.read(data)
        except (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile) as error:
            # Found readable when the run began, damaged since: removed, so that the next run
            # computes it again.
            path.unlink(missing_ok=True)
            raise UnreadablePart(f"{path}: unreadable part ({type(error).__name__}); it is "
                                 "removed: run the same command again to compute it") from None

    def read(self, data) -> dict:
        """A finished chunk from its open part file ``data`` (as :meth:`save` wrote it)."""
        return {"outputs": {key[len("output_"):]: data[key] for key in data.files
                            if key.startswith("output_")},
                "status": data["status"], "errors": data["errors"].tolist()}

    def remove(self):
        shutil.rmtree(self.folder, ignore_errors=True)


class HeldChunks:
    """Finished chunks held in memory, for a sweep returned without a file: the interface of
    :class:`Parts`, with nothing to resume."""

    folder = None

    def __init__(self):
        self.chunks = {}

    def open(self, chunk_size: int, fresh: bool, log, chunks_of=None) -> int:
        return chunk_size

    def finished(self) -> set:
        return set(self.chunks)

    def save(self, start: int, stop: int, result: dict):
        self.chunks[start, stop] = result

    def load(self, start: int, stop: int) -> dict:
        return self.chunks[start, stop]

    def remove(self):
        self.chunks.clear()


class OutputLock:
    """An exclusive lock on an output path, released when the process ends, however it ends.

    The lock file is removed while it is still locked, never after: a run that opened it
    meanwhile then finds, once it gets the lock, that the file has no name any more (filelock
    checks it) and is refused, instead of holding the lock of a file that no other run sees.
    """

    def __init__(self, output):
        self.output = Path(output)
        self.path = self.output.with_name(f".{self.output.name}.lock")
        self.lock = filelock.FileLock(self.path, timeout=0)

    def __enter__(self):
        """Take the lock; :class:`OutputBusy` if another run holds it, and a lock file that
        cannot be made (a read-only folder, a filesystem that takes no files: /proc) is one
        of :meth:`_not_made`."""
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as error:
            raise self._not_made(error, f"its folder {self.path.parent} cannot be made") \
                from None
        for _ in range(3):  # again if the holder let it go while it was looked at
            try:
                self.lock.acquire()
            except filelock.Timeout:  # said also where the file cannot be made: look
                failure = _creation_failure(self.path)
                if failure is None:
                    raise OutputBusy(f"{self.output}: another bearing-sweep run is writing this "
                                     "output; wait for it to finish or choose another -o") \
                        from None
            except OSError as error:
                failure = error
            else:
                break
            if failure is not False:
                raise self._not_made(failure, f"its lock file {self.path.name} cannot be "
                                              f"made in {self.path.parent}") from None
        else:
            raise OutputBusy(f"{self.output}: another bearing-sweep run keeps taking and "
                             "leaving this output's lock; wait for it to finish or choose "
                             "another -o")
        remove_stale_temporaries(self.output)
        return self

    def _not_made(self, error: OSError, what: str) -> OSError:
        """The error of a lock that cannot be made (``what``, for ``error``): a full disk's
        is an ``OSError`` (a failure of the machine), any other an :class:`UnsafeOutput` (an
        output where nothing can be written)."""
        reason = error.strerror or str(error) or type(error).__name__
        if error.errno in WRITING_ERRORS and error.errno != errno.EROFS:
            return OSError(error.errno, f"{what}: {reason}", str(self.output))
        return UnsafeOutput(f"{self.output}: cannot be written: {what} ({reason}); choose "
                            "another output")

    def __exit__(self, *exc):
        try:
            self.path.unlink(missing_ok=True)
        except OSError:  # Windows cannot remove an open file: filelock removes it on release
            pass
        self.lock.release()


def _creation_failure(path: Path) -> OSError | bool | None:
    """Why no file can be opened or made at ``path`` (an ``OSError``); None where one exists
    that opens (its lock is another process's), False where one could be made (the holder
    has just removed it). Nothing is made at ``path`` itself: a file made and removed there
    could be the one another process has just opened to lock."""
    try:
        os.close(os.open(path, os.O_RDWR | getattr(os, "O_NOFOLLOW", 0)))
        return None
    except FileNotFoundError:
        pass  # not there, or a folder that takes no files (/proc says so too)
    except OSError as error:
        return error
    try:  # whether the folder takes a new file, tried under a name of its own
        handle, probe = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".probe",
                                         dir=path.parent)
    except OSError as error:
        return error
    os.close(handle)
    os.unlink(probe)
    return False


def _read_json(path: Path):
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return None


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


#: A temporary file of :func:`written_atomically`: ``.<name>.<process id>.tmp``.
_TEMPORARY = re.compile(r"\..+\.\d+\.tmp")


def _remove(path: Path):
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    else:
        path.unlink(missing_ok=True)


def remove_stale_temporaries(output) -> list[str]:
    """Remove the temporary files of ``output`` (``.<name>.<process id>.tmp``, beside it, a
    file or a zarr store's folder) that a run killed while writing it left. Called by the holder of the output's lock
    (:class:`OutputLock`): every writer of such a file holds the lock as long as the file
    exists, and a process's lock dies with it, however it ends, so none of them is being
    written (on this host or another sharing the folder, whatever became of the process
    id). Returns their names."""
    output = Path(output)
    ours = re.compile(rf"\.{re.escape(output.name)}\.\d+\.tmp")
    removed = []
    try:
        entries = list(os.scandir(output.parent))
    except OSError:  # no folder yet: nothing left there
        return removed
    for entry in entries:
        if not ours.fullmatch(entry.name) or entry.is_symlink():
            continue
        if entry.is_dir():  # only a zarr store's is a folder (an analysis written as one)
            if not is_zarr(output):
                continue
            shutil.rmtree(entry.path, ignore_errors=True)
        else:
            Path(entry.path).unlink(missing_ok=True)
        removed.append(entry.name)
    return removed


def _unreadable(path: Path, points: int) -> str | None:
    """Why the part at ``path`` cannot be used, or None. Reads its index and status only."""
    try:
        with np.load(path) as data:
            if "status" not in data.files or "errors" not in data.files:
                return "incomplete"
            if data["status"].shape != (points,):
                return f"{data['status'].shape[0]} points instead of {points}"
    except (OSError, ValueError, EOFError, zipfile.BadZipFile) as error:
        return str(error).splitlines()[0] if str(error) else type(error).__name__
    return None


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


def counts_unreadable(path: Path, points: int) -> str | None:
    """Why a part file holding :func:`saved_counts` cannot be used for a chunk of ``points``
    points, or None. Reads its counts only."""
    try:
        with np.load(path) as data:
            tally = json.loads(str(data["tally"]))
    except (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile):
        return "incomplete"
    return None if sum(tally["status"]) == points else "not this chunk's counts"


def write_durably(path: Path, write):
    """Write ``path`` atomically: ``write(handle)`` fills a temporary file beside it."""
    with written_atomically(path) as temporary, open(temporary, "wb") as handle:
        write(handle)


@contextmanager
def written_atomically(path, before_rename=None):
    """A temporary path beside ``path`` for the block to write; when the block ends without
    an error it takes ``path``'s place (:func:`replace_durably`; ``before_rename()`` is
    called just before), otherwise it is removed. An existing file at ``path`` stays intact
    until then; the folder is made if need be. An ``OSError`` of writing that names no file
    (a full disk met by a library writing the temporary file: ``WRITING_ERRORS``) names
    ``path``."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        yield temporary
        replace_durably(temporary, path, before_rename)
    except OSError as error:
        if error.filename is not None or error.errno not in WRITING_ERRORS:
            raise
        raise OSError(error.errno, os.strerror(error.errno), str(path)) from None
    finally:
        if temporary.exists():
            temporary.unlink()


def replace_durably(temporary: Path, path: Path, before_rename=None):
    """Rename the finished ``temporary`` to ``path`` so that a power loss leaves the old file
    or the new one, never a renamed but empty one: the data reaches the disk before the
    rename, and the rename then too. ``before_rename()``, if given, is called once the data
    is on the disk, just before the rename."""
    with open(temporary, "rb+") as handle:
        os.fsync(handle.fileno())
    if before_rename is not None:
        before_rename()
    os.replace(temporary, path)
    fsync_path(path.parent)


def fsync_path(path):
    """fsync the file or folder at ``path`` (a folder: the names just made or changed in it
    reach the disk). Nothing happens where it cannot be opened: a file that is not there, a
    folder on some systems (Windows, where the rename stands)."""
    try:
        handle = os.open(path, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(handle)
    finally:
        os.close(handle)
