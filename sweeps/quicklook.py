"""A quick look at any result: one output against one axis, without writing a figure script.

``plot(result)`` draws the first output against the first axis, a line per value of the next
axis and a panel per value of the one after (rows for a fourth); further axes are held at their
first value. Points whose status says the values do not hold are marked on the axis, points
solved outside the model's validity ringed. An output with its own entries (per roller, per
ball, along a rotation) is drawn as their distribution: the mean and the band from the least
to the largest entry. The inputs the sweep held fixed are the figure's conditions.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr
from matplotlib.lines import Line2D

from .dependence import flag_holds, held_points, on_grid
from .parts import write_durably
from .plotting import conditions, in_unit, label, plt
from .spec import SpecError, suggestion
from .store import open_result

#: Figure formats ``plot`` writes, with the first bytes of such a file: only a figure is ever
#: replaced by another one.
FORMATS = {".png": (b"\x89PNG",), ".pdf": (b"%PDF",), ".svg": (b"<?xml", b"<svg")}
#: What a point's mark code says: its values hold, hold but outside validity, or none.
_HOLDS, _OUTSIDE, _NO_VALUE = range(3)
#: Most lines in a panel, and most panels across or down; a longer axis is thinned.
MOST_LINES, MOST_PANELS = 8, 4
#: How the points whose status is not converged are marked.
_MARKS = {"out of validity": {"marker": "o", "ms": 9, "mfc": "none"},
          "no value (status)": {"marker": "x", "ms": 7}}


def plot(result, variable: str | None = None, *, x: str | None = None, output=None):
    """Draw one output of a sweep's result against one of its axes.

    Parameters
    ----------
    result : str, pathlib.Path or xarray.Dataset
        A netCDF file written by ``bearing-sweep run``, or such a dataset.
    variable : str, optional
        The output to draw (default: the model's first output).
    x : str, optional
        The axis along the figure's x axis: a sweep axis, or a dimension of the output's
        own (``angle``, ``roller``). Default: the first sweep axis.
    output : str or pathlib.Path, optional
        Write the figure there too (PNG, PDF or SVG, by its suffix).

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    bearing_sweep.spec.SpecError
        For an unknown variable or axis (with the closest name), or an output path that
        must not be written (see :func:`check_figure_path`).
    """
    data = result if isinstance(result, xr.Dataset) else _open(result)
    if "status" not in data or "flag_meanings" not in data["status"].attrs:
        raise SpecError(f"{result if not isinstance(result, xr.Dataset) else 'the dataset'}: "
                        "not a result of bearing-sweep run (it has no status variable)")
    data = on_grid(data)  # an output stored on fewer axes than the grid: at every point
    outputs = [n for n, v in data.data_vars.items()
               if v.attrs.get("coverage_content_type") == "modelResult"]
    axes = list(data["status"].dims)
    variable = _choose(variable or outputs[0], outputs, "output")
    values = data[variable]
    own = [d for d in values.dims if d not in axes]
    # Labelled entries of an output's own (dof: axial, radial_y, ...) are categories, to be
    # told apart like axes; numbered ones (roller 1..Z, an angle) form a distribution.
    categorical = [d for d in own if data[d].dtype.kind in "OUS"]
    distributed = [d for d in own if d not in categorical]
    x = _choose(x or axes[0], axes + own, "axis")
    if x in distributed:
        distributed.remove(x)
    if output is not None:
        output = check_figure_path(output, None if isinstance(result, xr.Dataset) else result)
    rest = [d for d in axes + categorical if d != x and data.sizes[d] > 1]
    lines, columns, rows = (rest + [None] * 3)[:3]
    held = rest[3:]
    thinned = []  # a legend of a hundred lines reads as none: a few values, evenly spaced
    for dim, most in ((lines, MOST_LINES), (columns, MOST_PANELS), (rows, MOST_PANELS)):
        if dim is not None and data.sizes[dim] > most:
            thinned.append(f"{dim.replace('_', ' ')}: {most} of {data.sizes[dim]} values")
            data = data.isel({dim: np.unique(np.linspace(0, data.sizes[dim] - 1, most)
                                             .round().astype(int))})
    # Axes of one value, and those beyond a panel grid, are held at their first value.
    first = {d: 0 for d in axes + categorical if d != x and (d in held or data.sizes[d] == 1)}
    values = data[variable].isel({d: 0 for d in first if d in data[variable].dims})
    status = _marks(data["status"]).isel({d: 0 for d in first if d in axes})
    shown = {d: _shown(data[d]) for d in (x, lines, columns, rows) if d is not None}

    nrows, ncols = (data.sizes[rows] if rows else 1), (data.sizes[columns] if columns else 1)
    # Panels of an output's entries (dof: a translation, a tilt) may differ in unit and scale.
    figure, grid = plt.subplots(nrows, ncols, squeeze=False, sharex=True,
                                sharey=not {columns, rows} & set(categorical),
                                figsize=(4.2 * ncols + 1.2, 3.2 * nrows + 1.0))
    for r in range(nrows):
        for c in range(ncols):
            axis = grid[r, c]
            where = {d: i for d, i in ((rows, r), (columns, c)) if d is not None}
            panel = values.isel(where)
            panel_status = status.isel({d: i for d, i in where.items() if d in status.dims})
            _draw_panel(axis, panel, panel_status, x, lines, distributed, shown)
            axis.set_title(", ".join(_value_text(shown[d], i) for d, i in where.items()),
                           fontsize=8)
            if r == nrows - 1:
                axis.set_xlabel(label(shown[x], long=True))
            if c == 0:
                axis.set_ylabel(label(values, long=True) + (
                    f"\nmean; band: least to largest over {', '.join(distributed)}"
                    if distributed else ""))
    # What the user chose (a preset, [fixed]) is the figure's condition; the model's defaults
    # are many (30 for cage_slip) and named once, in the file.
    fixed = [n for n in data.attrs.get("fixed_inputs", "").split()
             if n in data and data[n].attrs.get("origin") != "default"]
    held_text = ", ".join([_value_text(_shown(data[d]), 0) + " (first of "
                           f"{data.sizes[d]})" for d in held] + thinned)
    width = int(14 * figure.get_figwidth())  # characters of the title's font across the figure
    figure.suptitle("\n".join(t for t in (data.attrs.get("title", ""),
                                          conditions(data, *fixed, width=width), held_text)
                              if t), fontsize=8)
    figure.tight_layout()
    if output is not None:
        _write(figure, output)
    return figure


def _draw_panel(axis, values, status, x, lines, distributed, shown):
    """One panel: a line (or a distribution) per value of ``lines``, failures marked."""
    positions, ticks = _positions(shown[x])
    marked = set()
    style = {"marker": "o", "ms": 3} if len(positions) <= 40 else {}  # dots while they read
    for index in range(values.sizes[lines] if lines else 1):
        line = values.isel({lines: index}) if lines else values
        point_status = status.isel({lines: index}) if lines in status.dims else status
        name = _value_text(shown[lines], index, named=False) if lines else None
        if distributed:
            low, high = line.min(distributed), line.max(distributed)
            mean = line.mean(distributed)
            drawn, = axis.plot(positions, mean.transpose(x).values, label=name,
                               **style)
            axis.fill_between(positions, low.transpose(x).values, high.transpose(x).values,
                              color=drawn.get_color(), alpha=0.2, lw=0)
            line = mean
        else:
            drawn, = axis.plot(positions, line.transpose(x).values, label=name,
                               **style)
        marked |= _mark(axis, positions, line.transpose(x).values,
              np.broadcast_to(point_status.transpose(*[d for d in (x,) if d in
                                                       point_status.dims]).values,
                              np.shape(positions)), drawn.get_color())
    if ticks is not None:
        axis.set_xticks(positions, ticks, rotation=20, fontsize=7)
    handles = [line for line in axis.lines if not line.get_label().startswith("_")]
    handles += [Line2D([], [], ls="none", color="grey", **_MARKS[kind], label=kind)
                for kind in _MARKS if kind in marked]
    if handles:
        axis.legend(handles=handles, fontsize=7, title_fontsize=7,
                    title=label(shown[lines], long=True) if lines else None)
    axis.grid(alpha=0.3)


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


def _positions(coordinate: xr.DataArray):
    """Where the values of ``coordinate`` go on the x axis, and tick labels for names."""
    if coordinate.dtype.kind in "OUS":
        return np.arange(coordinate.size), [str(v) for v in coordinate.values]
    return np.asarray(coordinate.values, dtype=float), None


def _shown(coordinate: xr.DataArray) -> xr.DataArray:
    """A coordinate in the unit its definition was written in."""
    written = coordinate.attrs.get("written_units")
    if written and "units" in coordinate.attrs:
        return in_unit(coordinate, written)
    return coordinate


def _value_text(coordinate: xr.DataArray, index: int, named: bool = True) -> str:
    """``"clearance = 0.03 mm"``, or ``"0.03 mm"`` unless ``named``."""
    value = coordinate.values[index]
    unit = coordinate.attrs.get("units", "1")
    shown = f"{value:g}" if isinstance(value, (float, np.floating)) else str(value)
    shown += "" if unit == "1" else f" {unit}"
    return f"{coordinate.name.replace('_', ' ')} = {shown}" if named else shown


def _open(path) -> xr.Dataset:
    try:
        return open_result(path)
    except (OSError, ValueError) as error:
        raise SpecError(f"{path}: cannot be read as a result: "
                        f"{str(error).splitlines()[0] if str(error) else type(error).__name__}"
                        ) from None


def _choose(name: str, options: list, what: str) -> str:
    if name not in options:
        raise SpecError(f"unknown {what} {name!r}" + suggestion(name, options)
                        + f" ({what} names: {', '.join(options)})")
    return name


def check_figure_path(output, result=None) -> Path:
    """Refuse a figure path that must not be written: the result itself, a folder or any
    other kind of file than a regular one, a suffix other than ``FORMATS``', an existing file
    that is not a figure of that format, a folder that does not exist."""
    output = Path(output)
    if result is not None and output.exists() and output.resolve() == Path(result).resolve():
        raise SpecError(f"{output}: is the result itself; choose another figure path")
    suffix = output.suffix.lower()
    if suffix not in FORMATS:
        raise SpecError(f"{output}: a figure is written as {', '.join(FORMATS)} (by its "
                        "suffix)")
    if output.is_symlink() or (output.exists() and not output.is_file()):
        raise SpecError(f"{output}: exists and is not a regular file; refusing to replace it")
    if output.exists():
        with open(output, "rb") as handle:
            head = handle.read(8)
        if not head.startswith(FORMATS[suffix]):
            raise SpecError(f"{output}: exists and is not a {suffix[1:].upper()} figure; "
                            "refusing to replace it (remove it or choose another path)")
    if not output.parent.is_dir():
        raise SpecError(f"{output}: its folder {output.parent} does not exist")
    return output


def _write(figure, output: Path):
    """Write ``figure`` to ``output`` atomically (a finished file replaces the old one)."""
    write_durably(output, lambda handle: figure.savefig(
        handle, format=output.suffix[1:].lower(), dpi=110))
