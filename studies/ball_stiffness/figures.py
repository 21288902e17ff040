"""Paper 001's trend figures (Figs. 6-9), the cross terms it drops and the geometry it fixes,
from the netCDF results only."""
from pathlib import Path

import numpy as np

from bearing_sweep import units
from bearing_sweep.plotting import (at, conditions, histogram, in_unit, label, result, save,
                                    subplots)
from bearing_sweep.study import Study, agreement

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
    "unstated_inputs.png": "Beyond the paper: the stated numbers when the unstated groove "
                           "curvature ratios (0.51-0.54) and clearance (+-5 um) are drawn (512 "
                           "samples): the Hertz contact constant against the paper's K "
                           "(shaded: within the claim's tolerance), and whether the radial "
                           "stiffness rises from 500 to 3000 N in each geometry.",
}

_FORMS = {"jones": "Jones, tilts held", "fixed_angle": "fixed angle (paper), tilts held",
          "jones_free_tilt": "Jones, free to tilt"}
_PAIRS = (("axial", "radial_y"), ("radial_y", "tilt_z"), ("radial_z", "tilt_y"),
          ("axial", "tilt_z"))
#: The degrees of freedom as the paper writes them (eq. 10): x axial, y and z radial.
_DOF = {"axial": r"$\delta_x$", "radial_y": r"$\delta_y$", "radial_z": r"$\delta_z$",
        "tilt_y": r"$\theta_y$", "tilt_z": r"$\theta_z$"}


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _axial(results, figures)
    _radial(results, figures)
    _cross_terms(results, figures)
    _geometry(results, figures)
    _contact_constant(results, figures)
    _unstated(results, figures)


#: The units the figures show: displacements in um, stiffnesses in kN/mm.
_SHOWN = {"axial_displacement": "um", "radial_displacement": "um", "axial_stiffness": "kN/mm",
          "radial_stiffness": "kN/mm"}


def _axial(results, figures):
    data, hertz = result(results, "fig06_07_axial"), result(results, "fig06_07_axial_hertz")
    figure, axes = subplots(1, 2, figsize=(9, 3.9))
    for axis, name in zip(axes, ("axial_displacement", "axial_stiffness")):
        for form in data.form.values:
            axis.plot(data.axial_load, in_unit(data[name].sel(form=form), _SHOWN[name]), "o-",
                      ms=2, label=f"{_FORMS[form]}, paper's K")
        axis.plot(hertz.axial_load, in_unit(hertz[name], _SHOWN[name]), "s--", ms=2,
                  label="Jones, tilts held, Hertz K (fi 0.52, fo 0.53)")
        axis.set(xlabel=label(data.axial_load), ylabel=label(in_unit(data[name], _SHOWN[name])))
        axis.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    figure.suptitle(conditions(data, "contact_angle", "clearance", "radial_load", width=None),
                    fontsize=9)
    save(figure, figures, "fig06_07_axial.png")


def _radial(results, figures):
    data = result(results, "fig08_09_radial")
    figure, axes = subplots(1, 2, figsize=(9, 3.9))
    for axis, name in zip(axes, ("radial_displacement", "radial_stiffness")):
        for form in data.form.values:
            axis.plot(data.radial_load, in_unit(data[name].sel(form=form), _SHOWN[name]), "o-",
                      ms=2, label=_FORMS[form])
        axis.set(xlabel=label(data.radial_load), ylabel=label(in_unit(data[name],
                                                                       _SHOWN[name])))
        axis.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    figure.suptitle(_radial_conditions(data), fontsize=9)
    save(figure, figures, "fig08_09_radial.png")


