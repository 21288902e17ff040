"""The bearing as it runs: operating clearance from fits and temperatures, the fit at speed,
the oil film and the static safety, from the netCDF results only."""
from pathlib import Path

import numpy as np

from bearing_sweep.plotting import (at, conditions, in_unit, label, plain_log_ticks, result,
                                    save, subplots)

FIGURES = {
    "fits.png": "NU 208 on a solid steel shaft: operating clearance, radial stiffness and "
                "largest contact pressure against the shaft fit, the inner ring as warm as "
                "the outer ring and 10 K and 20 K warmer; below zero operating clearance the "
                "rollers are preloaded.",
    "speed.png": "NU 208: the interference its inner ring keeps on the shaft (left) and the "
                 "operating clearance (right) against speed for three shaft fits; the inner "
                 "ring's centrifugal expansion loosens the fit until it is lost (dots).",
    "film.png": "71807AC under 1 kN preload and 500 N radial load, ISO VG 32 oil: the "
                "smallest minimum film of its ball contacts (Hamrock and Dowson) and the "
                "film parameter against speed at three oil temperatures.",
    "static_safety.png": "NU 208: static safety from the largest contact pressure against "
                         "radial load, without clearance and with 40 um, beside the "
                         "catalogue's s0 = C0r / P0r (dotted); the dashed line is ISO 76's "
                         "basic static load rating C0r.",
    "friction.png": "NU 208 under 6.2 kN in an ISO VG 68 oil bath: SKF's frictional moment "
                    "against speed at three oil temperatures beside SKF's constant-coefficient "
                    "estimate (dashed), its rolling and sliding parts at 70 degC, and the "
                    "power loss.",
}

#: ISO 76:2006's basic static load rating of the NU 208 of the study [N]:
#: C0r = 44 (1 - D/dm) Z l D with D = 11 mm, dm = 60.5 mm, Z = 14, l = 10 mm.
STATIC_RATING = 44 * (1 - 11 / 60.5) * 14 * 10 * 11
#: SKF's estimate of the NU 208's frictional moment under 6.2 kN, M = 0.5 mu P d with its
#: constant coefficient mu = 0.0011 for cylindrical roller bearings with a cage (Rolling
#: bearings, 2013, "Friction", Table 1) [N m].
CONSTANT_COEFFICIENT_TORQUE = 0.5 * 0.0011 * 6200 * 40e-3


def draw(results: Path, figures: Path):
    results, figures = Path(results), Path(figures)
    _fits(results, figures)
    _speed(results, figures)
    _film(results, figures)
    _static(results, figures)
    _friction(results, figures)


def _fits(results, figures):
    data = result(results, "fits")
    fit = in_unit(data.shaft_fit, "um")
    figure, axes = subplots(1, 3, figsize=(13, 4))
    shown = (("operating_clearance", "um"), ("radial_stiffness", "N/um"),
             ("largest_contact_pressure", "MPa"))
    for axis, (name, unit) in zip(axes, shown):
        for index, temperature in enumerate(in_unit(data.inner_ring_temperature, "degC").values):
            point = data.isel(inner_ring_temperature=index)
            axis.plot(fit, in_unit(point[name], unit), color=f"C{index}",
                      label=f"inner ring {temperature:g} degC")
        axis.set(xlabel="shaft fit (interference) [µm]",
                 ylabel=f"{label(data[name]).split(' [')[0]} [{unit.replace('u', 'µ')}]")
    axes[0].axhline(0.0, color="0.6", linewidth=0.8)
    axes[0].legend()
    figure.suptitle("NU 208: " + conditions(data, "clearance", "radial_load", "speed",
                                            "outer_ring_temperature", width=110,
                                            clearance="um", radial_load="kN"), fontsize=9)
    save(figure, figures, "fits.png")


def _lost_at(speed, remaining):
    """The speed at which a fit's remaining interference reaches zero (linear between grid
    points), NaN where it does not on the grid."""
    crossing = np.flatnonzero((remaining[:-1] > 0) & (remaining[1:] <= 0))
    if not crossing.size:
        return np.nan
    i = crossing[0]
    return float(speed[i] + (speed[i + 1] - speed[i]) * remaining[i]
                 / (remaining[i] - remaining[i + 1]))


