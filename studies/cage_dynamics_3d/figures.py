"""Paper 002's Figs. 18-33 from the spatial model ``cage_dynamics_6dof``: cage whirl, cage and
roller slip, roller skew and tilt, and the pocket, end-face and rib contacts, with cage mass
eccentricity (section 3.1) and ring misalignment (section 3.2), from the netCDF results only;
section 3.1's cases again with a thin pocket film (``eccentricity_thin_film``), under which the
pocket arcs can touch dry.
Results are selected by quantity (``at``) and shown in the units chosen here (``in_unit``),
whatever units the files store them in."""
import textwrap
from pathlib import Path

import matplotlib
import numpy as np
from matplotlib.colors import ListedColormap, Normalize, TwoSlopeNorm
from matplotlib.ticker import MaxNLocator

from bearing_sweep.plotting import at, conditions, in_unit, label, result, save, subplots

#: The paper's eccentricity cases (e_r, e_a), in the order of its legends.
CASES = (("0 mm", "0 mm"), ("2 mm", "0 mm"), ("0 mm", "2 mm"), ("2 mm", "2 mm"))
MISALIGNED = {"about_x": "1 deg about X", "about_y": "1 deg about Y"}
ROLLER = 1  # the roller whose histories are drawn (on the load line at the start)
_SETTLED = 0.5  # the model's settled part: the last half of each run
_OUTER_EDGE = 0.25  # the share of each pocket arc nearest the cage's outside diameter

_TIME = "elapsed time since the steady start"
FIGURES = {
    "fig18_whirl_eccentricity.png": "Fig. 18: path of the cage's geometric centre over the "
                                    "settled half for the four cage mass eccentricities "
                                    "(e_r, e_a); sigma_b: eq. 28's speed deviation ratio, of "
                                    "the mass centre's speed (mass, as the paper's caption) "
                                    "and of the geometric centre's (geom., as its text).",
    "fig19_cage_slip_eccentricity.png": "Fig. 19: cage slip against time for the four "
                                        "eccentricities.",
    "fig20_roller_slip_eccentricity.png": f"Fig. 20: spin slip of roller {ROLLER} against "
                                          "time for the four eccentricities.",
    "fig21_skew_eccentricity.png": f"Fig. 21: skew of roller {ROLLER} (its axis turned about "
                                   "the radial direction) against time.",
    "fig22_tilt_eccentricity.png": f"Fig. 22: tilt of roller {ROLLER} (its axis turned about "
                                   "the tangential direction) against time.",
    "fig23_arc_force_eccentricity.png": "Fig. 23: largest dry force of each pocket-arc "
                                        "element over the settled half, in the pocket with "
                                        "the largest force, for the four eccentricities "
                                        "(arc elements 1 and 16: the arcs' edges at the cage "
                                        "bore, 8 and 9: at its outside diameter); a run "
                                        "whose arcs never touch dry says so in its panel "
                                        "(the flooded film carries the rollers).",
    "fig24_end_clearance_eccentricity.png": "Fig. 24: smallest gap between the roller end "
                                            "faces and their pockets' end faces over the "
                                            "settled half and all rollers, e_r = e_a = 2 mm "
                                            "(negative: dry contact; grey: no cage face "
                                            "there). The face seen along the roller's axis, "
                                            "0 deg radially outwards.",
    "fig25_rib_clearance_eccentricity.png": "Fig. 25: smallest gap between the roller end "
                                            "faces and the inner ring's ribs, same run and "
                                            "view (grey: above the rib).",
    "fig26_whirl_misalignment.png": "Fig. 26: path of the cage's geometric centre over the "
                                    "settled half, aligned and with the inner ring turned "
                                    "1 deg about X and about Y; sigma_b of the mass centre "
                                    "(mass) and of the geometric centre (geom.), as in "
                                    "Fig. 18.",
    "fig27_cage_slip_misalignment.png": "Fig. 27: cage slip against time, misaligned and "
                                        "aligned.",
    "fig28_roller_slip_misalignment.png": f"Fig. 28: spin slip of roller {ROLLER} against "
                                          "time, misaligned and aligned.",
    "fig29_skew_misalignment.png": f"Fig. 29: skew of roller {ROLLER} against time, "
                                   "misaligned and aligned.",
    "fig30_tilt_misalignment.png": f"Fig. 30: tilt of roller {ROLLER} against time, "
                                   "misaligned and aligned.",
    "fig31_arc_force_misalignment.png": "Fig. 31: largest dry force of each pocket-arc "
                                        "element, 1 deg about X, in the pocket with the "
                                        "largest force.",
    "fig32_end_clearance_misalignment.png": "Fig. 32: smallest gap between the roller end "
                                            "faces and their pockets' end faces, 1 deg about "
                                            "X, all rollers.",
    "fig33_rib_clearance_misalignment.png": "Fig. 33: smallest gap between the roller end "
                                            "faces and the ribs, 1 deg about X, all rollers.",
    "fig23_arc_force_thin_film.png": "Fig. 23 with a thin pocket film (5 % of the arcs under "
                                     "oil): largest dry force of each pocket-arc element over "
                                     "the settled half, in the pocket with the largest force, "
                                     "for the four eccentricities (elements as in Fig. 23).",
    "fig21_skew_film_pressure.png": "Fig. 21 with the end films' pressure: the rollers' root "
                                    "mean square skew against time with the paper's end "
                                    "films (shear only, eq. 7; left), under which the "
                                    "centred cage's skew grows from round-off to the "
                                    "eccentric cases' after 45-50 ms, and with the films' "
                                    "squeeze and wedge pressure (right), under which only "
                                    "the axial eccentricity skews the rollers (the centred "
                                    "cage's 1e-5 to 1e-4 µrad are the integrator's error).",
    "skew_stability.png": "The aligned bearing at 2 kN, 6000 r/min, every roller started "
                          "with 1e-6 rad of skew: the rollers' root mean square skew against "
                          "time with the paper's end films (shear only, eq. 7), under which it "
                          "grows fast, and with the films' squeeze and wedge pressure, under "
                          "which it falls, then grows ten times slower.",
    "thin_film_summary.png": "Flooded pocket film against a thin one (5 % of the arcs under "
                             "oil) for the four eccentricities: settled mean cage slip and "
                             "roller slip, sigma_b of the mass centre and of the geometric "
                             "centre, and the dry pocket-arc contacts begun in the settled "
                             "half.",
}


