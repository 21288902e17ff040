"""A tapered roller bearing on a shaft: trb_load's roller law in the shaft's five degrees of
freedom, checked against trb_load solving the same bearing alone, against its own finite
differences and against statics on a shaft."""
import numpy as np
import pytest

from bearing_sweep.definition.values import default_value
from bearing_sweep.models.registry import CONVERGED, OUT_OF_VALIDITY, outcome
from bearing_sweep.models.shaft_mounting import SUPPORT_OPERATING_INPUTS
from bearing_sweep.models.shaft_tapered import TaperedSupport
from bearing_sweep.models.tapered import trb_load

MOUNTING = {spec.name for spec in SUPPORT_OPERATING_INPUTS}
#: Paper 003's bearing (Table 1), in SI, with eq. 14's contact constant.
TAPERED = {"roller_count": 16, "effective_length": 21.5e-3, "roller_mean_diameter": 13.71e-3,
           "outer_contact_angle": np.radians(28.0), "pitch_diameter": 79.537e-3}


def test_its_rollers_carry_what_trb_load_finds_at_their_displacement():
    support = TaperedSupport(**TAPERED)
    for radial, axial in [(40e3, 27e3), (5e3, 20e3), (1e3, 30e3)]:
        alone = trb_load(radial, axial, **TAPERED)  # paper 003's eq. 13-18 solved alone
        assert outcome(alone["status"])[0] == CONVERGED
        moved = [alone["axial_displacement"][0], alone["radial_displacement"][0], 0, 0, 0]
        load, _ = support.loads(moved)
        assert load[0, :3] == pytest.approx([axial, radial, 0.0], rel=1e-9, abs=1e-6)
        assert support.largest_pressure(moved)[0] == pytest.approx(
            alone["largest_contact_pressure"][0], rel=1e-12)
        rating = 127.6e3
        turns = 2e6 * np.pi  # trb_load's lives in SI [rad]; the support's in 10^6 rev
        assert support.reference_life(moved, rating)[0] == pytest.approx(
            trb_load(radial, axial, **TAPERED, dynamic_load_rating=rating)[
                "reference_rating_life"][0] / turns, rel=1e-12)


def test_its_stiffness_is_the_derivative_of_its_loads():
    support = TaperedSupport(**TAPERED, clearance=-20e-6)
    moved = np.array([15e-6, 8e-6, -5e-6, 2e-4, -1e-4])
    _, stiffness = support.loads(moved)
    steps = np.array([1e-9, 1e-9, 1e-9, 1e-8, 1e-8])
    numeric = np.empty((5, 5))
    for column, step in enumerate(steps):
        change = np.zeros(5)
        change[column] = step
        numeric[:, column] = (support.loads(moved + change)[0][0]
                              - support.loads(moved - change)[0][0]) / (2 * step)
    np.testing.assert_allclose(stiffness[0], numeric, rtol=1e-6,
                               atol=1e-7 * np.abs(numeric).max())
    np.testing.assert_allclose(stiffness[0], stiffness[0].T, rtol=1e-12,
                               atol=1e-12 * np.abs(numeric).max())


def test_a_tilt_moves_the_rollers_load_as_the_axial_parts_moment_has_it():
    # Tilting about z by theta moves the pitch circle's point at azimuth 0 (on +y) by
    # -R theta along x: a preloaded bearing's rollers there unload, those at 180 deg load
    # up, and the moment on the bearing is -R sum Q sin(alpha) cos(psi) > 0 against it.
    support = TaperedSupport(**TAPERED, clearance=-20e-6)
    load, _ = support.loads([0.0, 0.0, 0.0, 0.0, 1e-4])
    assert load[0, 4] > 0 and load[0, 3] == pytest.approx(0.0, abs=1e-9 * load[0, 4])
    _, centred = support.loads(np.zeros(5))  # every roller preloaded alike
    assert centred[0, 4, 4] > 0 and centred[0, 3, 3] == pytest.approx(
        centred[0, 4, 4], rel=1e-12)  # the same about y and z, by symmetry


def system(loads, clearance=0.0, **values):
    """A 300 mm shaft of 45 mm on two tapered roller bearings set face to face, at 50 and
    250 mm, the second mounted the other way round, under ``loads``."""
    from bearing_sweep.models.shaft_system import assemble

    model = assemble(np.array([(0.3, 0.045, 0.0)]), {"A": "trb_load", "B": "trb_load"},
                     list(loads))
    given = {"shaft_youngs_modulus": 210e9, "shaft_poisson_ratio": 0.3, "station_count": 5,
             "shaft_density": 7850.0, "gravity_x": 0.0, "gravity_y": 0.0, "gravity_z": 0.0,
             "speed": 0.0}
    for name, position, direction in (("A", 0.05, "positive"), ("B", 0.25, "negative")):
        given |= {f"supports_{name}_{key}": value for key, value in TAPERED.items()}
        given |= {f"supports_{name}_position": position, f"supports_{name}_clearance": clearance,
                  f"supports_{name}_axial_direction": direction,
                  f"supports_{name}_contact_constant": None,
                  f"supports_{name}_youngs_modulus": 206e9,
                  f"supports_{name}_poisson_ratio": 0.3,
                  f"supports_{name}_pressure_limit": 4e9,
                  f"supports_{name}_dynamic_load_rating": 127.6e3}
    for name, load in loads.items():
        given |= {f"loads_{name}_{key}": load.get(key, 0.0) for key in
                  ("position", "force_x", "force_y", "force_z", "moment_y", "moment_z")}
    given |= {spec.name: default_value(spec).si for spec in model.inputs  # unmounted, 20 degC
              if spec.name not in given and spec.name.split("_", 2)[-1] in MOUNTING}
    assert {i.name for i in model.inputs} == set(given)
    return {key: np.asarray(value)[0] for key, value in model.function(**given).items()}


def test_a_pair_on_a_shaft_balances_the_loads_and_shares_them_as_symmetry_says():
    result = system({"gear": {"position": 0.15, "force_y": 20e3}}, clearance=-30e-6)
    assert outcome(result["status"]) == CONVERGED
    on = result["support_load"]
    assert on[:, :3].sum(axis=0) == pytest.approx([0.0, 20e3, 0.0], abs=1e-5)
    # Moments about the left end: each support's own moment besides its forces' lever.
    positions = np.array([0.05, 0.25])
    about_z = (positions * on[:, 1]).sum() + on[:, 4].sum()
    assert about_z == pytest.approx(0.15 * 20e3, rel=1e-9)
    # Mirror symmetry about the load: equal radial loads, and thrusts equal and opposite
    # (each row pushes the shaft towards the other, preloaded against it).
    assert on[0, 1] == pytest.approx(on[1, 1], rel=1e-9)
    assert on[0, 0] == pytest.approx(-on[1, 0], rel=1e-9) and on[0, 0] > 0
    assert np.isfinite(result["system_reference_life"])


def test_each_row_takes_thrust_its_own_way_and_an_overload_is_flagged():
    # The row facing the shaft's thrust carries it and the thrust its neighbour's radial
    # load induces (a tapered row under radial load pushes its cone off axially).
    result = system({"gear": {"position": 0.15, "force_x": 8e3, "force_y": 5e3}})
    assert outcome(result["status"]) == CONVERGED
    on = result["support_load"]
    assert on[0, 0] + on[1, 0] == pytest.approx(8e3, rel=1e-9)
    assert on[0, 0] > 8e3 and on[1, 0] < 0
    heavy = system({"gear": {"position": 0.15, "force_x": 8e3, "force_y": 600e3}})
    assert heavy["status"] & OUT_OF_VALIDITY
