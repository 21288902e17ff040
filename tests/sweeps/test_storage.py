"""How result files store the outputs: compressed float64 reads back bit for bit, float32 on
request, integral outputs as integers with a fill value, the [output] table and the flags."""
import json
import zlib

import netCDF4
import numpy as np
import pytest
import xarray as xr
from jsonschema import Draft7Validator

import bearing_sweep.models.registry as registry
from bearing_sweep import api, cli, spec, stores
from bearing_sweep.stores.netcdf import write_netcdf
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
        found = stores.open_result(written(tmp_path, "[output]\n" + table, name))
        for output, variable in in_memory.data_vars.items():
            assert found[output].dtype == variable.dtype, output
            np.testing.assert_array_equal(found[output].values, variable.values, err_msg=output)
    assert filters(tmp_path / "zstd.nc", "roller_load")[0]["zstd"]
    assert filters(tmp_path / "zlib9.nc", "roller_load")[0]["shuffle"]
    # the default: zlib at level 1, no shuffle (benchmarks/output_encoding.py)
    default, _ = filters(tmp_path / "default.nc", "roller_load")
    assert default["zlib"] and default["complevel"] == 1 and not default["shuffle"]
    assert stores.open_result(tmp_path / "default.nc").attrs["output_encoding"] == \
        "float64, zlib level 1"


def test_float32_is_stored_on_request_and_said_so(tmp_path):
    double = stores.open_result(written(tmp_path, name="double"))
    path = written(tmp_path, '[output]\nencoding = "float32"\ncompression = "none"\n')
    stored, dtype = filters(path, "radial_stiffness")
    assert dtype == np.float32 and not stored["zlib"]
    single = stores.open_result(path)
    assert "stored as float32" in single.radial_stiffness.attrs["comment"]
    assert single.attrs["output_encoding"] == "float32, uncompressed"
    # numpy's own rounding of the float64 values: what netCDF stores
    np.testing.assert_array_equal(single.roller_load.values,
                                  double.roller_load.values.astype(np.float32))
    assert single.radial_load.dtype == np.float64  # inputs keep their values exactly


