"""Paper 001's trend figures (Figs. 6-9), the cross terms it drops and the geometry it fixes,
from the netCDF results only."""
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from sweeps import units
from sweeps.plotting import label, result, save

FIGURES = {
    "fig06_07_axial.png": "Figs. 6-7: 71807AC, axial displacement and axial stiffness against "
                          "axial load; the paper's K in Jones' and in the fixed-angle geometry, "
                          "and the Hertz K for fi = 0.52, fo = 0.53.",
    "fig08_09_radial.png": "Figs. 8-9: radial displacement and radial stiffness dFy/d(delta_y) "
                           "against radial load at 2800 N axial preload: tilts held (Jones, "
                           "fixed angle) and ring free to tilt (Jones).",
    "cross_terms.png": "Beyond the paper: the cross terms eq. 10 drops, as couplings "
                       "K_ij / sqrt(K_ii K_jj), against radial load at 2800 N axial preload.",
    "geometry.png": "Beyond the paper: how much the fixed-angle geometry (eq. 2-7 as printed) "
                    "over- or underestimates stiffness, and the contact angles that Jones' "
                    "geometry lets follow the load.",
    "contact_constant.png": "Beyond the paper: the contact constant Hertz theory gives against "
                            "the unstated groove curvature ratios; dotted: the paper's K.",
}

_FORMS = {"jones": "Jones, tilts held", "fixed_angle": "fixed angle (paper), tilts held",
          "jones_free_tilt": "Jones, free to tilt"}
_PAIRS = (("axial", "radial_y"), ("radial_y", "tilt_z"), ("radial_z", "tilt_y"),
          ("axial", "tilt_z"))


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _axial(results, figures)
    _radial(results, figures)
    _cross_terms(results, figures)
    _geometry(results, figures)
    _contact_constant(results, figures)


def _axial(results, figures):
    data, hertz = result(results, "fig06_07_axial"), result(results, "fig06_07_axial_hertz")
    figure, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for axis, name in zip(axes, ("axial_displacement", "axial_stiffness")):
        for form in data.form.values:
            axis.plot(data.axial_load, data[name].sel(form=form), "o-", ms=2,
                      label=f"{_FORMS[form]}, paper's K")
        axis.plot(hertz.axial_load, hertz[name], "s--", ms=2,
                  label="Jones, Hertz K (fi 0.52, fo 0.53)")
        axis.set(xlabel=label(data.axial_load), ylabel=label(data[name]))
        axis.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    save(figure, figures, "fig06_07_axial.png")


def _radial(results, figures):
    data = result(results, "fig08_09_radial")
    figure, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for axis, name in zip(axes, ("radial_displacement", "radial_stiffness")):
        for form in data.form.values:
            axis.plot(data.radial_load, data[name].sel(form=form), "o-", ms=2,
                      label=_FORMS[form])
        axis.set(xlabel=label(data.radial_load), ylabel=label(data[name]),
                 title="axial preload 2800 N")
        axis.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    save(figure, figures, "fig08_09_radial.png")


def _in_si(data):
    """The stiffness matrix in SI base units (its entries come in units of their own)."""
    factors = np.vectorize(lambda text: float(units.to_si(1.0, units.parse_unit(text))))(
        data.stiffness_matrix_units.values)
    return data.stiffness_matrix * factors


def _coupling(matrix, row: str, column: str):
    """``K_ij / sqrt(K_ii K_jj)`` of a matrix in consistent units: a cross term's weight."""
    diagonal = np.sqrt(matrix.sel(load_dof=row, dof=row) * matrix.sel(load_dof=column,
                                                                     dof=column))
    return matrix.sel(load_dof=row, dof=column) / diagonal


