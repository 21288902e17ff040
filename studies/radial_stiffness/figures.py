"""Paper 000's trend figures (Figs. 6-14) and its stated numbers, from the netCDF results only."""
from pathlib import Path

import numpy as np
from matplotlib.patches import Patch

from bearing_sweep.plotting import at as _at
from bearing_sweep.plotting import histogram as _histogram
from bearing_sweep.plotting import conditions as _conditions
from bearing_sweep.plotting import family as _family
from bearing_sweep.plotting import in_unit as _in_unit
from bearing_sweep.plotting import label as _label
from bearing_sweep.plotting import result as _open
from bearing_sweep.plotting import save as _save
from bearing_sweep.plotting import subplots
from bearing_sweep.study import Study, agreement

FIGURES = {
    "fig06_bearing_a.png": "Fig. 6: bearing A, radial stiffness against radial load (no speed, "
                           "straight rollers, one slice: the classical model).",
    "fig07_bearing_b.png": "Fig. 7: bearing B, radial stiffness against radial load for the two "
                           "effective lengths the paper tries (crowned rollers, no speed).",
    "fig08_bearing_c.png": "Fig. 8: bearing C, radial stiffness against speed at 4000 N: implicit "
                           "differentiation (eq. 16) and the perturbation method (0.001 mm).",
    "fig09_crown.png": "Fig. 9: bearing D, displacement and stiffness against crown for k = 10, "
                       "30, 60, 90 slices; top: consistent slicing, bottom: the paper's eq. 6 "
                       "and 9.",
    "fig10_clearance.png": "Fig. 10: bearing D, load distribution for four clearances, and "
                           "stiffness with the number of loaded rollers against clearance.",
    "fig11_load_clearance.png": "Fig. 11: bearing D, radial stiffness against radial load for "
                                "several clearances.",
    "fig12_loaded_rollers.png": "Fig. 12: bearing D, number of loaded rollers against radial load.",
    "fig13_crown_load.png": "Fig. 13: bearing D, radial stiffness against radial load for several "
                            "crowns.",
    "fig14_speed_load.png": "Fig. 14: bearing D, displacement and stiffness against speed for "
                            "several radial loads.",
    "slices_convergence.png": "Section 3: stiffness with k slices relative to k = 1000, for roller "
                              "lengths 10-100 mm; left: consistent slicing, right: eq. 9.",
    "contact_constant.png": "Beyond the paper: the stated percentages against the unstated "
                            "load-deflection constant K (multiples of Palmgren's); dotted: the "
                            "paper's values.",
    "unstated_inputs.png": "Beyond the paper: the stated percentages of bearing D when the "
                           "unstated K, roller density and pitch diameter are drawn (512 "
                           "samples); shaded: the paper's value within its tolerance; top: "
                           "their distribution, bottom: against K (light: the plausible band "
                           "0.8-1.25 times Palmgren's).",
}

#: Palmgren's load-deflection constant of a steel line contact, 8.06e4 l^(8/9) (N, mm)
#: (Harris & Kotzalas, Rolling Bearing Analysis, eq. for line contact), and the band of
#: multiples of it that the line-contact laws in use span (unstated_inputs.toml).
_PALMGREN = 8.06e4
_PLAUSIBLE = (0.8, 1.25)
#: Each stated percentage of the unstated-inputs study: its claim, and the two cases of the
#: zipped axis ``case`` whose stiffnesses it compares.
_UNSTATED = {"crown_consistent": ("crown_0", "crown_3.2um"),
             "crown_paper": ("crown_0_paper", "crown_3.2um_paper"),
             "clearance_6kN": ("6kN_Pd_0", "6kN_Pd_40um"),
             "clearance_8kN": ("8kN_Pd_0", "8kN_Pd_40um")}
#: What each of them changes, as a figure names it.
_UNSTATED_TITLES = {"crown_consistent": "crown 0 to 3.2 um at 4 kN",
                    "crown_paper": "crown 0 to 3.2 um at 4 kN, eq. 6 and 9",
                    "clearance_6kN": "clearance Pd 0 to 40 um at 6 kN",
                    "clearance_8kN": "clearance Pd 0 to 40 um at 8 kN"}


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _bearing_a(results, figures)
    _bearing_b(results, figures)
    _bearing_c(results, figures)
    _crown(results, figures)
    _clearance(results, figures)
    _load_clearance(results, figures)
    _crown_load(results, figures)
    _speed_load(results, figures)
    _slices(results, figures)
    _contact_constant(results, figures)
    _unstated(results, figures)


