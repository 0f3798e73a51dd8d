"""Coating thickness along the kiln estimated from a shell scan (issue 26, "Coating and rings"):
:func:`rotarykiln.studies.coating.estimate_coating` fits the coating's ``thickness_profile`` knots
of a case to shell temperatures (z, T) by the calibration machinery, with an interval per zone.

Synthetic scans: Barr's T4 kiln with a known coating (40 / 80 / 30 mm at 3.0 / 3.6 / 4.2 m, none
before 2.4 m and after 4.8 m), its computed shell temperatures at 60 stations plus Gaussian
noise of 5 K (a scanner's order of accuracy: the issue's), 20 seeds. The intervals are joint
(Sidak: each zone at 1 - 0.05^(1/3) two-sided, from the covariance of the weighted least squares
with the stated 5 K), so the true profile should lie inside all three in 95 % of the repeats:
the must-show asks for at least 18 of 20. Nothing is fitted to the checked quantity: the truth
is the input of the synthetic scan.
"""

from __future__ import annotations

import warnings

import numpy as np
import pandas as pd
import pytest
import yaml

from rotarykiln.cases import builtin_case_path
from rotarykiln.studies.coating import estimate_coating
from rotarykiln.studies.models import kiln_profile_model

KNOTS = (3.0, 3.6, 4.2)  # m, the zones estimated
TRUE = (40.0, 80.0, 30.0)  # mm
STATIONS = np.linspace(0.05, 5.45, 60)  # m, the scanner's stations
NOISE = 5.0  # K
# k = 1 W/(m K): the middle of the 0.5-1.5 quoted for cement-kiln coating (reference note,
# [MEMORY, low]); the estimate assumes the same k as the truth, as a scanner's method does
COATING = {"name": "coating", "k": [1.0], "emissivity": 0.9, "t_max": "1800 K"}


def _case(thickness_mm) -> dict:
    case = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    case.pop("measurements", None)
    case["solver"] = {"cells": 40}
    profile = [["0 m", "0 mm"], ["2.4 m", "0 mm"]]
    profile += [[f"{z} m", f"{t} mm"] for z, t in zip(KNOTS, thickness_mm, strict=True)]
    profile += [["4.8 m", "0 mm"]]
    case["wall"]["lining"] = [
        {"material": COATING, "thickness_profile": profile},
        *case["wall"]["lining"],
    ]
    return case


def _shell(case) -> np.ndarray:
    out = kiln_profile_model(case)
    cols = sorted((float(k.split("@")[1]), v) for k, v in out.items() if "shell_temperature@" in k)
    return np.interp(STATIONS, [z for z, _ in cols], [v for _, v in cols])


def _estimate(scan: np.ndarray):
    data = pd.DataFrame(
        {"quantity": "shell_temperature", "z": STATIONS, "value": scan, "uncertainty": NOISE}
    )
    return estimate_coating(_case((50.0,) * len(KNOTS)), data, bounds=("0 mm", "300 mm"))


@pytest.fixture(scope="module")
def clean_scan():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return _shell(_case(TRUE))


def test_the_scan_sees_the_coating(clean_scan):
    """The coated zone's shell is colder than without coating: the scan holds information."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = _case(TRUE)
        case["wall"]["lining"].pop(0)  # no coating
        bare = _shell(case)
    zone = (STATIONS > 3.3) & (STATIONS < 3.9)
    assert np.all(clean_scan[zone] < bare[zone] - NOISE)


def test_the_estimate_holds_the_true_profile_in_its_intervals(clean_scan):
    truth = np.array(TRUE) * 1e-3  # m
    inside = 0
    for seed in range(20):
        rng = np.random.default_rng(seed)
        scan = clean_scan + rng.normal(0.0, NOISE, STATIONS.size)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            est = _estimate(scan)
        assert est.result.success and est.level == 0.95
        np.testing.assert_allclose(est.z, KNOTS)
        inside += bool(np.all((est.low <= truth) & (truth <= est.high)))
    assert inside >= 18


def test_the_estimate_is_plotted_over_the_scan(clean_scan):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fig = _estimate(clean_scan).plot()
    top, bottom = fig.axes
    assert len(top.lines) >= 1 and bottom.get_xlabel() == "z (m)"
