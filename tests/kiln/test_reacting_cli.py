"""``rotarykiln run CASE.yaml`` on reacting cases: results, and bad input refused at load."""

import json

import matplotlib
import pytest
import yaml

from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main

matplotlib.use("Agg")


def _data(name):
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def _run(capsys, tmp_path, data, *extra):
    path = tmp_path / "case.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    code = main(["run", str(path), "--out", str(tmp_path / "out"), *extra])
    out, err = capsys.readouterr()
    return code, out, err


def test_run_limestone_case_from_the_cli(capsys, tmp_path):
    code, out, _ = _run(capsys, tmp_path, _data("limestone_calcination"), "--json")
    assert code == 0
    s = json.loads(out)
    assert s["kiln_conversion_CaCO3"] == pytest.approx(1.0)
    assert abs(s["kiln_energy_balance_closure"]) < 1e-6
    assert s["kiln_element_balance_closure"] < 1e-8
    assert (tmp_path / "out" / "kiln_profiles.png").exists()


def _bad(data, path, value):
    node = data
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return data


@pytest.mark.parametrize(
    ("path", "value", "message"),
    [
        (
            ["material", "composition"],
            {"H2O(l)": -0.1, "CaCO3": 0.9},
            "material.composition.H2O(l): -0.1 is not a mass fraction",
        ),
        (
            ["material", "composition"],
            {"H2O(l)": 0.2, "CaCO3": 0.9},
            "material.composition: the fractions sum to 1.1, expected 1",
        ),
        (
            ["material", "composition"],
            {"H2O(l)": 0.1, "CaCO4": 0.9},
            '"CaCO4" is not a known species',
        ),
        (
            ["gas", "mass_fractions"],
            {"N2": 0.7, "CO2": 0.3, "unobtainium": 0.0},
            '"unobtainium" is not a known species',
        ),
        (
            ["chemistry", "reactions"],
            [
                {
                    "name": "half_calcination",
                    "stoichiometry": {"CaCO3": -1, "CaO": 1},
                    "basis": "CaCO3",
                    "rate": {"law": "luisser_calcination"},
                    "heat": "1.7 MJ/kg",
                }
            ],
            "half_calcination.stoichiometry",
        ),
        (["chemistry", "reactions"], ["calcination_by_magic"], "is not a built-in reaction"),
    ],
)
def test_bad_input_refused_at_load(capsys, tmp_path, path, value, message):
    data = _bad(_data("limestone_calcination"), path, value)
    code, out, err = _run(capsys, tmp_path, data)
    assert code == 2
    assert message in err
    assert len(err.strip().splitlines()) == 1  # one clear line
    assert not (tmp_path / "out" / "kiln_profiles.csv").exists()


def test_unbalanced_reaction_message_names_the_atoms(capsys, tmp_path):
    data = _bad(
        _data("limestone_calcination"),
        ["chemistry", "reactions"],
        [
            "drying_ahmad",
            {
                "name": "leaky",
                "stoichiometry": {"CaCO3": -1, "CaO": 1, "CO": 1},
                "basis": "CaCO3",
                "rate": {"law": "luisser_calcination"},
                "heat": "1.7 MJ/kg",
            },
        ],
    )
    code, _, err = _run(capsys, tmp_path, data)
    assert code == 2
    assert "O -1 atoms per event" in err and "element-balanced" in err


def test_sweep_command_with_the_kiln_model(capsys, tmp_path):
    code = main(
        [
            "sweep",
            "--case",
            "charcoal_activation",
            "--model",
            "kiln",
            "--oat",
            "gas.steam_flow=0.0025 kg/s,0.0075 kg/s",
            "--workers",
            "2",
            "--out",
            str(tmp_path),
            "--name",
            "steam",
            "--json",
        ]
    )
    out, _ = capsys.readouterr()
    assert code == 0
    rows = json.loads(out)
    burn = {r["gas.steam_flow"]: r["burn_off_percent"] for r in rows}
    assert burn["0.0025 kg/s"] < burn["0.0075 kg/s"]  # steam is a reactant (seed 004 Fig. 5.4)
    assert (tmp_path / "steam.csv").exists() and (tmp_path / "steam.png").exists()
