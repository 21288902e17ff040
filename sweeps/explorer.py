"""An interactive page of a result: move through its axes and watch an output change.

``explore(result)`` writes one self-contained HTML page (bokeh, its JavaScript inline: it opens
without a network) beside the result: a choice of output and of the axis along x, a slider per
other sweep axis, the chosen output drawn against the chosen axis in the units the definition
was written in, points outside the model's validity ringed and the statuses of the points drawn
counted under the figure (a point without a value leaves a gap). A sampled result is drawn a
point per sample against a drawn input. The values drawn are the file's: the page holds each
point's value of the outputs it offers and slices them in the browser.

bokeh is an optional extra (``pip install 'bearing-sweep[explore]'``).
"""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import xarray as xr

from .dependence import on_grid
from .plotting import MAKER, label
from .quicklook import (_NO_VALUE, _OUTSIDE, _SAMPLE, _choose, _marks, _open, _outputs,
                        _shown, _value_text, check_figure_path)
from .definition.tables import MissingExtra
from .spec import SpecError
from .stores import is_result
from .stores.durable import OutputLock, write_durably
from .stores.paths import argument_text, is_zarr, path_argument

#: The most values (points times outputs) a page holds: some 8 bytes each in the page, which
#: a browser holds in memory as well.
MOST_VALUES = 5_000_000
#: What a page of this program begins with and carries, so that only such a page is replaced.
PAGE_FORMAT = {".html": (b"<!DOCTYPE html>",)}

#: What marks a page as this program's: no other page names it its generator.
GENERATOR = f'<meta name="generator" content="{MAKER} explore">'
#: The page's script: slice the chosen output along the chosen axis at the sliders' indices.
_DRAW = """
const out = output.value, name = along.value, dim = meta.dim_of[name];
const values = every.data[out], marks = every.data["__mark"];
const index = {};
for (const d of meta.dims) index[d] = sliders[d] ? sliders[d].value : 0;
const x = [], y = [], rx = [], ry = [];
let holds = 0, outside = 0, none = 0;
for (let i = 0; i < meta.sizes[dim]; i++) {
  index[dim] = i;
  let flat = 0;
  for (const d of meta.dims) flat += index[d] * meta.strides[d];
  const at = meta.coords[name][i], value = values[flat], mark = marks[flat];
  x.push(at); y.push(mark == meta.no_value ? NaN : value);
  if (mark == meta.outside) { rx.push(at); ry.push(value); outside++; }
  else if (mark == meta.no_value) { none++; } else { holds++; }
}
drawn.data = {x: x, y: y};
ringed.data = {x: rx, y: ry};
line.visible = dim != meta.sample;
for (const d of meta.dims) {
  if (!sliders[d]) continue;
  sliders[d].visible = d != dim;
  sliders[d].title = meta.texts[d][sliders[d].value];
}
xaxis.axis_label = meta.labels[name];
yaxis.axis_label = meta.labels[out];
status.text = `${x.length} points drawn: ${holds} converged within validity, ` +
  `${outside} out of validity (ringed), ${none} without a value (gaps)`;
"""


def explore(result: str | os.PathLike, variables: list[str] | None = None, *,
            output: str | os.PathLike | None = None) -> Path:
    """Write an interactive page of a result, to open in a browser.

    Parameters
    ----------
    result : str or pathlib.Path
        A netCDF file (or zarr store) written by ``bearing-sweep run``.
    variables : list of str, optional
        The outputs the page offers (default: every output with one value per point, as many
        as :data:`MOST_VALUES` allows at the result's size).
    output : str or pathlib.Path, optional
        Where the page goes (default: the result's path with ``.html``); only a page this
        program wrote is ever replaced.

    Returns
    -------
    pathlib.Path
        The page written.

    Raises
    ------
    bearing_sweep.spec.SpecError
        A path that is no result, an unknown output (with the closest name), an output with
        entries of its own (per roller: ``bearing-sweep plot`` draws those), a result of a
        single point, more values than a page holds, or a page path that must not be written.
    bearing_sweep.definition.tables.MissingExtra
        bokeh is not installed (a RuntimeError).
    """
    import importlib.util

    if importlib.util.find_spec("bokeh") is None:
        raise MissingExtra("the interactive page needs bokeh, an optional extra: "
                           "pip install 'bearing-sweep[explore]'")
    result = path_argument(result, "result", "a result:", optional=False)
    output = path_argument(output, "output")
    if variables is not None and (isinstance(variables, str) or not all(
            isinstance(v, str) for v in variables)):
        raise SpecError(f"variables={argument_text(variables)}: expected a list of outputs' "
                        "names")
    if not is_result(result):
        raise SpecError(f"{result}: no such result file")
    output = Path(output) if output is not None else Path(result).with_suffix(".html")
    output = check_figure_path(output, result, PAGE_FORMAT, "an interactive page", GENERATOR)
    data = _open(result)
    try:
        page = _page(_document(on_grid(data), variables, str(result),
                               declared=is_zarr(result)))
    finally:
        data.close()
    with OutputLock(output):
        write_durably(output, lambda handle: handle.write(page.encode()))
    return output


