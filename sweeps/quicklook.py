"""A quick look at any result: one output against one axis, without writing a figure script.

``plot(result)`` draws the first output against the first axis that has more than one value, a
line per value of the next axis and a panel per value of the one after (rows for a fourth);
further axes are held at their first value. A sampled result is drawn against its first drawn
input, a point per sample. Points whose status says the values do not hold are marked on the
axis, points solved outside the model's validity ringed. An output with its own entries (per
roller, per ball, along a rotation) is drawn as their distribution: the mean and the band from
the least to the largest entry; a result of a single point draws such an output along its
entries. The inputs the sweep held fixed are the figure's conditions. What cannot be drawn (a
single value, an output without any value) is a :class:`SpecError` saying why.
"""
from __future__ import annotations

import os
import textwrap
from pathlib import Path

import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from .dependence import flag_holds, held_points, on_grid
from .duty_cycle import SUFFIX as CYCLE_SUFFIX
from .models.registry import get_model
from .stores import is_result, open_result
from .stores.durable import OutputLock, write_durably
from .stores.paths import argument_text, check_outside_results, is_zarr, path_argument
from .plotting import MAKER, conditions, in_unit, label, metadata, shown_unit, subplots
from .definition.tables import suggestion
from .spec import SpecError

#: Figure formats ``plot`` writes, with the first bytes of such a file: only a figure is ever
#: replaced by another one.
FORMATS = {".png": (b"\x89PNG",), ".pdf": (b"%PDF",), ".svg": (b"<?xml", b"<svg")}
#: The most of a figure read to find who wrote it (a quick look is some 100 kB).
MOST_FIGURE_BYTES = 64 * 2**20
#: What a point's mark code says: its values hold, hold but outside validity, or none.
_HOLDS, _OUTSIDE, _NO_VALUE = range(3)
#: Most lines in a panel, and most panels across or down; a longer axis is thinned.
MOST_LINES, MOST_PANELS = 8, 4
#: How the points whose status is not converged are marked.
_MARKS = {"out of validity": {"marker": "o", "ms": 9, "mfc": "none"},
          "no value (status)": {"marker": "x", "ms": 7}}
#: The dimension of a sampled result's samples.
_SAMPLE = "sample"


