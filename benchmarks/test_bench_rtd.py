"""RTD speed: one least-squares fit of a 200-point curve (target <= 50 ms median) and the
open-open E(t) on 1e4 points (target <= 1 ms)."""

import numpy as np

from rotarykiln.rtd.dispersion import closed_closed_exit_age, open_open_exit_age
from rotarykiln.rtd.fitting import fit_rtd

TAU, PE = 2520.0, 550.0
T200 = np.linspace(30.0, 62.0, 200) * 60.0
E200 = open_open_exit_age(T200, TAU, PE) * (
    1 + 0.02 * np.random.default_rng(3).standard_normal(200)
)
T1E4 = np.linspace(1.0, 2 * TAU, 10_000)


def test_bench_fit_open_open_200_points(benchmark):
    fit = benchmark(fit_rtd, T200, E200, model="open-open")
    assert abs(fit.peclet / PE - 1) < 0.05


def test_bench_open_open_exit_age_1e4(benchmark):
    e = benchmark(open_open_exit_age, T1E4, TAU, PE)
    assert e.shape == (10_000,)


def test_bench_closed_closed_laplace_200_points(benchmark):
    e = benchmark(closed_closed_exit_age, T200, TAU, PE)
    assert e.shape == (200,)
