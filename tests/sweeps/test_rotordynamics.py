"""A bearing's stiffness over speed for a rotor-dynamics model, and ross BearingElements from
it."""
import math

import numpy as np
import pytest

import bearing_sweep
from bearing_sweep.models.registry import OUT_OF_VALIDITY
from bearing_sweep.rotordynamics import bearing_coefficients, bearing_element

SPEEDS = ["2000 rpm", "6000 rpm", "10000 rpm", "14000 rpm", "18000 rpm"]
#: The 71807AC of paper 001 preloaded, its inner ring growing with speed (a bore given), so
#: that its operating clearance and stiffness change along the speeds.
DEFINITION = {"sweep": {"model": "ball_5dof", "bearing": "paper001-71807AC"},
              "fixed": {"axial_load": "1 kN", "radial_load": "300 N", "bore": "35 mm",
                        "outside_diameter": "47 mm", "shaft_fit": "5 um",
                        "clearance": "-2 um"},
              "axes": {"speed": list(reversed(SPEEDS))}}


@pytest.fixture(scope="module")
def swept():
    return bearing_sweep.run(DEFINITION, workers=0, progress=False)


def test_the_coefficients_are_the_stiffness_matrix_s_lateral_terms_in_rad_per_s(swept):
    coefficients = bearing_coefficients(swept)
    np.testing.assert_allclose(coefficients["frequency"],
                               np.array([2000, 6000, 10000, 14000, 18000]) * math.pi / 30,
                               rtol=1e-12)
    at = swept.stiffness_matrix.sel(speed=6000.0)
    assert coefficients["kxx"][1] == at.sel(load_dof="radial_y", dof="radial_y")
    assert coefficients["kyx"][1] == at.sel(load_dof="radial_z", dof="radial_y")
    # The inner ring's centrifugal growth takes clearance: the bearing stiffens with speed.
    assert (np.diff(coefficients["kxx"]) > 0).all()


def test_a_roller_bearing_s_coefficients_are_its_stiffness_along_and_its_secant_across():
    # Across its load a cylindrical roller bearing's rollers answer a sideways step as a turn
    # of the displacement: the load stays along it, so the stiffness across is F / delta.
    swept = bearing_sweep.run({"sweep": {"model": "crb_radial", "bearing": "paper000-D"},
                               "fixed": {"radial_load": "5 kN", "clearance": "10 um"},
                               "axes": {"speed": SPEEDS}}, workers=0, progress=False)
    coefficients = bearing_coefficients(swept)
    np.testing.assert_allclose(coefficients["kxx"], 1e3 * swept.radial_stiffness.values,
                               rtol=1e-12)  # N/mm to N/m
    assert swept.radial_displacement.attrs["units"] == "mm"
    np.testing.assert_allclose(coefficients["kyy"],
                               5e3 / (1e-3 * swept.radial_displacement.values), rtol=1e-12)
    assert (coefficients["kxy"] == 0).all() and (coefficients["kyx"] == 0).all()
    assert (coefficients["kyy"] < coefficients["kxx"]).all()  # a stiffening contact law


#: A shaft on a ball bearing at its front and a cylindrical roller bearing at its rear.
SHAFT = """
[sweep]
model = "shaft_system"
[shaft]
sections = [{ length = "300 mm", diameter = "45 mm" }]
[supports.front]
model = "ball_5dof"
bearing = "paper001-71807AC"
position = "30 mm"
[supports.rear]
model = "crb_radial"
bearing = "paper000-D"
position = "270 mm"
clearance = "10 um"
[loads.gear]
position = "200 mm"
force_x = "300 N"
force_y = "4 kN"
[axes]
speed = ["2000 rpm", "6000 rpm", "10000 rpm", "14000 rpm", "18000 rpm"]
"""


def test_a_shaft_system_s_bearings_give_their_own_stiffness_at_its_equilibrium():
    system = bearing_sweep.run(SHAFT, workers=0, progress=False)
    rear = bearing_coefficients(system, support="rear")
    np.testing.assert_allclose(rear["frequency"],
                               np.array([2000, 6000, 10000, 14000, 18000]) * math.pi / 30,
                               rtol=1e-12)
    stiffness = system.support_stiffness.sel(support="rear")
    np.testing.assert_array_equal(rear["kxx"], stiffness.sel(load_dof="radial_y",
                                                             dof="radial_y").values)
    # The rollers' centrifugal force presses every one on the outer ring: those contacts,
    # preloaded, are stiffer, and so is the bearing at the same load.
    assert (np.diff(rear["kxx"]) > 0).all()
    front = bearing_coefficients(system, support="front")
    assert front["kxx"].min() > 0 and np.isfinite(front["kyx"]).all()
    with pytest.raises(ValueError, match="not one of the shaft's: front, rear"):
        bearing_coefficients(system, support="middle")
    with pytest.raises(ValueError, match="names a shaft system's support"):
        bearing_coefficients(bearing_sweep.run(DEFINITION, workers=0, progress=False),
                             support="rear")


def test_a_result_with_another_axis_or_without_speeds_is_refused_in_a_line(swept):
    with pytest.raises(ValueError, match="select one value"):
        bearing_coefficients(swept.expand_dims(axial_load=[1.0, 2.0]))
    with pytest.raises(ValueError, match="two speeds or more"):
        bearing_coefficients(swept.isel(speed=[0]))
    with pytest.raises(ValueError, match="stiffness_matrix along 'speed'"):
        bearing_coefficients(swept.drop_vars("stiffness_matrix"))
    flagged = swept.copy()
    flagged["status"] = flagged["status"].copy(data=flagged["status"].values | OUT_OF_VALIDITY)
    with pytest.raises(ValueError, match="outside the model's validity"):
        bearing_coefficients(flagged)


