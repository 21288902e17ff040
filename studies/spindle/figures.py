"""A machine-tool spindle on a preloaded pair of angular contact ball bearings and a
cylindrical roller bearing: nose stiffness, bearing loads, pressures and lives against span
and preload, and lives over a duty cycle, from the netCDF results only."""
from pathlib import Path

import numpy as np

from bearing_sweep.plotting import in_unit, result, save, subplots

FIGURES = {
    "span.png": "Spindle on a back-to-back pair of 71807AC bearings (front) and the NU bearing "
                "D of paper 000 (rear), 1 kN of cutting force at the nose: stiffness at the "
                "nose, the bearings' radial loads and largest contact pressures, and the "
                "system's reference life against the span, for three preloads of the pair; "
                "the crosses mark where the classic formula of a front bearing free to tilt "
                "puts the optimum span.",
    "duty_cycle.png": "The spindle at a span of 252.5 mm, medium preload: each bearing's "
                      "reference life in each cutting case and over the duty cycle "
                      "(Palmgren-Miner), and the system's (Weibull combination).",
}

#: The cutting force's distance to the front pair's centre, and the pair's centre [m].
OVERHANG = 0.0475
#: The shaft between the bearings: 55 mm with a 12 mm bore, steel [m^4, Pa].
SPAN_INERTIA = np.pi * (0.055**4 - 0.012**4) / 64
STEEL = 210e9
PRELOADS = {"light": "2 µm", "medium": "5 µm", "heavy": "10 µm"}
BEARINGS = {"front_a": "front, first", "front_b": "front, second", "rear": "rear"}


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _span(results, figures)
    _duty_cycle(results, figures)


def _nose_stiffness(data):
    """The stiffness against a radial force at the nose [N/µm]."""
    return in_unit(data.stiffness_at_load.sel(load="cutting", load_dof="radial_y",
                                              dof="radial_y"), "N/um")


def _span_of(data):
    """The bearing span, front pair's centre to rear bearing [mm]."""
    return in_unit(data.supports_rear_position, "mm").values - OVERHANG * 1e3


def classic_optimum(data) -> float:
    """The span [mm] that the classic formula of a spindle on two radial springs gives,
    L^3 - 6 E I L / (a k_A) - 6 E I (1/k_A + 1/k_B) = 0 (the nose deflection of an overhung
    beam on two springs, Roark's Formulas, Table 8.1, made stationary in L), with the front
    pair's and the rear bearing's radial stiffness (load over displacement) at ``data``'s
    stiffest span."""
    best = data.isel(supports_rear_position=int(np.argmax(_nose_stiffness(data).values)))
    force = in_unit(best.support_load.sel(dof="radial_y"), "N")
    moved = best.support_displacement.sel(dof="radial_y")  # [m] entry units
    front = float(force.sel(support=["front_a", "front_b"]).sum()
                  / moved.sel(support=["front_a", "front_b"]).mean())
    rear = float(force.sel(support="rear") / moved.sel(support="rear"))
    product = STEEL * SPAN_INERTIA
    roots = np.roots([1.0, 0.0, -6 * product / (OVERHANG * front),
                      -6 * product * (1 / front + 1 / rear)])
    return float(roots[np.isreal(roots)].real.max() * 1e3)


