"""Paper 002's cage slip trends (Figs. 13, 17, 20 in steady state, Figs. 17-20 transient) and
the sensitivity to the inputs it does not state, from the netCDF results only. Every figure
states its conditions; results are selected by quantity (``at``), whatever unit a coordinate
is stored in."""
from pathlib import Path

import numpy as np

from bearing_sweep.plotting import (at, conditions, family, label, result, save, shown_unit,
                                    subplots)

FIGURES = {
    "fig17_load_speed.png": "Fig. 17: steady cage slip of the test bearing against radial load "
                            "at 6000, 9000 and 12000 r/min (room-temperature oil, documented "
                            "defaults for the unstated oil, traction and drag). Shaded: loads "
                            "with two stable equilibria (hysteresis band, 5 N grid); solid: "
                            "the high-slip branch a cage reaches from rest, dashed: the "
                            "low-slip branch.",
    "roller_slip_orbit.png": "Steady counterpart of Fig. 20: roller spin slip around the orbit "
                             "at 12000 r/min (0 deg: the load line; the load zone is about "
                             "+-70 deg).",
    "nu2330_spin.png": "Fig. 13: NU2330EM1 mean roller spin over its kinematic value at "
                       "1000 r/min and 50 kN against oil temperature; dotted: the paper's "
                       "84.6 % (simulated) and 82.7 % (measured).",
    "sensitivity.png": "Beyond the paper: cage slip at 12000 r/min against the inputs the paper "
                       "does not state: oil temperature, traction peak speed, cavity oil "
                       "fraction.",
    "fig17_transient.png": "Fig. 17 again: settled mean cage slip of the planar transient "
                           "model (dots) and of the spatial one, the paper's own (squares), "
                           "beside the steady model (lines, high-slip branch).",
    "fig18_whirl.png": "Fig. 18: the cage's whirl over the settled half, 800 N, 12000 r/min, "
                       "without and with 2 mm radial cage eccentricity: the path of its "
                       "geometric centre, and the speed of its mass centre over its mean "
                       "(the spread of which is eq. 28's deviation ratio).",
    "fig19_20_histories.png": "Figs. 19-20: cage slip and the slip of roller 1 against time, "
                              "same runs.",
    "pocket_play.png": "The steady and the planar model at their common case (2 kN, 6000 "
                       "r/min, no eccentricity) against the pocket clearance: the steady "
                       "model holds each roller at the cage's orbit speed, the planar one "
                       "lets it move across its pocket's play; as the play closes, so does "
                       "the gap between them.",
    "three_models.png": "The steady, planar and spatial models at their common case (2 kN, "
                        "6000 r/min, no eccentricity, no misalignment), each step one named "
                        "term of model form: the pocket film over the paper's 1 rad or over "
                        "the spatial pockets' arcs, the rollers' free play in the planar "
                        "pockets, the share of the end faces under oil.",
}


def _title(data, *names, note: str = "") -> str:
    """A result's bearing and the inputs ``names`` it holds fixed, as read from the file, then
    ``note``."""
    return conditions(data, *names, width=None) + (f"; {note}" if note else "")


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _fig17(results, figures)

    orbit = result(results, "roller_slip_orbit")
    figure, axis = subplots(figsize=(6, 3.8))
    for load in orbit.radial_load.values:
        point = orbit.sel(radial_load=load)
        angle = (point.orbit_angle + 180) % 360 - 180
        order = np.argsort(angle.values)
        axis.plot(angle.values[order], point.roller_slip.values[order],
                  label=f"{load:g} {orbit.radial_load.attrs['units']}")
    axis.set(xlabel="orbit position from the load line [deg]",
             ylabel=label(orbit.roller_slip, long=True),
             title=_title(orbit, "speed", "oil_temperature", note="steady model"))
    axis.title.set_fontsize(9)
    axis.legend(fontsize=7, title="radial load", title_fontsize=7)
    axis.grid(alpha=0.3)
    save(figure, figures, "roller_slip_orbit.png")

    spin = result(results, "nu2330_spin")
    figure, axis = subplots(figsize=(6.8, 3.8))
    axis.plot(spin.oil_temperature, spin.roller_spin_ratio, "o-", ms=3, label="ours (steady)")
    for value, text, style in ((84.6, "paper, simulated", ":"), (82.7, "paper, measured",
                                                                  "--")):
        axis.axhline(value, ls=style, color="k", lw=1, label=f"{text}: {value:g} %")
    axis.set(xlabel=label(spin.oil_temperature, long=True),
             ylabel=label(spin.roller_spin_ratio, long=True),
             title=_title(spin, "radial_load", "speed", note="Fig. 13 of paper 002"))
    axis.title.set_fontsize(9)
    axis.legend(fontsize=7, loc="center right")
    axis.grid(alpha=0.3)
    save(figure, figures, "nu2330_spin.png")

    figure, axes = subplots(1, 3, figsize=(13, 4.1), sharey=True)
    for axis, (name, variable) in zip(axes, (("temperature", "oil_temperature"),
                                             ("traction", "traction_peak_speed"),
                                             ("oil_fraction", "oil_fraction"))):
        data = result(results, f"sensitivity_{name}")
        family(axis, data[variable], data.cage_slip, "radial_load",
               "{:g} " + data.radial_load.attrs["units"],
               xlabel=label(data[variable], long=True), yscale="log")
        axis.get_legend().set_title("radial load", prop={"size": 7})
    axes[0].set_ylabel(label(data.cage_slip, long=True))
    figure.suptitle(_title(data, "speed", note="each input at its default where not on the x "
                           "axis; steady model, high-slip branch"), fontsize=9)
    save(figure, figures, "sensitivity.png")
    _transient(results, figures)
    _pocket_play(results, figures)
    _three_models(results, figures)


