"""Every model's file reads right in the ecosystem's tools: UDUNITS units, pint-xarray, CF
coordinates, plot-friendly labels; and its numbers do not depend on the chunking."""
from pathlib import Path

import cf_units
import netCDF4
import numpy as np
import pint_xarray  # noqa: F401  (registers the .pint accessor)
import pytest

from bearing_sweep.models.registry import all_models
from bearing_sweep import spec, stores, units
from bearing_sweep.stores.netcdf import write_netcdf
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.testing import assert_same_numbers

DEFINITIONS = Path(__file__).parents[1] / "data" / "every_model"
MODELS = sorted(all_models())
#: Besides every model's sweep: a zipped axis with float32 shuffled outputs, a sampled design.
STRUCTURES = sorted((Path(__file__).parents[1] / "data" / "structure").glob("*.toml"))


def test_there_is_a_definition_for_every_model():
    assert sorted(p.stem for p in DEFINITIONS.glob("*.toml")) == MODELS


def _declared_units():
    for model in all_models().values():
        for item in model.inputs + model.outputs:
            for unit in np.ravel(getattr(item, "entry_units", ())).tolist() + [item.unit]:
                if unit and "," not in unit:
                    yield model.name, item.name, unit


@pytest.mark.parametrize("model, name, unit", list(_declared_units()))
def test_every_declared_unit_reads_the_same_in_udunits_as_in_pint(model, name, unit):
    cf = units.cf_units(unit)
    if cf is None:  # no UDUNITS form: stored in SI, said in a comment
        assert units.convert(1.0, units.parse_unit(units.si_text(unit)),
                             units.UREG.get_base_units(units.parse_unit(unit))[1]) == 1.0
        return
    # 2 of the unit in SI base units, by each library
    by_pint = units.to_si(2.0, units.parse_unit(unit))
    base = cf_units.Unit(cf)
    by_udunits = base.convert(2.0, _udunits_si(base))
    assert by_udunits == pytest.approx(float(by_pint), rel=1e-12), (model, name, unit)


def _udunits_si(unit: cf_units.Unit) -> cf_units.Unit:
    """The SI base unit UDUNITS reduces ``unit`` to (radians count as SI)."""
    definition = unit.definition
    return cf_units.Unit(definition.split(" @ ")[0].split(" ", 1)[-1]
                         if definition[0].isdigit() or definition[0] == "-" else definition
                         .split(" @ ")[0])


@pytest.fixture(scope="module")
def runs(tmp_path_factory, every_model_files):
    """Each model's sweep written as it computes, whole and one point per chunk, and
    computed in memory then written by xarray."""
    folder = tmp_path_factory.mktemp("every_model")
    made = {}
    with Executor(workers=0) as executor:
        for definition in [DEFINITIONS / f"{name}.toml" for name in MODELS] + STRUCTURES:
            sweep, name = spec.load(definition), definition.stem
            paths = []
            for chunk in (None, 1):
                if chunk is None and name in every_model_files:  # computed once a session
                    paths.append(every_model_files[name])
                    continue
                paths.append(folder / f"{name}-{chunk}.nc")
                run_sweep(sweep, paths[-1], executor, chunk_size=chunk, progress=False)
            in_memory = run_sweep(sweep, None, executor, progress=False).dataset
            paths.append(write_netcdf(in_memory, folder / f"{name}-xarray.nc"))
            made[name] = paths
    return made


@pytest.fixture(scope="module")
def files(runs):
    """Each model's sweep computed whole and one point per chunk, opened."""
    return {name: [stores.open_result(runs[name][chunk]) for chunk in (0, 1)] for name in MODELS}


@pytest.mark.parametrize("name", MODELS + [p.stem for p in STRUCTURES])
def test_the_file_written_as_chunks_arrive_is_the_one_xarray_writes(runs, name):
    streamed, _, by_xarray = runs[name]
    ours, theirs = netcdf_layout(streamed), netcdf_layout(by_xarray)
    assert ours.keys() == theirs.keys()
    for key in ours:
        assert ours[key] == theirs[key], (name, key)


