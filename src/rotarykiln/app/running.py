"""Runs of the app: validate the edited case, run it as ``rotarykiln run --report`` does, keep
the files for download.

Each run gets its own folder under one temporary root (removed when the app stops); the last
:data:`KEEP_RUNS` runs are kept. A run is done by a worker process
(:class:`~rotarykiln.app.worker.Worker`) within bounds no client can lift: at most
:data:`~rotarykiln.app.checks.MAX_APP_CELLS` cells, :data:`MAX_RUN_SECONDS` and
:data:`MAX_RUN_BYTES` of memory (the worker is killed beyond them). There are two lanes, each
with a worker of its own that runs one case at a time: heavy runs (at most :data:`MAX_WAITING`
waiting behind the one running) and light runs (at most :data:`LIGHT_CELLS` cells, such as every
built-in case; at most :data:`LIGHT_WAITING` waiting), so that a light run never waits behind a
heavy one. A run whose lane is full is refused at once (:class:`ServerBusy`) instead of
waiting. The page gets the profiles thinned to
:data:`MAX_SHOWN_POINTS` rows (the tables for download keep every cell), and the results of the
case's other models (bed profile, RTD, transverse results: :mod:`rotarykiln.app.results`).
"""

from __future__ import annotations

import atexit
import collections
import contextlib
import json
import math
import re
import shutil
import tempfile
import threading
import uuid
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from rotarykiln.app.checks import MAX_APP_CELLS, check_run_size, parse_app_case
from rotarykiln.app.worker import START_SECONDS, RunStopped, Worker, process_rss
from rotarykiln.case_io import case_to_yaml

__all__ = [
    "KEEP_RUNS",
    "LIGHT_CELLS",
    "LIGHT_WAITING",
    "MAX_RUN_BYTES",
    "MAX_RUN_SECONDS",
    "MAX_SHOWN_POINTS",
    "MAX_WAITING",
    "RunResult",
    "RunStopped",
    "RunStore",
    "ServerBusy",
    "outlet_temperature",
]

KEEP_RUNS = 20
"""Runs whose files the app keeps for download (the oldest goes first)."""
MAX_RUN_SECONDS = 30.0
"""Longest run, s (the heaviest built-in case at the most cells the app runs takes about 8 s)."""
MAX_RUN_BYTES = 1_500_000_000
"""Most resident memory of the process running a case, bytes (about 0.4 GB at the most cells)."""
MAX_WAITING = 2
"""Most runs waiting for their turn behind the one running; one more is refused at once."""
MAX_SHOWN_POINTS = 400
"""Most rows of a profile sent to the page (the tables for download keep every cell)."""
LIGHT_CELLS = 200
"""Runs of at most this many cells are light: they have a lane of their own, served first."""
LIGHT_WAITING = 1
"""Most light runs waiting for their turn behind the light run in progress."""
_RECYCLE_BYTES = 800_000_000  # a worker grown past this after a run is replaced

_OUTLET = re.compile(r"(^|_)bed_outlet_temperature_K$")