def plot(result: str | os.PathLike | xr.Dataset, variable: str | None = None, *,
         x: str | None = None, output: str | os.PathLike | None = None) -> Figure:
    """Draw one output of a sweep's result against one of its axes.

    Parameters
    ----------
    result : str, pathlib.Path or xarray.Dataset
        A netCDF file (or zarr store) written by ``bearing-sweep run``, or such a dataset.
    variable : str, optional
        The output to draw (default: the model's first output; for a result of a single
        point, the first output with entries of its own).
    x : str, optional
        The axis along the figure's x axis: a sweep axis, an input of a zipped axis or drawn
        by ``[sample]``, or a dimension of the output's own (``angle``, ``roller``). Default:
        the first sweep axis of more than one value (a sampled result: its first drawn
        input, a point per sample; a single point: the output's first own dimension).
    output : str or pathlib.Path, optional
        Write the figure there too (PNG, PDF or SVG, by its suffix).

    Returns
    -------
    matplotlib.figure.Figure
        Drawn outside pyplot (no backend is chosen or changed): a notebook shows it as a
        cell's value; ``figure.savefig`` writes it.

    Raises
    ------
    bearing_sweep.spec.SpecError
        For an unknown variable or axis (with the closest name), a variable that is not an
        output, an output with nothing to draw (one value, no value at any point), or an
        output path that must not be written (see :func:`check_figure_path`).
    """
    if not isinstance(result, xr.Dataset):
        result = path_argument(result, "result", "a result: an xarray.Dataset or",
                               optional=False)
    output = path_argument(output, "output")
    for name, value in (("variable", variable), ("x", x)):
        if value is not None and not isinstance(value, str):
            raise SpecError(f"{name}={argument_text(value)}: expected the name of "
                            + ("an output" if name == "variable" else "an axis") + ", a string")
    source = "the dataset" if isinstance(result, xr.Dataset) else str(result)
    if source != "the dataset" and not is_result(result):
        raise SpecError(f"{result}: no such result file")
    if output is not None:  # before the result is read: a path refused costs nothing
        output = check_figure_path(output, None if isinstance(result, xr.Dataset) else result)
    data = result if isinstance(result, xr.Dataset) else _open(result)
    if "status" not in data or "flag_meanings" not in data["status"].attrs:
        raise SpecError(f"{source}: not a result of bearing-sweep run (it has no status "
                        "variable)")
    data = on_grid(data)  # an output stored on fewer axes than the grid: at every point
    outputs = _outputs(data, declared=not isinstance(result, xr.Dataset) and is_zarr(result))
    axes = list(data["status"].dims)
    variable = _output(data, variable, outputs, axes, source)
    values = data[variable]
    if not values.notnull().any():
        raise SpecError(f"{source}: {variable} has no value at any point "
                        f"({_statuses(data['status'])}): nothing to draw")
    own = [d for d in values.dims if d not in axes]
    # Labelled entries of an output's own (dof: axial, radial_y, ...) are categories, to be
    # told apart like axes; numbered ones (roller 1..Z, an angle) form a distribution.
    categorical = [d for d in own if data[d].dtype.kind in "OUS"]
    distributed = [d for d in own if d not in categorical]
    x = _choose_x(data, x, axes, own, variable, source)
    along = data[x].dims[0]  # the dimension x lies along: a zipped or sampled input's axis
    if along in distributed:
        distributed.remove(along)
    rest = [d for d in axes + categorical if d != along and data.sizes[d] > 1]
    lines, columns, rows = (rest + [None] * 3)[:3]
    held = rest[3:]
    single = [d for d in axes + categorical if d != along and data.sizes[d] == 1]
    thinned = []  # a legend of a hundred lines reads as none: a few values, evenly spaced
    for dim, most in ((lines, MOST_LINES), (columns, MOST_PANELS), (rows, MOST_PANELS)):
        if dim is not None and data.sizes[dim] > most:
            thinned.append(f"{dim.replace('_', ' ')}: {most} of {data.sizes[dim]} values")
            data = data.isel({dim: np.unique(np.linspace(0, data.sizes[dim] - 1, most)
                                             .round().astype(int))})
    # Axes of one value, and those beyond a panel grid, are held at their first value.
    first = {d: 0 for d in held + single}
    values = data[variable].isel({d: 0 for d in first if d in data[variable].dims})
    status = data["status"].isel({d: 0 for d in first if d in axes})
    shown = {d: _shown(data[d]) for d in (x, lines, columns, rows) if d is not None}

    nrows, ncols = (data.sizes[rows] if rows else 1), (data.sizes[columns] if columns else 1)
    # Panels of an output's entries (dof: a translation, a tilt) may differ in unit and scale.
    shared = not {columns, rows} & set(categorical)
    key = _key_width(data, lines, shown)
    figure, grid = subplots(nrows, ncols, squeeze=False, sharex=True, sharey=shared,
                            figsize=(4.2 * ncols + 1.2 + key, 3.2 * nrows + 1.0))
    # Samples are in no order, labels (geometry: jones, fixed_angle) have nothing between
    # them: points, not joined.
    scatter = along == _SAMPLE or data[x].dtype.kind in "OUS"
    marked = set()
    for r in range(nrows):
        for c in range(ncols):
            axis = grid[r, c]
            where = {d: i for d, i in ((rows, r), (columns, c)) if d is not None}
            panel = values.isel(where)
            panel_status = status.isel({d: i for d, i in where.items() if d in status.dims})
            marked |= _draw_panel(axis, panel, panel_status, x, along, lines, distributed,
                                  shown, data, scatter)
            axis.set_title(", ".join(_value_text(data, d, i) for d, i in where.items()),
                           fontsize=8)
            if r == nrows - 1:
                axis.set_xlabel(label(shown[x], long=True))
            if c == 0 or not shared:
                axis.set_ylabel(_y_label(data, variable, panel, distributed))
    # One legend for every panel (each draws the same lines), beside them, not over the data.
    handles = [line for line in grid[0, 0].lines if not line.get_label().startswith("_")]
    handles += [Line2D([], [], ls="none", color="grey", **_MARKS[kind], label=kind)
                for kind in _MARKS if kind in marked]
    if handles:
        figure.legend(handles=handles, fontsize=7, title_fontsize=7, loc="center left",
                      bbox_to_anchor=(1 - key / figure.get_figwidth(), 0.5),
                      title=label(shown[lines], long=True) if lines else None)
    figure.suptitle(_title(data, held, single, thinned, along, x, figure), fontsize=8)
    figure.tight_layout(rect=(0, 0, 1 - key / figure.get_figwidth(), 1))
    if output is not None:
        _write(figure, output)
    return figure


