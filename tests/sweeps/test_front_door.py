"""The command line is a layer over the Python API: ``bearing-sweep run`` is one call of
``bearing_sweep.run``, and the options the command takes are keywords a notebook has too."""
import pytest

from bearing_sweep import api, cli
from bearing_sweep.spec import SpecError

DEFINITION = """
[sweep]
model = "hertz_point"
[fixed]
curvature_1x = "0.2 1/mm"
curvature_1y = "0.2 1/mm"
[axes]
load = ["1 kN", "2 kN", "3 kN"]
"""


def test_the_run_command_is_one_call_of_the_api(tmp_path, monkeypatch):
    calls = []
    monkeypatch.setattr(api, "run", lambda *args, **keywords: calls.append((args, keywords)))
    definition = tmp_path / "d.toml"
    assert cli.main(["run", str(definition), "-o", "out.zarr", "--workers", "3", "--chunk-size",
                     "7", "--quiet", "--fresh", "--encoding", "float32", "--compression",
                     "zstd:3", "--scheduler", "tcp://host:8786"]) == 0
    [(args, keywords)] = calls
    assert args == (definition,)
    assert {k: keywords[k] for k in ("output", "scheduler", "workers", "chunk_size", "fresh",
                                     "progress", "encoding", "compression", "open_output")} == {
        "output": "out.zarr", "scheduler": "tcp://host:8786", "workers": 3, "chunk_size": 7,
        "fresh": True, "progress": False, "encoding": "float32", "compression": "zstd:3",
        "open_output": False}


@pytest.mark.parametrize("keywords, message", [
    ({"chunk_size": 0}, "chunk_size=0: expected a positive integer"),
    ({"chunk_size": 2.0}, "chunk_size=2.0: expected a positive integer"),
    ({"fresh": "yes"}, "fresh='yes': expected True or False"),
    ({"scheduler": "host"}, "scheduler='host': not a scheduler address"),
    ({"scheduler": 8786}, "scheduler=8786: expected a scheduler's address"),
    ({"scheduler": "tcp://host:8786", "workers": 0},
     "workers=0 and argument scheduler exclude each other"),
    ({"scheduler": "tcp://host:8786", "client": object()},
     "scheduler and client exclude each other"),
])
def test_the_commands_options_are_checked_as_arguments(keywords, message, tmp_path):
    with pytest.raises(SpecError, match="^" + message.replace("(", r"\(")):
        api.run(DEFINITION, output=tmp_path / "d.nc", **keywords)
    assert list(tmp_path.iterdir()) == []


def test_messages_and_summary_go_where_the_caller_says(tmp_path, capsys):
    notes, summaries = [], []
    returned = api.run(DEFINITION, output=tmp_path / "d.nc", workers=0, chunk_size=1,
                       progress=False, log=notes.append, summary=summaries.append,
                       open_output=False)
    assert returned is None and (tmp_path / "d.nc").is_file()
    assert summaries == [summaries[0]] and summaries[0].startswith("hertz_point: 3 points")
    assert notes == []
    (tmp_path / "d.nc").unlink()
    (tmp_path / "d.nc.parts").mkdir()  # a parts folder of no run: discarded, with a message
    capsys.readouterr()
    api.run(DEFINITION, output=tmp_path / "d.nc", workers=0, progress=False,
            log=notes.append, summary=summaries.append, open_output=False)
    assert capsys.readouterr() == ("", "")  # progress=False: no bar; the rest to the callables
    assert notes == [f"no readable manifest in {tmp_path / 'd.nc.parts'}: discarding the folder"]
    assert len(summaries) == 2