class ServerBusy(RuntimeError):
    """A run refused at once: its lane is full (a run in progress and :data:`MAX_WAITING`
    heavy runs, or :data:`LIGHT_WAITING` light ones, waiting)."""


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
    """What one run gives the page: summary, kiln profiles, the results of the other models
    (``models``: ``bed``, ``rtd``, ``transverse``), warnings and the files written."""

    run_id: str
    name: str
    summary: dict
    profiles: dict[str, dict[str, list]] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    files: list[str] = field(default_factory=list)
    models: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        """Plain data for the page (non-finite numbers as None)."""
        return _plain(
            {
                "run_id": self.run_id,
                "name": self.name,
                "summary": self.summary,
                "profiles": self.profiles,
                "models": self.models,
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
    """Run folders of one app, under a temporary root removed at exit, and the two worker
    processes that run the cases, one for heavy runs and one for light runs (each started at
    its lane's first run, or both by :meth:`start`; :meth:`close` ends them).

    Parameters
    ----------
    root : path, optional
        Where the run folders go (a new temporary folder by default).
    keep : int
        Runs whose files are kept.
    max_seconds, max_bytes, max_waiting, max_cells
        The bounds of a run (:data:`MAX_RUN_SECONDS`, :data:`MAX_RUN_BYTES`,
        :data:`MAX_WAITING`, :data:`~rotarykiln.app.checks.MAX_APP_CELLS`).
    """

    def __init__(
        self,
        root: str | Path | None = None,
        keep: int = KEEP_RUNS,
        *,
        max_seconds: float = MAX_RUN_SECONDS,
        max_bytes: int = MAX_RUN_BYTES,
        max_waiting: int = MAX_WAITING,
        max_cells: int = MAX_APP_CELLS,
    ):
        if root is None:
            root = tempfile.mkdtemp(prefix="rotarykiln-app-")
            atexit.register(shutil.rmtree, root, ignore_errors=True)
        self.root = Path(root)
        self.root.mkdir(parents=True, exist_ok=True)
        self.keep = keep
        self.max_seconds = max_seconds
        self.max_bytes = max_bytes
        self.max_waiting = max_waiting
        self.max_cells = max_cells
        # each lane: its run in progress (the first) and those waiting, and its worker
        self._heavy: collections.deque = collections.deque()
        self._light: collections.deque = collections.deque()
        self._changed = threading.Condition()
        self._order: list[str] = []
        self._workers: dict[bool, Worker | None] = {False: None, True: None}  # light -> worker
        atexit.register(self.close)

    def folder(self, run_id: str) -> Path | None:
        """The folder of a kept run, else None (an unknown or removed id)."""
        if not isinstance(run_id, str) or not re.fullmatch(r"[0-9a-f]{32}", run_id):
            return None
        path = self.root / run_id
        return path if path.is_dir() else None

    def start(self) -> RunStore:
        """Start both worker processes now (each takes about 2 s to import the models) rather
        than at the first run of each lane."""
        self._worker(False)
        self._worker(True)
        return self

    def _worker(self, light: bool) -> Worker:
        """The worker of a lane, a new one when it has none or it ended."""
        with self._changed:
            worker = self._workers[light]
            if worker is None or not worker.alive():
                worker = self._workers[light] = Worker("light" if light else "heavy")
            return worker

    def close(self) -> None:
        """End both worker processes (a run in progress is stopped)."""
        for light in (False, True):
            worker, self._workers[light] = self._workers[light], None
            if worker is not None:
                worker.stop()

    def worker_pid(self, light: bool = False) -> int | None:
        """The process id of the heavy runs' worker (``light``: the light runs'), if one is
        running."""
        worker = self._workers[light]
        return worker.pid if worker is not None and worker.alive() else None

    def worker_pids(self) -> list[int]:
        """The process ids of the workers running (heavy, then light)."""
        return [pid for pid in (self.worker_pid(False), self.worker_pid(True)) if pid]

    def check_free(self, light: bool | None = None) -> None:
        """Refuse at once when a run cannot wait for its turn now: a heavy run (``light``
        False), a light one (True), or either (None: before the case is read).

        Raises
        ------
        ServerBusy
            The run's lane is full: a run is running in it and :attr:`max_waiting` heavy runs
            (or :data:`LIGHT_WAITING` light ones) are waiting.
        """
        heavy_full = len(self._heavy) > self.max_waiting
        light_full = len(self._light) > LIGHT_WAITING
        if light is None:
            full = heavy_full and light_full
        else:
            full = light_full if light else heavy_full
        if full:
            waiting = len(self._light if light else self._heavy) - 1
            raise ServerBusy(
                f"the server is busy (a run and {waiting} waiting): try again in a minute"
            )

    @staticmethod
    def is_light(raw: Any) -> bool:
        """Whether a raw case is a light run (at most :data:`LIGHT_CELLS` cells), from its
        mapping: a cheap look before it is validated (a cells value that is not an integer is
        taken as heavy; the run itself goes by the validated case)."""
        solver = raw.get("solver") if isinstance(raw, dict) else None
        cells = solver.get("cells", 100) if isinstance(solver, dict) else 100
        return isinstance(cells, int) and not isinstance(cells, bool) and cells <= LIGHT_CELLS

    @contextlib.contextmanager
    def _turn(self, light: bool):
        """Wait for this run's turn in its lane (the lane's worker takes its oldest run), or
        refuse at once when the lane is full. The lanes do not wait for each other."""
        token = object()
        lane = self._light if light else self._heavy

        with self._changed:
            self.check_free(light)
            lane.append(token)
            # the runs ahead end within their bound, so this wait does too (the timeout: a guard)
            ahead = LIGHT_WAITING if light else self.max_waiting
            bound = (ahead + 1) * (self.max_seconds + START_SECONDS)
            if not self._changed.wait_for(lambda: lane[0] is token, timeout=bound):
                lane.remove(token)
                self._changed.notify_all()
                raise ServerBusy("the server is busy: try again in a minute")
        try:
            yield
        finally:
            with self._changed:
                lane.remove(token)
                self._changed.notify_all()

    def run(self, raw: dict, source: str = "case") -> RunResult:
        """Validate a raw case mapping and run it (summary, tables, figures, report.html).

        Raises
        ------
        InputError
            The case is not valid (the message of :func:`rotarykiln.case.parse_case`), names a
            file, or has more cells than the app runs.
        ConvergenceError
            A solver failed.
        ServerBusy
            The run's lane is full (:meth:`check_free`): refused at once.
        RunStopped
            The run went over :attr:`max_seconds` or :attr:`max_bytes` and was stopped.
        """
        case = parse_app_case(raw, source=source)
        check_run_size(case, self.max_cells)
        light = case.solver.cells <= LIGHT_CELLS
        with self._turn(light):
            run_id = uuid.uuid4().hex
            out = self.root / run_id
            out.mkdir()
            try:
                answer = self._in_worker(light, raw, out, source)
            except BaseException:
                shutil.rmtree(out, ignore_errors=True)
                raise
            (out / "case.yaml").write_text(case_to_yaml(case), encoding="utf-8")
            with self._changed:  # the two lanes finish runs at the same time
                self._order.append(run_id)
                removed = self._order[: max(0, len(self._order) - self.keep)]
                del self._order[: len(removed)]
            for old in removed:
                shutil.rmtree(self.root / old, ignore_errors=True)
            summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
            profiles, files = _profiles(out), _files(out)
        return RunResult(
            run_id=run_id,
            name=str(summary.get("name") or source),
            summary=_file_names(summary, out),
            profiles=profiles,
            warnings=list(answer.get("warnings") or []),
            files=files,
            models=dict(answer.get("models") or {}),
        )

    def _in_worker(self, light: bool, raw: dict, out: Path, source: str) -> dict:
        """Run in the lane's worker (one is started when there is none); a worker stopped,
        ended or grown large is replaced at the lane's next run."""
        worker = self._worker(light)
        try:
            return worker.run(raw, out, source, self.max_seconds, self.max_bytes)
        finally:
            rss = process_rss(worker.pid) if worker.alive() else None
            if not worker.alive() or (rss is not None and rss > _RECYCLE_BYTES):
                worker.stop()
                with self._changed:
                    if self._workers[light] is worker:
                        self._workers[light] = None


_ORDER = {".html": 0, ".yaml": 1, ".csv": 2, ".json": 3, ".txt": 4, ".png": 5, ".svg": 5}


def _file_names(summary: dict, out: Path) -> dict:
    """The summary with the paths of the run's files (``transport_profile_csv``) as their
    names: the page shows no path of the server's.

    >>> _file_names({"a_csv": "/tmp/x/1/a.csv", "n": 1}, Path("/tmp/x/1"))
    {'a_csv': 'a.csv', 'n': 1}
    """
    folder = str(out)
    return {
        k: Path(v).name if isinstance(v, str) and v.startswith(folder) else v
        for k, v in summary.items()
    }


def _files(out: Path) -> list[str]:
    names = [p.name for p in out.iterdir() if p.is_file() and not p.name.startswith(".")]
    return sorted(names, key=lambda n: (_ORDER.get(Path(n).suffix, 9), n))


def _profiles(out: Path, rows: int = MAX_SHOWN_POINTS) -> dict[str, dict[str, list]]:
    """The ``*_profiles.csv`` tables of a run: name -> column -> values, at most ``rows`` rows
    (evenly spaced, the first and the last kept)."""
    tables = {}
    for path in sorted(out.glob("*_profiles.csv")):
        frame = pd.read_csv(path).select_dtypes("number").astype(float)
        if len(frame) > rows:
            frame = frame.iloc[np.unique(np.linspace(0, len(frame) - 1, rows).round().astype(int))]
        tables[path.stem.removesuffix("_profiles")] = {
            c: [v if math.isfinite(v) else None for v in frame[c].tolist()] for c in frame.columns
        }
    return tables
