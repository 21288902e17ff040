"""Compute a sweep in chunks: in this process, on a LocalCluster or on a dask cluster."""
from __future__ import annotations

import contextlib
import functools
import itertools
import logging
import math
import os
import signal
import socket
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

import numpy as np

from .models.registry import MODEL_ERROR, known_status, values_kept
from . import hdf5_chunks, quiet, store, units
from .footprint import Footprint, InsufficientSpace, duration
from .grid import Grid, block_shape
# RESULT_COMPLETE and Interrupts: the command and the API take them from here.
from .interrupts import RESULT_COMPLETE, Interrupts, interruptions_raised  # noqa: F401
from .labels import stored_unit
from .output_paths import check_output, check_parts_folder, is_zarr
from .parts import HeldChunks, OutputLock, Parts
from .spec import SpecError, Sweep

#: Below this estimated single-core time [s] a sweep runs in-process: starting a cluster
#: would take longer than the work. benchmarks/cluster_break_even.py measured a fresh
#: LocalCluster of two paying from 4.2 s of in-process work on a quiet machine (and from
#: 3.0 s and 6.3 s with others' load of 2-3 on its 2 cores).
IN_PROCESS_SECONDS = 4.0
#: Largest chunk, in estimated seconds of work on one core (a task costs a few milliseconds of
#: scheduling; within a chunk the model runs in blocks of its ``points_per_call``).
CHUNK_SECONDS = 1.0
#: Chunks submitted per worker at a time; the next is submitted as one finishes.
CHUNKS_IN_FLIGHT = 4
#: How long to wait for a scheduler given by ``--scheduler`` to answer [s].
CONNECT_SECONDS = 10.0
#: The size of the local cluster when none is asked for.
DEFAULT_WORKERS = 2


class WorkerMismatch(RuntimeError):
    """A worker runs another version of the package or the model; the message is for the user."""


class ClusterFailure(RuntimeError):
    """The cluster could not start, or lost a worker for good; the message is for the user."""


def available_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system says, as a batch
    scheduler sets it, otherwise the machine's)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # macOS and Windows have no affinity call
        return os.cpu_count() or 1


def versions(model) -> dict:
    """What a chunk's numbers depend on besides the definition: the package's and the model's
    versions in the process that computes it."""
    return {"package": store.package_version(), "model": model.version}


def evaluate_chunk(grid: Grid, start: int, stop: int) -> dict:
    """Run the model on points ``start..stop-1``.

    Returns ``{"outputs": {name: array}, "status": array, "errors": [str], "versions": dict}``
    (the :func:`versions` of the process that computed it); outputs are in their declared
    units, with the grid's largest size on each own dimension (NaN beyond a point's own size).
    Points are grouped by their structural inputs (counts, choices) and the model is called
    once per group. An exception in the model marks that group's points with
    ``model_error`` and records its message; it does not stop the sweep, but a Ctrl-C does,
    whatever exception the model turned it into (:func:`interrupts.interruptions_raised`).
    The model's warnings are not shown (:func:`quiet.silenced`): its statuses say it.
    """
    model = grid.model
    count = stop - start
    varying, axis_index = grid.inputs(start, stop)
    outputs = {o.name: np.full((count,) + tuple(grid.dim_sizes[d] for d in o.dims), np.nan)
               for o in model.outputs}
    status = np.full(count, MODEL_ERROR, dtype=np.int8)
    errors = []
    structural = [i.name for i in model.inputs if i.structural and i.name in varying]
    if structural:
        axes = sorted({grid.axis_values[name][0] for name in structural})
        codes = np.ravel_multi_index([axis_index[grid.dims[a]] for a in axes],
                                     [grid.shape[a] for a in axes])
        groups = [np.flatnonzero(codes == code) for code in np.unique(codes)]
    else:
        groups = [np.arange(count)]
    block = model.points_per_call
    groups = [g[i:i + block] for g in groups for i in range(0, g.size, block)]
    for members in groups:
        arguments = dict(grid.fixed)
        for name, values in varying.items():
            if name in structural:
                value = values[members[0]]
                arguments[name] = value.item() if isinstance(value, np.generic) else value
            else:
                arguments[name] = values[members]
        try:
            # A Ctrl-C that compiled code turns into another exception stops the run; the
            # model's warnings stay off the screen (its points say what went wrong).
            with interruptions_raised(), quiet.silenced():
                result = model.function(**arguments)
        except Exception as error:  # one bad group must not cost the whole sweep
            errors.append(f"{type(error).__name__}: {error}".splitlines()[0])
            continue
        with np.errstate(all="ignore"):  # a huge value in its unit is inf, as it says
            for spec in model.outputs:
                value = _per_point(result[spec.name], members.size, len(spec.dims))
                region = (members,) + tuple(slice(0, n) for n in value.shape[1:])
                outputs[spec.name][region] = _from_si(value, spec)
        returned = _per_point(result["status"], members.size, 0)
        unknown = ~known_status(returned)
        if unknown.any():  # a code no reader could decode: the model is wrong there
            errors.append(f"the model returned status {returned[unknown][0]}, not a code of "
                          "bearing_sweep.models.registry")
        status[members] = np.where(unknown, MODEL_ERROR, returned)
    failed = ~values_kept(status)
    for values in outputs.values():
        values[failed] = np.nan  # whatever a model left there, a failed point is NaN
    return {"outputs": outputs, "status": status, "errors": errors, "versions": versions(model)}


