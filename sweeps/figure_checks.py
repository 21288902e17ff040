"""What a reader of a figure would stumble on, found from the drawn figure itself: for the
tests of the studies' figure scripts and of the quick look (and a new study's own)::

    from bearing_sweep.figure_checks import figure_problems

    assert figure_problems(figure) == []

Checked: every panel shows something (data, or a text saying why not; a map of one colour
is blank); every panel's axes are labelled (or share a labelled axis); a label naming a
dimensional quantity carries its unit in brackets, a real one (not ``[SI]``, ``[1]``); no
text holds an internal name (a snake_case identifier, outside mathtext); no legend lies over
data; no two tick labels overlap; no text runs off the figure.
"""
from __future__ import annotations

import re

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection, PathCollection, QuadMesh
from matplotlib.image import AxesImage
from matplotlib.patches import Rectangle

#: Words of a label that name a quantity with a unit: such a label carries its unit.
DIMENSIONAL = ("load", "force", "stiffness", "displacement", "pressure", "clearance", "speed",
               "time", "temperature", "runout", "diameter", "radius", "length", "life",
               "slip", "crown", "approach", "skew", "tilt", "gap", "angle", "amplitude",
               "semi-major", "semi-minor", "centre x", "centre y", "viscosity")
#: Words of a label that make it a number without a unit (a ratio of two quantities, an
#: index, a count).
DIMENSIONLESS = ("/", "ratio", "factor", "index", "relative", "share", "fraction", "number",
                 "count", "coupling")
#: Units a label must not show: they tell the reader nothing.
MEANINGLESS_UNITS = ("[SI]", "[1]", "[]")
#: An identifier of the code (``radial_load``, ``crown_0``); a symbol of one letter with its
#: index (``u_m``, a paper's notation) is not one.
_INTERNAL = re.compile(r"\b[A-Za-z][A-Za-z0-9]+_[A-Za-z0-9_]+\b")
_MATH = re.compile(r"\$[^$]*\$")
_TOLERANCE = 2.0  # display pixels a text may touch the edge or another by


def figure_problems(figure, names: bool = True) -> list[str]:
    """What a reader of ``figure`` (a :class:`matplotlib.figure.Figure`, laid out as it is
    saved) would stumble on, each in words; empty when nothing. ``names``: check texts for
    internal names too (a quick look shows the labels a user wrote, whatever they are)."""
    if not isinstance(figure.canvas, FigureCanvasAgg):  # one of plotting.subplots has one
        FigureCanvasAgg(figure)
    figure.draw_without_rendering()  # lays the texts out: their sizes and places
    problems = []
    for index, axis in enumerate(figure.axes):
        where = f"panel {index + 1} ({axis.get_title() or axis.get_ylabel() or 'untitled'})"
        if hasattr(axis, "_colorbar"):
            problems += [f"{where}: {p}" for p in _unit_problems(axis.get_ylabel())
                         + _unit_problems(axis.get_xlabel())]
            problems += [f"{where}: {p}" for p in _tick_overlaps(axis)]
            continue
        if not axis.get_visible():
            continue
        if not _shows_something(axis):
            problems.append(f"{where}: a blank panel (no data and no text saying why)")
            continue
        if _has_data(axis) or any(_has_data(twin) for twin in _twins(axis)):
            problems += [f"{where}: {p}" for p in _label_problems(axis)]
        problems += [f"{where}: {p}" for p in _tick_overlaps(axis)]
        legend = axis.get_legend()
        if legend is not None and _covers_data(legend, [axis, *_twins(axis)]):
            problems.append(f"{where}: the legend lies over data")
    for legend in figure.legends:
        if _covers_data(legend, figure.axes):
            problems.append("a figure legend lies over data")
    problems += _cut_off(figure)
    if names:
        problems += [f"an internal name in {text!r}" for text in _texts(figure)
                     if _INTERNAL.search(_MATH.sub("", text))]
    return problems


def _has_data(axis) -> bool:
    """Whether ``axis`` draws data: a line or points with a finite value, bars, a map of
    more than one colour."""
    for line in axis.lines:
        if line.get_transform() == axis.transData and np.isfinite(
                np.asarray(line.get_ydata(), dtype=float)).any():
            return True
    for collection in axis.collections:
        if isinstance(collection, QuadMesh):
            values = np.ma.masked_invalid(np.ma.asarray(collection.get_array(), dtype=float))
            if values.count() and values.max() > values.min():
                return True
        elif isinstance(collection, (PathCollection, LineCollection)):
            if len(collection.get_offsets()) or len(collection.get_paths()):
                return True
    if any(_is_bar(p, axis) for p in axis.patches):
        return True
    return any(isinstance(image, AxesImage) for image in axis.images)


def _is_bar(patch, axis) -> bool:
    """Whether ``patch`` is a bar of data (a bar, a histogram's bin), not a band across the
    panel (``axvspan``)."""
    return (isinstance(patch, Rectangle) and patch.get_data_transform() == axis.transData
            and patch.get_height() != 0)


def _shows_something(axis) -> bool:
    return _has_data(axis) or any(_has_data(twin) for twin in _twins(axis)) \
        or any(t.get_text().strip() for t in axis.texts)


def _twins(axis) -> list:
    """The axes drawn over ``axis`` in the same place (``twinx``)."""
    return [other for other in axis.figure.axes if other is not axis
            and other.get_position().bounds == axis.get_position().bounds]


