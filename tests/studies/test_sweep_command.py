import json

import pytest

from rotarykiln.cli import main
from rotarykiln.errors import InputError

MODEL = "rotarykiln.studies.examples:ortiz_isothermal_burn_off"


def test_sweep_command_writes_table_and_plot(tmp_path, capsys):
    rc = main(
        [
            "sweep",
            "--case",
            "charcoal_activation",
            "--model",
            MODEL,
            "--executor",
            "serial",
            "--oat",
            "chemistry.residence_time=3000 s,6480 s",
            "--out",
            str(tmp_path),
            "--json",
        ]
    )
    assert rc == 0
    rows = json.loads(capsys.readouterr().out)
    assert len(rows) == 3 and rows[0]["group"] == "base"
    assert rows[2]["burn_off"] > rows[1]["burn_off"]
    assert (tmp_path / "sweep.csv").is_file() and (tmp_path / "sweep.png").is_file()


def test_sweep_command_bad_arguments():
    from rotarykiln.commands.sweep import _load_model, _ranges

    with pytest.raises(InputError, match="PATH=V1"):
        _ranges(["novalues"], "--grid")
    with pytest.raises(InputError, match="module:function"):
        _load_model("nocolon")
    with pytest.raises(InputError, match="importable"):
        _load_model("rotarykiln.studies:nothing_here")
    assert main(["sweep", "--case", "charcoal_activation", "--model", MODEL]) == 2


def test_sweep_command_sampled_design_resumes_and_fails_loudly(tmp_path, capsys):
    args = ["sweep", "--case", "charcoal_activation", "--model", MODEL, "--executor", "serial"]
    args += ["--lhs", "6", "--param", "chemistry.residence_time=uniform(3000 s, 9000 s)"]
    assert main([*args, "--out", str(tmp_path)]) == 0
    assert "6 run now, 0 from the store" in capsys.readouterr().out
    assert main([*args, "--out", str(tmp_path)]) == 0
    assert "0 run now, 6 from the store" in capsys.readouterr().out
    bad = ["sweep", "--case", "charcoal_activation", "--model", MODEL, "--executor", "serial"]
    bad += ["--grid", "chemistry.residence_time=3000 s,fast", "--out", str(tmp_path / "b")]
    assert main(bad) == 1
    assert "1 of 2 cases failed" in capsys.readouterr().err
    assert main([*args[:-2], "--param", "chemistry.residence_tme=uniform(1 s, 2 s)"]) == 2
    assert "did you mean chemistry.residence_time" in capsys.readouterr().err