def _page(document) -> str:
    """The self-contained HTML page of a bokeh ``document``, marked as this program's."""
    from bokeh.embed import file_html
    from bokeh.resources import INLINE

    title = document.roots[0].select_one({"name": "figure"}).title.text
    page = file_html(document, resources=INLINE, title=f"{title} - bearing-sweep explore")
    return page.replace("<head>", f"<head>\n    {GENERATOR}", 1)


def _document(data: xr.Dataset, variables, source: str, declared: bool = False):
    """The page's bokeh document: its widgets, figure, data and script; ``declared``: the
    outputs in the model's order rather than the file's (a zarr store's is by name)."""
    from bokeh.document import Document
    from bokeh.layouts import column, row
    from bokeh.models import ColumnDataSource, CustomJS, Div, Select, Slider
    from bokeh.plotting import figure as new_figure

    if "status" not in data or "flag_meanings" not in data["status"].attrs:
        raise SpecError(f"{source}: not a result of bearing-sweep run (it has no status "
                        "variable)")
    dims = list(data["status"].dims)
    if not dims:
        raise SpecError(f"{source}: a single point (the sweep has no axes): nothing to move "
                        "through; `bearing-sweep plot` draws its outputs' entries")
    offered = _offered(data, variables, dims, source, declared)
    sizes = {d: data.sizes[d] for d in dims}
    along = _along(data, dims)
    if not along:
        raise SpecError(f"{source}: no axis of more than one value to draw along")
    strides = {d: int(np.prod([sizes[e] for e in dims[i + 1:]], dtype=np.int64))
               for i, d in enumerate(dims)}
    shown = {name: _shown(data[name]) for name in along}
    meta = {
        "dims": dims, "sizes": sizes, "strides": strides, "dim_of": along,
        "coords": {name: shown[name].values.astype(float).tolist() for name in along},
        "labels": {**{name: label(shown[name]) for name in along},
                   **{name: label(data[name], long=True) for name in offered}},
        "texts": {d: [_value_text(data, d, i) for i in range(sizes[d])] for d in dims},
        "outside": _OUTSIDE, "no_value": _NO_VALUE, "sample": _SAMPLE,
    }
    marks = _marks(data["status"]).transpose(*dims)
    every = ColumnDataSource({name: data[name].transpose(*dims).values.astype(float).ravel()
                              for name in offered}
                             | {"__mark": marks.values.astype(np.int8).ravel()}, name="every")
    drawn_inputs = [n for n in data.attrs.get("sample_inputs", "").split() if n in along]
    x_name = drawn_inputs[0] if _SAMPLE in dims and drawn_inputs else next(iter(along))
    # The first drawing, as the page's script draws it: the first output along x, every
    # other axis at its first value (the figure's ranges are set from it).
    at = {d: 0 for d in dims if d != along[x_name]}
    first_x = np.asarray(meta["coords"][x_name])
    first_marks = marks.isel(at).values
    first_y = data[offered[0]].isel(at).values.astype(float)
    outside = first_marks == _OUTSIDE
    drawn = ColumnDataSource({"x": first_x, "y": np.where(first_marks == _NO_VALUE, np.nan,
                                                          first_y)}, name="drawn")
    ringed = ColumnDataSource({"x": first_x[outside], "y": first_y[outside]}, name="ringed")
    title = data.attrs.get("title") or f"{data.attrs.get('model', 'result')}: {Path(source).name}"
    plot = new_figure(width=760, height=460, title=title, name="figure",
                      tools="pan,wheel_zoom,box_zoom,reset,save,hover",
                      tooltips=[("x", "@x{0.[0000]}"), ("y", "@y{0.[0000]}")])
    line = plot.line("x", "y", source=drawn, line_width=2, name="line")
    plot.scatter("x", "y", source=drawn, size=5)
    plot.scatter("x", "y", source=ringed, size=12, fill_alpha=0, line_color="firebrick",
                 line_width=2, legend_label="out of validity")
    plot.legend.location = "top_left"
    output_select = Select(title="output", value=offered[0], name="output",
                           options=[(n, meta["labels"][n]) for n in offered])
    along_select = Select(title="along x", value=x_name, name="along",
                          options=[(n, meta["labels"][n]) for n in along])
    sliders = {d: Slider(start=0, end=max(sizes[d] - 1, 1), value=0, step=1, show_value=False,
                         title=meta["texts"][d][0], name=f"slider-{d}", disabled=sizes[d] == 1,
                         width=360)
               for d in dims}
    status = Div(name="status")
    draw = CustomJS(args=dict(every=every, drawn=drawn, ringed=ringed,
                              output=output_select, along=along_select, sliders=sliders,
                              xaxis=plot.xaxis[0], yaxis=plot.yaxis[0], line=line,
                              status=status, meta=meta), code=_DRAW)
    for widget in (output_select, along_select):
        widget.js_on_change("value", draw)
    for slider in sliders.values():
        slider.js_on_change("value", draw)
    layout = row(column(output_select, along_select, *sliders.values(), width=380),
                 column(plot, status))
    document = Document()
    document.add_root(layout)
    document.js_on_event("document_ready", draw)
    return document


