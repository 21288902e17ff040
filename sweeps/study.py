"""Studies: a paper's sweep definitions, its figure script and the numbers it states.

A study is a folder ``studies/<name>/`` holding ``*.toml`` sweep definitions, ``figures.py``
(``FIGURES``: file name -> caption; ``draw(results, figures)``; ``ours(results)``: our value
of each stated number, from the netCDF files only; optionally ``tables(results)``: Markdown
the report shows after ``about.md``, the runs' numbers as these results have them),
``claims.toml`` (the paper's numbers) and ``about.md`` (what the study shows and assumes).
The figure script is loaded from its file: studies are data for the engine (installed with
it as package data).
"""
from __future__ import annotations

import importlib.util
import os
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr

from . import spec as spec_module
from .compute import Executor, run_sweep
from .grid import Grid
from .definition.tables import suggestion
from .spec import SpecError


@dataclass(frozen=True)
class Study:
    name: str
    folder: Path

    @property
    def definitions(self) -> list[Path]:
        return sorted(p for p in self.folder.glob("*.toml") if p.name != "claims.toml")

    def result(self, results: Path, definition: Path) -> Path:
        return results / self.name / f"{definition.stem}.nc"

    def figures_module(self):
        path = self.folder / "figures.py"
        loader = importlib.util.spec_from_file_location(f"_study_{self.name}_figures", path)
        module = importlib.util.module_from_spec(loader)
        loader.loader.exec_module(module)
        return module

    def _claims_file(self) -> dict:
        path = self.folder / "claims.toml"
        return tomllib.loads(path.read_text()) if path.exists() else {}

    def claims(self) -> list[dict]:
        return self._claims_file().get("claim", [])

    @property
    def beyond_the_papers(self) -> bool:
        """Whether the claims are expected trends (``beyond_the_papers = true`` at the top of
        claims.toml) rather than numbers a paper states."""
        return bool(self._claims_file().get("beyond_the_papers", False))

    def about(self) -> str:
        path = self.folder / "about.md"
        return path.read_text() if path.exists() else ""


def default_studies_folder() -> Path:
    """``./studies`` when run from a checkout's root, else the one beside the package."""
    here = Path("studies")
    if here.is_dir():
        return here
    from . import studies  # the studies installed with the package

    return Path(studies.__file__).resolve().parent


#: What a folder of studies holds, for the messages that find none in one.
LAYOUT = ("a folder of studies holds a folder per study, each with its sweep definitions "
          "(*.toml) and figures.py")
#: What each folder option names, for the messages that refuse one.
_PURPOSE = {"--results": "the folder of the studies' results",
            "--figures": "the folder of the studies' figures and report pages"}


def find_studies(folder: Path) -> dict[str, Study]:
    return {p.parent.name: Study(p.parent.name, p.parent)
            for p in sorted(Path(folder).glob("*/figures.py"))}


def select(folder: Path, names) -> list[Study]:
    """The studies ``names`` of ``folder`` (a name or a list of them, in their order; ``"all"``:
    each of them); a :class:`SpecError` for a folder that is none or holds no study, an
    unknown name, a study without sweeps."""
    folder = Path(folder)
    names = [names] if isinstance(names, str) else list(names)
    if not folder.is_dir():
        raise SpecError(f"{folder}: {'is not a' if os.path.lexists(folder) else 'no such'} "
                        f"folder of studies (--studies: {LAYOUT})")
    studies = find_studies(folder)
    if not studies:
        raise SpecError(f"{folder}: holds no study (--studies: {LAYOUT})")
    for name in names:
        if name != "all" and name not in studies:
            raise SpecError(f"study {name!r}: no such study in {folder}"
                            + suggestion(name, studies) + " (studies: "
                            + ", ".join(sorted(studies) + ["all"]) + ")")
    chosen = list(studies.values()) if "all" in names else [studies[n] for n in
                                                            dict.fromkeys(names)]
    for study in chosen:
        if not study.definitions:
            raise SpecError(f"{study.folder}: study {study.name} has no sweep definitions "
                            f"(*.toml) ({LAYOUT})")
    return chosen