def _speed(results, figures):
    data = result(results, "speed")
    speed = in_unit(data.speed, "rpm").values
    figure, (left, right) = subplots(1, 2, figsize=(11, 4))
    for index, fit in enumerate(in_unit(data.shaft_fit, "um").values):
        point = data.isel(shaft_fit=index)
        remaining = in_unit(point.shaft_fit_remaining, "um").values
        left.plot(speed, remaining, color=f"C{index}", label=f"shaft fit {fit:g} µm")
        lost = _lost_at(speed, remaining)
        left.plot([lost], [0.0], "o", color=f"C{index}")
        right.plot(speed, in_unit(point.operating_clearance, "um"), color=f"C{index}",
                   label=f"shaft fit {fit:g} µm")
    left.axhline(0.0, color="0.6", linewidth=0.8)
    left.set(xlabel="inner ring speed [r/min]", ylabel="interference remaining [µm]",
             title="Shaft fit at speed")
    right.set(xlabel="inner ring speed [r/min]", ylabel="operating clearance [µm]",
              title="Operating clearance")
    left.legend()
    figure.suptitle("NU 208: " + conditions(data, "clearance", "radial_load", width=110,
                                            clearance="um", radial_load="kN"), fontsize=9)
    save(figure, figures, "speed.png")


def _film(results, figures):
    data = result(results, "film")
    speed = in_unit(data.speed, "rpm")
    figure, (left, right) = subplots(1, 2, figsize=(11, 4))
    for index, temperature in enumerate(in_unit(data.oil_temperature, "degC").values):
        point = data.isel(oil_temperature=index)
        left.loglog(speed, in_unit(point.minimum_film_thickness, "um"), color=f"C{index}",
                    label=f"oil at {temperature:g} degC")
        right.semilogx(speed, point.film_parameter, color=f"C{index}",
                       label=f"oil at {temperature:g} degC")
    right.axhline(1.0, color="0.6", linewidth=0.8)
    left.set(xlabel="inner ring speed [r/min]", ylabel="minimum film thickness [µm]",
             title="Smallest minimum film")
    right.set(xlabel="inner ring speed [r/min]", ylabel="film parameter λ [-]",
              title="Film parameter h_min / σ")
    plain_log_ticks(left.xaxis, left.yaxis, right.xaxis)
    left.legend()
    figure.suptitle(conditions(data, "axial_load", "radial_load", "viscosity_40",
                               "viscosity_100", "composite_roughness", width=110,
                               composite_roughness="um"), fontsize=9)
    save(figure, figures, "film.png")


def _static(results, figures):
    data = result(results, "static_safety")
    load = in_unit(data.radial_load, "kN")
    figure, axis = subplots(1, 1, figsize=(6.5, 4.2))
    for index, clearance in enumerate(in_unit(data.clearance, "um").values):
        axis.loglog(load, data.pressure_safety_factor.isel(clearance=index),
                    color=f"C{index}", label=f"clearance {clearance:g} µm")
    axis.loglog(load, data.static_safety_factor.isel(clearance=0), color="0.3", linestyle=":",
                label="C0r / P0r (ISO 76)")
    axis.axvline(STATIC_RATING / 1e3, color="0.4", linestyle="--", label="C0r (ISO 76)")
    axis.axhline(1.0, color="0.6", linewidth=0.8)
    axis.set(xlabel="radial load [kN]", ylabel="static safety s0 [-]",
             title="NU 208: (4000 MPa / p_max)^2 and C0r / P0r")
    plain_log_ticks(axis.xaxis, axis.yaxis)
    axis.legend()
    save(figure, figures, "static_safety.png")


