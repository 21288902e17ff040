"""What the load distribution is for: contact stress and rating life (ISO 281, ISO/TS 16281)
of the papers' bearings against clearance, crown, preload and axial load, from the netCDF
results only."""
from pathlib import Path

import numpy as np

from bearing_sweep.models.bearing_life import beyond_life_equation
from bearing_sweep.plotting import (at, conditions, family, in_unit, label,
                                    plain_log_ticks, result, ring, save, subplots)

FIGURES = {
    "clearance.png": "Bearing D (paper 000): ISO/TS 16281 reference life L10r (solid) and "
                     "ISO 281 basic life L10 (dashed, blind to clearance), and the largest "
                     "contact pressure, against diametral clearance (negative: preload) for "
                     "three radial loads; dots: the longest L10r.",
    "crown.png": "Bearing D: L10r and the largest contact pressure against the crown drop of "
                 "a logarithmic profile at zero clearance, aligned and with the inner ring "
                 "misaligned by 1 and 2 mrad. Aligned, the model's straight roller has no "
                 "edge stress and no crown is its best; misaligned, its ends load and a crown "
                 "of a few micrometres pays.",
    "preload_71807ac.png": "71807AC (paper 001): L10r (solid), ISO 281 L10 (dashed) and the "
                           "largest contact pressure against the axial load (preload) for "
                           "several radial loads; rings: an equivalent load above half the "
                           "dynamic load rating, where ISO 281 (5.3.1) no longer vouches for "
                           "its life equation.",
    "tapered.png": "Tapered roller bearing of paper 003 at its radial load: L10r and ISO 281 "
                   "L10 (left) and the largest contact pressure with the loaded rollers "
                   "(right) against Fa/Fr, from just above Fr tan(alpha), below which the "
                   "rollers cannot carry the radial load; rings: an equivalent load above "
                   "half the dynamic load rating (ISO 281, 7.3.1).",
    "modified_life.png": "Bearing D with ISO VG 68 oil: L10r, L10rm, L10 and L10m against "
                         "radial load at 70 degC (left), and the life modification factor "
                         "aISO of L10rm for three oil temperatures (right).",
}

_LIFE_UNIT = "Mturn"  # millions of revolutions, the unit of both standards
_LIFE_SHOWN = "$10^6$ rev"  # the same, as the standards write it
#: What the rings on a life curve mean (the models flag the points so).
_HEAVY = "P > 0.5 Cr, beyond ISO 281"


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _clearance(results, figures)
    _crown(results, figures)
    _preload(results, figures)
    _tapered(results, figures)
    _modified(results, figures)


def _in_kn(data):
    """``data`` with its radial loads in kN, the unit the figures show them in."""
    return data.assign_coords(radial_load=in_unit(data.radial_load, "kN"))


def _life(variable):
    return in_unit(variable, _LIFE_UNIT)


def _clearance(results, figures):
    data = _in_kn(result(results, "clearance"))
    data = data.assign_coords(clearance=in_unit(data.clearance, "um"))
    figure, (left, right) = subplots(1, 2, figsize=(10, 4.2))
    for index, load in enumerate(data.radial_load.values):
        point = data.sel(radial_load=load)
        colour = f"C{index}"
        reference = _life(point.reference_rating_life)
        left.semilogy(point.clearance, reference, "-", color=colour, label=f"Fr = {load:g} kN")
        left.semilogy(point.clearance, _life(point.basic_rating_life), "--", color=colour)
        best = int(np.nanargmax(reference.values))
        left.semilogy(point.clearance[best], reference[best], "o", color=colour)
        right.plot(point.clearance, in_unit(point.largest_contact_pressure, "MPa"), "-",
                   color=colour, label=f"Fr = {load:g} kN")
    left.set(xlabel=label(data.clearance), ylabel=f"rating life [{_LIFE_SHOWN}]",
             title="L10r (solid), L10 (dashed)")
    right.set(xlabel=label(data.clearance), ylabel="largest contact pressure [MPa]",
              title="Largest contact pressure")
    for axis in (left, right):
        axis.axvline(0.0, color="k", lw=0.8, ls=":")
        axis.grid(alpha=0.3)
        axis.legend(fontsize=7)
    figure.suptitle(conditions(data, "speed", "crown", "crown_profile", "slices",
                               "dynamic_load_rating", width=None,
                               dynamic_load_rating="kN", crown="um"), fontsize=9)
    save(figure, figures, "clearance.png")


