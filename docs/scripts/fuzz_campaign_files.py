"""Fuzz campaign over the input files that are not case files (issue 21): transient events files,
species files and reaction files.

The mutations are those of tests/test_fuzz_input_files.py (a value of a shipped file replaced
or deleted, or its text damaged: a line deleted or repeated, a character inserted, the file cut
short, a Latin-1 byte), at scale: each mutated file is written to disk and read as the program
reads it (events: :func:`rotarykiln.transient_file.read_transient_file` and
:func:`~rotarykiln.transient_file.parse_transient` against the barr_T4 kiln; species:
:func:`rotarykiln.chemistry.species.load_species`; reactions:
:func:`rotarykiln.chemistry.reaction.load_reactions`), in worker processes with an
address-space limit (out-of-memory shows as MemoryError) and a per-item alarm.

Counts per kind: ``refused`` (one InputError line), ``accepted``, ``refused_not_one_line``,
``traceback`` (any other exception), ``out_of_memory``, ``timeout``, ``unphysical`` (an
accepted file whose result is not physical: a species with a molar mass or c_p that is not
finite and > 0; a reaction that does not conserve the elements or has a non-finite heat; an
events file whose transient run, when one is made (``--runs``), has temperatures that are not
finite, outside [150 K, its hottest source], or an energy closure worse than 1e-3).

Usage (2 workers; results as JSON on stdout and in ``--json FILE``)::

    python docs/scripts/fuzz_campaign_files.py --n 5000 --seed 21
    python docs/scripts/fuzz_campaign_files.py --n 300 --kinds events --runs 20 --cells 8
"""

from __future__ import annotations

import argparse
import math
import signal
import sys
import tempfile
import time
import traceback
from pathlib import Path

from campaign_common import ROOT, Alarm, counts, emit, run_pool, slowest_refusal

sys.path.insert(0, str(ROOT / "tests"))

MEMORY_LIMIT = 3 * 2**30  # bytes of address space per worker
ALARM = 30  # s per file read (a run gets RUN_ALARM)
RUN_ALARM = 300  # s per transient run
KINDS = ("events", "species", "reactions")

_KILN = None  # the barr_T4 kiln of a worker (events are checked against it)


def _load_kiln():
    global _KILN
    from test_fuzz_input_files import barr_kiln

    _KILN = barr_kiln()


# ------------------------------------------------------------------------------ physical checks


def _species_problems(table) -> list[str]:
    import numpy as np

    problems = []
    for s in table.species:
        if not (math.isfinite(s.molar_mass) and s.molar_mass > 0):
            problems.append(f"{s.name}: molar mass {s.molar_mass!r}")
        if not (math.isfinite(s.cp) and s.cp > 0):
            problems.append(f"{s.name}: c_p {s.cp!r}")
        if s.thermo is not None:
            try:
                cp = np.asarray(s.thermo.cp(np.linspace(300.0, 1000.0, 15)), dtype=float)
            except Exception as exc:  # a c_p form that fails where it was accepted
                problems.append(f"{s.name}: c_p(T) raises {type(exc).__name__}")
                continue
            if not np.all(np.isfinite(cp)):
                problems.append(f"{s.name}: c_p(T) not finite")
    return problems


def _reaction_problems(reactions: dict) -> list[str]:
    problems = []
    for name, r in reactions.items():
        residual = r.element_residual()
        scale = sum(
            abs(nu) * sum(abs(a) for a in r.species[n].elements.values())
            for n, nu in r.stoichiometry.items()
        )
        if residual and max(abs(v) for v in residual.values()) > 1e-6 * max(scale, 1.0):
            problems.append(f"{name}: element residual {residual}")
        if not math.isfinite(r.heat):
            problems.append(f"{name}: heat {r.heat!r}")
    return problems


def _transient_problems(kiln, transient, until: float, cells: int) -> list[str]:
    """Run the transient and check it (temperatures bounded by the sources, energy closed)."""
    import numpy as np

    from rotarykiln.kiln.transient.events import Schedule
    from rotarykiln.kiln.transient.integrate import simulate

    sol = simulate(kiln, cells, transient, until)
    temps = sol.x[:, :, : sol.i_species]
    problems = []
    if not np.all(np.isfinite(temps)):
        return ["non-finite temperature"]
    sched = Schedule(kiln, sol.bed_names, sol.gas_names, transient.events, until, transient.tracer)
    hottest, fired = 0.0, False
    for i in range(len(sched.segments())):
        _, knots, _ = sched._segment_knots(i)  # the inputs are linear between these knots
        for u in knots:
            hottest = max(hottest, u.gas_temperature, u.feed_temperature)
            fired = fired or u.heat_release > 0
    if fired:  # heat released along the flame: the adiabatic flame temperature bounds it
        hottest = max(hottest, 3000.0)
    if temps.min() < 150.0 or temps.max() > hottest + 1.0:
        problems.append(
            f"T in [{temps.min():.1f}, {temps.max():.1f}] K, hottest source {hottest:.1f} K"
        )
    closure = float(np.max(np.abs(sol.energy_conservation())))
    if not closure < 1e-3:
        problems.append(f"energy closure {closure:.3g}")
    return problems


