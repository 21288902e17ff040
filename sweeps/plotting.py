"""Small helpers that the studies' figure scripts share: open a result, label, draw, save."""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402

from sweeps import units  # noqa: E402
from sweeps.store import open_result  # noqa: E402


def result(results: Path, name: str) -> xr.Dataset:
    """The dataset of the study's sweep ``name`` (its definition's file stem)."""
    return open_result(Path(results) / f"{name}.nc")


def label(variable: xr.DataArray) -> str:
    """Axis label: the variable's name and units."""
    return f"{variable.name.replace('_', ' ')} [{variable.attrs['units']}]"


def family(axis, x, y, over: str, label: str, plot: str = "plot", **settings):
    """One line of ``y`` against ``x`` for each value along the dimension ``over``."""
    style = {"where": "post"} if plot == "step" else {"marker": "o", "ms": 2}
    for value in y[over].values:
        getattr(axis, plot)(x, y.sel({over: value}), label=label.format(value), **style)
    axis.set(**settings)
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)


def save(figure, figures: Path, name: str):
    """Write ``figure`` as ``figures/name`` and free it."""
    figure.tight_layout()
    figure.savefig(Path(figures) / name, dpi=110)
    plt.close(figure)


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
        number, unit = units.split_quantity(value)
        stored = units.parse_unit(data[name].attrs.get("units", "1"))
        return float(units.convert(number, units.parse_unit(unit or "1"), stored))

    for name, value in where.items():
        converted = magnitude(name, value)
        if method or isinstance(converted, slice) or converted is value:
            data = data.sel({name: converted}, method=method)
        else:  # a converted number may differ from the stored one in its last digit
            scale = np.max(np.abs(converted)) if np.size(converted) else 0.0
            data = data.sel({name: converted}, method="nearest", tolerance=1e-9 * scale)
    return data
