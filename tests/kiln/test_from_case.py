"""Kiln cases (gas, burner, wall sections) and the run_kiln_case / kiln_runner entry points."""

import json

import matplotlib
import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import kiln_runner
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln

matplotlib.use("Agg")


def _data(name):
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def test_flame_case_runs_and_writes(tmp_path):
    case = parse_case(_data("ubc_pilot_flame"))
    summary = kiln_runner(case, tmp_path)
    for name in ("kiln_profiles.csv", "kiln_summary.json", "kiln_profiles.png"):
        assert (tmp_path / name).is_file()
    assert abs(summary["kiln_energy_balance_closure"]) < 1e-6
    assert json.loads((tmp_path / "kiln_summary.json").read_text())["kiln_cells"] == 100
    assert (tmp_path / "kiln_profiles.png").stat().st_size < 200_000


@pytest.mark.parametrize(
    "path, value, message",
    [
        (("wall", "lining", 0, "thickness"), "0 mm", "wall.lining.0.thickness"),
        (("gas", "flow"), "-3 kg/h", "gas.flow"),
        (("wall", "emissivity"), 1.5, "wall.emissivity"),
        (("closures", "radiation"), "maybe", "closures.radiation"),
        (("closures", "preset"), "seed005", "closures.preset"),
        (("operation", "counter_current"), "sideways", "operation.counter_current"),
    ],
)
def test_bad_kiln_sections(path, value, message):
    data = _data("tscheng_A16")
    node = data
    for key in path[:-1]:
        node = node.setdefault(key, {}) if isinstance(node, dict) else node[key]
    node[path[-1]] = value
    with pytest.raises(InputError, match=message.replace(".", r"\.")):
        parse_case(data)


def test_bad_kiln_values_at_model_level():
    data = _data("tscheng_A16")
    data["closures"] = {"gas_wall": "dittus"}
    with pytest.raises(InputError, match="closures.gas_wall"):
        kiln_from_case(parse_case(data))
    data = _data("tscheng_A16")
    data["gas"]["flow"] = "0 kg/h"
    with pytest.raises(InputError, match="gas.flow"):
        kiln_from_case(parse_case(data))
    data = _data("tscheng_A16")
    data["wall"]["lining"][0]["material"] = "cheese"
    # caught by the case schema now, at its full path
    with pytest.raises(InputError, match=r"wall\.lining\.0\.material"):
        kiln_from_case(parse_case(data))
    data = _data("tscheng_A16")
    del data["operation"]["feed"]
    with pytest.raises(InputError, match="operation.feed"):
        kiln_from_case(parse_case(data))


def test_cli_run_writes_the_kiln_files(tmp_path, capsys):
    from rotarykiln import cli

    case_path = builtin_case_path("tscheng_A16")
    code = cli.main(["run", str(case_path), "--out", str(tmp_path), "--json"])
    assert code == 0
    summary = json.loads(capsys.readouterr().out)
    assert abs(summary["kiln_energy_balance_closure"]) < 1e-6
    assert (tmp_path / "kiln_profiles.csv").is_file()
    assert (tmp_path / "kiln_profiles.png").is_file()


def test_fired_kiln_is_picklable():
    # studies may ship kilns to worker processes (dask)
    import pickle

    data = _data("ubc_pilot_flame")
    data["burner"].update(combustion="burnout", flame_length="1 m")
    kiln, _ = kiln_from_case(parse_case(data))
    clone = pickle.loads(pickle.dumps(kiln))
    assert clone.firing.heat_release == kiln.firing.heat_release
    z = np.linspace(0, kiln.drum.length, 7)
    assert np.array_equal(clone.firing.profile(z), kiln.firing.profile(z))


def test_wall_needs_lining_or_u_and_gas_or_burner():
    data = _data("tscheng_A16")
    data["wall"]["U"] = "5 W/m2/K"
    with pytest.raises(InputError, match="wall: give lining .* or jacket, one of them"):
        parse_case(data)
    data = _data("tscheng_A16")
    del data["wall"]
    with pytest.raises(InputError, match="wall: missing"):
        kiln_from_case(parse_case(data))
    data = _data("tscheng_A16")
    data["gas"]["mass_fractions"] = {"N2": 1.0}
    with pytest.raises(InputError, match="composition .* or mass_fractions, not both"):
        parse_case(data.copy() | {"gas": {**data["gas"], "composition": "N2:1"}})
    data = _data("ubc_pilot_flame")
    data["gas"] = {"flow": "10 kg/h", "temperature": "900 K"}
    with pytest.raises(InputError, match="gas.flow.*burner"):
        kiln_from_case(parse_case(data))


def test_gas_by_mass_or_mole_fractions_builds_the_same_kiln():
    data = _data("tscheng_A16")
    a, _ = kiln_from_case(parse_case(data))
    total = sum(a.gas.flows.values())
    data["gas"]["mass_fractions"] = {k: v / total for k, v in a.gas.flows.items()}
    b, _ = kiln_from_case(parse_case(data))
    assert a.gas.flows.keys() == b.gas.flows.keys()
    for k in a.gas.flows:
        assert b.gas.flows[k] == pytest.approx(a.gas.flows[k], rel=1e-9)


JACKET = {"flow": "175 kg/h", "temperature": "833 K", "specific_heat": "1227 J/kg/K"}


@pytest.mark.parametrize(
    "wall, message",
    [
        ({"jacket": JACKET, "U": "5 W/m2/K"}, "lining .*, U .* or jacket, one of them"),
        ({"jacket": {**JACKET, "composition": "N2:1"}}, "specific_heat or composition"),
        ({"jacket": {k: v for k, v in JACKET.items() if k != "specific_heat"}}, "one of them"),
        ({"jacket": {**JACKET, "heat_transfer": "magic"}}, "wall.jacket.heat_transfer"),
        (
            {"jacket": JACKET, "heaters": [{"start": "0 m", "end": "1 m", "power": "1 kW"}]},
            "heaters need a lining",
        ),
    ],
)
def test_bad_jackets_are_refused(wall, message):
    data = _data("rotary_pyrolysis")
    data["wall"] = wall
    with pytest.raises(InputError, match=message):
        parse_case(data)


def test_counter_current_jacket_from_a_case_closes():
    from rotarykiln.kiln.wall.jacket import jacket_balance

    data = _data("rotary_pyrolysis")
    data["wall"]["jacket"].update(counter_current=True, heat_transfer="annulus", gap="50 mm")
    data["solver"] = {"cells": 40}
    kiln, cells = kiln_from_case(parse_case(data))
    sol = solve_kiln(kiln, cells)
    assert abs(sol.energy_closure) < 1e-6
    assert abs(jacket_balance(kiln, sol)["closure_relative"]) < 1e-6
