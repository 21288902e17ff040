"""The papers' studies regenerate every figure and stated number from their netCDF files."""
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from bearing_sweep import units
from bearing_sweep.plotting import at, conditions, in_unit
from bearing_sweep.store import open_result
from bearing_sweep.study import find_studies

STUDIES = Path(__file__).resolve().parents[1] / "studies"

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


@pytest.mark.parametrize("name", ["ball_stiffness", "tapered_rib", "runout", "cage_slip",
                                  "radial_stiffness"])
def test_a_study_regenerates_its_figures_and_report(name, tmp_path):
    study = find_studies(STUDIES)[name]
    folders = ["--studies", STUDIES, "--results", tmp_path / "results", "--figures",
               tmp_path / "figures"]
    for command in (["study", name, "--workers", "0"], ["report"]):
        done = subprocess.run([sys.executable, "-m", "bearing_sweep", *command, *map(str, folders)],
                              capture_output=True, text=True, timeout=300, cwd=tmp_path)
        assert done.returncode == 0, done.stderr
    for figure in study.figures_module().FIGURES:
        assert (tmp_path / "figures" / name / figure).stat().st_size > 10_000
    page = (tmp_path / "figures" / name / "README.md").read_text()
    rows = [line for line in page.splitlines() if line.startswith("| ") and "---" not in line]
    assert len(rows) == len(study.claims()) + 1  # and the header
    # A claim says in its assumptions when it is "not recomputed" or "not recomputable".
    computed = [claim for claim in study.claims() if "paper" in claim and "not recomput"
                not in claim.get("assumptions", "")]
    assert page.count("not computed") == len(study.claims()) - len(computed)


@pytest.mark.parametrize("name", ["ball_stiffness", "tapered_rib", "runout",
                                  "radial_stiffness"])
def test_a_study_selects_by_quantity_not_by_stored_numbers(name, tmp_path):
    """The same results with their inputs stored in other units give the same stated numbers
    and still draw: the figure scripts select by quantities and convert what they show."""
    study = find_studies(STUDIES)[name]
    done = subprocess.run([sys.executable, "-m", "bearing_sweep", "study", name, "--workers", "0",
                           "--studies", str(STUDIES), "--results", str(tmp_path / "results"),
                           "--figures", str(tmp_path / "figures")],
                          capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    stored = tmp_path / "results" / name
    assert _store_in_other_units(stored, tmp_path / "other") > 0
    module = study.figures_module()
    ours, in_other_units = module.ours(stored), module.ours(tmp_path / "other")
    assert in_other_units == pytest.approx(ours, rel=1e-9, nan_ok=True)
    (tmp_path / "redrawn").mkdir()
    module.draw(tmp_path / "other", tmp_path / "redrawn")
    assert sorted(p.name for p in (tmp_path / "redrawn").iterdir()) == sorted(module.FIGURES)


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
