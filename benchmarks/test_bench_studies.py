"""Overhead of a 100-case sweep in local processes (2 cores) with a cheap model."""

from rotarykiln.studies import grid, run_sweep
from rotarykiln.studies.examples import first_order_conversion

BASE = {"reaction": {"rate_constant": "0.01 1/s"}, "operation": {"residence_time": "100 s"}}


def test_bench_sweep_100_cases_2_processes(benchmark):
    design = grid(
        {
            "operation.residence_time": [f"{t} s" for t in range(10, 110, 10)],
            "reaction.rate_constant": [0.001 * k for k in range(1, 11)],
        }
    )
    res = benchmark.pedantic(
        run_sweep,
        args=(first_order_conversion, BASE, design),
        kwargs={"max_workers": 2},
        rounds=3,
        iterations=1,
    )
    assert len(res.frame) == 100 and res.n_failed == 0
