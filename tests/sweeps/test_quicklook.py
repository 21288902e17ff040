"""`plot` and `bearing-sweep plot`: one output against one axis, read from a real result."""
import subprocess
import sys
from pathlib import Path

import cf_units
import numpy as np
import pytest
import xarray as xr

from bearing_sweep.quicklook import plot
from bearing_sweep.spec import SpecError
from bearing_sweep.stores import open_result

EVERY_MODEL = Path(__file__).resolve().parents[1] / "data" / "every_model"
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


@pytest.fixture(scope="module")
def results(tmp_path_factory, run_cli):
    folder = tmp_path_factory.mktemp("results")
    (folder / "hertz_one_axis.toml").write_text(ONE_AXIS)
    paths = {}
    for name, definition in (("crb_radial", EVERY_MODEL / "crb_radial.toml"),
                             ("ball_5dof", EVERY_MODEL / "ball_5dof.toml"),
                             ("hertz", folder / "hertz_one_axis.toml")):
        paths[name] = folder / f"{name}.nc"
        done = run_cli("run", definition, "-o", paths[name], "--workers", "0", "--quiet",
                       cwd=folder)
        assert done.returncode == 0, done.stderr
    return paths


def markers(axis, marker):
    return [line for line in axis.lines if line.get_marker() == marker
            and line.get_linestyle() == "None"]


def test_two_axes_a_line_per_value_labels_and_conditions(results, tmp_path):
    figure = plot(results["crb_radial"], output=tmp_path / "f.png")
    data = open_result(results["crb_radial"])
    [axis] = figure.axes
    [legend] = figure.legends  # beside the panels, not over the data
    assert len(axis.lines) == data.sizes["clearance"]
    assert axis.get_xlabel() == f"{data.radial_load.attrs['long_name']} [kN]"  # as written
    first = data["radial_displacement"]
    assert axis.get_ylabel() == f"{first.attrs['long_name']} [{first.attrs['units']}]"
    assert [t.get_text() for t in legend.get_texts()] == ["0 mm", "0.03 mm"]
    np.testing.assert_allclose(axis.lines[0].get_xdata(), [0.5, 3.375, 6.25, 9.125, 12])
    np.testing.assert_allclose(axis.lines[1].get_ydata(),
                               data["radial_displacement"].isel(clearance=1).values)
    title = figure._suptitle.get_text()
    assert "paper000-D" in title and "speed = 6000 rpm" in title and "crown = 4 um" in title
    assert "pitch diameter = 65 mm" in title  # from the preset
    assert "slices" not in title and data.slices.attrs["origin"] == "default"  # not chosen
    assert (tmp_path / "f.png").read_bytes().startswith(b"\x89PNG")


def test_one_axis_one_line(results):
    figure = plot(results["hertz"])
    [axis] = figure.axes
    assert len(axis.lines) == 1 and not figure.legends
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


def test_unknown_names_have_a_close_match_and_name_the_file(results):
    import re

    file = re.escape(str(results["crb_radial"]))
    with pytest.raises(SpecError, match=f"^{file}: unknown output 'radial_stifness'; did you "
                                        "mean 'radial_stiffness'"):
        plot(results["crb_radial"], "radial_stifness")
    with pytest.raises(SpecError, match=f"^{file}: unknown axis 'clerance'; did you mean "
                                        "'clearance'"):
        plot(results["crb_radial"], x="clerance")


def test_cli_writes_beside_the_result_and_replaces_its_own_figure(results, tmp_path, run_cli):
    result = tmp_path / "r.nc"
    result.write_bytes(results["hertz"].read_bytes())
    for _ in range(2):
        done = run_cli("plot", result, cwd=tmp_path)
        assert done.returncode == 0, done.stderr
        assert (tmp_path / "r.png").read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize("case", ["result", "folder", "other_file", "variable", "axis"])
