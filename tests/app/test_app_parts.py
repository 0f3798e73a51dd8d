"""The app's parts without a browser: main inputs, edits, uploads, runs and the file route."""

from __future__ import annotations

import base64

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