def netcdf_layout(path) -> dict:
    """What a netCDF file holds, read without xarray, as comparable values: dimensions,
    global attributes (but the time of writing) and each variable's type, dimensions,
    attributes, filters, chunks (outputs' aside: they follow the sweep's chunks) and values,
    all in the file's order."""
    def comparable(value):
        value = np.asarray(value)
        if value.dtype.kind in "OUS":
            return value.dtype.kind, value.tolist()
        return value.dtype.str, value.shape, value.tobytes()

    layout = {}
    with netCDF4.Dataset(path) as data:
        data.set_auto_mask(False)
        layout["dimensions"] = [(n, len(d)) for n, d in data.dimensions.items()]
        layout["attributes"] = [(k, comparable(data.getncattr(k))) for k in data.ncattrs()
                                if k != "history"]
        layout["variables"] = list(data.variables)
        outputs = {o.name for o in all_models()[data.getncattr("model")].outputs} | {"status"}
        for name, variable in data.variables.items():
            layout[name] = (
                str(variable.dtype), variable.dimensions,
                [(k, comparable(variable.getncattr(k))) for k in variable.ncattrs()],
                variable.filters(), None if name in outputs else variable.chunking(),
                comparable(variable[...]))
    return layout


@pytest.mark.parametrize("name", MODELS)
def test_numbers_do_not_depend_on_the_chunking_to_the_last_bit(files, name):
    assert_same_numbers(*files[name], label=name)


@pytest.mark.parametrize("name", MODELS)
def test_every_variable_has_cf_units_labels_and_quantifies_with_pint_xarray(files, name,
                                                                            assert_cf_labelled):
    assert_cf_labelled(files[name][0])


@pytest.mark.parametrize("name", MODELS)
def test_coordinates_carry_no_fill_value_and_fixed_inputs_are_not_coordinates(files, name):
    data = files[name][0]
    assert all(data[c].ndim for c in data.coords), "a scalar coordinate fills plot titles"
    for coordinate in data.coords:
        assert "_FillValue" not in data[coordinate].encoding or \
            data[coordinate].encoding["_FillValue"] is None, coordinate
    for fixed in data.attrs["fixed_inputs"].split():
        assert fixed in data.data_vars


#: For every model, a sweep whose last point lies outside the model's validity (values kept or
#: not) and the other meaning its status must hold there besides ``out_of_validity``: the
#: file shows both, never the other alone.
OUTSIDE_VALIDITY = {
    "ball_5dof": ('bearing = "paper001-71807AC"', 'axial_load = ["1 kN", "300 kN"]',
                  "converged"),
    # the runs span two roller passes (1.3 and 0.94 ms) in their settled halves
    "cage_dynamics": ('bearing = "paper002-test"\n[fixed]\nspeed = "9000 rpm"\n'
                      'duration = "6 ms"\noutput_interval = "0.5 ms"\nradial_load = "800 N"',
                      'pocket_clearance = ["0.1 mm", "0.6 mm"]', "converged"),
    "cage_dynamics_6dof": ('bearing = "paper002-test"\n[fixed]\nspeed = "12000 rpm"\n'
                           'duration = "4 ms"\noutput_interval = "0.5 ms"\n'
                           'radial_load = "800 N"', 'pocket_clearance = ["0.6 mm"]',
                           "converged"),
    "cage_slip": ('bearing = "paper002-test"\n[fixed]\nspeed = "6000 rpm"\n'
                  'pocket_clearance = "0.6 mm"\norbit_points = 12',
                  'radial_load = ["1 N"]', "no_root_in_range"),
    "crb_radial": ('bearing = "paper000-D"\n[fixed]\nradial_load = "4 kN"',
                   'perturbation = ["0.001 mm", "1 m"]', "converged"),
    "crb_runout": ('bearing = "paper004-NU208-1"\n[fixed]\nroller_roundness_order = 2\n'
                   'roller_roundness_amplitude = "0.5 um"\nrevolutions = 1\n'
                   'steps_per_revolution = 360', 'outer_raceway_diameter = ["71.555 mm", '
                   '"80 mm"]', "converged"),
    "hertz_point": ('[fixed]\ncurvature_1x = "0.2 1/mm"\ncurvature_1y = "0.2 1/mm"\n'
                    'curvature_2x = "-0.19 1/mm"', 'load = ["10 N", "1 MN"]', "converged"),
    "shaft_system": ('[shaft]\nsections = [{ length = "200 mm", diameter = "40 mm" }]\n'
                     '[supports.A]\nmodel = "ball_5dof"\nbearing = "paper001-71807AC"\n'
                     'position = "20 mm"\n[supports.B]\nmodel = "spring"\n'
                     'position = "180 mm"\nradial_stiffness = "1e6 N/mm"\n[loads.gear]\n'
                     'position = "100 mm"', '"loads.gear.force_x" = ["1 kN", "300 kN"]',
                     "converged"),
    "trb_load": ('bearing = "paper003-table1"\n[fixed]\nradial_load = "10 kN"',
                 'axial_load = ["27 kN", "5000 kN"]', "converged"),
    "trb_rib": ('bearing = "paper003-table1-rib"\n[fixed]\nrib_angle = "89 deg"',
                'oil_groove_size = ["1 mm", "1 m"]', "no_root_in_range"),
}