def evaluate_into(writer, expected: dict, grid: Grid, start: int, stop: int) -> dict:
    """Run the model on points ``start..stop-1`` and write or encode them with ``writer`` (a
    :class:`zarr_store.StoreWriter`, or an :class:`hdf5_chunks.ChunkEncoder`) in the process
    that computed them.

    Returns ``{"tally": store.chunk_tally, "versions": dict}`` and what the writer returns:
    one value per cell of the outputs stored on fewer dimensions (``firsts``), for a netCDF
    file the encoded HDF5 chunks (``chunks``); the values themselves never travel. Values
    computed by other :func:`versions` than ``expected`` are neither written nor encoded
    (the driver refuses the chunk).
    """
    result = evaluate_chunk(grid, start, stop)
    written = writer.write(grid, start, stop, result) if result["versions"] == expected else {}
    return {"tally": store.chunk_tally(grid.model, result), "versions": result["versions"],
            **written}


def _from_si(value: np.ndarray, spec) -> np.ndarray:
    """An output's SI values in its declared unit, or in each entry's own unit."""
    if not spec.entry_units:
        return units.from_si(value, stored_unit(spec.unit))
    factors = np.vectorize(lambda unit: float(units.from_si(1.0, unit)))(
        np.array(spec.entry_units))
    return value * factors


def _per_point(value, count: int, own_dims: int) -> np.ndarray:
    """``value`` with one leading entry per point (a model given no per-point array returns
    unbatched results)."""
    value = np.asarray(value)
    own = value.shape[value.ndim - own_dims:]
    return np.broadcast_to(value.reshape((-1,) + own), (count,) + own)


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


def check_scheduler_address(address: str, named: str | None = None) -> str:
    """Refuse at once (:class:`SpecError`) an address that names no dask scheduler; the
    message names it as ``named`` (default: as the command line's option)."""
    from distributed.comm import parse_address, parse_host_port
    from distributed.comm.registry import backends

    named = named or f"--scheduler {address}"
    expected = f"{named}: not a scheduler address (expected tcp://HOST:PORT)"
    try:
        scheme, location = parse_address(address, strict=False)
        if scheme not in backends:
            raise ValueError(f"unknown protocol {scheme!r}")
        if scheme != "inproc":
            host, port = parse_host_port(location)
            if not host or not 0 < port < 65536:
                raise ValueError("no host or no valid port")
    except ValueError:
        raise SpecError(expected) from None
    return address


