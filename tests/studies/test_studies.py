"""The papers' studies regenerate every figure and stated number from their netCDF files."""
import contextlib
import re
import shutil
import subprocess
from pathlib import Path

import cf_units
import numpy as np
import pytest
import xarray as xr

import bearing_sweep
from bearing_sweep import units
from bearing_sweep.figure_checks import figure_problems
from bearing_sweep.plotting import at, conditions, in_unit
from bearing_sweep.stores import open_result
from bearing_sweep.spec import SpecError
from bearing_sweep.study import find_studies, select

STUDIES = Path(__file__).resolve().parents[2] / "studies"

#: Another unit for each unit the studies' inputs are stored in: a figure script that selects
#: or draws by bare numbers in the stored unit gives other numbers in these.
OTHER_UNIT = {"N": "kN", "mm": "um", "um": "nm", "degree": "arcmin", "rpm": "rad/s"}


def _store_in_other_units(source: Path, target: Path) -> int:
    """Copy every result in ``source`` to ``target`` with its inputs (coordinates and fixed
    inputs) in other units; return how many variables were converted."""
    target.mkdir(parents=True)
    converted = 0
    for path in sorted(source.glob("*.nc")):
        data = open_result(path)
        for name, variable in list(data.variables.items()):
            unit = variable.attrs.get("units")
            if unit not in OTHER_UNIT or not (name in data.coords or "origin" in variable.attrs):
                continue
            values = units.convert(variable.values, units.parse_unit(unit),
                                   units.parse_unit(OTHER_UNIT[unit]))
            replaced = (variable.dims, values, {**variable.attrs, "units": OTHER_UNIT[unit]})
            data = (data.assign_coords({name: replaced}) if name in data.coords
                    else data.assign({name: replaced}))
            converted += 1
        data.to_netcdf(target / path.name, engine="netcdf4")
    return converted


#: The definitions a study runs on a smaller grid, a smaller sample or a shorter transient in
#: ``make test`` (each replacement: the full text, then the reduced one); every value the
#: figure scripts and the claims select stays on the grid. The slow tests run the full ones.
REDUCED = {
    "ball_stiffness/unstated_inputs.toml": [("n = 512", "n = 64")],
    "radial_stiffness/unstated_inputs.toml": [("n = 512", "n = 64")],
    # radial loads 50 to 1000 N every 50 N: the claims read 200 to 1000 N every 50 N
    "cage_slip/fig17_load_speed.toml": [('step = "5 N"', 'step = "50 N"')],
    # the transient's loads 200 and 800 N: the claims read 800 N
    "cage_slip/fig17_transient.toml": [('duration = "0.03 s"', 'duration = "0.004 s"'),
                                       ('step = "200 N"', 'step = "600 N"')],
    # the spatial transient's loads 200 and 800 N, as the planar one's
    "cage_slip/fig17_transient_spatial.toml": [('duration = "0.05 s"', 'duration = "0.004 s"'),
                                               ('step = "200 N"', 'step = "600 N"')],
    "cage_slip/fig18_20_eccentricity.toml": [('duration = "0.06 s"', 'duration = "0.006 s"')],
    "cage_slip/three_models_spatial.toml": [('duration = "0.05 s"', 'duration = "0.004 s"')],
    # runout: a quarter of the rotation steps (of a revolution, in which the rollers' orders
    # of roundness pass), fewer random draws
    "runout/fig07_table3.toml": [("steps_per_revolution = 720", "steps_per_revolution = 180")],
    "runout/fig08_amplitude.toml": [("steps_per_revolution = 1800",
                                     "steps_per_revolution = 450")],
    "runout/fig09_10_order.toml": [("steps_per_revolution = 3600",
                                    "steps_per_revolution = 450")],
    "runout/fig11_table4.toml": [("steps_per_revolution = 3600", "steps_per_revolution = 900")],
    "runout/fig12_roller_count.toml": [("steps_per_revolution = 1800",
                                        "steps_per_revolution = 450")],
    "runout/monte_carlo_phases.toml": [("stop = 200, step = 1", "stop = 25, step = 1"),
                                       ("steps_per_revolution = 900",
                                        "steps_per_revolution = 225")],
    "runout/selective_assembly.toml": [("stop = 500, step = 1", "stop = 60, step = 1"),
                                       ("steps_per_revolution = 360",
                                        "steps_per_revolution = 90")],
    "runout/tolerances.toml": [("n = 64", "n = 16"),
                               ("steps_per_revolution = 180", "steps_per_revolution = 45")],
}

