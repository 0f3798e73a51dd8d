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
import sys
import tempfile
from pathlib import Path

from campaign_common import ROOT, counts, emit, run_cli, run_pool, slowest_refusal, times, warm_cli

MEMORY_LIMIT = 3 * 2**30  # bytes of address space per worker
ALARM = 60  # s per file
MODEL = "rotarykiln.studies.examples:exponential_heating"
FIT = "heat.exchange=1 1/m [0.01 1/m, 10 1/m]"


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
    with tempfile.TemporaryDirectory() as tmp:
        data = Path(tmp) / "data.csv"
        data.write_bytes(raw)
        argv = _argv(kind, data, tmp) + ["--out", f"{tmp}/out"]
        if kind == "calibration":
            argv += ["--max-evaluations", "20"]
        outcome, lines, dt = run_cli(
            argv, ALARM, {0: "accepted", 1: "convergence_error", 2: "refused"}
        )
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
    rows, wall = run_pool(_one, tasks, workers, MEMORY_LIMIT, warm_cli)
    result: dict = {"n_per_kind": n, "seed": seed, "wall_time_s": round(wall)}
    clean = ("refused", "accepted", "convergence_error")
    for kind in kinds:
        mine = [r for r in rows if r["kind"] == kind]
        part = {"n": len(mine), "counts": counts(mine), "time_s": times(mine)}
        slow = slowest_refusal(mine, ("i", "bytes", "time", "message"))
        if slow:
            part["slowest_refusal"] = slow
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
    emit(result, args.json)
    return 0 if not any(result[k]["not_clean"] for k in args.kinds) else 1


if __name__ == "__main__":
    sys.exit(main())