class SchedulerUnreachable(OSError):
    """No scheduler answers at the address given; the message is for the user."""


def _connect_to_scheduler(address: str):
    """A client of the scheduler at ``address``, or :class:`SchedulerUnreachable` within
    ``CONNECT_SECONDS`` (dask itself would retry a refused connection until its timeout)."""
    from distributed import Client
    from distributed.comm import parse_address, parse_host_port

    scheme, location = parse_address(check_scheduler_address(address), strict=False)
    if scheme in ("tcp", "tls", "ws", "wss"):
        try:
            socket.create_connection(parse_host_port(location), timeout=CONNECT_SECONDS).close()
        except OSError as error:
            reason = error.strerror or (f"no answer within {CONNECT_SECONDS:g} s"
                                        if isinstance(error, TimeoutError) else str(error))
            raise SchedulerUnreachable(f"--scheduler {address}: cannot reach it: {reason}") \
                from None
    try:
        return Client(address, timeout=f"{CONNECT_SECONDS}s", set_as_default=False)
    except OSError as error:  # something answers, but not a dask scheduler in time
        raise SchedulerUnreachable(f"--scheduler {address}: no dask scheduler answered: "
                                   f"{str(error).splitlines()[0]}") from None


def dask_setup(worker):
    """Run by dask in each worker process of the local cluster (a preload): Ctrl-C reaches the
    whole process group, and is for the driver to handle, which closes the cluster. Without
    this every worker would print a traceback."""
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)


