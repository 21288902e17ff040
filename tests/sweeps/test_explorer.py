"""The interactive page of a result (``bearing-sweep explore``): made for every model's file,
sampled and zipped ones too; what it cannot show refused in one line; and in a real browser
(Chromium from the distribution's packages, driven by selenium): the page loads without a
console error, moving a widget changes what is drawn, and what is drawn is the file's."""
import shutil
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import bearing_sweep
from bearing_sweep import spec, stores
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.plotting import in_unit

DATA = Path(__file__).parents[1] / "data"
MODELS = sorted(p.stem for p in (DATA / "every_model").glob("*.toml"))
STRUCTURES = sorted(p.stem for p in (DATA / "structure").glob("*.toml"))

#: A grid of three axes whose largest loads lie beyond a low pressure limit: out of validity.
GRID = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "4 um"
pressure_limit = "1500 MPa"
[axes]
radial_load = { start = "1 kN", stop = "9 kN", num = 5 }
clearance = ["0 mm", "0.02 mm", "0.04 mm"]
speed = ["0 rpm", "6000 rpm"]
"""


@pytest.fixture(scope="module")
def results(tmp_path_factory, every_model_files):
    """Each model's file, the sampled and zipped ones, and the three-axis grid."""
    folder = tmp_path_factory.mktemp("explore")
    (folder / "grid.toml").write_text(GRID)
    made = dict(every_model_files)
    with Executor(workers=0) as executor:
        for path in ([DATA / "structure" / f"{s}.toml" for s in STRUCTURES]
                     + [folder / "grid.toml"]):
            made[path.stem] = folder / f"{path.stem}.nc"
            run_sweep(spec.load(path), made[path.stem], executor, progress=False)
    return made


def _document(path):
    """The bokeh document of the page of the result at ``path``, as the page holds it."""
    from bearing_sweep import explorer
    from bearing_sweep.dependence import on_grid

    with stores.open_result(path) as data:
        return explorer._document(on_grid(data), None, str(path))


@pytest.mark.parametrize("name", MODELS + STRUCTURES)
def test_every_models_file_has_its_page_with_the_files_values(results, name, tmp_path):
    page = bearing_sweep.explore(results[name], output=tmp_path / f"{name}.html")
    assert page.read_bytes().startswith(b"<!DOCTYPE html>")
    from bearing_sweep.dependence import on_grid

    document = _document(results[name])
    with stores.open_result(results[name]) as stored:
        data = on_grid(stored)  # an output stored on fewer axes, at every point
        dims = list(data["status"].dims)
        every = document.get_model_by_name("every").data
        offered = [n for n in every if n != "__mark"]
        per_point = [n for n, v in data.data_vars.items()
                     if v.attrs.get("coverage_content_type") == "modelResult"
                     and set(v.dims) <= set(dims)
                     and not n.endswith("_over_duty_cycle")]  # one value for all its cases
        assert offered == per_point
        for name_ in offered:  # each point's value, in the order of the status' dimensions
            np.testing.assert_array_equal(every[name_],
                                          data[name_].transpose(*dims).values.ravel())
        sliders = {m.name for m in document.models if m.name and m.name.startswith("slider-")}
        assert sliders == {f"slider-{d}" for d in dims}
        along = document.get_model_by_name("along").value
        drawn = document.get_model_by_name("drawn").data
        x = data[along]
        if "written_units" in x.attrs:
            x = in_unit(x, x.attrs["written_units"])
        np.testing.assert_allclose(drawn["x"], x.values, rtol=1e-12)
        first = data[offered[0]].isel({d: 0 for d in dims if d != data[along].dims[0]})
        kept = np.isfinite(drawn["y"])
        np.testing.assert_array_equal(np.asarray(drawn["y"])[kept], first.values[kept])


