"""The house's rules that docs/architecture.md states: no import cycle, no engine module over
500 lines, models that never import the engine, and no test module importing another."""
import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: Each folder of the package and the import name it is installed under (pyproject.toml).
PACKAGES = {"sweeps": "bearing_sweep", "models": "bearing_sweep.models",
            "studies": "bearing_sweep.studies"}
MOST_ENGINE_LINES = 500


def module_name(path: Path) -> str:
    folder = path.relative_to(ROOT).parts[0]
    parts = list(path.relative_to(ROOT / folder).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join([PACKAGES[folder]] + parts)


def package_modules() -> dict[str, Path]:
    return {module_name(path): path for folder in PACKAGES
            for path in sorted((ROOT / folder).rglob("*.py"))
            if path.parent == ROOT / folder or (path.parent / "__init__.py").exists()}


def imported(path: Path, name: str, known) -> set[str]:
    """The package's modules that the module ``name`` at ``path`` imports, at any depth of
    its code (an import inside a function counts: it closes a cycle all the same)."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")
                anchor = anchor[:len(anchor) - node.level + 1]
                base = ".".join(anchor + ([base] if base else []))
            targets = [base] + [f"{base}.{alias.name}" for alias in node.names]
        else:
            continue
        for target in targets:
            while target and target not in known:
                target = target.rpartition(".")[0]
            if target and target != name:
                found.add(target)
    return found


def cycle(graph: dict) -> list | None:
    """One import cycle of ``graph`` (module -> modules it imports), or None."""
    state = {}

    def visit(node, trail):
        state[node] = "open"
        for following in sorted(graph[node]):
            if state.get(following) == "open":
                return trail[trail.index(following):] + [following]
            if following not in state:
                found = visit(following, trail + [following])
                if found:
                    return found
        state[node] = "done"
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node, [node])
            if found:
                return found
    return None


def import_graph() -> dict:
    modules = package_modules()
    return {name: imported(path, name, modules) for name, path in modules.items()}


def test_no_import_cycle():
    graph = import_graph()
    # A package imports its own modules only to hand names on; its modules may import it.
    graph = {name: {t for t in targets if not name.startswith(t + ".")}
             for name, targets in graph.items()}
    assert cycle(graph) is None


def test_the_cycle_finder_finds_one():
    assert cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert cycle({"a": {"b"}, "b": set()}) is None


def test_the_models_never_import_the_engine():
    for name, targets in import_graph().items():
        if name.startswith("bearing_sweep.models"):
            outside = {t for t in targets if not t.startswith("bearing_sweep.models")
                       and t != "bearing_sweep"}
            assert not outside, f"{name} imports {sorted(outside)}"


@pytest.mark.parametrize("path", sorted((ROOT / "sweeps").rglob("*.py")),
                         ids=lambda path: str(path.relative_to(ROOT)))
def test_no_engine_module_is_over_500_lines(path):
    assert len(path.read_text().splitlines()) <= MOST_ENGINE_LINES


def test_no_test_module_imports_another():
    tests = ROOT / "tests"
    names = {path.stem for path in tests.rglob("test_*.py")}
    for path in sorted(tests.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom):
                targets = [node.module or ""]
            elif isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            else:
                continue
            for target in targets:
                last = target.rpartition(".")[2]
                assert last not in names and not target.startswith("tests"), \
                    f"{path.relative_to(ROOT)} imports {target}"
