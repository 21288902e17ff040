"""The physics imports on its own: any module of ``bearing_sweep.models`` can be used on
arrays without the engine, its units library or its storage and plotting libraries."""
import pkgutil
import subprocess
import sys

import pytest

import bearing_sweep.models

#: What the engine brings and a model never needs: units, labelled arrays, the cluster, the
#: statistics of an analysis, figures.
ENGINE_LIBRARIES = ("pint", "xarray", "dask", "distributed", "scipy.stats", "matplotlib")

MODULES = sorted(info.name for info in pkgutil.iter_modules(bearing_sweep.models.__path__))

CHECK = """
import sys
import bearing_sweep.models.{module}
libraries = {libraries!r}
print(sorted(name for name in sys.modules
             if any(name == library or name.startswith(library + ".") for library in libraries)
             or (name.startswith("bearing_sweep.") and not name.startswith("bearing_sweep.models"))))
"""


def test_every_module_of_the_models_folder_is_checked():
    assert {"cylindrical", "registry", "life", "catalogue"} <= set(MODULES)


@pytest.mark.parametrize("module", MODULES)
def test_a_model_module_loads_neither_the_engine_nor_its_libraries(module):
    # bearing_sweep itself (sweeps/__init__.py) runs first, as for any subpackage: it is
    # lazy and imports nothing of the engine, which the list printed here would show.
    done = subprocess.run([sys.executable, "-c", CHECK.format(module=module,
                                                              libraries=ENGINE_LIBRARIES)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"
