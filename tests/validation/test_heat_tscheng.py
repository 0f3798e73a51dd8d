"""Tscheng's (1978) pilot kiln, all 44 runs, from measured inputs only (issue 6).

Regression bounds: the overall figures measured when this model was written (mean over the 44
runs of the per-run RMSE) were, in K: bed 4.92 and gas 4.51 in the 1.25-1.78 m window; bed 11.26
and gas 5.91 over the whole length (docs/validation.md). The bounds below sit about 10 %
above them, so that a change of closure or set-up that degrades the agreement fails here. The
issue's goal (bed <= 10 K, gas <= 15 K in the window) is asserted as well. The thermocouple
accuracy of the thesis is a few K, so differences below ~3 K per point are not meaningful.
"""

import numpy as np
import pytest

from rotarykiln.kiln.tscheng import load_tscheng_runs, validate_all


@pytest.fixture(scope="module")
def scores():
    return validate_all()


def test_all_44_runs_solved_and_closed(scores):
    assert len(scores) == 44 == len(load_tscheng_runs())
    assert np.all(np.abs(scores["closure"]) < 1e-6)


def test_overall_window_rmse(scores):
    assert scores["bed_window"].mean() <= 10.0 and scores["gas_window"].mean() <= 15.0  # goal
    assert scores["bed_window"].mean() <= 5.4
    assert scores["gas_window"].mean() <= 5.0


def test_overall_whole_length_rmse(scores):
    assert scores["bed_all"].mean() <= 12.4
    assert scores["gas_all"].mean() <= 6.5


def test_no_run_far_off(scores):
    # worst runs measured: bed window 24.3 K (A50), gas window 27.7 K (A40)
    assert scores["bed_window"].max() <= 27.0
    assert scores["gas_window"].max() <= 30.0
