"""The README and the documentation: their examples run as written and show what they say; the
pages written from the code hold every model's declaration; the examples' runner fails on an
example that does not run as shown."""
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
README = (ROOT / "README.md").read_text()
#: The pages written by hand (the generated ones are written from the code at build time).
PAGES = {str(path.relative_to(DOCS)): path.read_text() for path in sorted(DOCS.rglob("*.md"))
         if not {"generated", "_build"} & set(path.relative_to(DOCS).parts)}
GUIDE = "\n".join(PAGES.values())


def blocks(text, language):
    return re.findall(rf"^```{language}\n(.*?)^```", text, flags=re.S | re.M)


def run_python(script, folder):
    return subprocess.run([sys.executable, "-c", "import matplotlib\nmatplotlib.use('Agg')\n"
                           + script], cwd=folder, capture_output=True, text=True, timeout=300)


def test_the_readme_is_short_and_its_worked_example_runs(tmp_path, run_cli):
    assert len(README.encode()) <= 10_000
    (tmp_path / "example.toml").write_text(blocks(README, "toml")[0])
    commands = [line[2:].split() for line in blocks(README, "console")[0].splitlines()]
    for command in commands:
        assert command[0] == "bearing-sweep"
        run = run_cli(*command[1:], cwd=tmp_path, timeout=300)
        assert run.returncode == 0, run.stderr
    assert (tmp_path / "results" / "example.png").is_file()
    done = run_python(blocks(README, "python")[0], tmp_path)
    assert done.returncode == 0, done.stderr
    assert "N/mm" in done.stdout and "converged" in done.stdout
    # The figure the README shows is the one the example's plot command draws.
    assert (ROOT / "docs" / "_static" / "example.png").is_file()
    assert "(docs/_static/example.png)" in README


def test_the_documented_error_line_is_the_real_one(tmp_path, run_cli):
    page = PAGES["user-guide/definitions.md"]
    (tmp_path / "typo.toml").write_text(blocks(page, "toml")[1])
    shown = next(block for block in blocks(page, "console") if "typo.toml" in block)
    command, line = shown.strip().splitlines()
    run = run_cli(*command[2:].split()[1:], cwd=tmp_path, timeout=300)
    assert run.returncode == 2
    assert run.stderr.strip() == line


def test_every_command_and_option_is_documented_in_the_guide():
    from bearing_sweep.cli import _parser

    commands = _parser()._subparsers._group_actions[0].choices
    for name, command in commands.items():
        assert f"`bearing-sweep {name}" in GUIDE, name
        for action in command._actions:
            for option in action.option_strings:
                if option not in ("-h", "--help"):
                    assert f"`{option}" in GUIDE, f"{name} {option}"


def test_the_rating_life_example_runs_and_shows_the_clearance_optimum(tmp_path, run_cli):
    import xarray as xr

    page = PAGES["user-guide/models.md"]
    definition = next(block for block in blocks(page, "toml") if "dynamic_load_rating" in block)
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

    page = PAGES["user-guide/sampling.md"]
    definition = next(block for block in blocks(page, "toml") if "[sample]" in block)
    script = next(block for block in blocks(page, "python") if "bearing_sweep.analyze" in block)
    (tmp_path / "tolerances.toml").write_text(definition)
    for command in (["run", "tolerances.toml"], ["analyze", "results/tolerances.nc"]):
        done = run_cli(*command, cwd=tmp_path, timeout=300)
        assert done.returncode == 0, done.stderr
    assert "radial_stiffness:" in done.stdout
    done = run_python(script, tmp_path)
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


def test_the_shaft_system_example_runs_and_its_supports_carry_the_gear(tmp_path, run_cli):
    import xarray as xr

    definition = blocks(PAGES["user-guide/shaft-systems.md"], "toml")[0]
    (tmp_path / "shaft.toml").write_text(definition)
    done = run_cli("run", "shaft.toml", "-o", "shaft.nc", cwd=tmp_path, timeout=300)
    assert done.returncode == 0, done.stderr
    with xr.open_dataset(tmp_path / "shaft.nc") as result:
        assert result.status.dims == ("loads_gear_force_y", "supports_A_clearance")
        assert (result.status == 0).all()
        carried = result.support_load.sel(dof="radial_y").sum("support")
        gap = abs(carried - result.loads_gear_force_y) / result.loads_gear_force_y
        assert float(gap.max()) < 1e-9