def _eccentricity(results, sweep: str = "eccentricity"):
    """The runs of an eccentricity sweep as ``{(e_r, e_a): one run}``, and its whole dataset."""
    data = result(results, sweep)
    return {case: at(data, cage_eccentricity=case[0], cage_axial_eccentricity=case[1])
            for case in CASES}, data


def _misalignment(results):
    """The aligned run and the two misaligned ones, as ``{name: one run}``."""
    aligned = at(result(results, "eccentricity"), cage_eccentricity="0 mm",
                 cage_axial_eccentricity="0 mm")
    data = result(results, "misalignment")
    return {"aligned": aligned, **{name: data.sel(misalignment=name) for name in MISALIGNED}}


def _name(case) -> str:
    """A run's name as the paper writes it: its radial and axial cage mass eccentricity, or
    its misalignment."""
    if isinstance(case, tuple):
        return f"$e_r$ = {case[0]}, $e_a$ = {case[1]}"
    return MISALIGNED.get(case, case)


def _sigma(run) -> str:
    """Eq. 28's speed deviation ratio of the mass centre and of the geometric centre."""
    return (rf"$\sigma_b$ = {float(run.whirl_deviation_ratio):.3f} (mass centre), "
            f"{float(run.centre_whirl_deviation_ratio):.3f} (geometric)")


def _settled(run):
    return (run.elapsed_time >= _SETTLED * run.elapsed_time.max()).values


def _film(data) -> str:
    """The pocket film of a sweep, from its stored fill share."""
    share = float(in_unit(data.pocket_film_fill, "1"))
    return "flooded pocket film" if share == 1 else f"{share:.0%} of the pocket arcs under oil"


