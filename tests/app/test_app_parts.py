"""The app's parts without a browser: main inputs, edits, uploads, runs and the file route."""

from __future__ import annotations

import base64
import json

import numpy as np
import pytest

from rotarykiln.app.inputs import apply_edits, check_value, field_of_error, present_inputs
from rotarykiln.app.loading import builtin_cases, load_builtin, load_upload
from rotarykiln.case import parse_case
from rotarykiln.errors import InputError


def _data_url(data: bytes) -> str:
    return "data:application/x-yaml;base64," + base64.b64encode(data).decode()


@pytest.mark.parametrize("name", builtin_cases())
def test_every_builtin_case_shows_its_main_inputs_and_reads_back(name):
    raw = load_builtin(name)
    items = present_inputs(raw)
    assert [i.path for i, _ in items][:2] == ["kiln.length", "kiln.diameter"]
    edited = apply_edits(raw, {i.path: text for i, text in items})  # unchanged texts
    assert parse_case(edited) == parse_case(raw)


def test_an_edit_changes_only_its_field():
    raw = load_builtin("tscheng_A16")
    edited = apply_edits(raw, {"operation.speed": "3 rpm", "bed.fill": "0.2"})
    assert edited["operation"]["speed"] == "3 rpm" and edited["bed"]["fill"] == 0.2
    assert raw["operation"]["speed"] == "1.5 rpm"  # the loaded case is not touched
    assert {k: v for k, v in edited.items() if k not in ("operation", "bed")} == {
        k: v for k, v in raw.items() if k not in ("operation", "bed")
    }


@pytest.mark.parametrize(
    ("path", "text", "message"),
    [
        ("operation.speed", "1.5", "operation.speed: 1.5 has no unit"),
        ("kiln.length", "", "kiln.length: empty"),
        ("operation.feed", "3 m", 'operation.feed: "3 m" is a length'),
        ("kiln.slope", "2", "kiln.slope: 2 has no unit"),
    ],
)
def test_a_bad_field_is_one_line_naming_it(path, text, message):
    with pytest.raises(InputError) as err:
        check_value(path, text)
    assert str(err.value).startswith(message)
    assert "\n" not in str(err.value)
    assert field_of_error(err.value, [path]) == path


def test_case_errors_land_on_their_field():
    raw = apply_edits(load_builtin("tscheng_A16"), {"kiln.diameter": "-1 m"})
    with pytest.raises(InputError) as err:
        parse_case(raw)
    assert field_of_error(err.value, ["kiln.length", "kiln.diameter"]) == "kiln.diameter"
    assert field_of_error(err.value, ["kiln.length"]) is None


@pytest.mark.parametrize(
    ("data", "message"),
    [
        (b"kiln: [1, 2\n", "case.yaml: malformed YAML at line 2"),
        (b"\xff\xfe\x00", "case.yaml: not UTF-8 text"),
        (b"", "case.yaml: the case is empty"),
        (b"- 1\n- 2\n", "case.yaml: not a case file"),
        (b"just words", "case.yaml: not a case file"),
    ],
)
def test_an_upload_that_is_not_a_case_is_refused_in_one_line(data, message):
    with pytest.raises(InputError) as err:
        load_upload(_data_url(data), "/home/someone/case.yaml")
    assert str(err.value).startswith(message), str(err.value)
    assert "/tmp" not in str(err.value) and "\n" not in str(err.value)


def test_an_upload_too_large_or_broken_is_refused():
    with pytest.raises(InputError, match="too large"):
        load_upload(_data_url(b"#" * 1_100_000), "big.yaml")
    with pytest.raises(InputError, match="could not be decoded"):
        load_upload("data:text/plain;base64,@@@", "x.yaml")
    with pytest.raises(InputError, match="empty upload"):
        load_upload(None, None)


def test_a_run_keeps_its_files_and_serves_only_them(tmp_path):
    pytest.importorskip("dash")
    from rotarykiln.app.running import RunStore
    from rotarykiln.app.server import create_app

    store = RunStore(tmp_path, keep=1)
    result = store.run(load_builtin("tscheng_A16"), "tscheng_A16")
    assert {"report.html", "case.yaml", "summary.json"} <= set(result.files)
    assert result.files[0] == "report.html"
    assert any("T_bed_K" in table for table in result.profiles.values()), list(result.profiles)
    client = create_app(store).server.test_client()
    page = client.get(f"/files/{result.run_id}/report.html")
    assert page.status_code == 200 and b"Tscheng" in page.data
    download = client.get(f"/files/{result.run_id}/case.yaml?download=1")
    assert "attachment" in download.headers["Content-Disposition"]
    secret = tmp_path.parent / "secret.txt"
    secret.write_text("not for the browser")
    for bad in (
        f"/files/{result.run_id}/..%2F..%2Fsecret.txt",
        f"/files/{result.run_id}/../../secret.txt",
        f"/files/{result.run_id}/nothing.csv",
        "/files/0123/report.html",
        "/files/" + "0" * 32 + "/report.html",
    ):
        served = client.get(bad)  # refused, or Dash's page for a path it does not know
        assert served.status_code == 404 or b"react-entry-point" in served.data, bad
        assert b"not for the browser" not in served.data
    second = store.run(load_builtin("tscheng_A16"), "tscheng_A16")  # keep=1: the first goes
    assert store.folder(result.run_id) is None and store.folder(second.run_id) is not None


