"""ball_5dof through definitions and the engine: held displacements, labelled matrix, units."""
import numpy as np
import pytest

from models.registry import CONVERGED, INFEASIBLE
from sweeps import run, spec
from sweeps.spec import SpecError

GOOD = """
[sweep]
model = "ball_5dof"
bearing = "paper001-71807AC"
[fixed]
axial_load = "2800 N"
[axes]
radial_load = ["0 N", "1500 N", "3000 N"]
[axes.form]
labels = ["held", "free", "fixed_angle_free"]
geometry = ["jones", "jones", "fixed_angle"]
fixed_dofs = [["tilt_z", "tilt_y"], [], []]
"""


def test_held_displacements_are_a_list_in_declared_order():
    sweep = spec.parse(GOOD, "def.toml")
    form = next(a for a in sweep.axes if a.name == "form")
    assert [v.si for v in form.values["fixed_dofs"]] == ["tilt_y tilt_z", "", ""]


@pytest.mark.parametrize("old, new, words", [
    ('[["tilt_z", "tilt_y"], [], []]', '[["tilt"], [], []]',
     ["axes.form.fixed_dofs[0]", "'tilt' is not accepted", "did you mean"]),
    ('[["tilt_z", "tilt_y"], [], []]', '[["axial", "axial"], [], []]', ["listed twice"]),
    ('[["tilt_z", "tilt_y"], [], []]', '["tilt_z", [], []]', ["a list of distinct values"]),
    ('axial_load = "2800 N"', 'axial_load = "2800 N"\nfixed_dofs = "axial"',
     ["fixed.fixed_dofs", "a list of distinct values"]),
    ('axial_load = "2800 N"', 'axial_load = "2800 N"\nfixed_dofs = ["axial"]',
     ["given twice"]),
    ('labels = ["held", "free", "fixed_angle_free"]', 'labels = ["held", "free", "f"]\n'
     'moment_y = ["1 N*m", "0 N*m", "0 N*m"]', ["load is given along a displacement held",
                                                 "moment_y = 1 N*m"]),
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


def test_the_dataset_labels_dofs_units_and_flags_the_singular_form(tmp_path):
    sweep = spec.parse(GOOD, "def.toml")
    run.run_sweep(sweep, tmp_path / "out.nc", run.Executor(workers=0), progress=False)
    data = run.store.open_result(tmp_path / "out.nc")
    assert list(data.dof.values) == ["axial", "radial_y", "radial_z", "tilt_y", "tilt_z"]
    assert data.stiffness_matrix_units.sel(load_dof="tilt_y", dof="axial").item() == "N*m/mm"
    assert data.displacement_units.sel(dof="tilt_z").item() == "rad"
    status = data.status.sel(radial_load=3000)
    assert list(status.values) == [CONVERGED, CONVERGED, INFEASIBLE]
    assert np.isnan(data.stiffness_matrix.sel(form="fixed_angle_free", radial_load=3000)).all()
    held = data.sel(form="held", radial_load=3000)
    assert held.displacement.sel(dof="tilt_y").item() == 0.0
    # Units at the boundary: a tilt stiffness in N*m/rad is the SI entry unchanged, a
    # translation entry in N/mm is the SI one / 1000.
    matrix = held.stiffness_matrix
    assert matrix.sel(load_dof="axial", dof="axial") > 1e4  # N/mm: ~1e5 for this bearing
    assert data.fixed_dofs.sel(form="held").item() == "tilt_y tilt_z"


def test_chunking_does_not_change_the_numbers(tmp_path):
    text = GOOD.replace('["0 N", "1500 N", "3000 N"]', '{start = "0 N", stop = "3000 N", num = 7}')
    sweep = spec.parse(text, "def.toml")
    one = run.run_sweep(sweep, tmp_path / "one.nc", run.Executor(workers=0), progress=False)
    many = run.run_sweep(sweep, tmp_path / "many.nc", run.Executor(workers=0), chunk_size=2,
                         progress=False)
    assert one.points == many.points == 21
    first = run.store.open_result(tmp_path / "one.nc")
    second = run.store.open_result(tmp_path / "many.nc")
    for name in ("stiffness_matrix", "ball_load", "displacement"):
        np.testing.assert_array_equal(first[name].values, second[name].values)


