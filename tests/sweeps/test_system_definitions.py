"""A definition that gives its model's structure in tables of its own: a shaft's [shaft]
sections, [supports.<name>] and [loads.<name>], whose inputs vary on axes and samples named
``supports.A.clearance``."""
import numpy as np
import pytest

from bearing_sweep import api, spec

#: The definition the documentation shows: a ball bearing and a housing's spring under a gear.
SYSTEM = """
[sweep]
model = "shaft_system"

[shaft]
sections = [{ length = "120 mm", diameter = "40 mm" },
            { length = "80 mm", diameter = "35 mm", bore = "10 mm" }]

[supports.A]
model = "ball_5dof"
bearing = "paper001-71807AC"
position = "20 mm"

[supports.B]
model = "spring"
position = "180 mm"
radial_stiffness = "1e6 N/mm"

[loads.gear]
position = "100 mm"
force_x = "500 N"
force_y = "5 kN"
"""


def test_the_inputs_of_supports_and_loads_vary_on_axes_named_by_their_tables():
    result = api.run(SYSTEM + '[axes]\n"loads.gear.force_y" = ["1 kN", "5 kN"]\n'
                     '"supports.A.clearance" = ["0 mm", "0.01 mm"]\n', workers=0)
    assert list(result.loads_gear_force_y.values) == [1e3, 5e3]  # stored in N, as declared
    assert result.loads_gear_force_y.attrs["units"] == "N"
    assert list(result.support.values) == ["A", "B"]
    assert (result.status == 0).all()
    # Statics, whatever the bearing: the supports carry the gear's forces between them, and
    # the moment about the gear balances (B 80 mm beyond it, A 80 mm before).
    force_y = result.support_load.sel(dof="radial_y")
    assert force_y.sum("support").values == pytest.approx(
        np.broadcast_to(result.loads_gear_force_y.values[:, None], (2, 2)), rel=1e-9)
    moment = result.support_load.sel(dof="tilt_z")  # My, Mz at the bearing [N m]
    balance = (0.08 * force_y.sel(support="B") - 0.08 * force_y.sel(support="A")
               + moment.sel(support="A"))
    assert np.abs(balance.values).max() < 1e-6 * force_y.max().item()
    assert result.support_load.sel(dof="axial").sum("support").values == pytest.approx(500.0)
    # the preset's clearance replaced by the axis'
    assert result.supports_A_clearance.attrs["units"] == "mm"
    assert "supports_A_ball_count" in result.attrs["fixed_inputs"].split()


def test_a_support_s_own_table_a_preset_and_an_axis_each_give_way_to_the_next():
    sweep = spec.parse(SYSTEM + '[axes]\n"supports.A.contact_angle" = ["15 deg", "25 deg"]\n')
    assert sweep.origin["supports_A_ball_count"] == "preset paper001-71807AC"
    assert sweep.origin["supports_B_radial_stiffness"] == "supports.B"
    assert "supports_A_contact_angle" not in sweep.fixed
    assert sweep.fixed["loads_gear_force_y"].si == pytest.approx(5e3)


def test_dotted_and_plain_names_are_the_same_input_in_zipped_axes_and_samples():
    zipped = api.run(SYSTEM + '[axes.mounting]\nlabels = ["tight", "loose"]\n'
                     '"supports.A.clearance" = ["0 mm", "0.02 mm"]\n'
                     'supports_B_radial_stiffness = ["1e6 N/mm", "1e5 N/mm"]\n',
                     workers=0)
    assert zipped.supports_A_clearance.dims == ("mounting",)
    assert (zipped.status == 0).all()
    # a softer housing moves the shaft more at B
    moved = np.abs(zipped.support_displacement.sel(support="B", dof="radial_y"))
    assert float(moved.sel(mounting="loose")) > float(moved.sel(mounting="tight"))
    sampled = api.run(SYSTEM + '[sample]\nn = 4\nmethod = "latin_hypercube"\n'
                      '"loads.gear.position" = { distribution = "uniform", low = "60 mm", '
                      'high = "140 mm" }\n', workers=0)
    assert sampled.loads_gear_position.dims == ("sample",)
    assert (sampled.status == 0).all()
    # the nearer the gear to A, the more A carries
    order = np.argsort(sampled.loads_gear_position.values)
    carried = sampled.radial_support_load.sel(support="A").values[order]
    assert (np.diff(carried) < 0).all()


def test_the_results_do_not_depend_on_how_the_points_are_chunked():
    # Points of one shaft are solved together in a batch; a point alone gives the same.
    definition = SYSTEM + '[axes]\n"loads.gear.force_y" = ["1 kN", "2 kN", "4 kN", "6 kN"]\n'
    whole = api.run(definition, workers=0, progress=False)
    one_by_one = api.run(definition, workers=0, chunk_size=1, progress=False)
    assert (whole.status == 0).all()
    for name in ("support_load", "support_displacement", "stiffness_at_load", "deflection",
                 "largest_contact_pressure"):
        np.testing.assert_allclose(whole[name], one_by_one[name], rtol=0, atol=0,
                                   err_msg=name)


@pytest.mark.slow
def test_the_results_do_not_depend_on_the_workers_that_compute_them():
    # The model of one system travels to the workers with the grid.
    definition = SYSTEM + '[axes]\n"loads.gear.force_y" = ["1 kN", "2 kN", "4 kN", "6 kN"]\n'
    alone = api.run(definition, workers=0, progress=False)
    clustered = api.run(definition, workers=2, chunk_size=1, progress=False)
    assert (clustered.status == 0).all()
    for name in ("support_load", "stiffness_at_load", "deflection", "system_reference_life"):
        np.testing.assert_array_equal(alone[name], clustered[name], err_msg=name)
