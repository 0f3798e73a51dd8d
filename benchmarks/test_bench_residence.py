"""Residence-time effects speed: segregated flow over 40 RTD classes through a solved kiln.

The kiln (limestone calcination, 100 cells) is solved once outside the timing; the benchmarks
time the batched integration of the RTD classes through its frozen profiles
(:func:`~rotarykiln.chemistry.segregated.kiln_segregated_conversion`, 40 classes and the mean)
and the whole :func:`~rotarykiln.kiln.bed.residence.residence_time_effects` step of ``rotarykiln
run`` (24 classes, the mean and the frozen plug class). Before the batching (one LSODA run per
class) the run step took 12-13 s.

Run: ``pytest benchmarks/bench_residence.py --benchmark-enable --benchmark-only``.
"""

import pytest
import yaml

import rotarykiln.kiln.bed.residence as residence
from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import bed_peclet
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln


@pytest.fixture(scope="module", params=["limestone_calcination", "charcoal_activation"])
def solved(request):
    data = yaml.safe_load(builtin_case_path(request.param).read_text(encoding="utf-8"))
    case = parse_case(data)
    kiln, cells = kiln_from_case(case)
    sol = solve_kiln(kiln, cells)
    seen = {}
    real = residence.kiln_segregated_conversion

    def spy(*args, **kwargs):
        seen["args"], seen["kwargs"] = args, kwargs
        return real(*args, **kwargs)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(residence, "kiln_segregated_conversion", spy)
        residence.residence_time_effects(kiln, sol, peclet=_peclet(case, sol))
    return case, kiln, sol, seen


def _peclet(case, sol):
    return bed_peclet(case, sol.residence_time)[0]


def test_bench_segregated_flow_40_classes(benchmark, solved):
    _, _, _, seen = solved
    kwargs = {**seen["kwargs"], "n_tau": 40}
    kwargs.pop("extra_residence_times")
    res = benchmark(residence.kiln_segregated_conversion, *seen["args"], **kwargs)
    assert res.class_tau.size == 41 and 0 < res.segregated <= 1


def test_bench_residence_time_effects(benchmark, solved):
    case, kiln, sol, _ = solved
    pe = _peclet(case, sol)
    eff = benchmark(residence.residence_time_effects, kiln, sol, peclet=pe)
    assert 0 < eff.result.segregated <= 1
