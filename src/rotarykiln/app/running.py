"""Runs of the app: validate the edited case, run it as ``rotarykiln run --report`` does, keep
the files for download.

Each run gets its own folder under one temporary root (removed when the app stops); the last
:data:`KEEP_RUNS` runs are kept. Runs are serialised by a lock: the models and matplotlib are
not meant to run in two threads at once, and the web server answers in threads.
"""

from __future__ import annotations

import atexit
import json
import math
import re
import shutil
import tempfile
import threading
import uuid
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from rotarykiln.case import parse_case
from rotarykiln.case_io import case_to_yaml

__all__ = ["KEEP_RUNS", "RunResult", "RunStore", "outlet_temperature"]

KEEP_RUNS = 20
"""Runs whose files the app keeps for download (the oldest goes first)."""

_OUTLET = re.compile(r"(^|_)bed_outlet_temperature_K$")


def outlet_temperature(summary: dict) -> tuple[str, float] | None:
    """The summary entry of the bed (solids) outlet temperature, K, as (key, value), else None.

    >>> outlet_temperature({"froude": 0.1, "heat_bed_outlet_temperature_K": 445.9})
    ('heat_bed_outlet_temperature_K', 445.9)
    """
    for key, value in summary.items():
        if _OUTLET.search(key) and isinstance(value, int | float) and math.isfinite(value):
            return key, float(value)
    return None


@dataclass
class RunResult:
    """What one run gives the page: summary, profiles, warnings and the files written."""

    run_id: str
    name: str
    summary: dict
    profiles: dict[str, dict[str, list]] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    files: list[str] = field(default_factory=list)

    def to_json(self) -> dict[str, Any]:
        """Plain data for the page's store (non-finite numbers as None)."""
        return _plain(
            {
                "run_id": self.run_id,
                "name": self.name,
                "summary": self.summary,
                "profiles": self.profiles,
                "warnings": self.warnings,
                "files": self.files,
            }
        )


def _plain(value: Any) -> Any:
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_plain(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


class RunStore:
    """Run folders of one app, under a temporary root removed at exit."""

    def __init__(self, root: str | Path | None = None, keep: int = KEEP_RUNS):
        if root is None:
            root = tempfile.mkdtemp(prefix="rotarykiln-app-")
            atexit.register(shutil.rmtree, root, ignore_errors=True)
        self.root = Path(root)
        self.root.mkdir(parents=True, exist_ok=True)
        self.keep = keep
        self._lock = threading.Lock()
        self._order: list[str] = []

    def folder(self, run_id: str) -> Path | None:
        """The folder of a kept run, else None (an unknown or removed id)."""
        if not re.fullmatch(r"[0-9a-f]{32}", run_id or ""):
            return None
        path = self.root / run_id
        return path if path.is_dir() else None

    def run(self, raw: dict, source: str = "case") -> RunResult:
        """Validate a raw case mapping and run it (summary, tables, figures, report.html).

        Raises
        ------
        InputError
            The case is not valid (the message of :func:`rotarykiln.case.parse_case`).
        ConvergenceError
            A solver failed.
        """
        case = parse_case(raw, source=source)
        run_id = uuid.uuid4().hex
        out = self.root / run_id
        out.mkdir()
        try:
            with self._lock:
                caught = _run_case(case, out, source)
        except BaseException:
            shutil.rmtree(out, ignore_errors=True)
            raise
        (out / "case.yaml").write_text(case_to_yaml(case), encoding="utf-8")
        self._order.append(run_id)
        while len(self._order) > self.keep:
            shutil.rmtree(self.root / self._order.pop(0), ignore_errors=True)
        summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
        return RunResult(
            run_id=run_id,
            name=str(summary.get("name") or source),
            summary=summary,
            profiles=_profiles(out),
            warnings=caught,
            files=_files(out),
        )


def _run_case(case, out: Path, source: str) -> list[str]:
    """``run_case(..., report=True)`` with its warnings collected (not printed); their texts."""
    import matplotlib

    matplotlib.use("Agg")
    from rotarykiln.commands.run import run_case

    shown: list[str] = []

    def collect(message, category, filename, lineno, file=None, line=None):
        text = str(message)
        if text not in shown:
            shown.append(text)

    previous = warnings.showwarning
    warnings.showwarning = collect
    try:
        run_case(case, out, report=True, source=source)
    finally:
        warnings.showwarning = previous
    return shown


_ORDER = {".html": 0, ".yaml": 1, ".csv": 2, ".json": 3, ".txt": 4, ".png": 5, ".svg": 5}


def _files(out: Path) -> list[str]:
    names = [p.name for p in out.iterdir() if p.is_file() and not p.name.startswith(".")]
    return sorted(names, key=lambda n: (_ORDER.get(Path(n).suffix, 9), n))


def _profiles(out: Path) -> dict[str, dict[str, list]]:
    """The ``*_profiles.csv`` tables of a run: name -> column -> values."""
    tables = {}
    for path in sorted(out.glob("*_profiles.csv")):
        frame = pd.read_csv(path).select_dtypes("number").astype(float)
        tables[path.stem.removesuffix("_profiles")] = {
            c: [v if math.isfinite(v) else None for v in frame[c].tolist()] for c in frame.columns
        }
    return tables