def _along(data: xr.Dataset, dims: list) -> dict:
    """What the x axis can run along, each with the dimension it lies on: the sweep axes of
    more than one value, the inputs of a zipped axis (not its numbering) and the drawn
    inputs of a sampled result (not the samples' numbers)."""
    found = {}
    drawn = data.attrs.get("sample_inputs", "").split()
    for name, coordinate in data.coords.items():
        if coordinate.ndim != 1 or coordinate.dims[0] not in dims \
                or coordinate.dtype.kind not in "fiu" or data.sizes[coordinate.dims[0]] < 2:
            continue
        dim = coordinate.dims[0]
        inputs = [n for n, c in data.coords.items() if n != dim and c.dims == (dim,)]
        if (name == dim and inputs) or (dim == _SAMPLE and name not in drawn):
            continue  # a zipped axis' numbering; a design's own numbers (blocks, replicates)
        found[name] = dim
    return found


def _offered(data: xr.Dataset, variables, dims: list, source: str,
             declared: bool = False) -> list[str]:
    """The outputs the page offers: ``variables`` or every output with one value per point,
    within :data:`MOST_VALUES`, in the file's order (``declared``: the model's)."""
    outputs = _outputs(data, declared=declared)
    points = int(np.prod([data.sizes[d] for d in dims], dtype=np.int64))
    per_point = [n for n in outputs if set(data[n].dims) <= set(dims)]
    if variables is None:
        offered = per_point[:max(1, MOST_VALUES // max(points, 1))]
    else:
        offered = []
        for name in variables:
            name = _choose(name, outputs, "output", source)
            if name not in per_point:
                raise SpecError(f"{source}: {name} has entries of its own "
                                f"({', '.join(d for d in data[name].dims if d not in dims)}): "
                                "`bearing-sweep plot` draws their distribution")
            offered.append(name)
    if not offered:
        raise SpecError(f"{source}: no output with one value per point to explore")
    if points * len(offered) > MOST_VALUES:
        raise SpecError(f"{source}: {len(offered)} output{'s' * (len(offered) != 1)} of "
                        f"{points} points are more values than a page holds ({MOST_VALUES}): "
                        "name fewer outputs")
    return offered
