import json
import math
import warnings

import numpy as np
import pandas as pd
import pytest

from rotarykiln.case import parse_case
from rotarykiln.cli import main
from rotarykiln.commands.model_runs import predict_from_case
from rotarykiln.errors import InputError
from rotarykiln.rtd.dispersion import open_open_exit_age
from rotarykiln.rtd.predict import predict_rtd

CASE = {
    "name": "pilot",
    "kiln": {"length": "1.95 m", "diameter": "0.1013 m", "slope": "2 deg"},
    "operation": {"speed": "3 rpm", "feed": "2.5 kg/h"},
    "material": {
        "bulk_density": "1422 kg/m3",
        "repose_angle": "39 deg",
        "particle_size": "0.55 mm",
    },
    "rtd": {"mean_residence_time": "43.3 min", "lifters": {"type": "rectangular"}},
}


def _case(**rtd):
    data = json.loads(json.dumps(CASE))
    data["rtd"].update(rtd)
    return parse_case(data)


def test_prediction_has_the_given_mean_and_the_correlation_dispersion():
    pred = predict_from_case(_case())
    assert pred.mean_residence_time == pytest.approx(43.3 * 60)
    assert np.trapezoid(pred.exit_age * pred.t, pred.t) == pytest.approx(43.3 * 60, rel=1e-4)
    # Bongo Njeng eq. 18 for sand with rectangular lifters at the benchmark (notes: 1.967e-6)
    assert pred.dispersion == pytest.approx(1.967e-6, rel=2e-3)
    assert pred.source == "bongo_njeng2015"


@pytest.mark.parametrize("corr", ["sherritt2003", "sai1990"])
def test_other_correlations(corr):
    pred = predict_from_case(_case(correlation=corr))
    assert pred.peclet > 100 and pred.source == corr


def test_given_peclet_and_transport_hook():
    case = _case(peclet=300.0, mean_residence_time=None)
    with pytest.raises(InputError, match="rtd.mean_residence_time"):
        predict_from_case(case)
    pred = predict_from_case(case, transport=lambda c: 1800.0)
    assert pred.peclet == 300.0 and pred.mean_residence_time == pytest.approx(1800.0)


def test_missing_inputs_are_named():
    with pytest.raises(InputError, match="rtd.lifters.type"):
        predict_from_case(_case(lifters={"type": "none"}))
    data = json.loads(json.dumps(CASE))
    del data["material"]["particle_size"]
    with pytest.raises(InputError, match="material.particle_size"):
        predict_from_case(parse_case(data))
    with pytest.raises(InputError, match="rtd"):
        predict_from_case(parse_case({k: v for k, v in CASE.items() if k != "rtd"}))


def test_predict_rtd_arguments():
    with pytest.raises(InputError, match="exactly one"):
        predict_rtd(100.0)
    with pytest.raises(InputError, match="Peclet"):
        predict_rtd(100.0, peclet=10.0, model="tanks-in-series")
    p = predict_rtd(100.0, peclet=50.0, model="closed-closed")
    assert p.tau == pytest.approx(100.0) and p.to_frame().shape == (400, 3)


def _tracer_csv(path, cut=None):
    t = np.arange(30, 62, 0.5)
    c = 1e5 * open_open_exit_age(t * 60, 2520.0, 550.0)
    if cut:
        t, c = t[t < cut], c[t < cut]
    pd.DataFrame({"time [min]": t, "C [uS/cm]": c}).to_csv(path, index=False)


def test_cli_fit_json_and_outputs(tmp_path, capsys):
    data = tmp_path / "tracer.csv"
    _tracer_csv(data)
    out = tmp_path / "out"
    code = main(["rtd", "fit", str(data), "--length", "1.95", "m", "--out", str(out), "--json"])
    assert code == 0
    result = json.loads(capsys.readouterr().out)
    assert result["peclet"] == pytest.approx(550.0, rel=1e-3)
    assert result["dispersion_m2_s"] == pytest.approx(1.95**2 / (550 * 2520), rel=1e-3)
    names = {p.name for p in out.iterdir()}
    assert names == {"fit.json", "fit.csv", "fit_units.json", "fit.png"}  # units beside the table


