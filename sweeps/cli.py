"""Command line: ``bearing-sweep run | analyze | study | report | models | describe | presets |
schema | plot``."""
from __future__ import annotations

import argparse
import gc
import json
import shlex
import sys
from pathlib import Path

from .models.catalogue import PRESETS
from . import api, schema, spec
from .stores import structure
from .stores.durable import OutputLock, write_durably
from .stores.paths import check_output, check_outside_results
from .compute import WorkerMismatch
from .executor import ClusterFailure, Executor
from .dependence import InconsistentOutput
from .interrupts import Terminated, interruption, terminated_as_interrupt
from .definition.tables import MissingExtra, suggestion
from .spec import SpecError

#: Exit status for a mistake in the user's input (a definition, a name, an option).
USAGE_ERROR = 2


class _Parser(argparse.ArgumentParser):
    """argparse's parser, a mistake in the options one line as every other mistake's (not
    the usage block): ``--help`` shows the usage."""

    def error(self, message):
        raise SpecError(f"{self.prog}: {message} (`{self.prog} --help` lists the options)")


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="bearing-sweep", description="Parametric studies of rolling bearings.")
    parser.add_argument("--version", action="version",
                        version=f"%(prog)s {structure.package_version()}")
    commands = parser.add_subparsers(dest="command", required=True)

    def cluster_options(command):
        command.add_argument("--workers", type=int, metavar="N",
                             help="size of the local dask cluster (default 2; 0: in-process)")
        command.add_argument("--scheduler", metavar="ADDRESS",
                             help="run on an existing dask.distributed scheduler (its workers "
                                  "need the same bearing-sweep version installed)")

    run = commands.add_parser("run", help="compute a sweep definition into a netCDF file or a "
                              "zarr store")
    run.add_argument("definition", type=Path, help="the sweep definition (TOML)")
    run.add_argument("-o", "--output",  # as written: a trailing / says "a folder"
                     help="netCDF file to write (default results/<definition name>.nc), or a "
                          "zarr store (a path ending in .zarr) that each worker writes into")
    run.add_argument("--chunk-size", type=int, metavar="POINTS",
                     help="grid points per task (default: chosen from the model's cost)")
    run.add_argument("--quiet", action="store_true", help="no progress bar")
    run.add_argument("--fresh", action="store_true",
                     help="ignore the finished chunks of an interrupted run and start over")
    run.add_argument("--encoding", metavar="TYPE",
                     help="float64 (default) or float32: the type the outputs are stored in "
                          "(overrides [output] encoding)")
    run.add_argument("--compression", metavar="NAME[:LEVEL]",
                     help="none, zlib[:1-9] (default zlib:1) or zstd[:1-22] (overrides "
                          "[output] compression)")
    cluster_options(run)

    analyze = commands.add_parser("analyze", help="statistics and Sobol indices of a sampled "
                                  "result")
    analyze.add_argument("result", type=Path, help="a netCDF file (or zarr store) of a sweep with "
                         "[sample]")
    analyze.add_argument("-o", "--output", type=Path, metavar="OUT",
                         help="the netCDF file (.nc) or zarr store (.zarr) to write (default "
                              "RESULT_analysis.nc beside it)")

    run_study = commands.add_parser("study", help="run a paper's sweeps (missing or stale) and "
                                    "draw its figures")
    run_study.add_argument("names", nargs="+", metavar="NAME",
                           help="a study's name, several, or 'all'")
    run_study.add_argument("--force", action="store_true", help="rerun every sweep")
    cluster_options(run_study)

    report = commands.add_parser("report", help="write figures/<study>/README.md and "
                                 "figures/README.md")
    report.add_argument("--index", action="store_true",
                        help="write only figures/README.md, from the pages the studies' runs "
                             "wrote (and any page that is missing)")
    commands.add_parser("models", help="list the models")
    describe = commands.add_parser("describe", help="show one model's inputs and outputs")
    describe.add_argument("model", help="a model's name (bearing-sweep models)")
    presets = commands.add_parser("presets", help="list the catalogue's bearings, or show one")
    presets.add_argument("name", nargs="?", help="a preset to show with its values")
    schema_command = commands.add_parser("schema", help="write the JSON Schema of sweep "
                                         "definitions, for editors that complete and check TOML")
    schema_command.add_argument("model", nargs="?",
                                help="one model's definitions only (default: any model)")
    schema_command.add_argument("-o", "--output", type=Path, metavar="FILE",
                                help="write the schema to FILE (default: standard output)")
    plot = commands.add_parser("plot", help="draw one output of a result against an axis")
    plot.add_argument("result", type=Path, help="a netCDF file (or zarr store) written by "
                      "bearing-sweep run")
    plot.add_argument("variable", nargs="?", help="the output to draw (default: the first)")
    plot.add_argument("--x", metavar="AXIS",
                      help="the axis along x (default: the sweep's first axis)")
    plot.add_argument("-o", "--output", type=Path, metavar="FIGURE",
                      help="the figure to write, .png, .pdf or .svg (default: RESULT.png "
                           "beside the result)")
    explore_command = commands.add_parser(
        "explore", help="write an interactive page of a result: a slider per axis, the chosen "
        "output against the chosen axis (needs the extra bearing-sweep[explore])")
    explore_command.add_argument("result", type=Path, help="a netCDF file (or zarr store) "
                                 "written by bearing-sweep run")
    explore_command.add_argument("variables", nargs="*", metavar="OUTPUT",
                                 help="the outputs the page offers (default: every output "
                                      "with one value per point)")
    explore_command.add_argument("-o", "--output", type=Path, metavar="PAGE",
                                 help="the page to write, .html (default: RESULT.html beside "
                                      "the result)")
    for command in commands.choices.values():
        if command.prog.split()[-1] in ("study", "report"):
            command.add_argument("--studies", type=Path, default=None,
                                 help="folder of studies (default ./studies)")
            command.add_argument("--results", type=Path, default=Path("results"),
                                 help="folder of the studies' netCDF files (default ./results)")
            command.add_argument("--figures", type=Path, default=Path("figures"),
                                 help="folder of the figures and report pages (default ./figures)")
    return parser


