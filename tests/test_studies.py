"""The papers' studies regenerate every figure and stated number from their netCDF files."""
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from sweeps.plotting import at, conditions, in_unit
from sweeps.study import find_studies

STUDIES = Path(__file__).resolve().parents[1] / "studies"


# radial_stiffness is left to `make reproduce`: its sweeps take half a minute.
@pytest.mark.parametrize("name", ["ball_stiffness", "tapered_rib", "runout", "cage_slip"])
def test_a_study_regenerates_its_figures_and_report(name, tmp_path):
    study = find_studies(STUDIES)[name]
    folders = ["--studies", STUDIES, "--results", tmp_path / "results", "--figures",
               tmp_path / "figures"]
    for command in (["study", name, "--workers", "0"], ["report"]):
        done = subprocess.run([sys.executable, "-m", "sweeps", *command, *map(str, folders)],
                              capture_output=True, text=True, timeout=300, cwd=tmp_path)
        assert done.returncode == 0, done.stderr
    for figure in study.figures_module().FIGURES:
        assert (tmp_path / "figures" / name / figure).stat().st_size > 10_000
    page = (tmp_path / "figures" / name / "README.md").read_text()
    rows = [line for line in page.splitlines() if line.startswith("| ") and "---" not in line]
    assert len(rows) == len(study.claims()) + 1  # and the header
    computed = [claim for claim in study.claims() if "paper" in claim and "not recomputed"
                not in claim.get("assumptions", "")]
    assert page.count("not computed") == len(study.claims()) - len(computed)


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
