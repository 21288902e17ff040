"""What several test modules share, as fixtures: bearing D, sweep definitions, the command
line, toy models, the checks of a refusal and of CF labels, the figures
a test saved. Test modules import no other test module (pytest imports each by its path)."""
import importlib.util
import math
import os
import signal
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

#: The models' compiled code in the tests: the checkout's build folder, not the machine's cache
#: (``models/compiled_cache.py``); set before any model is imported, for the processes the
#: tests start too.
os.environ["BEARING_SWEEP_CACHE"] = str(Path(__file__).parent.parent / "build" / "compiled")

MM = 1e-3
#: The tests' own definitions and files.
DATA = Path(__file__).parent / "data"

#: Bearing D of paper 000 (Table 4) in SI, for model-level tests.
BEARING_D = dict(roller_count=14, pitch_diameter=65 * MM, roller_diameter=10 * MM,
                 effective_length=9.6 * MM)


@pytest.fixture(scope="session", autouse=True)
def ctrl_c_as_a_terminal_sends_it():
    """Ctrl-C raises KeyboardInterrupt in the tests and in the processes they start, as for a
    user at a terminal, also where the suite itself was started in the background: a shell
    starts a background command with SIGINT ignored, which Python and every child keep."""
    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)  # children: the default
    yield


#: The models whose kernels numba compiles at their first call, and the module of kernels
#: that a small sweep runs interpreted unless it is loaded (``models.kernels``): the costliest
#: to compile first.
COMPILED = [("cage_dynamics_6dof", None), ("trb_load", "tapered_equilibrium"),
            ("ball_5dof", "ball_equilibrium"), ("cage_slip", None), ("crb_radial", None),
            ("cage_dynamics", None), ("crb_runout", "runout_envelope")]


@pytest.fixture(scope="session", autouse=True)
def kernels_compiled_once(tmp_path_factory):
    """In a fresh checkout numba compiles a model's kernels at their first call and keeps them
    (``BEARING_SWEEP_CACHE``, above); the two processes of ``make test`` would each compile
    those they start on at once. Each takes the models in another order, under a lock per model in the run's
    temporary root (which its processes share): the first to take one compiles its kernels,
    the other then loads them."""
    worker = os.environ.get("PYTEST_XDIST_WORKER")
    if worker is None:  # one process: each compiled where it is first used
        yield
        return
    import importlib

    from filelock import FileLock

    from bearing_sweep import spec
    from bearing_sweep.compute import Executor, run_sweep

    root = tmp_path_factory.getbasetemp().parent
    order = COMPILED if worker == "gw0" else COMPILED[::-1]
    folder = _every_model_folder(tmp_path_factory)
    with Executor(workers=0) as executor:
        for model, kernels in order:
            with FileLock(root / f"compiling-{model}.lock"):
                if kernels:
                    importlib.import_module(f"bearing_sweep.models.{kernels}")
                run_sweep(spec.load(DATA / "every_model" / f"{model}.toml"),
                          folder / f"{model}.nc", executor, progress=False)
    yield


def _every_model_folder(tmp_path_factory) -> Path:
    """This process' folder of each model's result of ``tests/data/every_model``."""
    folder = tmp_path_factory.getbasetemp() / "every_model_files"
    folder.mkdir(exist_ok=True)
    return folder


@pytest.fixture(scope="session")
def every_model_files(tmp_path_factory, kernels_compiled_once) -> dict:
    """Each model's definition in ``tests/data/every_model`` computed once in this process,
    whole, into netCDF: its path by model (the compiled models' were written as their
    kernels compiled). For reading only."""
    from bearing_sweep import spec
    from bearing_sweep.compute import Executor, run_sweep

    folder = _every_model_folder(tmp_path_factory)
    with Executor(workers=0) as executor:
        for definition in sorted((DATA / "every_model").glob("*.toml")):
            if not (folder / f"{definition.stem}.nc").exists():
                run_sweep(spec.load(definition), folder / f"{definition.stem}.nc", executor,
                          progress=False)
    return {path.stem: path for path in sorted(folder.glob("*.nc"))}