def _crown(results, figures):
    data = _in_kn(result(results, "crown"))
    data = data.assign_coords(crown=in_unit(data.crown, "um"),
                              misalignment=in_unit(data.misalignment, "mrad"))
    figure, (left, right) = subplots(1, 2, figsize=(11.5, 4.4))
    for index, tilt in enumerate(data.misalignment.values):
        for style, load in zip(("-", "--"), data.radial_load.values):
            point = data.sel(misalignment=tilt, radial_load=load)
            text = f"{tilt:g} mrad, Fr = {load:g} kN"
            life = _life(point.reference_rating_life)
            left.semilogy(point.crown, life, style, color=f"C{index}", label=text)
            best = int(np.nanargmax(life.values))
            left.semilogy(point.crown[best], life[best], "o", color=f"C{index}")
            right.plot(point.crown, in_unit(point.largest_contact_pressure, "MPa"), style,
                       color=f"C{index}", label=text)
    left.set(xlabel=label(data.crown), ylabel=f"reference rating life L10r [{_LIFE_SHOWN}]",
             title="L10r (dots: the longest)")
    right.set(xlabel=label(data.crown), ylabel="largest contact pressure [MPa]",
              title="Largest contact pressure")
    for axis in (left, right):
        axis.grid(alpha=0.3)
    right.legend(fontsize=7, title="misalignment", title_fontsize=7, loc="center left",
                 bbox_to_anchor=(1.02, 0.5))
    figure.suptitle(conditions(data, "speed", "clearance", "crown_profile", "slices",
                               "dynamic_load_rating", width=None, dynamic_load_rating="kN"),
                    fontsize=9)
    save(figure, figures, "crown.png")


def _preload(results, figures):
    data = result(results, "preload_71807ac")
    data = data.assign_coords(axial_load=in_unit(data.axial_load, "N"),
                              radial_load=in_unit(data.radial_load, "N"))
    figure, (left, right) = subplots(1, 2, figsize=(10, 4.2))
    for index, load in enumerate(data.radial_load.values):
        point = data.sel(radial_load=load)
        left.semilogy(point.axial_load, _life(point.reference_rating_life), "-",
                      color=f"C{index}", label=f"Fr = {load:g} N")
        left.semilogy(point.axial_load, _life(point.basic_rating_life), "--", color=f"C{index}")
    for index, load in enumerate(data.radial_load.values):  # after the lines, in the legend too
        point = data.sel(radial_load=load)
        ring(left, point.axial_load, _life(point.basic_rating_life),
             beyond_life_equation(point.load_rating_ratio), _HEAVY if index == 0 else None)
    left.set(xlabel=label(data.axial_load), ylabel=f"rating life [{_LIFE_SHOWN}]",
             title="L10r (solid), L10 (dashed)")
    left.legend(fontsize=7)
    left.grid(alpha=0.3)
    family(right, data.axial_load, in_unit(data.largest_contact_pressure, "MPa"),
           "radial_load", "Fr = {:g} N", xlabel=label(data.axial_load),
           ylabel="largest contact pressure [MPa]", title="Largest contact pressure")
    figure.suptitle(conditions(data, "contact_angle", "clearance", "dynamic_load_rating",
                               width=None, dynamic_load_rating="kN"), fontsize=9)
    save(figure, figures, "preload_71807ac.png")


def _load_ratio(data):
    """Fa/Fr of a sweep over the axial load at one radial load."""
    ratio = (in_unit(data.axial_load, "N") / in_unit(data.radial_load, "N")).rename("Fa/Fr")
    return ratio.assign_attrs(units="1")


def _tapered(results, figures):
    data = result(results, "tapered")
    ratio = _load_ratio(data)
    figure, (left, right) = subplots(1, 2, figsize=(10, 4.2))
    left.semilogy(ratio, _life(data.reference_rating_life), "-", label="L10r (ISO/TS 16281)")
    left.semilogy(ratio, _life(data.basic_rating_life), "--", label="L10 (ISO 281)")
    ring(left, ratio, _life(data.basic_rating_life),
         beyond_life_equation(data.load_rating_ratio), _HEAVY)
    angle = float(in_unit(data.outer_contact_angle, "rad"))
    for value, text in ((np.tan(angle), r"$\tan\alpha$"),
                        (1.5 * np.tan(angle), r"$e = 1.5 \tan\alpha$")):
        left.axvline(value, color="k", lw=0.8, ls=":")
        left.annotate(text, (value, 0.02), xycoords=("data", "axes fraction"), fontsize=7,
                      rotation=90, ha="right")
    left.set(xlabel="Fa/Fr", ylabel=f"rating life [{_LIFE_SHOWN}]", title="Rating lives")
    left.legend(fontsize=7)
    right.plot(ratio, in_unit(data.largest_contact_pressure, "MPa"), color="C0")
    right.set(xlabel="Fa/Fr", title="Largest contact pressure and loaded rollers")
    right.set_ylabel("largest contact pressure [MPa]", color="C0")
    twin = right.twinx()
    twin.step(ratio, data.loaded_rollers, where="post", color="C3", alpha=0.7)
    twin.set_ylabel("loaded rollers", color="C3")
    for axis in (left, right):
        axis.grid(alpha=0.3)
    figure.suptitle(conditions(data, "radial_load", "outer_contact_angle", "roller_count",
                               "dynamic_load_rating", width=None, radial_load="kN",
                               dynamic_load_rating="kN"), fontsize=9)
    save(figure, figures, "tapered.png")


