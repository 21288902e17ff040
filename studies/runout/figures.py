"""Paper 004's figures on runout (Figs. 7-12) and two studies beyond it, from the netCDF
results only."""
from pathlib import Path

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from bearing_sweep import analyze
from bearing_sweep.plotting import (at, conditions, family, histogram, label, result, save,
                                    sobol_bars, subplots)

FIGURES = {
    "fig07_table3.png": "Fig. 7: runout of NU208 number 1 for the roller size arrangements of "
                        "Table 3 (rows 1-21).",
    "fig08_amplitude.png": "Fig. 8: runout against roller roundness amplitude; even orders "
                           "solid, odd dashed (all on zero).",
    "fig09_10_order.png": "Figs. 9-10: runout against roller roundness order for 12-15 rollers "
                          "(amplitude 0.5 um, equal phases), at whole orders only; filled: "
                          "even orders (Fig. 10), open: odd orders; dotted: multiples of Z.",
    "fig11_table4.png": "Fig. 11: runout for the roller order arrangements of Table 4; light "
                        "bars: rows 10-15 with the odd-order rollers made round.",
    "fig12_roller_count.png": "Fig. 12: runout against the number of rollers for even orders "
                              "(amplitude 0.5 um, equal phases).",
    "monte_carlo_phases.png": "Beyond the paper: runout with random roller phases (200 draws "
                              "for each order) against the paper's equal phases (dotted).",
    "selective_assembly.png": "Beyond the paper: runout over 500 random assembly orders of the "
                              "roller set of Table 3 row 19, with the paper's increasing and "
                              "alternating orders.",
    "tolerances.png": "Beyond the paper: runout of NU208 with rollers of grade G2 (diameter "
                      "+-1 um, oval up to 0.5 um, random phases) and an inner raceway oval "
                      "up to 1 um: its spread in random and selective assembly of the same "
                      "roller sets, and which tolerance drives it (Sobol' indices, 95 % "
                      "intervals).",
}


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _table3(results, figures)
    _amplitude(results, figures)
    _order(results, figures)
    _table4(results, figures)
    _roller_count(results, figures)
    _phases(results, figures)
    _assembly(results, figures)
    _tolerances(results, figures)


def _table3(results, figures):
    data = result(results, "fig07_table3")
    figure, axis = subplots(figsize=(8, 3.6))
    _zero_marked(axis, axis.bar(np.arange(1, data.arrangement.size + 1), data.runout))
    axis.set(xlabel="arrangement (row of Table 3)", ylabel=label(data.runout),
             xticks=np.arange(1, data.arrangement.size + 1))
    axis.set_title(conditions(data, "roller_count") + "; roller diameter errors of Table 3, "
                   "raceways and rollers otherwise round", fontsize=9)
    axis.grid(alpha=0.3, axis="y")
    save(figure, figures, "fig07_table3.png")


def _zero_marked(axis, bars):
    """Write 0 on the bars of no runout, which would otherwise look like missing ones."""
    axis.bar_label(bars, labels=["0" if abs(bar.get_height()) < 5e-4 else "" for bar in bars],
                   fontsize=7)


def _amplitude(results, figures):
    data = result(results, "fig08_amplitude")
    figure, axis = subplots(figsize=(5.5, 3.8))
    for order in data.roller_roundness_order.values:
        axis.plot(data.roller_roundness_amplitude, data.runout.sel(roller_roundness_order=order),
                  "o-" if order % 2 == 0 else "x--", ms=3, label=f"order {order:g}")
    axis.set(xlabel=label(data.roller_roundness_amplitude), ylabel=label(data.runout))
    axis.set_title(conditions(data, "roller_count", "roller_roundness_phase", width=70)
                   + "\nthe same harmonic on every roller; odd orders all on zero", fontsize=8)
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)
    save(figure, figures, "fig08_amplitude.png")


