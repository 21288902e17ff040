"""crb_radial's throughput with its operating outputs (operating clearance, lubricant film,
static safety and rating, friction) against the same model without them.

Baseline: ``crb_radial`` on the same 2000 points (one call, the model's ``points_per_call``)
with those outputs left out: the functions that form them replaced by ones that return, at no
cost, the operating clearance the model computes (so both solve the same preloaded bearing)
and NaN for the rest. Measured: the model as it is, with a shaft fit, ring temperatures, the
oil's viscosities, a composite roughness, SKF's friction constants and an oil bath's level
given, so that every part is computed. Both with
rating lives, on crb_radial_throughput.py's bearing (14 crowned rollers, 60 slices,
6000 r/min). Prints the throughput ratio, the baseline's time over the measured one (goal:
at least 0.8).
"""
from unittest import mock

import numpy as np

from bearing_sweep.models import cylindrical
from bearing_sweep.models.friction import FRICTION_OUTPUT_NAMES
from bearing_sweep.models.operating_clearance import OPERATING_OUTPUT_NAMES
from bearing_sweep.models.static_safety import RATING_OUTPUT_NAMES
from pairs import interleaved

POINTS = 2000
RPM = 2 * np.pi / 60


def _inputs():
    return dict(radial_load=np.linspace(500.0, 12_000.0, POINTS), roller_count=14,
                pitch_diameter=65e-3, roller_diameter=10e-3, effective_length=9.6e-3, crown=4e-6,
                speed=6000 * RPM, dynamic_load_rating=48e3, fatigue_load_limit=6e3,
                viscosity_40=68e-6, viscosity_100=8.7e-6, composite_roughness=0.15e-6,
                shaft_fit=12e-6, bore=45e-3, outside_diameter=85e-3,
                inner_ring_temperature=333.15, outer_ring_temperature=323.15,
                skf_rolling_constant_1=1.09e-6, skf_sliding_constant_1=0.16,
                skf_sliding_constant_2=0.0015, oil_level=20e-3, drag_loss_factor=3e-4,
                bearing_width=19e-3)


def _no_film(load, *args):
    nothing = np.full(np.shape(load), np.nan)
    return nothing, nothing


def _known(operating):
    """A stand-in for the operating clearance's computation that returns ``operating``, the
    result it computes, at no cost: both sides solve the same bearing."""
    def mounted(clearance, *args):
        nothing = np.full(np.shape(clearance), np.nan)
        return {"operating_clearance": operating, "fit_lost": np.zeros(np.shape(clearance), bool),
                **{name: nothing for name in OPERATING_OUTPUT_NAMES[1:]}}
    return mounted


def _no_static(largest_pressure, *args):
    nothing = np.full(np.shape(largest_pressure), np.nan)
    return {"pressure_safety_factor": nothing}, np.zeros(np.shape(largest_pressure), bool)


def _no_rating(roller_count, length, *args):
    nothing = np.full(np.shape(length), np.nan)
    return dict.fromkeys(RATING_OUTPUT_NAMES, nothing)


def _no_friction(kind, method, lubrication, speed, *args, **kwargs):
    return dict.fromkeys(FRICTION_OUTPUT_NAMES, np.full(np.shape(speed), np.nan))


def main():
    inputs = _inputs()
    operating = cylindrical.crb_radial(**inputs)["operating_clearance"]

    def measured():
        cylindrical.crb_radial(**inputs)

    def baseline():
        with mock.patch.multiple(cylindrical, line_contact_film=_no_film,
                                 mounted_clearance=_known(operating), static_safety=_no_static,
                                 roller_rating=_no_rating, bearing_friction=_no_friction):
            cylindrical.crb_radial(**inputs)

    ratio, lowest, highest, ours, theirs, load = interleaved(measured, baseline, pairs=7)
    print("crb_radial with its operating outputs (clearance, film, static safety, friction)")
    print(f"  baseline: the same model without them, {theirs / POINTS * 1e6:.1f} us a "
          f"point; with it {ours / POINTS * 1e6:.1f} us a point")
    print(f"  ratio: {1 / ratio:.3f}x (goal: at least 0.8, throughput with over without); "
          f"pairs {1 / highest:.3f}-{1 / lowest:.3f}x, load average {load[0]:.2f}")


if __name__ == "__main__":
    main()
