"""Unit tests of the heat closures against the check values of closures.md and limits."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.heat.bed_conductivity import (
    maxwell_bed_conductivity,
    zehner_schlunder_bed_conductivity,
)
from rotarykiln.heat.contact import (
    li_covered_wall_h,
    li_film_thickness,
    tscheng_covered_wall_h,
    wachters_kramers_covered_wall_h,
)
from rotarykiln.heat.convection import (
    gorog_gas_bed_h,
    tscheng_watkinson_gas_bed_nusselt,
    tscheng_watkinson_gas_wall_nusselt,
)
from rotarykiln.heat.gas_radiation import (
    gorog_mean_beam_length,
    johansson_wsgg_emissivity,
    smith_wsgg_emissivity,
)
from rotarykiln.heat.radiation import STEFAN_BOLTZMANN, freeboard_radiation
from rotarykiln.heat.wall import (
    churchill_bernstein_nusselt,
    churchill_chu_nusselt,
    cylinder_layer_heat_flow,
)

ATM = 101325.0


# --- convection (closures.md 1a) -------------------------------------------------------------
def test_tscheng_gas_wall_power_law():
    # independent evaluation of 1.54 Re^0.575 Re_w^-0.292 by logarithms
    re, rw = 4000.0, 100.0
    expected = np.exp(np.log(1.54) + 0.575 * np.log(re) - 0.292 * np.log(rw))
    assert tscheng_watkinson_gas_wall_nusselt(re, rw) == pytest.approx(expected, rel=1e-12)


def test_tscheng_rpm_pitfall_factor():
    # closures.md: using rev/s instead of rad/s in Re_w changes h_gw by x0.585 (2 pi ^ -0.292)
    ratio = tscheng_watkinson_gas_wall_nusselt(3000, 200 / (2 * np.pi)) / (
        tscheng_watkinson_gas_wall_nusselt(3000, 200)
    )
    assert 1 / ratio == pytest.approx(0.585, abs=1e-3)


def test_tscheng_gas_bed_fill_dependence():
    a = tscheng_watkinson_gas_bed_nusselt(3000, 200, 0.06)
    b = tscheng_watkinson_gas_bed_nusselt(3000, 200, 0.12)
    assert a / b == pytest.approx(2**0.341, rel=1e-12)


def test_tscheng_out_of_range_warns():
    with pytest.warns(OutOfRangeWarning, match="Re"):
        tscheng_watkinson_gas_wall_nusselt(500.0, 200.0)


def test_gorog_bed_thesis_magnitude():
    # closures.md / notes 004: G = 1100 kg/(m2 h) gives ~31 W/m2K (0.62) and ~110 (0.8)
    g = 1100.0 / 3600.0
    assert gorog_gas_bed_h(g) == pytest.approx(31.0, rel=0.02)
    assert gorog_gas_bed_h(g, exponent=0.8) == pytest.approx(110.0, rel=0.03)


# --- covered wall (closures.md 2a-2c) -------------------------------------------------------
def test_penetration_check_value():
    assert wachters_kramers_covered_wall_h(0.3, 1.6e6, 0.2094, 2.0) == pytest.approx(253, abs=1)


def test_li_check_value():
    h = li_covered_wall_h(0.06, 1e-3, 0.3, 1.6e6, 0.2094, 2.0, chi=0.1)
    assert h == pytest.approx(178, abs=1)


def test_tscheng_covered_check_value():
    assert tscheng_covered_wall_h(0.3, 1.6e6, 0.2094, 0.5, 2.0) == pytest.approx(184, abs=1)


def test_li_chi_fit_ends():
    # closures.md: the fit reproduces 0.196 at the low end and 0.097 at the high end
    assert li_film_thickness(157.5e-6) == pytest.approx(0.196, abs=1e-3)
    assert li_film_thickness(1038e-6) == pytest.approx(0.097, abs=1e-3)


@given(st.floats(0.05, 0.3), st.floats(1e-4, 5e-3))
def test_li_below_pure_penetration(chi, dp):
    h_li = li_covered_wall_h(0.05, dp, 0.3, 1.5e6, 0.3, 2.0, chi=chi)
    h_pen = wachters_kramers_covered_wall_h(0.3, 1.5e6, 0.3, 2.0)
    assert 0 < h_li < h_pen


# --- bed conductivity (closures.md 4a, 4b) ---------------------------------------------------
def test_maxwell_check_value():
    assert maxwell_bed_conductivity(1.0, 50.0, 0.6) == pytest.approx(4.90, abs=0.01)


def test_zehner_schlunder_check_value():
    assert zehner_schlunder_bed_conductivity(1.0, 50.0, 0.4) == pytest.approx(7.10, abs=0.01)


def test_maxwell_limits():
    assert maxwell_bed_conductivity(0.05, 2.0, 0.0) == pytest.approx(0.05)
    with pytest.raises(InputError, match="solid_fraction"):
        maxwell_bed_conductivity(0.05, 2.0, 1.2)


# --- gas radiation (closures.md 3a, 3c, 3d) --------------------------------------------------
def test_smith_check_values():
    assert smith_wsgg_emissivity(1200, 0.2 * ATM, "pw/pc=1") == pytest.approx(0.239, abs=1e-3)
    assert smith_wsgg_emissivity(1200, 0.2 * ATM, "pw/pc=2") == pytest.approx(0.263, abs=1e-3)
    assert smith_wsgg_emissivity(1200, 1.0 * ATM, "pw/pc=1") == pytest.approx(0.387, abs=1e-3)


def test_johansson_consistent_with_smith():
    p = 0.1 * ATM
    assert johansson_wsgg_emissivity(1200, p, p, 1.0) == pytest.approx(0.236, abs=1e-3)


def test_transparent_gas_and_bad_case():
    assert johansson_wsgg_emissivity(1000.0, 0.0, 0.0, 1.0) == 0.0
    with pytest.raises(InputError, match="case"):
        smith_wsgg_emissivity(1000.0, 1000.0, "ch4")


def test_beam_length():
    assert gorog_mean_beam_length(0.4, 0.0) == pytest.approx(0.38)


# --- radiation network (closures.md 3b) ------------------------------------------------------
@settings(max_examples=60)
@given(
    st.floats(300, 2000),
    st.floats(300, 2000),
    st.floats(300, 2000),
    st.floats(0, 0.9),
    st.floats(0.1, 1.0),
    st.floats(0.1, 1.0),
)
def test_network_conserves(tg, tw, tb, eg, ew, eb):
    qw, qb = freeboard_radiation(tg, tw, tb, eg, ew, eb, 1.0, 0.3)
    assert np.isfinite(qw) and np.isfinite(qb)
    # the gas loses what wall and bed gain; nothing flows at a uniform temperature
    q0 = freeboard_radiation(tg, tg, tg, eg, ew, eb, 1.0, 0.3)
    assert abs(q0[0]) + abs(q0[1]) <= 1e-9 * STEFAN_BOLTZMANN * tg**4


def test_network_transparent_limit():
    # two grey surfaces, chord seeing only the arc: q = sigma dT4 / (R_w + 1/A_b + R_b)
    ew, eb, aw, ab = 0.8, 0.9, 1.0, 0.3
    qw, qb = freeboard_radiation(800.0, 1000.0, 600.0, 0.0, ew, eb, aw, ab)
    r = (1 - ew) / (ew * aw) + 1 / ab + (1 - eb) / (eb * ab)
    expected = STEFAN_BOLTZMANN * (1000.0**4 - 600.0**4) / r
    assert qb == pytest.approx(expected, rel=1e-9)
    assert qw == pytest.approx(-expected, rel=1e-9)


def test_network_emissivity_validation():
    with pytest.raises(InputError, match="eps_wall"):
        freeboard_radiation(1000, 900, 800, 0.1, 1.2, 0.9, 1.0, 0.3)
    with pytest.raises(InputError, match="eps_bed"):
        freeboard_radiation(1000, 900, 800, 0.1, 0.9, 0.0, 1.0, 0.3)


# --- wall and shell (closures.md 4c-4e) ------------------------------------------------------
def test_churchill_chu_check_value():
    assert churchill_chu_nusselt(2.63e9 * 0.69, 0.69) == pytest.approx(139.13, abs=0.01)


def test_churchill_bernstein_check_value():
    assert churchill_bernstein_nusselt(6071.0, 0.7) == pytest.approx(40.64, abs=0.01)


def test_layer_constant_k_matches_log_formula():
    k, ri, ro = 1.7, 0.2, 0.3
    q = cylinder_layer_heat_flow(k * 900.0, k * 400.0, ri, ro)
    assert q == pytest.approx(2 * np.pi * k * 500.0 / np.log(ro / ri), rel=1e-12)