def _radial_conditions(data) -> str:
    """The fixed inputs of the radial sweep: the preload, the paper's K, the geometry."""
    return conditions(data, "axial_load", "contact_angle", "clearance", width=None)


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
    figure, axes = subplots(1, 2, figsize=(9, 3.9), sharey=True)
    for axis, form in zip(axes, ("jones_free_tilt", "jones")):
        for row, column in _PAIRS:
            axis.plot(data.radial_load, _coupling(matrix.sel(form=form), row,
                                                  column), "o-", ms=2,
                      label=f"{_DOF[row]} with {_DOF[column]}")
        axis.set(xlabel=label(data.radial_load), title=_FORMS[form])
        axis.grid(alpha=0.3)
    axes[0].set_ylabel(r"coupling $K_{ij} / \sqrt{K_{ii} K_{jj}}$")
    axes[1].legend(fontsize=8, loc="center left", bbox_to_anchor=(1.02, 0.5),
                   title="coupling of", title_fontsize=8)
    figure.suptitle(_radial_conditions(data), fontsize=9)
    save(figure, figures, "cross_terms.png")


def _geometry(results, figures):
    axial, radial = result(results, "fig06_07_axial"), result(results, "fig08_09_radial")
    figure, axes = subplots(1, 3, figsize=(12, 3.6))
    for name, data, load, axis in (("axial_stiffness", axial, axial.axial_load, axes[0]),
                                   ("radial_stiffness", radial, radial.radial_load, axes[1])):
        ratio = data[name].sel(form="fixed_angle") / data[name].sel(form="jones")
        axis.plot(load, 100 * (ratio - 1), "o-", ms=2)
        axis.set(xlabel=label(load),
                 ylabel=f"{name.replace('_', ' ')}:\nfixed angle / Jones - 1 [%]")
        axis.grid(alpha=0.3)
    axes[0].set_title(conditions(axial, "radial_load", preset=False), fontsize=9)
    axes[1].set_title(conditions(radial, "axial_load", preset=False), fontsize=9)
    angles = in_unit(radial.ball_contact_angle.sel(form="jones"), "degree")
    opposite = 1 + radial.ball.size // 2
    for ball, text in ((1, "ball on the load line"), (opposite, "ball opposite")):
        axes[2].plot(radial.radial_load, angles.sel(ball=ball), "o-", ms=2, label=text)
    axes[2].set(xlabel=label(radial.radial_load), ylabel="ball contact angle [deg]")
    axes[2].set_title(f"Jones, tilts held, {conditions(radial, 'axial_load', preset=False)}",
                      fontsize=9)
    axes[2].legend(fontsize=7)
    axes[2].grid(alpha=0.3)
    figure.suptitle(conditions(radial, "contact_angle", "clearance", width=None), fontsize=9)
    save(figure, figures, "geometry.png")


def _contact_constant(results, figures):
    data = result(results, "contact_constant")
    constant = data.hertz_contact_constant
    figure, axis = subplots(figsize=(5.5, 3.8))
    for outer in data.outer_curvature_ratio.values:
        axis.plot(data.inner_curvature_ratio,
                  _per_m(constant.sel(outer_curvature_ratio=outer)) / 1e10,
                  label=f"fo = {outer:g}")
    axis.axhline(_PAPER_CONSTANT / 1e10, ls=":", color="k", label="paper, Table 1")
    axis.set(xlabel="inner curvature ratio fi", ylabel=r"contact constant K [1e10 N/m$^{1.5}$]")
    axis.set_title(conditions(data, "ball_diameter", "pitch_diameter", "contact_angle"),
                   fontsize=8)
    axis.legend(fontsize=7, loc="center right", bbox_to_anchor=(1.0, 0.45))
    axis.grid(alpha=0.3)
    save(figure, figures, "contact_constant.png")


_PAPER_CONSTANT = 1.0649e10  # N/m^1.5, paper 001 Table 1