def _order(results, figures):
    """One row per roller count; a stem at each whole order (no line between orders, which
    do not exist in between); even orders filled, odd orders open; dotted: multiples of Z."""
    data = result(results, "fig09_10_order")
    orders = data.roller_roundness_order.values
    even = orders % 2 == 0
    counts = data.roller_count.values
    figure, axes = subplots(counts.size, 1, figsize=(10, 1.7 * counts.size + 1.4),
                                sharex=True, sharey=True)
    for index, (axis, count) in enumerate(zip(np.atleast_1d(axes), counts)):
        runout = data.runout.sel(roller_count=count).values
        color = f"C{index}"
        for multiple in np.arange(count, orders.max() + 1, count):
            axis.axvline(multiple, color="0.4", ls="--", lw=0.8, zorder=0)
        axis.vlines(orders, 0, runout, color=color, lw=1, alpha=0.5)
        axis.plot(orders[even], runout[even], "o", color=color, ms=4)
        axis.plot(orders[~even], runout[~even], "o", mfc="white", color=color, ms=4)
        axis.set_ylabel(f"Z = {count}\n{label(data.runout)}")
        axis.grid(alpha=0.3, axis="y")
    axis.set(xlabel="roller roundness order n", xticks=np.arange(0, orders.max() + 1, 2),
             xlim=(orders.min() - 1, orders.max() + 1))
    keys = [Line2D([], [], marker="o", ls="", color="k", label="even order"),
            Line2D([], [], marker="o", ls="", color="k", mfc="white", label="odd order"),
            Line2D([], [], color="0.4", ls="--", lw=0.8, label="multiple of Z")]
    axis.legend(handles=keys, fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.32),
                ncol=3)
    figure.suptitle(conditions(data, "roller_roundness_amplitude", "roller_roundness_phase",
                               width=None) + " (the same harmonic on every roller)",
                    fontsize=9)
    save(figure, figures, "fig09_10_order.png")


def _table4(results, figures):
    data = result(results, "fig11_table4")
    rows = [label for label in data.arrangement.values if not label.endswith("e")]
    figure, axis = subplots(figsize=(8, 3.6))
    _zero_marked(axis, axis.bar(np.arange(len(rows)), data.runout.sel(arrangement=rows),
                                label="Table 4"))
    round_odd = [f"{label}e" for label in rows if f"{label}e" in data.arrangement.values]
    positions = [rows.index(label[:-1]) for label in round_odd]
    axis.bar(positions, data.runout.sel(arrangement=round_odd), width=0.4, alpha=0.5,
             label="odd-order rollers round")
    axis.set(xlabel="arrangement (row of Table 4)", ylabel=label(data.runout),
             xticks=np.arange(len(rows)), xticklabels=rows)
    amplitude = data.roller_roundness_amplitude.where(data.roller_roundness_amplitude > 0)
    axis.set_title(conditions(data, "roller_count", "roller_roundness_phase") + "\namplitude "
                   f"{float(amplitude.max()):g} {amplitude.units} on every out-of-round roller",
                   fontsize=9)
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3, axis="y")
    save(figure, figures, "fig11_table4.png")


def _roller_count(results, figures):
    data = result(results, "fig12_roller_count")
    figure, axis = subplots(figsize=(6.5, 3.8))
    family(axis, data.roller_count, data.runout, "roller_roundness_order", "order {:g}",
           xlabel="number of rollers Z", ylabel=label(data.runout),
           xticks=data.roller_count.values)
    axis.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5))
    axis.set_title(conditions(data, "roller_roundness_amplitude", "roller_roundness_phase",
                              width=60), fontsize=8)
    save(figure, figures, "fig12_roller_count.png")


