"""The hardening campaigns of docs/dev/hardening.md (issue 15).

``fuzz``: mutated built-in case files (the seeded generator of tests/test_fuzz_cases.py) written
to disk and run through ``rotarykiln run FILE --out DIR --no-plots`` in-process
(:func:`rotarykiln.cli.main`: the CLI's own code, exit codes and messages), in worker processes
with an address-space limit (out-of-memory shows as MemoryError) and a per-case alarm. Counts:
refused (exit 2, one line), converged (exit 0), ConvergenceError (exit 1), tracebacks (anything
else escaping main), out-of-memory, time-outs; the slowest refusal.

``envelope``: random, physically sensible operating points around the built-in kiln cases
(speed, feed, gas or fuel and air flows, gas and feed temperatures within sensible factors),
solved as ``rotarykiln run`` solves them (:func:`rotarykiln.commands.kiln_runs.run_kiln_case`), each
solution checked: energy closure, element closure, finite temperatures; an inert hot-gas kiln
(tscheng_A16) no hotter than its hottest inlet and no colder than its coldest source.

Usage (2 workers; results as JSON on stdout and in ``--json FILE``)::

    python docs/scripts/hardening_campaign.py fuzz --n 5000 --seed 15
    python docs/scripts/hardening_campaign.py envelope --n 1000 --seed 7
"""

from __future__ import annotations

import argparse
import copy
import random
import signal
import sys
import tempfile
import time
import traceback
from pathlib import Path

from campaign_common import (
    ROOT,
    Alarm,
    counts,
    emit,
    run_cli,
    run_pool,
    slowest_refusal,
    times,
    warm_cli,
)

MEMORY_LIMIT = 4 * 2**30  # bytes of address space per worker
ALARM = 120  # s per case


# ---------------------------------------------------------------------------------------- fuzz


def _fuzz_one(task):
    index, name, path, data = task
    import yaml

    with tempfile.TemporaryDirectory() as tmp:
        case_file = Path(tmp) / "case.yaml"
        try:
            case_file.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
        except Exception as exc:  # not representable as YAML (e.g. nan keys): skip
            return {"i": index, "case": name, "outcome": "unwritable", "error": repr(exc)}
        outcome, lines, dt = run_cli(
            ["run", str(case_file), "--out", f"{tmp}/out", "--no-plots"],
            ALARM,
            {0: "converged", 1: "convergence_error", 2: "refused"},
        )
    return {
        "i": index,
        "case": name,
        "path": [str(p) for p in path],
        "outcome": outcome,
        "time": dt,
        "message": lines[-1][:300] if lines else "",
    }


def fuzz(n: int, seed: int, workers: int) -> dict:
    sys.path.insert(0, str(ROOT / "tests"))
    from test_fuzz_cases import _mutations

    tasks = [(i, name, path, data) for i, (name, path, data) in enumerate(_mutations(n, seed))]
    return _campaign(_fuzz_one, tasks, workers, "fuzz")


# ------------------------------------------------------------------------------------ envelope


def _scale(text, f):
    number, unit = str(text).split(" ", 1)
    return f"{float(number) * f:.6g} {unit}"


def _temperature(text, f):
    from rotarykiln.units import to_si

    return f"{to_si('T', text, 'temperature') * f:.6g} K"


ENVELOPE_CASES = (
    "tscheng_A16",
    "barr_T4",
    "ubc_pilot_flame",
    "limestone_fired",
    "limestone_calcination",
    "charcoal_activation",
)


def _operating_point(name: str, base: dict, rng: random.Random) -> tuple[dict, dict]:
    """A random operating point around the case ``base``: the case and the factors used."""
    d = copy.deepcopy(base)
    f = {"speed": rng.uniform(0.6, 1.6), "feed": rng.uniform(0.6, 1.6)}
    d["operation"]["speed"] = _scale(d["operation"]["speed"], f["speed"])
    d["operation"]["feed"] = _scale(d["operation"]["feed"], f["feed"])
    if "feed_temperature" in d["operation"]:
        f["feed_temperature"] = rng.uniform(0.95, 1.05)
        d["operation"]["feed_temperature"] = _temperature(
            d["operation"]["feed_temperature"], f["feed_temperature"]
        )
    if "burner" in d:  # fuel within +-30 %, the air with it (excess air kept >= nominal - 10 %)
        b = d["burner"]
        f["fuel"] = rng.uniform(0.7, 1.3)
        f["air"] = f["fuel"] * rng.uniform(0.9, 1.3)
        b["fuel_flow"] = _scale(b["fuel_flow"], f["fuel"])
        for key in ("primary_air", "secondary_air"):
            if key in b:
                b[key]["flow"] = _scale(b[key]["flow"], f["air"])
    else:  # a hot-gas kiln: gas flow and inlet temperature
        g = d["gas"]
        f["gas_flow"] = rng.uniform(0.6, 1.6)
        g["flow"] = _scale(g["flow"], f["gas_flow"])
        high = 1.15 if name == "tscheng_A16" else 1.0  # the reacting cases: their top is given
        f["gas_temperature"] = rng.uniform(0.9, high)
        g["temperature"] = _temperature(g["temperature"], f["gas_temperature"])
        if "steam_flow" in g:
            f["steam"] = rng.uniform(0.7, 1.3)
            g["steam_flow"] = _scale(g["steam_flow"], f["steam"])
    return d, f