def test_every_model_has_a_case_outside_its_validity():
    assert sorted(OUTSIDE_VALIDITY) == MODELS


@pytest.mark.parametrize("name", sorted(OUTSIDE_VALIDITY))
def test_a_point_outside_validity_shows_it_beside_its_other_status(name, tmp_path):
    from bearing_sweep.dependence import flag_holds

    head, axis, other = OUTSIDE_VALIDITY[name]
    sweep = spec.parse(f'[sweep]\nmodel = "{name}"\n{head}\n[axes]\n{axis}\n')
    with Executor(workers=0) as executor:
        run_sweep(sweep, tmp_path / "outside.nc", executor, progress=False)
    status = stores.open_result(tmp_path / "outside.nc")["status"]
    last = status.isel({status.dims[0]: -1})
    assert bool(flag_holds(last, "out_of_validity")), (name, int(last))
    assert bool(flag_holds(last, other)), (name, int(last), other)
    if status.size > 1:  # the ordinary point stays within validity
        assert int(status.isel({status.dims[0]: 0})) == 0, name


# -- The IOOS compliance checker, CF 1.10 ---------------------------------------------------
#: The checker's check that raises on a string coordinate variable (a zipped axis' labels,
#: ball_5dof's dof names, choices on an axis: CF allows them as labels); the test checks the
#: numeric coordinates' monotonicity itself instead (CF 5: strictly monotonic).
_STRING_COORDINATE_CRASH = "check_coordinate_variables_strict_monotonicity"


@pytest.fixture(scope="module")
def cf_checker(tmp_path_factory):
    """``check(path)``: what the IOOS compliance checker's CF 1.10 suite finds wrong in a
    netCDF file: every failed check of high (CF's "must": errors) or medium priority ("should":
    warnings), and every check that raised. Offline: with no ``standard_name_vocabulary`` the
    checker reads the standard-name table it ships; a download is recorded and fails the
    test (the checker would swallow its failure), and its cache folder is a temporary one."""
    from compliance_checker.base import BaseCheck
    from compliance_checker.cf import util as cf_util
    from compliance_checker.runner import CheckSuite

    downloads = []
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("XDG_DATA_HOME", str(tmp_path_factory.mktemp("checker_cache")))
        patch.setattr(cf_util, "download_cf_standard_name_table",
                      lambda *args, **kwargs: downloads.append(args))
        suite = CheckSuite()
        suite.load_all_available_checkers()

        def check(path) -> list[str]:
            dataset = suite.load_dataset(str(path))
            try:
                groups, crashed = suite.run_all(dataset, ["cf:1.10"], skip_checks=[])["cf:1.10"]
            finally:
                dataset.close()
            problems = []

            def walk(result):
                score = result.value
                failed = score is not None and (score[0] < score[1] if isinstance(score, tuple)
                                                else not score)
                if failed and result.weight >= BaseCheck.MEDIUM:
                    problems.append(f"{result.name}: {'; '.join(result.msgs)}")
                for child in result.children or ():
                    walk(child)

            for group in groups:
                walk(group)
            for name, (error, _) in crashed.items():
                if name == _STRING_COORDINATE_CRASH and "'str'" in str(error):
                    problems += _unordered_numeric_coordinates(path)
                else:
                    problems.append(f"{name} raised {type(error).__name__}: {error}")
            assert not downloads, "the checker went to the network for its name table"
            return problems

        yield check


