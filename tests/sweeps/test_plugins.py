"""Models from other packages: found through the entry-point group ``bearing_sweep.models``,
swept through the CLI and the engine; a broken plug-in is one line and hides no other model.

The third-party package is the user guide's "Add your own model" example, laid out as an installed
distribution (its module and a ``*.dist-info`` with the entry points of its pyproject) in a
folder put on the path: importlib.metadata finds distributions on ``sys.path``.
"""
import importlib
import logging
import os
import re
import subprocess
import sys
import textwrap
import tomllib
from pathlib import Path

import numpy as np
import pytest

import bearing_sweep.models.registry as registry
from bearing_sweep import stores
from bearing_sweep.models.registry import Input, Model, Output
from bearing_sweep.testing import assert_chunking_invariant, assert_valid_declaration

ROOT = Path(__file__).resolve().parents[2]
GUIDE_PAGE = (ROOT / "docs" / "user-guide" / "adding-a-model.md").read_text()


#: What the guide's example's springs.toml gives: deflection [mm] by load (1, 2 kN) and
#: springs (1, 3) at 50 N/mm per spring (1000 N / 50 N/mm = 20 mm per spring).
DEFLECTION_MM = [[20.0, 60.0], [40.0, 120.0]]


def readme_example() -> dict[str, str]:
    """The files of the guide's "Add your own model" example, by the path on their first
    line."""
    section = GUIDE_PAGE
    files = {}
    for block in re.findall(r"```\w+\n(.*?)```", section, flags=re.S):
        first_line = block.split("\n", 1)[0]
        files[first_line.removeprefix("# ").strip()] = block
    return files


def lay_out_distribution(folder: Path, pyproject: str, files: dict[str, str],
                         doc_examples) -> Path:
    """``files`` (path -> text) in ``folder``, and the dist-info an install of ``pyproject``
    would write there, as the documentation's build (``doc_examples``) lays out its example."""
    for relative, text in files.items():
        (folder / relative).parent.mkdir(parents=True, exist_ok=True)
        (folder / relative).write_text(textwrap.dedent(text))
    doc_examples.write_distribution_info(folder, pyproject)
    return folder


def plugin_pyproject(name: str, entry_point: str) -> str:
    """The pyproject of a distribution ``name`` 0.1 with one model entry point, given as
    ``"entry = module"``."""
    entry, value = entry_point.split(" = ")
    return (f'[project]\nname = "{name}"\nversion = "0.1"\n'
            f'[project.entry-points."bearing_sweep.models"]\n{entry} = "{value}"\n')


def example_package() -> dict[str, str]:
    """The guide's example's package: its module, and the empty ``__init__.py`` it names."""
    return {"my_bearings/__init__.py": "",
            "my_bearings/springs.py": readme_example()["my_bearings/springs.py"]}


@pytest.fixture
def site(tmp_path, docs_module):
    """A folder holding the guide's example installed, as ``sys.path`` would see it."""
    return lay_out_distribution(tmp_path / "site", readme_example()["pyproject.toml"],
                                example_package(), docs_module("doc_examples"))


@pytest.fixture
def discover(monkeypatch):
    """Put folders on ``sys.path`` and let the registry find models afresh; the modules
    imported from them are forgotten afterwards."""
    added = []

    def put_on_path(*folders):
        for folder in folders:
            monkeypatch.syspath_prepend(str(folder))
            added.append(str(folder))
        monkeypatch.setattr(registry, "_MODELS", {})
        return registry.all_models()

    yield put_on_path
    for name, module in list(sys.modules.items()):
        if str(getattr(module, "__file__", None) or "").startswith(tuple(added or ["\0"])):
            del sys.modules[name]


def path_environment(path):
    """This process's environment with ``path`` (folders) as PYTHONPATH."""
    return {**os.environ, "PYTHONPATH": os.pathsep.join(str(p) for p in path)}


def check_springs_result(data):
    np.testing.assert_allclose(data.deflection.transpose("load", "springs").values,
                               DEFLECTION_MM, rtol=1e-12)
    assert data.deflection.attrs["units"] == "mm"
    # One spring: its load, then NaN for the entries only three springs have.
    one = data.spring_load.sel(load=1000.0, springs=1).values
    np.testing.assert_allclose(one, [1000.0, np.nan, np.nan])
    np.testing.assert_allclose(data.spring_load.sel(load=2000.0, springs=3).values, [2000.0] * 3)