def _title(data, held, single, thinned, along, x, figure) -> str:
    """The result's title, what the user chose (a preset, [fixed]) and the axes the figure
    does not show. The model's defaults are many (30 for cage_slip) and named once, in the
    file."""
    fixed = [n for n in data.attrs.get("fixed_inputs", "").split()
             if n in data and data[n].attrs.get("origin") != "default"]
    notes = [_value_text(data, d, 0) for d in single]
    notes += [_value_text(data, d, 0) + f" (first of {data.sizes[d]})" for d in held]
    notes += thinned
    if along == _SAMPLE:
        drawn = [n for n in data.attrs.get("sample_inputs", "").split() if n in data and n != x]
        notes.append(f"{data.sizes[_SAMPLE]} samples ({data.attrs.get('sample_method', 'drawn')})"
                     + (f"; {', '.join(n.replace('_', ' ') for n in drawn)} drawn as well"
                        if drawn else ""))
    width = int(14 * figure.get_figwidth())  # characters of the title's font across the figure
    return "\n".join(t for t in (data.attrs.get("title", ""),
                                  conditions(data, *fixed, width=width),
                                  textwrap.fill(", ".join(notes), width)) if t)


def _draw_panel(axis, values, status, x, along, lines, distributed, shown, data, scatter):
    """One panel: a line (or a distribution) per value of ``lines``, failures marked.
    Returns the kinds of mark drawn."""
    positions, ticks = _positions(shown[x])
    marked = set()
    style = {"marker": "o", "ms": 3} if len(positions) <= 40 or scatter else {}
    if scatter:
        style["ls"] = "none"
    for index in range(values.sizes[lines] if lines else 1):
        line = values.isel({lines: index}) if lines else values
        point_status = status.isel({lines: index}) if lines in status.dims else status
        point_marks = _marks(point_status)
        name = _value_text(data, lines, index, named=False) if lines else None
        if distributed:
            low, high = (v.transpose(along).values for v in (line.min(distributed),
                                                              line.max(distributed)))
            line = line.mean(distributed)
            drawn, = axis.plot(positions, line.transpose(along).values, label=name, **style)
            if scatter:
                axis.vlines(positions, low, high, color=drawn.get_color(), alpha=0.3)
            else:
                axis.fill_between(positions, low, high, color=drawn.get_color(), alpha=0.2,
                                  lw=0)
        else:
            drawn, = axis.plot(positions, line.transpose(along).values, label=name, **style)
        shown_values = line.transpose(along).values
        if len(positions) == 1 and np.isfinite(shown_values[0]):  # a lone point: its value
            axis.annotate(f"{shown_values[0]:.4g}", (positions[0], shown_values[0]),
                          xytext=(5, 3), textcoords="offset points", fontsize=7,
                          color=drawn.get_color())
        marked |= _mark(axis, positions, shown_values,
                        np.broadcast_to(point_marks.transpose(
                            *[d for d in (along,) if d in point_marks.dims]).values,
                            np.shape(positions)), drawn.get_color())
    if not values.notnull().any():  # say so, rather than leave a blank panel
        axis.text(0.5, 0.5, f"no value here\n({_statuses(status)})", transform=axis.transAxes,
                  ha="center", va="center", fontsize=8, color="0.4")
    if ticks is not None:
        axis.set_xticks(positions, ticks, rotation=20, fontsize=7)
    axis.grid(alpha=0.3)
    return marked


