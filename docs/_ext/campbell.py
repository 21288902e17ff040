"""The Campbell diagram of the rotor-dynamics page: a shaft on a ball bearing and a cylindrical
roller bearing, solved by ``shaft_system`` over the speed, its bearings' stiffness at each
speed given to ross as ``BearingElement`` objects, and ross's damped natural frequencies drawn
against the speed.

ross prints and warns as it imports (its dependency ccp looks for a REFPROP library, from C
and from Python): both are kept from the build's output here, and the caller's warning
filters are as they were after it.
"""
from __future__ import annotations

import contextlib
import os
import sys
import warnings
from pathlib import Path

import numpy as np

#: The rotor: a 600 mm shaft of 40 mm, a preloaded angular contact ball bearing at 50 mm and a
#: cylindrical roller bearing at 550 mm (each at a node of the 50 mm ross elements), a gear's
#: load between them; the shaft's speed swept (its roller bearing's stiffness depends on it).
DEFINITION = """
[sweep]
model = "shaft_system"
title = "A shaft on a 71807AC and the roller bearing D, over speed"
[shaft]
sections = [{ length = "600 mm", diameter = "40 mm" }]
[supports.front]
model = "ball_5dof"
bearing = "paper001-71807AC"
position = "50 mm"
clearance = "-5 um"
[supports.rear]
model = "crb_radial"
bearing = "paper000-D"
position = "550 mm"
clearance = "10 um"
[loads.gear]
position = "300 mm"
force_x = "300 N"
force_y = "2 kN"
[axes]
speed = { start = "1000 rpm", stop = "30000 rpm", num = 11 }
"""
#: The ross model: elements, the bearings' nodes, the damping given to each [m, N s/m].
ELEMENT_LENGTH, DIAMETER, NODES, DAMPING = 0.05, 0.04, {"front": 1, "rear": 11}, 200.0


def campbell_figure(path: Path) -> Path:
    """Compute the rotor's Campbell diagram and save it as a PNG at ``path``."""
    import bearing_sweep
    from bearing_sweep.plotting import save, subplots
    from bearing_sweep.rotordynamics import bearing_coefficients, bearing_element

    system = bearing_sweep.run(DEFINITION, workers=0, progress=False)
    swept = bearing_coefficients(system, support="rear")["frequency"]
    speeds = np.linspace(swept[0], swept[-1], 30)  # rad/s, within the sweep's speeds
    with warnings.catch_warnings(), _descriptors_silenced():
        warnings.simplefilter("ignore")
        import ross
        steel = ross.Material(name="docs_steel", rho=7850, E=210e9, G_s=81e9)
        shaft = [ross.ShaftElement(L=ELEMENT_LENGTH, idl=0.0, odl=DIAMETER, material=steel)
                 for _ in range(12)]
        bearings = [bearing_element(system, node, damping=DAMPING, support=name)
                    for name, node in NODES.items()]
        rotor = ross.Rotor(shaft, [], bearings)
        campbell = rotor.run_campbell(speeds, frequencies=4)
    rpm = speeds * 30.0 / np.pi
    frequencies = campbell.wd / (2.0 * np.pi)  # Hz
    whirl = np.asarray(campbell.whirl_values)  # ross: 1 forward, 0 backward, 0.5 mixed
    at = np.broadcast_to(rpm[:, None], frequencies.shape)
    figure, axis = subplots(1, 1, figsize=(7.5, 4.5))
    for mode in range(frequencies.shape[1]):
        axis.plot(rpm, frequencies[:, mode], color="C0", linewidth=1.0)
    for value, style in ((1.0, {"color": "C0"}),
                         (0.0, {"facecolor": "white", "edgecolor": "C0"}),
                         (0.5, {"color": "C1", "marker": "x"})):
        chosen = np.isclose(whirl, value)
        name = {1.0: "forward", 0.0: "backward", 0.5: "mixed"}[value]
        if chosen.any():
            axis.scatter(at[chosen], frequencies[chosen], s=12, zorder=3,
                         label=f"mode, {name} whirl", **style)
    axis.plot(rpm, rpm / 60.0, color="C3", linestyle="--", label="running speed (1x)")
    gap = frequencies[:, 0] - rpm / 60.0  # the lowest mode against the running speed
    crossing = np.flatnonzero(np.diff(np.sign(gap)) != 0)
    if crossing.size:
        i = crossing[0]
        critical = rpm[i] - gap[i] * (rpm[i + 1] - rpm[i]) / (gap[i + 1] - gap[i])
        axis.plot([critical], [critical / 60.0], "o", color="C3", markersize=8,
                  markerfacecolor="none",
                  label=f"first critical speed, {critical:.0f} r/min")
    axis.set(xlabel="rotor speed [r/min]", ylabel="damped natural frequency [Hz]",
             title="Campbell diagram of a shaft on a 71807AC and the roller bearing D",
             ylim=(0.0, 1.1 * np.nanmax(frequencies)))
    axis.legend(fontsize=8, loc="center left")
    save(figure, path.parent, path.name)
    return path


@contextlib.contextmanager
def _descriptors_silenced():
    """The process' standard output and error sent to the null device for the block (a C
    library's prints too), then restored."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 1)
            os.dup2(null.fileno(), 2)
            yield
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for descriptor in saved:
            os.close(descriptor)
