"""The models' compiled code is kept once per machine, a folder for each version of their
source (``models/compiled_cache.py``): another checkout of the same source loads it, a changed
source compiles afresh, and functions outside the models are cached where numba keeps them."""
import ast
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from bearing_sweep.models import compiled_cache

MODELS = Path(compiled_cache.__file__).parent


def checkout(folder: Path) -> Path:
    """A copy of the models' source as the package ``models_copy`` under ``folder``."""
    copy = folder / "models_copy"
    shutil.copytree(MODELS, copy, ignore=shutil.ignore_patterns("__pycache__"))
    return copy


def first_call(package: Path, cache: str | None):
    """Call a compiled model function in a new process importing ``package``, with
    ``BEARING_SWEEP_CACHE`` = ``cache`` (unset for None): numba's cache folder for it, and
    whether the call loaded it from there (else it compiled)."""
    script = (f"import sys; sys.path.insert(0, {str(package.parent)!r})\n"
              f"from {package.name} import contact_laws as laws\n"
              "laws.traction_coefficient(1.0, 0.1, 0.2, 0.3, 0.4)\n"
              "stats = laws.traction_coefficient.stats\n"
              "print(stats.cache_path, sum(stats.cache_hits.values()),"
              " sum(stats.cache_misses.values()))\n")
    environment = {k: v for k, v in os.environ.items()
                   if k not in ("BEARING_SWEEP_CACHE", "NUMBA_CACHE_DIR")}
    if cache is not None:
        environment["BEARING_SWEEP_CACHE"] = cache
    environment["XDG_CACHE_HOME"] = str(package.parent / "home_cache")
    finished = subprocess.run([sys.executable, "-c", script], env=environment,
                              capture_output=True, text=True, check=True)
    path, hits, misses = finished.stdout.split()
    assert int(hits) + int(misses) == 1
    return Path(path), int(hits) == 1


def test_another_checkout_of_the_same_source_loads_what_one_compiled(tmp_path):
    cache = tmp_path / "machine"
    one, other = checkout(tmp_path / "one"), checkout(tmp_path / "other")
    folder, loaded = first_call(one, str(cache))
    assert folder.parent == cache / "numba" and not loaded
    assert first_call(other, str(cache)) == (folder, True)
    # a change to any of the models' files is another version: compiled afresh, elsewhere
    with open(other / "runout.py", "a") as source:
        source.write("\n# changed\n")
    changed, loaded = first_call(other, str(cache))
    assert changed.parent == cache / "numba" and changed != folder and not loaded
    assert first_call(one, str(cache)) == (folder, True)


def test_the_machine_cache_by_default_and_numbas_own_place_when_asked(tmp_path):
    one = checkout(tmp_path / "one")
    folder, _ = first_call(one, None)
    assert folder.parent == tmp_path / "one" / "home_cache" / "bearing-sweep" / "numba"
    beside, loaded = first_call(checkout(tmp_path / "two"), "")
    assert beside == tmp_path / "two" / "models_copy" / "__pycache__" and not loaded


def test_other_functions_are_cached_where_numba_keeps_them(tmp_path):
    # The models' locator registered, a function of another file is numba's business.
    (tmp_path / "elsewhere.py").write_text(
        "from numba import njit\n\n@njit(cache=True)\ndef twice(x):\n    return 2 * x\n")
    script = (f"import sys; sys.path.insert(0, {str(tmp_path)!r})\n"
              "from bearing_sweep.models import contact_laws\n"
              "import elsewhere\n"
              "elsewhere.twice(1.0)\n"
              "print(elsewhere.twice.stats.cache_path)\n")
    environment = {**os.environ, "BEARING_SWEEP_CACHE": str(tmp_path / "machine")}
    environment.pop("NUMBA_CACHE_DIR", None)
    finished = subprocess.run([sys.executable, "-c", script], env=environment,
                              capture_output=True, text=True, check=True)
    assert Path(finished.stdout.strip()) == tmp_path / "__pycache__"


def test_the_digest_is_of_the_files_names_and_contents(tmp_path):
    for name in ("a", "b"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "x.py").write_text("x = 1\n")
        (tmp_path / name / "notes.txt").write_text(name)  # not source
    assert compiled_cache.source_digest(tmp_path / "a") == compiled_cache.source_digest(
        tmp_path / "b")
    (tmp_path / "b" / "x.py").write_text("x = 2\n")
    assert compiled_cache.source_digest(tmp_path / "a") != compiled_cache.source_digest(
        tmp_path / "b")
    (tmp_path / "b" / "x.py").rename(tmp_path / "b" / "y.py")
    (tmp_path / "b" / "y.py").write_text("x = 1\n")
    assert compiled_cache.source_digest(tmp_path / "a") != compiled_cache.source_digest(
        tmp_path / "b")


def test_the_newest_versions_are_kept_and_those_used_within_a_day(tmp_path):
    now, day = time.time(), compiled_cache.KEPT_SECONDS
    for name, age in zip("abcdefg", (0, 1, 2, 3, 0.5 * day, 2 * day, 3 * day)):
        (tmp_path / name).mkdir()
        os.utime(tmp_path / name, (now - age, now - age))
    compiled_cache._prune(tmp_path / "a")  # "a" is the one in use
    kept = sorted(p.name for p in tmp_path.iterdir())
    assert compiled_cache.KEPT_VERSIONS == 4 and kept == ["a", "b", "c", "d", "e"]


def test_no_model_is_compiled_with_fastmath():
    # fastmath's fused multiply-adds and reassociated sums round a function compiled into its
    # caller otherwise than the caller's code loaded from the cache (the test below).
    for path in sorted(MODELS.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "njit":
                assert "fastmath" not in [k.arg for k in node.keywords], path.name


@pytest.mark.slow
def test_a_point_computed_while_compiling_equals_one_computed_from_the_cache(tmp_path):
    # The spatial cage model over 1 ms in a process that compiles every function it calls,
    # then in one that loads them: the same bits.
    mm = 1e-3  # the preset paper002-test (paper 002, Tables 2-3) at 800 N, 12000 r/min
    bearing = dict(roller_count=13, inner_raceway_diameter=44 * mm, roller_diameter=10 * mm,
                   roller_length=11 * mm, effective_length=7.2 * mm, clearance=0.02 * mm,
                   cage_inner_diameter=48.5 * mm, cage_outer_diameter=59 * mm,
                   cage_width=13 * mm, pocket_clearance=0.1 * mm)
    # (1 ms is too short a run to settle: its outcome converged, its values flagged)
    script = ("import hashlib\n"
              "from bearing_sweep.models.cage_dynamics_6dof import cage_dynamics_6dof\n"
              "from bearing_sweep.models.registry import outcome\n"
              f"out = cage_dynamics_6dof(800.0, 1256.6, **{bearing!r}, duration=1e-3,"
              " output_interval=1e-4)\n"
              "print(hashlib.sha256(b''.join(out[k].tobytes() for k in sorted(out)))"
              ".hexdigest(), int(outcome(out['status'])[0]))\n")
    environment = {**os.environ, "BEARING_SWEEP_CACHE": str(tmp_path / "machine")}
    environment.pop("NUMBA_CACHE_DIR", None)
    found = [subprocess.run([sys.executable, "-c", script], env=environment, text=True,
                            capture_output=True, check=True).stdout.split() for _ in range(2)]
    assert found[0] == found[1] and found[0][1] == "0"
