"""The app's callbacks over HTTP, as the browser posts them (tests and the load test).

:class:`AppClient` posts to Dash's ``/_dash-update-component`` endpoint the bodies the page
posts: loading a built-in case, uploading a file, pressing Run with the page's state. Standard
library only (``urllib``); each request has a timeout.

>>> AppClient("http://127.0.0.1:8050/").url
'http://127.0.0.1:8050/'
"""

from __future__ import annotations

import base64
import json
import urllib.error
import urllib.request
from dataclasses import dataclass
from typing import Any

__all__ = ["AppClient", "Answer", "run_body"]

LOAD_OUTPUT = (
    "..case-store.data...inputs.children...upload-error.children...case-error.children"
    "...case-info.children...case-description.children...case-yaml.children"
    "...case-picker.value.."
)
RUN_OUTPUT = (
    "..result-store.data...run-errors.data...run-error.children...run-status.children"
    "...case-download.data...results.children.."
)


@dataclass
class Answer:
    """An answer of the server: HTTP ``status``, the ``body`` as text, its ``seconds``."""

    status: int
    body: str
    seconds: float

    def json(self) -> Any:
        return json.loads(self.body)

    def output(self, component: str, prop: str = "children") -> Any:
        """A property the callback set (None when it set nothing there)."""
        try:
            return self.json()["response"].get(component, {}).get(prop)
        except (ValueError, KeyError, AttributeError, TypeError):
            return None


class AppClient:
    """Post callbacks to the app served at ``url`` (``http://127.0.0.1:PORT/``)."""

    def __init__(self, url: str, timeout: float = 120.0):
        self.url = url if url.endswith("/") else url + "/"
        self.timeout = timeout

    def post(self, body: bytes | dict, path: str = "_dash-update-component") -> Answer:
        """POST a body (a dict is sent as JSON); the answer, whatever its status."""
        import time

        data = body if isinstance(body, bytes) else json.dumps(body).encode("utf-8")
        request = urllib.request.Request(
            self.url + path,
            data=data,
            headers={"Content-Type": "application/json"},
            method="POST",
        )
        started = time.perf_counter()
        try:
            with urllib.request.urlopen(request, timeout=self.timeout) as response:  # noqa: S310
                status, text = response.status, response.read().decode("utf-8", "replace")
        except urllib.error.HTTPError as exc:
            status, text = exc.code, exc.read().decode("utf-8", "replace")
        return Answer(status, text, time.perf_counter() - started)

    def load(
        self, name: str | None = None, upload: bytes | None = None, filename: str = ""
    ) -> Answer:
        """The load callback: the built-in case ``name``, or the file ``upload`` dropped."""
        contents = None
        if upload is not None:
            contents = "data:application/x-yaml;base64," + base64.b64encode(upload).decode()
        trigger = "case-upload.contents" if upload is not None else "case-picker.value"
        return self.post(
            {
                "output": LOAD_OUTPUT,
                "outputs": [
                    {"id": i, "property": p}
                    for i, p in (
                        ("case-store", "data"),
                        ("inputs", "children"),
                        ("upload-error", "children"),
                        ("case-error", "children"),
                        ("case-info", "children"),
                        ("case-description", "children"),
                        ("case-yaml", "children"),
                        ("case-picker", "value"),
                    )
                ],
                "inputs": [
                    {"id": "case-picker", "property": "value", "value": name},
                    {"id": "case-upload", "property": "contents", "value": contents},
                ],
                "changedPropIds": [trigger],
                "state": [{"id": "case-upload", "property": "filename", "value": filename}],
            }
        )

    def run(
        self,
        case_data: Any,
        fields: dict[str, Any] | None = None,
        n: int = 1,
        previous: Any = None,
        save: bool = False,
    ) -> Answer:
        """The Run (or, with ``save``, Save) callback with the page's state: the case store's
        data, the fields' texts by path, the result store's data."""
        return self.post(run_body(case_data, fields, n, previous, save))


def run_body(
    case_data: Any,
    fields: dict[str, Any] | None = None,
    n: int = 1,
    previous: Any = None,
    save: bool = False,
    ids: list | None = None,
) -> dict:
    """The body the page posts when Run (or Save) is pressed; ``ids``: the fields' ids (from
    the paths of ``fields`` by default)."""
    fields = fields or {}
    if ids is None:
        ids = [{"path": path, "type": "main-input"} for path in fields]
    return {
        "output": RUN_OUTPUT,
        "outputs": [
            {"id": i, "property": p}
            for i, p in (
                ("result-store", "data"),
                ("run-errors", "data"),
                ("run-error", "children"),
                ("run-status", "children"),
                ("case-download", "data"),
                ("results", "children"),
            )
        ],
        "inputs": [
            {"id": "run-button", "property": "n_clicks", "value": 0 if save else n},
            {"id": "save-button", "property": "n_clicks", "value": n if save else 0},
        ],
        "changedPropIds": ["save-button.n_clicks" if save else "run-button.n_clicks"],
        "state": [
            {"id": "case-store", "property": "data", "value": case_data},
            [
                {"id": i, "property": "value", "value": v}
                for i, v in zip(ids, fields.values(), strict=False)
            ],
            [{"id": i, "property": "id", "value": i} for i in ids],
            {"id": "result-store", "property": "data", "value": previous},
        ],
    }
