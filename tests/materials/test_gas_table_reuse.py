"""A new composition's gas table and burnt gas, from what is kept between cases (issue 25 item
2): the thermo-only phases of a species set, the transport fits computed on first use, the
scalar enthalpy of the root finding. Every number is the one computed as before (the full
GRI-Mech 3.0 solution sampled at every temperature, scipy's splines, numpy's evaluation), to
the last bit; two compositions never share an entry; tables and burnt gases pickle and work
in threads and worker processes."""

from __future__ import annotations

import pickle
import threading
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

from rotarykiln.materials import gas as G

ct = pytest.importorskip("cantera")

T = np.concatenate([G.T_GRID, np.linspace(150.0, 3400.0, 1301), [G.T_MIN, G.T_MAX, G.T_REF]])
PRODUCTS = ["AR", "CO2", "H2O", "N2", "NO", "NO2", "O2", "OH", "CO", "H2", "H", "O", "CH4"]
FLOWS = [(2.0e-4 * (1.0 + 0.013 * i), 4.3e-3) for i in range(8)]  # fuel, air (kg/s)


def _table_arrays_as_before(composition, gas) -> dict:
    """The gas table as computed before the split: the full GRI-Mech 3.0 solution set in full
    at every temperature, one scipy spline per property."""
    X = dict(composition)
    cp, k, mu = (np.empty_like(G.T_GRID) for _ in range(3))
    for i, t in enumerate(G.T_GRID):
        gas.TPX = t, 101325.0, X
        cp[i], k[i], mu[i] = gas.cp_mass, gas.thermal_conductivity, gas.viscosity
    cp_fit = CubicSpline(G.T_GRID, cp)
    h_fit = cp_fit.antiderivative()
    h_fit.c[-1, :] -= float(h_fit(G.T_REF))
    names = gas.species_names
    gas.TPX = 300.0, 101325.0, X
    xs = gas.X
    fits = {
        "cp": cp_fit,
        "h": h_fit,
        "k": CubicSpline(G.T_GRID, k),
        "mu": CubicSpline(G.T_GRID, mu),
    }
    return {
        "molar_mass": np.float64(gas.mean_molecular_weight / 1000.0),
        "x_co2": np.float64(xs[names.index("CO2")]),
        "x_h2o": np.float64(xs[names.index("H2O")]),
        **{f"{n}_x": f.x for n, f in fits.items()},
        **{f"{n}_c": f.c for n, f in fits.items()},
    }


def _compositions(n: int, seed: int) -> list:
    """Product-like compositions: 1 to 9 species, fractions over many decades (traces 1e-7)."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        species = rng.choice(PRODUCTS, size=int(rng.integers(1, 10)), replace=False)
        x = np.maximum(rng.random(len(species)) ** rng.uniform(1.0, 12.0, len(species)), 1e-7)
        out.append(G.parse_composition(dict(zip(species.tolist(), x.tolist(), strict=True))))
    return out


def _clear():
    for f in (G._cantera_table, G._burn, G._grid_digest):
        f.cache_clear()
    G._thread.__dict__.pop("thermo_phases", None)


@pytest.fixture
def cold(monkeypatch):
    """No disk cache; the in-memory caches and this thread's phases emptied around."""
    monkeypatch.setenv("ROTARYKILN_CACHE_DIR", "off")
    _clear()
    yield
    _clear()


def _assert_same_arrays(a: dict, b: dict):
    assert a.keys() == b.keys()
    for key in a:
        assert np.asarray(a[key]).dtype == np.asarray(b[key]).dtype, key
        assert np.array_equal(a[key], b[key]), key


def _table_numbers(table) -> list:
    out = [np.array([table.molar_mass, table.x_co2, table.x_h2o])]
    out += [getattr(table, n).c for n in ("_cp", "_h", "_k", "_mu")]
    out += [getattr(table, m)(T) for m in ("cp", "enthalpy", "conductivity", "viscosity")]
    return out


def _burnt_numbers(b) -> list:
    head = [b.mass_flow, b.inlet_temperature, b.adiabatic_temperature, b.heat_release]
    return [b.composition, np.array(head), *_table_numbers(b.table)]