def _phases(results, figures):
    data = result(results, "monte_carlo_phases")
    count = int(data.roller_count)
    equal = at(result(results, "fig09_10_order"), roller_count=count)
    orders = data.roller_roundness_order.values
    figure, axes = subplots(orders.size, 1, figsize=(6, 1.9 * orders.size + 1.2),
                                sharex=True)
    bins = np.arange(0.0, float(data.runout.max()) + 0.04, 0.02)
    for index, (axis, order) in enumerate(zip(np.atleast_1d(axes), orders)):
        axis.hist(data.runout.sel(roller_roundness_order=order), bins=bins, color=f"C{index}")
        axis.axvline(float(at(equal.runout, roller_roundness_order=order)), color="k", ls=":")
        axis.set(ylabel="draws", title=f"order {order:g}")
        axis.grid(alpha=0.3, axis="y")
    axis.set_xlabel(label(data.runout))
    keys = [Patch(color="0.5", label=f"random phases ({data.phase_seed.size} draws)"),
            Line2D([], [], color="k", ls=":", label="equal phases (Figs. 9-10)")]
    axis.legend(handles=keys, fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.4),
                ncol=2)
    figure.suptitle(conditions(data, "roller_count", "roller_roundness_amplitude", width=None),
                    fontsize=9)
    save(figure, figures, "monte_carlo_phases.png")


def _assembly(results, figures):
    data = result(results, "selective_assembly")
    table3 = result(results, "fig07_table3")
    figure, axis = subplots(figsize=(5.5, 3.8))
    axis.hist(data.runout, bins=30, color="C0", alpha=0.7,
              label=f"random orders ({data.order_seed.size})")
    for row, text, color in ((19, "increasing (row 19)", "C3"), (20, "alternating (row 20)",
                                                                  "C2")):
        axis.axvline(float(table3.runout.sel(arrangement=row)), color=color, label=text)
    axis.set(xlabel=label(data.runout), ylabel="orders")
    axis.set_title(conditions(data, "roller_count", "roller_diameter_error", width=60),
                   fontsize=8)
    axis.legend(fontsize=7, loc="upper left")
    save(figure, figures, "selective_assembly.png")


_SHORT = {"roller_diameter_error": "diameter", "roller_roundness_amplitude":
          "roundness\namplitude", "roller_roundness_phase": "roundness\nphase",
          "inner_roundness_amplitude": "inner\nraceway"}


def assembly_gain(data) -> dict:
    """Selective assembly on the same roller sets: runout alternated by size over runout in
    the order drawn, per set, over the independent samples (a Saltelli design's A and B)."""
    independent = data.runout.where(data.saltelli_block < 2, drop=True)
    drawn = independent.sel(roller_arrangement="as_given")
    ratio = (independent.sel(roller_arrangement="alternating") / drawn).values
    return {"median_ratio": float(np.median(ratio)), "improved": float(np.mean(ratio < 1)),
            "sets": ratio.size}


def _tolerances(results, figures):
    data = result(results, "tolerances")
    analysis = analyze(data)
    figure, axes = subplots(1, 3, figsize=(13, 3.8))
    edges = np.linspace(0.0, float(data.runout.max()), 31)
    for arrangement, text in (("as_given", "random (as drawn)"),
                              ("alternating", "sorted, alternated")):
        histogram(axes[0], data, "runout", bins=edges, style={"alpha": 0.6, "label": text},
                  roller_arrangement=arrangement)
    gain = assembly_gain(data)
    axes[0].set_title(f"{gain['sets']} roller sets; alternated / random: median "
                      f"{gain['median_ratio']:.2f}, lower for {100 * gain['improved']:.0f} %",
                      fontsize=8)
    axes[0].legend(fontsize=7)
    for axis, arrangement, text in ((axes[1], "as_given", "random assembly"),
                                    (axes[2], "alternating", "selective assembly")):
        sobol_bars(axis, analysis, "runout", roller_arrangement=arrangement)
        axis.set_xticks(axis.get_xticks(), [_SHORT[name] for name in analysis.input.values])
        axis.set_title(text, fontsize=9)
    figure.suptitle(conditions(data, "roller_count", "roller_roundness_order", width=None)
                    + f"; Saltelli, {data.attrs['sample_replicates']} replicates of n = "
                    f"{data.attrs['sample_size']}", fontsize=9)
    figure.tight_layout()
    save(figure, figures, "tolerances.png")