def _envelope_one(task):
    index, name, data, factors = task
    import numpy as np

    from rotarykiln.case import parse_case
    from rotarykiln.commands.kiln_runs import run_kiln_case
    from rotarykiln.errors import ConvergenceError, InputError

    row = {"i": index, "case": name, "factors": factors}
    t0 = time.perf_counter()
    signal.alarm(ALARM)
    try:
        case = parse_case(data)
        sol = run_kiln_case(case)
        problems = []
        if not abs(sol.energy_closure) < 1e-6:
            problems.append(f"energy closure {sol.energy_closure:.3g}")
        elements = [abs(v) for v in (sol.element_closure or {}).values()]
        if elements and not max(elements) < 1e-8:
            problems.append(f"element closure {max(elements):.3g}")
        temps = np.concatenate([sol.t_bed, sol.t_gas, sol.t_wall])
        if not np.all(np.isfinite(temps)):
            problems.append("non-finite temperature")
        if name == "tscheng_A16":  # inert, heated by the gas alone
            hottest = max(case.gas.temperature, case.operation.feed_temperature)
            coldest = min(case.gas.temperature, case.operation.feed_temperature)
            coldest = min(coldest, case.wall.ambient_temperature)
            if temps.max() > hottest + 1e-6 or temps.min() < coldest - 1e-6:
                problems.append(f"T in [{temps.min():.1f}, {temps.max():.1f}] K outside sources")
        row["outcome"] = "unphysical" if problems else "converged"
        row["problems"] = problems
        row["t_bed_out_K"] = float(sol.bed_outlet_temperature)
        row["zigzag_K"] = float(np.max(np.abs(np.diff(sol.t_bed, 2)))) if sol.t_bed.size > 2 else 0
        # cell-to-cell oscillation: successive steps of the bed temperature of opposite signs,
        # both over 5 K (a smooth profile has a few turning points at most)
        d = np.diff(sol.t_bed)
        flips = (d[:-1] * d[1:] < 0) & (np.minimum(abs(d[:-1]), abs(d[1:])) > 5.0)
        row["flips"] = int(flips.sum())
    except ConvergenceError as exc:
        row["outcome"], row["message"] = "convergence_error", str(exc)[:300]
    except InputError as exc:
        row["outcome"], row["message"] = "refused", str(exc)[:300]
    except MemoryError:
        row["outcome"] = "out_of_memory"
    except Alarm:
        row["outcome"] = "timeout"
    except BaseException:
        row["outcome"], row["message"] = "traceback", traceback.format_exc()[-1500:]
    finally:
        signal.alarm(0)
    row["time"] = time.perf_counter() - t0
    return row


def envelope(n: int, seed: int, workers: int) -> dict:
    import yaml

    from rotarykiln.cases import builtin_case_path

    rng = random.Random(seed)
    bases = {c: yaml.safe_load(builtin_case_path(c).read_text()) for c in ENVELOPE_CASES}
    tasks = []
    for i in range(n):
        name = ENVELOPE_CASES[i % len(ENVELOPE_CASES)]
        data, factors = _operating_point(name, bases[name], rng)
        tasks.append((i, name, data, factors))
    return _campaign(_envelope_one, tasks, workers, "envelope")


# -------------------------------------------------------------------------------------- common


def _campaign(func, tasks, workers, kind) -> dict:
    rows, wall = run_pool(func, tasks, workers, MEMORY_LIMIT, warm_cli, label=f"{kind}: ")
    n_by_outcome = counts(rows)
    result = {"kind": kind, "n": len(rows), "wall_time_s": round(wall, 1), "counts": n_by_outcome}
    result["time_s"] = times(rows)
    slow = slowest_refusal(rows, ("case", "path", "time", "message"))
    if slow:
        result["slowest_refusal"] = slow
    result["not_clean"] = [
        r
        for r in rows
        if r["outcome"] not in ("refused", "converged", "convergence_error", "unwritable")
    ][:50]
    result["convergence_errors"] = [r for r in rows if r["outcome"] == "convergence_error"]
    if kind == "envelope":
        result["per_case"] = {}
        for r in rows:
            c = result["per_case"].setdefault(r["case"], {})
            c[r["outcome"]] = c.get(r["outcome"], 0) + 1
        for r in rows:
            if "zigzag_K" in r:
                c = result["per_case"][r["case"]]
                c["max_d2T_bed_K"] = round(max(c.get("max_d2T_bed_K", 0), r["zigzag_K"]), 1)
                c["max_flips"] = max(c.get("max_flips", 0), r["flips"])
        result["oscillating"] = [r for r in rows if r.get("flips", 0) > 2]
        conv = n_by_outcome.get("converged", 0)
        result["converged_percent"] = round(100 * conv / max(len(rows), 1), 2)
    return result


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("campaign", choices=("fuzz", "envelope"))
    p.add_argument("--n", type=int, default=5000)
    p.add_argument("--seed", type=int, default=15)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--json", help="also write the result to this file")
    args = p.parse_args()
    run = fuzz if args.campaign == "fuzz" else envelope
    result = run(args.n, args.seed, args.workers)
    emit(result, args.json)
    return 0 if not result["not_clean"] else 1


if __name__ == "__main__":
    sys.exit(main())
