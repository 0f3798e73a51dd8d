"""Monte Carlo uncertainty: bands of the heat model's profiles around the nominal."""

import json

import numpy as np
import pytest
import yaml

from rotarykiln.cases import builtin_case_path
from rotarykiln.cli import main
from rotarykiln.errors import InputError
from rotarykiln.studies.models import kiln_profile_model
from rotarykiln.studies.uncertainty import propagate

PARAMS = [
    "gas.temperature=normal(535 K, 10 K)",
    "gas.flow=uniform(22 kg/h, 27 kg/h)",
]


def test_bands_of_the_heat_profiles(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    base = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    res = propagate(kiln_profile_model, base, PARAMS, 16, executor="serial")
    assert len(res.samples) == 16 and res.n_failed == 0
    assert {"bed_temperature", "gas_temperature", "wall_temperature"} <= set(res.quantities)
    gas = res.bands("gas_temperature")
    assert len(gas) == 41 and gas["z_m"].iloc[-1] == pytest.approx(2.44)
    assert np.all(gas["p5"] <= gas["p50"]) and np.all(gas["p50"] <= gas["p95"])
    # the gas inlet temperature's 5-95 % spread is about 2 x 1.645 x 10 K
    assert 20 < gas["p95"].iloc[-1] - gas["p5"].iloc[-1] < 45
    assert gas["nominal"].iloc[-1] == pytest.approx(535.0)
    bed = res.bands("bed_temperature")
    inside = (bed["p5"] <= bed["nominal"] + 1e-9) & (bed["nominal"] <= bed["p95"] + 1e-9)
    assert inside.mean() > 0.9
    sc = res.scalars().set_index("output")
    assert sc.loc["bed_outlet_temperature_K", "sd"] > 1
    assert res.save_plot(tmp_path / "u.png").stat().st_size > 10000
    with pytest.raises(InputError, match="a profile"):
        res.bands("kiln_temperature")


def test_uncertainty_command(tmp_path, capsys):
    args = [
        "sensitivity",
        "tscheng_A16",
        "--model",
        "kiln_profiles",
        "--method",
        "uncertainty",
        "--n",
        "6",
        "--executor",
        "serial",
        "--out",
        str(tmp_path),
        "--json",
    ]
    for p in PARAMS:
        args += ["--param", p]
    assert main(args) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["cases"] == 6 and "bed_temperature" in summary["profiles"]
    for name in ("scalars.csv", "bands.csv", "uncertainty.png", "uncertainty.json"):
        assert (tmp_path / name).is_file()
