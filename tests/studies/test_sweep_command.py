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


def test_sweep_command_writes_no_plot_when_asked(tmp_path, capsys):
    args = ["sweep", "--case", "charcoal_activation", "--model", MODEL, "--executor", "serial"]
    args += ["--oat", "bed.residence_time=3000 s,6480 s", "--out", str(tmp_path), "--no-plots"]
    assert main(args) == 0
    assert (tmp_path / "sweep.csv").is_file() and not (tmp_path / "sweep.png").exists()


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


TRANSPORT = [
    "sweep",
    "--case",
    "charcoal_activation_kramers",
    "--model",
    "transport",
    "--executor",
    "serial",
    "--grid",
    "operation.speed=1 rpm,2 rpm,4 rpm",
]


def _rows(out: str) -> list[list[str]]:
    """The data rows of a printed sweep table (a case number first), split on blanks."""
    return [line.split() for line in out.splitlines() if line[:6].strip().isdigit()]


def test_sweep_prints_only_the_chosen_outputs_with_speed_in_rpm(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    argv = [*TRANSPORT, "--output", "mean_residence_time_min", "--out", str(tmp_path)]
    assert main(argv) == 0
    out = capsys.readouterr().out
    rows = _rows(out)
    assert [r[0] for r in rows] == ["0", "1", "2"]
    assert all(len(r) == 3 for r in rows)  # case, speed, the one chosen output
    assert [r[1] for r in rows] == ["1", "2", "4"]  # as typed, in rpm
    assert "[rpm]" in out and "rad/s" not in out
    assert "holdup" not in out and "discharge" not in out and "mean_fill" not in out
    assert all(len(line) <= 80 for line in out.splitlines() if str(tmp_path) not in line)
    # the bed depth follows the transport model: a faster kiln holds its solids a shorter time
    minutes = [float(r[2]) for r in rows]
    assert minutes[0] > 2.0 * minutes[2]
    # the files hold every output, values as given and in SI
    import pandas as pd

    table = pd.read_csv(tmp_path / "sweep.csv", keep_default_na=False)
    assert {"mean_fill", "holdup_kg", "discharge_fill", "operation.speed [SI]"} <= set(table)
    assert (tmp_path / "sweep.png").is_file()


def test_sweep_default_outputs_fit_the_terminal(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "100")
    argv = [
        *TRANSPORT[:-1],
        "operation.speed=1 rpm,3 rpm",
        "--grid",
        "transport.dam_height=2 cm,5 cm",
    ]
    assert main(argv) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    assert all(len(line) <= 100 for line in lines)
    rows = _rows(out)
    assert len(rows) == 4 and all(len(r) == 1 + 2 + 4 for r in rows)  # the 4 transport outputs
    assert "[cm]" in out and [r[2] for r in rows] == ["2", "5", "2", "5"]


def test_sweep_wrong_output_name_is_one_line_naming_the_outputs(tmp_path, capsys):
    assert main([*TRANSPORT, "--output", "mean_residence_time", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "--output: mean_residence_time is not an output of the model (" in err
    for name in ("mean_fill", "holdup_kg", "mean_residence_time_min", "discharge_fill"):
        assert name in err
    assert "did you mean mean_residence_time_min?" in err
    assert not (tmp_path / "sweep.csv").exists()
    # the cases were stored: the right name now runs nothing again
    assert main([*TRANSPORT, "--output", "holdup_kg", "--out", str(tmp_path)]) == 0
    assert "0 run now, 3 from the store" in capsys.readouterr().out
