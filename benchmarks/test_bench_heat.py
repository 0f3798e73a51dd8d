"""Speed of the steady kiln heat solver (issue 6 targets: one solve <= 100 ms, 44 runs <= 5 s)."""

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln import solve_kiln
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.studies.tscheng1978 import tscheng_case_name, tscheng_runs


def _kiln(name):
    return kiln_from_case(load_case(builtin_case_path(name)))


def test_bench_flame_solve_radiation_on(benchmark):
    kiln, cells = _kiln("ubc_pilot_flame")
    assert kiln.closures.radiation
    sol = benchmark(solve_kiln, kiln, cells)
    assert abs(sol.energy_closure) < 1e-6


def test_bench_tscheng_single(benchmark):
    kiln, cells = _kiln("tscheng_A16")
    sol = benchmark(solve_kiln, kiln, cells)
    assert abs(sol.energy_closure) < 1e-6


def test_bench_tscheng_44_runs(benchmark):
    # Tscheng's 44 runs, their built-in cases: read, built and solved each round
    def solve_all():
        return [solve_kiln(*_kiln(tscheng_case_name(run))) for run in tscheng_runs().index]

    sols = benchmark.pedantic(solve_all, rounds=3, iterations=1)
    assert len(sols) == 44