def _runout(data, **where) -> float:
    return float(data.runout.sel(**where))


def ours(results: Path) -> dict:
    results = Path(results)
    table3 = result(results, "fig07_table3")
    row = {int(a): _runout(table3, arrangement=a) for a in table3.arrangement.values}
    values = {
        "alternating_over_increasing": 100 * row[20] / row[19],
        "single_error_linear": (row[2] / 1.0) / (row[5] / 0.2),
        "adjacent_raise": row[9] / row[2],
        "three_adjacent_raise": row[12] / row[9],
        "mixed_below_grouped": row[18] / row[17],
    }
    amplitude = result(results, "fig08_amplitude")
    odd = amplitude.runout.sel(roller_roundness_order=[3, 5, 7])
    values["odd_orders_effect"] = float(odd.max())
    for order in (2, 4, 6):
        series = amplitude.runout.sel(roller_roundness_order=order)
        values[f"amplitude_linear_{order}"] = float(
            at(series, roller_roundness_amplitude="1 um")
            / (2 * at(series, roller_roundness_amplitude="0.5 um")))
    order = result(results, "fig09_10_order")
    values["period_even_z"] = _period_gap(order, 14, 14)
    values["period_odd_z"] = _period_gap(order, 13, 26)
    values["odd_orders_in_fig9"] = float(order.runout.sel(
        roller_roundness_order=order.roller_roundness_order % 2 == 1).max())
    values["extremes_even_z"] = float(_matches(order, 14, [14, 28, 42], [6, 8, 20, 22, 34, 36]))
    values["extremes_z12"] = float(_matches(order, 12, [12, 24, 36], [6, 18, 30, 42]))
    values["extremes_odd_z"] = float(_matches(order, 13, [12, 14, 26, 38, 40], [6, 20, 32])
                                     and _matches(order, 15, [14, 16, 30], [8, 22, 38]))
    table4 = result(results, "fig11_table4")
    t4 = {str(a): _runout(table4, arrangement=a) for a in table4.arrangement.values}
    values["two_even_orders_raise"] = min(t4[r] for r in "345") / max(t4["1"], t4["2"])
    values["odd_orders_mixed"] = max(t4[r] for r in "6789")
    values["only_even_rollers_matter"] = max(abs(t4[str(r)] - t4[f"{r}e"]) for r in
                                             range(10, 16))
    count = result(results, "fig12_roller_count").runout
    values["more_rollers_not_always_better"] = float((count.diff("roller_count") > 0).sum())
    return values


def _period_gap(data, roller_count, period) -> float:
    """Largest change of the runout between orders ``period`` apart [um]."""
    series = data.runout.sel(roller_count=roller_count)
    orders = series.roller_roundness_order.values
    shifted = series.sel(roller_roundness_order=orders[orders + period <= orders.max()] + period)
    base = series.sel(roller_roundness_order=orders[orders + period <= orders.max()])
    return float(np.abs(shifted.values - base.values).max())


def _matches(data, roller_count, maxima, minima) -> bool:
    """Whether the even orders' local maxima and minima fall on the stated orders."""
    series = data.runout.sel(roller_count=roller_count)
    even = series.sel(roller_roundness_order=series.roller_roundness_order % 2 == 0)
    orders, value = even.roller_roundness_order.values, even.values
    inner = np.arange(1, value.size - 1)
    tie = 1e-4  # um: equal extremes at two neighbouring orders (Z = 13: 12 and 14) both count
    peak = inner[(value[inner] >= value[inner - 1] - tie) & (value[inner] >= value[inner + 1]
                                                              - tie)]
    dip = inner[(value[inner] <= value[inner - 1] + tie) & (value[inner] <= value[inner + 1]
                                                            + tie)]
    stated_max = [m for m in maxima if orders[0] < m < orders[-1]]
    stated_min = [m for m in minima if orders[0] < m < orders[-1]]
    return (sorted(stated_max) == sorted(orders[peak].tolist())
            and sorted(stated_min) == sorted(orders[dip].tolist()))
