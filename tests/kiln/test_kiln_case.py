"""The heat: section of case files and the run_heat_case / heat_runner entry points."""

import json

import matplotlib
import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.kiln.run import heat_kiln_from_case, heat_runner, run_heat_case
from rotarykiln.kiln.solve import solve_kiln
from rotarykiln.kiln.tscheng import insulation_thickness, tscheng_kiln

matplotlib.use("Agg")


def _data(name):
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def test_builtin_tscheng_case_equals_module_setup():
    # the YAML case and the programmatic set-up of run A16 describe the same kiln
    data = _data("tscheng_A16")
    assert data["heat"]["lining"][2]["thickness"] == f"{insulation_thickness() * 1000:.2f} mm"
    a = run_heat_case(parse_case(data))
    b = solve_kiln(tscheng_kiln("A16"))
    assert np.max(np.abs(a.t_bed_nodes - b.t_bed_nodes)) < 0.05  # radius 0.1885/2 vs 0.09425
    assert a.measurements["t_bed"].tolist() == [341, 356, 374, 417, 473]


def test_flame_case_runs_and_writes(tmp_path):
    case = parse_case(_data("ubc_pilot_flame"))
    summary = heat_runner(case, tmp_path)
    for name in ("heat_profiles.csv", "heat_summary.json", "heat_profiles.png"):
        assert (tmp_path / name).is_file()
    assert abs(summary["heat_energy_balance_closure"]) < 1e-6
    assert json.loads((tmp_path / "heat_summary.json").read_text())["heat_cells"] == 100
    assert (tmp_path / "heat_profiles.png").stat().st_size < 200_000


@pytest.mark.parametrize(
    "path, value, message",
    [
        (("heat", "lining", 0, "thickness"), "0 mm", "heat.lining.0.thickness"),
        (("heat", "gas", "flow"), "-3 kg/h", "heat.gas.flow"),
        (("heat", "wall_emissivity"), 1.5, "heat.wall_emissivity"),
        (("heat", "closures", "radiation"), "maybe", "heat.closures.radiation"),
    ],
)
def test_bad_heat_sections(path, value, message):
    data = _data("tscheng_A16")
    node = data
    for key in path[:-1]:
        node = node.setdefault(key, {}) if isinstance(node, dict) else node[key]
    node[path[-1]] = value
    with pytest.raises(InputError, match=message.replace(".", r"\.")):
        parse_case(data)


def test_bad_heat_values_at_model_level():
    data = _data("tscheng_A16")
    data["heat"]["closures"] = {"gas_wall": "dittus"}
    with pytest.raises(InputError, match="heat.closures.gas_wall"):
        heat_kiln_from_case(parse_case(data))
    data = _data("tscheng_A16")
    data["heat"]["gas"]["flow"] = "0 kg/h"
    with pytest.raises(InputError, match="heat.gas_flow"):
        heat_kiln_from_case(parse_case(data))
    data = _data("tscheng_A16")
    data["heat"]["lining"][0]["material"] = "cheese"
    # caught by the case schema now, at its full path
    with pytest.raises(InputError, match=r"heat\.lining\.0\.material"):
        heat_kiln_from_case(parse_case(data))
    data = _data("tscheng_A16")
    del data["operation"]["feed"]
    with pytest.raises(InputError, match="operation.feed"):
        heat_kiln_from_case(parse_case(data))


def test_cli_run_with_heat_runner(tmp_path, monkeypatch, capsys):
    # how the lead wires the section: RUNNERS["heat"] = "rotarykiln.kiln.run:heat_runner"
    from rotarykiln import cli
    from rotarykiln.commands import run as run_cmd

    monkeypatch.setitem(run_cmd.RUNNERS, "heat", "rotarykiln.kiln.run:heat_runner")
    case_path = builtin_case_path("tscheng_A16")
    code = cli.main(["run", str(case_path), "--out", str(tmp_path), "--json"])
    assert code == 0
    summary = json.loads(capsys.readouterr().out)
    assert abs(summary["heat_energy_balance_closure"]) < 1e-6
    assert (tmp_path / "heat_profiles.csv").is_file()
    assert (tmp_path / "heat_profiles.png").is_file()


def test_heat_kiln_is_picklable():
    # studies may ship kilns to worker processes (dask)
    import pickle

    data = _data("ubc_pilot_flame")
    data["heat"]["burner"].update(combustion="burnout", flame_length="1 m")
    kiln, _ = heat_kiln_from_case(parse_case(data))
    clone = pickle.loads(pickle.dumps(kiln))
    assert clone.heat_release == kiln.heat_release
    z = np.linspace(0, kiln.length, 7)
    assert np.array_equal(clone.heat_release_profile(z), kiln.heat_release_profile(z))
