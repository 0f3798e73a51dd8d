"""Segregation model (eq 7.3, Table 7.3) against the 44 + 3 runs of Van Puyvelde (1999).

The thesis prints every number of Tables 7.1-7.4 to two decimals (P) or one decimal (%), so
the tolerances below are the half units of that printing, propagated; see docs/validation.md.
"""

import numpy as np
import pytest

from rotarykiln.transverse.data import load_table
from rotarykiln.transverse.segregation import (
    COEFFICIENT_SETS,
    vanpuyvelde_concentration_proportion,
)
from rotarykiln.transverse.segregation_fit import (
    backfit_segregation_coefficients,
    segregation_run_velocity,
)

HALF_UNIT = 0.005  # P printed to 0.01 in Tables 7.1 and 7.2


def _deviation(p, p_exp):
    return 100 * np.abs(p / p_exp - 1)  # thesis: absolute % of the experimental value


@pytest.fixture(scope="module")
def runs():
    d = load_table("segregation_experiments")
    # V_AL unrounded, as the thesis computed it: eqs 5.2/5.6 from N and the series loading
    # (the loading is not printed; fitted per series to the X_AL and V_AL columns of Table 7.2)
    d["v"] = segregation_run_velocity(d.speed_rpm, d.fill_fitted_percent / 100)
    for name in ("backfit", "printed"):
        p_in, p_out = vanpuyvelde_concentration_proportion(
            d.psr, d.v, warn=False, coefficients=name
        )
        d[f"p_in_{name}"], d[f"p_out_{name}"] = p_in, p_out
        d[f"dev_in_{name}"] = _deviation(p_in, d.p_in_exp)
        d[f"dev_out_{name}"] = _deviation(p_out, d.p_out_exp)
    return d


def test_printed_coefficients_fall_below_the_thesis_predictions(runs):
    # The documented cause of the old 4.9 / 2.8 %: with Table 7.3 as printed (two decimals)
    # eq 7.3 sits systematically below the thesis's own predicted column. "Systematically":
    # the mean gap is below minus three standard errors of what the printing of P_pred alone
    # can make (uniform +-HALF_UNIT: sd 2 HALF_UNIT / sqrt(12) per run, over the 47 runs).
    noise = 3 * 2 * HALF_UNIT / np.sqrt(12) / np.sqrt(len(runs))
    bias_in = (runs.p_in_printed - runs.p_in_pred).mean()
    bias_out = (runs.p_out_printed - runs.p_out_pred).mean()
    assert bias_in < -noise
    assert bias_out < -noise
    assert np.abs(runs.p_in_printed - runs.p_in_pred).max() > 2 * HALF_UNIT


def test_backfit_reproduces_the_thesis_predictions(runs):
    # Provenance of the back-fitted coefficients, not a validation: they were fitted to the
    # predicted columns of Table 7.2 (test_backfit_provenance). Stored to 4 decimals, they
    # reproduce every one of the 47 printed predictions within its own rounding (half unit
    # 0.005, + 0.0005 for the 4-decimal storage).
    assert np.abs(runs.p_in_backfit - runs.p_in_pred).max() <= HALF_UNIT + 0.0005
    assert np.abs(runs.p_out_backfit - runs.p_out_pred).max() <= HALF_UNIT + 0.0005
    assert abs((runs.p_in_backfit - runs.p_in_pred).mean()) < 0.001
    # with the printed (rounded) V_AL instead: + |m| <= 1.04 s/m times 0.005 m/s
    p_in, p_out = vanpuyvelde_concentration_proportion(runs.psr, runs.v_al_m_s, warn=False)
    assert np.abs(p_in - runs.p_in_pred).max() <= HALF_UNIT + 1.04 * 0.005
    assert np.abs(p_out - runs.p_out_pred).max() <= HALF_UNIT + 0.39 * 0.005


def test_backfit_provenance(runs):
    # the stored set is exactly what the back-fit to the predicted column gives ...
    fitted = backfit_segregation_coefficients(load_table("segregation_experiments"))
    assert fitted == COEFFICIENT_SETS["backfit"]
    # ... and each number is compatible with its two-decimal print (within the half unit)
    printed = COEFFICIENT_SETS["printed"]
    diff = np.array([np.subtract(fitted[k], printed[k]) for k in printed])
    assert np.abs(diff).max() <= HALF_UNIT + 1e-12