class Executor:
    """Where chunks are computed. A cluster is started only when a sweep is worth it.

    ``client`` is an existing ``dask.distributed.Client`` to compute on (left open: it is the
    caller's); ``scheduler`` connects to a running dask.distributed scheduler; ``workers=0``
    computes in-process; ``workers=N`` uses a LocalCluster of N single-threaded processes; by
    default a sweep worth it gets a LocalCluster of two, and a small one runs in-process (a
    local cluster never has more workers than the cores nor than the sweep's chunks:
    :meth:`plan`). A cluster is started on first need and kept for later sweeps; one that
    cannot start is a :class:`ClusterFailure`.
    """

    def __init__(self, workers: int | None = None, scheduler: str | None = None,
                 client=None):
        self.workers, self.scheduler = workers, scheduler
        self.client = client
        self.given = client is not None  # the caller's: used, never closed
        self.cluster = None
        self.starting = None  # a local cluster starting in the background (a Future)
        self.size = None  # the local cluster's worker processes, once planned (:meth:`plan`)

    def __enter__(self):
        return self

    def __exit__(self, kind, error, trace):
        if kind is KeyboardInterrupt:
            # Closing a cluster in the middle of its work makes dask log heartbeats that fail,
            # with their tracebacks: the interruption is one line, said by the command.
            logging.getLogger("distributed").setLevel(logging.CRITICAL)
        self.close()

    def close(self):
        if self.given:
            return
        if self.starting is not None:  # let it finish starting, to close it
            with contextlib.suppress(Exception):
                self.connect()
        if self.client is not None:
            self.client.close()
        if self.cluster is not None:
            self.cluster.close()
        self.client = self.cluster = None

    def parallel(self, grid: Grid) -> bool:
        if self.scheduler or self.given:
            return True
        if self.workers is not None:  # asked for: 0 in-process, N a local cluster of N
            return self.workers > 0
        cost = grid.size * grid.model.seconds_per_point
        return cost > IN_PROCESS_SECONDS

    def worker_count(self) -> int:
        if self.scheduler or self.given:
            return max(1, len(self.connect().scheduler_info()["workers"]))
        return self.size or min(self.workers or DEFAULT_WORKERS, available_cores())

    def plan(self, grid: Grid, chunk_size: int | None, log):
        """Size the local cluster for ``grid``: the workers asked for (default two), but no
        more than the cores this process may use (each worker is one single-threaded process:
        more would only share them; a line to ``log`` says so) nor than the sweep has chunks
        of ``chunk_size`` points, by default of :func:`largest_chunk` (about a second of
        work: a worker costs more than that to start). A cluster already started for an
        earlier sweep grows if this one needs more. An external cluster (``scheduler``,
        ``client``) is the caller's to size."""
        if self.scheduler or self.given:
            return
        asked = self.workers or DEFAULT_WORKERS
        cores = available_cores()
        block = block_shape(grid.shape, chunk_size or largest_chunk(grid))
        chunks = math.prod(math.ceil(n / b) for n, b in zip(grid.shape, block))  # as Grid.chunks
        count = max(1, min(asked, cores, chunks))
        if self.workers and self.workers > cores:
            work = grid.size * grid.model.seconds_per_point
            fewer = "" if chunks >= cores else (
                f" and {chunks} chunk{'s' * (chunks != 1)} of {chunk_size} "
                f"point{'s' * (chunk_size != 1)}"
                if chunk_size else f" and {duration(work)} of work (a worker for each second "
                                   "of it at most)")
            log(f"{self.workers} workers asked for, {cores} core{'s' * (cores != 1)} "
                f"available to this process{fewer}: a local cluster of {count} "
                f"worker{'s' * (count != 1)} (--scheduler runs on a larger cluster)")
        if self.cluster is not None and count > (self.size or 0):
            self.cluster.scale(count)
        self.size = max(count, self.size or 0)

    def start(self):
        """Begin connecting: a local cluster starts in a background thread (its processes
        start and import while the caller prepares the sweep); :meth:`connect` waits for it."""
        if self.client is not None or self.starting is not None:
            return
        if self.scheduler:
            self.connect()
            return
        # Imported here, not in the thread: two threads importing the same modules at once
        # can meet a module half initialised.
        import distributed  # noqa: F401

        pool = ThreadPoolExecutor(max_workers=1)
        self.starting = pool.submit(self._start_local)
        pool.shutdown(wait=False)  # returns at once: the start goes on, its thread ends with it

    def connect(self):
        if self.starting is not None:
            starting, self.starting = self.starting, None
            starting.result()  # raises what the start raised
        if self.client is None:
            # Not the default client: xarray would then guard every netCDF write with a lock
            # held through the scheduler, a round trip per variable.
            if self.scheduler:
                self.client = _connect_to_scheduler(self.scheduler)
            else:
                self._start_local()
        return self.client

    def _start_local(self):
        """Start a LocalCluster of ``workers`` (default 2) single-threaded processes and a
        client of it."""
        import dask
        from distributed import Client, LocalCluster

        # dask sets MALLOC_TRIM_THRESHOLD_=65536 in its workers, which makes glibc map
        # and unmap every large numpy temporary of a model afresh: twice the time. Its
        # profiler serves only the dashboard; slower housekeeping cuts an idle two-worker
        # cluster's CPU use from about 10 % to 4 % of a core, which the workers need
        # when they occupy every core.
        with dask.config.set({"distributed.nanny.pre-spawn-environ."
                              "MALLOC_TRIM_THRESHOLD_": None,
                              "distributed.worker.profile.enabled": False,
                              "distributed.admin.tick.interval": "500ms",
                              "distributed.admin.system-monitor.interval": "2s",
                              "distributed.worker.memory.monitor-interval": "1s"}):
            # The preload runs this module's dask_setup in every worker process,
            # restarted ones too. The cluster's own logs are not for the user: what
            # goes wrong reaches the summary or the command's one line of error.
            count = self.worker_count()
            try:
                with interruptions_raised():  # a Ctrl-C, not a failure to start
                    self.cluster = LocalCluster(
                        n_workers=count, threads_per_worker=1, processes=True,
                        dashboard_address=":0", silence_logs=logging.CRITICAL,
                        preload=[__name__])
                    self.client = Client(self.cluster, set_as_default=False)
            except Exception as error:  # dask's own traceback is not for the user
                reason = (str(error).splitlines() or [type(error).__name__])[0]
                raise ClusterFailure(
                    f"the local dask cluster of {count} worker{'s' * (count != 1)} could not "
                    f"start ({reason}); --workers 0 (workers=0 in Python) computes in this "
                    "process") from None

    def describe(self, parallel: bool) -> str:
        if not parallel:
            return "in-process"
        if self.scheduler:
            return f"dask scheduler {self.scheduler} ({self.worker_count()} workers)"
        if self.given:
            return (f"dask client of {self.client.scheduler.address} "
                    f"({self.worker_count()} workers)")
        return f"dask LocalCluster ({self.worker_count()} single-threaded worker processes)"

    def map(self, grid: Grid, chunks, parallel: bool, task=None):
        """Yield ``(start, stop, result)`` as chunks finish; ``result`` is
        ``task(grid, start, stop)`` (default :func:`evaluate_chunk`)."""
        task = task or evaluate_chunk
        if not parallel:
            for start, stop in chunks:
                yield start, stop, task(grid, start, stop)
            return
        from distributed import KilledWorker, as_completed

        client = self.connect()
        # A few chunks per worker in flight, the next submitted as one finishes: the driver
        # and the scheduler hold a bounded number of tasks (each carries the grid, whose long
        # axes can weigh megabytes) however many chunks a sweep has, and a worker never waits.
        in_flight = CHUNKS_IN_FLIGHT * self.worker_count()
        waiting = iter(chunks)

        def submit(start: int, stop: int):
            # The grid travels with every task: scattered data would be lost with a worker
            # that dies, and with it every chunk still to compute.
            future = client.submit(task, grid, start, stop, pure=False)
            futures[future] = (start, stop)
            return future

        futures = {}
        first = [submit(*chunk) for chunk in itertools.islice(waiting, in_flight)]
        try:
            with client.as_current():  # as_completed looks for the current client
                finished = as_completed(first)
                for future in finished:
                    start, stop = futures.pop(future)
                    try:
                        result = future.result()
                    except KilledWorker:  # dask's message is a paragraph
                        raise ClusterFailure(
                            f"the workers that computed points {start}..{stop - 1} died doing "
                            "it, as often as dask retries; the finished chunks are kept: run "
                            "the same command again, or with --workers 0 to compute in this "
                            "process") from None
                    # Let the worker drop it: held futures keep every result in the cluster.
                    future.release()
                    following = next(waiting, None)
                    if following is not None:
                        finished.add(submit(*following))
                    yield start, stop, result
        finally:
            client.cancel(list(futures))