def _title(data, what: str, figure=None) -> str:
    """The conditions of a run and what the figure shows, wrapped to ``figure``'s width."""
    text = conditions(data, "radial_load", "speed", width=None) + "; " + what
    return text if figure is None else textwrap.fill(text, int(13 * figure.get_figwidth()))


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    runs, data = _eccentricity(results)
    _orbits(runs, data, figures, "fig18_whirl_eccentricity.png")
    _histories(runs, data, figures, "eccentricity", "cage mass eccentricity")
    _arc_maps(runs, data, figures, "fig23_arc_force_eccentricity.png")
    combined = runs[("2 mm", "2 mm")]
    _face_map(combined, "pocket_end_clearance", figures,
              "fig24_end_clearance_eccentricity.png", _name(("2 mm", "2 mm")))
    _face_map(combined, "rib_clearance", figures, "fig25_rib_clearance_eccentricity.png",
              _name(("2 mm", "2 mm")))
    turned = _misalignment(results)
    _orbits(turned, data, figures, "fig26_whirl_misalignment.png")
    _histories(turned, data, figures, "misalignment", "inner ring")
    _arc_maps({"about_x": turned["about_x"]}, data, figures,
              "fig31_arc_force_misalignment.png")
    _face_map(turned["about_x"], "pocket_end_clearance", figures,
              "fig32_end_clearance_misalignment.png", MISALIGNED["about_x"])
    _face_map(turned["about_x"], "rib_clearance", figures,
              "fig33_rib_clearance_misalignment.png", MISALIGNED["about_x"])
    thin, thin_data = _eccentricity(results, "eccentricity_thin_film")
    _arc_maps(thin, thin_data, figures, "fig23_arc_force_thin_film.png")
    _film_summary(runs, thin, thin_data, figures, "thin_film_summary.png")
    _skew_stability(result(results, "skew_stability"), figures, "skew_stability.png")
    _skew_film_pressure(runs, result(results, "eccentricity_film_pressure"), figures,
                        "fig21_skew_film_pressure.png")


#: The end films of the stability runs, as the legend names them.
FILMS = {"shear": "shear only (the paper's, eq. 7)",
         "reynolds": "with the film's pressure (squeeze and wedge)"}


def _skew_stability(data, figures: Path, file: str):
    """The rollers' rms skew against time, one line per end film, on a log scale."""
    figure, axis = subplots(figsize=(8.6, 3.9))
    for name, legend in FILMS.items():
        run = data.sel(films=name)
        axis.semilogy(in_unit(run.elapsed_time, "ms"), _rms_skew(run), label=legend)
    axis.set(xlabel=f"{_TIME} [ms]", ylabel="rollers' rms skew [µrad]")
    axis.legend(fontsize=7, title="end films", title_fontsize=7)
    axis.grid(alpha=0.3, which="both")
    axis.set_title(_title(data, "every roller started with 1 µrad of skew, aligned, centred "
                                "cage", figure), fontsize=9)
    save(figure, figures, file)


def _rms_skew(run):
    """The rollers' root mean square skew [urad] at each sample."""
    skew = in_unit(run.roller_skew, "urad")
    return np.sqrt((skew**2).mean("roller"))


def _skew_film_pressure(paper: dict, pressure, figures: Path, file: str):
    """Fig. 21 as the rollers' rms skew on a log scale: the paper's end films (the four
    eccentricities) beside the films with their pressure (centred and axially eccentric)."""
    figure, axes = subplots(1, 2, figsize=(11, 4.1), sharey=True)
    colours = {case: f"C{index}" for index, case in enumerate(CASES)}
    for case, run in paper.items():
        axes[0].semilogy(in_unit(run.elapsed_time, "ms"), _rms_skew(run), lw=0.7,
                         color=colours[case], label=_name(case))
    for case in (("0 mm", "0 mm"), ("0 mm", "2 mm")):
        run = at(pressure, cage_axial_eccentricity=case[1])
        axes[1].semilogy(in_unit(run.elapsed_time, "ms"), _rms_skew(run), lw=0.7,
                         color=colours[case], label=_name(case))
    for axis, what in zip(axes, ("end films: shear only (the paper's, eq. 7)",
                                 "end films with their squeeze and wedge pressure")):
        axis.set(xlabel=f"{_TIME} [ms]", title=what)
        axis.title.set_fontsize(9)
        axis.grid(alpha=0.3, which="both")
        axis.legend(fontsize=7, title="cage mass eccentricity", title_fontsize=7)
    axes[0].set_ylabel("rollers' rms skew [µrad]")
    figure.suptitle(_title(pressure, "Fig. 21 as the rollers' rms skew"), fontsize=9)
    save(figure, figures, file)


