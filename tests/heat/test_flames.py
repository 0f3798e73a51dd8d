"""Jet flame length and burn-out profile (heat/flames.py)."""

import numpy as np
import pytest

from rotarykiln.errors import InputError
from rotarykiln.heat.flames import BURNOUT_EXPONENT, burnout_fraction, hawthorne_flame_length

METHANE = dict(
    c_t=0.095, t_flame=2225.0, t_nozzle=298.15, m_surroundings=0.02885, m_nozzle=0.016043
)


def test_burnout_fraction_runs_from_0_to_1_and_ends_flat():
    xi = np.linspace(0.0, 1.0, 201)
    xb = burnout_fraction(xi)
    assert xb[0] == 0.0 and xb[-1] == pytest.approx(1.0, abs=1e-15)
    assert np.all(np.diff(xb) > 0)
    # release rate dX_b/dxi = (1 + m)/m (1 - xi^m): (1 + m)/m at the burner, 0 at the flame tip
    m = BURNOUT_EXPONENT
    h = 1e-6
    assert (burnout_fraction(h) - burnout_fraction(0.0)) / h == pytest.approx((1 + m) / m, rel=1e-4)
    assert (burnout_fraction(1.0) - burnout_fraction(1.0 - h)) / h == pytest.approx(0.0, abs=1e-4)


def test_burnout_fraction_is_clipped_outside_the_flame():
    assert burnout_fraction(-0.5) == 0.0
    assert burnout_fraction(2.0) == burnout_fraction(1.0)
    assert burnout_fraction(0.3, m=2.0) != burnout_fraction(0.3)


def test_hawthorne_length_scales_with_the_nozzle():
    one = hawthorne_flame_length(1.0, **METHANE)
    assert hawthorne_flame_length(0.02, **METHANE) == pytest.approx(0.02 * one, rel=1e-12)
    assert round(one) == 200


def test_hawthorne_length_of_a_lean_nozzle_fluid():
    # C_T = 1: L/d = 5.3 sqrt(T_F / T_N), the molar masses drop out
    got = hawthorne_flame_length(0.1, 1.0, 1200.0, 300.0, 0.029, 0.02)
    assert got == pytest.approx(0.1 * 5.3 * 2.0, rel=1e-12)


@pytest.mark.parametrize("c_t", [0.0, 1.5])
def test_hawthorne_length_refuses_bad_input(c_t):
    with pytest.raises(InputError, match="c_t"):
        hawthorne_flame_length(0.1, c_t, 2225.0, 298.15, 0.029, 0.016)
    with pytest.raises(InputError, match="nozzle_diameter"):
        hawthorne_flame_length(0.0, 0.5, 2225.0, 298.15, 0.029, 0.016)
