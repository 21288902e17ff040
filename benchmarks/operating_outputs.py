"""crb_radial's throughput with its operating outputs (lubricant film, film parameter) against
the same model without them.

Baseline: ``crb_radial`` on the same 2000 points (one call, the model's ``points_per_call``)
with its film left out: the model's film functions replaced by ones that return NaN at no
cost. Measured: the model as it is, with the oil's viscosities and a composite roughness
given, so that every film is computed. Both with rating lives, on crb_radial_throughput.py's
bearing (14 crowned rollers, 60 slices, 6000 r/min). Prints the throughput ratio, the baseline's time
over the measured one (goal: at least 0.8).
"""
from unittest import mock

import numpy as np

from bearing_sweep.models import cylindrical
from pairs import interleaved

POINTS = 2000
RPM = 2 * np.pi / 60


def _inputs():
    return dict(radial_load=np.linspace(500.0, 12_000.0, POINTS), roller_count=14,
                pitch_diameter=65e-3, roller_diameter=10e-3, effective_length=9.6e-3, crown=4e-6,
                speed=6000 * RPM, dynamic_load_rating=48e3, fatigue_load_limit=6e3,
                viscosity_40=68e-6, viscosity_100=8.7e-6, composite_roughness=0.15e-6)


def _no_film(load, *args):
    nothing = np.full(np.shape(load), np.nan)
    return nothing, nothing


def main():
    inputs = _inputs()
    cylindrical.crb_radial(**{**inputs, "radial_load": inputs["radial_load"][:10]})

    def measured():
        cylindrical.crb_radial(**inputs)

    def baseline():
        with mock.patch.object(cylindrical, "line_contact_film", _no_film):
            cylindrical.crb_radial(**inputs)

    ratio, lowest, highest, ours, theirs, load = interleaved(measured, baseline, pairs=7)
    print("crb_radial with its operating outputs (film, film parameter)")
    print(f"  baseline: the same model without its film, {theirs / POINTS * 1e6:.1f} us a "
          f"point; with it {ours / POINTS * 1e6:.1f} us a point")
    print(f"  ratio: {1 / ratio:.3f}x (goal: at least 0.8, throughput with over without); "
          f"pairs {1 / highest:.3f}-{1 / lowest:.3f}x, load average {load[0]:.2f}")


if __name__ == "__main__":
    main()