@pytest.hookimpl(tryfirst=True)  # before pytest-xdist reads the groups
def pytest_collection_modifyitems(items):
    """``make test`` shares the tests between two processes (pytest-xdist, ``--dist
    loadgroup``): each module's tests in one of them, so that a module's fixtures run once,
    but each study's apart, the studies being the longest runs."""
    for item in items:
        group = item.nodeid.split("::")[0]
        params = getattr(item, "callspec", None)
        if "run_study" in item.fixturenames:
            group += "::" + params.params["name"]
        elif "short_3d_results" in item.fixturenames:
            group += "::cage_dynamics_3d"
        item.add_marker(pytest.mark.xdist_group(group))


@pytest.fixture(scope="session")
def bearing_d() -> dict:
    """Bearing D of paper 000 (Table 4) in SI: the crb_radial inputs roller_count,
    pitch_diameter, roller_diameter and effective_length."""
    return BEARING_D


@pytest.fixture
def definition(tmp_path):
    """Write a sweep definition (dedented TOML) and return its path."""

    def write(text: str, name: str = "sweep.toml"):
        path = tmp_path / name
        path.write_text(textwrap.dedent(text))
        return path

    return write


@pytest.fixture
def run_loads_numba(tmp_path):
    """Run a sweep definition (TOML text) with the CLI in a new process and say whether that
    process loaded numba."""
    def run(text: str) -> bool:
        (tmp_path / "d.toml").write_text(text)
        script = ("import sys\nfrom bearing_sweep import cli\n"
                  "cli.main(['run', 'd.toml', '-o', 'd.nc'])\n"
                  "print('numba' in sys.modules)\n")
        done = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True,
                              text=True, timeout=120)
        assert done.returncode == 0, done.stderr
        return done.stdout.strip().splitlines()[-1] == "True"

    return run


@pytest.fixture
def paper_slice_law_fails(monkeypatch):
    """crb_radial raises for every point with ``slice_law = "paper"`` (a model_error there)."""
    import bearing_sweep.models.registry as registry

    model = registry.get_model("crb_radial")
    original = model.function

    def fragile(**kwargs):
        if kwargs["slice_law"] == "paper":
            raise RuntimeError("simulated failure")
        return original(**kwargs)

    monkeypatch.setitem(registry._MODELS, "crb_radial",
                        registry.Model(**{**model.__dict__, "function": fragile}))


# -- definitions and the command line ------------------------------------------------------------

#: A four-point crb_radial sweep of bearing D of paper 000: two loads by two speeds.
FOUR_POINTS = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "0.004 mm"
[axes]
radial_load = ["2 kN", "4 kN"]
speed = { values = [0, 5000], units = "rpm" }
"""


@pytest.fixture(scope="session")
def four_points() -> str:
    """A four-point crb_radial sweep definition (TOML text): two loads by two speeds."""
    return FOUR_POINTS


def _run_command(*arguments, cwd, timeout=300, **settings) -> subprocess.CompletedProcess:
    """``bearing-sweep *arguments`` in a new process started in ``cwd``, as a user runs it;
    the finished process with its output as text."""
    return subprocess.run([sys.executable, "-m", "bearing_sweep", *map(str, arguments)], cwd=cwd,
                          capture_output=True, text=True, timeout=timeout, **settings)


def _starts_processes(arguments) -> bool:
    """Whether the command may start a cluster, whose workers' logs and processes are the
    operating system's to see."""
    words = list(map(str, arguments))
    if "--scheduler" in words:
        return True
    if words[0] not in ("run", "study"):
        return False
    return "--workers" not in words or words[words.index("--workers") + 1] != "0"


