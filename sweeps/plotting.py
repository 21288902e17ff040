"""Small helpers that the studies' figure scripts share: open a result, label, draw, save."""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import xarray as xr  # noqa: E402

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