_STIFFNESS_LABEL = "radial stiffness [1e5 N/mm]"
#: The slicing of each ``form``, as a figure names it.
_SLICING = {"consistent": "consistent slicing", "paper": "the paper's slicing (eq. 6, 9)"}


def _stiffness(variable):
    """A stiffness in units of 1e5 N/mm, the paper's scale."""
    return _in_unit(variable, "N/mm") / 1e5


def _in_kn(data):
    """``data`` with its radial loads in kN, the unit the figures show them in."""
    return data.assign_coords(radial_load=_in_unit(data.radial_load, "kN"))


def _title(axis, heading: str, data, *names, **shown_in):
    axis.set_title(f"{heading}\n{_conditions(data, *names, width=70, **shown_in)}", fontsize=8)


def _bearing_a(results, figures):
    data = _in_kn(_open(results, "fig06_bearing_a"))
    figure, axis = subplots(figsize=(5, 3.6))
    axis.plot(data.radial_load, _stiffness(data.radial_stiffness), "o-", ms=3)
    axis.set(xlabel=_label(data.radial_load), ylabel=_STIFFNESS_LABEL)
    _title(axis, "Bearing A (Table 1)", data, "speed", "clearance", "crown", "slices")
    axis.grid(alpha=0.3)
    _save(figure, figures, "fig06_bearing_a.png")


def _bearing_b(results, figures):
    data = _in_kn(_open(results, "fig07_bearing_b"))
    figure, axis = subplots(figsize=(5, 3.6))
    _family(axis, data.radial_load, _stiffness(data.radial_stiffness), "length", "{}",
            xlabel=_label(data.radial_load), ylabel=_STIFFNESS_LABEL)
    _title(axis, "Bearing B (Table 2), effective length l", data, "speed", "clearance",
           "crown", "slices")
    _save(figure, figures, "fig07_bearing_b.png")


def _bearing_c(results, figures):
    data = _open(results, "fig08_bearing_c")
    step = float(_in_unit(data.perturbation, "mm"))
    figure, axis = subplots(figsize=(5, 3.6))
    axis.plot(data.speed, _stiffness(data.radial_stiffness),
              label="implicit differentiation (eq. 16)")
    axis.plot(data.speed, _stiffness(data.perturbation_stiffness), "--",
              label=f"perturbation, step {step:g} mm")
    axis.set(xlabel=_label(data.speed), ylabel=_STIFFNESS_LABEL)
    _title(axis, "Bearing C (Table 3)", data, "radial_load", "clearance", "crown", "slices")
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)
    _save(figure, figures, "fig08_bearing_c.png")


def _crown(results, figures):
    data = _open(results, "fig09_crown")
    data = data.assign_coords(crown=_in_unit(data.crown, "um"))
    displacement = _in_unit(data.radial_displacement, "um")
    figure, axes = subplots(2, 2, figsize=(9, 6.6), sharex=True)
    for row, form in enumerate(data.form.values):
        _family(axes[row, 0], data.crown, displacement.sel(form=form), "slices", "k = {}",
                ylabel=_label(displacement), title=f"{_SLICING[form]}: displacement")
        _family(axes[row, 1], data.crown, _stiffness(data.radial_stiffness.sel(form=form)),
                "slices", "k = {}", ylabel=_STIFFNESS_LABEL, title=f"{_SLICING[form]}: stiffness")
    for axis in axes[1]:
        axis.set_xlabel("crown cmax [um]")
    figure.suptitle(_conditions(data, "radial_load", "speed", "clearance", "crown_profile"),
                    fontsize=9)
    _save(figure, figures, "fig09_crown.png")