def unstated_reach(results: Path) -> dict:
    """For each stated number the unstated-inputs study tests: the samples' values and
    whether each agrees with the paper within the claim's tolerance."""
    data = result(results, "unstated_inputs")
    claims = {c["id"]: c for c in Study("ball_stiffness", Path(__file__).parent).claims()}
    constant = _per_m(data.hertz_contact_constant.isel(radial_load=0, form=0))
    reach = {"contact_constant": (constant, agreement(claims["contact_constant"],
                                                      constant.values))}
    stiffness = data.radial_stiffness
    rise = (at(stiffness, radial_load="3000 N") / at(stiffness, radial_load="500 N"))
    for form in data.form.values:
        name = f"radial_stiffness_rises_{form}"
        one = rise.sel(form=form).assign_attrs(units="1", long_name=f"Kr(3000 N) / Kr(500 N), "
                                               f"{_FORMS[form]}")
        reach[name] = (one, agreement(claims[name], one.values))
    return reach


def _unstated(results, figures):
    data = result(results, "unstated_inputs")
    reach = unstated_reach(results)
    figure, (left, middle, right) = subplots(1, 3, figsize=(13, 4.6))
    constant, agrees = reach.pop("contact_constant")
    scaled = (constant / 1e10).assign_attrs(units="1e10 N/m^1.5", long_name="Hertz K")
    histogram(left, scaled.to_dataset(name="K"), "K", bins=30)
    left.axvspan((_PAPER_CONSTANT - 1.06e9) / 1e10, (_PAPER_CONSTANT + 1.06e9) / 1e10,
                 color="C2", alpha=0.3, label="paper's K (Table 1)\nwithin tolerance")
    left.set(xlabel=r"Hertz contact constant K [1e10 N/m$^{1.5}$]")
    left.set_title(f"K within tolerance: {100 * agrees.mean():.0f} % of the samples",
                   fontsize=8)
    left.legend(fontsize=7, loc="upper center")
    shown = middle.scatter(data.inner_curvature_ratio, data.outer_curvature_ratio,
                           c=scaled.values, s=4)
    figure.colorbar(shown, ax=middle, label=r"Hertz K [1e10 N/m$^{1.5}$]")
    middle.set(xlabel="inner groove curvature ratio fi", ylabel="outer groove curvature ratio fo")
    middle.set_title("Hertz K over the drawn curvature ratios", fontsize=8)
    edges = np.linspace(min(float(r.min()) for r, _ in reach.values()) - 0.01,
                        max(float(r.max()) for r, _ in reach.values()) + 0.01, 50)
    for name, (rise, agrees) in reach.items():
        form = name.removeprefix("radial_stiffness_rises_")
        histogram(right, rise.to_dataset(name="rise"), "rise", bins=edges,
                  style={"alpha": 0.7, "label": f"{_FORMS[form]}:\nrises in "
                         f"{100 * agrees.mean():.0f} % of the samples"})
    right.axvline(1.0, color="k", ls=":")
    right.set(xlabel="radial stiffness at 3000 N / at 500 N (> 1: rises)")
    right.set_title("Does the radial stiffness rise with load (as the paper states)?",
                    fontsize=8)
    # Below the panel: a bar of all the samples in one bin stands above any corner.
    right.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2)
    figure.suptitle(conditions(data, "axial_load", "contact_constant", width=None)
                    + "; drawn (Latin hypercube): fi, fo, clearance", fontsize=9)
    save(figure, figures, "unstated_inputs.png")


def _per_m(constant):
    """A contact constant in N/m^1.5."""
    return in_unit(constant, "N/m^1.5")


def _deviation_from_line(load, displacement) -> float:
    """Largest distance of a curve from the straight line through its ends [% of the end]."""
    x, y = np.asarray(load), np.asarray(displacement)
    line = y[0] + (y[-1] - y[0]) * (x - x[0]) / (x[-1] - x[0])
    return float(100 * np.abs(y - line).max() / y[-1])


def ours(results: Path) -> dict:
    results = Path(results)
    axial = result(results, "fig06_07_axial")
    radial = at(result(results, "fig08_09_radial"), radial_load=slice("500 N", "3000 N"))
    constants = result(results, "contact_constant").hertz_contact_constant
    values = {"contact_constant": float(_per_m(at(
        constants, inner_curvature_ratio=0.52, outer_curvature_ratio=0.53, method="nearest")))}
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