@pytest.mark.parametrize("call, words", [
    (lambda r, t: bearing_sweep.explore(r["crb_radial"], ["roller_load"], output=t / "a.html"),
     "roller_load has entries of its own (roller): `bearing-sweep plot` draws"),
    (lambda r, t: bearing_sweep.explore(r["crb_radial"], ["radial_stifness"],
                                        output=t / "a.html"),
     "crb_radial.nc: unknown output 'radial_stifness'; did you mean 'radial_stiffness'?"),
    (lambda r, t: bearing_sweep.explore(r["crb_radial"], output=t / "a.png"),
     "an interactive page is written as .html"),
    (lambda r, t: bearing_sweep.explore(t / "none.nc"), "none.nc: no such result file"),
    (lambda r, t: bearing_sweep.explore(r["crb_radial"], "radial_stiffness"),
     "expected a list of outputs' names"),
])
def test_what_a_page_cannot_show_is_one_line(results, tmp_path, call, words):
    with pytest.raises(bearing_sweep.SpecError, match=words.replace("(", r"\(").replace(
            ")", r"\)").replace("?", r"\?").replace(".", r"\.")):
        call(results, tmp_path)


def test_a_page_replaces_only_its_own_and_holds_no_more_than_it_can(results, tmp_path,
                                                                      monkeypatch):
    from bearing_sweep import explorer

    theirs = tmp_path / "notes.html"
    theirs.write_text("<!DOCTYPE html>\n<p>bearing-sweep notes</p>\n")
    with pytest.raises(bearing_sweep.SpecError, match="is not an HTML interactive page written "
                                                      "by bearing-sweep; refusing"):
        bearing_sweep.explore(results["grid"], output=theirs)
    assert theirs.read_text() == "<!DOCTYPE html>\n<p>bearing-sweep notes</p>\n"
    ours = bearing_sweep.explore(results["grid"], output=tmp_path / "grid.html")
    assert bearing_sweep.explore(results["grid"], output=ours) == ours  # our own: replaced
    monkeypatch.setattr(explorer, "MOST_VALUES", 40)  # the grid has 30 points
    with pytest.raises(bearing_sweep.SpecError, match="2 outputs of 30 points are more values"):
        bearing_sweep.explore(results["grid"], ["radial_stiffness", "radial_displacement"],
                              output=ours)
    assert len(_offered_by_default(results["grid"], explorer)) == 1


def _offered_by_default(path, explorer):
    with stores.open_result(path) as data:
        return explorer._offered(data, None, list(data["status"].dims), str(path))


def test_without_bokeh_the_page_is_one_line_naming_the_extra(results, tmp_path, monkeypatch,
                                                            run_cli):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *args: None if name == "bokeh" else real(name, *args))
    done = run_cli("explore", str(results["grid"]), "-o", str(tmp_path / "p.html"),
                   cwd=tmp_path)
    assert done.returncode == 1
    assert done.stderr == ("error: the interactive page needs bokeh, an optional extra: "
                           "pip install 'bearing-sweep[explore]'\n")
    assert not (tmp_path / "p.html").exists()


@pytest.fixture(scope="module")
def browser():
    """Headless Chromium from the distribution's packages (`.ci/run` installs them)."""
    chromium, driver_path = shutil.which("chromium"), shutil.which("chromedriver")
    if chromium is None or driver_path is None:
        pytest.skip("needs Debian's chromium and chromium-driver (.ci/run installs them)")
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--window-size=1280,800"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(driver_path), options=options)
    yield driver
    driver.quit()


class Page:
    """A page open in the browser: its widgets set, and what it draws read, through the
    bokeh document the page holds."""

    def __init__(self, driver, path):
        self.driver = driver
        driver.get(path.resolve().as_uri())
        for _ in range(100):
            if driver.execute_script("return typeof Bokeh !== 'undefined' && "
                                     "Bokeh.documents.length > 0"):
                break
            time.sleep(0.05)

    def set(self, name, value):
        self.driver.execute_script(
            "Bokeh.documents[0].get_model_by_name(arguments[0]).value = arguments[1];",
            name, value)

    def get(self, name, attribute):
        return self.driver.execute_script(
            "return Bokeh.documents[0].get_model_by_name(arguments[0])[arguments[1]];",
            name, attribute)

    def drawn(self, source="drawn"):
        x, y = self.driver.execute_script(
            "const s = Bokeh.documents[0].get_model_by_name(arguments[0]).data;"
            "return [Array.from(s.x), Array.from(s.y)];", source)
        return (np.array(x, dtype=float),
                np.array([np.nan if v is None else v for v in y], dtype=float))

    def axis_labels(self):
        return self.driver.execute_script(
            "const p = Bokeh.documents[0].get_model_by_name('figure');"
            "return [p.below[0].axis_label, p.left[0].axis_label];")

    def errors(self):
        return [entry for entry in self.driver.get_log("browser") if entry["level"] == "SEVERE"]