def test_thesis_averages_from_the_printed_tables(runs):
    # The thesis's 4.6 / 2.6 % were computed before rounding: its printed predictions against the
    # printed measurements give 4.67 / 2.63 %, and its stated extremes (min 0.2 % where the
    # printed values agree exactly, max 9.1 % outer at 32b where they give 8.4 %) need the lost
    # third decimals. Redrawing those decimals (uniform +-0.005 on both columns) gives the band
    # the printed tables allow around the thesis's model: it contains 4.6 and 2.6.
    fit = runs[runs.role == "fit"]
    assert _deviation(fit.p_in_pred, fit.p_in_exp).mean() == pytest.approx(4.6, abs=0.1)
    assert _deviation(fit.p_out_pred, fit.p_out_exp).mean() == pytest.approx(2.6, abs=0.1)
    rng = np.random.default_rng(1999)
    for col, stated in (("in", 4.6), ("out", 2.6)):
        pred, exp = fit[f"p_{col}_pred"].to_numpy(), fit[f"p_{col}_exp"].to_numpy()
        u = rng.uniform(-HALF_UNIT, HALF_UNIT, (2, 4000, len(fit)))
        means = _deviation(pred + u[0], exp + u[1]).mean(axis=1)
        lo, hi = np.percentile(means, [2.5, 97.5])
        assert lo <= stated <= hi
        assert hi - stated >= 0.15  # the allowance used below


def test_average_deviation_of_44_runs(runs):
    fit = runs[runs.role == "fit"]
    assert len(fit) == 44
    # thesis 4.6 % inner, 2.6 % outer; ours (back-fit) 4.69 / 2.73 %, which the two-decimal
    # tables cannot tell apart from the thesis's (band above: +0.15 points is inside it)
    assert fit.dev_in_backfit.mean() <= 4.6 + 0.15
    assert fit.dev_out_backfit.mean() <= 2.6 + 0.15
    # the printed coefficients do worse (4.92 / 2.79 %): the gap was the rounding
    assert fit.dev_in_printed.mean() > fit.dev_in_backfit.mean() + 0.15
    # extremes: thesis 19.4 % (29a) and 9.1 % (32b); a single run's deviation is fixed only to
    # 100 * 0.005 * (1/P_exp + P/P_exp^2) ~ 1 point by the printing
    i_max, o_max = fit.dev_in_backfit.idxmax(), fit.dev_out_backfit.idxmax()
    assert fit.exp[i_max] == "29a" and fit.exp[o_max] == "32b"
    assert fit.dev_in_backfit.max() == pytest.approx(19.4, abs=1.0)
    assert fit.dev_out_backfit.max() == pytest.approx(9.1, abs=1.2)


@pytest.mark.parametrize("exp", ["35", "36a", "36b"])
def test_validation_runs(runs, exp):
    table_7_4 = load_table("segregation_validation_deviations").set_index("exp")
    row = runs.set_index("exp").loc[exp]
    ref = table_7_4.loc[exp]
    # Table 7.4 equals the deviations of the printed predictions, so ours may differ by the half
    # unit of P (+ 0.0005 of the fit) over P_exp, + 0.05 for printing the % to 0.1
    tol_in = 100 * (HALF_UNIT + 0.0005) / row.p_in_exp + 0.05
    tol_out = 100 * (HALF_UNIT + 0.0005) / row.p_out_exp + 0.05
    assert row.dev_in_backfit == pytest.approx(ref.inner_dev_percent, abs=tol_in)
    assert row.dev_out_backfit == pytest.approx(ref.outer_dev_percent, abs=tol_out)


def test_layer_balance(runs):
    # 0.25 P_in + 0.75 P_out = 1: the fines are conserved between the two layers. The model has
    # independent lines for the two layers, so it closes this only approximately; the thesis's
    # own predicted columns close it to e_pred (2.5 %, from the shipped Table 7.2), and the
    # back-fitted model reproduces each P within HALF_UNIT + 0.0005 (above), hence closes it
    # within e_pred + (0.25 + 0.75) (HALF_UNIT + 0.0005). (The data themselves close it within
    # 2.3 %, the thesis's "about 2 %"; the printed coefficients, 3.6 %, have no such bound.)
    bal_pred = 0.25 * runs.p_in_pred + 0.75 * runs.p_out_pred
    e_pred = float(np.max(np.abs(bal_pred - 1)))
    bal = 0.25 * runs.p_in_backfit + 0.75 * runs.p_out_backfit
    assert float(np.max(np.abs(bal - 1))) <= e_pred + HALF_UNIT + 0.0005
