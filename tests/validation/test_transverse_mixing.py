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


def test_reproduces_tabulated_predictions(predictions):
    # Back-fitted limiting constants reproduce psi to 0.6 % mean / 1.9 % max; N, L and the ratio
    # are printed rounded, so 3 % per row is the resolution of the tables.
    d = predictions
    assert np.all(np.abs(d.alpha / d.alpha_pred_mm_s - 1) < 0.03)
    assert np.all(np.abs(d.lf / d.lf_pred_mm - 1) < 0.03)


def test_average_deviations_of_fitting_set(predictions):
    # Thesis: average deviation 14 % (rate) and 10 % (final contact) over exps 1-24, printed as
    # whole percents; +0.5 % covers that rounding.
    fit = predictions[predictions.role == "fit"]
    assert fit.alpha_dev.mean() <= 14.5
    assert fit.lf_dev.mean() <= 10.5
    assert fit.alpha_dev.max() <= 51  # thesis max 49 % (exp 1, lowest psi)
    assert fit.lf_dev.max() <= 36  # thesis max 33 %


@pytest.mark.parametrize(
    ("exp", "rate_dev", "lf_dev"), [("25", 19, 34), ("26", 3, 16), ("27", 3, 19)]
)
def test_independent_experiments(predictions, exp, rate_dev, lf_dev):
    # Table 6.2/6.3 report these deviations as whole percents; within 1.5 points.
    row = predictions.set_index("exp").loc[exp]
    assert row.alpha_dev == pytest.approx(rate_dev, abs=1.5)
    assert row.lf_dev == pytest.approx(lf_dev, abs=1.5)
    # final contact over-predicted in all three, as the thesis reports
    assert row.lf > row.lf_exp_mm