def test_the_page_in_a_browser_draws_the_files_values_as_widgets_move(results, browser,
                                                                      tmp_path):
    path = bearing_sweep.explore(results["grid"], ["radial_displacement", "radial_stiffness"],
                                 output=tmp_path / "grid.html")
    page = Page(browser, path)
    assert page.errors() == []
    data = xr.open_dataset(results["grid"])
    loads_kn = data.radial_load.values / 1000  # written in kN, stored in N
    x, y = page.drawn()
    np.testing.assert_allclose(x, loads_kn, rtol=1e-12)
    np.testing.assert_array_equal(y, data.radial_displacement.isel(clearance=0, speed=0))
    assert page.axis_labels() == ["radial load [kN]",
                                  "radial displacement of the inner ring [mm]"]

    page.set("slider-clearance", 2)  # 0.04 mm: the displacement grows by the clearance taken up
    x, moved = page.drawn()
    np.testing.assert_array_equal(moved, data.radial_displacement.isel(clearance=2, speed=0))
    assert (moved > y).all()
    assert page.get("slider-clearance", "title") == "clearance = 0.04 mm"

    page.set("output", "radial_stiffness")
    page.set("slider-speed", 1)
    x, y = page.drawn()
    np.testing.assert_array_equal(y, data.radial_stiffness.isel(clearance=2, speed=1))
    assert page.axis_labels()[1].endswith("[N/mm]")
    # The points out of validity (above the pressure limit) are ringed, the others not.
    outside = (data.status.isel(clearance=2, speed=1).values & 4) != 0
    assert 0 < outside.sum() < outside.size
    ringed_x, ringed_y = page.drawn("ringed")
    np.testing.assert_allclose(ringed_x, loads_kn[outside], rtol=1e-12)
    assert page.get("status", "text").startswith(
        f"5 points drawn: {5 - outside.sum()} converged within validity, "
        f"{outside.sum()} out of validity")

    page.set("along", "clearance")  # along x: the clearance, at the first load's slider
    x, y = page.drawn()
    np.testing.assert_allclose(x, data.clearance.values, rtol=1e-12)
    np.testing.assert_array_equal(y, data.radial_stiffness.isel(radial_load=0, speed=1))
    assert page.axis_labels()[0] == "clearance [mm]"
    assert page.get("slider-clearance", "visible") is False
    assert page.errors() == []
    data.close()


def test_a_sampled_and_a_zipped_result_in_a_browser(results, browser, tmp_path):
    sampled = Page(browser, bearing_sweep.explore(results["sampled"],
                                                  output=tmp_path / "s.html"))
    assert sampled.errors() == []
    with xr.open_dataset(results["sampled"]) as data:
        drawn_input = data.attrs["sample_inputs"].split()[0]
        assert sampled.get("along", "value") == drawn_input
        assert [o[0] for o in sampled.get("along", "options")] == data.attrs[
            "sample_inputs"].split()  # not the design's block and replicate numbers
        output = sampled.get("output", "value")
        x, y = sampled.drawn()
        stored = data[drawn_input]
        written = stored.attrs.get("written_units")  # a drawn input: in the unit it was given
        np.testing.assert_allclose(x, (in_unit(stored, written) if written else stored).values,
                                   rtol=1e-12)
        np.testing.assert_array_equal(y, data[output].values)
        assert sampled.get("line", "visible") is False  # samples: points, not a line
    zipped = Page(browser, bearing_sweep.explore(results["zipped_float32"],
                                                 output=tmp_path / "z.html"))
    with xr.open_dataset(results["zipped_float32"]) as data:
        output = zipped.get("output", "value")
        zipped.set("slider-case", 1)
        x, y = zipped.drawn()
        np.testing.assert_array_equal(y, data[output].isel(case=1).values.astype(float))
        assert zipped.get("slider-case", "title") == "case = long"  # the label the axis gives
    assert zipped.errors() == []