def _orbits(runs: dict, data, figures: Path, file: str):
    """One panel per run: the geometric centre's path over the settled half, in um."""
    figure, axes = subplots(1, len(runs), figsize=(3.9 * len(runs), 3.9))
    for axis, (case, run) in zip(axes, runs.items()):
        keep = _settled(run)
        x, y = in_unit(run.cage_x, "um"), in_unit(run.cage_y, "um")
        axis.plot(x.values[keep], y.values[keep], lw=0.5)
        axis.set(xlabel=label(x, long=True), ylabel=label(y, long=True),
                 title=f"{_name(case)}\n{_sigma(run)}")
        axis.title.set_fontsize(8)
        axis.set_aspect("equal", adjustable="datalim")
        axis.grid(alpha=0.3)
    figure.suptitle(_title(data, "geometric centre of the cage, settled half"), fontsize=9)
    save(figure, figures, file)


def _histories(runs: dict, data, figures: Path, suffix: str, legend: str):
    """Figs. 19-22 (or 27-30): cage slip, and roller slip, skew and tilt of one roller."""
    numbers = {"eccentricity": (19, 20, 21, 22), "misalignment": (27, 28, 29, 30)}[suffix]
    shown = (("cage_slip", "%", "cage_slip", "cage slip"),
             ("roller_slip", "%", "roller_slip", f"roller {ROLLER}: spin slip"),
             ("roller_skew", "deg", "skew", f"roller {ROLLER}: skew"),
             ("roller_tilt", "deg", "tilt", f"roller {ROLLER}: tilt"))
    for number, (variable, unit, name, what) in zip(numbers, shown):
        figure, axis = subplots(figsize=(8.6, 3.9))
        for case, run in runs.items():
            values = run[variable]
            if "roller" in values.dims:
                values = values.sel(roller=ROLLER)
            values = in_unit(values, unit)
            time = in_unit(run.elapsed_time, "ms")
            axis.plot(time, values, lw=0.6, label=_name(case))
        axis.set(xlabel=f"{_TIME} [ms]", ylabel=f"{what} [{unit}]")
        axis.legend(fontsize=7, title=legend, title_fontsize=7, loc="center left",
                    bbox_to_anchor=(1.02, 0.5))  # beside the histories, not over them
        axis.grid(alpha=0.3)
        axis.set_title(_title(data, what), fontsize=9)
        save(figure, figures, f"fig{number}_{name}_{suffix}.png")


def _arc_maps(runs: dict, data, figures: Path, file: str):
    """Per run: the pocket whose arc saw the largest dry force, its elements' largest forces
    over arc elements (across the arcs) x axial elements; a run whose arcs never touched dry
    says so in its panel (the oil film carried the rollers: there is no force to map)."""
    figure, axes = subplots(1, len(runs), figsize=(3.8 * len(runs) + 1, 3.6), squeeze=False)
    for axis, (case, run) in zip(axes[0], runs.items()):
        force = in_unit(run.pocket_arc_force, "N")
        peak = force.max(["arc_axial", "arc_angle"])
        if float(peak.max()) <= 0:
            axis.text(0.5, 0.5, "no dry contact\non any pocket arc\nin the settled half:\n"
                      "the oil film carries\nthe rollers", transform=axis.transAxes,
                      ha="center", va="center", fontsize=10)
            axis.set(xticks=[], yticks=[], title=_name(case))
            axis.title.set_fontsize(9)
            continue
        pocket = int(peak.idxmax("roller"))
        one = force.sel(roller=pocket).transpose("arc_axial", "arc_angle")
        image = axis.pcolormesh(one.arc_angle, one.arc_axial, one, shading="nearest",
                                cmap="magma_r", vmin=0, vmax=float(one.max()))
        figure.colorbar(image, ax=axis, label="largest dry force [N]")
        half = one.arc_angle.size // 2  # the arcs' outer edges meet in the middle
        axis.set(xlabel=f"arc element number across both arcs\n({half}, {half + 1}: at the "
                        "cage's outside diameter)",
                 ylabel="axial element number\n(Gauss-Legendre points along the roller)",
                 title=f"{_name(case)}, pocket {pocket}")
        axis.xaxis.set_major_locator(MaxNLocator(integer=True))
        axis.yaxis.set_major_locator(MaxNLocator(integer=True))
        axis.title.set_fontsize(9)
    figure.suptitle(_title(data, f"pocket arcs, settled half; {_film(data)}", figure),
                    fontsize=9)
    save(figure, figures, file)


