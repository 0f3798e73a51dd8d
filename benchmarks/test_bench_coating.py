"""Speed of the coating estimate from a 60-station shell scan (issue 26 target: <= 30 s): the
calibration of three coating knots of Barr's T4 kiln (40 cells) to synthetic shell temperatures
(tests/validation/test_coating_estimate.py)."""

import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parents[1] / "tests" / "validation"))
from test_coating_estimate import NOISE, STATIONS, TRUE, _case, _estimate, _shell  # noqa: E402


def test_bench_coating_estimate_60_stations(benchmark):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scan = _shell(_case(TRUE)) + np.random.default_rng(0).normal(0.0, NOISE, STATIONS.size)

        def run():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return _estimate(scan)

        r = benchmark.pedantic(run, rounds=3, iterations=1)
    assert r.result.success
