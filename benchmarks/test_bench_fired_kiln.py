"""Speed of one converged solve of the fired kiln, Barr's trial T4 (issue 10 targets: <= 60 ms
at 100 cells, <= 1.5 s at 1600 cells).

The kiln (burner products, Cantera gas tables, heating values) is built once, outside the
timing; each round is one ``solve_kiln`` from the default initial guess.

Run: ``.venv/bin/python -m pytest benchmarks/bench_fired_kiln.py --benchmark-enable
--benchmark-only -q --benchmark-columns=median,iqr,rounds``.
"""

import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln


@pytest.fixture(scope="module")
def barr_t4():
    kiln, _ = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    assert kiln.firing.flame is not None and kiln.firing.flame.combustion == "instant"
    solve_kiln(kiln, 100)  # first-call costs (imports, caches) outside the timing
    return kiln


def _check(sol, n):
    assert len(sol.z) == n
    assert abs(sol.energy_closure) < 1e-6
    assert abs(sol.energy_sheet["closure_relative"]) < 1e-6


def test_bench_barr_T4_100_cells(benchmark, barr_t4):
    sol = benchmark(solve_kiln, barr_t4, 100)
    _check(sol, 100)


def test_bench_barr_T4_1600_cells(benchmark, barr_t4):
    sol = benchmark.pedantic(solve_kiln, args=(barr_t4, 1600), rounds=10, iterations=1)
    _check(sol, 1600)