def test_cli_refuses_in_one_line_and_writes_nothing(results, tmp_path, case, run_cli):
    result = tmp_path / "r.nc"
    result.write_bytes(results["hertz"].read_bytes())
    (tmp_path / "folder.png").mkdir()
    (tmp_path / "notes.png").write_text("not a figure")
    args = {"result": ["-o", result], "folder": ["-o", tmp_path / "folder.png"],
            "other_file": ["-o", tmp_path / "notes.png"], "variable": ["semi_majr"],
            "axis": ["--x", "lod"]}[case]
    before = sorted(p.name for p in tmp_path.iterdir())
    done = run_cli("plot", result, *args, cwd=tmp_path)
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
    [legend] = plot(data, x="clearance").legends
    assert [t.get_text() for t in legend.get_texts()] == [
        f"{v:g} kN" for v in (1, 2, 4, 5, 6, 7, 9, 10)]


# -- results of every shape: something meaningful drawn, or one line saying why not ---------

SINGLE_POINT = ONE_AXIS.replace('[axes]\nload = ["10 N", "500 N", "3 kN"]', 'load = "500 N"')
SAMPLED = ONE_AXIS.replace('[axes]\nload = ["10 N", "500 N", "3 kN"]', """[sample]
n = 12
method = "random"
load = { distribution = "uniform", low = "10 N", high = "3 kN" }""")


@pytest.fixture(scope="module")
def shapes(tmp_path_factory, run_cli):
    """Real results of the shapes a quick look must handle: a single point (netCDF and zarr),
    a sampled result, one axis (zarr)."""
    folder = tmp_path_factory.mktemp("shapes")
    paths = {}
    for name, text, suffix in (("single", SINGLE_POINT, ".nc"), ("single_zarr", SINGLE_POINT,
                                                                  ".zarr"),
                               ("sampled", SAMPLED, ".nc"), ("axis_zarr", ONE_AXIS, ".zarr")):
        (folder / f"{name}.toml").write_text(text)
        paths[name] = folder / f"{name}{suffix}"
        done = run_cli("run", folder / f"{name}.toml", "-o", paths[name], "--workers", "0",
                       "--quiet", cwd=folder)
        assert done.returncode == 0, done.stderr
    return paths


def drawn_lines(axis):
    """The data lines of a panel (not the marks of failed points)."""
    return [line for line in axis.lines
            if line.get_label() not in ("_out of validity", "_no value")]


def test_every_panel_shows_data_or_says_it_has_none(results):
    """No blank panel: a panel whose points all failed says so."""
    data = open_result(results["ball_5dof"])
    variable = data["axial_displacement"].copy()
    variable[{"geometry": 0, "fixed_dofs": 1}] = np.nan  # one panel without any value
    figure = plot(data.assign(axial_displacement=variable), "axial_displacement")
    empty = 0
    for axis in figure.axes:
        finite = any(np.isfinite(np.asarray(line.get_ydata(), dtype=float)).any()
                     for line in drawn_lines(axis))
        said = any(text.get_text().startswith("no value here") for text in axis.texts)
        assert finite != said, axis.get_title()
        empty += said
    assert empty == 1


