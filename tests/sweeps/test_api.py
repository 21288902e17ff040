"""The Python API: the CLI's results and error lines, from text, a path or a dict."""
import importlib
import inspect

import numpy as np
import pytest
import xarray as xr

import bearing_sweep
from bearing_sweep import cli, stores
from bearing_sweep.stores import netcdf
from bearing_sweep.models.cylindrical import crb_radial
from bearing_sweep.models.registry import all_models

TEXT = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"

[fixed]
crown = "4 um"

[axes]
radial_load = { start = "1 kN", stop = "4 kN", num = 4 }

[axes.case]
labels = ["tight", "loose"]
clearance = ["0 mm", "0.02 mm"]
"""
#: TEXT as a dict: the same structure, units in strings.
DOCUMENT = {
    "sweep": {"model": "crb_radial", "bearing": "paper000-D"},
    "fixed": {"crown": "4 um"},
    "axes": {"radial_load": {"start": "1 kN", "stop": "4 kN", "num": 4},
             "case": {"labels": ["tight", "loose"], "clearance": ["0 mm", "0.02 mm"]}},
}
#: Global attributes that say when and how a dataset was made, not what it holds.
CIRCUMSTANCES = {"history"}


def cli_result(tmp_path, *options):
    path = tmp_path / "sweep.toml"
    path.write_text(TEXT)
    assert cli.main(["run", str(path), "-o", str(tmp_path / "cli.nc"), "--quiet",
                     *options]) == 0
    return path, stores.open_result(tmp_path / "cli.nc")


def assert_same_result(ours: xr.Dataset, theirs: xr.Dataset, attributes=None):
    """Every variable and coordinate bitwise equal, with its attributes; the global
    attributes named (all but the circumstances when None) equal."""
    assert set(ours.variables) == set(theirs.variables)
    for name in theirs.variables:
        mine, expected = ours[name], theirs[name]
        assert mine.dims == expected.dims, name
        assert set(mine.attrs) == set(expected.attrs), name
        for key, value in expected.attrs.items():  # flag_values are arrays
            assert np.array_equal(mine.attrs[key], value), (name, key)
        if expected.dtype.kind in "fiub":
            assert mine.dtype == expected.dtype, name
            assert mine.values.tobytes() == expected.values.tobytes(), name
        else:  # strings: numpy's own in memory, Python objects as read from a file
            assert mine.values.tolist() == expected.values.tolist(), name
    keys = attributes or set(theirs.attrs) - CIRCUMSTANCES
    assert {k: ours.attrs.get(k) for k in keys} == {k: theirs.attrs[k] for k in keys}


def test_in_memory_result_is_the_clis_file_bitwise(tmp_path):
    path, expected = cli_result(tmp_path, "--workers", "0")
    data = bearing_sweep.run(path, workers=0, progress=False)
    assert_same_result(data, expected)
    assert not list(tmp_path.glob("*.parts")) and sorted(p.name for p in tmp_path.iterdir()) \
        == ["cli.nc", "sweep.toml"]  # nothing written without an output


def test_text_and_dict_give_the_same_numbers_as_the_path(tmp_path):
    _, expected = cli_result(tmp_path, "--workers", "0")
    numbers = set(expected.attrs) - CIRCUMSTANCES - {
        "definition", "definition_file", "definition_sha256", "title"}
    for definition in (TEXT, DOCUMENT):
        data = bearing_sweep.run(definition, workers=0, progress=False)
        assert_same_result(data, expected, numbers)
        assert data.attrs["definition_file"] == "<definition>"
    # A dict is stored as the TOML it stands for, which reads back to the same dict.
    import tomllib
    assert tomllib.loads(data.attrs["definition"]) == DOCUMENT


def test_with_an_output_the_file_is_the_clis_and_is_returned_opened(tmp_path):
    path, expected = cli_result(tmp_path, "--workers", "0")
    output = tmp_path / "api" / "out.nc"
    with bearing_sweep.run(path, output=output, workers=0, progress=False) as data:
        assert data.encoding["source"] == str(output)
        assert_same_result(data.load(), expected)
    assert_same_result(stores.open_result(output), expected)


def test_an_interrupted_run_to_an_output_resumes(tmp_path, monkeypatch, capsys):
    path = tmp_path / "sweep.toml"
    path.write_text(TEXT)
    output = tmp_path / "out.nc"
    original = netcdf.ChunkWriter.finish

    def interrupted(*args):  # every chunk computed, the file not yet written
        raise KeyboardInterrupt

    monkeypatch.setattr(netcdf.ChunkWriter, "finish", interrupted)
    with pytest.raises(KeyboardInterrupt):
        bearing_sweep.run(path, output=output, workers=0)
    assert not output.exists() and (tmp_path / "out.nc.parts").is_dir()
    monkeypatch.setattr(netcdf.ChunkWriter, "finish", original)
    capsys.readouterr()
    bearing_sweep.run(path, output=output, workers=0).close()
    err = capsys.readouterr().err
    assert "resuming: 1 chunk already computed" in err  # in-process: one chunk
    assert "crb_radial: 8 points (8 converged)" in err and str(output) in err


def test_check_raises_the_clis_line(tmp_path, capsys):
    bad = TEXT.replace("crown =", "crwn =")
    path = tmp_path / "bad.toml"
    path.write_text(bad)
    assert cli.main(["run", str(path), "-o", str(tmp_path / "out.nc")]) == 2
    line = capsys.readouterr().err.strip()
    assert line.startswith("error: ")
    assert bearing_sweep.check(TEXT) is None
    with pytest.raises(bearing_sweep.SpecError) as error:
        bearing_sweep.check(path)
    assert f"error: {error.value}" == line
    with pytest.raises(bearing_sweep.SpecError) as error:
        bearing_sweep.run(str(path), output=tmp_path / "out.nc")
    assert f"error: {error.value}" == line
    assert list(tmp_path.iterdir()) == [path]  # nothing written


def test_a_dicts_mistakes_name_its_keys_like_the_texts():
    document = {**DOCUMENT, "fixed": {"crwn": "4 um"}}
    with pytest.raises(bearing_sweep.SpecError, match=r"^<definition>: fixed\.crwn: unknown "
                       r"parameter 'crwn' of model crb_radial; did you mean 'crown'\?"):
        bearing_sweep.check(document)
    text = TEXT.replace("crown =", "crwn =")
    with pytest.raises(bearing_sweep.SpecError) as from_text:
        bearing_sweep.check(text)
    with pytest.raises(bearing_sweep.SpecError) as from_dict:
        bearing_sweep.check(document)
    assert str(from_dict.value) == str(from_text.value)
    for wrong, where in (({**DOCUMENT, "fixed": {"crown": None}}, "fixed.crown"),
                         ({**DOCUMENT, "axes": {"radial_load": ["1 kN", object()]}},
                          r"axes.radial_load\[1\]")):
        with pytest.raises(bearing_sweep.SpecError, match=rf"^<definition>: {where}: .* is "
                           "not a value of a definition"):
            bearing_sweep.check(wrong)
    with pytest.raises(bearing_sweep.SpecError, match="a definition is TOML text, a path or a "
                       "dict, not int"):
        bearing_sweep.check(3)


def test_a_missing_file_is_one_line():
    with pytest.raises(bearing_sweep.SpecError, match="^nowhere.toml: cannot read the "
                       "definition: No such file"):
        bearing_sweep.check("nowhere.toml")


@pytest.mark.parametrize("workers, client, message", [
    (-1, None, r"workers=-1: expected 0 \(in-process\) or more workers"),
    (1.5, None, r"workers=1.5: expected"),
    (2, object(), "workers and client exclude each other"),
])
def test_wrong_cluster_arguments_are_refused_before_computing(tmp_path, workers, client,
                                                               message):
    with pytest.raises(bearing_sweep.SpecError, match=message):
        bearing_sweep.run(TEXT, output=tmp_path / "out.nc", workers=workers, client=client)
    assert not list(tmp_path.iterdir())


def test_models_and_describe_are_the_registrys_declarations_as_data(capsys):
    table = bearing_sweep.list_models()
    assert [row["name"] for row in table] == list(all_models())
    row = next(r for r in table if r["name"] == "crb_radial")
    assert row["version"] == all_models()["crb_radial"].version
    assert row["reference"].startswith("Paper 000")
    described = bearing_sweep.describe("crb_radial")
    inputs = {i["name"]: i for i in described["inputs"]}
    assert inputs["radial_load"]["unit"] == "N" and inputs["radial_load"]["required"]
    assert inputs["radial_load"]["default"] is None
    assert inputs["crown_profile"]["kind"] == "choice" and "logarithmic" in \
        inputs["crown_profile"]["choices"]
    assert inputs["radial_load"]["minimum"] == 0.0 and inputs["radial_load"]["range"] == ">= 0 N"
    outputs = {o["name"]: o for o in described["outputs"]}
    assert outputs["roller_load"]["dims"] == ("roller",)
    assert "converged" in described["statuses"]
    module, _, name = described["function"].rpartition(".")
    assert getattr(importlib.import_module(module), name) is crb_radial  # usable on arrays


def test_models_and_a_description_show_as_tables_in_a_notebook():
    table = bearing_sweep.list_models()
    html = table._repr_html_()
    assert html.count("<tr>") == len(table) + 1  # a header and a row per model
    assert "<td style='text-align:left'>crb_radial</td>" in html
    frame = table.to_dataframe()
    assert list(frame.index) == [row["name"] for row in table]
    assert frame.loc["crb_radial", "version"] == all_models()["crb_radial"].version
    described = bearing_sweep.describe("crb_radial")
    html = described._repr_html_()
    for entry in described["inputs"] + described["outputs"]:
        assert f"<td style='text-align:left'>{entry['name']}</td>" in html
    assert "N/mm" in html and "required" in html
    inputs = described.to_dataframe("inputs")
    assert inputs.loc["radial_load", "unit"] == "N" and inputs.loc["radial_load", "required"]
    assert list(described.to_dataframe("outputs").index) == [
        o["name"] for o in described["outputs"]]


def test_an_unknown_model_is_the_clis_line(capsys):
    assert cli.main(["describe", "crb_radail"]) == 2
    line = capsys.readouterr().err.strip()
    with pytest.raises(bearing_sweep.SpecError) as error:
        bearing_sweep.describe("crb_radail")
    assert f"error: {error.value}" == line and "did you mean 'crb_radial'?" in line


@pytest.mark.slow
def test_chunks_run_on_a_given_client_which_stays_open(tmp_path):
    from distributed import Client, LocalCluster

    _, expected = cli_result(tmp_path, "--workers", "0")
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                      dashboard_address=":0") as cluster, Client(cluster) as client:
        data = bearing_sweep.run(TEXT, client=client, progress=False)
        assert client.status == "running"  # the caller's client is left open
        # The tasks are named by model and points, as the dashboard shows them.
        keys = [event["key"] for event in client.get_task_stream() if "key" in event] or [
            key for key in client.run_on_scheduler(
                lambda dask_scheduler: list(dask_scheduler.task_prefixes))]
        assert any(str(key).startswith("crb_radial-points") for key in keys), keys
        assert data.attrs["scheduler"] == f"dask client of {cluster.scheduler_address} " \
                                          "(1 workers)"
        numbers = set(expected.attrs) - CIRCUMSTANCES - {
            "definition", "definition_file", "definition_sha256", "title", "scheduler"}
        assert_same_result(data, expected, numbers)


@pytest.mark.parametrize("call, words", [
    (lambda: bearing_sweep.run(DOCUMENT, output=5), "output=5: expected a path"),
    (lambda: bearing_sweep.run(DOCUMENT, output=b"r.nc"), "output=b'r.nc': expected a path"),
    (lambda: bearing_sweep.run(DOCUMENT, output=""), "not an empty one"),
    (lambda: bearing_sweep.run(DOCUMENT, client="tcp://x"), "give Client('tcp://x')"),
    (lambda: bearing_sweep.run(DOCUMENT, client=5), "expected a dask.distributed.Client"),
    (lambda: bearing_sweep.run(DOCUMENT, progress="no"), "progress='no': expected True or"),
    (lambda: bearing_sweep.run(DOCUMENT, encoding=5), "argument encoding: 5 is not accepted"),
    (lambda: bearing_sweep.run(DOCUMENT, compression=5), "argument compression: 5"),
    (lambda: bearing_sweep.run(DOCUMENT, workers="2"), "workers='2'"),
    (lambda: bearing_sweep.check(5), "a definition is TOML text, a path or a dict"),
    (lambda: bearing_sweep.describe(5), "name=5: expected a model's name"),
    (lambda: bearing_sweep.analyze(5), "result=5: expected a sampled result"),
    (lambda: bearing_sweep.analyze("r.nc", output=5), "output=5: expected a path")])
def test_an_argument_of_the_wrong_type_is_one_line_before_anything_runs(call, words, tmp_path,
                                                                     monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(bearing_sweep.SpecError) as caught:
        call()
    assert words in str(caught.value) and "\n" not in str(caught.value)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("arguments, words", [
    (dict(result=5), "result=5: expected a result"), (dict(result=None), "result=None"),
    (dict(result="r.nc", variable=5), "variable=5: expected the name of an output"),
    (dict(result="r.nc", x=["radial_load"]), "x=['radial_load']: expected the name of an axis"),
    (dict(result="r.nc", output=5), "output=5: expected a path")])
def test_plot_refuses_an_argument_of_the_wrong_type_in_one_line(arguments, words, tmp_path,
                                                               monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(bearing_sweep.SpecError) as caught:
        bearing_sweep.plot(**arguments)
    assert words in str(caught.value) and "\n" not in str(caught.value)
    assert list(tmp_path.iterdir()) == []


def test_every_function_of_the_api_is_annotated():
    for name in bearing_sweep.__all__:
        function = getattr(bearing_sweep, name)
        if name in ("SpecError", "__version__"):
            continue
        signature = inspect.signature(function)
        unannotated = [p for p, parameter in signature.parameters.items()
                       if parameter.annotation is inspect.Parameter.empty]
        assert unannotated == [], (name, unannotated)
        assert signature.return_annotation is not inspect.Signature.empty, name
