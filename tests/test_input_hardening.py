"""Hostile inputs (issue 15, "Inputs"): each is refused quickly with one InputError line."""

import re
import time
from contextlib import contextmanager
from pathlib import Path

import pytest
import yaml

from rotarykiln.case import load_case, parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError

BASE = Path(builtin_case_path("tscheng_A16")).read_text(encoding="utf-8")


@contextmanager
def refused_quickly(*fragments: str, seconds: float = 2.0):
    """The block raises one InputError line containing every fragment, within ``seconds``."""
    start = time.perf_counter()
    with pytest.raises(InputError) as info:
        yield info
    elapsed = time.perf_counter() - start
    text = str(info.value)
    assert "\n" not in text
    for fragment in fragments:
        assert fragment in text
    assert elapsed < seconds, f"refused in {elapsed:.2f} s: {text}"


# --- case files ------------------------------------------------------------------------------


def nested_mapping(levels: int) -> str:
    """A mapping nested ``levels`` deep, indented one space per level."""
    lines = [" " * i + f"k{i}:" for i in range(levels)]
    return "\n".join(lines) + "\n" + " " * levels + "x: 1\n"


BILLION_LAUGHS = (
    'a: &a ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]\n'
    + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [" + ", ".join([f"*{chr(97 + i)}"] * 9) + "]\n"
        for i in range(8)
    )
)


@pytest.mark.parametrize(
    ("name", "content", "fragments"),
    [
        ("nested.yaml", nested_mapping(1000), ["nested deeper than 20 levels"]),
        ("flow.yaml", "kiln: " + "[" * 1000 + "]" * 1000 + "\n", ["nested deeper than 20"]),
        ("laughs.yaml", BILLION_LAUGHS, ["more than 100000 values", "aliases"]),
        ("big.yaml", BASE + "#" * 5_000_000 + "\n", ["5 MB is too large", "at most 1 MB"]),
        (
            "digits.yaml",
            BASE.replace("name:", "x: " + "9" * 5000 + "\nname:", 1),
            ["a number of 5000 characters (at most 100)"],
        ),
        (
            "float.yaml",
            BASE.replace("name:", "x: 0." + "1" * 500 + "\nname:", 1),
            ["a number of 502 characters"],
        ),
        ("self.yaml", "kiln: &k [1, *k]\n", ["refers to itself"]),
    ],
)
def test_hostile_case_files_are_refused_quickly(tmp_path, name, content, fragments):
    path = tmp_path / name
    path.write_text(content, encoding="utf-8")
    with refused_quickly(str(path), *fragments):
        load_case(path)


def test_many_aliases_are_refused(tmp_path):
    path = tmp_path / "aliases.yaml"
    path.write_text("a: &a 1\nb: [" + ", ".join(["*a"] * 101) + "]\n", encoding="utf-8")
    with refused_quickly(str(path), "more than 100 YAML aliases"):
        load_case(path)


def test_latin1_case_file_is_refused(tmp_path):
    path = tmp_path / "latin1.yaml"
    path.write_bytes(BASE.encode() + "description: caf\xe9\n".encode("latin-1"))
    with refused_quickly(str(path), "not UTF-8", "0xe9"):
        load_case(path)


def test_a_few_aliases_and_the_builtin_cases_still_load(tmp_path):
    path = tmp_path / "anchors.yaml"
    path.write_text(
        "kiln: {length: &d 0.4 m, diameter: *d}\noperation: {speed: 1.5 rpm}\n", encoding="utf-8"
    )
    case = load_case(path)
    assert case.kiln.length == case.kiln.diameter == pytest.approx(0.4)
    assert load_case(builtin_case_path("limestone_calcination")).chemistry is not None


def test_python_structures_are_checked_too():
    cyclic = []
    cyclic.append(cyclic)
    with refused_quickly("nested deeper than 20 levels"):
        parse_case({"kiln": cyclic})
    laughs = "lol"
    for _ in range(9):
        laughs = [laughs] * 9
    with refused_quickly("more than 100000 values"):
        parse_case({"kiln": laughs})
    with refused_quickly("kiln.length: an integer of more than 100 digits"):
        parse_case({"kiln": {"length": 10**5000}, "operation": {"speed": "1 rpm"}})