def _clearance(results, figures):
    data = _open(results, "fig10_clearance")
    figure, (left, right) = subplots(1, 2, figsize=(10, 4.2))
    count = data.roller.size
    azimuth = (float(_in_unit(data.cage_position, "degree"))
               + 360.0 * (data.roller - 1) / count)
    azimuth = (azimuth + 180.0) % 360.0 - 180.0
    order = np.argsort(azimuth.values)
    for clearance in ("0 mm", "0.01 mm", "0.02 mm", "0.04 mm"):
        loads = _at(data.roller_load, clearance=clearance, method="nearest")
        left.plot(azimuth[order], loads[order], "o-", ms=3, label=f"Pd = {clearance}")
    left.set(xlabel="roller azimuth from the load direction [deg]", ylabel=_label(loads),
             title="Load distribution", xticks=np.arange(-180, 181, 60))
    left.legend(fontsize=7)
    right.plot(data.clearance, _stiffness(data.radial_stiffness), color="C0")
    right.set(xlabel=_label(data.clearance), title="Stiffness and loaded rollers")
    right.set_ylabel(_STIFFNESS_LABEL, color="C0")
    twin = right.twinx()
    twin.step(data.clearance, data.loaded_rollers, where="post", color="C3", alpha=0.7)
    twin.set_ylabel("loaded rollers", color="C3")
    twin.yaxis.get_major_locator().set_params(integer=True)
    for axis in (left, right):
        axis.grid(alpha=0.3)
    figure.suptitle(_conditions(data, "radial_load", "speed", "crown", "slices"), fontsize=9)
    _save(figure, figures, "fig10_clearance.png")


def _load_clearance(results, figures):
    data = _in_kn(_open(results, "fig11_12_load_clearance"))
    fixed = ("speed", "crown", "slices")
    figure, axis = subplots(figsize=(5, 3.6))
    _family(axis, data.radial_load, _stiffness(data.radial_stiffness), "clearance",
            "Pd = {:g} mm", xlabel=_label(data.radial_load), ylabel=_STIFFNESS_LABEL)
    _title(axis, "Bearing D, diametral clearance Pd", data, *fixed)
    _save(figure, figures, "fig11_load_clearance.png")
    figure, axis = subplots(figsize=(5, 3.6))
    counts = _at(data.loaded_rollers, clearance=["0 mm", "0.01 mm", "0.02 mm"])
    _family(axis, data.radial_load, counts, "clearance", "Pd = {:g} mm", plot="step",
            xlabel=_label(data.radial_load), ylabel="loaded rollers", ylim=(0, 9))
    axis.legend(fontsize=7, loc="lower right")
    _title(axis, "Bearing D, diametral clearance Pd", data, *fixed)
    _save(figure, figures, "fig12_loaded_rollers.png")


def _crown_load(results, figures):
    data = _in_kn(_open(results, "fig13_crown_load"))
    figure, axis = subplots(figsize=(5, 3.6))
    _family(axis, data.radial_load, _stiffness(data.radial_stiffness), "crown",
            "cmax = {:g} mm", xlabel=_label(data.radial_load), ylabel=_STIFFNESS_LABEL)
    _title(axis, "Bearing D, crown cmax", data, "speed", "clearance", "slices")
    _save(figure, figures, "fig13_crown_load.png")


def _speed_load(results, figures):
    data = _in_kn(_open(results, "fig14_speed_load"))
    displacement = _in_unit(data.radial_displacement, "um")
    figure, (left, right) = subplots(1, 2, figsize=(10, 4.2))
    _family(left, data.speed, displacement, "radial_load", "Fr = {:g} kN",
            xlabel=_label(data.speed), ylabel=_label(displacement), title="Displacement")
    _family(right, data.speed, _stiffness(data.radial_stiffness), "radial_load",
            "Fr = {:g} kN", xlabel=_label(data.speed), ylabel=_STIFFNESS_LABEL,
            title="Stiffness")
    left.get_legend().remove()  # one legend, beside the data: the colours are shared
    right.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.02, 0.5))
    figure.suptitle(_conditions(data, "clearance", "crown", "slices"), fontsize=9)
    _save(figure, figures, "fig14_speed_load.png")