def _option(key: str, *value) -> str:
    """An argument of the API as the option that gives it: ``--chunk-size 0``."""
    option = "--" + key.replace("_", "-")
    return f"{option} {value[0]}" if value else option


def _note(message: str):
    print(message, file=sys.stderr)


def _describe(name: str) -> str:
    """The text of the declaration :func:`bearing_sweep.describe` gives as data."""
    model = api.describe(name)
    lines = [f"{model['name']} (version {model['version']}): {model['summary']}",
             f"Reference: {model['reference']}", "", "Inputs:"]
    lines += [_input_line(i) for i in model["inputs"]]
    for table, kinds in model["tables"].items():
        for kind, inputs in kinds.items():
            entry = f"[{table}.<name>] model = {kind!r}" if table == "supports" else (
                f"[{table}] {kind}" if table == "shaft" else f"[{table}.<name>]")
            lines += ["", f"Inputs of each {entry} (on an axis: \"{table}.<name>.<input>\"):"
                      if table != "shaft" else f"Inputs of each of {entry}:"]
            lines += [_input_line(i) for i in inputs]
    lines += ["", "Outputs:"]
    for o in model["outputs"]:
        dims = f" (dims: {', '.join(o['dims'])})" if o["dims"] else ""
        integer = ", an integer" if o["dtype"] == "int" else ""
        fewer = "" if o["depends_on"] is None else (
            f"; depends on {', '.join(o['depends_on']) or 'no input'} only")
        lines.append(f"  {o['name']} [{o['unit']}]{dims}: {o['meaning']}{integer}{fewer}")
    lines.append("  status: per point, one outcome, and out_of_validity beside it where it "
                 "holds:")
    lines += [f"    {status}: {text}" for status, text in model["statuses"].items()]
    if model["validity"]:
        lines.append(f"Validity (out_of_validity beyond): {model['validity']}")
    lines += [f"Condition: {condition}" for condition in model["conditions"]]
    return "\n".join(lines)


