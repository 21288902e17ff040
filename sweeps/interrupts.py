"""Ctrl-C during a run: what it stops (:class:`Interrupts`), and an interruption that code the
engine calls turns into another exception or drops (:func:`interruptions_raised`).

Python raises a Ctrl-C as a ``KeyboardInterrupt`` wherever the main thread is. In compiled
code that is not always where it stays: numba's dispatcher, whose compiled function was
running when the handler raised, returns a ``SystemError`` ("returned a result with an
exception set") whose cause is the ``KeyboardInterrupt``, and a ctypes callback (llvmlite's,
while numba compiles) prints it as "Exception ignored" and drops it. The engine catches a
model's exceptions to go on with the other points; such an interruption must stop the run
instead of marking points ``model_error``.
"""
from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

#: What a run says of a Ctrl-C that came once its result was in place (:class:`Interrupts`).
RESULT_COMPLETE = "interrupt ignored: the result was already complete"
#: The exceptions that stop a program rather than report a failure of what it computes.
INTERRUPTIONS = (KeyboardInterrupt, SystemExit)


class Terminated(KeyboardInterrupt):
    """A SIGTERM (``kill``, a batch system's time limit), raised where the program is: it
    stops a run as a Ctrl-C does, the finished chunks kept (:func:`terminated_as_interrupt`)."""


def _terminate(signum, frame):
    Interrupts.raised += 1
    Interrupts.last = Terminated
    raise Terminated()


@contextmanager
def terminated_as_interrupt():
    """SIGTERM raises :class:`Terminated` in the main thread while the block runs (Python's
    own handling ends the process at once, with no cleanup: temporary files left, no word
    said); the previous handler is restored after. For the program, not the library: a
    caller's own handling of SIGTERM is left alone."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGTERM, _terminate)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


class Interrupts:
    """Ctrl-C (SIGINT) during a run, in the main thread. Until the result is about to take its
    name it stops the run as usual (``KeyboardInterrupt``: the finished chunks are kept);
    from :meth:`result_taking_its_name` on, the result is complete, and an interrupt is
    recorded (:attr:`ignored`) instead: the short cleanup that follows (the parts removed,
    the cluster closed, the summary) finishes, and the caller says that the result is
    complete rather than that it was interrupted. Elsewhere than in the main thread, or
    where SIGINT is ignored (a job in the background), nothing changes.

    Every interrupt that the handler raises is counted (:attr:`raised`, for the process), so
    that :func:`interruptions_raised` knows of one that the code it wraps dropped."""

    #: How many interrupts the handlers of this process have raised, and the last one's kind.
    raised = 0
    last = KeyboardInterrupt

    def __init__(self):
        self.result_in_place = False
        self.ignored = False
        self.previous = {}

    def __enter__(self):
        if threading.current_thread() is threading.main_thread():
            previous = signal.getsignal(signal.SIGINT)
            if callable(previous):
                self.previous[signal.SIGINT] = previous
            if signal.getsignal(signal.SIGTERM) is _terminate:  # the program's, not a caller's
                self.previous[signal.SIGTERM] = _terminate
            for signum in self.previous:
                signal.signal(signum, self._interrupted)
        return self

    def __exit__(self, *exc):
        for signum, previous in self.previous.items():
            signal.signal(signum, previous)
        self.previous = {}

    def _interrupted(self, signum, frame):
        if self.result_in_place:
            self.ignored = True
            return
        try:
            self.previous[signum](signum, frame)
        except BaseException as error:
            Interrupts.raised += 1
            Interrupts.last = type(error)
            raise

    def result_taking_its_name(self):
        """Called once the result is complete on the disk, just before its rename."""
        self.result_in_place = True


def interruption(error: BaseException) -> BaseException | None:
    """The interruption (one of ``INTERRUPTIONS``) that ``error`` was raised from or while
    handling, however deep in its causes and contexts (and in a group's exceptions), or
    None."""
    pending, seen = [error], set()
    while pending:
        one = pending.pop()
        if one is None or id(one) in seen:
            continue
        if isinstance(one, INTERRUPTIONS):
            return one
        seen.add(id(one))
        pending += [one.__cause__, one.__context__, *getattr(one, "exceptions", ())]
    return None


@contextmanager
def interruptions_raised():
    """Run the block; an interruption that came during it is raised as what it is: an
    exception raised from or while handling one (:func:`interruption`), and an interrupt
    that the handler of :class:`Interrupts` raised but that the block dropped. Wrap in it
    a call whose exceptions are caught so that the caller goes on. (The handler raises in the
    main thread only: a block in another thread has no interrupt of its own to drop.)"""
    main = threading.current_thread() is threading.main_thread()
    before = Interrupts.raised
    try:
        yield
    except Exception as error:
        found = interruption(error)
        if found is not None:
            raise found from None
        if main and Interrupts.raised != before:
            raise Interrupts.last() from error
        raise
    if main and Interrupts.raised != before:
        raise Interrupts.last()
