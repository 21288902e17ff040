"""A model's warnings kept off the user's screen, in the thread that calls it only.

A point a model cannot compute is flagged by its status, not announced: an overflow at
``speed = "1e300 rpm"`` is a ``not_converged`` point, not numpy's "RuntimeWarning: overflow
encountered in square" on stderr in the middle of a run. Nothing of the user's changes: the
warnings filters are never touched, and another thread (a dask worker's other tasks, the
user's own threads in a notebook) warns as before.

- numpy's floating-point warnings are not raised in the block (``np.errstate``: numpy keeps
  that state per thread and per context).
- The warnings module's (a library's ``warnings.warn``, numba's while it compiles) have no
  such switch before Python 3.14: ``warnings.catch_warnings`` swaps the process's filters, and
  two threads in it at once restore each other's. Instead, while any thread is in the block,
  the module's ``_showwarnmsg``, through which every warning shown passes, is one that drops
  the warnings of the threads in the block and passes on the others'; the last thread out
  puts the original back. A filter that makes a warning an error (``-W error``) still raises
  it: the model's points are then ``model_error``, with the warning as the reason.
"""
from __future__ import annotations

import threading
import warnings
from contextlib import contextmanager

import numpy as np

_lock = threading.Lock()
_threads = threading.local()  # .depth: how deep this thread is in silenced blocks
_active = 0  # blocks open in the process
_original = None  # warnings._showwarnmsg before the first block


def _shown_unless_silenced(message):
    if getattr(_threads, "depth", 0):
        return
    _original(message)


@contextmanager
def silenced():
    """Run the block without showing its warnings (see the module's text)."""
    global _active, _original
    with _lock:
        if _active == 0 and warnings._showwarnmsg is not _shown_unless_silenced:
            _original = warnings._showwarnmsg
            warnings._showwarnmsg = _shown_unless_silenced
        _active += 1
    _threads.depth = getattr(_threads, "depth", 0) + 1
    try:
        with np.errstate(all="ignore"):
            yield
    finally:
        _threads.depth -= 1
        with _lock:
            _active -= 1
            if _active == 0 and warnings._showwarnmsg is _shown_unless_silenced:
                warnings._showwarnmsg = _original
