"""Heating jacket closures (heat/jacket.py): annulus convection and radiation to the drum."""

import numpy as np
import pytest

from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.heat.jacket import (
    annulus_heat_transfer_coefficient,
    gnielinski_annulus_nusselt,
    jacket_radiation_conductance,
    shah_london_annulus_nusselt,
)
from rotarykiln.heat.radiation import STEFAN_BOLTZMANN
from rotarykiln.materials.gas import air_table

A = 0.41 / 0.51  # a 0.41 m drum in a 50 mm gap


def test_annulus_coefficient_laminar_and_turbulent():
    # laminar developed annulus: Nu = 3.66 + 1.2 a^-0.8 (a = 0.41/0.51)
    h = annulus_heat_transfer_coefficient(0.01, 0.41, 0.05, 600.0)
    k = float(air_table().conductivity(600.0))
    assert h == pytest.approx((3.66 + 1.2 * (0.41 / 0.51) ** -0.8) * k / 0.1, rel=1e-9)
    # turbulent: larger, and rising with the flow
    h1 = annulus_heat_transfer_coefficient(1.0, 0.41, 0.05, 600.0)
    h2 = annulus_heat_transfer_coefficient(2.0, 0.41, 0.05, 600.0)
    assert h2 > h1 > 5 * h


def _air(mass_flow, t=600.0, d_i=0.41, gap=0.05):
    """Re, Pr and k of air in the annulus."""
    tab = air_table()
    k, mu, cp = (float(f(t)) for f in (tab.conductivity, tab.viscosity, tab.cp))
    d_o = d_i + 2 * gap
    area = np.pi / 4 * (d_o**2 - d_i**2)
    return mass_flow * 2 * gap / (area * mu), cp * mu / k, k


def test_annulus_coefficient_is_the_two_nusselt_numbers_with_the_transition():
    # turbulent (Re >= 1e4): Gnielinski on d_h = 2 s
    re, pr, k = _air(1.0)
    assert re > 1e4
    nu = gnielinski_annulus_nusselt(re, pr, A)
    h = annulus_heat_transfer_coefficient(1.0, 0.41, 0.05, 600.0)
    assert h == pytest.approx(float(nu) * k / 0.1, rel=1e-12)
    # transition: linear in Re between Nu_l at 2300 and Nu_t(1e4)
    m = 0.15
    re, pr, k = _air(m)
    assert 2300 < re < 1e4
    nu_l = shah_london_annulus_nusselt(A)
    nu_t = gnielinski_annulus_nusselt(1e4, pr, A)
    g = (re - 2300) / (1e4 - 2300)
    h = annulus_heat_transfer_coefficient(m, 0.41, 0.05, 600.0)
    assert h == pytest.approx(max(nu_l + g * (nu_t - nu_l), nu_l) * k / 0.1, rel=1e-9)


def test_annulus_coefficient_of_arrays_and_other_gases():
    t = np.array([500.0, 700.0, 900.0])
    h = annulus_heat_transfer_coefficient(0.05, 0.41, 0.05, t)
    assert h.shape == (3,)
    assert h[1] == annulus_heat_transfer_coefficient(0.05, 0.41, 0.05, 700.0)
    assert annulus_heat_transfer_coefficient(0.05, 0.41, 0.05, 700.0, gas=air_table()) == h[1]


def test_gnielinski_nusselt_rises_with_re_and_pr():
    nu = gnielinski_annulus_nusselt(np.array([1e4, 1e5, 1e6]), 0.7, A)
    assert np.all(np.diff(nu) > 0)
    assert gnielinski_annulus_nusselt(1e5, 5.0, A) > gnielinski_annulus_nusselt(1e5, 0.7, A)


def test_gnielinski_nusselt_warns_outside_its_range_and_refuses_bad_input():
    with pytest.warns(OutOfRangeWarning, match="Gnielinski"):
        gnielinski_annulus_nusselt(5e3, 0.7, A)
    with pytest.raises(InputError, match="diameter_ratio"):
        gnielinski_annulus_nusselt(2e4, 0.7, 1.0)
    with pytest.raises(InputError, match="reynolds"):
        gnielinski_annulus_nusselt(-1.0, 0.7, A)


def test_shah_london_nusselt_of_a_narrow_gap_and_bad_input():
    # a -> 1 (parallel plates, one side heated): 3.66 + 1.2 = 4.86
    assert shah_london_annulus_nusselt(1.0) == pytest.approx(4.86)
    assert shah_london_annulus_nusselt(0.5) > shah_london_annulus_nusselt(0.9)
    with pytest.raises(InputError, match="diameter_ratio"):
        shah_london_annulus_nusselt(0.0)


def test_annulus_coefficient_refuses_bad_input():
    with pytest.raises(InputError, match="jacket.gap"):
        annulus_heat_transfer_coefficient(0.05, 0.41, 0.0, 700.0)
    with pytest.raises(InputError, match="jacket.mass_flow"):
        annulus_heat_transfer_coefficient(-0.05, 0.41, 0.05, 700.0)


def test_radiation_conductance_of_black_surfaces_and_a_transparent_gas():
    g_gas, g_cas = jacket_radiation_conductance(
        900.0, 700.0, 0.41, 0.05, eps_drum=1.0, eps_casing=1.0
    )
    hr = 4 * STEFAN_BOLTZMANN * 800.0**3
    assert g_gas == 0.0
    assert g_cas == pytest.approx(hr * np.pi * 0.41, rel=1e-12)  # the drum's perimeter limits
    # grey surfaces conduct less; a radiating gas adds its direct path
    _, grey = jacket_radiation_conductance(900.0, 700.0, 0.41, 0.05)
    assert grey < g_cas
    g_gas, _ = jacket_radiation_conductance(900.0, 700.0, 0.41, 0.05, eps_gas=0.1)
    assert g_gas == pytest.approx(0.1 * hr * np.pi * 0.41, rel=1e-12)
