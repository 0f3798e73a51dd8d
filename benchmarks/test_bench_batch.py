"""Speed of batched steady solves (issue 25).

- ``solve_batch`` of 200 operating points of Barr T4 and of Tscheng A16 (kilns built outside
  the timing): the solve alone, per case (``extra_info["ms_per_case"]``), against one
  ``solve_kiln`` of the same kiln (test_bench_fired_kiln.py: 28 ms);
- the 200-case sweep of Barr T4 over fuel flow and feed, serial, as the command runs it
  (cases parsed and built, flames computed, outputs gathered);
- the Sobol study of 8 inputs of Barr T4 at N = 512 (5,120 cases) on 2 processes
  (target <= 10 s).

Run: ``.venv/bin/python -m pytest benchmarks/test_bench_batch.py --benchmark-enable
--benchmark-only -q --benchmark-columns=median,iqr,rounds``.
"""

import tempfile
import warnings

import numpy as np
import pytest
import yaml

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.batch import solve_batch
from rotarykiln.studies import run_sweep
from rotarykiln.studies.design import latin_hypercube
from rotarykiln.studies.models import kiln_model
from rotarykiln.studies.sensitivity import sobol_indices

N_POINTS = 200


def _points(name, n=N_POINTS, seed=0):
    kiln, cells = kiln_from_case(load_case(builtin_case_path(name)))
    rng = np.random.default_rng(seed)
    kilns = [
        kiln.replace(
            gas__temperature=kiln.gas.temperature * rng.uniform(0.95, 1.05),
            gas__flows={s: v * rng.uniform(0.8, 1.2) for s, v in kiln.gas.flows.items()},
            drum__omega=kiln.drum.omega * rng.uniform(0.7, 1.5),
        )
        for _ in range(n)
    ]
    return kilns, cells


@pytest.mark.parametrize("name", ["barr_T4", "tscheng_A16"])
def test_bench_solve_batch_200_operating_points(benchmark, name):
    kilns, cells = _points(name)

    def run():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return solve_batch(kilns, cells)

    out = benchmark.pedantic(run, rounds=3, iterations=1, warmup_rounds=1)
    benchmark.extra_info["ms_per_case"] = benchmark.stats.stats.median / N_POINTS * 1e3
    assert all(abs(s.energy_closure) < 1e-6 for s in out)


def test_bench_sweep_barr_T4_fuel_and_feed_200_cases_serial(benchmark):
    base = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    design = latin_hypercube(
        ["burner.fuel_flow=uniform(1.8 L/s, 2.1 L/s)", "operation.feed=uniform(55 kg/h, 70 kg/h)"],
        N_POINTS,
        seed=1,
    )

    def run():
        return run_sweep(kiln_model, base, design, executor="serial", store=tempfile.mkdtemp())

    res = benchmark.pedantic(run, rounds=3, iterations=1)
    assert len(res.frame) == N_POINTS and res.n_failed == 0


SOBOL_INPUTS = [
    "burner.fuel_flow=uniform(1.8 L/s, 2.1 L/s)",
    "operation.feed=uniform(55 kg/h, 70 kg/h)",
    "operation.speed=uniform(1.2 rpm, 1.8 rpm)",
    "operation.feed_temperature=uniform(290 K, 310 K)",
    "burner.secondary_air.flow=uniform(40 L/s, 46 L/s)",
    "burner.primary_air.flow=uniform(16 L/s, 19 L/s)",
    "burner.secondary_air.temperature=uniform(290 K, 320 K)",
    "burner.primary_air.temperature=uniform(290 K, 320 K)",
]


def test_bench_sobol_barr_T4_8_inputs_N_512(benchmark):
    base = yaml.safe_load(builtin_case_path("barr_T4").read_text())

    def run():
        return sobol_indices(
            kiln_model,
            base,
            SOBOL_INPUTS,
            "bed_outlet_temperature_K",
            512,
            max_workers=2,
            store=tempfile.mkdtemp(),
        )

    res = benchmark.pedantic(run, rounds=3, iterations=1)
    assert res is not None
