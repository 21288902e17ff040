"""The Python API: run and check sweep definitions, and read the models' declarations as data.

The same engine as the command line: ``run(definition)`` gives the dataset that
``bearing-sweep run`` writes, and every mistake is a :class:`~bearing_sweep.spec.SpecError`
whose message is the line the command prints after ``error:``.
"""
from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from .models.registry import REQUIRED, STATUS_DESCRIPTIONS, all_models
from . import spec
from .compute import RESULT_COMPLETE, Interrupts, run_sweep
from .executor import Executor, check_scheduler_address
from .stores import is_result, open_result, result_engine
from .stores.netcdf import write_netcdf
from .stores.paths import ZARR_SUFFIX, argument_text, check_output, is_zarr, path_argument
from .stores.zarr import write_dataset as write_zarr
from .definition.output import storage_options
from .spec import SpecError, Sweep
from .tables import ModelDescription, ModelList

if TYPE_CHECKING:  # xarray only once a dataset is made or read: `bearing-sweep run` needs none
    from collections.abc import Callable

    from typing import TypeAlias

    import xarray as xr
    from distributed import Client

    #: What a definition may be given as: TOML text (with a line break), a path, or a dict
    #: of the TOML's structure.
    Definition: TypeAlias = str | os.PathLike | dict


def argument_named(key: str, *value) -> str:
    """How a message of the API names its argument ``key`` (with its value: ``workers=-1``);
    the command line names its options instead (``--workers -1``)."""
    return f"{key}={argument_text(value[0])}" if value else f"argument {key}"


def _stderr(message: str):
    print(message, file=sys.stderr)


def run(definition: Definition, *, output: str | os.PathLike | None = None,
        client: Client | None = None, scheduler: str | None = None, workers: int | None = None,
        chunk_size: int | None = None, fresh: bool = False, progress: bool = True,
        log: Callable[[str], object] | None = None,
        summary: Callable[[str], object] | None = None, encoding: str | None = None,
        compression: str | None = None, open_output: bool = True,
        named: Callable[..., str] = argument_named) -> xr.Dataset | None:
    """Compute a sweep and return its labelled dataset.

    Parameters
    ----------
    definition : str, os.PathLike or dict
        TOML text (a string with a line break), the path of a TOML file, or a dict of the
        same structure with units in strings (``{"sweep": {"model": "crb_radial"},
        "axes": {"radial_load": ["2 kN", "4 kN"]}}``).
    output : str or os.PathLike, optional
        A netCDF file to write, atomically and resumably, as ``bearing-sweep run -o`` does,
        or a zarr store (a path ending in ``.zarr``) that each worker writes its chunks into;
        the dataset is then returned opened from it (lazily: close it, or use ``with``).
        Without it, nothing is written and the dataset is returned in memory.
    client : dask.distributed.Client, optional
        An existing client to compute the chunks on (a ``dask_jobqueue.SLURMCluster``'s, for
        one); it is left open. Its workers need the same bearing-sweep installed, and to
        write a zarr ``output`` the same filesystem at the same path.
    scheduler : str, optional
        The address of a running dask.distributed scheduler to compute on
        (``"tcp://HOST:PORT"``), instead of ``client``; with the same needs of its workers.
    workers : int, optional
        Without ``client``: a local dask cluster of this many single-threaded processes, 0 to
        compute in this process (default: two, or in this process for a small sweep).
    chunk_size : int, optional
        Grid points per task (default: chosen from the model's cost).
    fresh : bool
        Discard the finished chunks an interrupted run with the same ``output`` left, and
        start over (by default the run resumes from them).
    progress : bool
        A progress bar on stderr, and there too by default the messages and the summary.
    log : callable, optional
        Called with each message for the user, one line of text: resuming an interrupted
        run, discarding its chunks, the estimate of a long or large run, an interrupt that
        came once the result was complete (default: printed on stderr with ``progress``).
    summary : callable, optional
        Called with the closing summary (points, statuses, time; default: printed on stderr
        with ``progress``).
    encoding, compression : str, optional
        How ``output`` stores the outputs, over the definition's ``[output]`` table, as
        ``bearing-sweep run --encoding --compression`` takes them: ``"float32"``,
        ``"zlib:4"``, ``"none"`` (the returned dataset carries them as its variables'
        ``encoding``, for ``to_netcdf``).
    open_output : bool
        False: with ``output``, return None once it is written rather than open it (a script
        that only writes results then needs no xarray).
    named : callable
        How a message names an argument: ``named(key)``, ``named(key, value)``; the command
        line gives its options' names (``--workers -1`` rather than ``workers=-1``).

    Returns
    -------
    xarray.Dataset or None
        The sweep's axes as dimensions, every output (on the axes of the inputs it depends
        on, where it declares them: ``xarray.broadcast`` spreads it over the others) and the
        ``status`` of every point, with units and provenance: the same variables, values and
        attributes as the CLI's file.

    Raises
    ------
    SpecError
        A mistake in the definition or the arguments (an output path that must not be
        written: an earlier zarr store, which is never replaced), found before any computing;
        nothing is written.
    OSError
        A failure of the machine: a full disk, a result the disk cannot hold
        (:class:`~bearing_sweep.stores.footprint.InsufficientSpace`, before computing, or once the
        first chunks show it), another run writing ``output``; the finished chunks are kept.
    RuntimeError
        A local cluster that cannot start (:class:`~bearing_sweep.executor.ClusterFailure`),
        workers of another version.
    """
    check_cluster_arguments(workers, scheduler, client, named)
    if chunk_size is not None and (isinstance(chunk_size, bool) or not isinstance(chunk_size, int)
                                   or chunk_size < 1):
        raise SpecError(f"{named('chunk_size', chunk_size)}: expected a positive integer")
    for flag, value in (("fresh", fresh), ("progress", progress), ("open_output", open_output)):
        _flag_argument(value, flag)
    output = path_argument(output, "output")
    sweep = _sweep(definition)
    sweep.storage = storage_options(sweep.storage, encoding, compression, named)
    default = _stderr if progress else None
    log = default if log is None else log
    summary = default if summary is None else summary
    # A Ctrl-C once the result is in place waits for the cleanup: the result is complete.
    with Interrupts() as interrupts:
        with Executor(workers, scheduler, client) as executor:
            done = run_sweep(sweep, output, executor, chunk_size, progress, fresh, log,
                             interrupts)
        if summary is not None:
            summary(done.text())
        if interrupts.ignored and log is not None:
            log(RESULT_COMPLETE)
        if output is None:
            return done.dataset
        if not open_output:
            return None
        import xarray as xr

        return xr.open_dataset(output, engine=result_engine(output))


