"""Complete combustion by elements and the dissociation table (materials/combustion.py), against
Cantera: the products, heat of combustion and temperatures of a lean burner; the dissociation
heat interpolated over the equivalence ratio at points off the table's nodes (the error bound
of the module's docstring), in the heat itself and in a hot kiln's temperatures; the
equilibrium adiabatic temperature; a rich mixture or an equivalence ratio outside the table
refused or computed exactly; the table read back from the disk cache to the last bit."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from hot_limestone_kiln import hot_kiln
from scipy.interpolate import CubicSpline

from rotarykiln.kiln.combustion import flame as F
from rotarykiln.materials import combustion as C
from rotarykiln.materials import dissociation as D
from rotarykiln.materials.gas import AIR, T_GRID, burn_fuel, gas_table, parse_composition

ct = pytest.importorskip("cantera")

CH4 = parse_composition("CH4:1")
#: The table's error bound, J/kg of products, and the temperature it makes (K, c_p ~ 1300).
TABLE_ERROR = 1.5


def _exact_values(fuel, oxidiser, phi) -> np.ndarray:
    """Cantera's dissociation heat (J/kg of products) on T_GRID of the complete products."""
    return D.dissociation_enthalpy(C._products_at(fuel, oxidiser, phi), T_GRID)


def test_spline_maps_are_scipys_cubic_splines():
    rng = np.random.default_rng(3)
    for x in (T_GRID, C._table_variable(C._table_nodes())):
        y = rng.normal(size=(len(x), 3))
        want = CubicSpline(x, y).c
        got = np.tensordot(C._spline_map(x), y, 1)
        assert np.abs(got - want).max() <= 1e-13 * np.abs(want).max()


