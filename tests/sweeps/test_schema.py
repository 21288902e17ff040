"""The JSON Schema of sweep definitions accepts every definition the engine accepts among the
studies' and the every-model examples, and refuses the mistakes a schema can see."""
import json
import tomllib
from pathlib import Path

import pytest
from jsonschema import Draft7Validator

from bearing_sweep.models.registry import all_models
from bearing_sweep.schema import schema

ROOT = Path(__file__).resolve().parents[2]
DEFINITIONS = sorted(p for p in ROOT.glob("studies/*/*.toml") if p.name != "claims.toml") + \
    sorted((ROOT / "tests/data/every_model").glob("*.toml"))
BAD = ROOT / "tests/data/bad_definitions"


def read(path):
    return tomllib.loads(Path(path).read_text())


def errors(document, model=None):
    return list(Draft7Validator(schema(model)).iter_errors(document))


def test_the_schemas_are_valid_draft_07():
    Draft7Validator.check_schema(schema())
    for name in all_models():
        Draft7Validator.check_schema(schema(name))


@pytest.mark.parametrize("path", DEFINITIONS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_definition_is_valid(path):
    document = read(path)
    assert errors(document, document["sweep"]["model"]) == []
    assert errors(document) == []


@pytest.mark.parametrize("name", [
    "03_no_model", "04_unknown_model", "05_unknown_section", "06_unknown_parameter",
    "07_missing_units", "11_negative_load", "12_zero_rollers", "14_fractional_count",
    "15_bool_for_number", "16_list_in_fixed", "17_empty_axis", "19_range_num_and_step",
    "21_duplicate_labels", "23_unknown_preset", "24_preset_for_other_model",
    "27_unknown_choice", "30_unknown_dof"])
def test_mistakes_a_schema_can_see_are_refused(name):
    assert errors(read(BAD / f"{name}.toml"))


def test_a_model_schema_refuses_another_model_and_an_unknown_key_in_a_zipped_axis():
    document = read(ROOT / "tests/data/every_model/crb_radial.toml")
    assert errors(document, "ball_5dof")
    document["axes"]["case"] = {"labels": ["a", "b"], "crwn": ["1 um", "2 um"]}
    assert [e for e in errors(document, "crb_radial") if "crwn" in e.message]


def test_descriptions_carry_meaning_unit_default_and_range():
    crb = schema("crb_radial")["properties"]
    crown = crb["fixed"]["properties"]["crown"]
    model = all_models()["crb_radial"].input("crown")
    assert model.meaning in crown["description"] and "[mm]" in crown["description"]
    assert crown["default"] == f"{model.default:g} mm"
    slices = crb["fixed"]["properties"]["slices"]
    assert slices["type"] == "integer" and slices["minimum"] >= 1
    profile = crb["fixed"]["properties"]["crown_profile"]
    assert set(profile["enum"]) == set(all_models()["crb_radial"].input("crown_profile").choices)
    assert crb["sweep"]["properties"]["bearing"]["enum"][0].startswith("paper000")


def test_every_form_of_an_axis(definition):
    document = {"sweep": {"model": "crb_radial", "bearing": "paper000-D"},
                "axes": {"radial_load": {"start": "1 kN", "stop": "4 kN", "num": 4},
                         "clearance": {"values": [0, 0.01], "units": "mm"},
                         "speed": {"start": 0, "stop": 6000, "step": 2000, "units": "rpm"},
                         "case": {"labels": ["l25", "l28"],
                                  "effective_length": ["9 mm", "9.6 mm"]}}}
    assert errors(document, "crb_radial") == []
    document["axes"]["speed"]["num"] = 4  # num and step: one too many
    assert errors(document, "crb_radial")


def test_cli_writes_the_schema(tmp_path, run_cli):
    done = run_cli("schema", "hertz_point", timeout=120, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["title"].endswith("hertz_point sweep")
    out = tmp_path / "bearing-sweep.schema.json"
    done = run_cli("schema", "-o", out, timeout=120, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert len(json.loads(out.read_text())["oneOf"]) == len(all_models())
    done = run_cli("schema", "trb_rib", "-o", out, timeout=120, cwd=tmp_path)  # ours: replaced
    assert done.returncode == 0 and "oneOf" not in json.loads(out.read_text())


def test_cli_refuses_an_unknown_model_in_one_line(tmp_path, run_cli):
    done = run_cli("schema", "crb_radail", timeout=120, cwd=tmp_path)
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.count("\n") == 1 and "did you mean 'crb_radial'" in done.stderr
    definition = tmp_path / "sweep.toml"
    definition.write_text("[sweep]\n")
    done = run_cli("schema", "-o", definition, timeout=120, cwd=tmp_path)
    assert done.returncode == 2 and definition.read_text() == "[sweep]\n"
    other = tmp_path / "package.json"
    other.write_text('{"name": "x"}')
    done = run_cli("schema", "-o", other, timeout=120, cwd=tmp_path)
    assert done.returncode == 2 and other.read_text() == '{"name": "x"}'
