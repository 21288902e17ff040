"""Compute a sweep: its grid in chunks, computed where the :class:`executor.Executor` says,
each kept by the result's store (:mod:`stores`) as it arrives (:func:`run_sweep`)."""
from __future__ import annotations

import contextlib
import functools
import sys
import time
from dataclasses import dataclass, field

from . import stores
from .evaluate import choose_chunk_size, evaluate_into, installed_versions, versions
from .executor import Executor
from .grid import Grid
# RESULT_COMPLETE and Interrupts: the command and the API take them from here.
from .interrupts import RESULT_COMPLETE, Interrupts, interruptions_raised  # noqa: F401
from .spec import Sweep


class WorkerMismatch(RuntimeError):
    """A worker runs another version of the package or the model; the message is for the user."""


@dataclass
class Summary:
    """What a finished sweep reports."""

    model: str
    points: int
    status_counts: dict
    seconds: float
    output: str
    scheduler: str
    errors: list = field(default_factory=list)
    noted: dict = field(default_factory=dict)  # what the model counts, e.g. several equilibria
    dataset: object = None  # the result (an xarray.Dataset) of a sweep run without a file

    def text(self) -> str:
        counts = ", ".join(f"{n} {name}" for name, n in self.status_counts.items()
                           if n and name != "out_of_validity")
        if self.status_counts.get("out_of_validity"):  # of those, whatever their outcome
            counts += f"; {self.status_counts['out_of_validity']} out_of_validity"
        counts += "".join(f"; {n} {text}" for text, n in self.noted.items() if n)
        line = (f"{self.model}: {self.points} points ({counts or 'none'}) in {self.seconds:.1f} s "
                f"on {self.scheduler} -> {self.output}")
        if self.errors:
            line += f"\n  model errors: {self.errors[0]}" + (
                f" (and {len(self.errors) - 1} more)" if len(self.errors) > 1 else "")
        return line


class Progress:
    """A progress bar on stderr for work that takes longer than a moment."""

    def __init__(self, total: int, label: str, enabled: bool = True, stream=None):
        self.total, self.label, self.enabled = total, label, enabled
        self.stream = stream or sys.stderr
        self.start = self.last = time.monotonic()
        self.done = 0
        self.shown = False
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        # A Jupyter kernel's stream is no terminal, but its output area redraws a line on
        # a carriage return, as a terminal does.
        self.notebook = type(self.stream).__module__.split(".")[0] == "ipykernel"
        self.in_place = self.tty or self.notebook

    def advance(self, count: int):
        self.done += count
        now = time.monotonic()
        if not self.enabled or now - self.start < 0.5:
            return
        interval = 0.1 if self.tty else 0.5 if self.notebook else 10.0
        if self.shown and now - self.last < interval and self.done < self.total:
            return
        self.last, self.shown = now, True
        fraction = self.done / max(self.total, 1)
        bar = "#" * int(30 * fraction)
        line = (f"{self.label} [{bar:<30}] {self.done}/{self.total} points "
                f"{now - self.start:.0f} s")
        self.stream.write(("\r" + line) if self.in_place else line + "\n")
        self.stream.flush()

    def close(self):
        if self.shown and self.in_place:
            self.stream.write("\n")
            self.stream.flush()


def _check_versions(found: dict, expected: dict, executor: Executor, parts):
    """Refuse a chunk computed by another version of the package or the model: the file
    would mix two sets of numbers under one provenance."""
    if found == expected:
        return
    where = f"dask scheduler {executor.scheduler}" if executor.scheduler else "the cluster"
    count = 0 if parts.folder is None else parts.count()
    kept = "" if not count else (f" ({count} chunks computed so far are kept in {parts.folder})"
                                 if count > 1 else f" (the chunk computed so far is kept in "
                                                   f"{parts.folder})")
    raise WorkerMismatch(
        f"a worker of {where} runs bearing-sweep {found['package']} (model version "
        f"{found['model']}) where this run has bearing-sweep {expected['package']} (model version "
        f"{expected['model']}): install the same on every worker{kept}")