def _input_line(i: dict) -> str:
    default = "required" if i["required"] else (
        "derived" if i["default"] is None else f"default {i['default']}")
    unit = f" [{i['unit']}]" if i["unit"] not in ("", "1") else ""
    dims = f" per {', '.join(i['dims'])}" if i["dims"] else ""
    return f"  {i['name']}{unit}{dims}: {i['meaning']}; {default}; {i['range']}"


def _indices_table(analyzed) -> str:
    """The Sobol' indices of a Saltelli design, an output a block, or the sample count."""
    if "first_order" not in analyzed:
        count, drawn = analyzed.attrs["samples_analyzed"], analyzed.attrs.get("sample_size")
        return f"statistics of {count} samples of each output" + (
            f" (a selection of the {drawn} drawn)" if drawn not in (None, count) else "")
    replicates = int(analyzed.attrs.get("sample_replicates", 1))
    lines = ["first-order / total Sobol index [95 % interval] of each output:" if replicates > 1
             else "first-order / total Sobol index of each output (no interval: a design of one "
                  "replicate, from an earlier version; run it again for intervals):"]
    for output in analyzed.output.values:
        failed = int(analyzed.failed_evaluations.sel(output=output).sum())
        if analyzed.first_order.sel(output=output).isnull().all():
            lines.append(f"{output}: none ({failed} evaluations without a value)")
            continue
        if (analyzed[output].sel(statistic="std") == 0).all():
            lines.append(f"{output}: none (the same value in every sample)")
            continue
        lines.append(f"{output}:" + (f" NaN where evaluations failed ({failed} in all)"
                                     if failed else ""))
        for name in analyzed.input.values:
            one = analyzed.sel(output=output, input=name)
            if one.first_order.size != 1:  # indices over other axes: see the file
                lines.append(f"  {name}: {one.first_order.size} values over the other axes")
                continue
            low, high = one.first_order_interval.values
            total_low, total_high = one.total_order_interval.values
            lines.append(f"  {name}: {float(one.first_order):.3f} [{low:.3f}, {high:.3f}] / "
                         f"{float(one.total_order):.3f} [{total_low:.3f}, {total_high:.3f}]")
    return "\n".join(lines)


def _preset(name: str) -> str:
    if name not in PRESETS:
        raise SpecError(f"unknown preset {name!r}" + suggestion(name, PRESETS)
                        + " (`bearing-sweep presets` lists them)")
    preset = PRESETS[name]
    lines = [f"{preset.name}: for {', '.join(preset.models)}", f"Source: {preset.source}"]
    if preset.notes:
        lines.append(f"Notes: {preset.notes}")
    lines.append("Values:")
    lines += [f"  {key} = {value!r}" if not isinstance(value, str) else f"  {key} = {value}"
              for key, value in preset.values.items()]
    return "\n".join(lines)


def _schema(model: str | None, output: Path | None):
    """Print the schema, or write it to ``output`` (never over a definition or a result)."""
    if model is not None:
        spec.find_model(model)  # an unknown name is the one line every command gives
    text = json.dumps(schema.schema(model), indent=2) + "\n"
    if output is None:
        sys.stdout.write(text)
        return
    if output.suffix != ".json" or (output.exists() and not output.is_file()):
        raise SpecError(f"{output}: a schema is written to a .json file")
    check_outside_results(output)
    if output.exists() and not _our_schema(output):
        raise SpecError(f"{output}: exists and is not a schema written by bearing-sweep; "
                        "refusing to replace it (remove it or choose another path)")
    with OutputLock(output):  # a folder that takes no file says so, as for a run
        write_durably(output, lambda handle: handle.write(text.encode()))
    print(f"wrote {output}", file=sys.stderr)


def _our_schema(path: Path) -> bool:
    try:
        found = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return False
    return isinstance(found, dict) and str(found.get("$id", "")).startswith("bearing-sweep")