def _unordered_numeric_coordinates(path) -> list[str]:
    """The numeric coordinate variables (named as their one dimension) that are not strictly
    monotonic: the part of the check the string labels made the checker skip."""
    problems = []
    with netCDF4.Dataset(path) as data:
        for name, variable in data.variables.items():
            if variable.dimensions != (name,) or variable.dtype == str \
                    or variable.dtype.kind not in "iuf" or variable.size < 2:
                continue
            steps = np.diff(np.asarray(variable[...], dtype=float))
            if not ((steps > 0).all() or (steps < 0).all()):
                problems.append(f"{name}: coordinate not strictly monotonic")
    return problems


#: The files whose check costs the most (the checker's time grows with the variables, and
#: these have the most outputs): one writer writes them all, and the files of the other
#: models and designs exercise it in the quick tests; these are checked in the slow ones.
CF_CHECKED_SLOWLY = {"ball_5dof", "crb_radial", "trb_load", "cage_dynamics_6dof",
                     "zipped_float32"}


@pytest.mark.parametrize("name", [
    pytest.param(name, marks=pytest.mark.slow) if name in CF_CHECKED_SLOWLY else name
    for name in MODELS + [p.stem for p in STRUCTURES]])
# The file a run streams is the one users get; xarray's of the same data, the reference,
# is checked in the slow tests.
@pytest.mark.parametrize("writer", ["streamed", pytest.param("xarray", marks=pytest.mark.slow)])
def test_every_run_file_passes_the_cf_checker(runs, cf_checker, name, writer):
    path = runs[name][0 if writer == "streamed" else 2]
    assert cf_checker(path) == []


#: zarr stores of runs with every kind of output: own dimensions (roller, angle), string
#: labels and unit companions, integers, float32, a sampled design.
ZARR_CASES = ["ball_5dof", "crb_radial", "crb_runout", "sampled", "zipped_float32"]


@pytest.mark.parametrize("name", [name if name == "crb_runout" else
                                  pytest.param(name, marks=pytest.mark.slow)
                                  for name in ZARR_CASES])
def test_a_zarr_store_converted_by_xarray_passes_the_cf_checker(cf_checker, name, tmp_path):
    import xarray as xr

    definition = next(p for p in [*DEFINITIONS.glob("*.toml"), *STRUCTURES] if p.stem == name)
    store_path = tmp_path / f"{name}.zarr"
    with Executor(workers=0) as executor:
        run_sweep(spec.load(definition), store_path, executor, progress=False)
    # As the user guide's "Outputs" page says to convert a store.
    data = xr.open_zarr(store_path)
    for variable in data.variables.values():  # zarr keeps attributes as JSON: flags to type
        variable.attrs.update({key: np.asarray(value, variable.dtype)
                               for key, value in variable.attrs.items()
                               if key in ("flag_values", "flag_masks")})
        variable.encoding.pop("compressors", None)  # zarr's codecs are not netCDF's
        if "dtype" in variable.encoding:  # zarr states little-endian, netCDF4 wants native
            variable.encoding["dtype"] = variable.encoding["dtype"].newbyteorder("=")
    data.to_netcdf(tmp_path / f"{name}.nc",
                   encoding={name: {"_FillValue": None} for name in data.coords})
    data.close()
    assert cf_checker(tmp_path / f"{name}.nc") == []


@pytest.mark.parametrize("name", ["sampled", "sampled_lhs"])
def test_every_analyze_output_passes_the_cf_checker(runs, cf_checker, name, tmp_path):
    from bearing_sweep import analyze

    analyze(runs[name][0], output=tmp_path / "analyzed.nc")
    assert cf_checker(tmp_path / "analyzed.nc") == []