def test_sweep_reads_its_base_case_within_the_same_limits(tmp_path):
    from rotarykiln.commands.sweep import _load_case

    path = tmp_path / "nested.yaml"
    path.write_text(nested_mapping(1000), encoding="utf-8")
    with refused_quickly("nested deeper than 20 levels"):
        _load_case(str(path))


# --- quantities ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("9**9**9 m", "is not a number followed by a unit (no arithmetic)"),
        ("2**9999 m", "is not a number followed by a unit (no arithmetic)"),
        ("1+2 m", "is not a number followed by a unit (no arithmetic)"),
        ("5 m-m", "is not a number followed by a unit (no arithmetic)"),
        ("5 m*2", "is not a number followed by a unit (no arithmetic)"),
        ("1 m**2**9", "is not a number followed by a unit (no arithmetic)"),
        ("(3) m", "is not a quantity with a unit"),
        ("m", '"m" has no number, expected a length'),
        ("1" * 100_000 + " m", "(100002 characters) is too long for a quantity (at most 64"),
        ("0." + "1" * 5000 + " m", "too long for a quantity"),
    ],
)
def test_a_quantity_is_a_number_and_a_unit_nothing_else(text, message):
    from rotarykiln.units import to_si

    with refused_quickly("kiln.length: ", message, seconds=0.5):
        to_si("kiln.length", text, "length")


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("9**9**9 kg/h", "no arithmetic"),
        ("12 Nm3/h+2", "no arithmetic"),
        ("kg/h", "has no number"),
        ("2" * 100_000 + " kg/h", "too long"),
    ],
)
def test_gas_flows_are_a_number_and_a_unit_too(text, message):
    from rotarykiln.units import gas_flow

    with refused_quickly("burner.fuel_flow: ", message, seconds=0.5):
        gas_flow(text, "burner.fuel_flow")


def test_a_unit_without_number_is_refused_in_a_case_and_on_the_command_line(capsys):
    from rotarykiln.cli import main

    with refused_quickly('kiln.length: "m" has no number'):
        parse_case({"kiln": {"length": "m", "diameter": "0.4 m"}, "operation": {"speed": "1 rpm"}})
    args = ["bed", "--diameter", "m", "--length", "2 m", "--speed", "3 rpm", "--slope", "1 deg"]
    args += ["--feed", "62 kg/h", "--density", "1500 kg/m3", "--repose", "35 deg"]
    assert main(args) == 2
    assert '--diameter: "m" has no number' in capsys.readouterr().err


@pytest.mark.parametrize(
    ("text", "kind", "si"),
    [
        ("1.5 rpm", "rotation rate", 0.15707963),
        ("62 kg/h", "mass flow", 62 / 3600),
        ("3 %", "fraction", 0.03),
        ("1100 degC", "temperature", 1373.15),
        ("1100 deg C", "temperature", 1373.15),
        ("0.4 m", "length", 0.4),
        ("1e-3 m", "length", 1e-3),
        ("-5 degC", "temperature", 268.15),
        ("1.2 W/(m K)", "thermal conductivity", 1.2),
        ("10 W/m^2K", "heat transfer coefficient", 10.0),
        ("2 s^-1", "frequency", 2.0),
        ("1500 kg/m3", "density", 1500.0),
    ],
)
def test_the_usual_spellings_still_read(text, kind, si):
    from rotarykiln.units import to_si

    assert to_si("x", text, kind) == pytest.approx(si)


# --- counts ----------------------------------------------------------------------------------

SMALL = {"kiln": {"length": "2 m", "diameter": "0.4 m"}, "operation": {"speed": "1 rpm"}}


@pytest.mark.parametrize(
    ("n", "shown"),
    [
        (0, "0 is not"),
        (1, "1 is not"),
        (100_001, "100001 is not"),
        (10**7, "10000000 is not"),
        (1e7, "10000000.0 is not"),
        (2.5, "2.5 is not"),
        ("many", '"many" is not'),
        (None, "empty, expected"),
    ],
)
def test_transport_n_points_is_bounded(n, shown):
    with refused_quickly(f"transport.n_points: {shown} an integer in [2, 100000]"):
        parse_case({**SMALL, "transport": {"n_points": n}})