@pytest.mark.parametrize("result", ["single", "single_zarr"])
def test_a_single_point_of_one_value_is_one_line_exit_2(shapes, tmp_path, result, run_cli):
    before = sorted(p.name for p in shapes[result].parent.iterdir())
    done = run_cli("plot", shapes[result], "max_pressure", cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert "a single point (the sweep has no axes): max_pressure is one value" in done.stderr
    assert "MPa" in done.stderr and "Traceback" not in done.stderr
    default = run_cli("plot", shapes[result], cwd=tmp_path)  # the first output: one value too
    assert default.returncode == 2 and default.stderr.count("\n") == 1, default.stderr
    assert sorted(p.name for p in shapes[result].parent.iterdir()) == before


def test_a_single_point_draws_an_output_along_its_own_entries(results):
    """A result of one point (every axis gone) draws, by default, the first output with
    entries of its own along them: the load of each roller against the roller's number."""
    data = open_result(results["crb_radial"])
    point = data.isel(radial_load=2, clearance=1)
    point["status"] = point["status"].copy()
    assert point["status"].dims == ()
    [axis] = plot(point).axes
    [line] = drawn_lines(axis)
    np.testing.assert_array_equal(line.get_xdata(), data.roller.values)
    np.testing.assert_allclose(line.get_ydata(), point.roller_load.values)
    assert axis.get_xlabel().startswith(data.roller.attrs["long_name"])
    with pytest.raises(SpecError, match="one value.*outputs with entries of their own: "
                                        "roller_load"):
        plot(point, "radial_stiffness")
    with pytest.raises(SpecError, match="radial_stiffness has no dimension 'roller'"):
        plot(data, "radial_stiffness", x="roller")


def test_an_output_without_any_value_is_one_line_naming_the_statuses(results, tmp_path, run_cli):
    data = open_result(results["hertz"])
    data["semi_major"][:] = np.nan
    data["status"][:] = [1, 1, 2]  # not converged, not converged, infeasible
    with pytest.raises(SpecError, match=r"semi_major has no value at any point \(2 not "
                                        r"converged, 1 infeasible\): nothing to draw"):
        plot(data, "semi_major")
    data.to_netcdf(tmp_path / "failed.nc")
    done = run_cli("plot", tmp_path / "failed.nc", "semi_major", cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert not (tmp_path / "failed.png").exists()


@pytest.mark.parametrize("name, kind", [("status", "the status of each point"),
                                        ("load", "a sweep axis"),
                                        ("curvature_1x", "an input the sweep holds fixed")])
def test_a_variable_that_is_not_an_output_is_named_for_what_it_is(results, name, kind, run_cli):
    with pytest.raises(SpecError, match=f"'{name}' is {kind}.*not an output \\(outputs: "
                                        "semi_major, "):
        plot(results["hertz"], name)
    done = run_cli("plot", results["hertz"], name, cwd=results["hertz"].parent)
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and kind in done.stderr


def test_a_sampled_result_is_a_point_per_sample_against_a_drawn_input(shapes):
    data = open_result(shapes["sampled"])
    figure = plot(data)
    [axis] = figure.axes
    [points] = drawn_lines(axis)
    assert points.get_linestyle() == "None"  # samples are in no order: not joined
    np.testing.assert_allclose(points.get_xdata(), data["load"].values)
    np.testing.assert_allclose(points.get_ydata(), data.semi_major.values)
    assert axis.get_xlabel() == data["load"].attrs["long_name"] + " [N]"
    assert "12 samples (random)" in figure._suptitle.get_text()
    [axis] = plot(data, x="sample").axes  # the sample number, if asked for
    np.testing.assert_array_equal(drawn_lines(axis)[0].get_xdata(), np.arange(12))


def test_an_axis_of_one_value_is_named_and_a_lone_point_labelled(results):
    data = open_result(results["crb_radial"]).isel(radial_load=[3])
    figure = plot(data)
    [axis] = figure.axes
    assert axis.get_xlabel().startswith(data.clearance.attrs["long_name"])  # the longer axis
    assert "radial load = 9.125 kN" in figure._suptitle.get_text()  # the axis of one value
    [axis] = plot(data, x="radial_load").axes
    values = [float(data.radial_displacement.isel(clearance=c, radial_load=0)) for c in (0, 1)]
    assert sorted(t.get_text() for t in axis.texts) == sorted(f"{v:.4g}" for v in values)


def test_a_zipped_axis_is_shown_by_the_values_of_its_inputs(tmp_path, run_cli):
    (tmp_path / "zip.toml").write_text(ONE_AXIS.replace('curvature_2y = "0 1/mm"\n', "") + """
[axes.case]
curvature_2y = ["0 1/mm", "0.01 1/mm"]
poisson_ratio = [0.3, 0.29]
""")
    done = run_cli("run", tmp_path / "zip.toml", "-o", tmp_path / "zip.nc", "--workers", "0",
                   "--quiet", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    [legend] = plot(tmp_path / "zip.nc").legends
    assert [t.get_text() for t in legend.get_texts()] == [
        "curvature 2y = 0 1/mm, poisson ratio = 0.3",
        "curvature 2y = 0.01 1/mm, poisson ratio = 0.29"]
    [axis] = plot(tmp_path / "zip.nc", x="poisson_ratio").axes
    np.testing.assert_allclose(drawn_lines(axis)[0].get_xdata(), [0.3, 0.29])


def in_label_unit(variable: xr.DataArray, axis) -> np.ndarray:
    """``variable``'s values in the unit a figure axis' label ends with (``[kN]``), converted
    by UDUNITS."""
    unit = axis.get_label_text().rsplit("[", 1)[1].rstrip("]")
    return cf_units.Unit(variable.attrs["units"]).convert(variable.values, cf_units.Unit(unit))


def test_a_zarr_store_plots_as_a_file_does(shapes, tmp_path, run_cli):
    done = run_cli("plot", shapes["axis_zarr"], "-o", tmp_path / "z.png", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "z.png").read_bytes().startswith(b"\x89PNG")
    [axis] = plot(shapes["axis_zarr"]).axes
    # the model's first output, though a zarr store lists its variables by name
    with xr.open_zarr(shapes["axis_zarr"]) as stored:  # read apart from the quick look
        assert axis.get_ylabel().startswith(stored.semi_major.attrs["long_name"])
        [line] = drawn_lines(axis)  # the values stored, in the units the labels say
        np.testing.assert_allclose(line.get_xdata(), in_label_unit(stored["load"], axis.xaxis))
        np.testing.assert_allclose(line.get_ydata(),
                                   in_label_unit(stored.semi_major, axis.yaxis))


# -- the user's matplotlib, warnings and logging are theirs -----------------------------------

#: Runs a statement in a fresh interpreter whose user chose a backend ("pdf", as a notebook
#: chooses its inline one) and prints what the statement changed in matplotlib's settings,
#: the warnings filters and the logging configuration, and whether it used pyplot.
GLOBAL_STATE = r'''
import json, logging, sys, warnings
import matplotlib
matplotlib.rcParams["backend"] = "pdf"


def loggers():
    every = {"root": logging.root, **logging.root.manager.loggerDict}
    return {name: (log.level, [type(h).__name__ for h in log.handlers], log.propagate,
                   log.disabled) for name, log in every.items()
            if isinstance(log, logging.Logger)}


def state():
    return {"rcParams": {k: repr(v) for k, v in matplotlib.rcParams.items()},
            "warnings.filters": repr(warnings.filters),
            "logging.disable": logging.root.manager.disable}


def changed_by(statement):
    before, before_loggers = state(), loggers()
    exec(statement)
    after, after_loggers = state(), loggers()
    changed = {key: (before[key], after[key]) for key in before if before[key] != after[key]}
    # A library may add its own logger with a NullHandler (pint does); nothing else.
    quiet = (logging.NOTSET, [], True, False)
    changed["loggers"] = {
        name: (before_loggers.get(name), value) for name, value in after_loggers.items()
        if value != before_loggers.get(name, value)
        or (name not in before_loggers and (value[0], [h for h in value[1] if h != "NullHandler"],
                                            *value[2:]) != quiet)}
    changed["pyplot used"] = "matplotlib.pyplot" in sys.modules
    return changed


exec(sys.argv[2])  # what the libraries do on their own
# Each statement against the state the one before it left.
print(json.dumps({statement: changed_by(statement) for statement in json.loads(sys.argv[1])}))
'''

def _engine_modules() -> list[str]:
    import pkgutil

    import bearing_sweep

    return sorted(m.name for m in pkgutil.walk_packages(bearing_sweep.__path__, "bearing_sweep.")
                  if not m.name.endswith("__main__")  # that one runs the program
                  and not m.name.startswith(("bearing_sweep.models", "bearing_sweep.studies")))


#: The package, each module of the engine, and the API's names imported when first asked for.
#: Not the models: cage_dynamics and cage_dynamics_6dof import scipy.integrate, whose own
#: import adds filters for scipy's own warnings (SpecialFunctionWarning), as for any user.
IMPORTS = (["import bearing_sweep"] + [f"import {name}" for name in _engine_modules()]
           + ["import bearing_sweep; bearing_sweep.plot", "import bearing_sweep; bearing_sweep.run"])
STUDIES = Path(__file__).resolve().parents[2] / "studies"


def changes(statements: list[str], cwd, libraries: str = "") -> dict:
    """What each of ``statements`` changes, in one fresh process, after ``libraries`` ran:
    ``{statement: changes}``."""
    import json

    done = subprocess.run([sys.executable, "-c", GLOBAL_STATE, json.dumps(statements),
                           libraries], cwd=cwd, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])


#: Each import of the package, its modules and the studies' figure scripts.
STATEMENTS = IMPORTS + [
    pytest.param(f"from bearing_sweep.study import find_studies; "
                 f"find_studies({str(STUDIES)!r})[{name!r}].figures_module()",
                 id=f"studies/{name}/figures.py")
    for name in sorted(p.parent.name for p in STUDIES.glob("*/figures.py"))]
UNCHANGED = {"loggers": {}, "pyplot used": False}


def test_importing_changes_no_global_state(tmp_path):
    """No import of the package, its modules or a study's figure script changes the user's
    matplotlib backend or settings, warnings filters or logging (one after another in a fresh
    process; the slow tests import each in a process of its own)."""
    statements = [getattr(s, "values", [s])[0] for s in STATEMENTS]
    assert changes(statements, tmp_path) == {s: UNCHANGED for s in statements}


@pytest.mark.slow
@pytest.mark.parametrize("statement", STATEMENTS)
def test_importing_alone_changes_no_global_state(statement, tmp_path):
    assert changes([statement], tmp_path) == {statement: UNCHANGED}


def test_plotting_changes_no_global_state_and_leaves_pyplot_alone(results, tmp_path):
    result, figure = str(results["crb_radial"]), str(tmp_path / "f.png")
    statement = f"import bearing_sweep; bearing_sweep.plot({result!r}, output={figure!r})"
    # scipy.special, pint and xarray's open_dataset add (or move to the front) warnings
    # filters of their own, for their own warnings, whoever calls them: they run first (the
    # second opening after the backends the first loaded), and the plot must add nothing.
    libraries = ("import pint, scipy.special, xarray\nfor _ in range(2):\n"
                 f"    xarray.open_dataset({result!r}).close()")
    assert changes([statement], tmp_path, libraries) == {statement: UNCHANGED}
    assert (tmp_path / "f.png").read_bytes().startswith(b"\x89PNG")


# -- a quick look reads at a glance ------------------------------------------------------------

@pytest.mark.parametrize("name, variable, x", [
    ("crb_radial", None, None), ("crb_radial", "roller_load", None),
    ("crb_radial", "roller_load", "roller"), ("ball_5dof", "axial_displacement", None),
    ("ball_5dof", "displacement", None), ("ball_5dof", "axial_displacement", "geometry"),
    ("hertz", None, None)])
def test_a_quick_look_reads_at_a_glance(results, name, variable, x):
    """Every panel labelled with units, none blank, no legend over data, no overlapping
    ticks or text off the figure (a quick look shows the labels a user wrote: names are
    theirs)."""
    from bearing_sweep.figure_checks import figure_problems

    assert figure_problems(plot(results[name], variable, x=x), names=False) == []


@pytest.mark.parametrize("shape", ["sampled", "axis_zarr"])
def test_a_quick_look_of_every_shape_reads_at_a_glance(shapes, shape):
    from bearing_sweep.figure_checks import figure_problems

    assert figure_problems(plot(shapes[shape]), names=False) == []


def test_entries_in_units_of_their_own_are_labelled_with_each_entry_unit(results):
    """A displacement's translations are in m and its tilts in rad (displacement_units): a
    panel per entry, each labelled with its own unit."""
    data = open_result(results["ball_5dof"]).isel(geometry=[0], fixed_dofs=[0])
    figure = plot(data, "displacement")  # load along x, a line per other load, dof across
    by_entry = {axis.get_title(): axis.get_ylabel() for axis in figure.axes}
    units = dict(zip(data.dof.values, data.displacement_units.values))
    shown = [title for title in by_entry if title.startswith("dof = ")]
    assert len(shown) == 4  # a panel per entry (at most four across)
    for title in shown:
        entry = title.removeprefix("dof = ").split(",")[0]
        assert by_entry[title].endswith(f"[{units[entry]}]"), (title, by_entry[title])


@pytest.mark.parametrize("suffix", [".png", pytest.param(".pdf", marks=pytest.mark.slow),
                                    pytest.param(".svg", marks=pytest.mark.slow)])
def test_a_figure_another_program_wrote_is_never_replaced(results, tmp_path, suffix, run_cli):
    from matplotlib.figure import Figure

    result = tmp_path / "r.nc"
    result.write_bytes(results["hertz"].read_bytes())
    theirs = tmp_path / f"mine{suffix}"
    figure = Figure()
    figure.subplots().plot([1, 2, 3])
    figure.savefig(theirs)  # a figure of that format, by matplotlib as a user draws one
    before = theirs.read_bytes()
    done = run_cli("plot", result, "-o", theirs, cwd=tmp_path)
    article = {".svg": "an"}.get(suffix, "a")  # "an SVG", as it is read
    assert done.returncode == 2 and f"not {article} {suffix[1:].upper()} figure written by " \
        "bearing-sweep" in done.stderr, done.stderr
    assert theirs.read_bytes() == before
    ours = tmp_path / f"ours{suffix}"
    for _ in range(2):  # our own is replaced
        assert run_cli("plot", result, "-o", ours, cwd=tmp_path).returncode == 0
    assert b"bearing-sweep" in ours.read_bytes()


@pytest.fixture(scope="module")
def fractional():
    """crb_radial over its contact constant (N/mm^(10/9): a unit UDUNITS cannot write, stored
    in SI and named in the comment), and ball_5dof with one fixed (N/mm^1.5)."""
    import bearing_sweep

    over = bearing_sweep.run({"sweep": {"model": "crb_radial", "bearing": "paper000-D"},
                              "fixed": {"radial_load": "4 kN"},
                              "axes": {"contact_constant": ["5e4 N/mm^(10/9)",
                                                            "8e4 N/mm^(10/9)"]}},
                             workers=0, progress=False)
    fixed = bearing_sweep.run({"sweep": {"model": "ball_5dof", "bearing": "paper001-71807AC"},
                               "fixed": {"contact_constant": "5e5 N/mm^1.5"},
                               "axes": {"axial_load": ["500 N", "1 kN"]}},
                              workers=0, progress=False)
    return over, fixed


def test_a_coordinate_in_a_fractional_unit_is_selected_and_shown_in_it(fractional):
    from bearing_sweep.plotting import at, conditions

    over, fixed = fractional
    chosen = at(over, contact_constant="8e4 N/mm^(10/9)")
    assert float(chosen.contact_constant) == pytest.approx(8e4 * 1000 ** (10 / 9), rel=1e-9)
    # One variable of the result selects as the result does.
    one = at(over.radial_stiffness, contact_constant="8e4 N/mm^(10/9)")
    assert float(one) == float(chosen.radial_stiffness)
    assert conditions(fixed, "contact_constant", preset=False) == \
        "contact constant = 500000 N/mm^1.5"


@pytest.mark.parametrize("call, words", [
    (lambda d: __import__("bearing_sweep.plotting").plotting.at(d, contact_constant="4 kN"),
     "contact_constant = '4 kN': its units do not fit"),
    (lambda d: __import__("bearing_sweep.plotting").plotting.at(d, nosuch="1 N"),
     "the result has no 'nosuch'"),
    (lambda d: __import__("bearing_sweep.plotting").plotting.at(d.radial_stiffness, load="1 N"),
     "the result has no 'load'"),
    (lambda d: __import__("bearing_sweep.plotting").plotting.at(d, contact_constant=5.0),
     "contact_constant = 5.0: no such value"),
    (lambda d: __import__("bearing_sweep.plotting").plotting.conditions(5, "x"),
     "expected a result (an xarray.Dataset), not int"),
    (lambda d: __import__("bearing_sweep.plotting").plotting.sobol_bars(None, d, "x"),
     "sobol_bars draws the result of analyze on a Saltelli design")])
def test_the_figure_helpers_name_a_mistake_in_one_line(fractional, call, words):
    with pytest.raises(SpecError) as caught:
        call(fractional[0])
    assert words in str(caught.value) and "\n" not in str(caught.value)


def test_a_quick_look_shows_a_fractional_unit_as_the_definition_wrote_it(fractional):
    over, fixed = fractional
    [axis] = plot(over, "radial_stiffness").axes
    assert "N/mm^(10/9)" in axis.get_xlabel()
    assert list(axis.lines[0].get_xdata()) == pytest.approx([5e4, 8e4])
    title = plot(fixed, "displacement").get_suptitle()
    assert "contact constant = 500000 N/mm^1.5" in title