def _run_cli(*arguments, cwd, timeout=300, **settings) -> subprocess.CompletedProcess:
    """``bearing-sweep *arguments`` run from ``cwd``, its exit code and output as a finished
    process's: in this process (the program's ``main``: what it prints, the warnings it
    shows and its exit code, argparse's included), or in a new one where ``settings`` set
    up that process or the command may start a cluster."""
    if settings or _starts_processes(arguments):
        return _run_command(*arguments, cwd=cwd, timeout=timeout, **settings)
    import contextlib
    import io
    import os
    import warnings

    from bearing_sweep import cli

    out, err, before = io.StringIO(), io.StringIO(), os.getcwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), \
                warnings.catch_warnings(record=True) as shown:
            warnings.simplefilter("default")  # as a new process shows them
            try:
                code = cli.main(list(map(str, arguments)))
            except SystemExit as stop:  # argparse's refusals and --help
                code = stop.code if isinstance(stop.code, int) else int(stop.code is not None)
        for warning in shown:
            err.write(warnings.formatwarning(warning.message, warning.category,
                                             warning.filename, warning.lineno))
    finally:
        os.chdir(before)
    return subprocess.CompletedProcess(["bearing-sweep", *map(str, arguments)], code,
                                       out.getvalue(), err.getvalue())


@pytest.fixture(scope="session")
def run_cli():
    """``run_cli(*arguments, cwd=folder, timeout=300, env=..., ...)``: ``bearing-sweep
    *arguments`` run in ``folder`` (a test's own), a ``CompletedProcess`` (:func:`_run_cli`:
    in this process unless it needs one of its own)."""
    return _run_cli


@pytest.fixture(scope="session")
def docs_module():
    """``docs_module(name)``: a module of the documentation's build (``docs/_ext/name.py``),
    loaded from its file: the build is no package."""
    def load(name):
        if f"docs_{name}" not in sys.modules:
            spec = importlib.util.spec_from_file_location(
                f"docs_{name}", Path(__file__).resolve().parents[1] / "docs" / "_ext"
                / f"{name}.py")
            module = importlib.util.module_from_spec(spec)
            sys.modules[spec.name] = module  # a dataclass looks its module up there
            spec.loader.exec_module(module)
        return sys.modules[f"docs_{name}"]
    return load


@pytest.fixture(scope="session")
def run_command():
    """``run_command(*arguments, cwd=folder, timeout=300, ...)``: ``bearing-sweep *arguments``
    in a new process in ``folder``, as a user's shell starts it, its ``CompletedProcess``."""
    return _run_command


def _assert_cf_labelled(data):
    """Every variable has a short long_name and units UDUNITS reads (or says why not), and
    the dataset quantifies with pint-xarray."""
    import cf_units
    import pint_xarray  # noqa: F401  (registers the .pint accessor)

    for variable_name, variable in {**data.coords, **data.data_vars}.items():
        attrs = variable.attrs
        assert 0 < len(attrs["long_name"]) <= 48, (variable_name, attrs["long_name"])
        if "units" in attrs:
            cf_units.Unit(attrs["units"])  # UDUNITS reads it
            assert variable.dtype.kind not in "OUS", variable_name
        elif variable.dtype.kind not in "OUS" and "flag_meanings" not in attrs:  # CF flags
            # numbers without units: an entry-unit output, or a unit UDUNITS cannot express
            assert ("ancillary_variables" in attrs
                    or "fractional powers" in attrs.get("comment", "")), variable_name
    quantified = data.pint.quantify()
    for variable_name, variable in data.data_vars.items():
        if "units" in variable.attrs:
            assert hasattr(quantified[variable_name].data, "units"), variable_name


@pytest.fixture(scope="session")
def assert_cf_labelled():
    """``assert_cf_labelled(dataset)``: every variable has a short long_name and units UDUNITS
    reads (or says why not), and the dataset quantifies with pint-xarray."""
    return _assert_cf_labelled


# -- toy models: outputs on fewer axes than the grid ----------------------------------------------

