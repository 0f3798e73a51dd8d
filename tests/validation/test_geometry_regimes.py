"""Numbers printed in the sources for the cross-section and the regimes.

- Critical speeds 94.6, 66.9, 56.0 and 17.3 rpm for D = 0.2, 0.4, 0.57, 6 m: seed 000 (the
  oil-shale thesis) section 3.2 drums, given to 0.1 rpm, so the tolerance is 0.05 rpm.
- Fill at H = R is exactly one half; at H/R = 0.2 seed 002 notes give 5.20 % (to 0.01 %).
- Seed 003 (Bongo Njeng) Eq. 17: N_c = 132.9 rpm for iD = 0.1013 m (to 0.1 rpm), and its Froude
  numbers 2.26e-4 at 2 rpm and 8.15e-3 at 12 rpm (3 significant digits) are in Mellmann's rolling band.
- The issue's check point: D = 6 m, 5 rpm, fill 0.3 gives Fr = 0.084, 0.29 of critical speed.
"""

import numpy as np
import pytest

from rotarykiln.geometry import fill_from_depth
from rotarykiln.regimes import (
    classify_regime,
    critical_speed_rpm,
    fraction_of_critical,
    froude_number,
)

RPM = 2 * np.pi / 60


@pytest.mark.parametrize(
    ("diameter", "n_crit"), [(0.2, 94.6), (0.4, 66.9), (0.57, 56.0), (6.0, 17.3)]
)
def test_critical_speeds_seed000(diameter, n_crit):
    assert critical_speed_rpm(diameter / 2) == pytest.approx(n_crit, abs=0.05)


def test_critical_speed_seed003():
    assert critical_speed_rpm(0.1013 / 2) == pytest.approx(132.9, abs=0.05)


@pytest.mark.parametrize(("rpm", "fr"), [(2, 2.26e-4), (3, 5.10e-4), (10, 5.66e-3), (12, 8.15e-3)])
def test_froude_numbers_seed003(rpm, fr):
    value = froude_number(rpm * RPM, 0.05065)
    assert value == pytest.approx(fr, rel=5e-3)
    assert classify_regime(value, 0.15).name == "rolling"


def test_fill_check_values_seed002():
    assert fill_from_depth(1.0, 1.0) == pytest.approx(0.5, abs=1e-14)
    assert 100 * fill_from_depth(0.2, 1.0) == pytest.approx(5.20, abs=0.005)


def test_issue_check_point_6m_5rpm():
    fr = froude_number(5 * RPM, 3.0)
    assert fr == pytest.approx(0.084, abs=5e-4)
    assert fraction_of_critical(5 * RPM, 3.0) == pytest.approx(0.29, abs=5e-3)
    assert classify_regime(fr, 0.3, criterion="henein").name == "rolling"
    assert classify_regime(fr, 0.3, criterion="mellmann").name == "cascading"