def _friction(results, figures):
    data = result(results, "friction")
    speed = in_unit(data.speed, "rpm")
    figure, (total, parts, power) = subplots(1, 3, figsize=(14, 4))
    for index, temperature in enumerate(in_unit(data.oil_temperature, "degC").values):
        point = data.isel(oil_temperature=index)
        total.plot(speed, point.friction_torque, color=f"C{index}",
                   label=f"oil at {temperature:g} degC")
        power.plot(speed, point.power_loss, color=f"C{index}",
                   label=f"oil at {temperature:g} degC")
    total.axhline(CONSTANT_COEFFICIENT_TORQUE, color="0.4", linestyle="--",
                  label="0.5 µ P d, µ = 0.0011 (SKF)")
    warm = at(data, oil_temperature="70 degC")
    for name, style, text in (("friction_torque", "-", "total"),
                              ("rolling_friction_torque", "--", "rolling"),
                              ("sliding_friction_torque", ":", "sliding")):
        parts.plot(speed, warm[name], color="C1", linestyle=style, label=text)
    total.set(xlabel="inner ring speed [r/min]", ylabel="friction torque [N·m]",
              title="Frictional moment (SKF)", ylim=(0.0, None))
    parts.set(xlabel="inner ring speed [r/min]", ylabel="friction torque [N·m]",
              title="Its parts, oil at 70 degC", ylim=(0.0, None))
    power.set(xlabel="inner ring speed [r/min]", ylabel="power loss [W]",
              title="Power loss")
    for axis in (total, parts, power):
        axis.legend()
    figure.suptitle("NU 208: " + conditions(data, "radial_load", "viscosity_40",
                                            "viscosity_100", width=110, radial_load="kN"),
                    fontsize=9)
    save(figure, figures, "friction.png")


# -- the expected values, measured -------------------------------------------------------------

def ours(results: Path) -> dict:
    results = Path(results)
    values = {}
    fits = result(results, "fits")
    even = at(fits, inner_ring_temperature="40 degC")
    change = in_unit(even.operating_clearance, "um")
    # Between two fits the ring keeps at speed (at none it lifts off the shaft).
    values["fit_share"] = float(100 * (at(change, shaft_fit="10 um")
                                       - at(change, shaft_fit="20 um")) / 10.0)
    warm = in_unit(at(fits, shaft_fit="0 um").operating_clearance, "um")
    values["warm_inner_ring"] = float(warm.isel(inner_ring_temperature=0)
                                      - at(warm, inner_ring_temperature="50 degC"))
    stiffness = fits.radial_stiffness
    values["stiffness_rises"] = float((stiffness.diff("shaft_fit") > 0).all("shaft_fit").sum())
    speed = result(results, "speed")
    remaining = in_unit(at(speed, shaft_fit="10 um").shaft_fit_remaining, "um").values
    values["fit_lost_10um"] = _lost_at(in_unit(speed.speed, "rpm").values, remaining)
    film = result(results, "film")
    hot = at(film, oil_temperature="70 degC")
    values["film_speed_exponent"] = float(np.polyfit(
        np.log(in_unit(hot.speed, "rpm").values), np.log(hot.minimum_film_thickness.values),
        1)[0])
    values["film_cold_over_hot"] = float(
        at(film, oil_temperature="40 degC", speed="10000 rpm").minimum_film_thickness
        / at(film, oil_temperature="100 degC", speed="10000 rpm").minimum_film_thickness)
    static = at(result(results, "static_safety"), clearance="0 um")
    load = in_unit(static.radial_load, "N").values
    safety = static.pressure_safety_factor.values
    values["static_at_rating"] = float(np.median(safety * load) / STATIC_RATING)
    values["static_load_exponent"] = float(np.polyfit(np.log(load), np.log(safety), 1)[0])
    values["static_rating"] = float(in_unit(static.static_load_rating, "kN").max())
    friction = result(results, "friction")
    values["friction_over_constant_coefficient"] = float(
        at(friction, oil_temperature="70 degC", speed="1000 rpm").friction_torque
        / CONSTANT_COEFFICIENT_TORQUE)
    values["friction_cold_over_hot"] = float(
        at(friction, oil_temperature="40 degC", speed="10000 rpm").friction_torque
        / at(friction, oil_temperature="100 degC", speed="10000 rpm").friction_torque)
    hot = at(friction, oil_temperature="100 degC").rolling_friction_torque
    values["rolling_speed_exponent"] = float(np.log(at(hot, speed="1000 rpm")
                                                    / at(hot, speed="250 rpm")) / np.log(4.0))
    return values