def _assert_same(a: list, b: list):
    assert len(a) == len(b)
    for x, y in zip(a, b, strict=True):
        if isinstance(x, np.ndarray):
            assert x.dtype == y.dtype and np.array_equal(x, y)
        else:
            assert x == y


@pytest.mark.parametrize("seed", [1, 2])
def test_split_table_is_the_full_mechanism_table_to_the_last_bit(cold, seed):
    """Thermo from the species' own phase, transport with the temperature alone changed: the
    arrays of the full solution set in full at every temperature, for shared and fresh phases."""
    full = G.gri30()
    fresh = ct.Solution(G.MECHANISM)
    comps = [G.parse_composition(c) for c in ("N2:1", "CO2:1", "H2O:1", G.AIR)]
    for comp in comps + _compositions(40, seed):
        want = _table_arrays_as_before(comp, full)
        _assert_same_arrays(G._table_arrays(comp), want)
        _assert_same_arrays(G._table_arrays(comp, fresh), want)


def test_transport_fits_are_computed_on_first_use_only(cold, monkeypatch):
    calls = []
    original = G._transport_arrays
    monkeypatch.setattr(G, "_transport_arrays", lambda *a: calls.append(a) or original(*a))
    b = G.burn_fuel("CH4:1", 1.0e-3, 0.02)
    float(b.table.enthalpy(1500.0)), float(b.table.cp(1500.0))
    assert calls == []  # a burner's products need their enthalpy only
    k, mu = b.table.conductivity(T), b.table.viscosity(T)
    assert len(calls) == 1
    b.table.prandtl(T)
    assert len(calls) == 1  # kept with the table
    want = _table_arrays_as_before(b.table.composition, ct.Solution(G.MECHANISM))
    assert np.array_equal(b.table._k.c, want["k_c"]) and np.array_equal(b.table._mu.c, want["mu_c"])
    assert np.array_equal(k, b.table.conductivity(T)) and np.array_equal(mu, b.table.viscosity(T))


def test_transport_fits_read_back_from_disk(tmp_path, monkeypatch):
    monkeypatch.setenv("ROTARYKILN_CACHE_DIR", str(tmp_path / "cache"))
    _clear()
    try:
        first = _table_numbers(G.gas_table("CO2:0.1, H2O:0.2, N2:0.7"))
        kinds = sorted(p.name.split("-")[0] for p in (tmp_path / "cache").iterdir())
        assert kinds == ["table", "transport"]
        _clear()
        files = sorted((tmp_path / "cache").iterdir())
        monkeypatch.setattr(G, "_transport_arrays", None)  # nothing computed again
        monkeypatch.setattr(G, "_thermo_arrays", None)
        _assert_same(_table_numbers(G.gas_table("CO2:0.1, H2O:0.2, N2:0.7")), first)
        assert sorted((tmp_path / "cache").iterdir()) == files
    finally:
        _clear()


def test_a_sweep_gives_what_cold_computations_give(cold):
    """A fuel-flow sweep on the kept phases gives, case by case, what each case computed from
    nothing gives (in-memory caches, phases and the GRI-Mech 3.0 solution all new)."""
    swept = [_burnt_numbers(G.burn_fuel("CH4:1", f, a)) for f, a in FLOWS]
    for (fuel_flow, air_flow), want in zip(FLOWS, swept, strict=True):
        _clear()
        G._thread.__dict__.pop("gri30", None)
        _assert_same(_burnt_numbers(G.burn_fuel("CH4:1", fuel_flow, air_flow)), want)


def test_two_fuels_or_oxidisers_never_share_an_entry(cold):
    fuels = ("CH4:1", "CH4:0.9, C2H6:0.05, H2:0.03, N2:0.02", "H2:0.5, CO:0.5")
    oxidisers = (G.AIR, "O2:0.3, N2:0.7")
    got = {}
    for fuel in fuels:
        for air in oxidisers:
            got[fuel, air] = [G.burn_fuel(fuel, f, a, air=air) for f, a in FLOWS[:3]]
    comps = [b.composition for runs in got.values() for b in runs]
    assert len(set(comps)) == len(comps)  # every burner its own products
    tables = [b.table for runs in got.values() for b in runs]
    assert len({id(t) for t in tables}) == len(tables)
    for (fuel, air), runs in got.items():  # each the same as computed alone, from nothing
        for (f, a), b in zip(FLOWS[:3], runs, strict=True):
            _clear()
            _assert_same(_burnt_numbers(G.burn_fuel(fuel, f, a, air=air)), _burnt_numbers(b))


