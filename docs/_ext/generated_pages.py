"""The documentation's pages that are written from the code, never by hand: one page per model
(from its declaration and its function's docstring), the command-line reference (from the
argument parser) and the study gallery (from each study's folder and the report
``bearing-sweep report`` writes into ``figures/``).

:func:`write_all` writes them into ``docs/generated/``, which the build reads and git ignores.
"""
from __future__ import annotations

import argparse
import re
import shutil
from pathlib import Path

from bearing_sweep import describe, list_models

DOCS = Path(__file__).resolve().parents[1]
ROOT = DOCS.parent


def glossary_terms(glossary: Path = DOCS / "glossary.md") -> set[str]:
    """The terms the glossary defines: the lines at the start of its ``{glossary}`` block's
    entries (a term line begins in the first column; its definition is indented)."""
    text = glossary.read_text()
    block = text.split("```{glossary}", 1)[1].split("\n```", 1)[0]
    return {line.strip() for line in block.splitlines()
            if line.strip() and not line.startswith((" ", "\t"))}


def _cell(text) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _name(name: str, terms: set[str]) -> str:
    return f"{{term}}`{name}`" if name in terms else f"`{name}`"


def _default(entry: dict) -> str:
    if entry["required"]:
        return "required"
    default = entry["default"]
    return "" if default is None else f"`{default}`"


def model_page(name: str, terms: set[str]) -> str:
    """One model's reference page, in Markdown."""
    model = describe(name)
    lines = [f"# `{name}`", "", model["summary"], "",
             f"**Source:** {model['reference']}  ", f"**Model version:** {model['version']}  ",
             f"**Function:** {{py:func}}`{model['function']}`", "",
             "## Inputs", "",
             "In a definition, a quantity is written with its unit in any unit of the same "
             "dimension; the file stores it in the unit shown.", "",
             "| input | meaning | unit | default | valid |", "|---|---|---|---|---|"]
    for entry in model["inputs"]:
        valid = entry["range"] or ", ".join(f"`{choice}`" for choice in entry["choices"])
        dims = f" (over {', '.join(entry['dims'])})" if entry["dims"] else ""
        lines.append(f"| {_name(entry['name'], terms)} | {_cell(entry['meaning'])}{_cell(dims)} | "
                     f"{_cell(entry['unit'])} | {_cell(_default(entry))} | {_cell(valid)} |")
    lines += ["", "## Outputs", "", "| output | meaning | unit | dimensions |",
              "|---|---|---|---|"]
    for entry in model["outputs"]:
        dims = ", ".join(entry["dims"]) or "the sweep's"
        lines.append(f"| {_name(entry['name'], terms)} | {_cell(entry['meaning'])} | "
                     f"{_cell(entry['unit'])} | {_cell(dims)} |")
    lines += ["", "## Statuses", "",
              "Each point's `status` holds one outcome, and `out_of_validity` beside it where "
              "the point lies outside the validity below "
              "([Outputs, statuses](../../user-guide/outputs.md#status)).", "",
              "| status | means |", "|---|---|"]
    lines += [f"| `{status}` | {_cell(meaning)} |" for status, meaning in model["statuses"].items()]
    lines += ["", "## Validity", "", "Flagged `out_of_validity`, values kept: "
              + _cell(model["validity"] or "nothing beyond the statuses above") + ".", ""]
    if model["conditions"]:
        lines += ["Refused before computing:", ""]
        lines += [f"- {condition}" for condition in model["conditions"]]
        lines.append("")
    lines += ["## Equations and references", "",
              "The model function's own documentation: its arguments in SI units, the "
              "equations it solves and the references they come from.", "",
              "```{eval-rst}", f".. autofunction:: {model['function']}", "```", ""]
    return "\n".join(lines)


def models_index(names: list[str]) -> str:
    lines = ["# Model reference", "",
             "One page per model, written from its declaration and its function's "
             "documentation; `bearing-sweep describe MODEL` prints the same declaration.", "",
             "| model | what it computes |", "|---|---|"]
    for model in list_models():
        lines.append(f"| [`{model['name']}`]({model['name']}.md) | {_cell(model['summary'])} |")
    lines += ["", "```{toctree}", ":hidden:", "", *names, "```", ""]
    return "\n".join(lines)