def test_a_run_with_a_bad_case_leaves_no_folder(tmp_path):
    from rotarykiln.app.running import RunStore

    store = RunStore(tmp_path)
    raw = load_builtin("tscheng_A16")
    raw["kiln"]["diameter"] = "0 m"
    with pytest.raises(InputError):
        store.run(raw)
    assert list(tmp_path.iterdir()) == []


def test_a_port_in_use_is_one_line(capsys):
    import socket

    pytest.importorskip("dash")
    from rotarykiln.cli import main

    with socket.socket() as busy:
        busy.bind(("127.0.0.1", 0))
        busy.listen()
        port = busy.getsockname()[1]
        assert main(["app", "--port", str(port)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"rotarykiln app: error: --port: cannot listen on 127.0.0.1:{port}")
    assert err.count("\n") == 1
    assert main(["app", "--port", "70000"]) == 2


class _FailingStore:
    """A run store whose runs fail as a solver or a bug would."""

    def __init__(self, error: Exception):
        self.error = error

    def check_free(self, light=None):
        pass

    def is_light(self, raw):
        return True

    def run(self, raw, source="case"):
        raise self.error


def _press(store, **kwargs):
    pytest.importorskip("dash")
    import yaml

    from rotarykiln.app.callbacks import press

    raw = load_builtin("tscheng_A16")
    case_data = {"yaml": yaml.safe_dump(raw), "source": "tscheng_A16"}
    items = present_inputs(raw)
    ids = [{"type": "main-input", "path": i.path} for i, _ in items]
    values = [text for _, text in items]
    args = dict(saving=False, n_run=3, n_save=0, previous={"summary": {}})
    args.update(kwargs)
    flags = (args["saving"], args["n_run"], args["n_save"])
    return press(store, *flags, case_data, values, ids, args["previous"])


def test_a_failed_solve_is_one_line_and_keeps_the_results():
    from dash import no_update

    from rotarykiln.errors import ConvergenceError

    error = ConvergenceError("Newton did not converge at z = 1.2 m", iterations=60)
    result, errors, message, status, download, panel = _press(_FailingStore(error))
    assert result is no_update and panel is no_update  # what was computed stays
    assert download is no_update
    assert message == f"solver failed: {error}" and "\n" not in message
    assert status.startswith("Run 3 failed") and "last successful run" in status
    assert errors == {"n": 3, "errors": {}}


def test_a_bug_in_a_run_is_reported_and_the_app_goes_on():
    from dash import no_update

    result, _, message, status, _, panel = _press(
        _FailingStore(ZeroDivisionError("float division"))
    )
    assert result is no_update and panel is no_update
    assert message == "internal error: ZeroDivisionError: float division"
    assert status.startswith("Run 3 failed")


def test_save_writes_the_edited_case_without_running():
    _, errors, message, status, download, _ = _press(
        _FailingStore(AssertionError("no run when saving")), saving=True, n_run=0, n_save=1
    )
    assert message == "" and errors["errors"] == {}
    assert download["filename"] == "tscheng_A16.yaml"
    assert "speed: 1.5 rpm" in download["content"]
    assert status.startswith("Save 1: tscheng_A16.yaml")


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    """One run store (and its worker process) for the runs of the model results below."""
    from rotarykiln.app.running import RunStore

    runs = RunStore(tmp_path_factory.mktemp("runs"))
    try:
        yield runs
    finally:
        runs.close()


def _panel_text(result) -> str:
    """Every text of the results panel the page draws for a run."""
    pytest.importorskip("dash")
    from rotarykiln.app.callbacks import render

    data = {**result.to_json(), "case_yaml": ""}
    return json.dumps(render(data), default=lambda c: c.to_plotly_json())


def test_an_rtd_case_shows_its_distribution_with_its_moments(store):
    from rotarykiln.app.results import MAX_POINTS
    from rotarykiln.commands.model_runs import predict_from_case

    result = store.run(load_builtin("rtd/bongo_njeng_sand_rl"), "rtd/bongo_njeng_sand_rl")
    rtd = result.models["rtd"]
    t, e = np.array(rtd["t_s"]), np.array(rtd["E_1_s"])
    assert 100 <= len(t) <= MAX_POINTS
    prediction = predict_from_case(parse_case(load_builtin("rtd/bongo_njeng_sand_rl")))
    # the curve sent to the page is the prediction's: its moments, from the thinned points
    assert np.trapezoid(e, t) == pytest.approx(1.0, abs=0.01)
    mean = np.trapezoid(t * e, t)
    assert mean == pytest.approx(prediction.mean_residence_time, rel=0.01)
    assert np.trapezoid((t - mean) ** 2 * e, t) == pytest.approx(prediction.variance, rel=0.05)
    panel = _panel_text(result)
    assert "rtd-graph" in panel and "Mean residence time (RTD)" in panel
    assert f"{prediction.mean_residence_time / 60:.2f}" in panel
    assert "no heat model" not in panel.lower()


def test_a_transport_case_shows_its_bed_profile_and_no_server_path(store):
    from rotarykiln.commands.model_runs import bed_profile_from_case

    name = "charcoal_activation_kramers"
    result = store.run(load_builtin(name), name)
    profile = bed_profile_from_case(parse_case(load_builtin(name)))
    bed = result.models["bed"]
    assert bed["z_m"][-1] == pytest.approx(profile.z[-1])
    assert max(bed["depth_m"]) == pytest.approx(float(np.max(profile.depth)), rel=1e-6)
    assert result.summary["transport_profile_csv"] == "profile.csv"  # a name, not a path
    assert str(store.root) not in json.dumps(result.to_json())
    panel = _panel_text(result)
    assert "bed-profile-graph" in panel and "temperature-graph-kiln" in panel
    assert f"{profile.holdup_mass:.4g}" in panel


def test_a_transverse_case_runs_as_the_transverse_command(store):
    import dataclasses

    from rotarykiln.commands.transverse import retort_spec_from_case
    from rotarykiln.transverse.retort import run_retort

    result = store.run(load_builtin("retort/case02"), "retort/case02")
    found = result.models["transverse"]
    assert "skipped" not in found, found.get("skipped")
    spec = retort_spec_from_case(parse_case(load_builtin("retort/case02")))
    direct = run_retort(dataclasses.replace(spec, snapshot_times=()))
    assert found["summary"]["mixing_time_s"] == pytest.approx(direct.mixing_time)
    assert found["summary"]["final_shale_temperature_K"] == pytest.approx(direct.temperature[-1, 1])
    assert found["series"]["t_s"][-1] == pytest.approx(direct.t[-1])
    assert {"transverse_timeseries.csv", "transverse_summary.json"} <= set(result.files)
    panel = _panel_text(result)
    assert "transverse-graph" in panel and "Mixing time" in panel
    assert "no heat model" not in panel.lower()


@pytest.mark.parametrize("name", [n for n in builtin_cases() if n.startswith("retort/")])
def test_the_app_runs_the_transverse_section_of_every_builtin_retort_case(name):
    from rotarykiln.app.results import TRANSVERSE_SECONDS, transverse_estimate
    from rotarykiln.commands.transverse import retort_spec_from_case

    seconds, why = transverse_estimate(retort_spec_from_case(parse_case(load_builtin(name))))
    assert why == "" and seconds < TRANSVERSE_SECONDS / 2


def test_a_transverse_run_too_heavy_for_the_app_gives_its_command(tmp_path):
    from rotarykiln.app.results import model_results

    raw = load_builtin("retort/case02")
    raw["transverse"]["duration"] = "3000 s"
    raw["transverse"]["grid"] = {"layers": 20, "zones": 60}
    found = model_results(parse_case(raw), tmp_path, "my_retort.yaml")["transverse"]
    assert "series" not in found and list(tmp_path.iterdir()) == []  # nothing was run
    assert found["skipped"].startswith("The app does not run this transverse section: it ")
    assert "longer than the app runs" in found["skipped"]
    assert found["command"] == "rotarykiln transverse my_retort.yaml"
    assert ("Simulated time", "3000", "s") in found["inputs"]
    from rotarykiln.app.running import RunResult

    shown = RunResult("0" * 32, "retort", {"regime": "rolling"}, models={"transverse": found})
    panel = _panel_text(shown)
    assert found["skipped"] in panel and "rotarykiln transverse my_retort.yaml" in panel
    assert "no heat model" not in panel.lower()
    raw["transverse"]["grid"] = {"layers": 50, "zones": 50}
    found = model_results(parse_case(raw), tmp_path, "my_retort.yaml")["transverse"]
    assert "2500 control volumes" in found["skipped"]


def test_the_warnings_are_shown_as_the_models_give_them_in_every_run(store, tmp_path):
    """The page's warnings are the texts the run gives (their units included), in the second
    run of the same worker process too."""
    import warnings

    from rotarykiln.commands.run import run_case

    name = "rotary_pyrolysis"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("default")
        run_case(parse_case(load_builtin(name)), tmp_path, plots=False)
    given = list(dict.fromkeys(str(w.message) for w in caught))
    assert given  # the case warns: its gas is colder than a closure's range
    first = store.run(load_builtin(name), name)
    second = store.run(load_builtin(name), name)
    assert first.warnings == given and second.warnings == given
