"""Paper 002's cage slip trends (Figs. 13, 17, 20 in steady state) and the sensitivity to the
inputs it does not state, from the netCDF results only."""
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from sweeps.plotting import family, label, result, save

FIGURES = {
    "fig17_load_speed.png": "Fig. 17: steady cage slip of the test bearing against radial load "
                            "at 6000, 9000 and 12000 r/min (room-temperature oil, documented "
                            "defaults for the unstated oil, traction and drag).",
    "roller_slip_orbit.png": "Steady counterpart of Fig. 20: roller spin slip around the orbit "
                             "at 12000 r/min (0 deg: the load line; the load zone is about "
                             "+-70 deg).",
    "nu2330_spin.png": "Fig. 13: NU2330EM1 mean roller spin over its kinematic value at "
                       "1000 r/min and 50 kN against oil temperature; dotted: the paper's "
                       "84.6 % (simulated) and 82.7 % (measured).",
    "sensitivity.png": "Beyond the paper: cage slip at 12000 r/min against the inputs the paper "
                       "does not state: oil temperature, traction peak speed, cavity oil "
                       "fraction.",
    "fig17_transient.png": "Fig. 17 again: settled mean cage slip of the transient model (dots) "
                           "beside the steady model (lines).",
    "fig18_whirl.png": "Fig. 18: whirl orbit of the cage's mass centre over the settled half, "
                       "800 N, 12000 r/min, without and with 2 mm radial cage eccentricity, "
                       "and the speed deviation ratio of eq. 28.",
    "fig19_20_histories.png": "Figs. 19-20: cage slip and the slip of roller 1 against time, "
                              "same runs.",
}


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    data = result(results, "fig17_load_speed")
    figure, axis = plt.subplots(figsize=(5.5, 3.8))
    family(axis, data.radial_load, data.cage_slip, "speed", "{:g} r/min",
           xlabel=label(data.radial_load), ylabel=label(data.cage_slip), yscale="log")
    save(figure, figures, "fig17_load_speed.png")

    orbit = result(results, "roller_slip_orbit")
    figure, axis = plt.subplots(figsize=(6, 3.8))
    for load in orbit.radial_load.values:
        point = orbit.sel(radial_load=load)
        angle = (point.orbit_angle + 180) % 360 - 180
        order = np.argsort(angle.values)
        axis.plot(angle.values[order], point.roller_slip.values[order], label=f"{load:g} N")
    axis.set(xlabel="orbit position from the load line [deg]", ylabel=label(orbit.roller_slip))
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)
    save(figure, figures, "roller_slip_orbit.png")

    spin = result(results, "nu2330_spin")
    figure, axis = plt.subplots(figsize=(5.5, 3.8))
    axis.plot(spin.oil_temperature, spin.roller_spin_ratio, "o-", ms=3)
    for value in (84.6, 82.7):
        axis.axhline(value, ls=":", color="k", lw=1)
    axis.set(xlabel=label(spin.oil_temperature), ylabel=label(spin.roller_spin_ratio))
    axis.grid(alpha=0.3)
    save(figure, figures, "nu2330_spin.png")

    figure, axes = plt.subplots(1, 3, figsize=(13, 3.8), sharey=True)
    for axis, (name, variable) in zip(axes, (("temperature", "oil_temperature"),
                                             ("traction", "traction_peak_speed"),
                                             ("oil_fraction", "oil_fraction"))):
        data = result(results, f"sensitivity_{name}")
        family(axis, data[variable], data.cage_slip, "radial_load", "{:g} N",
               xlabel=label(data[variable]), yscale="log")
    axes[0].set_ylabel(label(data.cage_slip))
    save(figure, figures, "sensitivity.png")
    _transient(results, figures)


def _transient(results: Path, figures: Path):
    steady = result(results, "fig17_load_speed")
    data = result(results, "fig17_transient")
    figure, axis = plt.subplots(figsize=(5.5, 3.8))
    for index, speed in enumerate(data.speed.values):
        axis.plot(steady.radial_load, steady.cage_slip.sel(speed=speed), color=f"C{index}",
                  label=f"{speed:g} r/min, steady")
        axis.plot(data.radial_load, data.mean_cage_slip.sel(speed=speed), "o",
                  color=f"C{index}", label=f"{speed:g} r/min, transient")
    axis.set(xlabel=label(data.radial_load), ylabel=label(data.mean_cage_slip), yscale="log")
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)
    save(figure, figures, "fig17_transient.png")

    runs = result(results, "fig18_20_eccentricity")
    settled = runs.sample_time >= 0.5 * runs.sample_time.max()
    figure, axes = plt.subplots(1, 2, figsize=(9, 4.2))
    for axis, eccentricity in zip(axes, runs.cage_eccentricity.values):
        run = runs.sel(cage_eccentricity=eccentricity)
        keep = settled.sel(cage_eccentricity=eccentricity)
        axis.plot(run.cage_x.where(keep), run.cage_y.where(keep), lw=0.6)
        ratio = float(run.whirl_deviation_ratio)
        axis.set(xlabel=label(run.cage_x), ylabel=label(run.cage_y), aspect="equal",
                 title=f"eccentricity {eccentricity:g} mm, sigma_b = {ratio:.3f}")
        axis.grid(alpha=0.3)
    save(figure, figures, "fig18_whirl.png")

    figure, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    for eccentricity in runs.cage_eccentricity.values:
        run = runs.sel(cage_eccentricity=eccentricity)
        axes[0].plot(run.sample_time, run.cage_slip, lw=0.8, label=f"{eccentricity:g} mm")
        axes[1].plot(run.sample_time, run.roller_slip.sel(roller=1), lw=0.8,
                     label=f"{eccentricity:g} mm")
    axes[0].set(xlabel=label(runs.sample_time), ylabel=label(runs.cage_slip))
    axes[1].set(xlabel=label(runs.sample_time), ylabel="roller 1: " + label(runs.roller_slip))
    for axis in axes:
        axis.legend(fontsize=7, title="cage eccentricity")
        axis.grid(alpha=0.3)
    save(figure, figures, "fig19_20_histories.png")


def ours(results: Path) -> dict:
    results = Path(results)
    data = result(results, "fig17_load_speed").cage_slip
    values = {
        "slip_800_12000": float(data.sel(speed=12000, radial_load=800)),
        "falls_with_load": float((data.diff("radial_load") < 0).mean()),
        "rises_with_speed": float((data.diff("speed") > 0).mean()),
        "knee_12000": float((data.sel(speed=12000)[:-1].values
                             / data.sel(speed=12000)[1:].values).max()),
    }
    runs = result(results, "fig18_20_eccentricity")
    free, eccentric = (runs.sel(cage_eccentricity=e) for e in runs.cage_eccentricity.values)
    values["eccentricity_steadies_whirl"] = float(free.whirl_deviation_ratio
                                                  / eccentric.whirl_deviation_ratio)
    values["eccentricity_raises_slip"] = float(eccentric.mean_cage_slip / free.mean_cage_slip)
    transient = result(results, "fig17_transient").mean_cage_slip
    values["transient_slip_800_12000"] = float(transient.sel(speed=12000, radial_load=800))
    spin = result(results, "nu2330_spin").roller_spin_ratio
    values["nu2330_spin_ratio"] = float(spin.sel(oil_temperature=25, method="nearest"))
    values["nu2330_spin_ratio_lowest"] = float(spin.min())
    return values