class Progress:
    """A progress bar on stderr for work that takes longer than a moment."""

    def __init__(self, total: int, label: str, enabled: bool = True, stream=None):
        self.total, self.label, self.enabled = total, label, enabled
        self.stream = stream or sys.stderr
        self.start = self.last = time.monotonic()
        self.done = 0
        self.shown = False
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()

    def advance(self, count: int):
        self.done += count
        now = time.monotonic()
        if not self.enabled or now - self.start < 0.5:
            return
        if self.shown and now - self.last < (0.1 if self.tty else 10.0) and self.done < self.total:
            return
        self.last, self.shown = now, True
        fraction = self.done / max(self.total, 1)
        bar = "#" * int(30 * fraction)
        line = (f"{self.label} [{bar:<30}] {self.done}/{self.total} points "
                f"{now - self.start:.0f} s")
        self.stream.write(("\r" + line) if self.tty else line + "\n")
        self.stream.flush()

    def close(self):
        if self.shown and self.tty:
            self.stream.write("\n")
            self.stream.flush()


def largest_chunk(grid: Grid) -> int:
    """The most points a chunk holds by default: ``CHUNK_SECONDS`` of work on one core, by
    the model's declared cost."""
    return max(1, int(CHUNK_SECONDS / grid.model.seconds_per_point))


