"""Where numba keeps the models' compiled code: a folder of the machine's, one for each
version of the models' source, so that compiling is paid once per machine, not in every
checkout, virtual environment or test run.

numba keeps a function's compiled code beside its source file by default and knows it by that
file alone: a fresh checkout compiles everything again, and a function compiled into a caller
in another module keeps its callee's old code until its own file changes. Here every model's
compiled code goes to ``<cache>/numba/<digest>``, the digest over every source file of the
models, numba's version and Python's: a change to any model compiles afresh, and the same
source, in any checkout, loads what was compiled once.

``<cache>`` is ``$BEARING_SWEEP_CACHE`` when set, else ``$XDG_CACHE_HOME/bearing-sweep`` or
``~/.cache/bearing-sweep``; an empty ``BEARING_SWEEP_CACHE``, a ``NUMBA_CACHE_DIR`` of the
user's or a folder that cannot be written leave numba's own place. The four versions written
to last are kept, and any written to within a day (another checkout may be running it).

The models take ``njit`` from here, which registers the locator first; it answers for the
models' own files only, so numba caches any other function as before.

No model is compiled with ``fastmath``: with its flags (fused multiply-adds, reassociated
sums) a function compiled into its caller in a process that compiles both rounds otherwise
than the caller's code loaded from this cache, so a point's numbers would depend on whether
its process compiled the models or loaded them (a test holds the two to the bit).
"""
from __future__ import annotations

import hashlib
import os
import shutil
import sys
import time
from pathlib import Path

import numba
from numba import njit  # noqa: F401  (the models' njit: the locator registered below)
from numba.core import caching

#: How many versions' folders are kept, and for how long at least [s].
KEPT_VERSIONS, KEPT_SECONDS = 4, 86400.0
_SOURCE = Path(__file__).parent


def cache_root() -> Path | None:
    """The folder the models' compiled code goes under, or None for numba's own place."""
    chosen = os.environ.get("BEARING_SWEEP_CACHE")
    if chosen is not None:
        return Path(chosen) if chosen else None
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "bearing-sweep"


def source_digest(folder: Path = _SOURCE) -> str:
    """The digest of the Python files in ``folder`` (names and contents), numba's version and
    Python's."""
    digest = hashlib.sha256(f"{numba.__version__} {sys.version}".encode())
    for path in sorted(folder.glob("*.py")):
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


class _ModelsLocator(caching.InTreeCacheLocator):
    """numba's locator for the models' files: the folder of this version of their source."""

    folder: Path | None = None

    def __init__(self, py_func, py_file):
        super().__init__(py_func, py_file)
        self._cache_path = str(self.folder)

    @classmethod
    def from_function(cls, py_func, py_file):
        if cls.folder is None or numba.config.CACHE_DIR or Path(py_file).parent != _SOURCE:
            return None
        return super().from_function(py_func, py_file)  # None where it cannot be written


def _prune(folder: Path) -> None:
    """Delete the other versions' folders beside ``folder`` but the newest few and those
    changed within :data:`KEPT_SECONDS`."""
    others = sorted((p for p in folder.parent.iterdir() if p.is_dir() and p != folder),
                    key=lambda p: p.stat().st_mtime, reverse=True)
    now = time.time()
    for old in others[KEPT_VERSIONS - 1:]:
        if now - old.stat().st_mtime > KEPT_SECONDS:
            shutil.rmtree(old, ignore_errors=True)


def register() -> None:
    """Send the models' compiled code to this version's folder (see the module's text)."""
    locators = getattr(getattr(caching, "CacheImpl", None), "_locator_classes", None)
    root = cache_root()
    if root is None or not isinstance(locators, list) or _ModelsLocator in locators:
        return  # numba's own place (another numba keeps its locators elsewhere)
    folder = root / "numba" / source_digest()
    try:
        new = not folder.exists()
        folder.mkdir(parents=True, exist_ok=True)
        if new:
            _prune(folder)
    except OSError:
        return  # numba's own place
    _ModelsLocator.folder = folder
    locators.insert(0, _ModelsLocator)


register()
