"""Fuzz campaign over the data files (issue 21): calibration data and tracer curves.

The damaged files of tests/test_fuzz_data_files.py (the same seeded generator), written to disk
and run through the CLI in-process (:func:`rotarykiln.cli.main`: its own code, exit codes and
messages): ``rotarykiln calibrate CASE --model ...:exponential_heating --data FILE --fit ...`` and
``rotarykiln rtd fit FILE --out DIR``, in worker processes with an address-space limit (an
out-of-memory shows as MemoryError) and a per-file alarm. Counts: refused (exit 2, one line),
accepted (exit 0), clean solver failures (exit 1), tracebacks (anything else escaping main),
out-of-memory, time-outs; the slowest refusal.

Usage (2 workers; results as JSON on stdout and in ``--json FILE``)::

    python docs/scripts/fuzz_campaign_data.py --n 300 --seed 21
    python docs/scripts/fuzz_campaign_data.py --n 5000 --kinds tracer --json tracer.json
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import multiprocessing as mp
import os
import resource
import signal
import sys
import tempfile
import time
import traceback
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MEMORY_LIMIT = 3 * 2**30  # bytes of address space per worker
ALARM = 60  # s per file
MODEL = "rotarykiln.studies.examples:exponential_heating"
FIT = "heat.exchange=1 1/m [0.01 1/m, 10 1/m]"


class _Alarm(Exception):
    pass


def _on_alarm(signum, frame):
    raise _Alarm


def _init_worker():
    os.environ.setdefault("MPLBACKEND", "Agg")
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    signal.signal(signal.SIGALRM, _on_alarm)
    warnings.simplefilter("ignore")
    from rotarykiln.cli import build_parser

    build_parser()  # imports every command once: not counted in the first file's time


def _argv(kind: str, data: Path, tmp: str) -> list[str]:
    if kind == "calibration":
        import yaml

        from rotarykiln.studies.examples import EXPONENTIAL_CASE

        case = Path(tmp) / "case.yaml"
        case.write_text(yaml.safe_dump(EXPONENTIAL_CASE))
        return ["calibrate", str(case), "--model", MODEL, "--data", str(data), "--fit", FIT]
    return ["rtd", "fit", str(data), "--length", "1.95", "m"]


def _one(task):
    kind, index, raw = task
    from rotarykiln import cli

    with tempfile.TemporaryDirectory() as tmp:
        data = Path(tmp) / "data.csv"
        data.write_bytes(raw)
        argv = _argv(kind, data, tmp) + ["--out", f"{tmp}/out"]
        if kind == "calibration":
            argv += ["--max-evaluations", "20"]
        out, err = io.StringIO(), io.StringIO()
        t0 = time.perf_counter()
        signal.alarm(ALARM)
        try:
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                code = cli.main(argv)
            outcome = {0: "accepted", 1: "convergence_error", 2: "refused"}.get(code, f"exit{code}")
            detail = err.getvalue().strip().splitlines()
        except MemoryError:
            outcome, detail = "out_of_memory", []
        except _Alarm:
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
    return {
        "kind": kind,
        "i": index,
        "bytes": len(raw),
        "outcome": outcome,
        "time": dt,
        "message": lines[-1][:300] if lines else "",
        "head": raw[:120].decode("utf-8", "backslashreplace"),
    }


def campaign(n: int, seed: int, workers: int, kinds) -> dict:
    sys.path.insert(0, str(ROOT / "tests"))
    from test_fuzz_data_files import _mutations

    tasks = [(kind, i, raw) for kind in kinds for i, raw in _mutations(kind, n, seed)]
    t0 = time.perf_counter()
    rows = []
    ctx = mp.get_context("fork")
    with ctx.Pool(workers, initializer=_init_worker, maxtasksperchild=200) as pool:
        for k, row in enumerate(pool.imap_unordered(_one, tasks, chunksize=1)):
            rows.append(row)
            if (k + 1) % 100 == 0:
                print(
                    f"{k + 1}/{len(tasks)} ({time.perf_counter() - t0:.0f} s)",
                    file=sys.stderr,
                    flush=True,
                )
    result: dict = {"n_per_kind": n, "seed": seed, "wall_time_s": round(time.perf_counter() - t0)}
    clean = ("refused", "accepted", "convergence_error")
    for kind in kinds:
        mine = [r for r in rows if r["kind"] == kind]
        counts: dict[str, int] = {}
        times: dict[str, list[float]] = {}
        for r in mine:
            counts[r["outcome"]] = counts.get(r["outcome"], 0) + 1
            times.setdefault(r["outcome"], []).append(r["time"])
        part = {
            "n": len(mine),
            "counts": counts,
            "time_s": {
                k: {"median": round(sorted(v)[len(v) // 2], 3), "max": round(max(v), 3)}
                for k, v in times.items()
            },
        }
        refusals = [r for r in mine if r["outcome"] == "refused"]
        if refusals:
            slow = max(refusals, key=lambda r: r["time"])
            part["slowest_refusal"] = {k: slow[k] for k in ("i", "bytes", "time", "message")}
        part["not_clean"] = [r for r in mine if r["outcome"] not in clean][:50]
        result[kind] = part
    return result


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--n", type=int, default=300, help="mutations per kind")
    p.add_argument("--seed", type=int, default=21)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--kinds", nargs="+", default=["calibration", "tracer"])
    p.add_argument("--json", help="also write the result to this file")
    args = p.parse_args()
    result = campaign(args.n, args.seed, args.workers, args.kinds)
    text = json.dumps(result, indent=1)
    if args.json:
        Path(args.json).write_text(text + "\n")
    print(text)
    return 0 if not any(result[k]["not_clean"] for k in args.kinds) else 1


if __name__ == "__main__":
    sys.exit(main())