def check_folders(studies: list[Study], results: Path, figures: Path) -> None:
    """Refuse, before any sweep is computed, what would stop the studies afterwards: a
    ``results`` or ``figures`` folder (or a study's folder in them) that is not a folder and
    cannot be made one, a figure's path that is not a file, a figure script that does not
    load. Each is a :class:`SpecError` of one line."""
    for option, root in (("--results", Path(results)), ("--figures", Path(figures))):
        for folder in (root, *(root / study.name for study in studies)):
            _check_folder(folder, option)
    for study in studies:
        try:
            module = study.figures_module()
            names = list(module.FIGURES)
        except Exception as error:  # the study's own code: whatever it raises, in a line
            text = str(error).splitlines()[0] if str(error) else ""
            raise SpecError(f"{study.folder / 'figures.py'}: does not load: "
                            f"{type(error).__name__}{': ' + text if text else ''}") from None
        for name in names:
            path = Path(figures) / study.name / name
            if os.path.lexists(path) and (path.is_symlink() or not path.is_file()):
                raise SpecError(f"{path}: exists and is not a file; refusing to replace it "
                                f"with the figure (--figures: {_PURPOSE['--figures']})")


def _check_folder(folder: Path, option: str):
    """``folder`` is a folder, or can be made: its nearest existing ancestor is a writable
    folder."""
    ancestor = folder
    while not os.path.lexists(ancestor) and ancestor != ancestor.parent:
        ancestor = ancestor.parent
    purpose = f"({option}: {_PURPOSE[option]})"
    if not ancestor.is_dir():
        problem = ("is not a folder" if ancestor == folder
                   else f"cannot be made: {ancestor} is not a folder")
        raise SpecError(f"{folder}: {problem} {purpose}")
    if not os.access(ancestor, os.W_OK | os.X_OK):
        raise SpecError(f"{folder}: cannot be written: permission denied on {ancestor} "
                        f"{purpose}")


def is_stale(definition: Path, result: Path, sweep) -> bool:
    """Whether ``result`` is missing or was made from another definition, other input values
    (a preset of the catalogue changed since) or another model version."""
    if not result.exists():
        return True
    try:
        with xr.open_dataset(result, engine="netcdf4") as dataset:
            attrs = dataset.attrs
    except (OSError, ValueError):
        return True
    return (attrs.get("definition_sha256") != sweep.sha256
            or attrs.get("values_sha256") != Grid.from_sweep(sweep).values_sha256
            or attrs.get("model_version") != sweep.model.version)


def run_study(study: Study, results: Path, figures: Path, executor: Executor,
              force: bool = False, log=print) -> None:
    """Run the study's missing or stale sweeps, then draw its figures and write its page
    (:func:`write_page`)."""
    sweeps = [(d, spec_module.load(d)) for d in study.definitions]  # all valid before any run
    for definition, sweep in sweeps:
        result = study.result(results, definition)
        if not force and not is_stale(definition, result, sweep):
            log(f"{study.name}/{definition.name}: up to date ({result})")
            continue
        log(run_sweep(sweep, result, executor, log=log).text())
    target = figures / study.name
    target.mkdir(parents=True, exist_ok=True)
    study.figures_module().draw(results / study.name, target)
    log(f"{study.name}: figures in {target}")
    write_page(study, results, figures)
    log(f"wrote {target / 'README.md'}")


def write_report(studies: list[Study], results: Path, figures: Path, folders: str = "",
                 from_pages: bool = False) -> list[Path]:
    """Write ``figures/<study>/README.md`` for each study (:func:`write_page`) and the index
    ``figures/README.md``; ``folders``: the options that name the folders (``--results
    res``), repeated in the command a page gives to run a study that has not been run yet.
    ``from_pages``: index the pages as the studies' runs wrote them (:func:`run_study`), each
    by its summary, writing only those that are missing."""
    written, index = [], ["# Reproduced figures and stated numbers", ""]
    for study in studies:
        missing = [d.name for d in study.definitions if not study.result(results, d).exists()]
        if missing:
            index.append(f"- {study.name}: not run yet (`bearing-sweep study {study.name}"
                         f"{' ' + folders if folders else ''}`)")
            continue
        page = figures / study.name / "README.md"
        summary = _summary(page) if from_pages else None
        if summary is None:
            summary = write_page(study, results, figures)
            written.append(page)
        index.append(f"- [{study.name}]({study.name}/README.md): {summary}")
    figures.mkdir(parents=True, exist_ok=True)
    (figures / "README.md").write_text("\n".join(index) + "\n")
    written.append(figures / "README.md")
    return written


