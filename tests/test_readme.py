"""The README's worked example runs as written."""
import re
import subprocess
import sys
from pathlib import Path

README = (Path(__file__).resolve().parents[1] / "README.md").read_text()


def blocks(language):
    return re.findall(rf"```{language}\n(.*?)```", README, flags=re.S)


def test_worked_example(tmp_path, run_cli):
    definition, python = blocks("toml")[0], blocks("python")[0]
    (tmp_path / "example.toml").write_text(definition)
    run = run_cli("run", "example.toml", cwd=tmp_path, timeout=300)
    assert run.returncode == 0, run.stderr
    script = "import matplotlib\nmatplotlib.use('Agg')\n" + python
    done = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr


def test_python_api_example(tmp_path):
    definition = blocks("toml")[0]
    api = next(block for block in blocks("python") if "import bearing_sweep" in block)
    (tmp_path / "example.toml").write_text(definition)
    done = subprocess.run([sys.executable, "-c", api], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "N/mm" in done.stdout and "'crb_radial'" in done.stdout
    assert (tmp_path / "results" / "by_speed.nc").is_file()
    assert not (tmp_path / "results" / "example.nc").exists()  # in memory: no file


def test_the_documented_error_line_is_the_real_one(tmp_path, run_cli):
    definition = blocks("toml")[0].replace("crown =", "crwn =")
    (tmp_path / "example.toml").write_text(definition)
    run = run_cli("run", "example.toml", cwd=tmp_path, timeout=300)
    assert run.returncode == 2
    assert run.stderr.strip() in README


def test_every_command_and_option_is_documented():
    from bearing_sweep.cli import _parser

    commands = _parser()._subparsers._group_actions[0].choices
    for name, command in commands.items():
        assert f"`bearing-sweep {name}" in README, name
        for action in command._actions:
            for option in action.option_strings:
                if option not in ("-h", "--help"):
                    assert f"`{option}" in README, f"{name} {option}"


def test_the_rating_life_example_runs_and_shows_the_clearance_optimum(tmp_path, run_cli):
    import xarray as xr

    definition = next(block for block in blocks("toml") if "dynamic_load_rating" in block)
    (tmp_path / "life.toml").write_text(definition)
    run = run_cli("run", "life.toml", "-o", "life.nc", cwd=tmp_path, timeout=300)
    assert run.returncode == 0, run.stderr
    with xr.open_dataset(tmp_path / "life.nc") as result:
        assert result["modified_reference_rating_life"].notnull().all()
        # The classic optimum: the longest L10r at a slight preload or zero clearance, at
        # every load (Harris & Kotzalas, Rolling Bearing Analysis, ch. 7 and 11).
        best = result["reference_rating_life"].idxmax("clearance")
        assert ((best <= 0.0) & (best >= -0.015)).all(), best.values


def test_the_sampling_example_runs_and_analyze_names_what_drives_the_stiffness(tmp_path, run_cli):
    import xarray as xr

    definition = next(block for block in blocks("toml") if "[sample]" in block)
    script = next(block for block in blocks("python") if "bearing_sweep.analyze" in block)
    (tmp_path / "tolerances.toml").write_text(definition)
    for command in (["run", "tolerances.toml"], ["analyze", "results/tolerances.nc"]):
        done = run_cli(*command, cwd=tmp_path, timeout=300)
        assert done.returncode == 0, done.stderr
    assert "radial_stiffness:" in done.stdout
    done = subprocess.run([sys.executable, "-c", "import matplotlib\nmatplotlib.use('Agg')\n"
                           + script], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "tolerances.png").is_file()
    with xr.open_dataset(tmp_path / "results" / "tolerances_analysis.nc") as analysis:
        total = analysis.total_order.sel(output="radial_stiffness")
        # The load range moves the stiffness most (a line contact stiffens with load,
        # Palmgren's k ~ Fr^0.1 per roller), the clearance next; a micrometre of crown
        # tolerance hardly at all.
        assert total.idxmax("input") == "radial_load"
        assert float(total.sel(input="clearance")) > float(total.sel(input="crown"))
        assert float(analysis.total_order_interval.sel(
            output="radial_stiffness", input="crown", bound="high")) < 0.05
