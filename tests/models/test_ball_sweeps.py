"""ball_5dof through definitions and the engine: held displacements, labelled matrix, units."""
import numpy as np
import pytest

from bearing_sweep.models.registry import CONVERGED
from bearing_sweep import compute, spec
from bearing_sweep.spec import SpecError

GOOD = """
[sweep]
model = "ball_5dof"
bearing = "paper001-71807AC"
[fixed]
axial_load = "2800 N"
[axes]
radial_load = ["0 N", "1500 N", "3000 N"]
[axes.form]
labels = ["held", "free", "fixed_angle_held"]
geometry = ["jones", "jones", "fixed_angle"]
fixed_dofs = [["tilt_z", "tilt_y"], [], ["tilt_y", "tilt_z"]]
"""
FIXED_DOFS = '[["tilt_z", "tilt_y"], [], ["tilt_y", "tilt_z"]]'



def test_held_displacements_are_a_list_in_declared_order():
    sweep = spec.parse(GOOD, "def.toml")
    form = next(a for a in sweep.axes if a.name == "form")
    assert [v.si for v in form.values["fixed_dofs"]] == ["tilt_y tilt_z", "", "tilt_y tilt_z"]


@pytest.mark.parametrize("old, new, words", [
    (FIXED_DOFS, '[["tilt"], [], []]',
     ["axes.form.fixed_dofs[0]", "'tilt' is not accepted", "did you mean"]),
    (FIXED_DOFS, '[["axial", "axial"], [], []]', ["listed twice"]),
    (FIXED_DOFS, '["tilt_z", [], []]', ["a list of distinct values"]),
    ('axial_load = "2800 N"', 'axial_load = "2800 N"\nfixed_dofs = "axial"',
     ["fixed.fixed_dofs", "a list of distinct values"]),
    ('axial_load = "2800 N"', 'axial_load = "2800 N"\nfixed_dofs = ["axial"]',
     ["given twice"]),
    ('labels = ["held", "free", "fixed_angle_held"]', 'labels = ["held", "free", "f"]\n'
     'moment_y = ["1 N*m", "0 N*m", "0 N*m"]', ["load is given along a displacement held",
                                                 "moment_y = 1 N*m"]),
    # The fixed-angle geometry with free tilts: singular at every load, refused up front.
    (FIXED_DOFS, '[["tilt_z", "tilt_y"], [], []]',
     ["geometry 'fixed_angle' with tilt_y and radial_z free", "singular at every load",
      "geometry = fixed_angle"]),
    (FIXED_DOFS, '[["tilt_z", "tilt_y"], [], ["tilt_y", "radial_z"]]',
     ["singular at every load"]),
    ('bearing = "paper001-71807AC"', 'bearing = "paper001-71807AC"\n[fixed.clearance]',
     ["fixed.clearance", "expected a number with units"]),
])
def test_mistakes_in_ball_definitions_are_one_line(old, new, words):
    assert old in GOOD
    with pytest.raises(SpecError) as caught:
        spec.parse(GOOD.replace(old, new, 1), "def.toml")
    message = str(caught.value)
    assert "\n" not in message
    for word in words:
        assert word in message, message


def test_the_dataset_labels_dofs_and_stores_a_symmetric_matrix_in_si(tmp_path):
    sweep = spec.parse(GOOD, "def.toml")
    compute.run_sweep(sweep, tmp_path / "out.nc", compute.Executor(workers=0), progress=False)
    data = compute.stores.open_result(tmp_path / "out.nc")
    assert list(data.dof.values) == ["axial", "radial_y", "radial_z", "tilt_y", "tilt_z"]
    # One unit system (SI), so that the matrix can go as it is into a rotor-dynamics code:
    # dFx/d(phi_y) in N/rad, dMy/d(delta_x) in N*m/m = N.
    units_of = data.stiffness_matrix_units
    assert units_of.sel(load_dof="tilt_y", dof="axial").item() == "N"
    assert units_of.sel(load_dof="axial", dof="tilt_y").item() == "N/rad"
    assert units_of.sel(load_dof="axial", dof="axial").item() == "N/m"
    assert units_of.sel(load_dof="tilt_y", dof="tilt_z").item() == "N*m/rad"
    assert data.displacement_units.sel(dof="tilt_z").item() == "rad"
    assert data.displacement_units.sel(dof="axial").item() == "m"
    # UDUNITS has no fractional powers: no units attribute, the SI unit named in the comment
    assert "units" not in data.hertz_contact_constant.attrs
    assert "N/m^1.5 (SI)" in data.hertz_contact_constant.attrs["comment"]
    assert "units" not in data.stiffness_matrix.attrs
    assert data.stiffness_matrix.attrs["ancillary_variables"] == "stiffness_matrix_units"
    assert data.max_contact_pressure.attrs["units"] == "MPa"
    assert (data.status == CONVERGED).all()
    matrix = data.stiffness_matrix
    transposed = matrix.rename(load_dof="dof", dof="load_dof").transpose(*matrix.dims)
    assert (matrix.values == transposed.values).all()
    held = data.sel(form="held", radial_load=3000)
    assert held.displacement.sel(dof="tilt_y").item() == 0.0
    assert 1e7 < held.stiffness_matrix.sel(load_dof="axial", dof="axial") < 1e9  # N/m
    assert 0 < held.displacement.sel(dof="axial").item() < 1e-4  # m: tens of micrometres
    assert data.fixed_dofs.sel(form="held").item() == "tilt_y tilt_z"
    pressure = held.max_contact_pressure.max().item()
    assert 1000 < pressure < 4200  # MPa


def test_chunking_does_not_change_the_numbers(tmp_path):
    text = GOOD.replace('["0 N", "1500 N", "3000 N"]', '{start = "0 N", stop = "3000 N", num = 7}')
    sweep = spec.parse(text, "def.toml")
    one = compute.run_sweep(sweep, tmp_path / "one.nc", compute.Executor(workers=0), progress=False)
    many = compute.run_sweep(sweep, tmp_path / "many.nc", compute.Executor(workers=0), chunk_size=2,
                         progress=False)
    assert one.points == many.points == 21
    first = compute.stores.open_result(tmp_path / "one.nc")
    second = compute.stores.open_result(tmp_path / "many.nc")
    for name in ("stiffness_matrix", "ball_load", "displacement"):
        np.testing.assert_array_equal(first[name].values, second[name].values)