def _settled_roller_slip(run):
    """The planar model's roller slip over its rollers and the settled second half."""
    half = run.sample_time >= 0.5 * run.sample_time.max()
    return run.roller_slip.where(half).mean(("elapsed_time", "roller"))


def _three_model_rows(results: Path) -> list[tuple[str, float, float, str]]:
    """Cage slip and mean roller slip [%] of the three models at their common case, with the
    terms that set each apart: (name, cage slip, roller slip, colour)."""
    steady = result(results, "three_models_steady")
    planar = result(results, "three_models_planar")
    spatial = result(results, "three_models_spatial")
    rows = []
    for film, text in (("1 rad", "paper's pocket film (1 rad)"),
                       ("4.375 rad", "film over the spatial arcs")):
        point = at(steady, pocket_wrap_angle=film)
        rows.append((f"steady, {text}", float(point.cage_slip),
                     float(point.roller_slip.mean("orbit")), "C0"))
        point = at(planar, pocket_wrap_angle=film)
        rows.append((f"planar, {text}", float(point.mean_cage_slip),
                     float(_settled_roller_slip(point)), "C1"))
    for fill, text in ((0.25, "end films on 0.25 of the faces"),
                       (1.0, "end films on the whole faces")):
        point = spatial.sel(end_film_fill=fill)
        rows.append((f"spatial, {text}", float(point.mean_cage_slip),
                     float(point.mean_roller_slip), "C2"))
    return rows


def tables(results: Path) -> str:
    """The three models' slips at their common case, as the report shows them."""
    rows = _three_model_rows(Path(results))
    return "\n".join(["## The three cage models' numbers", "",
                      "Paper 002's test bearing, 2 kN, 6000 r/min, no eccentricity, no "
                      "misalignment; the transients' settled means.", "",
                      "| model, terms | cage slip [%] | mean roller slip [%] |",
                      "|---|---|---|",
                      *(f"| {name} | {cage:.3g} | {roller:.3g} |"
                        for name, cage, roller, _ in rows)])


def _three_models(results: Path, figures: Path):
    rows = _three_model_rows(results)
    spatial = result(results, "three_models_spatial")
    figure, axes = subplots(1, 2, figsize=(11, 3.9), sharey=True)
    places = np.arange(len(rows))[::-1]
    for axis, column, quantity in ((axes[0], 1, spatial.mean_cage_slip),
                                   (axes[1], 2, spatial.mean_roller_slip)):
        values = [row[column] for row in rows]
        axis.barh(places, values, color=[row[3] for row in rows], height=0.6)
        for place, value in zip(places, values):
            axis.text(value, place, f" {value:.3g}", va="center", fontsize=7)
        axis.set(xlabel=label(quantity, long=True))
        axis.set_xlim(0, 1.2 * max(values))
        axis.grid(alpha=0.3, axis="x")
    axes[0].set_yticks(places, [row[0] for row in rows], fontsize=8)
    axes[0].set_ylabel("model and the terms it takes")
    figure.suptitle(_title(spatial, "radial_load", "speed", note="no eccentricity, no "
                           "misalignment; transients: settled mean"), fontsize=9)
    save(figure, figures, "three_models.png")


