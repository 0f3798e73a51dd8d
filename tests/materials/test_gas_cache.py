"""The Cantera-derived numbers (gas tables, burnt gas, dissociation heat, fuel data, species) are
the same to the last bit whether computed, read back from the disk cache, or computed with the
per-thread shared Cantera solution instead of fresh ones; a damaged or unwritable cache falls
back to computing; importing the materials modules imports neither Cantera nor scipy."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

from rotarykiln.materials import dissociation as D
from rotarykiln.materials import gas as G

ct = pytest.importorskip("cantera")

COMPOSITIONS = ["N2:1", "CO2:1", "H2O:1", "O2:0.2095, N2:0.7808, AR:0.0097"]
BURNS = [  # fuel, fuel flow, air flow (kg/s), fuel and air temperatures (K)
    ("CH4:1", 1.0e-3, 1.0e-3 * 17.2 * 1.1, 298.15, 298.15),
    ("CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01", 4.1e-4, 9.3e-3, 310.0, 850.0),
    ("H2:0.5, CO:0.5", 2.0e-4, 1.9e-3, 298.15, 1100.0),
]
T = np.concatenate([G.T_GRID, np.linspace(150.0, 3300.0, 1001), [G.T_MIN, G.T_MAX]])


def _clear_memory():
    for f in (G._cantera_table, G._burn, G._gri30_species, G.fuel_data, D._heat, D._adiabatic):
        f.cache_clear()


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """An empty disk cache in a temporary folder; the in-memory caches cleared around."""
    monkeypatch.setenv("ROTARYKILN_CACHE_DIR", str(tmp_path / "cache"))
    _clear_memory()
    yield tmp_path / "cache"
    _clear_memory()


def _table_values(table):
    out = [np.array([table.molar_mass, table.x_co2, table.x_h2o])]
    out += [getattr(table, n).c for n in ("_cp", "_h", "_k", "_mu")]
    out += [getattr(table, m)(T) for m in ("cp", "enthalpy", "conductivity", "viscosity")]
    return out


def _everything():
    """Every cached result of the materials modules, as arrays."""
    out = []
    for comp in COMPOSITIONS:
        out += _table_values(G.gas_table(comp))
    for args in BURNS:
        b = G.burn_fuel(*args)
        out.append(np.array([b.mass_flow, b.inlet_temperature, b.adiabatic_temperature]))
        out.append(np.array([b.heat_release] + [x for _, x in b.composition]))
        out += _table_values(b.table)
        comp = [(k, x) for k, x in b.composition if k in D.DISSOCIATION_SPECIES]
        heat = D.dissociation_heat(comp)
        out += [heat.spline.c, heat.enthalpy(T), heat.cp(T)]
        out.append(np.array([D.equilibrium_adiabatic_temperature(comp, b.adiabatic_temperature)]))
        out.append(np.array(G.fuel_data(G.parse_composition(args[0]))))
    species = G._gri30_species()
    out.append(np.array([w for _, w in species.values()]))
    return out, [b.composition for b in (G.burn_fuel(*a) for a in BURNS)], list(species)


def test_read_back_from_disk_is_bit_identical_to_computed(cache):
    computed, comps, names = _everything()
    files = sorted(p.name for p in cache.iterdir())
    assert files and all(f.endswith(".npz") for f in files)
    _clear_memory()
    cached, comps_cached, names_cached = _everything()
    assert sorted(p.name for p in cache.iterdir()) == files  # nothing recomputed
    assert comps_cached == comps and names_cached == names
    assert len(cached) == len(computed)
    for a, b in zip(computed, cached, strict=True):
        assert a.dtype == b.dtype and np.array_equal(a, b)


def test_no_disk_cache_gives_the_same_numbers(cache, monkeypatch):
    with_cache, _, _ = _everything()
    monkeypatch.setenv("ROTARYKILN_CACHE_DIR", "off")
    _clear_memory()
    without, _, _ = _everything()
    for a, b in zip(with_cache, without, strict=True):
        assert np.array_equal(a, b)


def test_damaged_or_foreign_cache_files_are_recomputed(cache):
    computed, _, _ = _everything()
    files = sorted(cache.iterdir())
    for i, path in enumerate(files):
        if i % 2:
            path.write_bytes(path.read_bytes()[: len(path.read_bytes()) // 2])  # truncated
        else:  # a valid file stored under another key (a collision, a stale layout)
            np.savez(path, __key__=np.array("another key"), values=np.zeros(3))
    _clear_memory()
    again, _, _ = _everything()
    for a, b in zip(computed, again, strict=True):
        assert np.array_equal(a, b)
    _clear_memory()  # the damaged files were replaced by good ones
    assert sorted(cache.iterdir()) == files
    read, _, _ = _everything()
    for a, b in zip(computed, read, strict=True):
        assert np.array_equal(a, b)


def test_unwritable_cache_folder_falls_back_to_computing(tmp_path, monkeypatch):
    blocker = tmp_path / "a file"
    blocker.write_text("not a folder")
    monkeypatch.setenv("ROTARYKILN_CACHE_DIR", str(blocker / "cache"))
    _clear_memory()
    try:
        table = G.gas_table("N2:1")
        assert float(table.cp(1000.0)) > 1000.0
    finally:
        _clear_memory()
    assert blocker.read_text() == "not a folder"


def test_key_names_the_environment(monkeypatch):
    key = G._cache_key("table", (("N2", 1.0),))
    for part in ("cantera=", "scipy=", "numpy=", "python=", "gri30.yaml:", "gas.py=", "T_GRID="):
        assert part in key
    assert "(('N2', 1.0),)" in key


def test_shared_solution_gives_what_fresh_solutions_give(cache):
    """One GRI-Mech 3.0 solution per thread, its state set in full before use: the same
    numbers as a fresh solution (as computed before), whatever state it was left in."""
    shared = G.gri30()
    for comp in COMPOSITIONS:
        shared.TPX = 1873.0, 2.0e5, "CH4:1, O2:2"
        shared.equilibrate("HP")
        comp = G.parse_composition(comp)
        fresh = G._table_arrays(comp, ct.Solution(G.MECHANISM))
        reused = G._table_arrays(comp)
        assert fresh.keys() == reused.keys()
        for k in fresh:
            assert np.array_equal(fresh[k], reused[k])
    for fuel, *flows in BURNS:
        fuel = G.parse_composition(fuel)
        assert G._burn_state(fuel, *flows) == _burn_as_before(fuel, *flows)
        assert G._fuel_state(fuel) == G._fuel_state(fuel, ct.Solution(G.MECHANISM))
        b = G.burn_fuel(fuel, *flows)
        comp = D._checked([(k, x) for k, x in b.composition if k in D.DISSOCIATION_SPECIES])
        fresh = ct.Solution(thermo="ideal-gas", species=D._species())
        t = b.adiabatic_temperature
        assert D._adiabatic_state(comp, t, 101325.0) == D._adiabatic_state(comp, t, 101325.0, fresh)


def _burn_as_before(fuel, fuel_flow, air_flow, fuel_temperature, air_temperature):
    """The Cantera part of burn_fuel as it was: a fresh solution per stream."""
    from scipy.optimize import brentq

    gas_f = ct.Solution(G.MECHANISM)
    gas_f.TPX = fuel_temperature, 101325.0, dict(fuel)
    gas_a = ct.Solution(G.MECHANISM)
    gas_a.TPX = air_temperature, 101325.0, G.AIR
    mix = ct.Quantity(gas_f, mass=fuel_flow, constant="HP") + ct.Quantity(
        gas_a, mass=air_flow, constant="HP"
    )
    t_in = float(mix.T)
    h_reactants = float(mix.enthalpy_mass)
    mix.TP = 1200.0, 101325.0
    mix.equilibrate("TP")
    x = {s: float(v) for s, v in zip(mix.species_names, mix.X, strict=True) if v > 1e-7}
    mix.TP = t_in, 101325.0
    h_products = float(mix.enthalpy_mass)
    comp = G.parse_composition(x)
    table = G.gas_table(comp)
    m = fuel_flow + air_flow
    q = m * (h_reactants - h_products)
    target = float(table.enthalpy(t_in)) + q / m
    t_ad = float(brentq(lambda t: float(table.enthalpy(t)) - target, G.T_MIN, 2 * G.T_MAX))
    return comp, t_in, t_ad, q


def test_fuel_data_gives_the_tabulated_heating_values():
    """Methane and hydrogen against their standard heats of combustion at 298.15 K (NIST
    Chemistry WebBook: CH4 LHV 802.3 kJ/mol, HHV 890.6 kJ/mol; H2 LHV 241.8 kJ/mol, HHV
    285.8 kJ/mol); the GRI-Mech 3.0 enthalpies agree with them to about 0.1 %."""
    mm, o2, lhv, hhv = G.fuel_data(G.parse_composition("CH4:1"))
    assert mm == pytest.approx(16.043e-3, rel=1e-3) and o2 == pytest.approx(2.0)
    assert lhv * mm == pytest.approx(802.3e3, rel=2e-3)
    assert hhv * mm == pytest.approx(890.6e3, rel=2e-3)
    mm, o2, lhv, hhv = G.fuel_data(G.parse_composition("H2:1"))
    assert o2 == pytest.approx(0.5)
    assert lhv * mm == pytest.approx(241.8e3, rel=2e-3)
    assert hhv * mm == pytest.approx(285.8e3, rel=2e-3)


@pytest.mark.parametrize("nu", [0, 1])
def test_ppoly_values_are_scipys_to_the_last_bit(nu):
    rng = np.random.default_rng(7)
    y = np.cumsum(rng.normal(size=len(G.T_GRID))) * 1e4
    spline = CubicSpline(G.T_GRID, y)
    ours = D.PPolyValues(spline.x, spline.c)
    t = np.concatenate([G.T_GRID, rng.uniform(100.0, 3400.0, 5000), [np.nan, -1.0, 1e5]])
    assert np.array_equal(ours(t, nu), spline(t, nu), equal_nan=True)
    assert np.array_equal(ours(t.reshape(2, -1), nu), spline(t.reshape(2, -1), nu), equal_nan=True)
    assert ours(1234.5, nu).shape == () and ours(1234.5, nu) == spline(1234.5, nu)


def test_importing_the_materials_modules_imports_neither_cantera_nor_scipy(tmp_path):
    code = (
        "import sys\n"
        "import rotarykiln.materials.gas as G, rotarykiln.materials.dissociation as D\n"
        "heavy = [m for m in ('cantera', 'scipy.interpolate', 'scipy.optimize') if m in sys.modules]\n"
        "assert not heavy, heavy\n"
        "G.gas_table('N2:1'); D.dissociation_heat('CO2:1, H2O:2, N2:7.52')\n"
        "G.burn_fuel('CH4:1', 1e-3, 0.02); G.check_composition('CH4:1', 'burner.fuel')\n"
        "print(sorted(m for m in ('cantera', 'scipy.interpolate', 'scipy.optimize') "
        "if m in sys.modules))\n"
    )
    env = {"ROTARYKILN_CACHE_DIR": str(tmp_path / "cache"), "PATH": "/usr/bin:/bin"}
    first = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert first.returncode == 0, first.stderr
    assert "cantera" in first.stdout  # computed
    warm = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert warm.returncode == 0, warm.stderr
    assert warm.stdout.strip() == "[]"  # read back: no Cantera, no scipy
