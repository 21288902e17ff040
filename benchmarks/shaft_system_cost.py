"""A 1000-point sweep of a three-support shaft system against its bearings' own solves.

The system: a 300 mm spindle shaft on a back-to-back pair of 71807AC angular contact ball
bearings at the front (30 and 60 mm from the nose) and, at the rear (280 mm), a spring or the
cylindrical roller bearing D of paper 000, under a cutting force at the nose whose radial part
takes 1000 values. Measured: the sweep through ``bearing_sweep.run`` in this process, end to
end, as a user runs it. Baseline: the same bearings solved alone by ``ball_5dof`` and
``crb_radial`` at the same 1000 points, under the loads the system found on each (the roller
bearing with the shaft's tilt there as its misalignment; one vectorised call per bearing, as
a user sweeps a bearing). Prints the ratio, the system's time over the bearings' (goal: at
most 5).
"""
import numpy as np

import bearing_sweep
from bearing_sweep.models.ball import ball_5dof
from bearing_sweep.models.cylindrical import crb_radial
from pairs import interleaved

POINTS = 1000
PRESET = "paper001-71807AC"
#: The preset's bearing in SI, as ball_5dof takes it.
BEARING = dict(ball_count=25, ball_diameter=3.14e-3, pitch_diameter=41e-3,
               contact_angle=np.radians(25.0), inner_curvature_ratio=0.52,
               outer_curvature_ratio=0.53, clearance=-4e-6, contact_constant=1.0649e10)
#: Bearing D of paper 000 in SI, as crb_radial takes it.
ROLLERS = dict(roller_count=14, pitch_diameter=65e-3, roller_diameter=10e-3,
               effective_length=9.6e-3)


def definition(rear: str = "spring") -> dict:
    bearing = {"model": "ball_5dof", "bearing": PRESET, "clearance": "-0.004 mm"}
    return {
        "sweep": {"model": "shaft_system"},
        "shaft": {"sections": [{"length": "90 mm", "diameter": "35 mm"},
                               {"length": "210 mm", "diameter": "30 mm", "bore": "10 mm"}]},
        "supports": {"front": {**bearing, "position": "30 mm"},
                     "second": {**bearing, "position": "60 mm",
                                "axial_direction": "negative"},
                     "rear": {"model": "spring", "position": "280 mm",
                              "radial_stiffness": "2e5 N/mm"} if rear == "spring" else
                     {"model": "crb_radial", "bearing": "paper000-D", "position": "280 mm"}},
        "loads": {"nose": {"position": "0 mm", "force_x": "300 N"}},
        "axes": {"loads.nose.force_y": {"start": "200 N", "stop": "3000 N",
                                        "num": POINTS}},
        "fixed": {"station_count": 5},
    }


def compare(rear: str):
    system = definition(rear)
    result = bearing_sweep.run(system, workers=0, progress=False)
    assert int((result.status != 0).sum()) == 0, "every point converged within validity"
    carried = result.support_load.values  # (points, support, dof) [N, N m]
    moved = result.support_displacement.values[:, 2]  # the rear's, in the x-y plane

    def measured():
        bearing_sweep.run(system, workers=0, progress=False)

    def baseline():
        for index, flip in ((0, 1.0), (1, -1.0)):
            load = carried[:, index] * np.array([flip, 1.0, 1.0, flip, flip])
            ball_5dof(**BEARING, axial_load=load[:, 0], radial_load=load[:, 1],
                      radial_load_z=load[:, 2], moment_y=load[:, 3], moment_z=load[:, 4])
        if rear != "spring":
            crb_radial(**ROLLERS, radial_load=np.abs(carried[:, 2, 1]),
                       misalignment=moved[:, 4] * np.sign(moved[:, 1]))

    ratio, lowest, highest, ours, theirs, load = interleaved(measured, baseline, pairs=5)
    kind = "a spring" if rear == "spring" else "a cylindrical roller bearing"
    print(f"shaft_system, {POINTS} points, two ball bearings and {kind}, through the API")
    print(f"  baseline: the bearings alone at the same points, "
          f"{theirs / POINTS * 1e6:.1f} us a point; the system {ours / POINTS * 1e6:.1f} us "
          "a point")
    print(f"  ratio: {ratio:.2f}x (goal: at most 5, the system over its bearings' own "
          f"solves); pairs {lowest:.2f}-{highest:.2f}x, load average {load[0]:.2f}")


def main():
    for rear in ("spring", "crb_radial"):
        compare(rear)


if __name__ == "__main__":
    main()
