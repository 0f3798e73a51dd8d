"""Lime and dolomite: thermodynamic CO2 equilibria, product mass balance, heats; bad input."""

import math

import numpy as np
import pytest

from rotarykiln.chemistry import clinker as ck
from rotarykiln.chemistry import lime
from rotarykiln.chemistry.calcination import baker_co2_equilibrium_pressure
from rotarykiln.errors import InputError


def one_line(exc):
    msg = str(exc.value)
    assert "\n" not in msg
    return msg


@pytest.mark.parametrize("carbonate", list(lime.CARBONATES))
def test_pressure_and_temperature_are_inverse(carbonate):
    for p in (1e3, 3e4, 101325.0, 5e5):
        T = lime.holland_powell_equilibrium_temperature(p, carbonate)
        assert lime.holland_powell_co2_equilibrium_pressure(T, carbonate) == pytest.approx(
            p, rel=1e-9
        )


def test_pressure_rises_with_temperature_and_follows_van_t_hoff():
    T = np.linspace(900.0, 1300.0, 41)
    p = lime.holland_powell_co2_equilibrium_pressure(T)
    assert np.all(np.diff(p) > 0)
    # d ln p / d(1/T) = -Delta H / R
    T0, h = 1100.0, 1e-2
    slope = (
        math.log(lime.holland_powell_co2_equilibrium_pressure(T0 + h))
        - math.log(lime.holland_powell_co2_equilibrium_pressure(T0 - h))
    ) / (1 / (T0 + h) - 1 / (T0 - h))
    dH = ck.simcem_reaction_enthalpy("calcination_HP2011", T0)
    assert -slope * lime.R_GAS == pytest.approx(dH, rel=1e-5)


def test_dolomite_full_pressure_is_the_square_root_of_its_constant():
    # CaMg(CO3)2 -> CaO + MgO + 2 CO2: K = (p/p0)^2
    T = 950.0
    K = math.exp(-ck.simcem_reaction_gibbs("dolomite_full_HP2011", T) / (lime.R_GAS * T))
    assert lime.holland_powell_co2_equilibrium_pressure(T, "dolomite_full") == pytest.approx(
        1e5 * math.sqrt(K), rel=1e-12
    )


def test_order_of_the_decompositions():
    # at 1 atm: magnesite < dolomite half-calcination < dolomite full < calcite; Baker above HP
    Ts = {c: lime.holland_powell_equilibrium_temperature(101325.0, c) for c in lime.CARBONATES}
    assert Ts["magnesite"] < Ts["dolomite_half"] < Ts["dolomite_full"] < Ts["calcite"]
    assert baker_co2_equilibrium_pressure(Ts["calcite"]) < 101325.0


def test_equilibrium_bad_input():
    with pytest.raises(InputError) as e:
        lime.holland_powell_co2_equilibrium_pressure(1000.0, "aragonite")
    assert one_line(e).startswith("carbonate: aragonite is not one of calcite, magnesite")
    with pytest.raises(InputError) as e:
        lime.holland_powell_equilibrium_temperature(0.0)
    assert one_line(e) == "p_co2: 0 Pa is not in [0.001, 1e+07]"
    with pytest.raises(InputError, match="T: 0 K is not > 0"):
        lime.holland_powell_co2_equilibrium_pressure(0.0)


def test_mass_balance_conserves_mass():
    for xc, xm in ((1.0, 1.0), (0.9, 0.5), (0.0, 0.0)):
        b = lime.lime_calcination_mass_balance(0.55, 0.40, 0.05, xc, xm)
        assert b["yield"] + b["CO2_released"] == pytest.approx(1.0, rel=1e-12)
        assert sum(b[k] for k in ("CaO", "MgO", "CaCO3", "MgCO3", "inert")) == pytest.approx(1.0)
    full = lime.lime_calcination_mass_balance(0.97, 0.01, 0.02)
    assert full["residual_CO2"] == 0.0
    none = lime.lime_calcination_mass_balance(1.0, 0.0, 0.0, 0.0)
    assert none["residual_CO2"] == pytest.approx(lime.carbonate_co2_mass_fraction("calcite"))


def test_mass_balance_bad_input():
    with pytest.raises(InputError) as e:
        lime.lime_calcination_mass_balance(0.9, 0.05, 0.0)
    assert one_line(e) == "stone (dry basis: CaCO3 + MgCO3 + inert): sum 0.95 is not 1 +- 0.005"
    with pytest.raises(InputError, match="conversion_ca: 1.2 is not in"):
        lime.lime_calcination_mass_balance(1.0, 0.0, 0.0, 1.2)
    with pytest.raises(InputError, match="carbonate: siderite"):
        lime.carbonate_co2_mass_fraction("siderite")


def test_theoretical_heat_of_burning():
    # dolime: a mass-weighted mean of the two reactions per kg of oxide
    q_ca = lime.theoretical_heat_of_lime_burning(1.0, 0.0)
    q_mg = lime.theoretical_heat_of_lime_burning(0.0, 1.0)
    q = lime.theoretical_heat_of_lime_burning(0.5, 0.5)
    assert min(q_ca, q_mg) < q < max(q_ca, q_mg)
    # at kiln temperature the heat is lower (Delta c_p < 0)
    assert lime.theoretical_heat_of_lime_burning(1.0, 0.0, 1173.0) < q_ca
    with pytest.raises(InputError, match="CaCO3 \\+ MgCO3: 0 is not > 0"):
        lime.theoretical_heat_of_lime_burning(0.0, 0.0)
