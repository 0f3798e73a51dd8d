"""Reacting kiln speed: one converged solve (100 cells), and a 100-case sweep on 2 processes.

The fired limestone kiln (issue 10 targets: one converged solve <= 60 ms at 100 cells, <= 1.5 s
at 1600 cells) is built once, outside the timing.
"""

import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.studies import grid, run_sweep
from rotarykiln.studies.models import kiln_model


def _data(name):
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


def test_bench_reacting_solve_limestone_100_cells(benchmark):
    kiln, _ = kiln_from_case(parse_case(_data("limestone_calcination")))
    solve_kiln(kiln, 100)  # gas tables (Cantera) built once, outside the timing
    sol = benchmark(solve_kiln, kiln, 100)
    assert sol.conversion("CaCO3")[-1] > 0.999


def test_bench_reacting_solve_charcoal_100_cells(benchmark):
    kiln, _ = kiln_from_case(parse_case(_data("charcoal_activation")))
    solve_kiln(kiln, 100)
    sol = benchmark(solve_kiln, kiln, 100)
    assert sol.burn_off > 0


@pytest.fixture(scope="module")
def limestone_fired():
    kiln, _ = kiln_from_case(parse_case(_data("limestone_fired")))
    solve_kiln(kiln, 100)  # gas tables (Cantera) built once, outside the timing
    return kiln


def _check_fired(sol):
    assert sol.conversion("CaCO3")[-1] > 0.999
    assert abs(sol.energy_closure) <= 1e-6


def test_bench_reacting_solve_fired_100_cells(benchmark, limestone_fired):
    _check_fired(benchmark(solve_kiln, limestone_fired, 100))


def test_bench_reacting_solve_fired_1600_cells(benchmark, limestone_fired):
    sol = benchmark.pedantic(solve_kiln, args=(limestone_fired, 1600), rounds=5, iterations=1)
    _check_fired(sol)


def test_bench_reacting_sweep_100_cases_2_processes(benchmark):
    design = grid(
        {
            "bed.residence_time": [f"{t} s" for t in range(3000, 10000, 700)],
            "gas.steam_flow": [f"{0.001 * k:.3f} kg/s" for k in range(1, 11)],
        }
    )
    res = benchmark.pedantic(
        run_sweep,
        args=(kiln_model, _data("charcoal_activation"), design),
        kwargs={"max_workers": 2},
        rounds=1,
        iterations=1,
    )
    assert len(res.frame) == 100 and res.n_failed == 0
