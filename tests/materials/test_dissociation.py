"""Dissociation of hot products (materials/dissociation.py) and its use in the fired kiln:
the instant burn-out's inlet temperature is the equilibrium adiabatic temperature, checked
against an independent Cantera HP equilibrium of the unburnt fuel and air."""

from __future__ import annotations

import cantera as ct
import numpy as np
import pytest
from hot_limestone_kiln import hot_kiln

from rotarykiln.errors import InputError
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.materials.dissociation import (
    DISSOCIATION_SPECIES,
    dissociation_enthalpy,
    dissociation_heat,
    equilibrium_adiabatic_temperature,
)
from rotarykiln.materials.gas import T_GRID

STOICH = "CO2:1, H2O:2, N2:7.52"


def _restricted():
    species = [s for s in ct.Species.list_from_file("gri30.yaml") if s.name in DISSOCIATION_SPECIES]
    return ct.Solution(thermo="ideal-gas", species=species)


def test_methane_air_equilibrium_flame_temperature():
    # stoichiometric methane-air from 298.15 K: 2225 K with every GRI species (NO included);
    # without nitrogen oxides a few K more. Frozen complete products: about 2326 K.
    gas = ct.Solution("gri30.yaml")
    gas.TPX = 298.15, 101325.0, "CH4:1, O2:2, N2:7.52"
    h = gas.enthalpy_mass
    frozen = _restricted()
    frozen.TPX = 1500.0, 101325.0, STOICH
    frozen.HP = h, 101325.0
    t_eq = equilibrium_adiabatic_temperature(STOICH, frozen.T)
    assert frozen.T == pytest.approx(2326.0, abs=3.0)
    assert t_eq == pytest.approx(2232.0, abs=3.0)
    gas.equilibrate("HP")
    assert 0.0 < t_eq - gas.T < 10.0  # NO formation, left out, takes a few K more


def test_dissociation_heat_vanishes_when_cool_and_grows_with_temperature():
    dh = dissociation_enthalpy(STOICH, np.array([800.0, 1200.0, 1800.0, 2200.0, 2600.0]))
    assert dh[0] < 0.1 and dh[1] < 1e-4 * 1.2e6  # J/kg; sensible heat about 1.2 MJ/kg
    assert np.all(np.diff(dh) > 0)
    # excess oxygen suppresses the dissociation of CO2 and H2O (Le Chatelier)
    lean = "CO2:1, H2O:2, O2:2, N2:15.04"
    assert dissociation_enthalpy(lean, 2200.0) < dissociation_enthalpy(STOICH, 2200.0)


def test_heat_table_matches_equilibrium_and_its_derivative():
    d = dissociation_heat(STOICH)
    T = np.array([1510.0, 1990.0, 2345.0])
    gas = _restricted()
    gas.TPX = 298.15, 101325.0, STOICH
    y = dict(zip(gas.species_names, gas.Y, strict=True))
    exact = dissociation_enthalpy(STOICH, T) / (y["CO2"] + y["H2O"])
    np.testing.assert_allclose(d.enthalpy(T), exact, rtol=2e-3)
    step = 0.5
    fd = (d.enthalpy(T + step) - d.enthalpy(T - step)) / (2 * step)
    np.testing.assert_allclose(d.cp(T), fd, rtol=1e-5)
    assert np.all(d.cp(T_GRID) >= -1e-6)


def test_unknown_product_species_refused():
    with pytest.raises(InputError, match="products.composition"):
        dissociation_enthalpy("CO2:1, NO:0.1, N2:5", 2000.0)


def test_fired_kiln_enters_at_the_equilibrium_adiabatic_temperature():
    data, kiln = hot_kiln("equilibrium")
    _, frozen = hot_kiln("complete")
    flame, flame_fr = kiln.firing.flame, frozen.firing.flame
    # independent: Cantera HP equilibrium (no nitrogen oxides) of the unburnt fuel and air
    gas = _restricted()
    fuel = ct.Solution("gri30.yaml")
    fuel.TPX = 298.15, 101325.0, "CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01"
    b = flame.burner
    streams = [(fuel, b.fuel_flow)]
    for a in (b.primary_air, b.secondary_air):
        s = ct.Solution("gri30.yaml")
        s.TPX = a.temperature, 101325.0, "O2:0.2095, N2:0.7808, AR:0.0097"  # dry air
        streams.append((s, a.flow))
    m = sum(q for _, q in streams)
    h = sum(s.enthalpy_mass * q for s, q in streams) / m
    y = sum(s.Y * q for s, q in streams) / m
    elements = {e: sum(y[k] * fuel.n_atoms(k, e) / fuel.molecular_weights[k] for k in
                       range(fuel.n_species)) for e in ("C", "H", "O", "N", "Ar")}  # fmt: skip
    # products of the same elements: equilibrate from a complete-combustion start
    x = {"CO2": elements["C"], "H2O": elements["H"] / 2.0, "N2": elements["N"] / 2.0}
    x["AR"] = elements["Ar"]
    x["O2"] = (elements["O"] - 2.0 * x["CO2"] - x["H2O"]) / 2.0
    gas.TPX = 2000.0, 101325.0, x
    gas.HP = h, 101325.0
    gas.equilibrate("HP")
    assert flame.adiabatic_temperature == pytest.approx(gas.T, abs=0.5)
    assert flame_fr.adiabatic_temperature - flame.adiabatic_temperature > 50.0
    assert flame.inlet_temperature == flame.adiabatic_temperature


def test_fired_kiln_with_dissociation_closes_its_balances():
    _, kiln = hot_kiln("equilibrium")
    _, frozen = hot_kiln("complete")
    sol, sol_fr = solve_kiln(kiln, 100), solve_kiln(frozen, 100)
    for s in (sol, sol_fr):
        assert abs(s.energy_closure) < 1e-6
        assert abs(s.energy_sheet["closure_relative"]) < 1e-6
        assert max(s.element_closure.values()) < 1e-8
        # the heat of combustion the model releases is the fuel's LHV either way
        assert s.energy_sheet["combustion_heat_W"] == pytest.approx(
            s.energy_sheet["fuel_lhv_input_W"], rel=3e-3
        )
    # the gas enters cooler and gives back the dissociation heat downstream
    assert sol.t_gas_nodes[-1] < sol_fr.t_gas_nodes[-1] - 50.0
    assert sol.gas_outlet_temperature == pytest.approx(sol_fr.gas_outlet_temperature, abs=10.0)