def test_weirs_need_the_scott_model():
    weir = {"position": "1 m", "height": "0.02 m"}
    with refused_quickly("transport: weirs are given with the kramers model: weirs need model"):
        parse_case({**SMALL, "transport": {"weirs": [weir]}})
    assert parse_case({**SMALL, "transport": {"model": "scott", "weirs": [weir]}}).transport


@pytest.mark.parametrize("case", ["tscheng_A16", "limestone_calcination"])
@pytest.mark.parametrize("cells", [3, 20_001, 10**7])
def test_cells_are_bounded(case, cells):
    data = yaml.safe_load(Path(builtin_case_path(case)).read_text(encoding="utf-8"))
    data["solver"] = {"cells": cells}
    with refused_quickly(f"solver.cells: {cells} is not an integer in [4, 20000]"):
        parse_case(data)


@pytest.mark.parametrize("points", ["0", "1", "100000000"])
def test_bed_points_are_bounded(points, capsys):
    from rotarykiln.cli import main

    args = ["bed", "--diameter", "0.4 m", "--length", "2 m", "--speed", "3 rpm", "--slope", "1 deg"]
    args += ["--feed", "62 kg/h", "--density", "1500 kg/m3", "--repose", "35 deg"]
    start = time.perf_counter()
    assert main([*args, "--points", points]) == 2
    assert time.perf_counter() - start < 2
    err = capsys.readouterr().err.strip()
    assert err.endswith(f"--points: {points} is not an integer in [2, 100000]")
    assert "\n" not in err


# --- messages in English ---------------------------------------------------------------------

HEAT_CASE = "tscheng_A16"
FLAME_CASE = "ubc_pilot_flame"
PYDANTIC_TEXT = ("Input should", "None", "Field required", "Value error", "function-", "str.")


def mutated(case: str, path: str, value="DELETE"):
    data = yaml.safe_load(Path(builtin_case_path(case)).read_text(encoding="utf-8"))
    *parents, last = [int(k) if k.isdigit() else k for k in path.split(".")]
    node = data
    for key in parents:
        node = node[key]
    if value == "DELETE":
        del node[last]
    else:
        node[last] = value
    return data


@pytest.mark.parametrize(
    ("case", "path", "value", "message"),
    [
        (HEAT_CASE, "kiln.length", "DELETE", "kiln.length: missing (required)"),
        (HEAT_CASE, "kiln.length", None, "kiln.length: empty, expected a length (m, cm, mm)"),
        (HEAT_CASE, "kiln", [1, 2], "kiln: [1, 2] is not a mapping of keys"),
        (HEAT_CASE, "name", 12, "name: 12 is not a text (in quotes if it looks like a number)"),
        (HEAT_CASE, "wall.lining", {"a": 1}, "wall.lining: {'a': 1} is not a list"),
        (FLAME_CASE, "closures.radiation", 1.5, "closures.radiation: 1.5 is not true"),
        (
            FLAME_CASE,
            "closures.gas_emissivity",
            [1],
            "closures.gas_emissivity: [1] is not a text (in quotes if it looks like a "
            "number) or a number",
        ),
        (
            HEAT_CASE,
            "wall.lining.2.absent.0",
            [1, 2, 3],
            "wall.lining.2.absent.0: [1, 2, 3] is not a list of at most 2 items",
        ),
        (HEAT_CASE, "material.solid", "", 'material.solid: "" is not one of charcoal, lime,'),
        (
            HEAT_CASE,
            "measurements.z_gas",
            "abc",
            'measurements.z_gas: "abc" is not a list',
        ),
        (
            "limestone_calcination",
            "material.composition.CaCO3",
            "abc",
            'material.composition.CaCO3: "abc" is not a number in [0, 1]',
        ),
        (
            "limestone_calcination",
            "material.composition.CaCO3",
            None,
            "material.composition.CaCO3: empty, expected a number in [0, 1]",
        ),
        (
            "limestone_calcination",
            "chemistry.gas_gain_per_carbon",
            "both",
            'chemistry.gas_gain_per_carbon: "both" is not one of corrected, faithful',
        ),
        (
            "limestone_calcination",
            "chemistry.onset_width",
            "",
            'chemistry.onset_width: "" is not a number >= 0',
        ),
    ],
)
def test_messages_name_the_field_the_value_and_what_is_accepted(case, path, value, message):
    with refused_quickly(message) as info:
        parse_case(mutated(case, path, value))
    assert not any(text in str(info.value) for text in PYDANTIC_TEXT)