def _key_width(data, lines, shown) -> float:
    """About how wide [in] the legend beside the panels is: its longest text (a value of
    ``lines``, its title, a mark's name) in 7-point type."""
    texts = ["no value (status)"] + ([label(shown[lines], long=True)] + [
        _value_text(data, lines, i, named=False) for i in range(data.sizes[lines])]
        if lines else [])
    return 0.5 + 0.065 * max(len(t) for t in texts)


def _y_label(data, variable: str, panel, distributed: list) -> str:
    """The label of a panel's y axis: the output's name and unit (an output whose entries
    each have their own unit, as a displacement's translations and tilts: the unit of the
    panel's entry), and what a band means, wrapped to the panel's height."""
    values = data[variable]
    units = data.get(values.attrs.get("ancillary_variables", ""))
    if "units" not in values.attrs and units is not None and units.dtype.kind in "OUS":
        entry = units.sel({d: panel[d] for d in units.dims if d in panel.coords
                           and panel[d].ndim == 0})
        if entry.size == 1:
            values = values.assign_attrs(units=str(entry.values))
    text = label(values, long=True)
    if distributed:
        text += ("; mean, and band from the least to the largest over "
                 + ", ".join(data[d].attrs.get("long_name", d.replace("_", " "))
                             for d in distributed))
    return textwrap.fill(text, 45)


def _marks(status: xr.DataArray) -> xr.DataArray:
    """Each point's mark code from its status flags: ``_NO_VALUE`` where its values do not
    all hold (not converged, infeasible, failed, or a root not in range), else ``_OUTSIDE``
    where it is out of validity, else ``_HOLDS``."""
    holding = held_points(status) & ~flag_holds(status, "no_root_in_range")
    return xr.where(holding, xr.where(flag_holds(status, "out_of_validity"), _OUTSIDE, _HOLDS),
                    _NO_VALUE)


def _mark(axis, positions, values, marks, color) -> set:
    """Ring the points solved out of validity; mark with a cross, at the foot of the panel,
    the points whose values do not hold (NaN: not converged, infeasible, failed). ``marks``:
    each point's code from :func:`_marks`. Returns the kinds of mark drawn."""
    drawn = set()
    outside = marks == _OUTSIDE
    if outside.any():
        axis.plot(positions[outside], values[outside], ls="none", color=color,
                  label="_out of validity", **_MARKS["out of validity"])
        drawn.add("out of validity")
    failed = marks == _NO_VALUE
    if failed.any():
        axis.plot(positions[failed], np.zeros(failed.sum()), ls="none", color=color,
                  transform=axis.get_xaxis_transform(), clip_on=False,
                  label="_no value", **_MARKS["no value (status)"])
        drawn.add("no value (status)")
    return drawn


def _statuses(status: xr.DataArray) -> str:
    """How many points have each status flag: ``"3 not converged, 2 infeasible"`` (a point
    out of validity counts once for its outcome and once for that)."""
    counts = {meaning: int(flag_holds(status, meaning).sum())
              for meaning in status.attrs["flag_meanings"].split()}
    return ", ".join(f"{n} {meaning.replace('_', ' ')}" for meaning, n in counts.items() if n)


