"""The papers' studies regenerate every figure and stated number from their netCDF files."""
import subprocess
import sys
from pathlib import Path

import pytest

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