def write_page(study: Study, results: Path, figures: Path) -> str:
    """Write ``figures/<study>/README.md``: the study's text, its tables, its stated numbers
    beside ours (with a summary of how many agree, which it returns) and its figures."""
    module = study.figures_module()
    folder = figures / study.name
    ours = module.ours(results / study.name)
    kind, heading, column = (("expected trends", "What is expected beside ours", "expected")
                             if study.beyond_the_papers else
                             ("stated numbers", "The paper's numbers beside ours", "paper"))
    rows, agreeing, comparable = _claim_rows(study.claims(), ours, column)
    summary = (f"{agreeing} of {comparable} comparable {kind} agree within their tolerance "
               f"({len(rows)} stated)")
    tables = getattr(module, "tables", None)
    page = [study.about().rstrip(), ""]
    if tables is not None:
        page += [tables(results / study.name).rstrip(), ""]
    page += [f"## {heading}", "", f"{summary}.", "",
             f"| {kind[:-1]} | source | {column} | ours | agreement | assumptions |",
             "|---|---|---|---|---|---|", *rows, "", "## Figures", ""]
    for file, caption in module.FIGURES.items():
        if (folder / file).exists():
            page += [f"![{caption}]({file})", "", f"*{caption}*", ""]
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "README.md").write_text("\n".join(page))
    return summary


_SUMMARY = re.compile(r"^(\d+ of \d+ comparable (?:stated numbers|expected trends) agree "
                      r"within their tolerance \(\d+ stated\))\.$", re.MULTILINE)


def _summary(page: Path) -> str | None:
    """The summary :func:`write_page` wrote on ``page``, None where there is no such page."""
    found = _SUMMARY.search(page.read_text()) if page.is_file() else None
    return found.group(1) if found else None


def agreement(claim: dict, value):
    """Whether ``value`` (a number, or an array of them: one per sample) agrees with the
    stated number ``claim`` (a ``[[claim]]`` of claims.toml: its ``paper`` value, or for a
    study beyond the papers its ``expected`` one) within its tolerance."""
    paper = claim.get("paper", claim.get("expected"))
    tolerance = claim.get("tolerance", 0.0)
    value = np.asarray(value)
    comparison = claim.get("comparison", "within")
    if comparison == "at_most":
        return value <= paper + tolerance
    if comparison == "at_least":
        return value >= paper - tolerance
    return np.abs(value - paper) <= tolerance


def _claim_rows(claims: list[dict], ours: dict, column: str = "paper"
                ) -> tuple[list[str], int, int]:
    """Table rows, and how many claims agree and how many could be compared with the value in
    ``column`` (the paper's, or the expected one)."""
    rows, agreeing, comparable = [], 0, 0
    whose = "the paper's" if column == "paper" else f"the {column} value"
    for claim in claims:
        value = ours.get(claim["id"])
        unit = claim.get("unit", "")
        paper = claim.get("paper", claim.get("expected"))  # a study beyond the papers: expected
        digits = claim.get("digits", 3)  # significant digits shown
        if value is None or paper is None:
            shown, verdict = "not computed" if value is None else f"{value:.{digits}g} {unit}", \
                "not comparable"
        else:
            tolerance = claim.get("tolerance", 0.0)
            comparison = claim.get("comparison", "within")
            agrees = bool(agreement(claim, value))
            agreeing += agrees
            comparable += 1
            shown = f"{value:.{digits}g} {unit}"
            band = {"within": f"within {tolerance:g} {unit}", "at_most": f"at most {whose}",
                    "at_least": f"at least {whose}"}[comparison]
            verdict = (f"agrees ({band})" if agrees
                       else f"differs: ours - {column} = {value - paper:+.3g} {unit}")
        paper_text = "—" if paper is None else f"{paper:g} {unit}"
        rows.append(f"| {claim['statement']} | {claim.get('source', '')} | {paper_text} | "
                    f"{shown} | {verdict} | {claim.get('assumptions', '')} |")
    return rows, agreeing, comparable