def _outputs(data, declared: bool = False) -> list[str]:
    """The result's outputs at its points, in the file's order (a netCDF file's is the
    model's), or with ``declared`` in the order the model declares them (a zarr store lists
    its variables by name; this imports the model). Lives over a duty cycle are not at its
    points: each stands for all the cycle's."""
    found = [n for n, v in data.data_vars.items()
             if v.attrs.get("coverage_content_type") == "modelResult"
             and not n.endswith(CYCLE_SUFFIX)]
    try:
        order = [o.name for o in get_model(data.attrs.get("model", "")).outputs] \
            if declared else found
    except KeyError:  # a model not installed here: the file's order
        return found
    return sorted(found, key=lambda n: order.index(n) if n in order else len(order))


def _output(data, variable, outputs: list, axes: list, source: str) -> str:
    """The output to draw: ``variable``, or the default; a SpecError for a name that is no
    output, and for an output of a single point that is one value."""
    with_entries = [n for n in outputs if data[n].dims]
    if variable is None:
        if axes or not with_entries:
            variable = outputs[0]
        else:  # a single point: the first output that has something to draw along
            return with_entries[0]
    if variable not in outputs and variable in data.variables:
        raise SpecError(f"{source}: {variable!r} is {_kind(data, variable, axes)}, not an "
                        f"output (outputs: {', '.join(outputs)})")
    variable = _choose(variable, outputs, "output", source)
    if not data[variable].dims:
        value = data[variable]
        unit = value.attrs.get("units", "1")
        raise SpecError(
            f"{source}: a single point (the sweep has no axes): {variable} is one value, "
            f"{float(value):g}{'' if unit == '1' else ' ' + unit}, with nothing to draw it "
            "against" + (f"; outputs with entries of their own: {', '.join(with_entries)}"
                         if with_entries else ""))
    return variable


def _kind(data, name: str, axes: list) -> str:
    """What a variable of a result that is not an output is, in words."""
    if name == "status":
        return "the status of each point"
    if name in data.coords and set(data[name].dims) <= set(axes):
        return "a sweep axis (draw against it with --x)"
    if name in data.attrs.get("fixed_inputs", "").split():
        return "an input the sweep holds fixed"
    if name.endswith(CYCLE_SUFFIX):
        return ("one value over the duty cycle for all its cases (read it with xarray: "
                f"data[{name!r}])")
    return "not an output of the model"


def _choose_x(data, x, axes: list, own: list, variable: str, source: str) -> str:
    """The name along the figure's x axis: ``x``, or the default (see :func:`plot`)."""
    along_axes = [n for n, c in data.coords.items() if n not in data.dims and c.ndim == 1
                  and c.dims[0] in axes and c.dtype.kind in "fiu"]  # zipped, drawn inputs
    if x is None:
        drawn = [n for n in data.attrs.get("sample_inputs", "").split() if n in along_axes]
        longer = [d for d in axes if data.sizes[d] > 1]
        x = (drawn[0] if _SAMPLE in axes and drawn else
             longer[0] if longer else axes[0] if axes else own[0])
    if x in data.dims and x not in axes + own:
        raise SpecError(f"{source}: {variable} has no dimension {x!r} (its dimensions: "
                        f"{', '.join(data[variable].dims)})")
    return _choose(x, axes + own + along_axes, "axis", source)


def _positions(coordinate: xr.DataArray):
    """Where the values of ``coordinate`` go on the x axis, and tick labels for names."""
    if coordinate.dtype.kind in "OUS":
        return np.arange(coordinate.size), [str(v) for v in coordinate.values]
    return np.asarray(coordinate.values, dtype=float), None


def _shown(coordinate: xr.DataArray) -> xr.DataArray:
    """A coordinate in the unit its definition was written in."""
    written = coordinate.attrs.get("written_units")
    if written and coordinate.dtype.kind not in "OUS":  # also from SI (N/m^1.5, no units)
        return in_unit(coordinate, written)
    return coordinate