def _label_problems(axis) -> list[str]:
    problems = []
    if axis.name == "polar":
        return problems
    for name, shared in (("x", axis.get_shared_x_axes()), ("y", axis.get_shared_y_axes())):
        labels = [getattr(a, f"get_{name}label")() for a in shared.get_siblings(axis)]
        if name == "y":
            labels += [twin.get_ylabel() for twin in _twins(axis)]
        if not any(text.strip() for text in labels):
            problems.append(f"its {name} axis has no label")
        own = getattr(axis, f"get_{name}label")()
        if not _named_ticks(getattr(axis, f"{name}axis")):  # a choice has no unit
            problems += _unit_problems(own)
    for twin in _twins(axis):
        problems += _unit_problems(twin.get_ylabel())
    return problems


def _named_ticks(scale) -> bool:
    """Whether the ticks of ``scale`` are names (geometry: jones, fixed_angle), not numbers."""
    return any(re.search(r"[A-Za-z]", _MATH.sub("", t.get_text())) for t in _tick_labels(scale))


def _unit_problems(label: str) -> list[str]:
    """A label naming a dimensional quantity without its unit, or with a meaningless one."""
    text = _MATH.sub("", label).lower()
    if any(unit.lower() in text for unit in MEANINGLESS_UNITS):
        return [f"the label {label!r} shows no real unit"]
    named = any(re.search(rf"\b{re.escape(word)}s?\b", text) for word in DIMENSIONAL)
    if named and "[" not in text and not any(word in text for word in DIMENSIONLESS):
        return [f"the label {label!r} names a quantity without its unit"]
    return []


def _data_points(axis) -> np.ndarray:
    """Display coordinates of the data of ``axis``: line points (and points between them),
    scatter points, the corners and middles of bars."""
    points = [np.empty((0, 2))]
    for line in axis.lines:
        if line.get_transform() != axis.transData or not line.get_visible():
            continue
        xy = np.column_stack([np.asarray(line.get_xdata(), dtype=float),
                              np.asarray(line.get_ydata(), dtype=float)])
        xy = xy[np.isfinite(xy).all(axis=1)]
        if len(xy) > 1 and line.get_linestyle() not in ("None", "", " "):
            steps = np.linspace(0, 1, 12)[:, None, None]  # along each segment too
            xy = (xy[:-1] + steps * (xy[1:] - xy[:-1])).reshape(-1, 2)
        if len(xy):
            points.append(axis.transData.transform(xy))
    for collection in axis.collections:
        if isinstance(collection, PathCollection) and len(collection.get_offsets()):
            offsets = np.asarray(collection.get_offsets(), dtype=float)
            points.append(collection.get_offset_transform().transform(offsets))
    for patch in axis.patches:
        if _is_bar(patch, axis):
            box = patch.get_window_extent()
            points.append(np.array([[box.x0, box.y1], [box.x1, box.y1],
                                    [(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2]]))
    return np.concatenate(points)


def _covers_data(legend, axes) -> bool:
    box = legend.get_window_extent()
    for axis in axes:
        points = _data_points(axis)
        inside = ((points[:, 0] > box.x0) & (points[:, 0] < box.x1)
                  & (points[:, 1] > box.y0) & (points[:, 1] < box.y1))
        if inside.any():
            return True
    return False


def _tick_labels(scale) -> list:
    """The tick labels drawn on ``scale`` (an x or y axis): those of ticks in its view."""
    low, high = sorted(scale.get_view_interval())
    margin = 1e-9 * max(abs(low), abs(high), 1.0)
    return [label for location, label in zip(scale.get_ticklocs(), scale.get_ticklabels())
            if low - margin <= location <= high + margin and label.get_visible()
            and label.get_text().strip()]


def _tick_overlaps(axis) -> list[str]:
    problems = []
    for name, scale in (("x", axis.xaxis), ("y", axis.yaxis)):
        boxes = [t.get_window_extent() for t in _tick_labels(scale)]
        for first, second in zip(boxes, boxes[1:]):
            if (min(first.x1, second.x1) - max(first.x0, second.x0) > _TOLERANCE
                    and min(first.y1, second.y1) - max(first.y0, second.y0) > _TOLERANCE):
                problems.append(f"its {name} tick labels overlap")
                break
    return problems


def _visible_texts(figure):
    """Every text of ``figure`` a reader sees."""
    texts = [figure._suptitle, *figure.texts]
    for legend in figure.legends:
        texts += [*legend.get_texts(), legend.get_title()]
    for axis in figure.axes:
        if not axis.get_visible():
            continue
        texts += [axis.title, axis._left_title, axis._right_title, axis.xaxis.label,
                  axis.yaxis.label, *axis.texts, *_tick_labels(axis.xaxis),
                  *_tick_labels(axis.yaxis)]
        legend = axis.get_legend()
        if legend is not None:
            texts += [*legend.get_texts(), legend.get_title()]
    return [t for t in texts if t is not None and t.get_visible() and t.get_text().strip()]


def _texts(figure) -> list[str]:
    return [t.get_text() for t in _visible_texts(figure)]


def _cut_off(figure) -> list[str]:
    """Texts that run off the figure's edges."""
    edge = figure.bbox
    return [f"the text {t.get_text()!r} runs off the figure" for t in _visible_texts(figure)
            if (box := t.get_window_extent()).x0 < edge.x0 - _TOLERANCE
            or box.x1 > edge.x1 + _TOLERANCE or box.y0 < edge.y0 - _TOLERANCE
            or box.y1 > edge.y1 + _TOLERANCE]