#: The bars of the flooded-against-thin-film summary: output, unit, panel title.
_SUMMARY = (("mean_cage_slip", "%", "mean cage slip [%]"),
            ("mean_roller_slip", "%", "mean roller slip [%]"),
            ("whirl_deviation_ratio", "1", r"$\sigma_b$ of the mass centre"),
            ("centre_whirl_deviation_ratio", "1", r"$\sigma_b$ of the geometric centre"),
            ("pocket_arc_events", "1", "dry pocket-arc contacts begun"))


def _film_summary(flooded: dict, thin: dict, data, figures: Path, file: str):
    """Grouped bars: each eccentricity case's settled numbers, flooded beside thin film, each
    bar with its value (a bar of a thousandth is not seen)."""
    figure, axes = subplots(1, len(_SUMMARY), figsize=(3.3 * len(_SUMMARY), 4.0))
    place, width = np.arange(len(CASES)), 0.38
    for axis, (name, unit, what) in zip(axes, _SUMMARY):
        for shift, (film, runs) in zip((-width / 2, width / 2),
                                       (("flooded", flooded), ("thin film", thin))):
            bars = axis.bar(place + shift, [float(in_unit(runs[c][name], unit)) for c in CASES],
                            width, label=film)
            axis.bar_label(bars, fmt=lambda v: f"{v:.0f}" if abs(v) >= 100 else f"{v:.3g}",
                           fontsize=6, rotation=90, padding=2)
        axis.set_xticks(place, [f"{c[0].split()[0]}, {c[1].split()[0]}" for c in CASES],
                        fontsize=7)
        axis.set(xlabel="$e_r$, $e_a$ [mm]", ylabel=what)
        axis.margins(y=0.25)  # room for the values above the bars
        axis.grid(alpha=0.3, axis="y")
    handles, names = axes[0].get_legend_handles_labels()
    figure.legend(handles, names, fontsize=8, loc="upper right", ncol=2)
    figure.suptitle(_title(data, f"settled half; thin film: {_film(data)}"), fontsize=9)
    save(figure, figures, file)


def _face_map(run, variable: str, figures: Path, file: str, case: str):
    """Polar maps of an end-face clearance, smallest over the rollers, left and right end.

    The model's face elements are rings of equal area (edges at ``R sqrt(i / n)``, ``R`` the
    face radius ``D/2 - end chamfer``) times equal angles from the radial direction."""
    gap = in_unit(run[variable], "um").min("roller")
    radius = float(in_unit(run.roller_diameter, "mm")) / 2 - float(in_unit(run.end_chamfer,
                                                                           "mm"))
    rings, angles = gap.face_ring.size, gap.face_angle.size
    ring_edges = radius * np.sqrt(np.arange(rings + 1) / rings)
    angle_edges = 2 * np.pi * np.arange(angles + 1) / angles
    low, high = (float(f(gap)) if np.isfinite(gap).any() else 0.0 for f in (np.nanmin,
                                                                              np.nanmax))
    colours, scale, ticks = _gap_scale(low, high)
    figure, axes = subplots(1, 2, figsize=(10, 5.2), subplot_kw={"projection": "polar"})
    figure.subplots_adjust(left=0.04, right=0.8, top=0.8, bottom=0.2, wspace=0.35)
    # Few round radii, on a spoke between the angle labels: five sqrt-spaced rings overlap.
    radii = [r for r in MaxNLocator(3).tick_values(0, radius) if 0 < r <= radius]
    for axis, end in zip(axes, gap.end.values):
        one = gap.sel(end=end).transpose("face_ring", "face_angle")
        image = axis.pcolormesh(angle_edges, ring_edges, np.ma.masked_invalid(one.values),
                                cmap=colours, norm=scale)
        axis.set_title(f"{end} end: smallest {float(one.min()):.3g} um", fontsize=9, pad=14)
        axis.set_ylim(0, radius)
        axis.set_facecolor("0.8")  # where the face has no counterpart: apart from a small gap
        axis.set_yticks(radii, [f"{r:g} mm" for r in radii], fontsize=7)
        axis.set_rlabel_position(112.5)
        for text in axis.get_yticklabels():  # legible over the colours
            text.set_bbox({"facecolor": "white", "alpha": 0.7, "linewidth": 0, "pad": 1})
        axis.tick_params(axis="x", labelsize=7)
    bar = figure.colorbar(image, cax=figure.add_axes((0.85, 0.25, 0.02, 0.5)), ticks=ticks)
    bar.set_label(f"{run[variable].attrs['long_name']} [um]\n(below 0: overlap, dry contact)",
                  fontsize=8)
    bar.ax.tick_params(labelsize=7)
    counterpart = "the pocket's end face" if variable == "pocket_end_clearance" else "the rib"
    figure.text(0.42, 0.04,
                "Each roller end face seen along the roller's axis: angle from the radial "
                "direction (0 deg: radially outwards),\nradius from the roller's axis (face "
                f"radius {radius:.2g} mm). Red: the face overlaps {counterpart} (dry contact); "
                f"blue: a gap;\ngrey: {counterpart} does not reach there.",
                ha="center", fontsize=7.5)
    figure.suptitle(_title(run, f"{case}; smallest over rollers and the settled half"),
                    fontsize=9)
    save(figure, figures, file, tight=False)  # tight_layout does not suit polar axes