def _pocket_play(results: Path, figures: Path):
    steady = result(results, "pocket_play_steady")
    planar = result(results, "pocket_play_planar")
    clearance = steady.pocket_clearance
    ratio = planar.mean_cage_slip.values / steady.cage_slip.values
    figure, (slips, gap) = subplots(1, 2, figsize=(10, 3.9))
    slips.plot(clearance, steady.cage_slip, "-", color="C0", label="steady model")
    slips.plot(planar.pocket_clearance, planar.mean_cage_slip, "o", color="C1",
               label="planar transient, settled mean")
    slips.set(xlabel=label(clearance, long=True), ylabel=label(steady.cage_slip, long=True),
              xscale="log")
    slips.legend(fontsize=7)
    gap.plot(clearance, ratio, "o-", color="C1")
    gap.axhline(1.0, color="k", lw=1, ls=":")
    gap.set(xlabel=label(clearance, long=True),
            ylabel="cage slip, planar over steady [-]", xscale="log")
    for axis in (slips, gap):
        axis.grid(alpha=0.3)
    figure.suptitle(_title(steady, "radial_load", "speed", note="no eccentricity"),
                    fontsize=9)
    save(figure, figures, "pocket_play.png")


def _fig17(results: Path, figures: Path):
    data = result(results, "fig17_load_speed")
    load = data.radial_load
    figure, axis = subplots(figsize=(6.5, 4.4))
    for index, speed in enumerate(("6000 rpm", "9000 rpm", "12000 rpm")):
        colour = f"C{index}"
        high, low = (at(data, speed=speed, branch=b) for b in ("high_slip", "low_slip"))
        several = (high.equilibrium_count >= 2).values
        axis.plot(load, high.cage_slip, "-", color=colour, lw=1.2, label=f"{speed}")
        axis.plot(load.values[several], low.cage_slip.values[several], "--", color=colour,
                  lw=1.2)
        step = float(load[1] - load[0])
        for value in load.values[several]:
            axis.axvspan(value - step / 2, value + step / 2, color=colour, alpha=0.25, lw=0)
    axis.plot([], [], "k-", lw=1.2, label="high-slip branch (from rest)")
    axis.plot([], [], "k--", lw=1.2, label="low-slip branch")
    axis.fill_between([], [], color="grey", alpha=0.3, label="two stable equilibria")
    axis.set(xlabel=label(load, long=True), ylabel=label(data.cage_slip, long=True),
             yscale="log", title=_title(data, "oil_temperature",
                                        note="steady model; Fig. 17 of paper 002"))
    axis.title.set_fontsize(9)
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)
    save(figure, figures, "fig17_load_speed.png")


def _drifting(cage_slip) -> np.ndarray:
    """Whether each run's cage slip still drifts: its means over the last two quarters of the
    run differ by more than 5 % of their mean."""
    time = cage_slip.dims[-1]
    quarter = cage_slip.sizes[time] // 4
    third = cage_slip.isel({time: slice(-2 * quarter, -quarter)}).mean(time)
    last = cage_slip.isel({time: slice(-quarter, None)}).mean(time)
    return (abs(last - third) > 0.05 * 0.5 * (last + third)).values


def _duration(data) -> str:
    """A transient result's bearing time, as its file states it."""
    return conditions(data, "duration", width=None, preset=False).removeprefix("duration = ")


