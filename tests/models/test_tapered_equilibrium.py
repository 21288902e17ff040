"""trb_load's compiled equilibrium: the same numbers interpreted, in any block, and for a small
sweep without numba."""
import dataclasses
import importlib
import sys

import numpy as np

from bearing_sweep import spec
from bearing_sweep.evaluate import evaluate_chunk
from bearing_sweep.grid import Grid
from bearing_sweep.models import tapered
from bearing_sweep.models.kernels import Kernels
from bearing_sweep.models.registry import (CONVERGED, INFEASIBLE, NOT_CONVERGED,
                                           OUT_OF_VALIDITY)

MM = 1e-3
COMPILED = "bearing_sweep.models.tapered_equilibrium"


def _points(count, seed):
    rng = np.random.default_rng(seed)
    points = dict(radial_load=rng.uniform(0.0, 40e3, count),
                  axial_load=rng.uniform(100.0, 80e3, count),
                  effective_length=rng.uniform(10.0, 30.0, count) * MM,
                  roller_mean_diameter=rng.uniform(5.0, 15.0, count) * MM,
                  outer_contact_angle=np.radians(rng.uniform(5.0, 40.0, count)),
                  pitch_diameter=rng.uniform(60.0, 120.0, count) * MM, dynamic_load_rating=1e5)
    points["radial_load"][:2] = 0.0, np.nan  # pure axial; a NaN input
    points["axial_load"][2] = 0.0  # infeasible
    return points


def test_the_interpreted_equilibrium_gives_the_compiled_ones_bits(monkeypatch):
    # A small sweep runs the equilibrium's source uncompiled (no numba to load): its numbers
    # must be the compiled ones to the bit, or results would depend on the sweep's size.
    compiled = importlib.import_module(COMPILED)
    interpreted = tapered._EQUILIBRIUM.interpreted()
    assert interpreted is not compiled and interpreted.INTERPRETED
    points = _points(40, 3)
    statuses = set()
    for rollers, iterations in ((17, 200), (5, 200), (23, 3)):  # 3: points that do not converge
        monkeypatch.setattr(tapered, "_MAX_ITERATIONS", iterations)
        results = []
        for module in (compiled, interpreted):
            monkeypatch.setattr(tapered, "_kernels", lambda points, module=module: module)
            results.append(tapered.trb_load(roller_count=rollers, **points))
        statuses |= set(np.unique(results[0]["status"]).tolist())
        for name, values in results[0].items():
            assert values.tobytes() == results[1][name].tobytes(), (rollers, name)
    assert statuses >= {CONVERGED, NOT_CONVERGED, INFEASIBLE}  # failures are compared too


def test_a_point_has_its_own_bits_whatever_the_block():
    # The engine calls the model in blocks of points_per_call: each point is solved alone, so
    # its numbers do not depend on the block's size or on the points it shares it with.
    definition = ('[sweep]\nmodel = "trb_load"\nbearing = "paper003-table1"\n[axes]\n'
                  'radial_load = { start = "0 kN", stop = "40 kN", num = 9 }\n'
                  'axial_load = { start = "27 kN", stop = "400 kN", num = 7 }\n')
    grid = Grid.from_sweep(spec.parse(definition, "blocks.toml"))
    results = []
    for block in (1, 5, 64, 4096):
        model = dataclasses.replace(grid.model, points_per_call=block)
        results.append(evaluate_chunk(dataclasses.replace(grid, model=model), 0, grid.size))
    assert set(np.unique(results[0]["status"])) == {CONVERGED, OUT_OF_VALIDITY}
    for result in results[1:]:
        assert result["status"].tobytes() == results[0]["status"].tobytes()
        for name, values in result["outputs"].items():
            assert values.tobytes() == results[0]["outputs"][name].tobytes(), name


def test_no_axial_load_is_infeasible_not_an_error():
    # Called directly (the engine refuses it): the unloaded start has no stiffness and no
    # damping, which stopped the whole block with a singular matrix before.
    result = tapered.trb_load(radial_load=[1e3, 1e3], axial_load=[0.0, 2e4], roller_count=17,
                              effective_length=20 * MM, roller_mean_diameter=10 * MM,
                              outer_contact_angle=np.radians(15.0))
    assert list(result["status"]) == [INFEASIBLE, CONVERGED]
    assert np.isnan(result["axial_displacement"][0]) and result["axial_displacement"][1] > 0


def test_the_interpreted_module_serves_the_first_points_only(monkeypatch):
    monkeypatch.delitem(sys.modules, COMPILED, raising=False)
    kernels = Kernels(COMPILED, 10)
    assert kernels.for_points(6).INTERPRETED
    compiled = kernels.for_points(6)  # 12 > 10: compiled from now on
    assert not hasattr(compiled, "INTERPRETED") and compiled.__name__ == COMPILED
    assert kernels.for_points(1) is compiled


def test_a_small_trb_sweep_does_not_load_numba(run_loads_numba):
    # Start-up: importing numba and loading the compiled equilibrium costs about 0.3 s, more
    # than a hundred points take uncompiled.
    assert not run_loads_numba('[sweep]\nmodel = "trb_load"\nbearing = "paper003-table1"\n'
                               '[axes]\nradial_load = { start = "5 kN", stop = "40 kN", '
                               'num = 10 }\n'
                               'axial_load = { start = "27 kN", stop = "80 kN", num = 10 }\n')