def _gap_scale(low: float, high: float):
    """Colours, scale and colour-bar ticks of a gap from ``low`` to ``high`` [um]: red below
    zero (dry contact) and blue above, each side on its own scale, so that a contact of
    tenths of a micrometre stays visible beside gaps of micrometres; a side the map does not
    reach is left out of the bar."""
    colours = matplotlib.colormaps["RdBu"]
    if low < 0 < high:
        ticks = [t for side in ((low, 0.0), (0.0, high))
                 for t in MaxNLocator(3).tick_values(*side) if low <= t <= high]
        return colours, TwoSlopeNorm(vcenter=0.0, vmin=low, vmax=high), sorted(set(ticks))
    if high <= 0:  # every element touches: the red half
        low = min(low, -1e-3)
        half, side = ListedColormap(colours(np.linspace(0.0, 0.5, 128))), (low, 0.0)
    else:  # no element touches: the blue half
        half, side = ListedColormap(colours(np.linspace(0.5, 1.0, 128))), (0.0, high)
    ticks = [t for t in MaxNLocator(4).tick_values(*side) if side[0] <= t <= side[1]]
    return half, Normalize(*side), ticks


# -- the stated conclusions, as numbers

def _edge(gap) -> np.ndarray:
    """Elements at the edge of a face's contact zone (the elements that have a counterpart):
    on the face's outermost ring, or beside an element without one (NaN), in angle (round
    the face) or in ring."""
    values = gap.transpose("face_ring", "face_angle").values
    present = np.isfinite(values)
    padded = np.pad(~present, ((1, 1), (0, 0)), constant_values=False)
    padded[-1, :] = True  # beyond the outermost ring: the face's rim
    beside = (np.roll(~present, 1, axis=1) | np.roll(~present, -1, axis=1)
              | padded[:-2] | padded[2:])
    return present & beside


def _edge_share(gap) -> float | None:
    """Share of the dry (negative-gap) elements of both ends that lie at the edge of the
    contact zone; None where nothing is dry."""
    dry = edge = 0
    for end in gap.end.values:
        one = gap.sel(end=end)
        negative = (one < 0).transpose("face_ring", "face_angle").values
        dry += int(negative.sum())
        edge += int((negative & _edge(one)).sum())
    return edge / dry if dry else None


def _two_sided(gap) -> float:
    """The larger of the two ends' smallest gaps: negative when both ends touch dry."""
    return float(gap.min(["face_ring", "face_angle"]).max("end"))


def _alike(gap) -> float:
    """Correlation of the left and right ends' maps over the elements both have."""
    left = gap.sel(end="left").transpose("face_ring", "face_angle").values.ravel()
    right = gap.sel(end="right").transpose("face_ring", "face_angle").values.ravel()
    both = np.isfinite(left) & np.isfinite(right)
    return float(np.corrcoef(left[both], right[both])[0, 1])


def _outer_edge(arc_angles: int) -> np.ndarray:
    """Which arc elements (of ``arc_angles`` across a pocket's two arcs) form the arcs' outer
    edge: the quarter of each arc nearest the cage's outside diameter, at least one element.
    The model orders the elements by their angle theta from the pocket's radial axis,
    -theta_2 .. -theta_1 then theta_1 .. theta_2 in equal steps, and the smaller |theta| the
    nearer an element lies to the outside diameter."""
    per_arc = arc_angles // 2
    from_outside = np.concatenate([np.arange(per_arc)[::-1], np.arange(per_arc)])
    return from_outside < max(1, round(_OUTER_EDGE * per_arc))


