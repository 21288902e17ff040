"""The command line end to end, in fresh processes as a user runs it."""
import subprocess
import sys
import textwrap
from pathlib import Path

import xarray as xr

BIN = Path(sys.executable).parent

DEFINITION = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "0.004 mm"
[axes]
radial_load = ["2 kN", "4 kN"]
speed = { values = [0, 5000], units = "rpm" }
"""


def cli(*args, cwd):
    return subprocess.run([sys.executable, "-m", "bearing_sweep", *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=300)


def test_run_writes_a_labelled_file_and_a_summary(tmp_path):
    (tmp_path / "example.toml").write_text(DEFINITION)
    done = cli("run", "example.toml", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "crb_radial: 4 points (4 converged) in" in done.stdout
    assert "results/example.nc" in done.stdout
    data = xr.open_dataset(tmp_path / "results" / "example.nc")
    assert data.radial_stiffness.dims == ("radial_load", "speed")
    assert data.radial_stiffness.attrs["units"] == "N/mm"


def test_a_misspelt_parameter_exits_2_with_one_line_and_writes_nothing(tmp_path):
    (tmp_path / "bad.toml").write_text(DEFINITION.replace("crown =", "crwn ="))
    done = cli("run", "bad.toml", cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr.strip() == ("error: bad.toml: fixed.crwn: unknown parameter 'crwn' of model "
                                   "crb_radial; did you mean 'crown'? (`bearing-sweep describe "
                                   "crb_radial` lists them)")
    assert list(tmp_path.iterdir()) == [tmp_path / "bad.toml"]


def test_console_script_lists_and_describes_models(tmp_path):
    models = subprocess.run([BIN / "bearing-sweep", "models"], capture_output=True, text=True)
    assert models.returncode == 0
    assert any(line.startswith("crb_radial: ") for line in models.stdout.splitlines())
    describe = subprocess.run([BIN / "bearing-sweep", "describe", "crb_radial"],
                              capture_output=True, text=True)
    assert "clearance [mm]: diametral clearance Pd" in describe.stdout
    assert "radial_stiffness [N/mm]" in describe.stdout
    unknown = subprocess.run([BIN / "bearing-sweep", "describe", "crb"], capture_output=True,
                             text=True)
    assert unknown.returncode == 2 and "unknown model 'crb'" in unknown.stderr
    presets = cli("presets", cwd=tmp_path)
    assert "paper000-D (crb_radial): Paper 000, Table 4" in presets.stdout


def test_study_runs_what_is_stale_draws_and_reports(tmp_path):
    study = tmp_path / "studies" / "tiny"
    study.mkdir(parents=True)
    (study / "loads.toml").write_text(DEFINITION)
    (study / "about.md").write_text("# Tiny study\n")
    (study / "claims.toml").write_text(textwrap.dedent("""
        [[claim]]
        id = "points"
        statement = "four points"
        paper = 4
        unit = ""
        tolerance = 0
        """))
    (study / "figures.py").write_text(textwrap.dedent("""
        import xarray as xr
        FIGURES = {"stiffness.png": "stiffness against load"}
        def draw(results, figures):
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
            data = xr.open_dataset(results / "loads.nc")
            data.radial_stiffness.plot.line(x="radial_load")
            plt.savefig(figures / "stiffness.png")
        def ours(results):
            return {"points": xr.open_dataset(results / "loads.nc").status.size}
        """))
    first = cli("study", "tiny", cwd=tmp_path)
    assert first.returncode == 0, first.stderr
    assert (tmp_path / "results" / "tiny" / "loads.nc").exists()
    assert (tmp_path / "figures" / "tiny" / "stiffness.png").exists()
    second = cli("study", "all", cwd=tmp_path)
    assert "loads.toml: up to date" in second.stdout
    (study / "loads.toml").write_text(DEFINITION.replace('"4 kN"', '"5 kN"'))
    third = cli("study", "tiny", cwd=tmp_path)
    assert "crb_radial: 4 points" in third.stdout  # a changed definition is stale
    report = cli("report", cwd=tmp_path)
    assert report.returncode == 0, report.stderr
    page = (tmp_path / "figures" / "tiny" / "README.md").read_text()
    assert "| four points |  | 4  | 4  | agrees (within 0 ) |  |" in page
    assert "![stiffness against load](stiffness.png)" in page
    index = (tmp_path / "figures" / "README.md").read_text()
    assert "[tiny](tiny/README.md): 1 of 1 comparable stated numbers agree" in index
    missing = cli("study", "nothing", cwd=tmp_path)
    assert missing.returncode == 2 and "no such study" in missing.stderr
