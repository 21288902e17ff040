"""How result files store the outputs: compressed float64 reads back bit for bit, float32 on
request, integral outputs as integers with a fill value, the [output] table and the flags."""
import netCDF4
import numpy as np
import pytest
import xarray as xr
from jsonschema import Draft7Validator

import bearing_sweep.models.registry as registry
from bearing_sweep import api, cli, spec, store
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.schema import schema
from bearing_sweep.storage import INTEGER_FILL, integral_values

TEXT = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "4 um"
speed = "6000 rpm"
slices = 10
[axes]
radial_load = ["1 kN", "4 kN"]
clearance = ["0 mm", "0.02 mm"]
[axes.arrangement]
labels = ["uniform", "paper"]
slice_law = ["uniform", "paper"]
"""


def written(tmp_path, output_table="", name="result"):
    path = tmp_path / f"{name}.nc"
    run_sweep(spec.parse(TEXT + output_table, f"{name}.toml"), path, Executor(workers=0),
              progress=False)
    return path


def filters(path, variable):
    with netCDF4.Dataset(path) as data:
        return data[variable].filters(), data[variable].dtype


def test_every_compression_reads_back_bit_for_bit(tmp_path):
    in_memory = run_sweep(spec.parse(TEXT), None, Executor(workers=0), progress=False).dataset
    for name, table in (("default", ""), ("zlib9", 'compression = "zlib:9"\nshuffle = true'),
                        ("zstd", 'compression = "zstd:1"')):
        found = store.open_result(written(tmp_path, "[output]\n" + table, name))
        for output, variable in in_memory.data_vars.items():
            assert found[output].dtype == variable.dtype, output
            np.testing.assert_array_equal(found[output].values, variable.values, err_msg=output)
    assert filters(tmp_path / "zstd.nc", "roller_load")[0]["zstd"]
    assert filters(tmp_path / "zlib9.nc", "roller_load")[0]["shuffle"]
    # the default: zlib at level 1, no shuffle (benchmarks/output_encoding.py)
    default, _ = filters(tmp_path / "default.nc", "roller_load")
    assert default["zlib"] and default["complevel"] == 1 and not default["shuffle"]
    assert store.open_result(tmp_path / "default.nc").attrs["output_encoding"] == \
        "float64, zlib level 1"


def test_float32_is_stored_on_request_and_said_so(tmp_path):
    double = store.open_result(written(tmp_path, name="double"))
    path = written(tmp_path, '[output]\nencoding = "float32"\ncompression = "none"\n')
    stored, dtype = filters(path, "radial_stiffness")
    assert dtype == np.float32 and not stored["zlib"]
    single = store.open_result(path)
    assert "stored as float32" in single.radial_stiffness.attrs["comment"]
    assert single.attrs["output_encoding"] == "float32, uncompressed"
    # numpy's own rounding of the float64 values: what netCDF stores
    np.testing.assert_array_equal(single.roller_load.values,
                                  double.roller_load.values.astype(np.float32))
    assert single.radial_load.dtype == np.float64  # inputs keep their values exactly


def test_integral_outputs_are_integers_with_a_fill_value_where_a_point_failed(
        tmp_path, paper_slice_law_fails):
    path = written(tmp_path)
    with netCDF4.Dataset(path) as data:
        data.set_auto_mask(False)
        rollers = data["loaded_rollers"]
        assert rollers.dtype == np.int32 and rollers._FillValue == INTEGER_FILL
        raw = rollers[:]  # radial_load, clearance, arrangement (uniform, paper)
        assert (raw[..., 1] == INTEGER_FILL).all() and (raw[..., 0] > 0).all()
        assert data["status"].dtype == np.int8
    found = store.open_result(path)
    assert found.loaded_rollers.sel(arrangement="paper").isnull().all()
    assert "_FillValue" in found.loaded_rollers.attrs["comment"]


def test_a_value_declared_integral_that_is_not_is_refused():
    np.testing.assert_array_equal(integral_values(np.array([3.0, np.nan]), "n"),
                                  [3, INTEGER_FILL])
    with pytest.raises(ValueError, match="'n' is declared an integer but holds 2.5"):
        integral_values(np.array([2.5]), "n")


def test_describe_names_the_integer_outputs(capsys):
    assert {o["name"]: o["dtype"] for o in api.describe("crb_radial")["outputs"]}[
        "loaded_rollers"] == "int"
    assert cli.main(["describe", "crb_radial"]) == 0
    assert "  loaded_rollers [1]: number of rollers carrying load, an integer\n" in \
        capsys.readouterr().out


def test_an_integer_output_must_be_dimensionless():
    model = registry.get_model("crb_radial")
    outputs = (registry.Output("roller_count_load", "N", "a load", dtype="int"),)
    problems = registry.declaration_problems(registry.Model(**{**model.__dict__,
                                                               "outputs": outputs}))
    assert problems == ["output 'roller_count_load': an integer output has unit '1', not 'N'"]


def test_the_flags_override_the_table_and_bad_flags_are_one_line(tmp_path, capsys):
    definition = tmp_path / "flags.toml"
    definition.write_text(TEXT + '[output]\nencoding = "float32"\ncompression = "zlib:4"\n')
    output = tmp_path / "flags.nc"
    common = ["run", str(definition), "-o", str(output), "--workers", "0", "--quiet"]
    assert cli.main(common + ["--encoding", "float64", "--compression", "none"]) == 0
    found, dtype = filters(output, "radial_displacement")
    assert dtype == np.float64 and not found["zlib"]
    output.unlink()
    capsys.readouterr()
    assert cli.main(common + ["--compression", "zlib:0"]) == 2
    assert capsys.readouterr().err == ("error: --compression: 'zlib:0': the level of zlib is an "
                                       "integer from 1 to 9\n")
    assert not list(tmp_path.glob("*.nc*")) and not list(tmp_path.glob(".flags*"))


def test_the_api_takes_them_too():
    with pytest.raises(spec.SpecError, match=r"^encoding=: 'half' is not accepted"):
        api.run(TEXT, encoding="half", progress=False)


def test_the_schema_knows_the_output_table():
    document = {"sweep": {"model": "crb_radial", "bearing": "paper000-D"},
                "fixed": {"radial_load": "4 kN"},
                "output": {"encoding": "float32", "compression": "zstd:19", "shuffle": False}}
    assert not list(Draft7Validator(schema("crb_radial")).iter_errors(document))
    document["output"]["compression"] = "zlib:10"
    assert list(Draft7Validator(schema("crb_radial")).iter_errors(document))


def test_the_in_memory_dataset_writes_the_same_file(tmp_path):
    data = run_sweep(spec.parse(TEXT + '[output]\nencoding = "float32"\n'), None,
                     Executor(workers=0), progress=False).dataset
    assert data.roller_load.dtype == np.float64  # in memory: as computed
    data.to_netcdf(tmp_path / "copy.nc")
    found, dtype = filters(tmp_path / "copy.nc", "roller_load")
    assert dtype == np.float32 and found["zlib"]
    assert filters(tmp_path / "copy.nc", "loaded_rollers")[1] == np.int32
    assert xr.open_dataset(tmp_path / "copy.nc").loaded_rollers.dtype == np.float64


def test_an_interrupted_run_stored_otherwise_computes_its_chunks_again(tmp_path, capsys,
                                                                       monkeypatch):
    # The parts hold the chunks as the file stores them (encoded by the workers): written
    # into a file stored otherwise they would be misread.
    definition = tmp_path / "d.toml"
    definition.write_text(TEXT)
    output = tmp_path / "out.nc"
    arguments = ["run", str(definition), "-o", str(output), "--workers", "0", "--chunk-size",
                 "4", "--quiet"]

    def interrupted(*args):  # every chunk computed, the file not yet written
        raise KeyboardInterrupt

    monkeypatch.setattr("bearing_sweep.store.ChunkWriter.finish", interrupted)
    assert cli.main(arguments) == 130
    monkeypatch.undo()
    capsys.readouterr()
    assert cli.main(arguments + ["--encoding", "float32"]) == 0
    assert "storage changed: discarding 2 finished chunks" in capsys.readouterr().err
    assert filters(output, "roller_load")[1] == np.float32
    double = store.open_result(written(tmp_path, name="double"))
    np.testing.assert_array_equal(store.open_result(output).roller_load.values,
                                  double.roller_load.values.astype(np.float32))


def test_outputs_are_stored_in_hdf5_chunks_of_one_sweep_chunk(tmp_path):
    # Each HDF5 chunk is then complete (and compressed) when its sweep chunk arrives, not
    # when the file is closed after the last one. The grid is 2 x 2 x 2 (radial_load,
    # clearance, arrangement), 10 slices: 4 points per chunk are the last two axes whole.
    path = tmp_path / "chunked.nc"
    run_sweep(spec.parse(TEXT, "chunked.toml"), path, Executor(workers=0), chunk_size=4,
              progress=False)
    with netCDF4.Dataset(path) as data:
        assert data["radial_stiffness"].chunking() == [1, 2, 2]
        assert data["status"].chunking() == [1, 2, 2]
        rollers = data.dimensions["roller"].size
        assert data["roller_load"].chunking() == [1, 2, 2, rollers]
    whole = run_sweep(spec.parse(TEXT), None, Executor(workers=0), progress=False).dataset
    with xr.open_dataset(path) as data:
        for name in whole.data_vars:
            np.testing.assert_array_equal(data[name].values, whole[name].values, err_msg=name)