def _cross_terms(results, figures):
    data = result(results, "fig08_09_radial")
    matrix = _in_si(data)
    figure, axes = plt.subplots(1, 2, figsize=(9, 3.6), sharey=True)
    for axis, form in zip(axes, ("jones_free_tilt", "jones")):
        for row, column in _PAIRS:
            axis.plot(data.radial_load, _coupling(matrix.sel(form=form), row,
                                                  column), "o-", ms=2, label=f"{row} - {column}")
        axis.set(xlabel=label(data.radial_load), title=_FORMS[form])
        axis.grid(alpha=0.3)
    axes[0].set_ylabel("K_ij / sqrt(K_ii K_jj) [1]")
    axes[0].legend(fontsize=7)
    save(figure, figures, "cross_terms.png")


def _geometry(results, figures):
    axial, radial = result(results, "fig06_07_axial"), result(results, "fig08_09_radial")
    figure, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    for name, data, load, axis in (("axial_stiffness", axial, axial.axial_load, axes[0]),
                                   ("radial_stiffness", radial, radial.radial_load, axes[1])):
        ratio = data[name].sel(form="fixed_angle") / data[name].sel(form="jones")
        axis.plot(load, 100 * (ratio - 1), "o-", ms=2)
        axis.set(xlabel=label(load), ylabel=f"fixed angle / Jones - 1, {name} [%]")
        axis.grid(alpha=0.3)
    angles = radial.ball_contact_angle.sel(form="jones")
    for ball, text in ((1, "ball on the load line"), (13, "ball opposite")):
        axes[2].plot(radial.radial_load, angles.sel(ball=ball), "o-", ms=2, label=text)
    axes[2].set(xlabel=label(radial.radial_load), ylabel=label(angles),
                title="Jones, tilts held, 2800 N axial")
    axes[2].legend(fontsize=7)
    axes[2].grid(alpha=0.3)
    save(figure, figures, "geometry.png")


def _contact_constant(results, figures):
    data = result(results, "contact_constant")
    constant = data.hertz_contact_constant
    figure, axis = plt.subplots(figsize=(5.5, 3.8))
    for outer in data.outer_curvature_ratio.values:
        axis.plot(data.inner_curvature_ratio, _per_m(constant.sel(outer_curvature_ratio=outer)),
                  label=f"fo = {outer:g}")
    axis.axhline(_PAPER_CONSTANT, ls=":", color="k", label="paper, Table 1")
    axis.set(xlabel="inner curvature ratio fi [1]", ylabel="K [N/m^1.5]", yscale="log")
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)
    save(figure, figures, "contact_constant.png")


_PAPER_CONSTANT = 1.0649e10  # N/m^1.5, paper 001 Table 1


def _per_m(constant):
    """A contact constant from the dataset's units in N/m^1.5."""
    return units.convert(np.asarray(constant), units.parse_unit(constant.attrs["units"]),
                         units.parse_unit("N/m^1.5"))


def _deviation_from_line(load, displacement) -> float:
    """Largest distance of a curve from the straight line through its ends [% of the end]."""
    x, y = np.asarray(load), np.asarray(displacement)
    line = y[0] + (y[-1] - y[0]) * (x - x[0]) / (x[-1] - x[0])
    return float(100 * np.abs(y - line).max() / y[-1])


def ours(results: Path) -> dict:
    results = Path(results)
    axial = result(results, "fig06_07_axial")
    radial = result(results, "fig08_09_radial").sel(radial_load=slice(500, 3000))
    constants = result(results, "contact_constant").hertz_contact_constant
    values = {"contact_constant": float(_per_m(constants.sel(
        inner_curvature_ratio=0.52, outer_curvature_ratio=0.53, method="nearest")))}
    for form in ("jones", "fixed_angle"):
        stiffness = axial.axial_stiffness.sel(form=form)
        values[f"axial_stiffness_rises_{form}"] = float(stiffness[-1] / stiffness[0])
        values[f"axial_linear_{form}"] = _deviation_from_line(
            axial.axial_load, axial.axial_displacement.sel(form=form))
    for form in radial.form.values:
        stiffness = radial.radial_stiffness.sel(form=form)
        values[f"radial_stiffness_rises_{form}"] = float(stiffness[-1] / stiffness[0])
        values[f"radial_linear_{form}"] = _deviation_from_line(
            radial.radial_load, radial.radial_displacement.sel(form=form))
    return values
