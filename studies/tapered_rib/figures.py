"""Paper 003's Table 2 and Fig. 4, and the limit rib angle beyond them, from the netCDF
results only."""
from pathlib import Path


from bearing_sweep.plotting import conditions, in_unit, label, result, save, subplots

FIGURES = {
    "table2_roller_loads.png": "Table 2: load of each roller under Fr = 40 kN, Fa = 27 kN; "
                               "crosses: the paper's values.",
    "fig04_rib_angle.png": "Fig. 4: rib load, semi-axes a and b, approach and maximum pressure "
                           "of the most loaded roller against the rib angle, with the rib force "
                           "of the roller's balance and of eq. 12; right: the groove distance CE "
                           "against b.",
    "limit_rib_angle.png": "Beyond the paper: the limit rib angle (CE = b) against axial load "
                           "(Fr = 40 kN) and against the roller end radius SR; dotted: the "
                           "paper's limit.",
}

#: Paper 003, Table 2 [N], rollers 1-16.
TABLE_2 = [11423, 10504, 7934, 4247, 360, 0, 0, 0, 0, 0, 0, 0, 360, 4247, 7934, 10504]
#: Section 3.1: the limit rib angle 89 deg 18' 58".
PAPER_LIMIT = 89 + 18 / 60 + 58 / 3600
_FORMS = {"balance": "force balance (eq. 10)", "paper": "eq. 12 as printed",
          "paper_eq6": "eq. 12 and eq. 6 as printed"}
_SHORT = {"balance": "balance", "paper": "eq. 12", "paper_eq6": "eq. 12, eq. 6"}
_FIG04 = ("rib_load", "semi_major", "semi_minor", "approach", "max_pressure")
#: The units Fig. 4 shows, where they are not the stored ones.
_SHOWN = {"approach": "um"}


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _table2(results, figures)
    _fig04(results, figures)
    _limits(results, figures)


def _degrees(variable):
    """An angle variable's values in degrees, whatever unit the file stores it in."""
    return in_unit(variable, "degree")


def _table2(results, figures):
    data = result(results, "table2_load")
    figure, axis = subplots(figsize=(5.5, 3.6))
    axis.bar(data.roller, data.roller_load, color="C0", label="ours")
    axis.plot(data.roller, TABLE_2, "kx", ms=7, label="paper, Table 2")
    axis.set(xlabel="roller number (roller 1 on the load line)", ylabel=label(data.roller_load),
             xticks=data.roller.values)
    axis.set_title(conditions(data, "radial_load", "axial_load", "roller_count", width=60),
                   fontsize=9)
    axis.legend(fontsize=7, loc="upper center")  # above the unloaded rollers
    axis.grid(alpha=0.3, axis="y")
    save(figure, figures, "table2_roller_loads.png")


def _fig04(results, figures):
    data = result(results, "fig04_rib_angle")
    angle = _degrees(data.rib_angle)
    figure, axes = subplots(2, 3, figsize=(12, 6.4), sharex=True)
    for axis, name in zip(axes.flat, _FIG04):
        shown = in_unit(data[name], _SHOWN.get(name, data[name].attrs["units"]))
        for form in data.form.values:
            axis.plot(angle, shown.sel(form=form), "o-", ms=2, label=_FORMS[form])
        axis.set(ylabel=label(shown, long=True))
        axis.grid(alpha=0.3)
    last = axes.flat[5]
    axes.flat[0].legend(fontsize=7, loc="center right")
    last.plot(angle, data.groove_distance.sel(form="paper"), "k-", label="CE")
    for index, form in enumerate(data.form.values):
        last.plot(angle, data.semi_minor.sel(form=form), "--", color=f"C{index}",
                  label=f"b, {_SHORT[form]}")
    last.axvline(PAPER_LIMIT, ls=":", color="k", lw=1, label="paper's limit")
    last.set(ylabel=f"length [{data.semi_minor.units}]", title="ellipse edge meets groove")
    last.legend(fontsize=7, loc="upper right")
    last.grid(alpha=0.3)
    for axis in axes[1]:
        axis.set_xlabel("rib angle [deg]")
    figure.suptitle(conditions(data, "radial_load", "axial_load", "roller_end_radius",
                               "oil_groove_size", width=None), fontsize=9)
    save(figure, figures, "fig04_rib_angle.png")


def _limits(results, figures):
    load, radius = result(results, "limit_axial_load"), result(results, "limit_end_radius")
    load = load.assign_coords(axial_load=in_unit(load.axial_load, "kN"))
    figure, axes = subplots(1, 2, figsize=(9, 4), sharey=True)
    for axis, data, x, fixed in ((axes[0], load, load.axial_load, ("radial_load",
                                                                    "roller_end_radius")),
                                 (axes[1], radius, radius.roller_end_radius, ("radial_load",
                                                                             "axial_load"))):
        for form in data.rib_force.values:
            axis.plot(x, _degrees(data.limit_rib_angle.sel(rib_force=form)), "o-", ms=2,
                      label=_FORMS[form])
        axis.axhline(PAPER_LIMIT, ls=":", color="k", lw=1, label="the paper's limit")
        axis.set(xlabel=label(x))
        axis.set_title(conditions(data, *fixed, preset=False), fontsize=9)
        axis.grid(alpha=0.3)
    axes[0].set_ylabel("limit rib angle [deg]")
    axes[0].legend(fontsize=7)
    figure.suptitle(load.attrs.get("bearing", ""), fontsize=9)
    save(figure, figures, "limit_rib_angle.png")


def _ratio(variable, form: str) -> float:
    """A Fig. 4 quantity at the largest rib angle over that at the smallest."""
    series = variable.sel(form=form)
    return float(series[-1] / series[0])


def ours(results: Path) -> dict:
    results = Path(results)
    load = result(results, "table2_load")
    values = {"radial_displacement": float(load.radial_displacement),
              "axial_displacement": float(load.axial_displacement),
              "loaded_rollers": float(load.loaded_rollers)}
    for roller in range(1, 6):
        values[f"roller_{roller}"] = float(load.roller_load.sel(roller=roller))
    named = result(results, "chosen_angles")
    for form in named.rib_force.values:
        point = named.sel(rib_force=form)
        limit = float(_degrees(point.limit_rib_angle.sel(named="stated_limit")))
        values[f"limit_{form}"] = 3600 * (limit - 89)
        values[f"ellipse_at_limit_{form}"] = float(point.semi_minor.sel(named="stated_limit"))
        tolerance_end = float(_degrees(point.rib_angle.sel(named="chosen_plus_tolerance")))
        values[f"chosen_margin_{form}"] = 60 * (limit - tolerance_end)
    values["groove_distance_at_limit"] = float(named.groove_distance.sel(
        named="stated_limit", rib_force="paper"))
    fig04 = result(results, "fig04_rib_angle")
    for name in _FIG04:
        values[f"{name}_falls_paper"] = _ratio(fig04[name], "paper_eq6")
        values[f"{name}_falls_exact"] = _ratio(fig04[name], "paper")
    return values