def test_thermo_phases_are_kept_per_species_set_and_bounded(cold):
    comp_a = G.parse_composition("CO2:0.1, H2O:0.2, N2:0.7")
    comp_b = G.parse_composition("CO2:0.12, H2O:0.18, N2:0.7")  # the same species
    comp_c = G.parse_composition("CO2:0.1, H2O:0.2, N2:0.69, O2:0.01")
    table_a, table_b, table_c = (G.gas_table(c) for c in (comp_a, comp_b, comp_c))
    phases = G._thread.thermo_phases
    assert sorted(phases) == [("H2O", "CO2", "N2"), ("O2", "H2O", "CO2", "N2")]  # gri30 order
    assert table_a.x_co2 == pytest.approx(0.1) and table_b.x_co2 == pytest.approx(0.12)
    assert table_c.x_co2 == pytest.approx(0.1)
    assert float(table_a.cp(1500.0)) != float(table_b.cp(1500.0))
    for c in _compositions(G.THERMO_PHASES + 10, 3):
        G.gas_table(c)
    assert len(G._thread.thermo_phases) <= G.THERMO_PHASES


def test_enthalpy_at_is_the_numpy_enthalpy_to_the_last_bit(cold):
    rng = np.random.default_rng(5)
    t = np.concatenate([T, rng.uniform(100.0, 7000.0, 3000), G.T_GRID - 1e-9, G.T_GRID + 1e-9])
    for comp in ["N2:1", G.AIR, *_compositions(5, 4)]:
        table = G.gas_table(comp)
        got = np.array([table._enthalpy_at(float(v)) for v in t])
        want = np.array([float(table.enthalpy(v)) for v in t])
        assert np.array_equal(got, want)
        assert np.array_equal(got, table.enthalpy(t))


def test_piecewise_value_on_uneven_breakpoints():
    rng = np.random.default_rng(6)
    x = np.cumsum(rng.uniform(0.5, 3.0, 40))
    p = G.PiecewisePolynomials(x, CubicSpline(x, np.sin(x)).c)
    assert p._step is None
    t = np.concatenate([x, rng.uniform(x[0], x[-1], 2000)])
    got = np.array([p.value(float(v)) for v in t])
    assert np.array_equal(got, p.evaluate(*p.interval(t)))


def test_tables_and_burnt_gases_pickle(cold):
    b = G.burn_fuel("CH4:1", 1.0e-3, 0.02)
    lazy = pickle.loads(pickle.dumps(b))  # transport not computed yet: computed after
    assert lazy.table._transport is None and "_transport_fits" not in lazy.table.__dict__
    _assert_same(_burnt_numbers(lazy), _burnt_numbers(b))
    done = pickle.loads(pickle.dumps(b))  # transport computed: carried along
    assert "_transport_fits" in done.table.__dict__
    _assert_same(_burnt_numbers(done), _burnt_numbers(b))


def _burn_in_worker(args):
    fuel, fuel_flow, air_flow = args
    return _burnt_numbers(G.burn_fuel(fuel, fuel_flow, air_flow))


def test_threads_and_worker_processes_give_the_same_numbers(cold):
    want = [_burnt_numbers(G.burn_fuel("CH4:1", f, a)) for f, a in FLOWS]
    _clear()
    got: dict = {}

    def run(i, f, a):
        got[i] = _burnt_numbers(G.burn_fuel("CH4:1", f, a))

    threads = [threading.Thread(target=run, args=(i, f, a)) for i, (f, a) in enumerate(FLOWS)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    for i, w in enumerate(want):
        _assert_same(got[i], w)
    with ProcessPoolExecutor(max_workers=2) as pool:
        done = list(pool.map(_burn_in_worker, [("CH4:1", f, a) for f, a in FLOWS]))
    for g, w in zip(done, want, strict=True):
        _assert_same(g, w)