def run_sweep(sweep: Sweep, output=None, executor: Executor | None = None,
              chunk_size: int | None = None, progress: bool = True, fresh: bool = False,
              log=None, interrupts: Interrupts | None = None) -> Summary:
    """Compute ``sweep`` and write its result atomically at ``output`` (a netCDF file, or a
    zarr store for a path ending in ``.zarr``), or, when ``output`` is None, return its
    dataset in :attr:`Summary.dataset` without a file.

    The result goes to its store (:mod:`stores`), which keeps the finished chunks until the
    result is in place, so a run after an interruption computes only what is missing
    (``fresh`` discards them), and writes each chunk as it arrives, while the others compute:
    memory is bounded by the chunk size, and the result is complete soon after the last
    chunk. A cluster, when the sweep is worth one, starts while the grid is made and the
    resume state is looked at. Nothing of an earlier run's changes until every refusal that
    may come before computing has passed: a result the disk cannot hold
    (:class:`stores.footprint.InsufficientSpace`), a cluster that cannot start, workers of another
    version (a chunk computed by one later is refused too). ``log`` receives messages for the
    user (resuming, discarding, and with ``progress`` the estimate of a long or large run:
    :mod:`stores.footprint`). ``interrupts``: the caller's :class:`Interrupts`, entered by the caller
    for as long as it has cleanup to do after the run (by default the run's own).
    """
    store = stores.for_output(output, sweep)
    own = executor is None
    executor = executor or Executor()
    log = log or (lambda message: None)
    guard = Interrupts() if interrupts is None else contextlib.nullcontext()
    interrupts = guard if interrupts is None else interrupts
    interrupts.result_in_place = False
    began = time.monotonic()
    try:
        with guard, store.locked():
            grid = Grid.from_sweep(sweep)
            model = grid.model
            expected = versions(model)
            parallel = executor.parallel(grid)
            if parallel:
                executor.plan(grid, chunk_size, log)
                executor.start()
            size = chunk_size or choose_chunk_size(
                grid, executor.worker_count() if parallel else 0)
            key = {"definition_sha256": sweep.sha256, "values_sha256": grid.values_sha256,
                   "model_version": model.version, "points": grid.size,
                   "package_version": expected["package"]}
            # Looked at only: nothing of an earlier run's changes before every refusal that
            # may come before computing has passed.
            size = store.open(grid, key, size, fresh)
            chunks = grid.chunks(size)
            done = store.finished()
            todo = [chunk for chunk in chunks if chunk not in done]
            workers = executor.worker_count() if parallel else 1
            footprint = store.footprint(sum(stop - start for start, stop in todo), workers)
            if parallel:  # the cluster started, its workers of this version
                _check_workers(executor, model, expected, store.parts)
                dashboard = executor.dashboard()
                if progress and dashboard:
                    log(f"dask dashboard: {dashboard}")
            store.begin(log)
            if footprint is not None and progress and footprint.announced():
                log(footprint.text(model.name, f"{workers} worker{'s' * (workers != 1)}"
                                   if parallel else "one core, in this process"))
            scheduler = executor.describe(parallel)
            with store.recording(size, scheduler, interrupts.result_taking_its_name) as writer:
                # A writer: each chunk written or encoded by the process that computes it.
                task = None if writer is None else functools.partial(evaluate_into, writer,
                                                                     expected)
                bar = Progress(grid.size, model.name, progress)
                bar.advance(sum(stop - start for start, stop in done))
                kept = len(done)
                try:
                    for start, stop, result in executor.map(grid, todo, parallel, task):
                        _check_versions(result.pop("versions"), expected, executor,
                                        store.parts)
                        store.record(start, stop, result)
                        kept += 1
                        stored = store.stored_bytes(result)
                        bar.advance(stop - start)
                        if footprint is not None and stored is not None:
                            footprint.check(stop - start, stored, kept)
                finally:
                    bar.close()
                counts, errors, noted = store.counts(chunks)
            store.remove()
        return Summary(model.name, grid.size, counts, time.monotonic() - began, store.where,
                       scheduler, errors, noted, store.dataset)
    finally:
        if own:
            executor.close()


def _check_workers(executor: Executor, model, expected: dict, parts):
    """Wait for the cluster (:class:`ClusterFailure` if it cannot start) and refuse workers
    of another version (:func:`_check_versions`), before a chunk is computed; a worker that
    joins later is checked by its chunks."""
    client = executor.connect()
    try:
        with interruptions_raised():
            found = client.run(installed_versions, model.name)
    except Exception:  # a worker that cannot run it: its chunks will say what it does
        return
    for one in found.values():
        if one is not None:
            _check_versions(one, expected, executor, parts)