def test_our_models_are_the_modules_declared_in_the_entry_point_group():
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"][
        "entry-points"]["bearing_sweep.models"]
    declaring = {p.stem for p in (ROOT / "models").glob("*.py")
                 if re.search(r"^MODELS\b", p.read_text(), flags=re.M)}
    assert {v.rsplit(".", 1)[-1] for v in declared.values()} == declaring
    models = registry.all_models()
    for module in declaring:
        for model in importlib.import_module(f"bearing_sweep.models.{module}").MODELS:
            assert models[model.name] is model


def test_the_readme_example_sweeps_through_the_cli(site, tmp_path, run_cli):
    example = readme_example()
    work = tmp_path / "work"
    work.mkdir()
    (work / "springs.toml").write_text(example["springs.toml"])
    described = run_cli("describe", "spring_stack", cwd=work, env=path_environment([site]))
    assert described.returncode == 0, described.stderr
    assert "spring_load [N] (dims: spring)" in described.stdout
    listed = run_cli("models", cwd=work, env=path_environment([site]))
    assert "spring_stack: Identical springs in series" in listed.stdout
    assert "crb_radial" in listed.stdout
    run = run_cli("run", "springs.toml", "--quiet", cwd=work, env=path_environment([site]))
    assert run.returncode == 0, run.stderr
    check_springs_result(stores.open_result(work / "results" / "springs.nc"))


@pytest.mark.slow
def test_the_readme_example_sweeps_on_local_workers(site, tmp_path, run_cli):
    # Worker processes find the plug-in on their own (they inherit PYTHONPATH).
    (tmp_path / "springs.toml").write_text(readme_example()["springs.toml"])
    run = run_cli("run", "springs.toml", "--quiet", "--workers", "1", "--chunk-size", "1",
                  cwd=tmp_path, env=path_environment([site]))
    assert run.returncode == 0, run.stderr
    check_springs_result(stores.open_result(tmp_path / "results" / "springs.nc"))


@pytest.mark.slow
def test_the_readme_example_installs_with_pip(tmp_path, run_cli):
    # What the other tests lay out by hand is what pip makes of the example's pyproject.
    source = tmp_path / "my-bearings"
    for relative, text in {**example_package(),
                           "pyproject.toml": readme_example()["pyproject.toml"]}.items():
        (source / relative).parent.mkdir(parents=True, exist_ok=True)
        (source / relative).write_text(text)
    environment = {**os.environ, "TMPDIR": str(tmp_path), "PIP_CACHE_DIR": str(tmp_path / "cache"),
                   "PIP_DISABLE_PIP_VERSION_CHECK": "1"}
    installed = subprocess.run(
        [sys.executable, "-m", "pip", "install", "--quiet", "--no-deps", "--target",
         str(tmp_path / "site"), str(source)],
        env=environment, capture_output=True, text=True, timeout=600)
    if installed.returncode and "satisfies the requirement setuptools" in installed.stderr:
        pytest.skip("pip cannot reach setuptools to build the example (no package index)")
    assert installed.returncode == 0, installed.stderr
    described = run_cli("describe", "spring_stack", cwd=tmp_path,
                        env=path_environment([tmp_path / "site"]))
    assert described.returncode == 0, described.stderr
    assert described.stdout.startswith("spring_stack (version 1): Identical springs")


def test_the_readme_example_sweeps_through_the_python_api(site, discover, tmp_path):
    import bearing_sweep

    discover(site)
    check_springs_result(bearing_sweep.run(readme_example()["springs.toml"], workers=0,
                                           progress=False))
    with bearing_sweep.run(readme_example()["springs.toml"], output=tmp_path / "springs.nc",
                           workers=0, progress=False) as written:
        check_springs_result(written.load())


def test_the_testing_helpers_pass_the_readme_example(site, discover, tmp_path):
    model = discover(site)["spring_stack"]
    assert model.function.__module__ == "my_bearings.springs"
    assert_valid_declaration(model)
    assert_chunking_invariant(readme_example()["springs.toml"], tmp_path)