# ---------------------------------------------------------------------------------------- items


def _one(task):
    index, kind, name, what, content, run, cells = task
    from rotarykiln.errors import ConvergenceError, InputError
    from test_fuzz_input_files import EVENTS_UNTIL, read_file

    row = {"i": index, "kind": kind, "base": name, "mutation": what}
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / f"{kind}.yaml"
        path.write_bytes(content)
        signal.alarm(ALARM)
        try:
            result = read_file(kind, path, _KILN)
            problems = []
            if kind == "species":
                problems = _species_problems(result)
            elif kind == "reactions":
                problems = _reaction_problems(result)
            elif run:
                signal.alarm(RUN_ALARM)
                row["ran"] = True
                try:
                    problems = _transient_problems(_KILN, result, EVENTS_UNTIL, cells)
                except ConvergenceError as exc:
                    row["run_failed"] = str(exc)[:200]
                except InputError as exc:  # refused at run time (a burner without air...)
                    row["run_refused"] = str(exc)[:200]
            row["outcome"] = "unphysical" if problems else "accepted"
            row["problems"] = problems[:5]
        except InputError as exc:
            msg = str(exc)
            row["outcome"] = "refused" if "\n" not in msg else "refused_not_one_line"
            row["message"] = msg[:300]
        except MemoryError:
            row["outcome"] = "out_of_memory"
        except Alarm:
            row["outcome"] = "timeout"
        except BaseException:
            row["outcome"] = "traceback"
            row["message"] = traceback.format_exc().splitlines()[-3:]
        finally:
            signal.alarm(0)
    row["time"] = time.perf_counter() - t0
    return row


def _choose_runs(tasks: list, runs: int) -> None:
    """Mark the first ``runs`` of the events ``tasks`` that are accepted to be run."""
    from rotarykiln.errors import InputError
    from test_fuzz_input_files import barr_kiln, read_file

    kiln = barr_kiln()
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "events.yaml"
        for task in tasks:
            path.write_bytes(task[4])
            try:
                read_file("events", path, kiln)
            except InputError:
                continue
            except Exception:  # counted by the campaign itself
                continue
            task[5] = True
            runs -= 1
            if runs <= 0:
                return


def campaign(n: int, seed: int, workers: int, kinds, runs: int, cells: int) -> dict:
    from test_fuzz_input_files import mutations

    tasks = []
    for kind in kinds:
        for name, what, content in mutations(kind, n, seed):
            tasks.append([len(tasks), kind, name, what, content, False, cells])
    if runs and "events" in kinds:  # the first ``runs`` accepted events files are run
        _choose_runs([t for t in tasks if t[1] == "events"], runs)
    tasks = [tuple(t) for t in tasks]
    rows, wall = run_pool(
        _one,
        tasks,
        workers,
        MEMORY_LIMIT,
        _load_kiln,
        maxtasksperchild=500,
        chunksize=4,
        every=200,
    )
    result = {"n_per_kind": n, "seed": seed, "wall_time_s": round(wall, 1)}
    for kind in kinds:
        mine = [r for r in rows if r["kind"] == kind]
        ran = [r for r in mine if r.get("ran")]
        entry = {"n": len(mine), "counts": counts(mine)}
        if ran:
            entry["runs"] = {
                "made": len(ran),
                "solver_failed": sum("run_failed" in r for r in ran),
                "refused_at_run": sum("run_refused" in r for r in ran),
                "max_time_s": round(max(r["time"] for r in ran), 1),
            }
        slow = slowest_refusal(mine, ("mutation", "time", "message"))
        if slow:
            entry["slowest_refusal"] = slow
        entry["not_clean"] = [r for r in mine if r["outcome"] not in ("refused", "accepted")][:30]
        result[kind] = entry
    return result


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--n", type=int, default=5000, help="mutations per kind")
    p.add_argument("--seed", type=int, default=21)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--kinds", nargs="+", choices=KINDS, default=list(KINDS))
    p.add_argument("--runs", type=int, default=0, help="accepted events files run (transient)")
    p.add_argument("--cells", type=int, default=8, help="cells of those runs")
    p.add_argument("--json", help="also write the result to this file")
    args = p.parse_args()
    result = campaign(args.n, args.seed, args.workers, args.kinds, args.runs, args.cells)
    emit(result, args.json)
    return 0 if not any(result[k]["not_clean"] for k in args.kinds) else 1


if __name__ == "__main__":
    sys.exit(main())