def _span(results, figures):
    data = result(results, "span")
    span = _span_of(data)
    figure, axes = subplots(2, 2, figsize=(11, 8))
    stiffness, loads, pressures, lives = axes.ravel()
    for index, (preload, shown) in enumerate(PRELOADS.items()):
        point = data.sel(preload=preload)
        nose = _nose_stiffness(point).values
        color = f"C{index}"
        stiffness.plot(span, nose, color=color, label=f"preload: clearance −{shown}")
        best = int(np.argmax(nose))
        stiffness.plot(span[best], nose[best], "o", color=color)
        stiffness.plot(classic_optimum(point), nose[best], "x", color=color, markersize=9)
        lives.semilogy(span, in_unit(point.system_reference_life, "Mturn"), color=color,
                       label=f"clearance −{shown}")
    medium = data.sel(preload="medium")
    for index, (support, name) in enumerate(BEARINGS.items()):
        bearing = medium.sel(support=support)
        loads.plot(span, in_unit(bearing.radial_support_load, "N"), color=f"C{index + 3}",
                   label=name)
        pressures.plot(span, in_unit(bearing.largest_contact_pressure, "MPa"),
                       color=f"C{index + 3}", label=name)
    stiffness.set(xlabel="bearing span [mm]", ylabel="radial stiffness at the nose [N/µm]",
                  title="Nose stiffness (dots: stiffest; crosses: classic optimum)")
    loads.set(xlabel="bearing span [mm]", ylabel="radial load on the bearing [N]",
              title="Bearing loads, medium preload")
    pressures.set(xlabel="bearing span [mm]", ylabel="largest contact pressure [MPa]",
                  title="Largest contact pressure, medium preload")
    lives.set(xlabel="bearing span [mm]", ylabel="system reference life L10r [10⁶ rev]",
              title="System life (Weibull combination)")
    for axis in (stiffness, loads, lives):
        axis.legend(fontsize=8)
    figure.suptitle("Spindle, 1 kN radial and 300 N axial cutting force at the nose, 47.5 mm "
                    "before the front pair", fontsize=9)
    save(figure, figures, "span.png")


def cycle_lives(data) -> dict:
    """Each bearing's reference life over the duty cycle and the system's [10^6 rev], as the
    result holds them."""
    lives = in_unit(data.reference_rating_life_over_duty_cycle, "Mturn")
    over = {support: float(lives.sel(support=support)) for support in BEARINGS}
    over["system"] = float(in_unit(data.system_reference_life_over_duty_cycle, "Mturn"))
    return over


def _duty_cycle(results, figures):
    data = result(results, "duty_cycle")
    lives = in_unit(data.reference_rating_life, "Mturn")
    over = cycle_lives(data)
    figure, axis = subplots(1, 1, figsize=(9, 4.5))
    cases = [str(case) for case in data.case.values]
    groups = cases + ["duty cycle"]
    width = 0.25
    for index, (support, name) in enumerate(BEARINGS.items()):
        heights = list(lives.sel(support=support).values) + [over[support]]
        axis.bar(np.arange(len(groups)) + (index - 1) * width, heights, width,
                 color=f"C{index + 3}", label=name)
    axis.axhline(over["system"], color="0.3", linestyle="--",
                 label=f"system over the cycle: {over['system']:.3g}")
    axis.set_yscale("log")
    shares = dict(zip(cases, data.time_share.values))
    axis.set_xticks(np.arange(len(groups)),
                    [f"{g} ({shares[g]:.0%})" if g in shares else g for g in groups])
    axis.set(xlabel="cutting case (time share)", ylabel="reference life L10r [10⁶ rev]",
             title="Lives by case and over the duty cycle")
    axis.legend(fontsize=8)
    save(figure, figures, "duty_cycle.png")


def ours(results: Path) -> dict:
    results = Path(results)
    data = result(results, "span")
    values = {}
    optimum = {}
    for preload in PRELOADS:
        point = data.sel(preload=preload)
        optimum[preload] = float(_span_of(point)[int(np.argmax(_nose_stiffness(point).values))])
    heavy = data.sel(preload="heavy")
    values["optimum_beyond_classic"] = optimum["heavy"] / classic_optimum(heavy)
    spans = list(optimum.values())
    values["optimum_shortens_with_preload"] = float(sum(
        later < earlier for earlier, later in zip(spans, spans[1:])))
    nose = _nose_stiffness(data)
    values["preload_stiffens"] = float(
        ((nose.sel(preload="medium") > nose.sel(preload="light"))
         & (nose.sel(preload="heavy") > nose.sel(preload="medium"))).sum())
    return values