def check_cluster_arguments(workers=None, scheduler=None, client=None, named=argument_named):
    """Refuse (:class:`SpecError`) a cluster asked for in a way that cannot be, before anything
    starts: a negative or non-integer ``workers``, ``workers=0`` (in this process) with a
    ``scheduler``, ``workers`` or ``scheduler`` with a ``client``, an address that names no
    scheduler, a ``client`` that is not a dask.distributed Client."""
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or workers < 0):
        raise SpecError(f"{named('workers', workers)}: expected 0 (in-process) or more workers")
    if workers is not None and client is not None:
        raise SpecError("workers and client exclude each other: the client's cluster has its "
                        "own workers")
    if scheduler is not None and client is not None:
        raise SpecError("scheduler and client exclude each other: the client is connected to "
                        "its own scheduler")
    if workers == 0 and scheduler:
        raise SpecError(f"{named('workers', 0)} and {named('scheduler')} exclude each other")
    if scheduler is not None:
        if not isinstance(scheduler, str):
            raise SpecError(f"{named('scheduler', scheduler)}: expected a scheduler's address, "
                            "a string (tcp://HOST:PORT)")
        check_scheduler_address(scheduler, named("scheduler", scheduler))
    _client_argument(client)


def check(definition: Definition) -> None:
    """Validate a definition (as :func:`run` takes it) without computing anything.

    Raises :class:`SpecError` with the one line ``bearing-sweep run`` would print.
    """
    _sweep(definition)


def analyze(result: str | os.PathLike | xr.Dataset, *,
            output: str | os.PathLike | None = None) -> xr.Dataset:
    """Summary statistics of a sampled result and, for a Saltelli design, its Sobol' indices.

    Parameters
    ----------
    result : xarray.Dataset, str or os.PathLike
        A result of a definition with a ``[sample]`` table, or its netCDF file or zarr store.
    output : str or os.PathLike, optional
        Where to write the analysis, atomically, as ``bearing-sweep analyze -o``: a netCDF
        file (a path ending in ``.nc`` or ``.nc4``) or a zarr store (``.zarr``).

    Returns
    -------
    xarray.Dataset
        Every output's ``mean``, ``std``, ``p5``, ``p50`` and ``p95`` over the samples (the
        dimension ``statistic``), and for a Saltelli design ``first_order`` and
        ``total_order`` with dimensions (``output``, ``input``, the result's other axes) and
        their 95 % intervals; see :func:`bearing_sweep.analysis.analyze`.

    Raises
    ------
    SpecError
        Not a sampled result, no such file, or an output path that must not be written.
    """
    where = "the dataset"
    output = path_argument(output, "output")
    if output is not None:
        _check_analysis_output(output)
    import xarray as xr

    if not isinstance(result, xr.Dataset):
        result = path_argument(result, "result", "a sampled result: an xarray.Dataset or",
                               optional=False)
        where = str(result)
        if not is_result(result):
            raise SpecError(f"{result}: no such result file")
        if output is not None and os.path.exists(output) and os.path.samefile(result, output):
            raise SpecError(f"{output}: is the result itself; choose another output")
        try:
            result = open_result(result)
        except (OSError, ValueError) as error:  # not netCDF, or not one xarray reads
            raise SpecError(f"{where}: not a result of bearing-sweep run "
                            f"({str(error).splitlines()[0]})") from None
    if output is not None:
        check_output(output, result="analysis")
    from . import analysis  # its scipy.stats only for who analyses

    analyzed = analysis.analyze(result, where)
    if is_zarr(output):
        write_zarr(analyzed, output)
    elif output is not None:
        write_netcdf(analyzed, output)
    return analyzed