#: Each study at ``make test``'s resolution and, in the slow tests, at its own (``make
#: reproduce`` computes the figures' numbers at that one).
RESOLUTIONS = ["reduced", pytest.param("full", marks=pytest.mark.slow)]


def reduced(path: Path) -> str:
    """The text of the study definition at ``path`` (studies/<study>/<name>.toml) as ``make
    test`` runs it: as it is, or with the replacements of ``REDUCED``."""
    text = path.read_text()
    for full, smaller in REDUCED.get(f"{path.parent.name}/{path.name}", []):
        assert text.count(full) == 1, (path, full)  # a changed definition: say how to reduce it
        text = text.replace(full, smaller)
    return text


def _study_copy(name: str, folder: Path, resolution: str) -> None:
    """``folder/studies`` holding a copy of the study ``name``, its definitions ``reduced``
    at the reduced resolution."""
    target = folder / "studies" / name
    shutil.copytree(STUDIES / name, target)
    if resolution == "reduced":
        for definition in target.glob("*.toml"):
            definition.write_text(reduced(STUDIES / name / definition.name))


@pytest.fixture(scope="module")
def study_figures():
    """The figures each study run of :func:`run_study` drew, by (study, results folder), as
    :func:`drawn` gives them."""
    return {}


@pytest.fixture(scope="module")
def run_study(tmp_path_factory, run_cli, study_figures):
    """``run_study(name, resolution="reduced")``: the folder holding ``studies/`` (the
    study's copy), ``results/`` and ``figures/`` of the study run once for all the tests of
    this module (whole studies are the suite's longest runs); the figures it drew are kept in
    ``study_figures``."""
    runs = {}

    def run(name: str, resolution: str = "reduced") -> Path:
        if (name, resolution) not in runs:
            folder = tmp_path_factory.mktemp(f"{name}-{resolution}")
            _study_copy(name, folder, resolution)
            with kept_figures() as figures:
                done = run_cli("study", name, "--workers", "0", *_folders(folder),
                               timeout=1200, cwd=folder)
            assert done.returncode == 0, done.stderr
            study_figures[name, folder / "results" / name] = figures
            runs[name, resolution] = folder
        return runs[name, resolution]

    return run


@contextlib.contextmanager
def kept_figures(saved: bool = True):
    """``{file: Figure}`` of each figure saved (``plotting.save``) by the study scripts loaded
    within, laid out as it was saved; ``saved`` false: kept only, neither laid out nor written
    (for a test that reads what is drawn, not the file)."""
    import bearing_sweep.plotting as plotting

    original, figures = plotting.save, {}

    def keep(figure, folder, file, tight=True):
        if saved:
            original(figure, folder, file, tight)
        figures[file] = figure

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(plotting, "save", keep)  # the scripts import it when loaded
        yield figures


def _folders(folder: Path) -> list[str]:
    return ["--studies", str(folder / "studies"), "--results", str(folder / "results"),
            "--figures", str(folder / "figures")]


def test_several_studies_are_selected_in_their_order_once_each():
    assert [s.name for s in select(STUDIES, ["runout", "life", "runout"])] == ["runout", "life"]
    assert [s.name for s in select(STUDIES, "all")] == sorted(find_studies(STUDIES))
    assert [s.name for s in select(STUDIES, ["life", "all"])] == sorted(find_studies(STUDIES))
    with pytest.raises(SpecError, match="study 'lief': no such study .*did you mean 'life'"):
        select(STUDIES, ["runout", "lief"])