def _transient(results: Path, figures: Path):
    steady = at(result(results, "fig17_load_speed"), branch="high_slip")
    data = result(results, "fig17_transient")
    spatial = result(results, "fig17_transient_spatial")
    figure, axis = subplots(figsize=(6.5, 4.2))
    for index, speed in enumerate(data.speed.values):
        text = f"{speed:g} {data.speed.attrs['units']}"
        axis.plot(steady.radial_load, at(steady, speed=text).cage_slip, color=f"C{index}",
                  label=f"{text}, steady")
        axis.plot(data.radial_load, at(data, speed=text).mean_cage_slip, "o",
                  color=f"C{index}", label=f"{text}, planar transient")
        run = at(spatial, speed=text)
        axis.plot(spatial.radial_load, run.mean_cage_slip, "s", mfc="none",
                  color=f"C{index}", label=f"{text}, spatial transient")
        drifting = _drifting(run.cage_slip)
        axis.plot(spatial.radial_load[drifting], run.mean_cage_slip[drifting], "x", ms=4,
                  color=f"C{index}")
    axis.plot([], [], "kx", ms=4, label="spatial, still drifting (> 5 % between\n"
                                       "the last two quarters of the run)")
    axis.set(xlabel=label(data.radial_load, long=True),
             ylabel=label(data.mean_cage_slip, long=True), yscale="log",
             title=f"{data.attrs['bearing']}; transients: mean over the second half of "
                   f"{_duration(data)} (planar), {_duration(spatial)} (spatial)")
    axis.title.set_fontsize(9)
    axis.legend(fontsize=7, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.16))
    axis.title.set_fontsize(8)
    axis.grid(alpha=0.3)
    save(figure, figures, "fig17_transient.png")

    runs = result(results, "fig18_20_eccentricity")
    settled = runs.sample_time >= 0.5 * runs.sample_time.max()
    figure, axes = subplots(1, 2, figsize=(10.5, 4.3),
                                gridspec_kw={"width_ratios": [1, 1.4]})
    for index, eccentricity in enumerate(("0 mm", "2 mm")):
        run = at(runs, cage_eccentricity=eccentricity)
        keep = at(settled, cage_eccentricity=eccentricity).values
        ratio = float(run.whirl_deviation_ratio)
        name = rf"{eccentricity}: $\sigma_b$ = {ratio:.3f}"
        axes[0].plot(run.cage_centre_x.values[keep], run.cage_centre_y.values[keep], lw=0.5,
                     color=f"C{index}", alpha=0.8, label=name)
        speed = run.whirl_speed.values[keep]
        axes[1].plot(run.sample_time.values[keep], speed / speed.mean(), lw=0.7,
                     color=f"C{index}", label=name)
    axes[0].set(xlabel="cage geometric centre x [um]", ylabel="cage geometric centre y [um]",
                title="path of the cage's geometric centre")
    axes[0].set_aspect("equal", adjustable="datalim")
    axes[1].set(xlabel=label(runs.sample_time), ylabel="mass centre speed / its mean",
                title="speed of the cage's mass centre (eq. 28)")
    axes[0].legend(fontsize=7, title="cage mass eccentricity", title_fontsize=7,
                   loc="upper right")  # the path keeps to the middle of its panel
    for axis in axes:
        axis.title.set_fontsize(9)
        axis.grid(alpha=0.3)
    figure.suptitle(_title(runs, "radial_load", "speed", "duration",
                           note="planar transient, settled half"), fontsize=9)
    save(figure, figures, "fig18_whirl.png")

    figure, axes = subplots(1, 2, figsize=(10, 4.1))
    for eccentricity in runs.cage_eccentricity.values:
        run = runs.sel(cage_eccentricity=eccentricity)
        text = f"{eccentricity:g} {runs.cage_eccentricity.attrs['units']}"
        axes[0].plot(run.sample_time, run.cage_slip, lw=0.8, label=text)
        axes[1].plot(run.sample_time, run.roller_slip.sel(roller=1), lw=0.8, label=text)
    axes[0].set(xlabel=label(runs.sample_time), ylabel=label(runs.cage_slip, long=True))
    axes[1].set(xlabel=label(runs.sample_time), ylabel="roller 1: spin slip "
                f"[{shown_unit(runs.roller_slip.attrs['units'])}]")
    for axis in axes:
        axis.grid(alpha=0.3)
    axes[1].legend(fontsize=7, title="cage mass eccentricity", title_fontsize=7,
                   loc="center left", bbox_to_anchor=(1.02, 0.5))  # beside the histories
    figure.suptitle(_title(runs, "radial_load", "speed", note="planar transient"), fontsize=9)
    save(figure, figures, "fig19_20_histories.png")


def ours(results: Path) -> dict:
    results = Path(results)
    data = at(result(results, "fig17_load_speed"), branch="high_slip").cage_slip
    grid = at(data, radial_load=[f"{f} N" for f in range(200, 1001, 50)])
    fast = at(grid, speed="12000 rpm")
    values = {
        "slip_800_12000": float(at(data, speed="12000 rpm", radial_load="800 N")),
        "falls_with_load": float((grid.diff("radial_load") < 0).mean()),
        "rises_with_speed": float((grid.diff("speed") > 0).mean()),
        "knee_12000": float((fast[:-1].values / fast[1:].values).max()),
    }
    runs = result(results, "fig18_20_eccentricity")
    free, eccentric = (at(runs, cage_eccentricity=e) for e in ("0 mm", "2 mm"))
    values["eccentricity_steadies_whirl"] = float(free.whirl_deviation_ratio
                                                  / eccentric.whirl_deviation_ratio)
    values["eccentricity_raises_slip"] = float(eccentric.mean_cage_slip / free.mean_cage_slip)
    transient = result(results, "fig17_transient").mean_cage_slip
    values["transient_slip_800_12000"] = float(at(transient, speed="12000 rpm",
                                                  radial_load="800 N"))
    spatial = result(results, "fig17_transient_spatial").mean_cage_slip
    values["spatial_transient_slip_800_12000"] = float(at(spatial, speed="12000 rpm",
                                                          radial_load="800 N"))
    values["spatial_transient_falls_with_load"] = float((spatial.diff("radial_load") < 0)
                                                        .mean())
    values["spatial_transient_rises_with_speed"] = float((spatial.diff("speed") > 0).mean())
    spin = result(results, "nu2330_spin").roller_spin_ratio
    values["nu2330_spin_ratio"] = float(at(spin, oil_temperature="25 degC", method="nearest"))
    values["nu2330_spin_ratio_lowest"] = float(spin.min())
    return values