#: The suffixes (in any case) of an analysis' output: a netCDF file, or a zarr store.
ANALYSIS_SUFFIXES = (".nc", ".nc4", ZARR_SUFFIX)


def _check_analysis_output(output):
    """Refuse an analysis output whose suffix names another format than the one it would be
    written in."""
    suffix = Path(output).suffix
    if suffix.lower() not in ANALYSIS_SUFFIXES:
        raise SpecError(f"{output}: an analysis is written as a netCDF file (.nc, .nc4) or a "
                        "zarr store (.zarr), as the suffix says; "
                        + (f"not {suffix}" if suffix else "this name has none"))


def list_models() -> ModelList:
    """The registered models, one dict each: ``name``, ``summary``, ``reference``,
    ``version``; a list that shows as a table in a notebook (``.to_dataframe()``: a
    pandas DataFrame)."""
    return ModelList({"name": m.name, "summary": m.summary, "reference": m.reference,
                      "version": m.version} for m in all_models().values())


def _input(i) -> dict:
    """One input's declaration as :func:`describe` gives it."""
    return {"name": i.name, "unit": i.unit, "meaning": i.meaning, "dims": i.dims,
            "kind": i.kind, "default": None if i.required else (
                list(i.default) if i.kind == "subset" else i.default),
            "required": i.default is REQUIRED, "minimum": i.minimum, "maximum": i.maximum,
            "range": i.range_text(), "choices": i.choices}


def describe(name: str) -> ModelDescription:
    """One model's declaration as data, what ``bearing-sweep describe`` prints.

    Returns
    -------
    ModelDescription
        A dict that shows as tables in a notebook (``.to_dataframe("inputs")``, or
        ``"outputs"``: a pandas DataFrame): ``name``, ``version``, ``summary``, ``reference``, ``function`` (the import path of
        the model's function, for direct use on arrays in SI units), ``inputs`` and
        ``outputs`` (lists of dicts: ``name``, ``unit``, ``meaning``, ``dims``; an output also
        ``dtype``, ``"int"`` for one stored as integers; an input also
        ``kind``, ``default``, ``required``, ``minimum``, ``maximum``, ``range`` and
        ``choices``; ``default`` is None for a required input and for one the model derives
        when it is not given), ``tables`` (for a model whose definition gives its structure in
        tables of its own, a shaft system's: each table's inputs by kind of entry, as
        ``inputs``), ``validity``, ``conditions`` and ``statuses``.

    Raises
    ------
    SpecError
        No model has that name (the message names the closest).
    """
    if not isinstance(name, str):
        raise SpecError(f"name={argument_text(name)}: expected a model's name, a string "
                        "(list_models() "
                        "gives them)")
    model = spec.find_model(name)
    function = model.function
    return ModelDescription({
        "name": model.name, "version": model.version, "summary": model.summary,
        "reference": model.reference, "function": f"{function.__module__}.{function.__qualname__}",
        "inputs": [_input(i) for i in model.inputs],
        "tables": {table: {kind: [_input(i) for i in inputs] for kind, inputs in kinds.items()}
                   for table, kinds in model.tables.items()},
        "outputs": [{"name": o.name, "unit": o.unit, "meaning": o.meaning, "dims": o.dims,
                     "dtype": o.dtype, "depends_on": o.depends_on} for o in model.outputs],
        "validity": model.validity,
        "conditions": [c.message for c in model.constraints],
        "statuses": dict(STATUS_DESCRIPTIONS),
    })


def _sweep(definition) -> Sweep:
    """The validated sweep of a definition given as text, a path or a dict."""
    if isinstance(definition, dict):
        return spec.from_dict(definition)
    if isinstance(definition, str) and "\n" in definition:
        return spec.parse(definition)
    if isinstance(definition, (str, os.PathLike)):
        return spec.load(definition)
    raise SpecError(f"a definition is TOML text, a path or a dict, not "
                    f"{type(definition).__name__}")


def _client_argument(client):
    if client is None:
        return
    if isinstance(client, str):
        raise SpecError(f"client={client!r}: expected a dask.distributed.Client; for a "
                        f"scheduler's address, give Client({client!r})")
    if not all(hasattr(client, method) for method in ("submit", "scheduler_info")):
        raise SpecError(f"client={argument_text(client)}: expected a dask.distributed.Client, "
                        "not "
                        f"{type(client).__name__}")


def _flag_argument(value, name: str):
    if not isinstance(value, bool):
        raise SpecError(f"{name}={argument_text(value)}: expected True or False")
