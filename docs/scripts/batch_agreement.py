"""Batched against single steady solves on every built-in kiln case and N random operating
points around each (issue 25's must-show: agreement to 1e-8 K on 200 points per case).

Each point changes the feed and gas flows (+-15 %), the feed temperature (+0..20 K), the gas
inlet temperature (+-3 %), the rotation (+-15 %) and the heat released (+-10 %): the
operating points of ``tests/kiln/steady/test_batch.py``. Both paths solve to 1e-13 (a single
solve that stalls just above it is polished by Broyden's updates), and the largest difference
of the bed, gas and wall temperatures is reported per case, with the points that failed in
either path (a point without a steady state must fail in both, with the same error).

Run: ``.venv/bin/python docs/scripts/batch_agreement.py [N] [CASE ...]`` (default 200 points
of every case of the test; the industrial kilns take about an hour each on two cores); prints
a Markdown table.
"""

from __future__ import annotations

import importlib.util
import sys
import time
import warnings
from pathlib import Path

import numpy as np

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import ConvergenceError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.batch import solve_batch
from rotarykiln.kiln.steady.solve import solve_kiln


def _test_module():
    """tests/kiln/steady/test_batch.py: its operating points and tolerances are the ones used
    here (one definition)."""
    path = Path(__file__).resolve().parents[2] / "tests" / "kiln" / "steady" / "test_batch.py"
    spec = importlib.util.spec_from_file_location("batch_test_points", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


_TEST = _test_module()
operating_points = _TEST.operating_points
CASES = _TEST.KILN_CASES


def compare(name: str, n: int) -> dict:
    kiln, cells = kiln_from_case(load_case(builtin_case_path(name)))
    kilns = [kiln, *operating_points(kiln, n, seed=len(name))]
    tol = _TEST.TOL_OF.get(name, _TEST.TOL)
    t0 = time.perf_counter()
    batched = solve_batch(kilns, cells, tol=tol)
    t_batch = time.perf_counter() - t0
    worst, failed, mismatched, t_single = 0.0, 0, 0, 0.0
    for k, sol in zip(kilns, batched, strict=True):
        t0 = time.perf_counter()
        try:
            single = solve_kiln(k, cells, tol=tol)
        except ConvergenceError as err:
            single = err
        t_single += time.perf_counter() - t0
        if isinstance(sol, ConvergenceError) or isinstance(single, ConvergenceError):
            failed += 1
            if type(sol) is not type(single) or str(sol) != str(single):
                mismatched += 1
            continue
        for attr in ("t_bed", "t_gas", "t_wall"):
            worst = max(worst, float(np.max(np.abs(getattr(sol, attr) - getattr(single, attr)))))
    return {
        "case": name,
        "points": len(kilns),
        "max_dT_K": worst,
        "failed": failed,
        "failed_differently": mismatched,
        "batch_ms_per_case": 1e3 * t_batch / len(kilns),
        "single_ms_per_case": 1e3 * t_single / len(kilns),
    }


def main(n: int = 200, cases=None) -> None:
    print(
        "| case | points | largest difference (K) | failed (both paths) | failed differently |"
        " batched (ms/case) | single (ms/case) |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for name in cases or CASES:
            r = compare(name, n)
            print(
                f"| {r['case']} | {r['points']} | {r['max_dT_K']:.1e} | {r['failed']} | "
                f"{r['failed_differently']} | {r['batch_ms_per_case']:.1f} | "
                f"{r['single_ms_per_case']:.1f} |",
                flush=True,
            )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200, sys.argv[2:])
