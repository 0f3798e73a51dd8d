"""Segregation model (eq 7.3, Table 7.3) against the 44 + 3 runs of Van Puyvelde (1999)."""

import numpy as np
import pytest

from rotarykiln.transverse.data import load_table
from rotarykiln.transverse.segregation import vanpuyvelde_concentration_proportion


@pytest.fixture(scope="module")
def runs():
    d = load_table("segregation_experiments")
    p_in, p_out = vanpuyvelde_concentration_proportion(d.psr, d.v_al_m_s, warn=False)
    d["p_in"], d["p_out"] = p_in, p_out
    d["dev_in"] = 100 * np.abs(p_in / d.p_in_exp - 1)
    d["dev_out"] = 100 * np.abs(p_out / d.p_out_exp - 1)
    return d


def test_matches_tabulated_predictions(runs):
    # Table 7.3 coefficients are printed to 0.01; the rounding of slope and intercept moves P by
    # up to ~0.005 (1 + PSR)(1 + V) ~ 0.03 at PSR 2-3: our P are within that of Table 7.2.
    assert np.all(np.abs(runs.p_in - runs.p_in_pred) <= 0.03)
    assert np.all(np.abs(runs.p_out - runs.p_out_pred) <= 0.03)


def test_average_deviation_of_44_runs(runs):
    fit = runs[runs.role == "fit"]
    assert len(fit) == 44
    # Thesis: 4.6 % inner, 2.6 % outer. The printed coefficients' rounding (see above, about
    # 0.015 on P_in, 0.005 on P_out, i.e. ~1.2 % / 0.5 %) is allowed for on top.
    assert fit.dev_in.mean() <= 4.6 + 0.5
    assert fit.dev_out.mean() <= 2.6 + 0.3
    assert fit.dev_in.max() <= 19.4 + 1.5
    assert fit.dev_out.max() <= 9.1 + 1.5


@pytest.mark.parametrize("exp", ["35", "36a", "36b"])
def test_validation_runs(runs, exp):
    table_7_4 = load_table("segregation_validation_deviations").set_index("exp")
    row = runs.set_index("exp").loc[exp]
    ref = table_7_4.loc[exp]
    # within 1.5 points of Table 7.4 (same rounding allowance as above)
    assert row.dev_in == pytest.approx(ref.inner_dev_percent, abs=1.5)
    assert row.dev_out == pytest.approx(ref.outer_dev_percent, abs=1.6)


def test_layer_balance(runs):
    # 0.25 P_in + 0.75 P_out ~ 1: the data close it within 2.3 %; the model (independent lines
    # for the two layers) within 4 % (lowest value 0.964 at PSR 5.71, high speed).
    bal = 0.25 * runs.p_in + 0.75 * runs.p_out
    assert float(np.max(np.abs(bal - 1))) < 0.04
    bal_exp = 0.25 * runs.p_in_exp + 0.75 * runs.p_out_exp
    assert float(np.max(np.abs(bal_exp - 1))) < 0.025