def test_make_reproduce_runs_every_study_once():
    # its two groups of studies run side by side: each study in one of them
    done = subprocess.run(["make", "-n", "--no-print-directory", "studies-on-cluster",
                           "studies-in-process"], cwd=STUDIES.parent, capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    commands = [line.split(" study ", 1)[1].split() for line in done.stdout.splitlines()
                if "bearing-sweep study " in line]
    named = [word for words in commands for word in words if word not in ("--workers", "0")]
    assert len(commands) == 2 and sorted(named) == sorted(find_studies(STUDIES))


def test_every_reduction_applies_to_a_study_definition():
    for key in REDUCED:
        reduced(STUDIES / key)  # each text it replaces is there, once


@pytest.mark.parametrize("name", ["ball_stiffness", "tapered_rib", "runout", "cage_slip",
                                  "radial_stiffness", "life", "operating_conditions",
                                  "spindle"])
@pytest.mark.parametrize("resolution", RESOLUTIONS)
def test_a_study_regenerates_its_figures_and_report(name, resolution, run_study, run_cli):
    study = find_studies(STUDIES)[name]
    folder = run_study(name, resolution)
    done = run_cli("report", *_folders(folder), timeout=300, cwd=folder)
    assert done.returncode == 0, done.stderr
    for figure in study.figures_module().FIGURES:  # what they show: below
        assert (folder / "figures" / name / figure).read_bytes().startswith(b"\x89PNG")
    page = (folder / "figures" / name / "README.md").read_text()
    table = re.split(r"## (?:The paper's numbers|What is expected) beside ours", page)[1]
    table = table.split("## Figures")[0]
    rows = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line]
    assert len(rows) == len(study.claims()) + 1  # and the header
    # A study beyond the papers sets its expected trends, not a paper's numbers, beside ours.
    assert ("## What is expected beside ours" in page) == study.beyond_the_papers
    assert ("## The paper's numbers beside ours" in page) != study.beyond_the_papers
    # A claim says in its assumptions when it is "not recomputed" or "not recomputable".
    computed = [claim for claim in study.claims() if ("paper" in claim or "expected" in claim)
                and "not recomput" not in claim.get("assumptions", "")]
    assert page.count("not computed") == len(study.claims()) - len(computed)


@pytest.mark.parametrize("name", ["ball_stiffness", "tapered_rib", "runout",
                                  "radial_stiffness", "life", "operating_conditions",
                                  "spindle"])
@pytest.mark.parametrize("resolution", RESOLUTIONS)
def test_a_study_selects_by_quantity_not_by_stored_numbers(name, resolution, run_study,
                                                           study_figures, tmp_path):
    """The same results with their inputs stored in other units give the same stated numbers
    and draw the same figures: the figure scripts select by quantities and convert what they
    show."""
    study = find_studies(STUDIES)[name]
    stored = run_study(name, resolution) / "results" / name
    assert _store_in_other_units(stored, tmp_path / "other") > 0
    module = study.figures_module()
    ours, in_other_units = module.ours(stored), module.ours(tmp_path / "other")
    assert in_other_units == pytest.approx(ours, rel=1e-9, nan_ok=True)
    with kept_figures(saved=False) as redrawn:
        study.figures_module().draw(tmp_path / "other", tmp_path)
    assert sorted(redrawn) == sorted(module.FIGURES)
    for file, figure in redrawn.items():  # the same quantities, in the units the axes state
        drawn_first = _drawn_values(study_figures[name, stored][file])
        drawn_again = _drawn_values(figure)
        assert len(drawn_again) == len(drawn_first), file
        for (again, units_again), (first, units_first) in zip(drawn_again, drawn_first):
            for column, (unit, unit_first) in enumerate(zip(units_again, units_first)):
                if unit != unit_first:  # UDUNITS' conversion, not the plotting code's
                    again[:, column] = cf_units.Unit(unit).convert(again[:, column],
                                                                   cf_units.Unit(unit_first))
            np.testing.assert_allclose(again, first, rtol=1e-9, err_msg=file)


_LABEL_UNIT = re.compile(r"\[([^\]]+)\]\s*$")


def _drawn_values(figure) -> list[tuple[np.ndarray, tuple]]:
    """What ``figure`` draws, panel by panel, each with the units its axes state (``None``
    where a label states none), as (points, (x unit, y unit)): each line's points, each
    bar's corner and size, each scatter's points."""
    drawn = []
    for axis in figure.axes:
        stated = tuple(_stated_unit(axis, name) for name in "xy")
        points = [line.get_xydata() for line in axis.get_lines()
                  if line.get_transform() == axis.transData]  # not a line across the panel
        points += [np.reshape(patch.get_bbox().bounds, (2, 2)) for patch in axis.patches
                   if patch.get_data_transform() == axis.transData]
        points += [collection.get_offsets() for collection in axis.collections]
        drawn += [(np.array(p, dtype=float), stated) for p in points]
    return drawn


def _stated_unit(axis, name: str) -> str | None:
    """The unit the label of ``axis``'s x or y axis (``name``) states, or that of an axis it
    shares (a twin's), or None."""
    shared = getattr(axis, f"get_shared_{name}_axes")().get_siblings(axis)
    for label in [getattr(a, f"get_{name}label")() for a in [axis, *shared]]:
        if found := _LABEL_UNIT.search(label):
            return found[1]
    return None


