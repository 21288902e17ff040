"""The project as users install it: a wheel in a fresh environment outside the checkout runs a
study in an empty folder, installs nothing under a generic top-level name, and says the version
git gives it."""
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

from bearing_sweep.study import find_studies

ROOT = Path(__file__).resolve().parents[1]


def _run(command, **settings):
    done = subprocess.run(command, capture_output=True, text=True, timeout=600, **settings)
    assert done.returncode == 0, done.stderr[-3000:]
    return done


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """A fresh environment with the project's wheel; its dependencies are this one's."""
    folder = tmp_path_factory.mktemp("wheel")
    # A clone, which has the history the version is derived from, with the checkout's files
    # as they are: building writes build/ and egg-info beside the sources.
    source = folder / "source"
    _run(["git", "clone", "--quiet", "--no-local", str(ROOT), str(source)])
    for name in _run(["git", "ls-files"], cwd=ROOT).stdout.split():
        target = source / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / name, target)
    # The build backend comes from the index as pyproject.toml asks; pip's cache stays here.
    _run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "-w",
          str(folder / "dist"), str(source)],
         env=dict(os.environ, PIP_CACHE_DIR=str(folder / "pip-cache")))
    wheel = next((folder / "dist").glob("bearing_sweep-*.whl"))
    environment = folder / "env"
    _run([sys.executable, "-m", "venv", "--without-pip", str(environment)])
    python = environment / "bin" / "python"
    site = Path(_run([str(python), "-c", "import sysconfig; print(sysconfig.get_paths()"
                      "['purelib'])"]).stdout.strip())
    # numpy, dask, ... from this environment, as plain paths: its editable install of the
    # project is a finder that a plain path does not activate.
    (site / "dependencies.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    _run([sys.executable, "-m", "pip", "--python", str(python), "install", "--quiet",
          "--no-deps", "--no-cache-dir", str(wheel)])
    return environment


def _environment(tmp_path):
    return dict(os.environ, MPLCONFIGDIR=str(tmp_path / "matplotlib"), PYTHONNOUSERSITE="1")


@pytest.mark.slow
def test_only_bearing_sweep_is_importable_from_the_wheel(installed, tmp_path):
    python = str(installed / "bin" / "python")
    found = _run([python, "-c", "import bearing_sweep, bearing_sweep.models.registry as r; "
                  "print(bearing_sweep.__file__); print(len(r.all_models()))"], cwd=tmp_path,
                 env=_environment(tmp_path)).stdout.split()
    assert found[0].startswith(str(installed)) and int(found[1]) >= 8
    for generic in ("models", "sweeps", "studies"):
        done = subprocess.run([python, "-c", f"import {generic}"], cwd=tmp_path,
                              capture_output=True, text=True, env=_environment(tmp_path))
        assert done.returncode != 0 and "ModuleNotFoundError" in done.stderr, generic


@pytest.mark.slow
def test_an_installed_wheel_runs_a_study_in_an_empty_folder(installed, tmp_path):
    command = str(installed / "bin" / "bearing-sweep")
    work = tmp_path / "empty"
    work.mkdir()
    _run([command, "study", "tapered_rib", "--workers", "0"], cwd=work,
         env=_environment(tmp_path))
    _run([command, "report"], cwd=work, env=_environment(tmp_path))
    figures = sorted(p.name for p in (work / "figures" / "tapered_rib").glob("*.png"))
    expected = find_studies(ROOT / "studies")["tapered_rib"].figures_module().FIGURES
    assert figures == sorted(expected)
    page = (work / "figures" / "tapered_rib" / "README.md").read_text()
    assert "The paper's numbers beside ours" in page and "agrees" in page
    assert (work / "results" / "tapered_rib").is_dir()


@pytest.mark.slow
def test_the_installed_version_is_derived_from_git(installed, tmp_path):
    said = _run([str(installed / "bin" / "bearing-sweep"), "--version"], cwd=tmp_path,
                env=_environment(tmp_path)).stdout.split()
    assert said[0] == "bearing-sweep"
    head = _run(["git", "rev-parse", "HEAD"], cwd=ROOT).stdout.strip()
    tag = subprocess.run(["git", "describe", "--tags", "--exact-match"], cwd=ROOT,
                         capture_output=True, text=True).stdout.strip()
    if tag and "+" not in said[1]:  # a release: the tag's version
        assert said[1] == tag.removeprefix("v")
    else:  # a development release after the last tag, with its commit
        assert re.fullmatch(r"\d+\.\d+(\.\d+)?\.dev\d+\+g[0-9a-f]+(\.d\d{8})?", said[1]), said
        assert head.startswith(said[1].split("+g")[1].split(".")[0])