def _value_text(data, dim: str, index: int, named: bool = True) -> str:
    """``"clearance = 0.03 mm"``, or ``"0.03 mm"`` unless ``named``; for a zipped axis (its
    values numbered), the values of its inputs: ``"crown = 2 um, slices = 30"``."""
    inputs = [n for n, c in data.coords.items() if n != dim and c.dims == (dim,)]
    if dim == _SAMPLE or not inputs or data[dim].dtype.kind in "OUS":
        inputs, named = [dim], named
    else:
        named = True  # a zipped axis' number says nothing: its inputs are named
    texts = []
    for name in inputs:
        coordinate = _shown(data[name])
        value = coordinate.values[index]
        unit = coordinate.attrs.get("units", "1")
        shown = f"{value:g}" if isinstance(value, (float, np.floating)) else str(value)
        shown += "" if unit == "1" else f" {shown_unit(unit)}"
        texts.append(f"{name.replace('_', ' ')} = {shown}" if named else shown)
    return ", ".join(texts)


def _open(path) -> xr.Dataset:
    try:
        return open_result(path)
    except (OSError, ValueError) as error:
        raise SpecError(f"{path}: cannot be read as a result: "
                        f"{str(error).splitlines()[0] if str(error) else type(error).__name__}"
                        ) from None


def _choose(name: str, options: list, what: str, source: str) -> str:
    """``name`` if it is one of ``options``; else a :class:`SpecError` naming ``source``, the
    closest option and all of them."""
    if name not in options:
        raise SpecError(f"{source}: unknown {what} {name!r}" + suggestion(name, options)
                        + f" ({what} names: {', '.join(options)})")
    return name


def check_figure_path(output, result=None, formats=FORMATS, what="a figure",
                      mark=MAKER) -> Path:
    """Refuse a figure path that must not be written: the result itself, a folder or any
    other kind of file than a regular one, a suffix other than ``formats``', an existing file
    that is not ``what`` of that format carrying ``mark`` (:func:`ours`), a folder that does
    not exist, a path inside a zarr store or a parts folder
    (:func:`stores.paths.check_outside_results`)."""
    check_outside_results(output)
    output = Path(output)
    if result is not None and output.exists() and output.resolve() == Path(result).resolve():
        raise SpecError(f"{output}: is the result itself; choose another path for {what}")
    suffix = output.suffix.lower()
    if suffix not in formats:
        raise SpecError(f"{output}: {what} is written as {', '.join(formats)} (by its "
                        "suffix)")
    if output.is_symlink() or (output.exists() and not output.is_file()):
        raise SpecError(f"{output}: exists and is not a regular file; refusing to replace it")
    if output.exists() and not ours(output, formats, mark):
        kind = what.split(" ", 1)[1]
        raise SpecError(f"{output}: exists and is not {'an' if suffix[1] in 'aehs' else 'a'} "
                        f"{suffix[1:].upper()} {kind} written by bearing-sweep; refusing to "
                        "replace it (remove it or choose another path)")
    if not output.parent.is_dir():
        raise SpecError(f"{output}: its folder {output.parent} does not exist")
    return output


def ours(path: Path, formats=FORMATS, mark=MAKER) -> bool:
    """Whether the file at ``path`` was written by this program: of its format by its first
    bytes (``formats``), and carrying ``mark`` (a figure: :data:`plotting.MAKER` among its
    metadata, PNG's Software, PDF's and SVG's Creator, which no other program writes)."""
    suffix = path.suffix.lower()
    try:
        with open(path, "rb") as handle:
            content = handle.read(MOST_FIGURE_BYTES)
    except OSError:
        return False
    return content.startswith(formats.get(suffix, (b"\0",))) and mark.encode() in content


def _write(figure, output: Path):
    """Write ``figure`` to ``output`` atomically (a finished file replaces the old one)."""
    with OutputLock(output):  # a folder that takes no file says so, as for a run
        write_durably(output, lambda handle: figure.savefig(
            handle, format=output.suffix[1:].lower(), dpi=110,
            metadata=metadata(output.suffix)))
