"""The command line end to end, in fresh processes as a user runs it."""
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
import xarray as xr

BIN = Path(sys.executable).parent


def test_run_writes_a_labelled_file_and_a_summary(tmp_path, four_points, run_cli):
    (tmp_path / "example.toml").write_text(four_points)
    done = run_cli("run", "example.toml", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "crb_radial: 4 points (4 converged) in" in done.stdout
    assert "results/example.nc" in done.stdout
    data = xr.open_dataset(tmp_path / "results" / "example.nc")
    assert data.radial_stiffness.dims == ("radial_load", "speed")
    assert data.radial_stiffness.attrs["units"] == "N/mm"


def test_a_misspelt_parameter_exits_2_with_one_line_and_writes_nothing(tmp_path, four_points,
                                                                       run_cli):
    (tmp_path / "bad.toml").write_text(four_points.replace("crown =", "crwn ="))
    done = run_cli("run", "bad.toml", cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr.strip() == ("error: bad.toml: fixed.crwn: unknown parameter 'crwn' of model "
                                   "crb_radial; did you mean 'crown'? (`bearing-sweep describe "
                                   "crb_radial` lists them)")
    assert list(tmp_path.iterdir()) == [tmp_path / "bad.toml"]


def test_console_script_lists_and_describes_models(tmp_path, run_cli):
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
    presets = run_cli("presets", cwd=tmp_path)
    assert "paper000-D (crb_radial): Paper 000, Table 4" in presets.stdout


def test_the_version_is_the_installed_distribution_s(tmp_path, run_cli):
    from importlib.metadata import version

    import bearing_sweep

    installed = version("bearing-sweep")
    done = run_cli("--version", cwd=tmp_path)
    assert done.returncode == 0 and done.stdout == f"bearing-sweep {installed}\n"
    assert bearing_sweep.__version__ == installed


def test_study_runs_what_is_stale_draws_and_reports(tmp_path, four_points, run_cli):
    study = tmp_path / "studies" / "tiny"
    study.mkdir(parents=True)
    (study / "loads.toml").write_text(four_points)
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
        def tables(results):
            count = xr.open_dataset(results / "loads.nc").status.size
            return f"## The runs' numbers\\n\\n{count} points computed"
        """))
    first = run_cli("study", "tiny", cwd=tmp_path)
    assert first.returncode == 0, first.stderr
    assert (tmp_path / "results" / "tiny" / "loads.nc").exists()
    assert (tmp_path / "figures" / "tiny" / "stiffness.png").exists()
    # the run writes the study's page, and the index is made from it
    summary = "1 of 1 comparable stated numbers agree within their tolerance (1 stated)"
    assert f"\n{summary}.\n" in (tmp_path / "figures" / "tiny" / "README.md").read_text()
    indexed = run_cli("report", "--index", cwd=tmp_path)
    assert indexed.returncode == 0, indexed.stderr
    assert indexed.stdout == f"wrote {Path('figures', 'README.md')}\n"  # no page written
    assert f"[tiny](tiny/README.md): {summary}" in (tmp_path / "figures" / "README.md").read_text()
    second = run_cli("study", "all", "--workers", "0", cwd=tmp_path)
    assert "loads.toml: up to date" in second.stdout
    (study / "loads.toml").write_text(four_points.replace('"4 kN"', '"5 kN"'))
    third = run_cli("study", "tiny", "--workers", "0", cwd=tmp_path)
    assert "crb_radial: 4 points" in third.stdout  # a changed definition is stale
    report = run_cli("report", cwd=tmp_path)
    assert report.returncode == 0, report.stderr
    page = (tmp_path / "figures" / "tiny" / "README.md").read_text()
    assert "| four points |  | 4  | 4  | agrees (within 0 ) |  |" in page
    assert "![stiffness against load](stiffness.png)" in page
    # the study's own tables, from its results, between its page and the stated numbers
    assert (page.index("# Tiny study") < page.index("## The runs' numbers\n\n4 points computed")
            < page.index("## The paper's numbers beside ours"))
    index = (tmp_path / "figures" / "README.md").read_text()
    assert "[tiny](tiny/README.md): 1 of 1 comparable stated numbers agree" in index
    # a page without its summary (an earlier version's) is written again for the index
    (tmp_path / "figures" / "tiny" / "README.md").write_text("# Tiny study\n")
    again = run_cli("report", "--index", cwd=tmp_path)
    assert again.returncode == 0 and "tiny" in again.stdout, again.stderr
    assert (tmp_path / "figures" / "README.md").read_text() == index
    missing = run_cli("study", "nothing", cwd=tmp_path)
    assert missing.returncode == 2 and "no such study" in missing.stderr


STUDIES = Path(__file__).resolve().parents[2] / "studies"


def _mistaken_folders(tmp_path, case):
    """The options of `study` or `report` for one mistaken folder, over the real studies."""
    (tmp_path / "notes.txt").write_text("not a folder")
    (tmp_path / "empty").mkdir()
    options = {"--studies": STUDIES, "--results": tmp_path / "results",
               "--figures": tmp_path / "figures"}
    mistake = {"figures_file": ("--figures", tmp_path / "notes.txt"),
               "figures_under_a_file": ("--figures", tmp_path / "notes.txt" / "figures"),
               "results_file": ("--results", tmp_path / "notes.txt"),
               "studies_file": ("--studies", tmp_path / "notes.txt"),
               "studies_empty": ("--studies", tmp_path / "empty"),
               "studies_missing": ("--studies", tmp_path / "nowhere")}[case]
    options[mistake[0]] = mistake[1]
    return [str(part) for option in options.items() for part in option], mistake[1]


@pytest.mark.parametrize("command", ["study", "report"])
@pytest.mark.parametrize("case", ["figures_file", "figures_under_a_file", "results_file",
                                  "studies_file", "studies_empty", "studies_missing"])
def test_a_mistaken_folder_is_one_line_before_anything_is_computed(tmp_path, command, case,
                                                                   run_cli):
    options, named = _mistaken_folders(tmp_path, case)
    before = sorted(p.name for p in tmp_path.iterdir())
    args = ["study", "tapered_rib", "--workers", "0"] if command == "study" else ["report"]
    done = run_cli(*args, *options, cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert done.stderr.startswith(f"error: {named}: ") and "Traceback" not in done.stderr
    assert done.stdout == ""  # no sweep run, nothing drawn or written
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    if case.startswith("studies_"):  # says what a folder of studies holds
        assert "figures.py" in done.stderr and "*.toml" in done.stderr


def test_study_all_in_an_empty_folder_is_an_error(tmp_path, run_cli):
    (tmp_path / "studies").mkdir()
    done = run_cli("study", "all", "--workers", "0", cwd=tmp_path)  # ./studies: the default
    assert done.returncode == 2, done.stderr
    assert done.stderr == ("error: studies: holds no study (--studies: a folder of studies "
                           "holds a folder per study, each with its sweep definitions (*.toml) "
                           "and figures.py)\n")


def _tiny_study(tmp_path, figures_py: str, definition: str | None):
    study = tmp_path / "studies" / "tiny"
    study.mkdir(parents=True)
    if definition is not None:
        (study / "loads.toml").write_text(definition)
    (study / "figures.py").write_text(textwrap.dedent(figures_py))


@pytest.mark.parametrize("case", ["figure_is_a_folder", "script_fails", "no_definitions"])
def test_what_would_stop_a_study_after_its_sweeps_is_refused_before_them(tmp_path, case, run_cli,
                                                                        four_points):
    _tiny_study(tmp_path, 'FIGURES = {"k.png": "stiffness"}\n' if case != "script_fails"
                else "import no_such_module_anywhere\n",
                None if case == "no_definitions" else four_points)
    if case == "figure_is_a_folder":
        (tmp_path / "figures" / "tiny" / "k.png").mkdir(parents=True)
    done = run_cli("study", "tiny", "--workers", "0", cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert {"figure_is_a_folder": "k.png: exists and is not a file",
            "script_fails": "figures.py: does not load: ModuleNotFoundError",
            "no_definitions": "study tiny has no sweep definitions (*.toml)"}[case] \
        in done.stderr
    assert not (tmp_path / "results").exists()  # nothing computed


@pytest.mark.parametrize("options", [["run", "--workers", "1.5", "d.toml"], ["run"], [],
                                     ["frob"], ["plot", "r.nc", "--x"], ["run", "--bogus", "d.toml"]])
def test_a_mistaken_option_is_one_line_not_the_usage_block(options, tmp_path):
    done = subprocess.run([BIN / "bearing-sweep", *options], cwd=tmp_path, capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 2
    assert len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert done.stderr.startswith("error: bearing-sweep") and "--help` lists" in done.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_ctrl_c_raised_as_another_error_is_one_line(monkeypatch, capsys):
    # Python raises an interrupt that lands in a class's __set_name__ (as a module loads) as
    # a RuntimeError whose cause is the KeyboardInterrupt; numba's dispatcher, a SystemError.
    from bearing_sweep import cli

    def interrupted(name):
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as error:
            raise RuntimeError("Error calling __set_name__") from error

    monkeypatch.setattr(cli, "_describe", interrupted)
    assert cli.main(["describe", "crb_radial"]) == 130
    assert capsys.readouterr().err == "interrupted\n"
    monkeypatch.setattr(cli, "_describe", lambda name: 1 / 0)  # any other error is a bug
    with pytest.raises(ZeroDivisionError):
        cli.main(["describe", "crb_radial"])


@pytest.mark.slow
def test_ctrl_c_while_the_program_starts_is_one_line(tmp_path):
    # From the moment the program's own code runs (before it, a Ctrl-C lands in the
    # interpreter's start-up or in the import of the package's first lines, and is Python's to
    # report) to the end. That moment is told by an audit hook, installed in the real
    # command's interpreter by a sitecustomize, when the program imports its first module.
    # The program ends some 0.4 s after that; as the interpreter shuts down it gives SIGINT
    # back its default action, and a Ctrl-C then ends the process as the signal does, with
    # nothing to say (a shell reports 130): the status -2, its output complete.
    import os
    import signal
    import time

    (tmp_path / "sitecustomize.py").write_text(textwrap.dedent("""
        import sys

        def started(event, args):
            if event == "import" and args[0] == "bearing_sweep.interrupts":
                sys.stderr.write("started\\n")
                sys.stderr.flush()

        sys.addaudithook(started)
    """))
    environment = dict(os.environ, PYTHONPATH=str(tmp_path))
    command = [BIN / "bearing-sweep", "describe", "crb_radial"]
    whole = subprocess.run(command, cwd=tmp_path, env=environment, capture_output=True,
                           text=True, check=True).stdout
    for delay in (0.0, 0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6):
        started = subprocess.Popen(command, cwd=tmp_path, env=environment,
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert started.stderr.readline() == "started\n"
        time.sleep(delay)
        started.send_signal(signal.SIGINT)
        output, error = started.communicate(timeout=60)
        assert "Traceback" not in error, (delay, error)
        assert started.returncode in (0, 130, -signal.SIGINT), (delay, started.returncode,
                                                                 error)
        if started.returncode == -signal.SIGINT:
            assert output == whole, delay  # ended by the signal only once it was done
        assert len(error.strip().splitlines()) <= 1, error


def test_a_ctrl_c_that_lands_where_python_cannot_raise_it_is_raised_again(tmp_path):
    # A Ctrl-C inside a weak reference's callback (importlib's module locks have one) is
    # printed as "Exception ignored" and dropped by Python; the program signals it again so
    # that it stops the program where the main thread is next, here in a sleep.
    script = tmp_path / "dropped.py"
    script.write_text(textwrap.dedent("""
        import sys, time, weakref
        import bearing_sweep
        from bearing_sweep import cli

        def main(argv):
            class Body:
                pass
            body = Body()
            ref = weakref.ref(body, lambda ref: (_ for _ in ()).throw(KeyboardInterrupt()))
            started = time.monotonic()
            try:
                del body
                time.sleep(30)
            except KeyboardInterrupt:
                print(f"raised after {time.monotonic() - started:.1f} s", file=sys.stderr)
                return 130
            return 0

        cli.main = main
        sys.exit(bearing_sweep.program([]))
        """))
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                          timeout=60, cwd=tmp_path)
    assert done.returncode == 130, done.stderr
    assert done.stderr.strip() in ("raised after 0.0 s", "raised after 0.1 s"), done.stderr


def test_a_report_tells_how_to_run_a_study_in_the_folders_it_was_given(tmp_path, run_cli):
    done = run_cli("report", "--studies", STUDIES, "--results", "my results", "--figures", "fig",
                   cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    index = (tmp_path / "fig" / "README.md").read_text()
    assert (f"- runout: not run yet (`bearing-sweep study runout --studies {STUDIES} "
            "--results 'my results' --figures fig`)") in index
    assert run_cli("report", cwd=tmp_path).returncode == 0  # the default folders: no options
    assert "- runout: not run yet (`bearing-sweep study runout`)" in \
        (tmp_path / "figures" / "README.md").read_text()


def test_a_result_of_a_preset_since_changed_is_stale(tmp_path, monkeypatch, four_points):
    # The definition's text names the preset only: a catalogue that changes the preset's
    # values (an assumption corrected) must rerun the study's result, not draw the old one.
    import dataclasses

    from bearing_sweep import spec
    from bearing_sweep.compute import Executor, run_sweep
    from bearing_sweep.models.catalogue import PRESETS
    from bearing_sweep.study import is_stale

    definition = tmp_path / "loads.toml"
    definition.write_text(four_points)
    result = tmp_path / "loads.nc"
    run_sweep(spec.load(definition), result, Executor(workers=0), progress=False)
    assert not is_stale(definition, result, spec.load(definition))
    preset = PRESETS["paper000-D"]
    monkeypatch.setitem(PRESETS, "paper000-D", dataclasses.replace(
        preset, values={**preset.values, "pitch_diameter": "66 mm"}))
    assert is_stale(definition, result, spec.load(definition))
