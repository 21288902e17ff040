"""`plot` and `bearing-sweep plot`: one output against one axis, read from a real result."""
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from bearing_sweep.quicklook import plot
from bearing_sweep.spec import SpecError
from bearing_sweep.store import open_result

EVERY_MODEL = Path(__file__).resolve().parent / "data" / "every_model"
ONE_AXIS = """
[sweep]
model = "hertz_point"
[fixed]
curvature_1x = "0.2 1/mm"
curvature_1y = "0.2 1/mm"
curvature_2x = "-0.19 1/mm"
curvature_2y = "0 1/mm"
[axes]
load = ["10 N", "500 N", "3 kN"]
"""


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "bearing_sweep", *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=300)


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    folder = tmp_path_factory.mktemp("results")
    (folder / "hertz_one_axis.toml").write_text(ONE_AXIS)
    paths = {}
    for name, definition in (("crb_radial", EVERY_MODEL / "crb_radial.toml"),
                             ("ball_5dof", EVERY_MODEL / "ball_5dof.toml"),
                             ("hertz", folder / "hertz_one_axis.toml")):
        paths[name] = folder / f"{name}.nc"
        done = cli("run", definition, "-o", paths[name], "--workers", "0", "--quiet")
        assert done.returncode == 0, done.stderr
    return paths


def markers(axis, marker):
    return [line for line in axis.lines if line.get_marker() == marker
            and line.get_linestyle() == "None"]


def test_two_axes_a_line_per_value_labels_and_conditions(results, tmp_path):
    figure = plot(results["crb_radial"], output=tmp_path / "f.png")
    data = open_result(results["crb_radial"])
    [axis] = figure.axes
    assert len(axis.lines) == data.sizes["clearance"]
    assert axis.get_xlabel() == f"{data.radial_load.attrs['long_name']} [kN]"  # as written
    first = data["radial_displacement"]
    assert axis.get_ylabel() == f"{first.attrs['long_name']} [{first.attrs['units']}]"
    assert [t.get_text() for t in axis.get_legend().get_texts()] == ["0 mm", "0.03 mm"]
    np.testing.assert_allclose(axis.lines[0].get_xdata(), [0.5, 3.375, 6.25, 9.125, 12])
    np.testing.assert_allclose(axis.lines[1].get_ydata(),
                               data["radial_displacement"].isel(clearance=1).values)
    title = figure._suptitle.get_text()
    assert "paper000-D" in title and "speed = 6000 rpm" in title and "crown = 4 um" in title
    assert "pitch diameter = 65 mm" in title  # from the preset
    assert "slices" not in title and data.slices.attrs["origin"] == "default"  # not chosen
    assert (tmp_path / "f.png").read_bytes().startswith(b"\x89PNG")


def test_one_axis_one_line(results):
    [axis] = plot(results["hertz"]).axes
    assert len(axis.lines) == 1 and axis.get_legend() is None
    assert axis.get_xlabel().endswith("[N]")


def test_more_axes_make_panels_and_failed_points_are_marked(results):
    data = open_result(results["ball_5dof"])
    figure = plot(data, "axial_displacement")
    assert len(figure.axes) == data.sizes["geometry"] * data.sizes["fixed_dofs"]
    for axis in figure.axes:
        assert len([l for l in axis.lines if l.get_linestyle() != "None"]) == 3  # radial loads
    failed = (data.status != 0) & (data.status != 4)
    assert sum(len(line.get_xdata()) for axis in figure.axes
               for line in markers(axis, "x")) == int(failed.sum()) > 0


def test_a_string_axis_along_x(results):
    axis = plot(results["ball_5dof"], "axial_displacement", x="geometry").axes[-1]
    assert [t.get_text() for t in axis.get_xticklabels()] == ["jones", "fixed_angle"]


def test_a_per_roller_output_as_its_distribution(results):
    data = open_result(results["crb_radial"])
    [axis] = plot(data, "roller_load").axes
    assert "over roller" in axis.get_ylabel()
    assert len(axis.collections) == data.sizes["clearance"]  # a band per line
    band = axis.collections[0].get_paths()[0].vertices[:, 1]
    assert band.max() == pytest.approx(float(data.roller_load.isel(clearance=0).max()))
    np.testing.assert_allclose(axis.lines[0].get_ydata(),
                               data.roller_load.isel(clearance=0).mean("roller").values)


def test_out_of_validity_ringed_and_not_converged_crossed(results):
    data = open_result(results["crb_radial"])
    data["status"][1, 0] = 4  # out_of_validity: values kept
    data["status"][2, 1] = 1  # not_converged: NaN
    data["radial_displacement"][2, 1] = np.nan
    [axis] = plot(data).axes
    [ring] = [line for line in markers(axis, "o") if line.get_markerfacecolor() == "none"]
    assert ring.get_xdata() == pytest.approx([data.radial_load.values[1] / 1000])
    [cross] = markers(axis, "x")
    assert cross.get_xdata() == pytest.approx([data.radial_load.values[2] / 1000])


def test_unknown_names_have_a_close_match(results):
    with pytest.raises(SpecError, match="did you mean 'radial_stiffness'"):
        plot(results["crb_radial"], "radial_stifness")
    with pytest.raises(SpecError, match="did you mean 'clearance'"):
        plot(results["crb_radial"], x="clerance")


def test_cli_writes_beside_the_result_and_replaces_its_own_figure(results, tmp_path):
    result = tmp_path / "r.nc"
    result.write_bytes(results["hertz"].read_bytes())
    for _ in range(2):
        done = cli("plot", result)
        assert done.returncode == 0, done.stderr
        assert (tmp_path / "r.png").read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize("case", ["result", "folder", "other_file", "variable", "axis"])
def test_cli_refuses_in_one_line_and_writes_nothing(results, tmp_path, case):
    result = tmp_path / "r.nc"
    result.write_bytes(results["hertz"].read_bytes())
    (tmp_path / "folder.png").mkdir()
    (tmp_path / "notes.png").write_text("not a figure")
    args = {"result": ["-o", result], "folder": ["-o", tmp_path / "folder.png"],
            "other_file": ["-o", tmp_path / "notes.png"], "variable": ["semi_majr"],
            "axis": ["--x", "lod"]}[case]
    before = sorted(p.name for p in tmp_path.iterdir())
    done = cli("plot", result, *args)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    assert (tmp_path / "notes.png").read_text() == "not a figure"
    assert result.read_bytes() == results["hertz"].read_bytes()


def test_a_long_axis_of_lines_is_thinned_evenly(results):
    data = open_result(results["crb_radial"])
    loads = xr.DataArray(np.arange(1.0, 11.0) * 1000, dims="radial_load",
                         attrs=data.radial_load.attrs)  # ten loads, in N, written in kN
    data = data.isel(radial_load=[0, 1, 2, 3, 4, 0, 1, 2, 3, 4]).assign_coords(
        radial_load=loads)
    [axis] = plot(data, x="clearance").axes
    assert [t.get_text() for t in axis.get_legend().get_texts()] == [
        f"{v:g} kN" for v in (1, 2, 4, 5, 6, 7, 9, 10)]