@pytest.mark.parametrize("output", ["r.nc", "r.zarr", "one.nc", "none.nc"])
def test_a_value_beyond_float32_is_stored_infinite_without_a_warning(tmp_path, output):
    import warnings

    loads = '["1e300 N"]' if output == "one.nc" else '["1e30 N", "1e300 N"]'
    sweep = spec.parse('[sweep]\nmodel = "hertz_point"\n[fixed]\ncurvature_1x = "0.1 1/mm"\n'
                       f'curvature_1y = "0.1 1/mm"\n[axes]\nload = {loads}\n[output]\n'
                       'encoding = "float32"\n' + ('compression = "none"\n'
                                                    if output == "none.nc" else ""))
    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        run_sweep(sweep, tmp_path / output, Executor(workers=0), progress=False)
    assert [str(w.message) for w in shown] == []
    found = stores.open_result(tmp_path / output).max_pressure.values  # p0 ~ load^(1/3)
    assert found[-1] == np.inf and (output == "one.nc" or np.isfinite(found[0]))


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
    found = stores.open_result(path)
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
    with pytest.raises(spec.SpecError, match=r"^argument encoding: 'half' is not accepted"):
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

    monkeypatch.setattr("bearing_sweep.stores.netcdf.ChunkWriter.finish", interrupted)
    assert cli.main(arguments) == 130
    monkeypatch.undo()
    capsys.readouterr()
    assert cli.main(arguments + ["--encoding", "float32"]) == 0
    assert "storage changed: discarding 2 finished chunks" in capsys.readouterr().err
    assert filters(output, "roller_load")[1] == np.float32
    double = stores.open_result(written(tmp_path, name="double"))
    np.testing.assert_array_equal(stores.open_result(output).roller_load.values,
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


# A netCDF result's chunks are encoded (compressed) by the process that computes them and
# written as bytes (hdf5_chunks): the file must be the one netCDF4 writes from the dataset.
DIRECT = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
crown = "4 um"
{speed}
[axes]
{axes}
{table}
"""
LOADS = 'radial_load = {{ start = "1 kN", stop = "5 kN", num = {} }}\n'
CLEARANCES = 'clearance = {{ start = "0 mm", stop = "0.03 mm", num = {} }}\n'
SPEEDS = 'speed = { values = [0, 5000], units = "rpm" }\n'
#: Grids of 1, 2 and 3 axes, chunk sizes, [output] tables, and the HDF5 chunk each sweep chunk
#: then fills along the grid's axes: whole rows of the last axes, of nearly equal length
#: along the one axis they cut (5 loads by 2 points: 2, 2 and an edge block of 1).
CASES = {
    "1 axis, edge": (LOADS.format(5), 2, "", (2,)),
    "2 axes, odd size, edge, float32": (LOADS.format(5) + CLEARANCES.format(3), 7,
                                        'encoding = "float32"', (2, 3)),
    "3 axes, edge, shuffle": (LOADS.format(3) + CLEARANCES.format(3) + SPEEDS, 5,
                              'compression = "zlib:4"\nshuffle = true', (1, 2, 2)),
    "3 axes, one point, uncompressed": (LOADS.format(3) + CLEARANCES.format(4) + SPEEDS, 1,
                                        'compression = "none"', (1, 1, 1)),
    "2 axes, zstd": (LOADS.format(3) + CLEARANCES.format(3), 2, 'compression = "zstd:3"',
                     (1, 2)),
    "2 axes, larger than the grid, float32 shuffle": (
        LOADS.format(3) + CLEARANCES.format(4), 100,
        'encoding = "float32"\nshuffle = true', (3, 4)),
}


def direct_sweep(case: str):
    axes, size, table, block = CASES[case]
    text = DIRECT.format(speed="" if "speed" in axes else 'speed = "6000 rpm"', axes=axes,
                         table="[output]\n" + table)
    return spec.parse(text, "direct.toml"), size, block


def netcdf4_written(tmp_path, sweep):
    """The sweep's dataset in memory (``stores.memory.gather``), written by xarray and netCDF4."""
    data = run_sweep(sweep, None, Executor(workers=0), progress=False).dataset
    return write_netcdf(data, tmp_path / "netcdf4.nc")


def assert_same_file(path, reference, block):
    """Every variable and attribute alike, values bit for bit as stored (types, fill values,
    filters); each output on every point of the grid, and status, in HDF5 chunks of
    ``block`` along the grid's axes, their own dimensions whole."""
    with netCDF4.Dataset(path) as found, netCDF4.Dataset(reference) as expected:
        found.set_auto_maskandscale(False)
        expected.set_auto_maskandscale(False)
        assert ({n: d.size for n, d in found.dimensions.items()}
                == {n: d.size for n, d in expected.dimensions.items()})
        assert set(found.variables) == set(expected.variables)
        grid = found["status"].dimensions
        for name, variable in found.variables.items():
            other = expected[name]
            assert variable.dtype == other.dtype and variable.dimensions == other.dimensions
            assert variable.filters() == other.filters(), name
            attributes = {key: variable.getncattr(key) for key in variable.ncattrs()}
            np.testing.assert_equal(attributes, {key: other.getncattr(key)
                                                 for key in other.ncattrs()}, err_msg=name)
            np.testing.assert_array_equal(variable[...], other[...], err_msg=name)
            if variable.dimensions[:len(grid)] == grid and name not in found.dimensions:
                assert variable.chunking() == list(block) + list(variable.shape[len(grid):])
        made = ("history", "scheduler")  # when and where, not what
        np.testing.assert_equal({k: found.getncattr(k) for k in found.ncattrs()
                                 if k not in made},
                                {k: expected.getncattr(k) for k in expected.ncattrs()
                                 if k not in made})


@pytest.mark.parametrize("case", CASES)
def test_the_chunks_encoded_by_the_workers_make_the_file_netcdf4_writes(tmp_path, case):
    sweep, size, block = direct_sweep(case)
    path = tmp_path / "direct.nc"
    run_sweep(sweep, path, Executor(workers=0), chunk_size=size, progress=False)
    assert_same_file(path, netcdf4_written(tmp_path, sweep), block)
    with netCDF4.Dataset(path) as data:  # folded on the speed, or a single value
        assert data["centrifugal_force"].dimensions == (("speed",) if "speed" in
                                                        CASES[case][0] else ())


def test_two_workers_encode_the_same_file(tmp_path):
    sweep, size, block = direct_sweep("3 axes, edge, shuffle")
    with Executor(workers=2) as executor:
        run_sweep(sweep, tmp_path / "two.nc", executor, chunk_size=size, progress=False)
    assert_same_file(tmp_path / "two.nc", netcdf4_written(tmp_path, sweep), block)


def interrupted_run(tmp_path, monkeypatch, case: str, *options):
    """Run ``case``'s sweep (:func:`direct_sweep`) with the CLI in-process, in its blocks,
    interrupted when every chunk is computed but the file not yet complete. Returns the
    definition, the output, the CLI's arguments (without ``options``) and the block."""
    sweep, size, block = direct_sweep(case)
    definition = tmp_path / "direct.toml"
    definition.write_text(sweep.text)
    output = tmp_path / "out.nc"
    arguments = ["run", str(definition), "-o", str(output), "--workers", "0", "--chunk-size",
                 str(size), "--quiet"]

    def interrupted(*args):
        raise KeyboardInterrupt

    monkeypatch.setattr("bearing_sweep.stores.netcdf.ChunkWriter.finish", interrupted)
    assert cli.main(arguments + list(options)) == 130
    monkeypatch.undo()
    return definition, output, arguments, block


def test_an_interrupted_run_writes_its_encoded_chunks_on_resuming(tmp_path, capsys,
                                                                  monkeypatch):
    # chunks compressed by zstd are not this file's, compressed by zlib
    interrupted_run(tmp_path, monkeypatch, "2 axes, odd size, edge, float32",
                    "--compression", "zstd")
    definition, output, arguments, block = interrupted_run(
        tmp_path, monkeypatch, "2 axes, odd size, edge, float32")
    assert "storage changed: discarding 3 finished chunks" in capsys.readouterr().err

    def computed(*args):
        raise AssertionError("a finished chunk computed again")

    monkeypatch.setattr("bearing_sweep.evaluate.evaluate_chunk", computed)
    assert cli.main(arguments) == 0
    assert "resuming: 3 chunks already computed" in capsys.readouterr().err
    monkeypatch.undo()
    assert_same_file(output, netcdf4_written(tmp_path, spec.load(definition)), block)


def test_a_chunk_leaves_its_worker_compressed_as_the_file_stores_it(tmp_path):
    from bearing_sweep.evaluate import evaluate_chunk, evaluate_into, versions
    from bearing_sweep.grid import Grid
    from bearing_sweep.stores.hdf5_chunks import ChunkEncoder, layouts

    sweep, size, block = direct_sweep("1 axis, edge")
    run_sweep(sweep, tmp_path / "direct.nc", Executor(workers=0), chunk_size=size,
              progress=False)
    with netCDF4.Dataset(tmp_path / "direct.nc") as data:
        stored = layouts(data, [name for name, variable in data.variables.items()
                                if variable.dimensions[:1] == ("radial_load",)
                                and name != "radial_load"])
    grid = Grid.from_sweep(sweep)
    result = evaluate_into(ChunkEncoder(stored), versions(grid.model), grid, 4, 5)
    assert set(result) == {"tally", "versions", "chunks", "firsts"}  # no values but these
    assert set(result["firsts"]) == {"centrifugal_force", "viscosity_ratio"}  # one value each
    offset, data = result["chunks"]["roller_load"]
    assert offset == (4, 0)  # the last block, of one point in a chunk of two: zlib, no shuffle
    values = np.frombuffer(zlib.decompress(data), dtype="<f8").reshape(2, -1)
    np.testing.assert_array_equal(values[0],
                                  evaluate_chunk(grid, 4, 5)["outputs"]["roller_load"][0])
    assert np.isnan(values[1]).all()  # beyond the grid: the fill value, never read


def test_parts_kept_by_a_version_before_encoded_chunks_are_not_read(tmp_path, capsys,
                                                                    monkeypatch):
    # Its parts held each chunk's arrays, under a manifest that did not say so.
    _, _, arguments, _ = interrupted_run(tmp_path, monkeypatch, "1 axis, edge")
    manifest = tmp_path / "out.nc.parts" / "manifest.json"
    earlier = json.loads(manifest.read_text())
    assert earlier.pop("parts_hold").startswith("hdf5 chunks, float64, zlib level 1, outputs ")
    manifest.write_text(json.dumps(earlier))
    capsys.readouterr()
    assert cli.main(arguments) == 0
    assert "storage changed: discarding 3 finished chunks" in capsys.readouterr().err


def test_parts_of_another_declaration_of_the_model_are_not_read(tmp_path, capsys, monkeypatch):
    # The same model version declaring centrifugal_force on every point: the parts' chunks
    # hold it on the speed alone, none on every point.
    import dataclasses

    _, output, arguments, _ = interrupted_run(tmp_path, monkeypatch, "1 axis, edge")
    model = registry.get_model("crb_radial")
    outputs = tuple(dataclasses.replace(o, depends_on=None) if o.name == "centrifugal_force"
                    else o for o in model.outputs)
    monkeypatch.setitem(registry._MODELS, "crb_radial",
                        registry.Model(**{**model.__dict__, "outputs": outputs}))
    capsys.readouterr()
    assert cli.main(arguments) == 0
    assert "storage changed: discarding 3 finished chunks" in capsys.readouterr().err
    with netCDF4.Dataset(output) as data:
        assert data["centrifugal_force"].dimensions[0] == "radial_load"
        assert not np.ma.is_masked(data["centrifugal_force"][:])
