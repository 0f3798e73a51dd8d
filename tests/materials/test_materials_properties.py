"""Gas tables (Cantera fits), solids and lining materials."""

import numpy as np
import pytest
from scipy.integrate import quad

from rotarykiln.errors import InputError
from rotarykiln.materials.gas import air_table, burn_fuel, gas_table, parse_composition
from rotarykiln.materials.lining import Layer, lining_material_names, load_lining_material
from rotarykiln.materials.solids import load_solid, solid_names


def test_gas_table_matches_cantera_between_knots():
    import cantera as ct

    g = ct.Solution("gri30.yaml")
    table = gas_table("CO2:0.1, H2O:0.2, N2:0.7")
    for T in (333.3, 777.7, 1555.5, 2222.2):
        g.TPX = T, 101325.0, "CO2:0.1, H2O:0.2, N2:0.7"
        assert table.cp(T) == pytest.approx(g.cp_mass, rel=1e-3)
        assert table.conductivity(T) == pytest.approx(g.thermal_conductivity, rel=1e-3)
        assert table.viscosity(T) == pytest.approx(g.viscosity, rel=1e-3)
        assert table.density(T) == pytest.approx(g.density, rel=1e-9)


def test_gas_enthalpy_is_integral_of_cp():
    air = air_table()
    integral, _ = quad(lambda t: float(air.cp(t)), 298.15, 1500.0, limit=200)
    assert air.enthalpy(1500.0) == pytest.approx(integral, rel=1e-9)


def test_air_properties_textbook():
    # Incropera table A.4, air at 1000 K: cp 1141-1142 J/(kg K), k 0.0667, mu 42.4e-6
    air = air_table()
    assert air.cp(1000.0) == pytest.approx(1141.0, rel=0.01)
    assert air.conductivity(1000.0) == pytest.approx(0.0667, rel=0.05)
    assert air.viscosity(1000.0) == pytest.approx(42.4e-6, rel=0.03)


def test_methane_lhv():
    # LHV of methane 50.0 MJ/kg (e.g. Turns, An Introduction to Combustion, App. B: 50,016 kJ/kg)
    b = burn_fuel("CH4:1", 1e-3, 20e-3)
    assert b.heat_release / 1e-3 == pytest.approx(50.0e6, rel=0.005)
    # complete combustion by hand: 1 g CH4 + 20 g dry air (O2 0.2095, N2 0.7808, Ar 0.0097)
    n_ch4 = 1 / 16.043
    n_air = 20 / (0.2095 * 31.998 + 0.7808 * 28.014 + 0.0097 * 39.948)
    n_tot = n_ch4 + 2 * n_ch4 + (0.2095 * n_air - 2 * n_ch4) + 0.7905 * n_air
    assert b.table.x_co2 == pytest.approx(n_ch4 / n_tot, rel=1e-3)
    assert b.table.x_h2o == pytest.approx(2 * n_ch4 / n_tot, rel=1e-3)
    assert b.mass_flow * (b.table.enthalpy(b.adiabatic_temperature) - b.table.enthalpy(298.15)) == (
        pytest.approx(b.heat_release, rel=1e-9)
    )


def test_bad_composition():
    for _ in range(2):  # refused every time: a refusal is not kept as a parse
        with pytest.raises(InputError, match="gas.composition"):
            parse_composition("N2 0.79")
        with pytest.raises(InputError, match="gas.composition"):
            parse_composition((("N2", -1.0),))


def test_a_composition_parsed_again_is_the_same():
    text = "N2:79, O2:21"
    assert parse_composition(text) is parse_composition(text)  # kept
    assert parse_composition(dict([("O2", 21), ("N2", 79)])) == parse_composition(text)
    assert parse_composition((("O2", 21.0), ("N2", 79.0))) == parse_composition(text)
    with pytest.raises(InputError, match="gas.composition"):
        gas_table("XYZ:1")
    with pytest.raises(InputError, match="gas.fuel_flow"):
        burn_fuel("CH4:1", 0.0, 1.0)


def test_solids_library():
    assert {"sand", "limestone", "lime", "charcoal", "oil_shale"} <= set(solid_names())
    sand = load_solid("sand")
    # alpha quartz at 298 K: 44.4 J/(mol K) (NIST webbook) = 740 J/(kg K)
    assert sand.cp(298.15) == pytest.approx(740.0, rel=0.01)
    # calcite at 298 K: 83.5 J/(mol K) (NIST) -> 834 J/(kg K); Maier-Kelley gives 818 (2 %)
    assert load_solid("limestone").cp(298.15) == pytest.approx(834.0, rel=0.025)
    h = sand.enthalpy(np.array([298.15, 500.0]))
    assert h[0] == 0.0
    integral, _ = quad(lambda t: float(sand.cp(t)), 298.15, 500.0)
    assert h[1] == pytest.approx(integral, rel=1e-10)
    with pytest.raises(InputError, match="material.solid"):
        load_solid("unobtainium")
    with pytest.raises(InputError, match="emissivity"):
        load_solid("sand", emissivity=1.5)


def test_lining_library_and_layer():
    assert "fireclay_brick" in lining_material_names()
    steel = load_lining_material("carbon_steel")
    k_mean = (steel.conductivity_integral(600.0) - steel.conductivity_integral(400.0)) / 200.0
    assert k_mean == pytest.approx(float(steel.conductivity(500.0)), rel=1e-12)  # linear k
    with pytest.raises(InputError, match="thickness"):
        Layer(steel, 0.0)
    layer = Layer(steel, 0.01, absent=((1.0, 2.0),))
    assert layer.present(np.array([0.5, 1.5, 2.5])).tolist() == [True, False, True]
