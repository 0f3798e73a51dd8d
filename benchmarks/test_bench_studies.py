"""Study runner speed (issue 13): overhead per case with a trivial model, and a 1,000-case
heat-model sweep on 2 local workers. Targets: overhead <= 2 ms per case; the sweep <= 60 s."""

import tempfile

import yaml

from rotarykiln.cases import builtin_case_path
from rotarykiln.studies import grid, run_sweep
from rotarykiln.studies.design import latin_hypercube
from rotarykiln.studies.examples import first_order_conversion, trivial_model
from rotarykiln.studies.models import kiln_model

BASE = {"reaction": {"rate_constant": "0.01 1/s"}, "operation": {"residence_time": "100 s"}}
N_TRIVIAL = 2000


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


def _overhead(benchmark, executor, **kwargs):
    design = grid({"x": [float(i) for i in range(N_TRIVIAL)]})

    def run():  # a fresh store each round: every case runs and is written
        return run_sweep(
            trivial_model,
            {"x": 0.0},
            design,
            executor=executor,
            store=tempfile.mkdtemp(),
            **kwargs,
        )

    res = benchmark.pedantic(run, rounds=3, iterations=1)
    benchmark.extra_info["ms_per_case"] = benchmark.stats.stats.median / N_TRIVIAL * 1e3
    assert len(res.frame) == N_TRIVIAL and res.n_failed == 0


def test_bench_runner_overhead_2000_trivial_cases_serial_with_store(benchmark):
    _overhead(benchmark, "serial")


def test_bench_runner_overhead_2000_trivial_cases_2_processes_with_store(benchmark):
    _overhead(benchmark, "process", max_workers=2)


def test_bench_heat_sweep_1000_cases_2_processes(benchmark):
    base = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    design = latin_hypercube(
        [
            "operation.speed=uniform(1 rpm, 3 rpm)",
            "gas.temperature=uniform(500 K, 570 K)",
            "gas.flow=uniform(20 kg/h, 30 kg/h)",
        ],
        1000,
        seed=1,
    )
    res = benchmark.pedantic(
        lambda: run_sweep(kiln_model, base, design, max_workers=2, store=tempfile.mkdtemp()),
        rounds=3,
        iterations=1,
    )
    assert len(res.frame) == 1000 and res.n_failed == 0
