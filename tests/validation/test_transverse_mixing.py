"""Mixing model (eqs 6.8-6.11) against the 27 mixing experiments of Van Puyvelde (1999)."""

import warnings

import numpy as np
import pytest

from rotarykiln.transverse.active_layer import active_layer
from rotarykiln.transverse.data import load_table
from rotarykiln.transverse.mixing import vanpuyvelde_final_contact, vanpuyvelde_mixing_rate

RPM = 2 * np.pi / 60


@pytest.fixture(scope="module")
def predictions():
    d = load_table("mixing_experiments")
    al = active_layer(
        d.drum_diameter_mm.to_numpy() / 2000,
        d.speed_rpm.to_numpy() * RPM,
        d.fill_percent.to_numpy() / 100,
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no clamping for any experiment
        d["alpha"] = 1000 * vanpuyvelde_mixing_rate(
            al.active_velocity, al.active_area, d.dp_mm * 1e-3, d.ratio_used
        )
        d["lf"] = 1000 * vanpuyvelde_final_contact(al.bed_area, d.dp_mm * 1e-3, d.ratio_used)
    d["alpha_dev"] = 100 * np.abs(d.alpha / d.alpha_exp_mm_s - 1)
    d["lf_dev"] = 100 * np.abs(d.lf / d.lf_exp_mm - 1)
    return d


# The resolution to which the library's eqs 6.8-6.11 reproduce the thesis's predicted columns
# (test_reproduces_tabulated_predictions): N, L and the ratio are printed rounded.
REPRODUCTION = 0.03


def test_reproduces_tabulated_predictions(predictions):
    """Provenance of the four limiting constants, not a validation: they are not printed (lost
    figures) and were back-fitted to the predicted columns of Tables 6.2/6.3 (psi to 0.6 % mean,
    1.9 % max; rotarykiln.transverse.mixing). The check: with them every printed prediction is
    reproduced within 3 %, the resolution of the tables (N, L and the ratio printed rounded)."""
    d = predictions
    assert np.all(np.abs(d.alpha / d.alpha_pred_mm_s - 1) < REPRODUCTION)
    assert np.all(np.abs(d.lf / d.lf_pred_mm - 1) < REPRODUCTION)


def _thesis_bound(rows, printed_dev, predicted, measured):
    """Per row: the deviation the thesis prints for its own prediction (whole %, +0.5) plus the
    3 % to which ours reproduces that prediction, as a share of the measurement."""
    return rows[printed_dev] + 0.5 + 100 * REPRODUCTION * rows[predicted] / rows[measured]


def test_average_deviations_of_fitting_set(predictions):
    # Thesis: average deviation 14 % (rate) and 10 % (final contact) over exps 1-24, the
    # accuracy it claims for eqs 6.8-6.11, printed as whole percents; +0.5 % covers that rounding.
    fit = predictions[predictions.role == "fit"]
    assert fit.alpha_dev.mean() <= 14.5
    assert fit.lf_dev.mean() <= 10.5
    # each row no worse than the thesis's own deviation there (max 49 % rate, exp 1, and 33 %
    # final contact), up to the printing and the reproduction (_thesis_bound)
    rate = _thesis_bound(fit, "alpha_dev_percent", "alpha_pred_mm_s", "alpha_exp_mm_s")
    final = _thesis_bound(fit, "lf_dev_percent", "lf_pred_mm", "lf_exp_mm")
    assert np.all(fit.alpha_dev <= rate)
    assert np.all(fit.lf_dev <= final)


@pytest.mark.parametrize(
    ("exp", "rate_dev", "lf_dev"), [("25", 19, 34), ("26", 3, 16), ("27", 3, 19)]
)
def test_independent_experiments(predictions, exp, rate_dev, lf_dev):
    # Table 6.2/6.3 report the thesis's deviations as whole percents (+-0.5); ours differs from
    # the thesis's prediction by up to the 3 % reproduction, as a share of the measurement
    row = predictions.set_index("exp").loc[exp]
    tol_rate = 0.5 + 100 * REPRODUCTION * row.alpha_pred_mm_s / row.alpha_exp_mm_s
    tol_lf = 0.5 + 100 * REPRODUCTION * row.lf_pred_mm / row.lf_exp_mm
    assert row.alpha_dev == pytest.approx(rate_dev, abs=tol_rate)
    assert row.lf_dev == pytest.approx(lf_dev, abs=tol_lf)
    # the rate against the measurement: within the largest experimental error of the measured
    # rates of Table 6.2 (22 %), the thesis's claim for these runs ("less than the maximum
    # experimental error")
    fit = predictions[predictions.role == "fit"]
    assert row.alpha_dev <= fit.alpha_err_percent.max()
    # final contact over-predicted in all three, as the thesis reports
    assert row.lf > row.lf_exp_mm