def _slices(results, figures):
    data = _open(results, "slices_convergence")
    relative = 100 * (data.radial_stiffness / data.radial_stiffness.sel(slices=1000) - 1)
    figure, axes = subplots(1, 2, figsize=(10, 4.2), sharey=True)
    for axis, form in zip(axes, data.form.values):
        axis.axvline(60, color="k", lw=0.8, ls=":", label="k = 60, the paper's")
        _family(axis, data.slices, relative.sel(form=form), "effective_length", "l = {:g} mm",
                plot="semilogx", xlabel="slices k", title=_SLICING[form])
        axis.get_legend().set_title("roller length", prop={"size": 7})
    axes[0].set_ylabel("stiffness relative to k = 1000 [%]")
    figure.suptitle(_conditions(data, "radial_load", "speed", "crown", "clearance"),
                    fontsize=9)
    _save(figure, figures, "slices_convergence.png")


def _contact_constant(results, figures):
    data = _open(results, "contact_constant")
    multiple = data.contact_constant / data.contact_constant[0]
    curves = {"crown 0 -> 0.0032 mm, 4 kN (4.1 %)": (4.1, []),
              "5 -> 3 loaded rollers, 4 kN (21.3 %)": (21.3, []),
              "Pd 0 -> 0.04 mm at 6 kN (18.7 %)": (18.7, []),
              "Pd 0 -> 0.04 mm at 8 kN (13.6 %)": (13.6, [])}
    for constant in data.contact_constant.values:
        point = data.sel(contact_constant=constant)
        values = _stated_percentages(point.radial_stiffness, point.loaded_rollers)
        for (_, series), value in zip(curves.values(), values):
            series.append(value)
    figure, axis = subplots(figsize=(6, 5.2))
    for index, (label, (paper, series)) in enumerate(curves.items()):
        axis.semilogx(multiple, series, "o-", color=f"C{index}", label=label)
        axis.axhline(paper, color=f"C{index}", ls=":", lw=1)
    axis.set(xlabel="K / Palmgren's K", ylabel="fall of radial stiffness [%]")
    _title(axis, "Bearing D, crown 0.004 mm unless named; dotted: the paper", data, "speed",
           "slices")
    axis.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=2)
    axis.grid(alpha=0.3)
    _save(figure, figures, "contact_constant.png")


def unstated_reach(results: Path) -> dict:
    """For each stated percentage of the unstated-inputs study: the samples' percentages, K
    over Palmgren's, and whether each sample agrees with the paper within its tolerance."""
    data = _open(results, "unstated_inputs")
    length = float(_in_unit(data.effective_length, "mm"))
    multiple = (_in_unit(data.contact_constant, "N/mm^(10/9)")
                / (_PALMGREN * length ** (8 / 9))).values
    claims = {c["id"]: c for c in Study("radial_stiffness", Path(__file__).parent).claims()}
    reach = {}
    for name, (before, after) in _UNSTATED.items():
        stiffness = data.radial_stiffness
        fall = 100.0 * (1.0 - stiffness.sel(case=after) / stiffness.sel(case=before))
        fall = fall.assign_attrs(units="%", long_name=f"fall of Kr: {before} -> {after}")
        reach[name] = {"claim": claims[name], "fall": fall, "multiple": multiple,
                       "agrees": agreement(claims[name], fall.values)}
    return reach