@pytest.mark.slow
def test_a_ross_rotor_on_two_bearings_from_a_sweep_bounces_on_their_springs(swept):
    """A short, thick steel rotor (0.2 m long, 0.3 m across: its bending is some 1e-3 of the
    bearings' compliance) on two such bearings: its first two lateral modes are the rigid
    rotor bouncing on the bearings' springs in each direction, omega = (2 k / m)^(1/2), with
    k the bearing's kyy and kxx (tolerance 1 %: the rotor's shear and bending, and the
    bearings' cross terms, shift them slightly; its conical modes lie 3 % above)."""
    bearings = [bearing_element(swept, node, damping=0.0) for node in (0, 4)]
    import ross  # as bearing_element imported it, beside the tests' pint registry

    steel = ross.Material(name="test_steel", rho=7810, E=211e9, G_s=81.2e9)
    shaft = [ross.ShaftElement(L=0.05, idl=0.0, odl=0.3, material=steel) for _ in range(4)]
    rotor = ross.Rotor(shaft, [], bearings)
    modal = rotor.run_modal(speed=0.0)
    coefficients = bearing_coefficients(swept)
    expected = [math.sqrt(2 * coefficients[k][0] / rotor.m) for k in ("kyy", "kxx")]
    np.testing.assert_allclose(np.sort(modal.wn[:2]), np.sort(expected), rtol=1e-2)


@pytest.mark.slow
def test_ross_imports_beside_pint_xarray_and_leaves_its_unit_registry(swept, tmp_path):
    """ross's dependency ccp loads its units into pint's application registry where one is
    in use (pint-xarray's, here), where they clash; bearing_element imports ross beside it
    and leaves that registry as it was. In a fresh process: ross not yet imported."""
    import subprocess
    import sys

    swept.to_netcdf(tmp_path / "swept.nc")
    script = tmp_path / "check.py"
    script.write_text(
        "import pint, pint_xarray, xarray as xr\n"
        "xr.DataArray([1.0], dims='x').pint.quantify('m')\n"
        "before = pint.get_application_registry().get()\n"
        "from bearing_sweep.rotordynamics import bearing_element\n"
        f"bearing_element(xr.open_dataset({str(tmp_path / 'swept.nc')!r}), 0)\n"
        "assert pint.get_application_registry().get() is before\n")
    done = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]


@pytest.mark.slow
def test_a_ross_rotor_on_a_shaft_systems_bearings_bends_between_its_bounds():
    """A 500 mm steel shaft of 40 mm on a 71807AC at its left end and the roller bearing D at
    its right (ross nodes 0 and 10 of 50 mm elements), their stiffness at each speed from the
    shaft system's equilibrium under a gear's load. Its first lateral mode lies below the
    same shaft's pinned on rigid supports, (pi/2) (EI / (rho A))^(1/2) / L^2 (Euler-Bernoulli),
    and above Dunkerley's lower bound, 1 / omega_1^2 <= trace of the flexibility times the
    mass: the pinned beam's sum over its modes, pi^4 / 90 / omega_b^2 (omega_n = n^2
    omega_b), plus the rigid shaft's two modes on the bearings' softer springs (S. Dunkerley,
    On the whirling and vibration of shafts, Phil. Trans. R. Soc. A 185 (1894) 279-360,
    doi:10.1098/rsta.1894.0008). The shaft's shear, which ross models and the
    bound leaves out, softens it by some 1 %: the lower bound is taken 3 % lower."""
    system = bearing_sweep.run(SHAFT.replace('"300 mm", diameter = "45 mm"',
                                             '"500 mm", diameter = "40 mm"')
                               .replace('position = "30 mm"', 'position = "0 mm"')
                               .replace('position = "270 mm"', 'position = "500 mm"')
                               .replace('position = "200 mm"', 'position = "250 mm"'),
                               workers=0, progress=False)
    bearings = [bearing_element(system, node, damping=0.0, support=name)
                for name, node in (("front", 0), ("rear", 10))]
    import ross  # as bearing_element imported it

    steel = ross.Material(name="test_steel_2", rho=7850, E=210e9, G_s=81e9)
    shaft = [ross.ShaftElement(L=0.05, idl=0.0, odl=0.04, material=steel) for _ in range(10)]
    rotor = ross.Rotor(shaft, [], bearings)
    speeds = bearing_coefficients(system, support="rear")["frequency"]
    lowest = min(rotor.run_modal(speed=speed).wn[0] for speed in speeds[[0, -1]])
    length, area, inertia = 0.5, math.pi * 0.04**2 / 4, math.pi * 0.04**4 / 64
    pinned = math.pi**2 / length**2 * math.sqrt(210e9 * inertia / (7850 * area))
    springs = [min(bearing_coefficients(system, support=name)[k].min() for k in ("kxx", "kyy"))
               for name in ("front", "rear")]
    mass = 7850 * area * length
    stiffness = np.array([[springs[0] + springs[1], (springs[1] - springs[0]) * length / 2],
                          [(springs[1] - springs[0]) * length / 2,
                           (springs[0] + springs[1]) * length**2 / 4]])
    inverse_rigid = np.trace(np.linalg.solve(stiffness, np.diag([mass, mass * length**2 / 12])))
    bound = 1 / math.sqrt(math.pi**4 / 90 / pinned**2 + inverse_rigid)
    assert 0.97 * bound < lowest < pinned
