"""Speed of the steady kiln heat solver (issue 6 targets: one solve <= 100 ms, 44 runs <= 5 s)."""

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln import solve_kiln
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.tscheng import tscheng_kiln, validate_all


def test_bench_flame_solve_radiation_on(benchmark):
    kiln, cells = kiln_from_case(load_case(builtin_case_path("ubc_pilot_flame")))
    assert kiln.closures.radiation
    sol = benchmark(solve_kiln, kiln, cells)
    assert abs(sol.energy_closure) < 1e-6


def test_bench_tscheng_single(benchmark):
    kiln = tscheng_kiln("A16")
    sol = benchmark(solve_kiln, kiln, 100)
    assert abs(sol.energy_closure) < 1e-6


def test_bench_tscheng_44_runs(benchmark):
    scores = benchmark.pedantic(validate_all, rounds=3, iterations=1)
    assert len(scores) == 44