def _outer_share(force) -> float | None:
    """Share of the arc elements' largest dry forces (summed over all pockets) carried by the
    arcs' outer edge (8 elements per arc: the outer 2, so an even spread gives 0.25). None
    where no arc touched dry."""
    total = float(force.sum())
    if total == 0:
        return None
    outer = np.flatnonzero(_outer_edge(force.sizes["arc_angle"]))
    return float(force.isel(arc_angle=outer).sum()) / total


def _evenness(force) -> float | None:
    """How evenly the pocket with the largest dry arc force carries it: the mean of its arc
    elements' largest forces over their peak (1: all alike; one element of n: 1 / n). None
    where no arc touched dry."""
    peak = force.max(["arc_axial", "arc_angle"])
    if float(peak.max()) == 0:
        return None
    pocket = force.isel(roller=int(peak.argmax("roller")))
    return float(pocket.mean() / pocket.max())


def _ratio(top, bottom) -> float | None:
    """``top / bottom``; None where both are zero (nothing to compare)."""
    top, bottom = float(top), float(bottom)
    if bottom == 0:
        return None if top == 0 else float("inf")
    return top / bottom


def _row(name: str, run) -> str:
    """One run's line of :func:`tables`."""
    def gaps(variable):
        gap = in_unit(run[variable], "um")
        return " / ".join(f"{float(gap.sel(end=end).min()):.2f}" for end in ("left", "right"))

    force = float(in_unit(run.pocket_arc_force, "N").max()) if np.isfinite(
        run.pocket_arc_force).any() else 0.0
    events = " / ".join(f"{_value(run, v, '1'):.0f}" for v in (
        "pocket_arc_events", "pocket_end_events", "rib_events"))
    return (f"| {name} | {_value(run, 'mean_cage_slip', '%'):.3g} | "
            f"{_value(run, 'mean_roller_slip', '%'):.3g} | "
            f"{_value(run, 'whirl_deviation_ratio', '1'):.2g} / "
            f"{_value(run, 'centre_whirl_deviation_ratio', '1'):.3g} | "
            f"{_value(run, 'rms_roller_skew', 'deg'):.3g} | "
            f"{_value(run, 'rms_roller_tilt', 'deg'):.2g} | {events} | {force:.3g} | "
            f"{gaps('pocket_end_clearance')} | {gaps('rib_clearance')} |")


def tables(results: Path) -> str:
    """The runs' settled statistics, as the report shows them after about.md."""
    results = Path(results)
    runs, _ = _eccentricity(results)
    thin, _ = _eccentricity(results, "eccentricity_thin_film")
    turned = _misalignment(results)
    pressure = result(results, "eccentricity_film_pressure")
    lines = ["## The runs' numbers", "",
             "Settled half; slips are means over the rollers; gaps the smallest over all "
             "rollers, elements and settled samples; contacts: dry contacts begun between "
             "settled samples. Thin film: 5 % of the pocket arcs under oil; films' pressure: "
             "the end films' squeeze and wedge (60 ms, settled from 30 ms).", "",
             "| case | cage slip [%] | roller slip [%] | sigma_b, mass / geometric centre | "
             "rms skew [deg] | rms tilt [deg] | dry contacts begun (arc / pocket end / rib) | "
             "largest dry arc force [N] | smallest pocket-end gap, left / right [um] | "
             "smallest rib gap, left / right [um] |", "|---|---|---|---|---|---|---|---|---|---|"]
    plain = {case: f"e_r, e_a = {case[0]}, {case[1]}" for case in CASES}
    lines += [_row(plain[case], run) for case, run in runs.items()]
    lines += [_row(MISALIGNED[name], turned[name]) for name in MISALIGNED]
    lines += [_row(f"thin film, {plain[case]}", run) for case, run in thin.items()]
    lines += [_row(f"films' pressure, e_r, e_a = 0 mm, {axial}",
                   at(pressure, cage_axial_eccentricity=axial)) for axial in ("0 mm", "2 mm")]
    return "\n".join(lines)


def _value(run, name: str, unit: str) -> float:
    return float(in_unit(run[name], unit))


def _change(run, base, name: str) -> float:
    """Ratio of a settled statistic of ``run`` to that of ``base``, unit-free."""
    return _value(run, name, "1") / _value(base, name, "1")