def choose_chunk_size(grid: Grid, workers: int) -> int:
    """Chunks of at most :func:`largest_chunk` (the progress bar moves, an interruption loses
    little), on a cluster eight per worker to balance uneven points; in-process
    (``workers`` 0) as few as that allows: each chunk costs a model call and a write."""
    largest = largest_chunk(grid)
    return max(1, min(largest, math.ceil(grid.size / (8 * workers)) if workers else grid.size))


def _check_versions(found: dict, expected: dict, executor: Executor, parts: Parts):
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


def _stored_bytes(result: dict) -> int | None:
    """The bytes a computed chunk takes in the result (encoded for a netCDF file, or written
    into a zarr store); None for values not yet encoded."""
    if "chunks" in result:
        return sum(len(data) for _, data in result["chunks"].values())
    return result.get("stored_bytes")


def run_sweep(sweep: Sweep, output=None, executor: Executor | None = None,
              chunk_size: int | None = None, progress: bool = True, fresh: bool = False,
              log=None, interrupts: Interrupts | None = None) -> Summary:
    """Compute ``sweep`` and write its netCDF file atomically at ``output``, or, when
    ``output`` is None, return its dataset in :attr:`Summary.dataset` without a file.

    Finished chunks are kept as part files beside ``output`` until the file is written, so a
    run after an interruption computes only what is missing (``fresh`` discards them). Each
    chunk is written into the file as it arrives, while the others compute: memory is bounded
    by the chunk size, and the file is complete soon after the last chunk. An output ending
    in ``.zarr`` is a zarr store that each chunk is written into by the worker that computes
    it (:mod:`zarr_store`). A cluster, when the sweep is worth one, starts while the grid is
    made and the parts are looked at. Nothing in the parts folder changes until every refusal
    that may come before computing has passed (:meth:`parts.Parts.begin`): a result the disk
    cannot hold, a cluster that cannot start, workers of another version (a chunk computed
    by one later is refused too). ``log`` receives messages for the user
    (resuming, discarding, and with ``progress`` the estimate of a long or large run:
    :mod:`footprint`). A result the disk cannot hold raises
    :class:`footprint.InsufficientSpace`. ``interrupts``: the caller's :class:`Interrupts`,
    entered by the caller for as long as it has cleanup to do after the run (by default the
    run's own).
    """
    if output is not None:
        check_output(output, sweep.path)
        check_parts_folder(output)
    own = executor is None
    executor = executor or Executor()
    log = log or (lambda message: None)
    guard = Interrupts() if interrupts is None else contextlib.nullcontext()
    interrupts = guard if interrupts is None else interrupts
    interrupts.result_in_place = False
    began = time.monotonic()
    try:
        with guard, OutputLock(output) if output is not None else contextlib.nullcontext():
            grid = Grid.from_sweep(sweep)
            model = grid.model
            expected = versions(model)
            parallel = executor.parallel(grid)
            if parallel:
                executor.plan(grid, chunk_size, log)
                executor.start()
            size = chunk_size or choose_chunk_size(
                grid, executor.worker_count() if parallel else 0)
            zarr = is_zarr(output)
            if zarr:
                from . import zarr_store  # zarr: only for a store
            # A netCDF file's chunks encoded by the workers, the driver writing their bytes.
            direct = output is not None and not zarr and hdf5_chunks.writes_directly(
                sweep.storage, grid)
            key = {"definition_sha256": sweep.sha256, "values_sha256": grid.values_sha256,
                   "model_version": model.version, "points": grid.size,
                   "package_version": expected["package"]}
            if output is not None and not zarr:
                key["parts_hold"] = hdf5_chunks.parts_hold(direct, sweep.storage, grid)
            parts = HeldChunks() if output is None else (
                zarr_store.StoreParts if zarr else hdf5_chunks.EncodedParts if direct
                else Parts)(output, key, grid, sweep.storage)
            # Looked at only: nothing of an earlier run's changes before every refusal that
            # may come before computing has passed.
            size = parts.open(size, fresh, grid.chunks)
            chunks = grid.chunks(size)
            done = parts.finished()
            todo = [chunk for chunk in chunks if chunk not in done]
            footprint = None if output is None else _footprint(
                sweep, grid, output, todo, executor, parallel)
            if parallel:  # the cluster started, its workers of this version
                _check_workers(executor, model, expected, parts)
            parts.begin(log)
            if footprint is not None and progress and footprint.announced():
                workers = executor.worker_count() if parallel else 1
                log(footprint.text(model.name, f"{workers} worker{'s' * (workers != 1)}"
                                   if parallel else "one core, in this process"))
            scheduler = executor.describe(parallel)
            task = None
            if zarr:  # each chunk is written into the store by the worker that computes it
                parts.prepare(sweep, grid, size, scheduler)
                task = functools.partial(evaluate_into, parts.writer, expected)
            tallies = []
            with contextlib.nullcontext() if output is None or zarr else store.result_file(
                    sweep, grid, output, store.provenance(scheduler), size, direct,
                    interrupts.result_taking_its_name) as writer:
                if direct:  # each chunk encoded by the process that computes it
                    task = functools.partial(evaluate_into, writer.encoder, expected)

                def finished(start: int, stop: int, part: dict):
                    tallies.append(part["tally"] if direct else store.chunk_tally(model, part))
                    if writer is not None:
                        writer.write(start, stop, part)

                if not zarr:  # an interrupted run's chunks (a zarr store holds them already)
                    for start, stop in sorted(done):
                        finished(start, stop, parts.load(start, stop))
                bar = Progress(grid.size, model.name, progress)
                bar.advance(sum(stop - start for start, stop in done))
                kept = len(done)
                try:
                    for start, stop, result in executor.map(grid, todo, parallel, task):
                        _check_versions(result.pop("versions"), expected, executor, parts)
                        parts.save(start, stop, result)
                        kept += 1
                        stored = _stored_bytes(result)
                        if not zarr:  # a zarr chunk is in the store, its counts in its mark
                            finished(start, stop, result)
                        bar.advance(stop - start)
                        if footprint is not None and stored is not None:
                            footprint.check(stop - start, stored, kept)
                finally:
                    bar.close()
                counts, errors, noted = (parts.tally(model, chunks) if zarr
                                         else store.summed(model, tallies))
                dataset = None
                if output is None:
                    dataset = store.gather(sweep, grid, parts, chunks, scheduler, errors)
                else:
                    check_output(output, sweep.path)  # nothing has taken its place meanwhile
                    if zarr:
                        parts.finish(sweep, grid, chunks, output, scheduler, errors,
                                     interrupts.result_taking_its_name)
            parts.remove()
        return Summary(model.name, grid.size, counts, time.monotonic() - began,
                       "(in memory)" if output is None else str(output), scheduler, errors, noted,
                       dataset)
    finally:
        if own:
            executor.close()


def _footprint(sweep, grid, output, todo, executor, parallel) -> Footprint:
    """The run's :class:`footprint.Footprint`; a result stored uncompressed that the disk
    cannot hold is refused (:class:`footprint.InsufficientSpace`) before any computing."""
    workers = executor.worker_count() if parallel else 1
    footprint = Footprint.of(sweep, grid, output, sum(stop - start for start, stop in todo),
                             workers, netcdf=not is_zarr(output))
    footprint.refuse_if_too_large()
    return footprint


def installed_versions(model_name: str) -> dict | None:
    """The :func:`versions` a worker computes ``model_name`` with, or None where its
    installation has no such model (its chunks will say what it does)."""
    from .models.registry import get_model

    try:
        return versions(get_model(model_name))
    except KeyError:
        return None


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