def main(argv=None) -> int:
    args = None
    try:
        args = _parser().parse_args(argv)
        if args.command == "models":
            for model in api.list_models():
                print(f"{model['name']}: {model['summary']}")
        elif args.command == "describe":
            print(_describe(args.model))
        elif args.command == "presets":
            if args.name is None:
                for preset in PRESETS.values():
                    print(f"{preset.name} ({', '.join(preset.models)}): {preset.source}")
            else:
                print(_preset(args.name))
        elif args.command == "schema":
            _schema(args.model, args.output)
        elif args.command == "plot":
            output = args.output or args.result.with_suffix(".png")
            from . import quicklook  # matplotlib only for who plots

            quicklook.plot(args.result, args.variable, x=args.x, output=output)
            print(f"wrote {output}")
        elif args.command == "explore":
            from . import explorer  # bokeh only for who explores

            page = explorer.explore(args.result, args.variables or None, output=args.output)
            print(f"wrote {page}")
        elif args.command == "run":
            output = args.output or Path("results") / f"{args.definition.stem}.nc"
            api.run(args.definition, output=output, scheduler=args.scheduler or None,
                    workers=args.workers, chunk_size=args.chunk_size,
                    fresh=args.fresh, progress=not args.quiet, log=_note, summary=print,
                    encoding=args.encoding, compression=args.compression, open_output=False,
                    named=_option)
        elif args.command == "analyze":
            output = args.output or args.result.with_name(f"{args.result.stem}_analysis.nc")
            print(_indices_table(api.analyze(args.result, output=output)))
            print(f"wrote {output}")
        elif args.command == "study":
            from . import study

            api.check_cluster_arguments(args.workers, args.scheduler or None, named=_option)
            chosen = study.select(args.studies or study.default_studies_folder(), args.names)
            study.check_folders(chosen, args.results, args.figures)
            for one in chosen:  # every result it may write, before any computing
                for definition in one.definitions:
                    check_output(one.result(args.results, definition), definition)
            with Executor(args.workers, args.scheduler) as executor:
                for one in chosen:
                    study.run_study(one, args.results, args.figures, executor, args.force)
        elif args.command == "report":
            from . import study

            chosen = study.select(args.studies or study.default_studies_folder(), "all")
            study.check_folders(chosen, args.results, args.figures)
            folders = " ".join(f"--{name} {shlex.quote(str(value))}" for name, value in (
                ("studies", args.studies), ("results", args.results), ("figures", args.figures))
                if value is not None and value != Path(name))
            for path in study.write_report(chosen, args.results, args.figures, folders,
                                           from_pages=args.index):
                print(f"wrote {path}")
    except SpecError as error:
        print(f"error: {error}", file=sys.stderr)
        return USAGE_ERROR
    # The cluster or the installation, not the input, is at fault.
    except (WorkerMismatch, ClusterFailure, MissingExtra) as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    except InconsistentOutput as error:  # the model's declaration, not the input, is at fault
        print(f"error: {error}; the computed chunks are kept, nothing else is written",
              file=sys.stderr)
        return 1
    except OSError as error:  # a folder that cannot be written, a full disk, a busy output
        # A failed rename names its destination second: that is the file the user asked for.
        target = getattr(error, "filename2", None) or error.filename
        where = f"{target}: " if target else ""
        print(f"error: {where}{error.strerror or error}; any earlier result is left as it was",
              file=sys.stderr)
        return 1
    except KeyboardInterrupt as error:
        return _interrupted(args, error)
    except Exception as error:  # a Ctrl-C that Python or a library raised as another error
        interrupt = interruption(error)
        if not isinstance(interrupt, KeyboardInterrupt):
            raise
        return _interrupted(args, interrupt)
    return 0


def _interrupted(args, error: BaseException) -> int:
    """Say that the command was interrupted (or terminated), in one line; its exit status."""
    computing = args is not None and args.command in ("run", "study")
    word = "terminated" if isinstance(error, Terminated) else "interrupted"
    print(f"{word}: the finished chunks are kept; run the same command again to resume"
          if computing else word, file=sys.stderr)
    return 143 if isinstance(error, Terminated) else 130


def program(argv=None) -> int:
    """The ``bearing-sweep`` program (through :func:`bearing_sweep.program`, which imports
    this module): :func:`main`, its objects then frozen out of the garbage collector's passes
    at the interpreter's shutdown, which would otherwise search every object numba, pint and
    the model left for cycles: a fifth of a second of a small run's second. Every file is
    closed by then, and exit handlers still run."""
    with terminated_as_interrupt():
        code = main(argv)
    gc.freeze()
    return code


if __name__ == "__main__":
    sys.exit(program())