@pytest.mark.parametrize(
    "fuel, oxidiser, fuel_flow, air_flow, t_fuel, t_air",
    [
        ("CH4:1", AIR, 1.0e-3, 1.0e-3 * 17.2 * 1.1, 298.15, 298.15),
        ("CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01", AIR, 4.1e-4, 9.3e-3, 310.0, 850.0),
        ("H2:0.5, CO:0.5", AIR, 2.0e-4, 1.9e-3, 298.15, 1100.0),
        ("CH4:1", "O2:0.3, N2:0.7", 1.0e-3, 0.03, 298.15, 700.0),
    ],
)
def test_complete_combustion_is_cantera_by_elements(
    fuel, oxidiser, fuel_flow, air_flow, t_fuel, t_air
):
    b = C.complete_combustion(fuel, fuel_flow, t_fuel, ((air_flow, t_air, oxidiser),))
    gas = ct.Solution("gri30.yaml")
    gas.TPX = t_fuel, 101325.0, fuel
    mix = ct.Quantity(gas, mass=fuel_flow, constant="HP")
    gas.TPX = t_air, 101325.0, oxidiser
    mix += ct.Quantity(gas, mass=air_flow, constant="HP")
    elements = {e: mix.elemental_mole_fraction(e) for e in ("C", "H", "O", "N")}
    assert b.inlet_temperature == pytest.approx(mix.T, abs=1e-6)  # Cantera stops within 1e-6 K
    mix.TP = b.inlet_temperature, 101325.0
    h_in = mix.enthalpy_mass * mix.mass
    mix.TPX = b.inlet_temperature, 101325.0, dict(b.composition)
    assert set(dict(b.composition)) <= {"CO2", "H2O", "O2", "N2", "AR"}
    for e, x in elements.items():  # the same elements
        assert mix.elemental_mole_fraction(e) == pytest.approx(x, rel=1e-10, abs=1e-13)
    assert b.mass_flow == fuel_flow + air_flow
    assert b.heat_release == pytest.approx(h_in - mix.enthalpy_mass * mix.mass, rel=1e-9)
    # the products' table mixed from the species' tables is their own Cantera table
    own = gas_table(b.composition)
    T = np.linspace(150.0, 3300.0, 501)
    np.testing.assert_allclose(b.table.enthalpy(T), own.enthalpy(T), rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(b.table.cp(T), own.cp(T), rtol=1e-12)
    assert b.table.molar_mass == pytest.approx(own.molar_mass, rel=1e-14)
    assert (b.table.x_co2, b.table.x_h2o) == pytest.approx((own.x_co2, own.x_h2o), rel=1e-12)
    # the frozen adiabatic temperature holds the heat of combustion in the products' table
    gained = own.enthalpy(b.adiabatic_temperature) - own.enthalpy(b.inlet_temperature)
    assert gained * b.mass_flow == pytest.approx(b.heat_release, rel=1e-12)
    # within Cantera's products at 1200 K by their traces of NO (its heat of formation)
    ref = burn_fuel(fuel, fuel_flow, air_flow, t_fuel, t_air, oxidiser)
    assert b.adiabatic_temperature == pytest.approx(ref.adiabatic_temperature, abs=0.5)


def test_a_rich_mixture_is_left_to_cantera():
    rich = ((1.0e-3 * 17.2 * 0.9, 298.15, AIR),)
    assert C.complete_combustion("CH4:1", 1.0e-3, 298.15, rich) is None
    assert C.equivalence_ratio("CH4:1", 1.0e-3, rich) == pytest.approx(
        17.235 / 17.2 / 0.9, rel=1e-4
    )
    burner = F.Burner("CH4:1", 1.0e-3, F.AirStream(1.0e-3 * 17.2 * 0.95))
    flame = F.fire(burner, 0.5)
    comp = dict(flame.products.composition)
    assert comp["CO"] > 1e-3 and comp["H2"] > 1e-3  # Cantera's equilibrium at 1200 K
    heat = D.dissociation_heat(
        [(k, x) for k, x in flame.products.composition if k in D.DISSOCIATION_SPECIES]
    )
    assert flame.dissociation is not None and np.array_equal(
        flame.dissociation.spline.c, heat.spline.c
    )


def test_an_equivalence_ratio_outside_the_table_is_refused():
    table = C.dissociation_table(CH4, AIR)
    for phi in (-1e-9, 1.0 + 1e-9, float("nan"), 3.0):
        with pytest.raises(ValueError, match="outside the dissociation table"):
            table.enthalpy(phi)
    with pytest.raises(Exception, match="burner.fuel"):
        C.dissociation_table("N2:1", AIR)  # no O2 demand: no table


@pytest.mark.parametrize(
    "fuel, oxidiser",
    [("CH4:1", AIR), ("CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01", AIR), ("CH4:1", "O2:0.3, N2:0.7")],
)
def test_table_matches_cantera_off_its_nodes(fuel, oxidiser):
    """At random equivalence ratios (uniform, and clustered towards 0 and 1 where the table's
    nodes cluster), every temperature of the grid: within :data:`TABLE_ERROR` J/kg of
    products, about 1e-3 K of gas temperature."""
    fuel, oxidiser = parse_composition(fuel), parse_composition(oxidiser)
    table = C.dissociation_table(fuel, oxidiser)
    rng = np.random.default_rng(5)
    phis = np.concatenate([rng.uniform(0, 1, 6), 1 - 10 ** rng.uniform(-7, -1, 4), [1e-4, 0.99]])
    nodes = set(table.phi.tolist())
    for phi in phis:
        assert phi not in nodes
        err = np.abs(table.enthalpy(phi) - _exact_values(fuel, oxidiser, phi))
        assert err.max() < TABLE_ERROR, (phi, T_GRID[err.argmax()], err.max())


def test_table_heat_is_the_exact_heat_to_its_error():
    """The :class:`DissociationHeat` of a flame from the table and from Cantera (its own
    composition): the same spline to the table's error, per kg of CO2 + H2O."""
    b = C.complete_combustion("CH4:1", 1.0e-3, 298.15, ((1.0e-3 * 17.2 * 1.07, 700.0, AIR),))
    phi = C.equivalence_ratio("CH4:1", 1.0e-3, ((1.0e-3 * 17.2 * 1.07, 700.0, AIR),))
    table = C.dissociation_table(CH4, AIR)
    got = table.heat(phi, b.composition)
    want = D.dissociation_heat(b.composition)
    y = dict(zip(*_mass_fractions(b.composition), strict=True))
    carriers = y["CO2"] + y["H2O"]
    T = np.linspace(200.0, 3200.0, 1201)
    assert np.abs(got.enthalpy(T) - want.enthalpy(T)).max() * carriers < TABLE_ERROR
    assert got.composition == want.composition
    assert np.all(got.enthalpy(T_GRID) >= 0.0)


def _mass_fractions(composition):
    gas = ct.Solution("gri30.yaml")
    gas.TPX = 300.0, 101325.0, dict(composition)
    return gas.species_names, gas.Y


def test_dissociated_adiabatic_temperature_is_cantera_equilibrium():
    for lam, t_air in ((1.0001, 298.15), (1.05, 900.0), (1.3, 1100.0), (3.0, 298.15)):
        air = ((1.0e-3 * 17.235 * lam, t_air, AIR),)
        b = C.complete_combustion("CH4:1", 1.0e-3, 298.15, air)
        heat = D.dissociation_heat(b.composition)
        t_eq = C.dissociated_adiabatic_temperature(b, heat)
        want = D.equilibrium_adiabatic_temperature(b.composition, b.adiabatic_temperature)
        assert t_eq == pytest.approx(want, abs=1e-5)
        assert t_eq <= b.adiabatic_temperature


def test_fire_takes_the_table_and_refires_to_the_last_bit():
    """A burner of one fuel and one oxidiser composition: its dissociation heat from the
    table; the same burner again gives the same objects; an O2-enriched stream beside air (two
    compositions) takes Cantera's dissociation heat of its products."""
    air = 1.0e-3 * 17.12 * 1.2
    b = F.Burner("CH4:1", 1.0e-3, F.AirStream(0.2 * air), F.AirStream(0.8 * air, 1000.0))
    f = F.fire(b, 0.5)
    phi = C.equivalence_ratio(CH4, b.fuel_flow, F._streams(b.flame_air))
    want = C.dissociation_table(CH4, parse_composition(AIR)).heat(phi, f.products.composition)
    assert np.array_equal(f.dissociation.spline.c, want.spline.c)
    assert F.fire(b, 0.5).dissociation is f.dissociation
    t_eq = C.dissociated_adiabatic_temperature(f.products, f.dissociation)
    assert f.adiabatic_temperature == t_eq == f.inlet_temperature
    enriched = dataclasses.replace(
        b, secondary_air=F.AirStream(0.8 * air, 1000.0, "O2:0.3, N2:0.7")
    )
    g = F.fire(enriched, 0.5)
    assert g.dissociation is D.dissociation_heat(
        [(k, x) for k, x in g.products.composition if k in D.DISSOCIATION_SPECIES]
    )


def test_kiln_temperatures_from_the_table_are_cantera_s(monkeypatch):
    """A hot, nearly stoichiometric kiln (test_dissociation's: 10 % excess air, secondary air
    at 1000 K, an equilibrium adiabatic temperature of 2403 K) solved with the table's
    dissociation heat and with Cantera's: the same inlet temperature within 1e-3 K (3.8e-4 K
    when written), outlet temperatures within 1e-4 K (3e-6 K gas, 4e-5 K bed)."""
    from rotarykiln.kiln.steady.solve import solve_kiln

    _, kiln = hot_kiln("equilibrium")
    flame = kiln.firing.flame
    assert flame.adiabatic_temperature > 2000.0
    F._table_heat.cache_clear()
    monkeypatch.setattr(
        F, "_table_heat", lambda fuel, oxidiser, phi, comp: D.dissociation_heat(comp)
    )
    _, exact = hot_kiln("equilibrium")
    assert not np.array_equal(exact.firing.flame.dissociation.spline.c, flame.dissociation.spline.c)
    d_in = abs(exact.firing.flame.adiabatic_temperature - flame.adiabatic_temperature)
    a, b = solve_kiln(kiln, 100), solve_kiln(exact, 100)
    assert d_in < 1e-3
    for name in ("gas_outlet_temperature", "bed_outlet_temperature"):
        assert getattr(a, name) == pytest.approx(getattr(b, name), abs=1e-4)
    assert np.abs(a.t_gas_nodes - b.t_gas_nodes).max() < 1e-3
    assert np.abs(a.t_bed_nodes - b.t_bed_nodes).max() < 1e-4


def test_table_read_back_from_disk_is_bit_identical(tmp_path, monkeypatch):
    monkeypatch.setenv("ROTARYKILN_CACHE_DIR", str(tmp_path / "cache"))
    oxidiser = parse_composition("O2:0.25, N2:0.75")
    C._table.cache_clear()
    computed = C.dissociation_table(CH4, oxidiser)
    files = sorted(p.name for p in (tmp_path / "cache").iterdir())
    assert any(f.startswith("dissociation-") for f in files)
    C._table.cache_clear()
    again = C.dissociation_table(CH4, oxidiser)
    assert again is not computed
    assert sorted(p.name for p in (tmp_path / "cache").iterdir()) == files
    for a, b in ((computed.phi, again.phi), (computed.values, again.values)):
        assert a.dtype == b.dtype and np.array_equal(a, b)
    C._table.cache_clear()
