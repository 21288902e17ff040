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
