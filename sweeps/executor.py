"""Where a sweep's chunks are computed: in this process, on a LocalCluster or on a dask cluster
(:class:`Executor`)."""
from __future__ import annotations

import contextlib
import itertools
import logging
import math
import os
import signal
import socket
import threading
import uuid
from concurrent.futures import ThreadPoolExecutor

from . import evaluate
from .evaluate import largest_chunk
from .stores.footprint import duration
from .grid import Grid, block_shape
from .interrupts import interruptions_raised
from .spec import SpecError


#: Below this estimated single-core time [s] a sweep runs in-process: starting a cluster
#: would take longer than the work (benchmarks/cluster_break_even.py measures where a fresh
#: LocalCluster of two pays).
IN_PROCESS_SECONDS = 4.0


#: Chunks submitted per worker at a time; the next is submitted as one finishes.
CHUNKS_IN_FLIGHT = 4


#: How long to wait for a scheduler given by ``--scheduler`` to answer [s].
CONNECT_SECONDS = 10.0


#: The size of the local cluster when none is asked for.
DEFAULT_WORKERS = 2


class ClusterFailure(RuntimeError):
    """The cluster could not start, or lost a worker for good; the message is for the user."""


def available_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system says, as a batch
    scheduler sets it, otherwise the machine's)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # macOS and Windows have no affinity call
        return os.cpu_count() or 1


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
        cost = grid.size * grid.seconds_per_point
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
            work = grid.size * grid.seconds_per_point
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
        # and unmap every large numpy temporary of a model afresh, slowing the models.
        # Its profiler serves only the dashboard; slower housekeeping leaves an idle
        # cluster's share of a core to the workers, which need it when they occupy every
        # core (benchmarks/RESULTS.md).
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

    def dashboard(self) -> str | None:
        """The address of the dashboard of the local cluster this executor started, where
        one is served (dask serves it when bokeh is installed)."""
        import importlib.util

        if self.cluster is None or importlib.util.find_spec("bokeh") is None:
            return None
        return self.cluster.dashboard_link

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
        task = task or evaluate.evaluate_chunk
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
            future = client.submit(task, grid, start, stop, pure=False,
                                   key=f"{grid.model.name}-points-{start}-{stop}-{run}")
            futures[future] = (start, stop)
            return future

        futures = {}
        run = uuid.uuid4().hex  # a run's own keys: the same chunk of another run is another task
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