def _subcommands(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    return {}


def cli_page() -> str:
    """The command-line reference, from the parser ``bearing-sweep`` uses."""
    from bearing_sweep.cli import _parser

    parser = _parser()
    helps = {}
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            helps = {choice.dest: choice.help for choice in action._choices_actions}
    lines = ["# Command-line reference", "", parser.description or "", "",
             "Written from the command's own argument parser; `bearing-sweep COMMAND --help` "
             "prints the same. The [commands page](../user-guide/commands.md) explains them.",
             "", "```text", parser.format_usage().strip(), "```", ""]
    for name, command in _subcommands(parser).items():
        lines += [f"## `bearing-sweep {name}`", "", _cell(helps.get(name) or ""), "",
                  "```text", command.format_usage().strip(), "```", "",
                  "| argument | meaning | default |", "|---|---|---|"]
        for action in command._actions:
            if isinstance(action, argparse._HelpAction):
                continue
            names = ", ".join(f"`{option}`" for option in action.option_strings) \
                or f"`{action.metavar or action.dest}`"
            if action.option_strings and action.nargs != 0:
                names += f" `{action.metavar or action.dest.upper()}`"
            default = action.default
            shown = "" if default in (None, False, argparse.SUPPRESS) else f"`{default}`"
            lines.append(f"| {names} | {_cell(action.help or '')} | {shown} |")
        lines.append("")
    return "\n".join(lines)


def study_pages(target: Path) -> list[str]:
    """Copy each study's report (``figures/<study>/``, made by ``bearing-sweep study`` and
    ``bearing-sweep report``) into ``target`` and write a gallery page; returns the pages'
    names. A study whose report is missing is named in :class:`FileNotFoundError`."""
    from bearing_sweep.study import find_studies

    names = []
    for study in find_studies(ROOT / "studies").values():
        folder = study.folder
        report = ROOT / "figures" / folder.name
        if not (report / "README.md").is_file():
            raise FileNotFoundError(f"{report / 'README.md'}: no report of study "
                                    f"{folder.name}; `make reproduce` writes it")
        shutil.copytree(report, target / folder.name, dirs_exist_ok=True,
                        ignore=shutil.ignore_patterns("*.md"))
        text = (report / "README.md").read_text()
        (target / f"{folder.name}.md").write_text(re.sub(
            r"\]\((?!https?:)([^)#]+\.png)\)", rf"]({folder.name}/\1)", text))
        names.append(folder.name)
    return names


def gallery(studies: list[str], folder: Path) -> str:
    """The gallery's index: each study's title and its first figure, linked to its page."""
    lines = ["# Gallery of studies", "",
             "Each study regenerates a paper's figures with the project's models, sets every "
             "number the paper states beside ours, and says what it assumes where the paper "
             "is silent; each study's run (`bearing-sweep study`) writes its page.", ""]
    for name in studies:
        text = (folder / f"{name}.md").read_text()
        title = text.split("\n", 1)[0].lstrip("# ").strip()
        figure = re.search(r"!\[([^\]]*)\]\(([^)]+\.png)\)", text)
        lines += [f"## [{title}]({name}.md)", ""]
        if figure:
            lines += [f"[![{figure.group(1)}]({figure.group(2)})]({name}.md)", ""]
    lines += ["```{toctree}", ":hidden:", "", *studies, "```", ""]
    return "\n".join(lines)


def write_all(target: Path = DOCS / "generated") -> None:
    """Write every generated page into ``target`` (made afresh)."""
    if target.exists():
        shutil.rmtree(target)
    (target / "models").mkdir(parents=True)
    (target / "studies").mkdir()
    terms = glossary_terms()
    names = [model["name"] for model in list_models()]
    for name in names:
        (target / "models" / f"{name}.md").write_text(model_page(name, terms))
    (target / "models" / "index.md").write_text(models_index(names))
    (target / "cli.md").write_text(cli_page())
    (target / "studies" / "index.md").write_text(gallery(study_pages(target / "studies"),
                                                         target / "studies"))
