"""Speed of the transverse grid simulation with heating (targets: base case <= 2 s median,
the 16 cases of Table 9.2 <= 30 s)."""

from rotarykiln.transverse.retort import retort_case, run_retort


def test_bench_base_case_220s(benchmark):
    spec = retort_case(2, duration=220.0, snapshot_times=())
    result = benchmark.pedantic(run_retort, args=(spec,), rounds=3, iterations=1)
    assert result.energy_error < 1e-9


def _all_cases():
    return [run_retort(retort_case(c, duration=220.0, snapshot_times=())) for c in range(1, 17)]


def test_bench_sixteen_cases(benchmark):
    results = benchmark.pedantic(_all_cases, rounds=1, iterations=1)
    assert len(results) == 16
