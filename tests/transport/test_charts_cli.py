import json

import numpy as np
import pytest

from rotarykiln.case import parse_case
from rotarykiln.cli import main
from rotarykiln.transport.charts import design_chart

ARGS = (
    "bed --diameter 0.4 m --length 2 m --speed 3 rpm --slope 1 deg --feed 62 kg/h "
    "--density 1500 kg/m3 --repose 35 deg"
).split()


def test_design_chart_matches_regenerated_table():
    # notes 002 section 4: tau 41.87 min at y/R 0.2, 61.33 at 1.0; q 28.72 m3/h at 0.2
    c = design_chart(36.6, 3.66, np.pi / 30, np.radians(3), np.radians(40), density=1600, n=5)
    assert c.residence_time[0] / 60 == pytest.approx(41.87, abs=0.01)
    assert c.residence_time[-1] / 60 == pytest.approx(61.33, abs=0.01)
    assert c.flow[0] * 3600 == pytest.approx(28.72, abs=0.01)
    assert c.mass_flow[0] * 3.6 == pytest.approx(45.95, abs=0.02)
    # spread candidate of notes 002 (y/R = 0.2: sd 1.75 min, mean 44.33 = hold-up based)
    assert c.residence_time_std[0] / 60 == pytest.approx(1.75, abs=0.02)
    assert c.residence_time_holdup[0] / 60 == pytest.approx(44.33, abs=0.02)
    assert len(c.to_frame()) == 5


def test_design_chart_plot():
    import matplotlib

    matplotlib.use("Agg")
    fig = design_chart(36.6, 3.66, np.pi / 30, np.radians(3), np.radians(40)).plot()
    assert len(fig.axes) == 2


def test_cli_bed_kramers_json(capsys):
    assert main(ARGS + ["--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["model"] == "kramers"
    assert out["holdup_mass_kg"] == pytest.approx(out["mean_residence_time_s"] * 62 / 3600)


def test_cli_bed_scott_with_dam_writes_files(tmp_path, capsys):
    code = main(ARGS + ["--model", "scott", "--dam", "0.05", "m", "--out", str(tmp_path)])
    assert code == 0
    assert {p.name for p in tmp_path.iterdir()} >= {"profile.csv", "profile.png", "summary.json"}
    assert "mean_fill" in capsys.readouterr().out


@pytest.mark.parametrize(
    "extra,match",
    [
        (["--dam", "0.2", "m"], "drum radius"),
        (["--slope", "40", "deg"], "slope"),
        (["--feed", "6000", "kg/h", "--slope", "0", "deg"], "no steady solution"),
    ],
)
def test_cli_bed_bad_input(extra, match, capsys):
    # later options override earlier ones (argparse)
    assert main(list(ARGS) + extra) == 2
    assert match in capsys.readouterr().err


def test_case_transport_section(tmp_path):
    case = parse_case(
        {
            "kiln": {"length": "2 m", "diameter": "0.4 m", "slope": "1 deg"},
            "operation": {"speed": "3 rpm", "feed": "62 kg/h"},
            "material": {"bulk_density": "1500 kg/m3", "repose_angle": "35 deg"},
            "transport": {
                "model": "scott",
                "dam_height": "5 cm",
                "weirs": [{"position": "1 m", "height": "6 cm"}],
            },
        }
    )
    from rotarykiln.commands.bed import run_case_section

    res = run_case_section(case, tmp_path)
    assert 0 < res["transport_mean_fill"] < 0.5
    assert (tmp_path / "profile.csv").exists()


def test_run_case_with_transport_section(tmp_path, capsys):
    case = tmp_path / "kiln.yaml"
    case.write_text(
        "name: pilot\n"
        "kiln: {length: 2 m, diameter: 0.4 m, slope: 1 deg}\n"
        "operation: {speed: 3 rpm, feed: 62 kg/h}\n"
        "material: {bulk_density: 1500 kg/m3, repose_angle: 35 deg}\n"
        "transport: {model: kramers, dam_height: 5 cm}\n"
    )
    out = tmp_path / "res"
    assert main(["run", str(case), "--out", str(out), "--no-plots", "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["transport_model"] == "kramers"
    assert (out / "profile.csv").exists()


def test_case_transport_section_rejects_unknown_model():
    from rotarykiln.errors import InputError

    with pytest.raises(InputError, match="transport"):
        parse_case(
            {
                "kiln": {"length": "2 m", "diameter": "0.4 m"},
                "operation": {"speed": "3 rpm"},
                "transport": {"model": "bogus"},
            }
        )
