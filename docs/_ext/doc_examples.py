"""Run the code examples of the documentation's pages, as a reader would in one folder.

The pages are read in order and their fenced blocks acted on in order, all in one folder, so that
a page can use what an earlier one made (``results/example.nc`` of Getting started):

- a ``toml`` block right after a line naming a file (```` `example.toml`: ````), or any block
  whose first line is a comment naming a path (``# my_bearings/springs.py``), is written to that
  file; any other ``toml`` block must parse as TOML;
- a ``console`` block's ``$ `` lines are run by the shell, with the ``bearing-sweep`` of this
  Python first on the ``PATH``; the lines shown under a command must appear in what it prints
  (``...`` in a line stands for anything), and it must succeed unless what is shown of it
  begins with ``error:``;
- a ``python`` block runs in the page's namespace (one per page), in the folder, and must
  not warn;
- ``sh`` and ``bash`` blocks (installation, a cluster's own processes) and directive blocks
  (```` ```{code-block} ````) are shown, not run.

A plug-in example (a ``pyproject.toml`` file block with entry points) is made importable as
its install would make it: its folder on ``PYTHONPATH`` and a ``*.dist-info`` naming its entry
points beside its modules.
"""
from __future__ import annotations

import contextlib
import io
import os
import re
import subprocess
import sys
import tomllib
import warnings
from dataclasses import dataclass
from pathlib import Path

FENCE = re.compile(r"^```(?P<language>[^\n`]*)\n(?P<body>.*?)^```[ \t]*$", re.M | re.S)
NAMED_FILE = re.compile(r"^`(?P<path>[\w./-]+)`:\s*$")
PATH_COMMENT = re.compile(r"^# (?P<path>[\w-]+(?:/[\w-]+)*\.(?:py|toml))\s*$")


class ExampleFailed(Exception):
    """An example of a page did not run as the page shows it."""


@dataclass(frozen=True)
class Block:
    page: str
    line: int
    language: str
    body: str
    file: str | None


def blocks(page: str, text: str) -> list[Block]:
    """The fenced blocks of a page's Markdown ``text``, with the file each one is, if any."""
    found = []
    for match in FENCE.finditer(text):
        body = match.group("body")
        before = text[:match.start()].rstrip("\n").rsplit("\n", 1)[-1]
        named = NAMED_FILE.match(before) or PATH_COMMENT.match(body.split("\n", 1)[0])
        found.append(Block(page, text.count("\n", 0, match.start()) + 1,
                           match.group("language").strip(), body,
                           named.group("path") if named else None))
    return found


def _matches(shown: str, printed: list[str]) -> bool:
    pattern = ".*".join(re.escape(part.strip()) for part in shown.split("..."))
    return any(re.search(pattern, line) for line in printed)


def write_distribution_info(folder: Path, pyproject: str) -> Path:
    """The ``*.dist-info`` an install of ``pyproject`` would write into ``folder``: its name,
    version and entry points, which ``importlib.metadata`` finds on ``sys.path``."""
    project = tomllib.loads(pyproject)["project"]
    info = folder / f"{project['name'].replace('-', '_')}-{project['version']}.dist-info"
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {project['name']}\n"
                                   f"Version: {project['version']}\n")
    (info / "entry_points.txt").write_text("".join(
        f"[{group}]\n" + "".join(f"{name} = {value}\n" for name, value in entries.items())
        for group, entries in project.get("entry-points", {}).items()))
    return info


def _install_plugin(folder: Path, pyproject: str, environment: dict[str, str]) -> None:
    """Make the package described by ``pyproject`` (its modules already in ``folder``)
    importable and its entry points found, as ``pip install`` would."""
    write_distribution_info(folder, pyproject)
    environment["PYTHONPATH"] = os.pathsep.join(
        filter(None, [str(folder), environment.get("PYTHONPATH")]))


def _run_console(block: Block, folder: Path, environment: dict[str, str]) -> None:
    commands: list[tuple[str, list[str]]] = []
    for line in block.body.splitlines():
        if line.startswith("$ "):
            commands.append((line[2:], []))
        elif commands and line.strip():
            commands[-1][1].append(line)
    for command, shown in commands:
        done = subprocess.run(command, shell=True, cwd=folder, env=environment,
                              capture_output=True, text=True, timeout=900)
        printed = done.stdout.splitlines() + done.stderr.splitlines()
        expect_failure = bool(shown) and shown[0].startswith("error:")
        if (done.returncode != 0) != expect_failure:
            raise ExampleFailed(f"{block.page}:{block.line}: `{command}` exited with "
                                f"{done.returncode}: {' / '.join(printed[-5:])}")
        for line in shown:
            if not _matches(line, printed):
                raise ExampleFailed(f"{block.page}:{block.line}: `{command}` did not print "
                                    f"{line.strip()!r}; it printed: {' / '.join(printed[-8:])}")


def _run_python(block: Block, folder: Path, namespace: dict) -> None:
    output = io.StringIO()
    here = Path.cwd()
    try:
        os.chdir(folder)
        with contextlib.redirect_stdout(output), warnings.catch_warnings(record=True) as shown:
            warnings.simplefilter("always")
            exec(compile(block.body, f"{block.page}:{block.line}", "exec"), namespace)
    except Exception as failure:
        raise ExampleFailed(f"{block.page}:{block.line}: {type(failure).__name__}: "
                            f"{failure}") from failure
    finally:
        os.chdir(here)
    if shown:
        warning = shown[0]
        raise ExampleFailed(f"{block.page}:{block.line}: warns: {warning.category.__name__}: "
                            f"{warning.message}")


def run_page(page: str, text: str, folder: Path, environment: dict[str, str] | None = None
             ) -> int:
    """Run the examples of one page in ``folder``; return how many blocks ran or were
    written. Raises :class:`ExampleFailed` at the first that does not run as shown."""
    if environment is None:
        environment = dict(os.environ)
        environment["PATH"] = os.pathsep.join([str(Path(sys.executable).parent),
                                               environment.get("PATH", "")])
        environment.setdefault("MPLBACKEND", "Agg")
    namespace: dict = {"__name__": "__example__"}
    count = 0
    for block in blocks(page, text):
        if block.file is not None:
            target = folder / block.file
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(block.body)
            if block.file.endswith(".py") and not (target.parent / "__init__.py").exists() \
                    and target.parent != folder:
                (target.parent / "__init__.py").write_text("")
            if Path(block.file).name == "pyproject.toml":
                _install_plugin(folder, block.body, environment)
        elif block.language == "toml":
            try:
                tomllib.loads(block.body)
            except tomllib.TOMLDecodeError as failure:
                raise ExampleFailed(f"{block.page}:{block.line}: not TOML: {failure}") from None
        elif block.language == "console":
            _run_console(block, folder, environment)
        elif block.language == "python":
            _run_python(block, folder, namespace)
        else:
            continue
        count += 1
    return count