def _unstated(results, figures):
    reach = unstated_reach(results)
    figure, axes = subplots(2, len(reach), figsize=(3.3 * len(reach), 6.8))
    for column, (name, one) in enumerate(reach.items()):
        claim, multiple, agrees = one["claim"], one["multiple"], one["agrees"]
        plausible = (multiple >= _PLAUSIBLE[0]) & (multiple <= _PLAUSIBLE[1])
        band = (claim["paper"] - claim.get("tolerance", 0), claim["paper"]
                + claim.get("tolerance", 0))
        top, bottom = axes[0, column], axes[1, column]
        _histogram(top, one["fall"].to_dataset(name="fall"), "fall", bins=40)
        top.axvspan(*band, color="C2", alpha=0.3)
        top.set_title(f"{_UNSTATED_TITLES[name]}: paper {claim['paper']:g} %\nsamples within "
                      f"tolerance: {100 * agrees.mean():.0f} % of all,\n"
                      f"{100 * agrees[plausible].mean():.0f} % of those with a plausible K",
                      fontsize=8)
        top.set_xlabel("fall of radial stiffness [%]")
        bottom.plot(multiple, one["fall"].values, ".", ms=2)
        bottom.axhspan(*band, color="C2", alpha=0.3)
        bottom.axvspan(*_PLAUSIBLE, color="0.5", alpha=0.15)
        bottom.set(xlabel="K / Palmgren's K", ylabel="fall of radial stiffness [%]")
        bottom.grid(alpha=0.3)
    keys = [Patch(color="C2", alpha=0.3, label="the paper's value within its tolerance"),
            Patch(color="0.5", alpha=0.15, label=f"plausible K: {_PLAUSIBLE[0]:g} to "
                                                  f"{_PLAUSIBLE[1]:g} times Palmgren's")]
    figure.legend(handles=keys, loc="lower center", ncol=2, fontsize=8)
    data = _open(results, "unstated_inputs")
    figure.suptitle(_conditions(data, "speed", "slices", width=None) + "; drawn (Latin "
                    "hypercube): K, roller density, pitch diameter", fontsize=9)
    figure.tight_layout(rect=(0, 0.04, 1, 1))  # room for the legend below
    _save(figure, figures, "unstated_inputs.png", tight=False)


# -- the paper's stated numbers, recomputed ---------------------------------------------------

def _drop(before, after) -> float:
    """Relative fall from ``before`` to ``after`` [%]."""
    return float(100.0 * (1.0 - after / before))


def _shedding_drop(stiffness, loaded) -> float:
    """Fall of stiffness between the first clearance with 5 loaded rollers and the first with 3."""
    five = stiffness.clearance[loaded <= 5][0]
    three = stiffness.clearance[loaded <= 3][0]
    return _drop(stiffness.sel(clearance=five), stiffness.sel(clearance=three))


def _stated_percentages(stiffness, loaded):
    """The crown, shedding and clearance percentages from a load x crown x clearance grid."""
    fig10 = dict(radial_load="4 kN", crown="0.004 mm")
    return (_drop(_at(stiffness, radial_load="4 kN", crown="0 mm", clearance="0 mm"),
                  _at(stiffness, radial_load="4 kN", crown="0.0032 mm", clearance="0 mm")),
            _shedding_drop(_at(stiffness, **fig10), _at(loaded, **fig10)),
            *(_drop(_at(stiffness, radial_load=load, crown="0.004 mm", clearance="0 mm"),
                    _at(stiffness, radial_load=load, crown="0.004 mm", clearance="0.04 mm"))
              for load in ("6 kN", "8 kN")))


def ours(results: Path) -> dict:
    results = Path(results)
    values = {}
    crown = _open(results, "fig09_crown").radial_stiffness.sel(slices=60)
    for form in crown.form.values:
        values[f"crown_{form}"] = _drop(_at(crown.sel(form=form), crown="0 mm"),
                                        _at(crown.sel(form=form), crown="0.0032 mm",
                                            method="nearest"))
    clearance = _open(results, "fig10_clearance")
    values["rollers_5_to_3"] = _shedding_drop(clearance.radial_stiffness, clearance.loaded_rollers)
    grid = _open(results, "fig11_12_load_clearance").radial_stiffness
    for load in (6, 8):
        point = _at(grid, radial_load=f"{load} kN")
        values[f"clearance_{load}kN"] = _drop(_at(point, clearance="0 mm"),
                                              _at(point, clearance="0.04 mm"))
    speed = _open(results, "fig08_bearing_c")
    values["perturbation_c"] = float(100 * np.abs(
        speed.perturbation_stiffness / speed.radial_stiffness - 1).max())
    slices = _open(results, "slices_convergence").radial_stiffness.sel(form="consistent")
    error = np.abs(slices / slices.sel(slices=1000) - 1).max("effective_length").values
    # The fewest slices from which on every finer slicing stays within 0.5 % of k = 1000.
    outside = np.flatnonzero(error > 0.005)
    first = outside[-1] + 1 if outside.size else 0
    values["slices_enough"] = float(slices.slices[first])
    counts = _at(_open(results, "fig11_12_load_clearance").loaded_rollers, clearance="0 mm")
    values["rollers_fixed_at_zero_clearance"] = float(np.unique(counts).size)
    return values
