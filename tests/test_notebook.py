"""The getting-started notebook (examples/getting_started.ipynb) runs from top to bottom."""

from __future__ import annotations

import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient

NOTEBOOK = Path(__file__).resolve().parents[1] / "examples" / "getting_started.ipynb"


def _text(cell) -> str:
    """Everything a code cell printed or displayed, as text."""
    parts = []
    for out in cell.get("outputs", []):
        parts.append(out.get("text", ""))
        data = out.get("data", {})
        parts.append(data.get("text/plain", "") + data.get("text/html", ""))
    return "".join(parts)


def test_getting_started_notebook_runs(tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")  # the kernel inherits it: no display needed
    nb = nbformat.read(NOTEBOOK, as_version=4)
    assert not any(c.get("outputs") for c in nb.cells if c.cell_type == "code"), (
        "the notebook is stored without outputs"
    )
    start = time.perf_counter()
    NotebookClient(
        nb, timeout=120, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    ).execute()
    assert time.perf_counter() - start < 60
    code = [c for c in nb.cells if c.cell_type == "code"]
    errors = [o for c in code for o in c.outputs if o.output_type == "error"]
    assert not errors, errors
    shown = "\n".join(_text(c) for c in code)
    assert "rotarykiln result: Barr pilot kiln T4" in shown  # the result's HTML display
    assert "operation.sped: not a field of the case" in shown  # the wrong override, one line
    assert 'operation.speed: "2 m" is a length' in shown
    assert "True" in _text(next(c for c in code if "more_feed == same" in c.source))
    assert not list(tmp_path.iterdir()), "the notebook writes no file"
