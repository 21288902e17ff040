"""A user's mistake is one clear line and exit 2, and nothing is written: a corpus of bad
definitions, and random definitions from hypothesis."""
import string
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bearing_sweep import cli, stores

CORPUS = sorted((Path(__file__).parents[1] / "data" / "bad_definitions").glob("*.toml"))


def expectation(path: Path) -> str:
    first = path.read_bytes().splitlines()[0].decode()
    assert first.startswith("# expect: "), path
    return first[len("# expect: "):]


def run(definition: Path, output: Path, capsys):
    code = cli.main(["run", str(definition), "-o", str(output), "--workers", "0", "--quiet"])
    captured = capsys.readouterr()
    return code, captured.err


def nothing_written(output: Path):
    return not any(output.parent.glob(output.name + "*")) and not any(
        output.parent.glob("." + output.name + "*"))


def test_the_corpus_is_large_enough():
    assert len(CORPUS) >= 30


@pytest.mark.parametrize("definition", CORPUS, ids=[p.stem for p in CORPUS])
def test_each_bad_definition_is_one_clear_line(definition, tmp_path, capsys):
    output = tmp_path / "out.nc"
    code, err = run(definition, output, capsys)
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("error: "), err
    assert expectation(definition) in lines[0], err
    assert "Traceback" not in err
    assert nothing_written(output)


NAMES = st.sampled_from(["radial_load", "crown", "clearance", "speed", "slices", "roller_count",
                         "slice_law", "crwn", "pitch_diameter", "effective_length"])
VALUES = st.one_of(
    st.integers(-5, 100), st.floats(-1e3, 1e6, allow_nan=False),
    st.sampled_from(['"4 kN"', '"0.004 mm"', '"-1 mm"', '"5000 rpm"', '"50 Hz"', '"abc"',
                     '"uniform"', '"paper"', '"1e30 N"', '"0 mm"', "true", "[]", '["1 kN"]',
                     '{ start = "1 kN", stop = "2 kN", num = 3 }']),
    st.text(alphabet=string.ascii_letters + string.digits + ' "[]{}=.,-', max_size=12))


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(fixed=st.dictionaries(NAMES, VALUES, max_size=4),
       axis=st.one_of(st.none(), st.tuples(NAMES, VALUES)))
def test_random_definitions_give_a_clean_error_or_a_dataset(fixed, axis, tmp_path_factory,
                                                            capsys):
    folder = tmp_path_factory.mktemp("random")
    text = '[sweep]\nmodel = "crb_radial"\nbearing = "paper000-D"\n[fixed]\n'
    text += "".join(f"{name} = {value}\n" for name, value in fixed.items())
    if axis is not None:
        text += f"[axes]\n{axis[0]} = {axis[1]}\n"
    definition = folder / "random.toml"
    definition.write_text(text)
    output = folder / "out.nc"
    code, err = run(definition, output, capsys)
    assert "Traceback" not in err
    if code == 0:
        stores.open_result(output)  # a readable dataset
    else:
        assert code == 2, err
        assert len(err.strip().splitlines()) == 1, err
        assert nothing_written(output)
