"""The app through its HTTP endpoint, as any client can post to it: no file of the server is
read, the page's state is checked as an upload is, a request too large or too deep is refused,
and a run is bounded in cells and in time."""

from __future__ import annotations

import os
import time
import uuid

import pytest
import yaml

from rotarykiln.cases import builtin_case_path

pytest.importorskip("dash")

from rotarykiln.app.client import AppClient, run_body  # noqa: E402
from rotarykiln.app.running import MAX_SHOWN_POINTS, RunStore  # noqa: E402
from rotarykiln.app.server import AppServer  # noqa: E402


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    """A client of the app served on a free local port (runs stopped after 20 s)."""
    store = RunStore(tmp_path_factory.mktemp("runs"), max_seconds=20.0)
    with AppServer(port=0, store=store) as server:
        yield AppClient(server.url, timeout=60)


def _raw(name: str = "tscheng_A16") -> dict:
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def _state(raw: dict, source: str = "tscheng_A16") -> dict:
    """The case store's data as the page keeps it."""
    return {"yaml": yaml.safe_dump(raw, sort_keys=False), "source": source}


def _one_line(text) -> str:
    assert isinstance(text, str) and text and "\n" not in text, text
    assert "internal error" not in text and "Traceback" not in text, text
    return text


def test_a_light_run_works_through_http(client):
    """The baseline of the refusals below: the same posts with a good case run it."""
    loaded = client.load("tscheng_A16")
    assert loaded.status == 200 and loaded.output("upload-error") == ""
    state = loaded.output("case-store", "data")
    answer = client.run(state, {"operation.speed": "2 rpm"})
    assert answer.status == 200, answer.body[:300]
    assert answer.output("run-status").startswith("Run 1 finished"), answer.output("run-error")
    kept = answer.output("result-store", "data")
    assert kept["inputs"]["operation.speed"] == "2 rpm" and kept["outlet"] > 300


@pytest.fixture
def canary(tmp_path):
    """A file of the server's with a unique content, beside a case file named like an upload."""
    token = f"canary-{uuid.uuid4().hex}"
    path = tmp_path / "canary.yaml"
    path.write_text(f"{token}\n", encoding="utf-8")
    (tmp_path / "case.yaml").write_text("# the folder an old app resolved paths in\n")
    return path, token


def test_no_file_of_the_server_is_read_through_the_app(client, canary):
    path, token = canary
    names = [str(path), os.path.relpath(path), "canary.yaml", f"file://{path}"]
    for name in names:
        raw = _raw()
        raw["chemistry"] = {"species": name}
        text = yaml.safe_dump(raw, sort_keys=False).encode()
        # uploaded: loaded with its error shown, the file not read
        loaded = client.load(upload=text, filename=str(path.parent / "case.yaml"))
        assert loaded.status == 200 and token not in loaded.body
        error = _one_line(loaded.output("case-error"))
        assert "chemistry.species:" in error and "names a file" in error, error
        state = loaded.output("case-store", "data")
        assert state["source"] == "case.yaml"  # a name, never the server's path
        # Run with the page's state, and with a state naming the canary's folder as the source
        for case_data in (state, _state(raw, source=str(path.parent / "case.yaml"))):
            for save in (False, True):
                answer = client.run(case_data, {"operation.speed": "2 rpm"}, save=save)
                assert answer.status == 200 and token not in answer.body, name
                message = _one_line(answer.output("run-error"))
                assert message.startswith("chemistry.species: ") and "names a file" in message
                assert "not done" in answer.output("run-status")
                assert answer.output("result-store", "data") is None  # nothing ran


def test_a_builtin_case_is_a_name_never_a_path(client, canary):
    path, token = canary
    for name in (str(path.with_suffix("")), os.path.relpath(path.with_suffix("")), "../cases/x"):
        answer = client.load(name)
        assert answer.status == 200 and token not in answer.body
        assert "is not a built-in case" in _one_line(answer.output("upload-error"))
        assert answer.output("case-store", "data") is None


def test_a_request_too_large_is_refused_before_it_is_read(client):
    started = time.perf_counter()
    answer = client.post(b'{"output": "' + b"x" * 5_000_000 + b'"}')
    assert answer.status == 413 and "too large" in answer.body
    assert time.perf_counter() - started < 5