_MODIFIED = (("reference_rating_life", "L10r (ISO/TS 16281)", "C0-"),
             ("modified_reference_rating_life", "L10rm = aISO L10r", "C0--"),
             ("basic_rating_life", "L10 (ISO 281)", "C1-"),
             ("modified_rating_life", "L10m = aISO L10", "C1--"))


def _modified(results, figures):
    data = _in_kn(result(results, "modified_life"))
    data = data.assign_coords(oil_temperature=in_unit(data.oil_temperature, "degC"))
    warm = at(data, oil_temperature="70 degC")
    figure, (left, right) = subplots(1, 2, figsize=(10, 4.2))
    for name, text, style in _MODIFIED:
        left.loglog(warm.radial_load, _life(warm[name]), style, label=text)
    left.set(xlabel=label(data.radial_load), ylabel=f"rating life [{_LIFE_SHOWN}]",
             title=rf"Oil at 70 degC ($\kappa$ = {float(warm.viscosity_ratio.max()):.2f})")
    left.legend(fontsize=7)
    left.grid(alpha=0.3, which="both")
    family(right, data.radial_load, data.life_modification_factor, "oil_temperature",
           "oil at {:g} degC", plot="semilogy", xlabel=label(data.radial_load),
           ylabel="life modification factor aISO of L10rm", title="aISO (capped at 50)")
    plain_log_ticks(left.xaxis, right.yaxis)
    figure.suptitle(conditions(data, "speed", "clearance", "crown", "contamination_factor",
                               "fatigue_load_limit", "viscosity_40", "viscosity_100",
                               width=110, fatigue_load_limit="kN", crown="um"), fontsize=9)
    save(figure, figures, "modified_life.png")


# -- the expected trends, measured ------------------------------------------------------------

def _best_clearance(data, load: str) -> tuple[float, float, float]:
    """Clearance of the longest L10r [um], that life and the clearance of the lowest largest
    contact pressure [um] at the radial load ``load``."""
    point = at(data, radial_load=load)
    clearance = in_unit(point.clearance, "um").values
    life = _life(point.reference_rating_life).values
    pressure = point.largest_contact_pressure.values
    best = int(np.nanargmax(life))
    return float(clearance[best]), float(life[best]), float(clearance[np.nanargmin(pressure)])


def ours(results: Path) -> dict:
    results = Path(results)
    values = {}
    clearance = result(results, "clearance")
    for load in ("2 kN", "5 kN", "10 kN"):
        values[f"optimum_clearance_{load.split()[0]}kN"] = _best_clearance(clearance, load)[0]
    best, longest, least_pressure = _best_clearance(clearance, "5 kN")
    life = _life(at(clearance, radial_load="5 kN").reference_rating_life)
    values["preload_40um"] = float(100 * at(life, clearance="-40 um") / longest)
    values["clearance_60um"] = float(100 * at(life, clearance="60 um") / longest)
    values["pressure_at_optimum"] = least_pressure - best
    crown = result(results, "crown")
    for name, load, tilt in (("crown_best_aligned", "5 kN", "0 mrad"),
                             ("crown_best_2mrad_5kN", "5 kN", "2 mrad"),
                             ("crown_best_2mrad_10kN", "10 kN", "2 mrad")):
        point = at(crown, radial_load=load, misalignment=tilt)
        values[name] = float(in_unit(point.crown, "um")[
            int(np.nanargmax(point.reference_rating_life.values))])
    preload = result(results, "preload_71807ac").reference_rating_life
    falling = (preload.diff("axial_load") <= 0).all("axial_load")
    values["preload_71807ac_falls"] = float(falling.sum())
    tapered = result(results, "tapered")
    life = _life(tapered.reference_rating_life)
    values["tapered_optimum"] = float(_load_ratio(tapered)[int(np.nanargmax(life.values))])
    values["tapered_near_limit"] = float(100 * life[0] / life.max())
    modified = at(result(results, "modified_life"), oil_temperature="70 degC", radial_load="5 kN")
    values["modified_factor"] = float(modified.modified_reference_rating_life
                                      / modified.reference_rating_life)
    return values