def ours(results: Path) -> dict:
    results = Path(results)
    runs, _ = _eccentricity(results)
    free, radial, axial = runs[("0 mm", "0 mm")], runs[("2 mm", "0 mm")], runs[("0 mm",
                                                                                "2 mm")]
    combined = runs[("2 mm", "2 mm")]
    turned = _misalignment(results)

    values = {"slip_800_12000_3d": _value(free, "mean_cage_slip", "%")}
    for case, run in (("radial", radial), ("axial", axial)):
        values[f"whirl_{case}"] = _change(run, free, "whirl_deviation_ratio")
        values[f"whirl_{case}_centre"] = _change(run, free, "centre_whirl_deviation_ratio")
        for name in ("mean_cage_slip", "mean_roller_slip", "rms_roller_skew",
                     "rms_roller_tilt"):
            values[f"{name}_{case}"] = _change(run, free, name)
    for name in ("whirl_radial", "whirl_radial_centre"):  # steadier: centred over eccentric
        values[name] = 1 / values[name]
    values["arc_contacts_radial"] = _value(radial, "pocket_arc_events", "1")
    values["arc_force_radial_over_axial"] = _ratio(radial.pocket_arc_force.max(),
                                                   axial.pocket_arc_force.max())
    for name in ("pocket_end_clearance", "rib_clearance"):
        gap = in_unit(combined[name], "um").min("roller")
        values[f"{name}_one_sided"] = _two_sided(gap)
        values[f"{name}_edge_combined"] = _edge_share(gap)

    aligned = turned["aligned"]
    for axis in ("x", "y"):
        run = turned[f"about_{axis}"]
        values[f"whirl_misaligned_{axis}"] = _change(run, aligned, "whirl_deviation_ratio")
        values[f"whirl_misaligned_{axis}_centre"] = _change(run, aligned,
                                                           "centre_whirl_deviation_ratio")
        for name in ("mean_cage_slip", "mean_roller_slip", "rms_roller_skew",
                     "rms_roller_tilt"):
            values[f"{name}_misaligned_{axis}"] = _change(run, aligned, name)
    x, y = turned["about_x"], turned["about_y"]
    for name in ("whirl_deviation_ratio", "mean_cage_slip", "mean_roller_slip",
                 "rms_roller_skew", "rms_roller_tilt"):
        values[f"{name}_x_over_y"] = _change(x, y, name)
    values["whirl_deviation_ratio_x_over_y_centre"] = _change(x, y, "centre_whirl_deviation_ratio")
    values["arc_contacts_misaligned_x"] = _value(x, "pocket_arc_events", "1")
    for name in ("pocket_end_clearance", "rib_clearance"):
        gap = in_unit(x[name], "um").min("roller")
        values[f"{name}_both_sides_x"] = _two_sided(gap)
        values[f"{name}_edge_x"] = _edge_share(gap)
        values[f"{name}_alike_x"] = _alike(gap)
    values.update(_thin_film(results))
    pressure = result(results, "eccentricity_film_pressure")
    values["rms_roller_skew_axial_film_pressure"] = _change(
        at(pressure, cage_axial_eccentricity="2 mm"),
        at(pressure, cage_axial_eccentricity="0 mm"), "rms_roller_skew")
    return {key: v for key, v in values.items() if v is not None}


def _thin_film(results: Path) -> dict:
    """Section 3.1's claims on the pocket arcs, slip and whirl, with the thin pocket film."""
    runs, _ = _eccentricity(results, "eccentricity_thin_film")
    free, radial, axial = runs[("0 mm", "0 mm")], runs[("2 mm", "0 mm")], runs[("0 mm",
                                                                                "2 mm")]
    values = {}
    for name in ("mean_cage_slip", "mean_roller_slip"):
        values[f"{name}_radial_thin_film"] = _change(radial, free, name)
    for name, output in (("whirl_radial", "whirl_deviation_ratio"),
                         ("whirl_radial_centre", "centre_whirl_deviation_ratio")):
        values[f"{name}_thin_film"] = _change(free, radial, output)  # centred over eccentric
    values["arc_contacts_radial_thin_film"] = _value(radial, "pocket_arc_events", "1")
    values["arc_force_radial_over_axial_thin_film"] = _ratio(radial.pocket_arc_force.max(),
                                                             axial.pocket_arc_force.max())
    values["arc_force_outer_edge_radial_thin_film"] = _outer_share(radial.pocket_arc_force)
    values["arc_force_even_axial_thin_film"] = _evenness(axial.pocket_arc_force)
    return values