def test_a_request_nested_too_deeply_is_refused_in_one_line(client):
    answer = client.post(b"[" * 100_000 + b"]" * 100_000)
    assert answer.status == 400 and answer.body.count("\n") <= 1 and "Traceback" not in answer.body
    # the server goes on
    assert client.load("tscheng_A16").status == 200


@pytest.mark.parametrize(
    ("case_data", "expected"),
    [
        ({"yaml": "[" * 100_000 + "]" * 100_000, "source": "x"}, "nested deeper than 20 levels"),
        ({"yaml": "kiln: [1, 2\n", "source": "x"}, "x: malformed YAML at line 2"),
        ({"yaml": "k: " + "9" * 200, "source": "x"}, "a number of 200 characters"),
        ({"yaml": "#" * 1_500_000, "source": "x"}, "too large for a case file"),
        ({"yaml": "- 1\n- 2\n", "source": "x"}, "not a case file"),
        ({"yaml": ["kiln"], "source": "x"}, "case-store: the page's state holds no loaded case"),
        (["yaml"], "case-store: the page's state holds no loaded case"),
    ],
)
def test_the_runs_stored_state_is_read_as_an_upload(client, case_data, expected):
    started = time.perf_counter()
    answer = client.run(case_data, {})
    assert answer.status == 200, answer.body[:200]
    assert expected in _one_line(answer.output("run-error"))
    assert answer.output("result-store", "data") is None
    assert time.perf_counter() - started < 10


def test_a_large_case_in_the_stored_state_is_refused(client):
    """The 1 MB upload limit holds for the case the page sends back: a case of 1.5 MB of
    values (here a long description) is refused, not run."""
    raw = _raw()
    raw["description"] = "x" * 1_500_000
    answer = client.run(_state(raw), {})
    assert answer.status == 200
    assert "too large for a case file" in _one_line(answer.output("run-error"))


@pytest.mark.parametrize(
    ("fields", "ids", "expected"),
    [
        ({"operation.speed": {"a": [1]}}, None, "operation.speed: {"),
        (
            {"operation.speed": "1" * 300 + " rpm"},
            None,
            "operation.speed: a text of 304 characters",
        ),
        (
            {"operation.speed": "2 rpm"},
            [{"path": "kiln.secret", "type": "main-input"}],
            "main-input",
        ),
        ({"operation.speed": "2 rpm"}, [{"path": ["x"] * 50}], "main-input"),
    ],
)
def test_the_fields_state_is_checked(client, fields, ids, expected):
    answer = client.post(run_body(_state(_raw()), fields, ids=ids))
    assert answer.status == 200, answer.body[:200]
    shown = answer.output("run-error") or answer.output("run-errors", "data")["errors"].get(
        "operation.speed"
    )
    assert _one_line(shown).startswith(expected)
    assert "not done" in answer.output("run-status")


def test_more_cells_than_the_app_runs_is_refused_at_once(client):
    raw = _raw("rotary_pyrolysis")
    raw.setdefault("solver", {})["cells"] = 20_000
    loaded = client.load(upload=yaml.safe_dump(raw).encode(), filename="big.yaml")
    assert "solver.cells: 20000 cells is more than the app runs" in loaded.output("case-error")
    started = time.perf_counter()
    answer = client.run(loaded.output("case-store", "data"), {})
    assert _one_line(answer.output("run-error")).startswith("solver.cells: 20000 cells is more")
    assert time.perf_counter() - started < 5


def test_the_run_answer_is_small(client):
    """Profiles are thinned for the page: a run at the most cells the app runs answers in a
    few hundred kB (the 20,000-cell runs answered 18.5 MB)."""
    raw = _raw("rotary_pyrolysis")
    raw.setdefault("solver", {})["cells"] = 1_000
    answer = client.run(_state(raw, "rotary_pyrolysis"), {})
    assert answer.output("run-status").startswith("Run 1 finished"), answer.output("run-error")
    assert len(answer.body) < 1_000_000, len(answer.body)
    graphs = [
        item
        for item in _walk(answer.output("results"))
        if "temperature-graph" in str(item.get("id"))
    ]
    assert graphs
    for graph in graphs:
        for trace in graph["figure"]["data"]:
            assert 2 <= len(trace["x"]) <= MAX_SHOWN_POINTS


def _walk(node):
    """Every component (a dict with props) in a Dash layout as JSON."""
    if isinstance(node, list):
        for item in node:
            yield from _walk(item)
    elif isinstance(node, dict):
        props = node.get("props")
        if isinstance(props, dict):
            yield props
            yield from _walk(props.get("children"))
