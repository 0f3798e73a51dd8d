"""Seed 004 chapter 5 by Sobol indices on the reacting kiln model (slow: RK_SLOW=1, ~1 min)."""

import pytest

from rotarykiln.studies.ahmad2006 import chapter5_params, chapter5_sobol, oat_ranking, run_chapter5


def test_chapter5_params_span_the_one_at_a_time_ranges():
    p = chapter5_params()
    assert len(p) == 5 and "operation.feed=uniform(0.001 kg/s, 0.010 kg/s)" in p


@pytest.mark.slow
def test_sobol_ranks_burn_off_inputs_as_the_one_at_a_time_study(tmp_path):
    sobol = chapter5_sobol(128, max_workers=2, store=tmp_path / "runs")  # 896 cases
    oat = run_chapter5(max_workers=2)
    assert sobol.sweep.n_failed == 0
    assert sobol.ranking() == oat_ranking(oat)
    assert sobol.indices["S1"].sum() <= 1.0
