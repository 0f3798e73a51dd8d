"""What the campaign scripts share: limited worker processes, the CLI run in-process, the tallies.

Used by fuzz_campaign_data.py, fuzz_campaign_files.py and hardening_campaign.py (run as scripts,
so this folder is on ``sys.path``). A worker has an address-space limit (an out-of-memory shows
as MemoryError) and answers SIGALRM with :class:`Alarm` (a per-item time limit).
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import multiprocessing as mp
import os
import resource
import signal
import sys
import time
import traceback
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


class Alarm(Exception):
    """Raised in a worker when its per-item alarm rings."""


def _on_alarm(signum, frame):
    raise Alarm


def init_worker(memory_limit: int, warm=None) -> None:
    """Set up a worker: Agg backend, address-space limit, alarm handler, no warnings; ``warm()``."""
    os.environ.setdefault("MPLBACKEND", "Agg")
    resource.setrlimit(resource.RLIMIT_AS, (memory_limit, memory_limit))
    signal.signal(signal.SIGALRM, _on_alarm)
    warnings.simplefilter("ignore")
    if warm is not None:
        warm()


def warm_cli() -> None:
    """Import every command of the CLI once: not counted in the first item's time."""
    from rotarykiln.cli import build_parser

    build_parser()


def run_cli(argv: list[str], alarm: int, outcomes: dict[int, str]) -> tuple[str, list[str], float]:
    """Run ``rotarykiln ARGV`` in-process under an alarm: (outcome, message lines, seconds).

    ``outcomes`` names the exit codes (others are ``exitN``); the outcome is also
    ``out_of_memory``, ``timeout``, ``traceback`` (anything else escaping main) or
    ``refused_not_one_line`` (exit 2 with other than one line on stderr, warnings aside).
    """
    from rotarykiln import cli

    out, err = io.StringIO(), io.StringIO()
    t0 = time.perf_counter()
    signal.alarm(alarm)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = cli.main(argv)
        outcome = outcomes.get(code, f"exit{code}")
        detail = err.getvalue().strip().splitlines()
    except MemoryError:
        outcome, detail = "out_of_memory", []
    except Alarm:
        outcome, detail = "timeout", []
    except SystemExit as exc:
        outcome, detail = f"exit{exc.code}", err.getvalue().strip().splitlines()
    except BaseException:
        outcome, detail = "traceback", traceback.format_exc().splitlines()[-6:]
    finally:
        signal.alarm(0)
    dt = time.perf_counter() - t0
    lines = [x for x in detail if not x.startswith("warning: ")]
    if outcome == "refused" and len(lines) != 1:
        outcome = "refused_not_one_line"
    return outcome, lines, dt


def run_pool(
    func,
    tasks: list,
    workers: int,
    memory_limit: int,
    warm=None,
    *,
    maxtasksperchild: int = 200,
    chunksize: int = 1,
    every: int = 100,
    label: str = "",
) -> tuple[list[dict], float]:
    """``func`` over ``tasks`` in limited worker processes, progress on stderr: (rows, seconds)."""
    t0 = time.perf_counter()
    rows = []
    ctx = mp.get_context("fork")
    with ctx.Pool(
        workers,
        initializer=init_worker,
        initargs=(memory_limit, warm),
        maxtasksperchild=maxtasksperchild,
    ) as pool:
        for k, row in enumerate(pool.imap_unordered(func, tasks, chunksize=chunksize)):
            rows.append(row)
            if (k + 1) % every == 0:
                print(
                    f"{label}{k + 1}/{len(tasks)} ({time.perf_counter() - t0:.0f} s)",
                    file=sys.stderr,
                    flush=True,
                )
    return rows, time.perf_counter() - t0


def counts(rows: list[dict]) -> dict[str, int]:
    """How many rows have each outcome."""
    out: dict[str, int] = {}
    for r in rows:
        out[r["outcome"]] = out.get(r["outcome"], 0) + 1
    return out


def times(rows: list[dict]) -> dict[str, dict[str, float]]:
    """Median and largest time of the rows of each outcome, s."""
    by_outcome: dict[str, list[float]] = {}
    for r in rows:
        by_outcome.setdefault(r["outcome"], []).append(r["time"])
    return {
        k: {"median": round(sorted(v)[len(v) // 2], 3), "max": round(max(v), 3)}
        for k, v in by_outcome.items()
    }


def slowest_refusal(rows: list[dict], keys) -> dict | None:
    """The ``keys`` of the slowest refused row, or None when none was refused."""
    refusals = [r for r in rows if r["outcome"] == "refused"]
    if not refusals:
        return None
    slow = max(refusals, key=lambda r: r["time"])
    return {k: slow.get(k) for k in keys}


def emit(result: dict, json_path: str | None) -> None:
    """Print the result as JSON (non-finite floats as null) and write it to ``json_path`` too."""
    text = json.dumps(
        result,
        indent=1,
        default=lambda o: str(o) if not isinstance(o, float) or math.isfinite(o) else None,
    )
    if json_path:
        Path(json_path).write_text(text + "\n")
    print(text)