def _toy(a, b, c=2.0):
    """``total = a + b + c`` everywhere; ``product = b c``; a point fails where a or b is
    negative (the model leaves its values there, the engine makes them NaN)."""
    from bearing_sweep.models.registry import CONVERGED, INFEASIBLE

    a, b, c = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (a, b, c)))
    failed = (a < 0) | (b < 0)
    return {"total": a + b + c, "product": b * c, "whole_b": np.rint(b),
            "status": np.where(failed, INFEASIBLE, CONVERGED).astype(np.int8)}


def _liar(a, b, c=2.0):
    """Says ``product`` depends on b and c only, but adds a."""
    result = _toy(a, b, c)
    result["product"] = result["product"] + a
    return result


def _toy_declaration(name, function=_toy):
    from bearing_sweep.models.registry import Input, Model, Output

    return Model(name, function, "a test model", "none", "1",
                 (Input("a", "1", "a", kind="number"), Input("b", "1", "b", kind="number"),
                  Input("c", "1", "c", kind="number", default=2.0)),
                 (Output("total", "1", "a + b + c"),
                  Output("product", "1", "b c", depends_on=("b", "c")),
                  Output("whole_b", "1", "b rounded", dtype="int", depends_on=("b",))))


@pytest.fixture
def toy_model():
    """``toy_model(name, function=toy's)``: the toy declaration (inputs a, b, c; ``product``
    on b and c only, ``whole_b`` on b only) of ``function``, not registered."""
    return _toy_declaration


@pytest.fixture
def toy(monkeypatch):
    """Models ``toy`` (``_toy``) and ``liar`` (declares ``product`` on b and c, adds a)
    registered for one test; the definition of a 3 x 4 grid of ``toy`` whose first row
    (a = -1) and first column (b = -2) fail."""
    import bearing_sweep.models.registry as registry

    registry.all_models()  # ours first, then the test models
    for model in (_toy_declaration("toy", _toy), _toy_declaration("liar", _liar)):
        monkeypatch.setitem(registry._MODELS, model.name, model)
    return '[sweep]\nmodel = "toy"\n[axes]\na = [-1, 1, 2]\nb = [-2, 1, 2, 3]\n'


# -- the Ishigami function: a sensitivity analysis with known indices -----------------------------

def _ishigami(x1, x2, x3, a=7.0):
    """Ishigami & Homma's test function, b = 0.1 (IEEE ISUMA 1990,
    doi:10.1109/ISUMA.1990.151285)."""
    x1, x2, x3 = np.broadcast_arrays(x1, x2, x3)
    y = np.sin(x1) + a * np.sin(x2) ** 2 + 0.1 * x3 ** 4 * np.sin(x1)
    return {"y": y, "status": np.zeros(y.shape, dtype=np.int8)}


@pytest.fixture
def ishigami_model(monkeypatch):
    """The Ishigami function registered as model ``ishigami`` (inputs x1, x2, x3, a) for one
    test."""
    import bearing_sweep.models.registry as registry
    from bearing_sweep.models.registry import Input, Model, Output

    registry.all_models()  # ours first, then the toy
    model = Model("ishigami", _ishigami, "Ishigami function", "Ishigami & Homma 1990", "1",
                  tuple(Input(x, "1", x, kind="number") for x in ("x1", "x2", "x3"))
                  + (Input("a", "1", "a", default=7.0, kind="number"),),
                  (Output("y", "1", "y"),), seconds_per_point=1e-8)
    monkeypatch.setitem(registry._MODELS, model.name, model)
    return model


def _ishigami_indices(a, b=0.1):
    """Analytic first-order and total indices of the Ishigami function on [-pi, pi]^3
    (Homma & Saltelli, Reliab. Eng. Syst. Saf. 52(1), 1-17, 1996,
    doi:10.1016/0951-8320(96)00002-6)."""
    pi = math.pi
    v1 = 0.5 * (1 + b * pi**4 / 5) ** 2
    v2 = a**2 / 8
    v13 = b**2 * pi**8 * (1 / 18 - 1 / 50)
    variance = v1 + v2 + v13
    return [v1 / variance, v2 / variance, 0.0], [(v1 + v13) / variance, v2 / variance,
                                                  v13 / variance]