def test_every_model_page_holds_its_whole_declaration(docs_module):
    import bearing_sweep

    pages = docs_module("generated_pages")
    terms = pages.glossary_terms()
    assert {"pitch_diameter", "clearance", "cage_slip"} <= terms
    for model in bearing_sweep.list_models():
        page = pages.model_page(model["name"], terms)
        declaration = bearing_sweep.describe(model["name"])
        for entry in declaration["inputs"] + declaration["outputs"]:
            row = next(line for line in page.splitlines()
                       if line.startswith((f"| `{entry['name']}` |",
                                           f"| {{term}}`{entry['name']}` |")))
            assert f"| {entry['meaning']}" in row and f"| {entry['unit']} |" in row, row
        for status in declaration["statuses"]:
            assert f"| `{status}` |" in page
        assert f".. autofunction:: {declaration['function']}" in page


def test_the_cli_page_holds_every_option(docs_module):
    from bearing_sweep.cli import _parser

    page = docs_module("generated_pages").cli_page()
    for name, command in _parser()._subparsers._group_actions[0].choices.items():
        assert f"## `bearing-sweep {name}`" in page
        for action in command._actions:
            for option in action.option_strings:
                assert option in ("-h", "--help") or f"`{option}`" in page, option


# The runner's rules on shell commands cheaper than bearing-sweep (the build runs those).
@pytest.mark.parametrize("page, problem", [
    ("```console\n$ exit 2\n```\n", "exited with 2"),
    ("```console\n$ echo one model\nanother model\n```\n", "did not print 'another model'"),
    ("```console\n$ echo one model\none ...el\n```\n", None),
    ("```console\n$ echo 'error: no such model' >&2; exit 2\nerror: ...such...\n```\n", None),
    ("```console\n$ echo 'error: no such model' >&2\nerror: no such model\n```\n",
     "exited with 0"),
    ("```python\nraise ValueError('shown')\n```\n", "ValueError: shown"),
    ("```python\nimport warnings\nwarnings.warn('shown')\n```\n", "warns: UserWarning: shown"),
    ("```toml\n[sweep\n```\n", "not TOML"),
    ("`a.toml`:\n\n```toml\n[sweep\n```\n```sh\nfalse\n```\n", None),
])
def test_the_examples_runner_fails_on_an_example_that_does_not_run_as_shown(
        tmp_path, page, problem, docs_module):
    examples = docs_module("doc_examples")
    if problem is None:
        examples.run_page("page.md", page, tmp_path)
    else:
        with pytest.raises(examples.ExampleFailed, match=re.escape(problem)):
            examples.run_page("page.md", page, tmp_path)


def test_the_notebook_runs_headless_and_shows_tables_and_a_figure(tmp_path):
    import nbformat
    from nbclient import NotebookClient

    notebook = nbformat.read(DOCS / "notebooks" / "first_sweep.ipynb", as_version=4)
    NotebookClient(notebook, timeout=300, kernel_name="python3",
                   resources={"metadata": {"path": str(tmp_path)}}).execute()
    code = [cell for cell in notebook.cells if cell.cell_type == "code"]

    def shown(cell, kind):
        return "".join(output.get("data", {}).get(kind, "") for output in cell.outputs)

    models, described, outputs = (shown(code[i], "text/html") for i in range(3))
    assert models.count("<tr>") == 11 and ">crb_radial<" in models  # a header, ten models
    assert ">radial_stiffness<" in described and ">N/mm<" in described
    assert "radial_stiffness" in outputs and "max_contact_pressure" in outputs
    printed = "".join(output.get("text", "") for output in code[4].outputs)
    assert printed.strip().endswith("N/mm")
    values = [float(v) for v in printed.split("[", 1)[1].split("]", 1)[0].split()]
    # Paper 000's conclusion: the radial stiffness falls as the clearance grows.
    assert len(values) == 3 and values[0] > values[1] > values[2] > 0
    assert shown(code[5], "image/png")  # the quick look's figure
    assert shown(code[6], "text/plain") == "True"
    assert (tmp_path / "example.html").is_file()
