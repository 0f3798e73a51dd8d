"""The notebook API (rotarykiln.api): load_case with overrides, Case.replace, run and Result."""

from __future__ import annotations

import json
import re

import numpy as np
import pandas as pd
import pytest
import yaml

import rotarykiln as rk
from rotarykiln.case import read_case_yaml
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")

# the bed depth follows the transport model (Kramers, a discharge dam), and an RTD is predicted
TRANSPORT = {
    "bed": None,
    "transport.model": "kramers",
    "transport.dam_height": "20 mm",
    "rtd.correlation": "sherritt2003",
}


def _edited_file(tmp_path, name, edit):
    """The built-in case ``name`` as a YAML file in ``tmp_path``, its mapping edited by hand."""
    data = read_case_yaml(builtin_case_path(name))
    edit(data)
    path = tmp_path / f"{name}_edited.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return path


def _speed_and_feed(data):
    data["operation"]["speed"] = "2.5 rpm"
    data["operation"]["feed"] = "80 kg/h"


def _transport_bed(data):
    del data["bed"]
    data["transport"] = {"model": "kramers", "dam_height": "20 mm"}
    data["rtd"] = {"correlation": "sherritt2003"}


@pytest.mark.parametrize(
    ("overrides", "edit"),
    [
        ({"operation.speed": "2.5 rpm", "operation.feed": "80 kg/h"}, _speed_and_feed),
        (TRANSPORT, _transport_bed),
    ],
    ids=["speed-and-feed", "transport-bed"],
)
def test_overrides_give_the_result_of_the_edited_file(tmp_path, overrides, edit):
    by_overrides = rk.run(rk.load_case("barr_T4", overrides=overrides))
    by_file = rk.run(rk.load_case(_edited_file(tmp_path, "barr_T4", edit)))
    assert by_overrides.models == by_file.models
    for model in by_file.models:  # every profile, to the last bit
        pd.testing.assert_frame_equal(
            by_overrides.to_frame(model), by_file.to_frame(model), check_exact=True
        )
    assert by_overrides.summary.keys() == by_file.summary.keys()
    # and the edit changed the answer: the comparison above could fail
    base = rk.run("barr_T4").to_frame("kiln")
    assert not np.array_equal(base["T_bed_K"], by_file.to_frame("kiln")["T_bed_K"])


@pytest.mark.parametrize(
    ("overrides", "field", "words"),
    [
        ({"operation.sped": "2.5 rpm"}, "operation.sped", ["not a field", '"speed"']),
        ({"speed": "2.5 rpm"}, "speed", ['did you mean "operation.speed"']),
        ({"wall.lining[0].thicknes": "80 mm"}, "wall.lining.0.thicknes", ['"thickness"']),
        ({"transport.modle": "kramers"}, "transport.modle", ['"model"']),
        ({"operation.speed": "3 m"}, "operation.speed", ['"3 m"', "rotation rate"]),
        ({"kiln.diameter": "-0.4 m"}, "kiln.diameter", ["-0.4 m", "1 um"]),
        ({"wall.lining[7].thickness": "80 mm"}, "wall.lining.7", ["no such item"]),
        ({"operation.speed.value": 2}, "operation.speed", ["is a value"]),
    ],
)
def test_a_wrong_override_names_the_dotted_field(overrides, field, words):
    with pytest.raises(InputError) as info:
        rk.load_case("barr_T4", overrides=overrides)
    message = str(info.value)
    assert message.startswith(f"{field}: "), message
    assert "\n" not in message
    for word in words:
        assert word in message, message


def test_replace_validates_and_returns_a_new_case():
    case = rk.load_case("barr_T4")
    faster = case.replace({"operation.speed": "3 rpm"}, transport={"model": "kramers"})
    assert faster.operation.speed == pytest.approx(3 * 2 * np.pi / 60, rel=1e-15)
    assert faster.transport.model == "kramers"
    assert case.operation.speed == pytest.approx(1.5 * 2 * np.pi / 60, rel=1e-15)
    assert case.transport is None  # the case itself is frozen and unchanged
    assert faster.replace({"operation.speed": "1.5 rpm"}, transport=None) == case
    with pytest.raises(InputError, match=r"^kiln\.diameter: -0\.4 is not in \[1 um, 10 km\]"):
        case.replace({"kiln.diameter": -0.4})
    with pytest.raises(InputError, match=r"^bed\.fill: "):
        case.replace(bed={"fill": 1.5})


