"""Every model's file reads right in the ecosystem's tools: UDUNITS units, pint-xarray, CF
coordinates, plot-friendly labels; and its numbers do not depend on the chunking."""
from pathlib import Path

import cf_units
import netCDF4
import numpy as np
import pint_xarray  # noqa: F401  (registers the .pint accessor)
import pytest

from bearing_sweep.models.registry import all_models
from bearing_sweep import spec, store, units
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.testing import assert_same_numbers

DEFINITIONS = Path(__file__).parent / "data" / "every_model"
MODELS = sorted(all_models())
#: Besides every model's sweep: a zipped axis with float32 shuffled outputs, a sampled design.
STRUCTURES = sorted((Path(__file__).parent / "data" / "structure").glob("*.toml"))


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
def runs(tmp_path_factory):
    """Each model's sweep written as it computes, whole and one point per chunk, and
    computed in memory then written by xarray."""
    folder = tmp_path_factory.mktemp("every_model")
    made = {}
    with Executor(workers=0) as executor:
        for definition in [DEFINITIONS / f"{name}.toml" for name in MODELS] + STRUCTURES:
            sweep, name = spec.load(definition), definition.stem
            paths = []
            for chunk in (None, 1):
                paths.append(folder / f"{name}-{chunk}.nc")
                run_sweep(sweep, paths[-1], executor, chunk_size=chunk, progress=False)
            in_memory = run_sweep(sweep, None, executor, progress=False).dataset
            paths.append(store.write_netcdf(in_memory, folder / f"{name}-xarray.nc"))
            made[name] = paths
    return made


@pytest.fixture(scope="module")
def files(runs):
    """Each model's sweep computed whole and one point per chunk, opened."""
    return {name: [store.open_result(runs[name][chunk]) for chunk in (0, 1)] for name in MODELS}


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
def test_every_variable_has_cf_units_labels_and_quantifies_with_pint_xarray(files, name):
    assert_cf_labelled(files[name][0])


def assert_cf_labelled(data):
    """Every variable has a short long_name and units UDUNITS reads (or says why not), and
    the dataset quantifies with pint-xarray."""
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


@pytest.mark.parametrize("name", MODELS)
def test_coordinates_carry_no_fill_value_and_fixed_inputs_are_not_coordinates(files, name):
    data = files[name][0]
    assert all(data[c].ndim for c in data.coords), "a scalar coordinate fills plot titles"
    for coordinate in data.coords:
        assert "_FillValue" not in data[coordinate].encoding or \
            data[coordinate].encoding["_FillValue"] is None, coordinate
    for fixed in data.attrs["fixed_inputs"].split():
        assert fixed in data.data_vars
