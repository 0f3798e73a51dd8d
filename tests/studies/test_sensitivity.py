"""Sobol and Morris indices through the study runner."""

import json
import math

import numpy as np
import pytest
import yaml

from rotarykiln.cli import main
from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.studies.examples import failing_model, ishigami
from rotarykiln.studies.sensitivity import morris_indices, sobol_indices

PI = math.pi
PARAMS = [f"x{i}=uniform({-PI}, {PI})" for i in (1, 2, 3)]
BASE = {"x1": 0.0, "x2": 0.0, "x3": 0.0}
S1 = [0.3139, 0.4424, 0.0]
ST = [0.5576, 0.4424, 0.2437]


def test_ishigami_sobol_indices_through_the_runner_match_the_analytic_values(tmp_path):
    res = sobol_indices(
        ishigami,
        BASE,
        PARAMS,
        "y",
        n=1024,
        executor="process",
        max_workers=2,
        store=tmp_path / "runs",
    )
    idx = res.indices
    assert len(res.sweep.frame) == 1024 * 5 and res.sweep.n_failed == 0
    for i, name in enumerate(["x1", "x2", "x3"]):
        assert abs(idx.loc[name, "S1"] - S1[i]) <= idx.loc[name, "S1_conf"], name
        assert abs(idx.loc[name, "ST"] - ST[i]) <= idx.loc[name, "ST_conf"], name
    assert idx["S1"].sum() <= 1.0 + idx["S1_conf"].max()
    assert res.ranking() == ["x1", "x2", "x3"]
    # the cases are stored: the same study again runs nothing and gives the same indices
    again = sobol_indices(
        ishigami, BASE, PARAMS, "y", n=1024, executor="serial", store=tmp_path / "runs"
    )
    assert again.sweep.meta["ran"] == 0
    assert np.allclose(again.indices["ST"], idx["ST"])


def test_morris_screens_x1_first_and_plots(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    res = morris_indices(ishigami, BASE, PARAMS, "y", n=30, executor="serial")
    assert len(res.sweep.frame) == 30 * 4
    assert res.ranking()[0] == "x1"
    assert abs(res.indices.loc["x2", "mu"]) < 0.2 * res.indices.loc["x2", "mu_star"]  # sin^2
    assert res.save_plot(tmp_path / "m.png").stat().st_size > 5000


def test_bad_output_and_failed_cases():
    with pytest.raises(InputError, match="did you mean y"):
        sobol_indices(ishigami, BASE, PARAMS, "yy", n=4, executor="serial")
    with pytest.raises(InputError, match="power of 2"):
        sobol_indices(ishigami, BASE, PARAMS, "y", n=1, executor="serial")
    with pytest.raises(ConvergenceError, match="cases failed"):
        sobol_indices(failing_model, {"x": 1.0}, ["x=uniform(-1, 1)"], "y", n=8, executor="serial")


def test_sensitivity_command_on_the_kiln_model(tmp_path, capsys):
    out = tmp_path / "sens"
    args = [
        "sensitivity",
        "tscheng_A16",
        "--model",
        "kiln",
        "--method",
        "sobol",
        "--param",
        "operation.speed=uniform(1 rpm, 3 rpm)",
        "--param",
        "gas.temperature=normal(535 K, 10 K)",
        "--output",
        "bed_outlet_temperature_K",
        "--n",
        "4",
        "--executor",
        "serial",
        "--out",
        str(out),
        "--json",
    ]
    assert main(args) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["cases"] == 16 and summary["ranking"][0] == "gas.temperature"
    assert (out / "indices.csv").is_file() and (out / "sensitivity.png").is_file()
    assert len(list((out / "runs").glob("part-*.parquet"))) >= 1
    assert main([*args[:-1], "--output", "bed_outlet"]) == 2
    assert "did you mean" in capsys.readouterr().err


def test_sensitivity_command_morris_with_a_case_file(tmp_path, capsys):
    case = tmp_path / "ishigami.yaml"
    case.write_text(yaml.safe_dump(BASE))
    args = [
        "sensitivity",
        str(case),
        "--model",
        "rotarykiln.studies.examples:ishigami",
        "--method",
        "morris",
        "--output",
        "y",
        "--n",
        "10",
        "--executor",
        "serial",
        "--out",
        str(tmp_path / "m"),
    ]
    for p in PARAMS:
        args += ["--param", p]
    assert main(args) == 0
    assert "morris indices of y from 40 cases" in capsys.readouterr().out
