"""Small helpers that the studies' figure scripts share: open a result, label, draw, save.

Figures are drawn on :class:`matplotlib.figure.Figure` objects, never through pyplot: the
user's backend, pyplot's list of open figures and every other setting of matplotlib stay as
they were (a notebook goes on drawing its own figures).
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import xarray as xr
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import LogLocator, NullFormatter, StrMethodFormatter

from . import units
from .definition.tables import suggestion
from .definition.values import convert_written
from .spec import SpecError
from .stores import open_result


def result(results: Path, name: str) -> xr.Dataset:
    """The dataset of the study's sweep ``name`` (its definition's file stem)."""
    return open_result(Path(results) / f"{name}.nc")


#: How a figure writes the units whose UDUNITS names read as words.
_SHOWN_UNITS = {"percent": "%", "degree": "deg"}


def shown_unit(unit: str) -> str:
    """``unit`` as a figure writes it: ``"%"`` for ``"percent"``, ``"deg"`` for
    ``"degree"``, any other as it is."""
    return _SHOWN_UNITS.get(unit, unit)


#: How a file names, in a variable's ``comment``, the SI unit of values that have no
#: ``units`` attribute (a fractional power: labels.described writes it).
_SI_UNIT = re.compile(r"Units: (\S+) \(SI\)")


def stored_unit(variable: xr.DataArray) -> str:
    """The unit ``variable``'s values are in: its ``units``, or for one stored without them
    (N/m^1.5, which UDUNITS cannot write) the SI unit its ``comment`` names; "1" for labels,
    "SI" where neither says."""
    if "units" in variable.attrs:
        return variable.attrs["units"]
    named = _SI_UNIT.search(variable.attrs.get("comment", ""))
    return "1" if variable.dtype.kind in "OUS" else named.group(1) if named else "SI"


def label(variable: xr.DataArray, long: bool = False) -> str:
    """Axis label: the variable's name and units (:func:`stored_unit`); ``long``: its
    ``long_name`` instead of its name, no unit for a number."""
    unit = stored_unit(variable)
    if not long:
        return f"{variable.name.replace('_', ' ')} [{shown_unit(unit)}]"
    name = variable.attrs.get("long_name", variable.name.replace("_", " "))
    return name if unit == "1" else f"{name} [{shown_unit(unit)}]"


def _variable(data, name: str) -> xr.DataArray:
    """``data[name]``; a :class:`SpecError` naming what ``data`` holds where it has none."""
    if not isinstance(data, (xr.Dataset, xr.DataArray)):
        raise SpecError(f"expected a result (an xarray.Dataset), not {type(data).__name__}")
    held = data.variables if isinstance(data, xr.Dataset) else data.coords
    if not isinstance(name, str) or name not in held:
        raise SpecError(f"the result has no {name!r}" + suggestion(str(name), list(held))
                        + f" (its axes: {', '.join(map(str, data.dims))})")
    return data[name]


def family(axis, x, y, over: str, label: str, plot: str = "plot", **settings):
    """One line of ``y`` against ``x`` for each value along the dimension ``over``."""
    style = {"where": "post"} if plot == "step" else {"marker": "o", "ms": 2}
    for value in y[over].values:
        getattr(axis, plot)(x, y.sel({over: value}), label=label.format(value), **style)
    axis.set(**settings)
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)


def ring(axis, x, y, where, label=None):
    """Ring the points of the line ``y`` against ``x`` where ``where`` holds (values kept but
    not vouched for: a status outside validity, or a life beyond its standard); ``label``
    names the rings in the legend."""
    flagged = np.asarray(where, dtype=bool).ravel()
    if flagged.any():
        axis.plot(np.asarray(x).ravel()[flagged], np.asarray(y).ravel()[flagged], "o",
                  mfc="none", mec="k", ms=6, mew=0.8, ls="none", label=label)


#: Resolution of the saved figures [dots per inch].
DPI = 110


def subplots(nrows: int = 1, ncols: int = 1, *, figsize=None, **settings):
    """A new figure and its axes, as ``matplotlib.pyplot.subplots`` gives them (``settings``:
    ``sharex``, ``squeeze``, ``subplot_kw``, ``gridspec_kw``, ...), but outside pyplot: no
    backend is chosen or changed, and the figure is freed with its last reference. Its canvas
    draws at the saved resolution, so laying it out, saving it and checking it
    (``figure_checks``) measure each text once."""
    figure = Figure(figsize=figsize, dpi=DPI)
    FigureCanvasAgg(figure)
    return figure, figure.subplots(nrows, ncols, **settings)


#: Who wrote a figure, in its metadata: a figure is replaced only by one of ours.
MAKER = "bearing-sweep"


def plain_log_ticks(*scales):
    """Ticks at 1, 2, 5, 10, ... on the logarithmic axes ``scales`` (``axis.xaxis``, ...),
    written as plain numbers rather than powers of ten."""
    for scale in scales:
        scale.set_major_locator(LogLocator(subs=(1, 2, 5)))
        scale.set_major_formatter(StrMethodFormatter("{x:g}"))
        scale.set_minor_formatter(NullFormatter())


def metadata(suffix: str) -> dict:
    """The metadata a figure of that suffix carries: this program as its maker."""
    return {"Software" if suffix.lower() == ".png" else "Creator": MAKER}


def save(figure, figures: Path, name: str, tight: bool = True):
    """Write ``figure`` as ``figures/name``, laid out tight unless ``tight`` is false (polar
    axes, whose labels tight_layout does not see)."""
    if tight:
        figure.tight_layout()
    figure.savefig(Path(figures) / name, dpi=DPI, metadata=metadata(Path(name).suffix or ".png"))


def at(data, method=None, **where):
    """``data.sel`` by quantities: ``at(data, radial_load="800 N", speed="12000 rpm")``.

    Each value is a quantity string, a list of them or a ``slice`` of them, converted to the
    unit the coordinate is stored in, so a figure does not depend on the units a definition
    was written in. Labels and dimensionless numbers pass unchanged. ``method`` is
    ``xarray.Dataset.sel``'s (``"nearest"``).
    """

    def magnitude(name, value):
        if isinstance(value, slice):
            return slice(magnitude(name, value.start), magnitude(name, value.stop))
        if isinstance(value, (list, tuple)):
            return [magnitude(name, v) for v in value]
        if not isinstance(value, str) or data[name].dtype.kind in "OUS":
            return value
        unit = stored_unit(data[name])
        try:
            number, written = units.split_quantity(value)
            return float(convert_written(number, written or "1", "1" if unit == "SI" else unit))
        except units.UnitError as error:
            raise SpecError(f"{name} = {value!r}: {error}") from None
        except units.pint.errors.DimensionalityError:
            raise SpecError(f"{name} = {value!r}: its units do not fit {name}, which is in "
                            f"{shown_unit(unit)}") from None

    for name, value in where.items():
        _variable(data, name)
        converted = magnitude(name, value)
        try:
            if method or isinstance(converted, slice) or converted is value:
                data = data.sel({name: converted}, method=method)
            else:  # a converted number may differ from the stored one in its last digit
                scale = np.max(np.abs(converted)) if np.size(converted) else 0.0
                data = data.sel({name: converted}, method="nearest", tolerance=1e-9 * scale)
        except KeyError:
            shown = np.atleast_1d(data[name].values)
            raise SpecError(f"{name} = {value!r}: no such value of {name} (it holds "
                            f"{', '.join(map(str, shown[:8]))}{' ...' if len(shown) > 8 else ''}"
                            f" {shown_unit(stored_unit(data[name]))})") from None
    return data


def in_unit(variable: xr.DataArray, unit: str) -> xr.DataArray:
    """``variable``'s values in ``unit``, whatever unit the file stores them in.

    Its ``units`` attribute becomes ``unit``, so ``label`` shows it; a dimension coordinate is
    converted with its index, so ``data.assign_coords(radial_load=in_unit(data.radial_load,
    "kN"))`` draws and selects in kN. A variable without ``units`` holds SI values (UDUNITS has
    no form for fractional powers such as N/m^1.5: the file says so in ``comment``).
    """
    stored = stored_unit(variable)
    if stored == "SI":
        values = units.from_si(variable.values, unit)
    else:
        values = convert_written(variable.values, stored, unit)
    converted = variable.copy(data=values)
    converted.attrs["units"] = unit
    if variable.name in variable.dims:
        converted = converted.assign_coords({variable.name: converted.variable})
    return converted


def conditions(data: xr.Dataset, *names: str, width: int | None = 80, preset: bool = True,
               **shown_in: str) -> str:
    """The preset (unless ``preset`` is false) and the inputs ``names`` a result holds fixed,
    as read from the file: ``"paper000-D: speed = 5000 rpm, crown = 0.004 mm"``, wrapped
    between inputs at ``width`` characters (None: one line).

    Each value is shown in the unit ``shown_in`` names for it (``radial_load="kN"``), else in
    the unit its definition was written in, else in its stored unit. An input that varies
    over a pattern is shown as its range.
    """
    parts = []
    for name in names:
        variable = _variable(data, name)
        unit = shown_in.get(name, variable.attrs.get("written_units", stored_unit(variable)))
        if variable.dtype.kind in "OUS":
            parts.append(f"{name.replace('_', ' ')} = {variable.values}")
            continue
        if unit != "1":
            variable = in_unit(variable, unit)
        low, high = float(variable.min()), float(variable.max())
        shown = f"{low:g}" if low == high else f"{low:g} to {high:g}"
        parts.append(f"{name.replace('_', ' ')} = {shown}"
                     + ("" if unit == "1" else " " + shown_unit(unit)))
    bearing = data.attrs.get("bearing") if preset else None
    if bearing:
        parts = [f"{bearing}:" + (f" {parts[0]}" if parts else ""), *parts[1:]]
    lines = [""]
    for part in parts:  # wrapped between inputs, never inside one
        if lines[-1] and width and len(lines[-1]) + len(part) + 2 > width:
            lines[-1] += ","
            lines.append(part)
        else:
            lines[-1] += (", " if lines[-1] else "") + part
    return "\n".join(lines)


def sobol_bars(axis, analysis: xr.Dataset, output: str, **where):
    """First-order and total Sobol' indices of ``output`` (a result of ``analyze``), a pair
    of bars per sampled input with their confidence intervals as error bars; ``where``
    selects a point of the result's other axes (``speed="5000 rpm"``, as :func:`at`)."""
    if "first_order" not in getattr(analysis, "variables", ()):
        raise SpecError("sobol_bars draws the result of analyze on a Saltelli design (it has "
                        "first_order and total_order); this has no first_order")
    if output not in analysis["output"].values:
        raise SpecError(f"no Sobol indices of {output!r}" + suggestion(
            str(output), [str(o) for o in analysis["output"].values]))
    one = at(analysis, **where).sel(output=output)
    inputs = list(one.input.values)
    place = np.arange(len(inputs))
    for shift, name, text in ((-0.2, "first_order", "first order"),
                              (0.2, "total_order", "total")):
        values = one[name].transpose("input").values
        low, high = one[f"{name}_interval"].transpose("bound", "input").values
        axis.bar(place + shift, values, width=0.4, label=text,
                 yerr=[values - low, high - values], capsize=3)
    axis.set_xticks(place, [n.replace("_", " ") for n in inputs])
    axis.set(xlabel="sampled input", ylabel=f"Sobol index of {output.replace('_', ' ')}")
    axis.axhline(0.0, color="k", lw=0.5)
    axis.legend(fontsize=7)


def histogram(axis, data: xr.Dataset, name: str, bins=30, style: dict | None = None,
              **where):
    """The distribution of ``name`` (an output or a sampled input) over the samples of a
    sampled result, at the point of its other axes that ``where`` selects (as :func:`at`);
    a Saltelli design's repeated AB blocks are left out. ``bins``: a count or the edges (the
    same edges for histograms drawn over each other); ``style``: settings of ``axis.hist``
    (``label``, ``alpha``, ``color``)."""
    _variable(data, name)
    values = at(data, **where)[name]
    if "saltelli_block" in values.coords:
        values = values.where(values.saltelli_block < 2, drop=True)
    axis.hist(values.values.ravel()[np.isfinite(values.values.ravel())], bins=bins,
              **(style or {}))
    axis.set(xlabel=label(values, long=True), ylabel="samples")
