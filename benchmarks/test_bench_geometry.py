"""Speed of the cross-section geometry and regime classification on 1e5 operating points."""

import numpy as np

from rotarykiln.geometry import CrossSection, half_angle_from_fill
from rotarykiln.regimes import classify_regime

FILL = np.random.default_rng(0).uniform(1e-6, 1 - 1e-6, 100_000)


def test_bench_half_angle_from_fill_1e5(benchmark):
    theta = benchmark(half_angle_from_fill, FILL)
    assert theta.shape == FILL.shape


def test_bench_cross_section_1e5(benchmark):
    result = benchmark(lambda: CrossSection.from_fill(FILL, 1.0).as_dict())
    assert result["bed_area_m2"].shape == FILL.shape


def test_bench_classify_regime_1e5(benchmark):
    fr = np.logspace(-6, 0.5, FILL.size)
    result = benchmark(classify_regime, fr, FILL)
    assert result.name.shape == FILL.shape
