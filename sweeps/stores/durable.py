"""Durable writing of outputs: a lock per output path, files written aside and renamed into
place once they are on the disk, and the failures of writing them as one ``OSError`` naming
the output.

A lock on ``.<output>.lock`` keeps two runs from writing the same output (:class:`OutputLock`);
the run that holds it removes the temporary files that a killed run left
(:func:`remove_stale_temporaries`). Every file a run writes is written beside its place and
renamed there once flushed (:func:`written_atomically`): a power loss leaves the old file or
the new one, never half of one.
"""
from __future__ import annotations

import contextlib
import errno
import os
import re
import shutil
import tempfile
from contextlib import contextmanager
from pathlib import Path

import filelock
import numpy as np

from ..interrupts import interruptions_raised
from .paths import UnsafeOutput, is_zarr


class OutputBusy(OSError):
    """Another run holds the output; the message is for the user."""


#: The errors of a file that cannot be written on (a full disk or quota, a file larger than
#: the process may write, a disk failing or read-only).
WRITING_ERRORS = (errno.ENOSPC, errno.EFBIG, errno.EDQUOT, errno.EIO, errno.EROFS)


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


#: A temporary file of :func:`written_atomically`: ``.<name>.<process id>.tmp``.
TEMPORARY = re.compile(r"\..+\.\d+\.tmp")


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



@contextmanager
def writing(output):
    """The block's failures of HDF5 or netCDF writing the file of ``output`` (``OSError``,
    ``RuntimeError``: a full disk, a file larger than the process may write) as one
    ``OSError`` naming ``output``, in the words of its errno where they give one; a Ctrl-C
    that the libraries turned into another exception stays one. A value beyond the range of
    the type it is stored in (float32) is stored as infinite, without numpy's warning."""
    try:
        with interruptions_raised(), np.errstate(over="ignore"):
            yield
    except (OSError, RuntimeError) as error:
        code = error.errno if isinstance(getattr(error, "errno", None), int) else None
        if not code or code < 0:  # netCDF's own codes are negative; HDF5 says it in words
            found = re.search(r"errno = (\d+)", str(error))
            code = int(found[1]) if found else None
        text = os.strerror(code) if code else (str(error).splitlines() or ["not written"])[0]
        raise OSError(code or errno.EIO, text, str(output)) from None


@contextmanager
def closed_after(opened, output):
    """``opened`` (a netCDF4 or h5py file) for the block, closed after it. A failure of the
    block is not hidden by the file's failure to close after it (HDF5 cannot flush to a full
    disk either); a failure to close it otherwise is one of :func:`writing`."""
    try:
        yield opened
    except BaseException:
        with contextlib.suppress(Exception):
            opened.close()
        raise
    with writing(output):
        opened.close()