@pytest.fixture(scope="session")
def ishigami_indices():
    """``ishigami_indices(a, b=0.1)``: the analytic (first-order, total) Sobol' indices of the
    Ishigami function, each a list over x1, x2, x3."""
    return _ishigami_indices


@pytest.fixture
def ishigami_sweep(ishigami_model):
    """``ishigami_sweep(n, seed)``: a Saltelli design of ``n`` base samples of the Ishigami
    function on [-pi, pi]^3 at a = 7 and 5, computed in this process (an xarray Dataset)."""
    import bearing_sweep

    def sweep(n: int, seed: int):
        uniform = ('{ distribution = "uniform", low = -3.141592653589793, '
                   'high = 3.141592653589793 }')
        return bearing_sweep.run(f"""
[sweep]
model = "ishigami"
[axes]
a = [7, 5]
[sample]
n = {n}
method = "saltelli"
seed = {seed}
x1 = {uniform}
x2 = {uniform}
x3 = {uniform}
""", workers=0, progress=False)

    return sweep


# -- refusals: before any computing, with nothing written -----------------------------------------

def _tree(folder):
    """Every path under ``folder`` with its kind and size: what a refusal must leave as it was."""
    return {str(p.relative_to(folder)): (stat.S_IFMT(p.lstat().st_mode), p.lstat().st_size)
            for p in folder.rglob("*")}


@pytest.fixture(scope="session")
def tree():
    """``tree(folder)``: every path under ``folder`` with its kind and size."""
    return _tree


@pytest.fixture
def no_computing(monkeypatch):
    """A refusal must come before the lock, the parts and the model."""

    def computed(*args, **kwargs):
        raise AssertionError("computing started before the output was checked")

    monkeypatch.setattr("bearing_sweep.stores.base.OutputLock", computed)
    monkeypatch.setattr("bearing_sweep.evaluate.evaluate_chunk", computed)


@pytest.fixture
def refused(tmp_path, capsys):
    """``refused(output, definition=tmp_path / "def.toml")``: ``bearing-sweep run definition -o
    output`` in this process must be refused in one line, exit status 2, with nothing in
    tmp_path written or replaced; its error line. A missing definition is written first (the
    four-point sweep)."""
    from bearing_sweep import cli

    def run(output, definition=None):
        definition = definition or tmp_path / "def.toml"
        if not definition.exists():
            definition.write_text(FOUR_POINTS)
        before = _tree(tmp_path)
        code = cli.main(["run", str(definition), "-o", str(output), "--workers", "0",
                         "--quiet"])
        err = capsys.readouterr().err
        assert code == 2, err
        assert err.startswith("error: ") and len(err.strip().splitlines()) == 1, err
        assert _tree(tmp_path) == before  # nothing written, nothing replaced
        return err

    return run


@pytest.fixture(scope="session")
def start_cli():
    """``start_cli(*arguments, cwd=folder, **settings)``: ``bearing-sweep *arguments`` started
    in a new process in ``folder``, not waited for (to be interrupted); its ``Popen``, output
    piped as text."""

    def start(*arguments, cwd, **settings) -> subprocess.Popen:
        return subprocess.Popen([sys.executable, "-m", "bearing_sweep", *map(str, arguments)],
                                cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True, **settings)

    return start


@pytest.fixture
def saved_figures(monkeypatch) -> list:
    """The matplotlib Figures saved during the test, in order (each still saved as asked):
    what a figure shows, to compare with the data it was drawn from."""
    from matplotlib.figure import Figure

    saved, original = [], Figure.savefig

    def save(figure, *args, **kwargs):
        saved.append(figure)
        return original(figure, *args, **kwargs)

    monkeypatch.setattr(Figure, "savefig", save)
    return saved