def test_model_copy_validates_or_points_to_replace():
    case = rk.load_case("barr_T4")
    copy = case.model_copy(update={"operation.feed": "70 kg/h"})
    assert copy.operation.feed == pytest.approx(70 / 3600, rel=1e-15)
    assert case.model_copy() == case
    with pytest.raises(InputError, match=r"^operation\.speed: \"2\.5 m\" is a length"):
        case.model_copy(update={"operation.speed": "2.5 m"})
    with pytest.raises(InputError, match=r"^update: .*case\.replace"):
        case.operation.model_copy(update={"speed": "2.5 rpm"})


def test_run_matches_the_command(tmp_path):
    """rk.run and `rotarykiln run` share their code path: the same summary and profiles."""
    from rotarykiln.commands.run import run_case_into
    from rotarykiln.outputs import to_json

    case = rk.load_case("barr_T4", overrides=TRANSPORT)
    result = rk.run(case)
    assert result.models == ("transport", "kiln", "rtd")
    run_case_into(case, tmp_path / "out", plots=False)
    written = json.loads((tmp_path / "out" / "summary.json").read_text())
    ours = json.loads(to_json(result.summary))
    files = {k: v for k, v in written.items() if k not in ours}
    assert files and all(k.endswith(("_csv", "_png")) for k in files)
    assert {k: v for k, v in written.items() if k in ours} == ours
    csv = pd.read_csv(tmp_path / "out" / "kiln_profiles.csv")
    pd.testing.assert_frame_equal(csv, result.to_frame("kiln"), check_exact=True)
    # the transport model set the kiln's fill: the kiln's residence time is the bed profile's
    assert result.summary["kiln_fill"] == pytest.approx(result.bed.mean_fill, rel=0.05)


def test_result_repr_is_short():
    result = rk.run("barr_T4")
    text = repr(result)
    lines = text.splitlines()
    assert 3 <= len(lines) < 20
    assert max(len(line) for line in lines) < 160
    assert "array" not in text and len(re.findall(r"\d+\.\d+", text)) < 30
    assert "Barr pilot kiln T4" in lines[0] and "RMSE" in text
    solution = repr(result.solution)
    assert "\n" not in solution and len(solution) < 250 and "array" not in solution
    page = result._repr_html_()
    assert page.startswith("<div>") and "Barr pilot kiln T4" in page and "array" not in page


def test_result_tables_and_figures():
    import matplotlib.pyplot as plt

    result = rk.run("barr_T4")
    frame = result.to_frame()
    assert len(frame) == 101 and {"z_m", "T_bed_K", "T_gas_K"} <= set(frame)
    measured = result.measured()
    assert set(measured["profile"]) == set(result.scores)
    rmse = measured.groupby("profile")["residual_K"].apply(lambda r: float(np.sqrt(np.mean(r**2))))
    for profile, value in result.scores.items():  # the scores are these residuals' RMSE
        assert rmse[profile] == pytest.approx(value, rel=1e-12)
    fig = result.plot()
    assert fig.axes and fig.axes[0].lines
    plt.close(fig)
    with pytest.raises(InputError, match=r"^model: rtd is not one of the models this case ran"):
        result.to_frame("rtd")
    assert result.bed is None and result.rtd is None and result.residence is None


def test_result_of_a_reacting_kiln_has_its_residence_time_effects():
    import matplotlib.pyplot as plt

    result = rk.run("limestone_calcination")
    assert result.residence is not None
    assert "conversion: CaCO3" in repr(result)
    assert result.measured().empty and result.scores == {}
    fig = result.plot("residence")
    assert fig.axes
    plt.close("all")


def test_warnings_are_kept_once():
    with pytest.warns(UserWarning):
        result = rk.run("barr_T4")
    assert result.warnings and len(set(result.warnings)) == len(result.warnings)
    assert any("Li et al." in w for w in result.warnings)
