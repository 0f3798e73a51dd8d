import pytest
import yaml

from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main
from rotarykiln.studies import grid, run_sweep
from rotarykiln.studies.models import MODELS, kiln_model, transport_model


def _case(name):
    return yaml.safe_load(builtin_case_path(name).read_text())


def test_kiln_model_sweep_hotter_gas_heats_the_bed_more():
    res = run_sweep(
        kiln_model,
        _case("tscheng_A16"),
        grid({"gas.temperature": ["500 K", "600 K"]}),
        executor="serial",
    )
    frame = res.frame
    assert res.n_failed == 0
    assert all(abs(v) < 1e-6 for v in frame["energy_balance_closure"])
    assert frame["bed_outlet_temperature_K"].iloc[1] > frame["bed_outlet_temperature_K"].iloc[0]


def test_transport_model_residence_time_rises_with_a_dam():
    base = _case("tscheng_A16")
    base["transport"] = {"model": "kramers"}
    open_end = transport_model(base)
    base["transport"] = {"model": "kramers", "dam_height": "4 cm"}
    dammed = transport_model(base)
    assert dammed["mean_residence_time_min"] > open_end["mean_residence_time_min"]
    assert dammed["mean_fill"] > open_end["mean_fill"]


def test_sweep_cli_accepts_model_names(capsys, tmp_path):
    assert set(MODELS) >= {"kiln", "kiln_profiles", "transport"}
    code = main(
        [
            "sweep",
            "--case",
            "tscheng_A16",
            "--model",
            "kiln",
            "--grid",
            "operation.speed=1 rpm,2 rpm",
            "--executor",
            "serial",
            "--out",
            str(tmp_path),
        ]
    )
    assert code == 0
    assert (tmp_path / "sweep.csv").exists()
    code = main(["sweep", "--case", "tscheng_A16", "--model", "nonsense", "--grid", "a=1"])
    assert code == 2
    assert "a model name" in capsys.readouterr().err


@pytest.mark.parametrize("name", sorted(MODELS))
def test_models_are_documented(name):
    assert MODELS[name].__doc__