# A broken plug-in beside the guide's: (module text, entry point, words of its line).
CLASHING = """
    from bearing_sweep.models.registry import Input, Model, Output
    from my_bearings.springs import spring_stack

    MODELS = [Model("crb_radial", spring_stack, "s", "r", "1",
                    (Input("load", "N", "l"), Input("stiffness", "N/mm", "k", default=100.0),
                     Input("springs", "1", "n", default=2, kind="count")),
                    (Output("deflection", "mm", "d"),
                     Output("spring_load", "N", "f", dims=("spring",))),
                    dim_sizes={"spring": "springs"})]
"""
MISMATCHED = """
    from bearing_sweep.models.registry import Input, Model, Output

    def product(a, c):
        return {"p": a * c, "status": 0 * a}

    MODELS = [Model("product", product, "s", "r", "1", (Input("a", "1", "a", kind="number"),
                    Input("b", "1", "b", kind="number")), (Output("p", "1", "p"),))]
"""
BROKEN = {
    "import_error": ("import no_such_package_for_bearing_sweep\n", "broken = broken_module",
                     "cannot be imported (ModuleNotFoundError: No module named "
                     "'no_such_package_for_bearing_sweep'); its models are left out"),
    "name_clash": (CLASHING, "broken = broken_module",
                   "model 'crb_radial' left out: the name is already taken by a model of "
                   "bearing-sweep"),
    "declaration_mismatch": (MISMATCHED, "broken = broken_module",
                             "model 'product' left out: the function's parameters (a, c) are "
                             "not its declared inputs (a, b) in that order"),
    "no_models": ("VALUE = 1\n", "broken = broken_module:VALUE", "holds no models"),
}


@pytest.fixture(params=sorted(BROKEN))
def broken_site(request, tmp_path, docs_module):
    text, entry_point, words = BROKEN[request.param]
    folder = lay_out_distribution(tmp_path / "site_broken", plugin_pyproject(
        "broken-plugin", entry_point), {"broken_module.py": text}, docs_module("doc_examples"))
    return folder, words


def test_a_broken_plugin_is_one_line_and_hides_no_other_model(site, broken_site, discover,
                                                                caplog):
    folder, words = broken_site
    with caplog.at_level(logging.WARNING, logger=registry.__name__):
        models = discover(site, folder)
    assert len(caplog.records) == 1
    line = caplog.records[0].getMessage()
    assert line.startswith("model plug-in 'broken' (broken-plugin 0.1: broken_module")
    assert words in line and "\n" not in line
    assert "spring_stack" in models
    assert models["crb_radial"].function.__module__ == "bearing_sweep.models.cylindrical"
    assert {"ball_5dof", "cage_dynamics", "hertz_point", "trb_rib"} <= set(models)


def test_the_cli_shows_a_broken_plugin_as_one_line(site, broken_site, tmp_path, run_cli):
    folder, words = broken_site
    listed = run_cli("models", cwd=tmp_path, env=path_environment([site, folder]))
    assert listed.returncode == 0
    assert listed.stderr.count("\n") == 1 and words in listed.stderr, listed.stderr
    assert "Traceback" not in listed.stderr
    assert "spring_stack:" in listed.stdout and "crb_radial:" in listed.stdout


def test_an_entry_point_may_name_one_model(site, discover, tmp_path, docs_module):
    folder = lay_out_distribution(tmp_path / "site_single", plugin_pyproject(
        "single-model", "single = single_module:DOUBLED"), {"single_module.py": """
            from bearing_sweep.models.registry import Input, Model, Output

            def doubled(x):
                return {"y": 2 * x, "status": 0 * x}

            DOUBLED = Model("doubled", doubled, "twice x", "none", "1",
                            (Input("x", "1", "x", kind="number"),), (Output("y", "1", "y"),))
        """}, docs_module("doc_examples"))
    assert discover(site, folder)["doubled"].function.__module__ == "single_module"


def _springs_with_wrong_si_default(load, stiffness=100.0, springs=2):
    return {}


def test_a_default_not_in_si_fails_the_declaration_check():
    model = Model("springs", _springs_with_wrong_si_default, "s", "r", "1",
                  (Input("load", "N", "l"), Input("stiffness", "N/mm", "k", default=100.0),
                   Input("springs", "1", "n", default=2, kind="count")),
                  (Output("deflection", "mm", "d"),))
    with pytest.raises(AssertionError, match=r"input 'stiffness': the function's default "
                       r"100.0 is not the declared 100.0 N/mm in SI base units \(100000.0\)"):
        assert_valid_declaration(model)


def _centred(x):
    """Depends on which points share a call: not a model."""
    x = np.asarray(x, dtype=float)
    return {"y": x - x.mean(), "status": np.zeros(x.shape, dtype=np.int8)}


def test_a_model_whose_points_influence_each_other_fails_the_chunking_check(monkeypatch,
                                                                            tmp_path):
    registry.all_models()  # ours first, then the toy
    model = Model("centred", _centred, "s", "r", "1", (Input("x", "1", "x", kind="number"),),
                  (Output("y", "1", "y"),))
    monkeypatch.setitem(registry._MODELS, model.name, model)
    with pytest.raises(AssertionError, match="centred.y"):
        assert_chunking_invariant('[sweep]\nmodel = "centred"\n[axes]\nx = [1, 2, 4]\n',
                                  tmp_path)
