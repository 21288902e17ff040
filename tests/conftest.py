import textwrap

import numpy as np
import pytest

MM = 1e-3
RPM = 2.0 * np.pi / 60.0

#: Bearing D of paper 000 (Table 4) in SI, for model-level tests.
BEARING_D = dict(roller_count=14, pitch_diameter=65 * MM, roller_diameter=10 * MM,
                 effective_length=9.6 * MM)


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
    import subprocess
    import sys

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