def test_transport_messages_are_english():
    with refused_quickly('transport.friction: "wet" is not zero, dynamic, static or a number'):
        parse_case({**SMALL, "transport": {"model": "scott", "friction": "wet"}})
    with refused_quickly('transport.model: "x" is not one of kramers, scott'):
        parse_case({**SMALL, "transport": {"model": "x"}})


def test_missing_values_of_lower_layers_read_missing_required():
    assert str(InputError("rtd", "missing", "an rtd: section in the case")) == (
        "rtd: missing (required: an rtd: section in the case)"
    )
    assert str(InputError("x.value", "missing", "given")) == "x.value: missing (required)"
    assert str(InputError("heat", None, "present (the case has no heat: section)")) == (
        "heat: missing (required: the case has no heat: section)"
    )


def test_measurement_lists_of_unequal_length_refused_at_load():
    import yaml

    from rotarykiln.cases import builtin_case_path

    data = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    data["measurements"]["t_bed"] = data["measurements"]["t_bed"][:-1]
    with pytest.raises(InputError, match="z_bed has 5 positions but t_bed 4 temperatures"):
        parse_case(data)


@pytest.mark.parametrize("angle", ["200 deg", "0 deg"])
def test_half_angle_out_of_range_says_degrees(angle, capsys):
    from rotarykiln import cli

    assert cli.main(["geometry", "--diameter", "0.4", "m", "--half-angle", *angle.split()]) == 2
    err = capsys.readouterr().err
    assert f"--half-angle: {angle} is not in (0, 180) deg" in err


def test_out_folder_checked_writable_before_solving(tmp_path, monkeypatch, capsys):
    from rotarykiln import cli, outputs

    (tmp_path / "out").mkdir()  # an existing folder (a missing one is created at the commit)
    monkeypatch.setattr(outputs.os, "access", lambda path, mode: False)  # a read-only folder
    code = cli.main(["run", "tscheng_A16", "--out", str(tmp_path / "out")])
    err = capsys.readouterr().err
    assert code == 2 and "--out: cannot write in" in err and "Traceback" not in err
    assert not any((tmp_path / "out").iterdir())  # nothing solved, nothing written
    long = tmp_path / ("x" * 300)
    assert cli.main(["run", "tscheng_A16", "--out", str(long)]) == 2


@pytest.mark.parametrize(
    ("path", "value", "field"),
    [
        (("kiln", "length"), "1e-308 m", "kiln.length"),
        (("kiln", "length"), "1e300 m", "kiln.length"),
        (("operation", "feed"), "1e300 kg/h", "operation.feed"),
        (("operation", "speed"), "1e-308 rpm", "operation.speed"),
        (("gas", "temperature"), "1e-308 K", "gas.temperature"),
        (("gas", "temperature"), "1e300 K", "gas.temperature"),
        (("material", "bulk_density"), "1e300 kg/m3", "material.bulk_density"),
    ],
)
def test_extreme_values_never_reach_a_solver(path, value, field):
    import yaml

    from rotarykiln.cases import builtin_case_path

    data = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    node = data
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    with pytest.raises(InputError, match=re.escape(field) + r".* is not in \["):
        parse_case(data)


@pytest.mark.parametrize("name", ["../../escape", "/tmp/x", "a/b", ".hidden"])
def test_sweep_name_cannot_write_outside_out(name, tmp_path, capsys):
    from rotarykiln import cli

    argv = ["sweep", "--case", "tscheng_A16", "--model", "heat"]
    argv += ["--grid", "operation.speed=1 rpm,2 rpm", "--out", str(tmp_path), "--name", name]
    assert cli.main(argv) == 2
    assert "--name" in capsys.readouterr().err
    assert not any(tmp_path.iterdir())


def test_zero_speed_and_endless_durations_refused(capsys):
    from rotarykiln import cli

    assert cli.main(["regime", "--diameter", "6", "m", "--speed", "0", "rpm", "--fill", "0.3"]) == 2
    assert "--speed: 0 rpm is not > 0" in capsys.readouterr().err
    assert cli.main(["transverse", "retort/case02", "--duration", "5", "fortnights"]) == 2
    assert "--duration: 5 fortnights is not in (0, 1 h]" in capsys.readouterr().err