def test_cli_fit_bad_data_writes_nothing(tmp_path, capsys):
    data = tmp_path / "bad.csv"
    data.write_text("time [min],C\n0,0\n1,-2\n2,0\n3,0\n")
    out = tmp_path / "out"
    assert main(["rtd", "fit", str(data), "--out", str(out)]) == 2
    assert "is not >= 0" in capsys.readouterr().err
    assert not out.exists()


def test_cli_fit_warns_on_a_cut_tail(tmp_path, capsys):
    data = tmp_path / "cut.csv"
    _tracer_csv(data, cut=45.5)
    assert main(["rtd", "fit", str(data)]) == 0
    assert "of the tracer is unaccounted for" in capsys.readouterr().err


def test_cli_predict(tmp_path, capsys):
    import yaml

    case = tmp_path / "kiln.yaml"
    case.write_text(yaml.safe_dump(CASE))
    out = tmp_path / "pred"
    assert main(["rtd", "predict", str(case), "--out", str(out), "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["rtd_mean_residence_time_s"] == pytest.approx(2598.0)
    assert (out / "prediction.png").is_file()
    bad = dict(CASE, rtd={"mean_residence_time": "-3 min"})
    case.write_text(yaml.safe_dump(bad))
    assert main(["rtd", "predict", str(case)]) == 2
    assert "rtd.mean_residence_time" in capsys.readouterr().err
    assert not math.isnan(result["rtd_peclet"])


def test_rotarykiln_run_writes_the_rtd_prediction(tmp_path, capsys):
    import yaml

    case = tmp_path / "kiln.yaml"
    case.write_text(yaml.safe_dump(CASE))
    out = tmp_path / "run"
    assert main(["run", str(case), "--out", str(out), "--json", "--no-plots"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["rtd_peclet_source"] == "bongo_njeng2015"
    assert (out / "rtd_prediction.csv").is_file()


def test_builtin_rtd_case():
    from rotarykiln.case import load_case
    from rotarykiln.cases import builtin_case_path

    pred = predict_from_case(load_case(builtin_case_path("rtd/bongo_njeng_sand_rl")))
    assert pred.mean_residence_time == pytest.approx(43.34 * 60)
    assert pred.dispersion == pytest.approx(1.967e-6, rel=2e-3)  # notes sec. 2.6, sand RL


# --------------------------------------------------------------------- issue 21: hardening


@pytest.mark.parametrize(
    ("change", "match"),
    [
        ({"rtd": {"peclet": 1e300}}, r"rtd.peclet: 1e\+300 is not in \[1e-06, 1e\+10\]"),
        ({"rtd": {"peclet": 1e-300}}, r"rtd.peclet: 1e-300 is not in \[1e-06, 1e\+10\]"),
        (
            {"operation": {"feed": "1e-308 kg/h"}},
            r"rtd.peclet: about 1e-26\d.\d from the bongo_njeng2015 correlation .* is not in",
        ),
    ],
)
@pytest.mark.parametrize("model", ["open-open", "closed-closed", "open-closed", "gaussian"])
def test_extreme_rtd_sections_are_refused_in_one_line(change, match, model):
    # were OverflowError / ZeroDivisionError in rtd/dispersion.py
    data = json.loads(json.dumps(CASE))
    for section, values in change.items():
        data[section].update(values)
    data["rtd"]["model"] = model
    with warnings.catch_warnings(), pytest.raises(InputError, match=match) as e:
        warnings.simplefilter("ignore")  # the correlation's validated range
        predict_from_case(parse_case(data))
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("model", ["closed-closed", "open-closed"])
def test_a_tiny_repose_angle_gives_a_sharp_but_finite_prediction_quickly(model):
    # a 3.9e-11 deg static repose angle: Pe ~ 1.3e8 from the correlation; was 1.5 GB allocated
    # by the Laplace inversion before it failed
    import time

    data = json.loads(json.dumps(CASE))
    data["material"]["static_repose_angle"] = "3.9e-11 deg"
    data["rtd"]["model"] = model
    t0 = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        p = predict_from_case(parse_case(data))
    assert time.perf_counter() - t0 < 2.0
    assert 1e7 < p.peclet < 1e10
    assert np.all(np.isfinite(p.exit_age)) and p.exit_age.max() > 0
    assert p.mean_residence_time == pytest.approx(43.3 * 60, rel=1e-9)
