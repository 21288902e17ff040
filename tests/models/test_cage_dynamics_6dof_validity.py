"""What the spatial cage model's run checks of its own state: the raceway contacts' pressure,
the cage's reach toward the rings, an unstable fixed step; and the inputs it refuses."""
import numpy as np
import pytest

import bearing_sweep
from bearing_sweep import spec
from bearing_sweep.dependence import flag_holds
from bearing_sweep.models.cylindrical import crb_radial

MM, RPM = 1e-3, 2 * np.pi / 60


def sweep(axes: str, **fixed):
    """The test bearing (preset paper002-test) at 800 N and 12000 r/min over 4 ms, in this
    process, with ``fixed`` values and ``axes`` (TOML lines of the [axes] table)."""
    values = {"radial_load": "800 N", "speed": "12000 rpm", "duration": "4 ms", **fixed}
    lines = "\n".join(f'{name} = "{value}"' for name, value in values.items())
    return bearing_sweep.run('[sweep]\nmodel = "cage_dynamics_6dof"\nbearing = "paper002-test"\n'
                             f'[fixed]\n{lines}\n[axes]\n{axes}\n', workers=0, progress=False)


def flagged(status) -> list[bool]:
    return flag_holds(status, "out_of_validity").values.tolist()


def test_the_raceway_pressure_is_the_load_distributions_and_crushing_is_flagged():
    found = sweep('misalignment_x = ["0 deg", "0.5 deg", "2 deg"]')
    pressure = found.largest_contact_pressure.values  # [MPa]
    # The aligned bearing's dynamic peak against crb_radial's static load distribution of the
    # same bearing (paper002-test: 13 rollers of 10 mm on a 54.01 mm pitch circle, 7.2 mm
    # effective length in 10 slices, 0.02 mm clearance, 7820 kg/m^3, 207 GPa, 0.28).
    static = crb_radial(800.0, 13, 54.01 * MM, 10 * MM, 7.2 * MM, clearance=0.02 * MM,
                        slices=10, speed=12000 * RPM, roller_density=7820.0,
                        youngs_modulus=207e9, poisson_ratio=0.28)
    assert pressure[0] == pytest.approx(float(static["largest_contact_pressure"]) / 1e6, rel=0.03)
    # 2 deg of misalignment presses the rollers' edges past ISO 76's 4000 MPa: flagged
    assert pressure[1] < 4000 < pressure[2]
    assert flagged(found.status) == [False, False, True]


def test_a_cage_reaching_the_rib_is_out_of_validity():
    # The cage's bore (48.5 mm) clears the rib (44 + 2 x 2 mm) by 0.25 mm: a pocket
    # clearance of 0.3 mm lets the cage's centre wander farther.
    found = sweep('pocket_clearance = ["0.1 mm", "0.3 mm"]', duration="5 ms")
    reach = np.hypot(found.cage_x, found.cage_y).max("elapsed_time").values  # [um]
    assert reach[0] < 250 < reach[1]
    assert flagged(found.status) == [False, True]


def test_an_unstable_fixed_step_is_not_converged():
    found = sweep('rk4_step = ["1e-5 s", "1e-4 s"]', integrator="rk4")
    assert flag_holds(found.status, "not_converged").values.all()


@pytest.mark.parametrize("changes, refused", [
    ({}, None),
    ({"rib_height": "1 mm"}, "face_rings x face_angles too coarse"),
    ({"rib_height": "1 mm", "face_rings": 10, "face_angles": 24}, None),
    ({"rib_height": "0.5 mm"}, "rib_height must exceed end_chamfer"),
    ({"face_rings": 1, "face_angles": 3}, "face_rings x face_angles too coarse"),
    ({"winkler_depth": "2 mm"}, None),
    ({"winkler_depth": "6 mm"}, "winkler_depth must not exceed the cage's wall"),
    ({"winkler_depth": "2.5 mm"}, "winkler_depth must not exceed"),  # the rib: 2 mm
    ({"film_breakdown": "7 um"}, None),
    ({"film_breakdown": "8 um"}, "film_breakdown must be below half of pocket_clearance"),
    ({"duration": "1 ms", "output_interval": "0.3 ms"}, "a whole number of them"),
])
def test_inputs_the_model_cannot_stand_for_are_refused(changes, refused):
    # The cage's wall (59 - 48.5) / 2 = 5.25 mm; the end film 15 um; the end-face elements
    # against the faces: models.cage_end_faces (test_cage_end_faces).
    fixed = "\n".join(f'{k} = "{v}"' if isinstance(v, str) else f"{k} = {v}"
                      for k, v in changes.items())
    text = ('[sweep]\nmodel = "cage_dynamics_6dof"\nbearing = "paper002-test"\n'
            f'[fixed]\nradial_load = "800 N"\nspeed = "12000 rpm"\n{fixed}\n')
    if refused is None:
        spec.parse(text)
        return
    with pytest.raises(spec.SpecError, match=refused):
        spec.parse(text)