@pytest.fixture(scope="module")
def short_3d_results(tmp_path_factory):
    """The cage_dynamics_3d study's own sweeps cut to 1 ms with coarse elements: the model's
    real output for its figure script, in seconds (its full sweeps take minutes)."""
    folder = tmp_path_factory.mktemp("cage_dynamics_3d")
    coarse = ('duration = "1 ms"\noutput_interval = "0.05 ms"\nslices = 4\narc_axial_points = 2\n'
              'arc_angle_points = 2\nface_rings = 3\nface_angles = 8')
    for definition in find_studies(STUDIES)["cage_dynamics_3d"].definitions:
        text = re.sub(r"^output_interval = .*\n", "", definition.read_text(), flags=re.M)
        short, replaced = re.subn(r"^duration = .*$", coarse, text, flags=re.M)
        assert replaced == 1, definition
        path = folder / definition.name
        path.write_text(short)
        bearing_sweep.run(path, output=folder / f"{definition.stem}.nc", workers=0,
                          progress=False).close()
    return folder


def test_the_3d_study_draws_every_figure_and_computes_every_claim(short_3d_results,
                                                                    tmp_path):
    study = find_studies(STUDIES)["cage_dynamics_3d"]
    module = study.figures_module()
    module.draw(short_3d_results, tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(module.FIGURES)
    table = module.tables(short_3d_results).splitlines()
    runs = 4 + 2 + 4 + 2  # eccentricities, misalignments, thin film, the films' pressure
    assert len([line for line in table if line.startswith("| ") and "---" not in line]) \
        == runs + 1  # and the header
    assert "nan" not in "\n".join(table)
    ours = module.ours(short_3d_results)
    # Only a claim that says when it is "not computed" may be missing (a share of dry
    # elements where none is dry, as in 1 ms).
    undefined = {claim["id"] for claim in study.claims()
                 if "not computed when" in claim["assumptions"]}
    assert 0 < len(undefined) < len(study.claims())
    assert {claim["id"] for claim in study.claims()} - set(ours) <= undefined
    assert set(ours) <= {claim["id"] for claim in study.claims()}


def test_the_3d_study_selects_by_quantity_not_by_stored_numbers(short_3d_results, tmp_path):
    module = find_studies(STUDIES)["cage_dynamics_3d"].figures_module()
    assert _store_in_other_units(short_3d_results, tmp_path / "other") > 0
    assert module.ours(tmp_path / "other") == pytest.approx(module.ours(short_3d_results),
                                                            rel=1e-9, nan_ok=True)


def _face(rows):
    """An end-face map of both ends (the same on each), rings x angles, NaN: no counterpart."""
    values = np.array(rows, dtype=float)
    return xr.DataArray(np.stack([values, values]), dims=("end", "face_ring", "face_angle"),
                        coords={"end": ["left", "right"]})


def test_edge_elements_are_on_the_outer_ring_or_beside_a_missing_one():
    module = find_studies(STUDIES)["cage_dynamics_3d"].figures_module()
    gap = _face([[1, 1, 1, 1, 1, 1], [1, 1, 1, 1, 1, 1], [1, 1, np.nan, 1, 1, 1],
                 [1, 1, 1, 1, 1, 1]]).sel(end="left")
    expected = np.zeros((4, 6), dtype=bool)
    expected[3] = True  # the outermost ring
    expected[2, [1, 3]] = True  # beside the missing element, round the face
    expected[[1, 3], 2] = True  # beside it, across the rings
    assert (module._edge(gap) == expected).all()


def test_edge_share_counts_the_dry_elements_at_the_edge():
    module = find_studies(STUDIES)["cage_dynamics_3d"].figures_module()
    # dry: one inner element (ring 1) and one on the outer ring, on each end
    gap = _face([[-1, 1, 1, 1], [1, 1, 1, 1], [1, 1, -1, 1]])
    assert module._edge_share(gap) == 0.5
    assert module._edge_share(_face([[1, 1, 1], [1, 1, 1]])) is None


def test_two_sided_is_the_larger_of_the_two_ends_smallest_gaps():
    module = find_studies(STUDIES)["cage_dynamics_3d"].figures_module()
    gap = _face([[-0.3, 0.2], [0.5, np.nan]])
    gap.loc[{"end": "right"}] = [[0.1, 0.2], [0.4, np.nan]]
    assert module._two_sided(gap) == pytest.approx(0.1)  # only the left end touches
    # left (-0.3, 0.2, 0.5) against right (0.1, 0.2, 0.4): Pearson's r by hand
    assert module._alike(gap) == pytest.approx(0.11667 / np.sqrt(0.32667 * 0.04667), abs=1e-4)



def test_the_outer_edge_is_the_quarter_of_each_arc_nearest_the_outside_diameter():
    module = find_studies(STUDIES)["cage_dynamics_3d"].figures_module()
    # 8 elements per arc, ordered -theta_2 .. -theta_1, theta_1 .. theta_2: the outer edge is
    # elements 6-7 of the first arc and 0-1 of the second (indices 6, 7, 8, 9 of 16).
    assert np.flatnonzero(module._outer_edge(16)).tolist() == [6, 7, 8, 9]
    assert np.flatnonzero(module._outer_edge(4)).tolist() == [1, 2]  # at least one per arc


def _arc_forces(per_pocket):
    """Largest arc-element forces [N], pockets x axial x angle elements."""
    return xr.DataArray(np.array(per_pocket, dtype=float),
                        dims=("roller", "arc_axial", "arc_angle"))


def test_outer_share_and_evenness_of_the_arc_forces():
    module = find_studies(STUDIES)["cage_dynamics_3d"].figures_module()
    # 2 elements per arc (4 across): outer edge at indices 1 and 2
    force = _arc_forces([[[0, 3, 1, 0], [0, 0, 0, 0]], [[2, 0, 0, 0], [0, 2, 0, 0]]])
    assert module._outer_share(force) == pytest.approx((3 + 1 + 2) / 8)
    assert module._evenness(force) == pytest.approx((4 / 8) / 3)  # pocket 0, peak 3
    nothing = _arc_forces(np.zeros((2, 2, 4)))
    assert module._outer_share(nothing) is None and module._evenness(nothing) is None


def test_every_whirl_claim_is_stated_for_both_centres():
    """sigma_b of the mass centre (the paper's caption) and of the geometric centre (its
    text): each whirl claim of the flooded film has its twin ending in _centre."""
    ids = {claim["id"] for claim in find_studies(STUDIES)["cage_dynamics_3d"].claims()}
    mass = {i for i in ids if i.startswith("whirl") and not i.endswith(("_centre",
                                                                        "_thin_film"))}
    assert len(mass) == 5
    assert {f"{i}_centre" for i in mass} <= ids

def _loads(values_in_n):
    coordinate = xr.DataArray(np.asarray(values_in_n, dtype=float), dims="radial_load",
                              name="radial_load", attrs={"units": "N", "long_name": "load"})
    return xr.Dataset({"stiffness": ("radial_load", [1.0, 2.0, 3.0])},
                      coords={"radial_load": coordinate})


def test_in_unit_converts_a_coordinate_with_its_index():
    data = _loads([2000.0, 4000.0, 6000.0])
    in_kn = in_unit(data.radial_load, "kN")
    assert in_kn.values.tolist() == pytest.approx([2.0, 4.0, 6.0])
    assert in_kn.attrs == {"units": "kN", "long_name": "load"}
    shown = data.assign_coords(radial_load=in_kn)
    assert shown.radial_load.values.tolist() == pytest.approx([2.0, 4.0, 6.0])
    assert float(at(shown, radial_load="4000 N").stiffness) == 2.0  # and selects in kN


def test_in_unit_reads_a_variable_without_units_as_si():
    # The files leave out `units` where UDUNITS has no form (N/m^1.5) and store SI values.
    constant = xr.DataArray(1.0649e10, name="contact_constant")  # N/m^1.5, paper 001 Table 1
    assert float(in_unit(constant, "N/mm^1.5")) == pytest.approx(1.0649e10 * 1e-3 ** 1.5)


def _fixed_inputs():
    return xr.Dataset(
        {"speed": ((), 5000.0, {"units": "rpm"}),
         "radial_load": ((), 4000.0, {"units": "N", "written_units": "kN"}),
         "cage_position": ((), 0.0, {"units": "degree"}),
         "slices": ((), 60, {"units": "1"}),
         "crown_profile": ((), "logarithmic"),
         "roller_diameter_error": ("roller", [0.1, 1.4], {"units": "um"})},
        attrs={"bearing": "paper000-D"})


def test_conditions_state_the_fixed_inputs_in_the_units_they_were_written_in():
    data = _fixed_inputs()
    stated = conditions(data, "speed", "radial_load", "cage_position", "slices",
                        "crown_profile", width=None)
    assert stated == ("paper000-D: speed = 5000 rpm, radial load = 4 kN, cage position = 0 deg, "
                      "slices = 60, crown profile = logarithmic")
    assert conditions(data, "radial_load", preset=False, radial_load="N") == \
        "radial load = 4000 N"
    assert conditions(data, "roller_diameter_error", preset=False) == \
        "roller diameter error = 0.1 to 1.4 um"


def test_conditions_wrap_between_inputs_only():
    text = conditions(_fixed_inputs(), "speed", "radial_load", "crown_profile", width=40)
    assert text.splitlines() == ["paper000-D: speed = 5000 rpm,", "radial load = 4 kN,",
                                 "crown profile = logarithmic"]


def test_agreement_reads_each_comparison_and_counts_samples_one_by_one():
    from bearing_sweep.study import agreement
    within = {"paper": 4.1, "tolerance": 0.6}
    assert agreement(within, [3.4, 3.6, 4.6, 4.8]).tolist() == [False, True, True, False]
    assert agreement({**within, "comparison": "at_most"}, [4.8, 4.6]).tolist() == [False, True]
    assert agreement({"paper": 1.0, "comparison": "at_least"}, [0.99, 1.0]).tolist() == [
        False, True]
    assert not agreement(within, float("nan"))


# -- every figure reads at a glance -----------------------------------------------------------

@pytest.fixture(scope="module")
def drawn(tmp_path_factory, study_figures):
    """``drawn(name, results)``: each figure of the study ``name`` drawn from ``results``, as
    ``{file: Figure}``, laid out as it was saved; drawn once for all the tests of this module
    (they only read the figures), by the study's run where :func:`run_study` ran it."""

    def draw(name: str, results: Path) -> dict:
        if (name, results) not in study_figures:
            with kept_figures() as figures:
                module = find_studies(STUDIES)[name].figures_module()
                module.draw(results, tmp_path_factory.mktemp(f"{name}-figures"))
            study_figures[name, results] = figures
        figures = study_figures[name, results]
        module = find_studies(STUDIES)[name].figures_module()
        assert sorted(figures) == sorted(module.FIGURES)  # each one saved through save
        return figures

    return draw


@pytest.mark.parametrize("name", ["ball_stiffness", "tapered_rib", "runout", "cage_slip",
                                  "radial_stiffness", "life", "operating_conditions",
                                  "spindle"])
@pytest.mark.parametrize("resolution", RESOLUTIONS)
def test_every_figure_of_a_study_reads_at_a_glance(name, resolution, run_study, drawn):
    """Labelled axes with units, no blank panel, no internal name, no legend over data, no
    overlapping ticks, nothing cut off (bearing_sweep.figure_checks)."""
    figures = drawn(name, run_study(name, resolution) / "results" / name)
    assert {file: figure_problems(f) for file, f in figures.items()} == {
        file: [] for file in figures}


#: A figure of each study and what one of its panels draws, to compare with the result it was
#: drawn from: (figure, panel, result, (x, unit shown), (y, unit shown), the dimension with a
#: line (or bar) per value, in order; None: one line). A unit None: shown as stored.
DRAWN = {
    "radial_stiffness": ("fig06_bearing_a.png", 0, "fig06_bearing_a", ("radial_load", "kN"),
                         ("radial_stiffness", "1e5 N/mm"), None),
    "ball_stiffness": ("fig06_07_axial.png", 1, "fig06_07_axial", ("axial_load", None),
                       ("axial_stiffness", "kN/mm"), "form"),
    "runout": ("fig08_amplitude.png", 0, "fig08_amplitude", ("roller_roundness_amplitude", None),
               ("runout", None), "roller_roundness_order"),
    "life": ("clearance.png", 1, "clearance", ("clearance", "um"),
             ("largest_contact_pressure", "MPa"), "radial_load"),
    "tapered_rib": ("table2_roller_loads.png", 0, "table2_load", ("roller", None),
                    ("roller_load", None), "bars"),
    "operating_conditions": ("fits.png", 0, "fits", ("shaft_fit", "um"),
                             ("operating_clearance", "um"), "inner_ring_temperature"),
}


def _shown(variable: xr.DataArray, unit: str | None) -> np.ndarray:
    """``variable``'s values in ``unit`` (UDUNITS' conversion, not the plotting code's)."""
    if unit is None:
        return variable.values
    return cf_units.Unit(variable.attrs["units"]).convert(variable.values, cf_units.Unit(unit))


@pytest.mark.parametrize("name", sorted(DRAWN))
@pytest.mark.parametrize("resolution", RESOLUTIONS)
def test_a_figure_draws_the_values_of_its_result(name, resolution, run_study, drawn):
    file, panel, sweep, (x, x_unit), (y, y_unit), per = DRAWN[name]
    results = run_study(name, resolution) / "results" / name
    axis = drawn(name, results)[file].axes[panel]
    with xr.open_dataset(results / f"{sweep}.nc") as data:  # read apart from the script
        if per == "bars":
            bars = axis.patches
            assert len(bars) == data.sizes[x]
            np.testing.assert_allclose([bar.get_x() + bar.get_width() / 2 for bar in bars],
                                       _shown(data[x], x_unit))
            np.testing.assert_allclose([bar.get_height() for bar in bars],
                                       _shown(data[y], y_unit), rtol=1e-12)
            return
        groups = [data] if per is None else [data.isel({per: i}) for i in range(data.sizes[per])]
        lines = axis.get_lines()
        assert len(lines) >= len(groups)
        for line, group in zip(lines, groups):  # the data lines come first, in order
            np.testing.assert_allclose(line.get_xdata(), _shown(group[x], x_unit), rtol=1e-12)
            np.testing.assert_allclose(line.get_ydata(), _shown(group[y], y_unit), rtol=1e-12)


def test_every_figure_of_the_3d_study_reads_at_a_glance(short_3d_results, drawn):
    figures = drawn("cage_dynamics_3d", short_3d_results)
    assert {file: figure_problems(f) for file, f in figures.items()} == {
        file: [] for file in figures}


def test_a_pocket_arc_map_without_dry_contact_says_so(short_3d_results, drawn):
    """A flooded film carries the rollers: no arc touches dry, and each panel says so rather
    than show a map of zeros; where an arc touches, the map shows its forces."""
    figures = drawn("cage_dynamics_3d", short_3d_results)
    forces = {}
    for sweep in ("eccentricity", "eccentricity_thin_film"):
        data = open_result(short_3d_results / f"{sweep}.nc")
        forces[sweep] = [float(at(data, cage_eccentricity=r, cage_axial_eccentricity=a)
                               .pocket_arc_force.max())
                         for r, a in (("0 mm", "0 mm"), ("2 mm", "0 mm"), ("0 mm", "2 mm"),
                                      ("2 mm", "2 mm"))]
    for file, sweep in (("fig23_arc_force_eccentricity.png", "eccentricity"),
                        ("fig23_arc_force_thin_film.png", "eccentricity_thin_film")):
        panels = [axis for axis in figures[file].axes if not hasattr(axis, "_colorbar")]
        assert len(panels) == 4
        for axis, force in zip(panels, forces[sweep]):
            said = any("no dry contact" in text.get_text() for text in axis.texts)
            assert said == (force == 0) and bool(axis.collections) == (force > 0), file


@pytest.mark.parametrize("file", ["fig24_end_clearance_eccentricity.png",
                                  "fig25_rib_clearance_eccentricity.png",
                                  "fig32_end_clearance_misalignment.png",
                                  "fig33_rib_clearance_misalignment.png"])
def test_an_end_face_map_says_what_its_radius_angle_and_sign_mean(short_3d_results, drawn,
                                                                  file):
    figure = drawn("cage_dynamics_3d", short_3d_results)[file]
    faces = [axis for axis in figure.axes if axis.name == "polar"]
    assert len(faces) == 2  # the left and the right end
    for axis in faces:
        radii = [t.get_text() for t in axis.get_yticklabels() if t.get_text()]
        assert radii and all(text.endswith(" mm") for text in radii)  # the radius has a unit
    [bar] = [axis for axis in figure.axes if hasattr(axis, "_colorbar")]
    assert "[um]" in bar.get_ylabel() and "below 0: overlap, dry contact" in bar.get_ylabel()
    note = " ".join(text.get_text() for text in figure.texts)
    assert "0 deg: radially outwards" in note and "radius from the roller's axis" in note
    assert "grey:" in note  # the elements without a counterpart
