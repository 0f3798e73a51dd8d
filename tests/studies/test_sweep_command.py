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
            "bed.residence_time=3000 s,6480 s",
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
    args += ["--lhs", "6", "--param", "bed.residence_time=uniform(3000 s, 9000 s)"]
    assert main([*args, "--out", str(tmp_path)]) == 0
    assert "6 run now, 0 from the store" in capsys.readouterr().out
    assert main([*args, "--out", str(tmp_path)]) == 0
    assert "0 run now, 6 from the store" in capsys.readouterr().out
    bad = ["sweep", "--case", "charcoal_activation", "--model", MODEL, "--executor", "serial"]
    bad += ["--grid", "bed.residence_time=3000 s,fast", "--out", str(tmp_path / "b")]
    assert main(bad) == 1
    assert "1 of 2 cases failed" in capsys.readouterr().err
    assert main([*args[:-2], "--param", "bed.residence_tme=uniform(1 s, 2 s)"]) == 2
    assert "did you mean bed.residence_time" in capsys.readouterr().err


def test_sweep_command_unreachable_scheduler_is_one_line(tmp_path, capsys, monkeypatch):
    import rotarykiln.studies.runner as runner

    real = runner.dask_client
    monkeypatch.setattr(runner, "dask_client", lambda s, w, t: real(s, w, 1.0))
    args = [
        "sweep",
        "--case",
        "charcoal_activation",
        "--model",
        MODEL,
        "--executor",
        "dask",
        "--scheduler",
        "tcp://127.0.0.1:9",
        "--grid",
        "bed.residence_time=3000 s",
        "--out",
        str(tmp_path),
    ]
    assert main(args) == 2
    err = capsys.readouterr().err.strip()
    assert "reachable Dask scheduler" in err and len(err.splitlines()) == 1
    assert main([*args[:5], "--executor", "process", *args[7:]]) == 2  # --scheduler needs dask
