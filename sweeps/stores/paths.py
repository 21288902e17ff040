"""Output paths: what a run (or an analysis, a figure, a schema) may write, refused before any
computing otherwise (:class:`UnsafeOutput`, a :class:`SpecError`: exit status 2).

Accepted: a path that does not exist yet in a folder that exists or can be made, or an earlier
result of this program that may be replaced (a netCDF file; a zarr store never is). Refused:
anything else, a name that does not say what it is, and a path inside a zarr store or a parts
folder (:func:`check_outside_results`).
"""
from __future__ import annotations

import json
import os
import stat
from pathlib import Path

from ..spec import SpecError


class UnsafeOutput(SpecError):
    """An output path that must not be written; the message is for the user."""


#: The first bytes of a netCDF file: classic and 64-bit offset formats, and HDF5 (netCDF-4).
NETCDF_SIGNATURES = (b"CDF\x01", b"CDF\x02", b"CDF\x05", b"\x89HDF\r\n\x1a\n")
#: The suffix of an output written as a zarr store (a folder) rather than a netCDF file.
ZARR_SUFFIX = ".zarr"
#: The suffix of the folder beside an output that keeps its run's finished chunks.
PARTS_SUFFIX = ".parts"
#: Names that are only a suffix: a hidden file, not a result with a name.
BARE_SUFFIXES = (ZARR_SUFFIX, ".nc")
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
        raise SpecError(f"{name}={argument_text(value)}: expected {expected or 'a'} path (a str "
                        "or os.PathLike), not " + ("an empty one" if isinstance(value, str)
                                                   else type(value).__name__))
    return value


def argument_text(value) -> str:
    """An argument as a message shows it: its repr, or its type where that is long."""
    shown = repr(value)
    return shown if len(shown) <= 60 and "\n" not in shown else f"<{type(value).__name__}>"


def check_output(output, definition=None, result: str = "run"):
    """Refuse, before any computing, an output path that a sweep must not replace.

    Accepted: a path that does not exist yet in a folder that exists or can be made, or a
    regular netCDF file that this program wrote as the same kind of ``result``, ``"run"`` or
    ``"analysis"`` (its global attributes say so: only the header is read; an analysis never
    replaces the result it may have been made from, nor a run an analysis). Anything else
    (the definition itself, another folder, a device, a pipe, a symbolic link, another
    program's file, an earlier zarr store) raises :class:`UnsafeOutput`; nothing is opened but
    a regular file's first bytes and header.
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
    reason = _not_ours(output, result)
    if reason:
        what = "a netCDF file" if result == "run" else "an analysis"
        raise UnsafeOutput(f"{output}: exists and is not {what} written by bearing-sweep "
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


def _not_ours(path: Path, kind: str = "run") -> str | None:
    """Why the regular file at ``path`` is not a result of this program of that ``kind``,
    or None if it is."""
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
    if not _names_us(attributes):
        return "its attributes do not name bearing-sweep"
    found = "run" if "definition" in attributes else "analysis"  # a run's holds its definition
    if found != kind:
        return (f"it is the result of a {found}, not an {kind}" if kind == "analysis" else
                f"it is an {found}, not the result of a {kind}")
    return None


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


def _read_json(path: Path):
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return None
