"""The JSON Schema of a case file (issue 14, item 4): built-in cases pass, misspelt keys fail."""

import json

import jsonschema
import pytest
import yaml

from rotarykiln.case import case_json_schema
from rotarykiln.case_io import shipped_schema_path
from rotarykiln.cases import builtin_case_path, list_builtin_cases
from rotarykiln.cli import main

SCHEMA = case_json_schema()
VALIDATOR = jsonschema.Draft202012Validator(SCHEMA)


def _case(name):
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def test_the_schema_is_a_valid_draft_2020_12_schema():
    jsonschema.Draft202012Validator.check_schema(SCHEMA)
    assert SCHEMA["$schema"].endswith("2020-12/schema")
    assert {"kiln", "operation"} <= set(SCHEMA["required"])


@pytest.mark.parametrize("name", list_builtin_cases())
def test_every_builtin_case_validates_against_the_schema(name):
    errors = [f"{list(e.absolute_path)}: {e.message}" for e in VALIDATOR.iter_errors(_case(name))]
    assert not errors, errors


def test_a_misspelt_key_is_rejected():
    data = _case("barr_T4")
    data["kiln"]["lenght"] = data["kiln"].pop("length")
    errors = list(VALIDATOR.iter_errors(data))
    assert errors
    assert any(
        list(e.absolute_path) == ["kiln"] and "lenght" in e.message
        for e in errors
        if e.validator == "additionalProperties"
    ), [e.message for e in errors]


def test_a_misspelt_top_level_section_and_a_nested_key_are_rejected():
    data = _case("limestone_fired")
    data["operaton"] = data.pop("operation")
    assert not VALIDATOR.is_valid(data)
    data = _case("barr_T4")
    data["burner"]["primary_air"]["temprature"] = "300 K"
    assert not VALIDATOR.is_valid(data)


@pytest.mark.parametrize(
    ("section", "key", "value"),
    [("kiln", "length", "5.5 m"), ("kiln", "length", 5.5), ("operation", "speed", "1.5 rpm")],
)
def test_quantities_accept_numbers_and_unit_strings(section, key, value):
    data = _case("barr_T4")
    data[section][key] = value
    assert VALIDATOR.is_valid(data)
    data[section][key] = [value]  # but not a list
    assert not VALIDATOR.is_valid(data)


def test_quantity_fields_say_their_unit():
    speed = SCHEMA["$defs"]["Operation"]["properties"]["speed"]
    assert speed["anyOf"] == [{"type": "number"}, {"type": "string"}]
    assert "rpm" in speed["description"]


def test_the_shipped_schema_is_the_generated_one():
    shipped = json.loads(shipped_schema_path().read_text(encoding="utf-8"))
    assert shipped == json.loads(json.dumps(SCHEMA)), (
        "src/rotarykiln/case.schema.json is stale: regenerate it with "
        "`make schema` (rotarykiln schema --out src/rotarykiln/case.schema.json)"
    )


def test_schema_command_prints_and_writes(capsys, tmp_path):
    assert main(["schema"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert printed == json.loads(json.dumps(SCHEMA))
    out = tmp_path / "sub" / "case.schema.json"
    assert main(["schema", "--out", str(out)]) == 0
    assert json.loads(out.read_text()) == printed
    assert str(out) in capsys.readouterr().out
    assert not [p for p in out.parent.iterdir() if p.name.startswith(".")]  # no temporary left
