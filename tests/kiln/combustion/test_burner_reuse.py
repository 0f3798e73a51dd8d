"""The burner's set-up of a new case from what is kept between cases (issue 25 item 2): a
sweep over fuel flow, air flows or air temperatures loads no Cantera mechanism after its first
case, and every flame is the one computed from nothing, to the last bit; the air streams mix
as Cantera mixes them (one fresh solution per stream, as before), closer to the enthalpy balance
than Cantera's own solution; two fuels or oxidisers never share an entry."""

from __future__ import annotations

import dataclasses
import pickle

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.combustion import flame as F
from rotarykiln.kiln.combustion.flame import AirStream, fire
from rotarykiln.kiln.from_case import burner_from_case
from rotarykiln.materials import combustion as C
from rotarykiln.materials import dissociation as D
from rotarykiln.materials import gas as G

ct = pytest.importorskip("cantera")

T = np.linspace(150.0, 3400.0, 651)


def _clear():
    for f in (
        G._cantera_table,
        G._burn,
        G.fuel_data,
        F._fuel_data,
        F._table_heat,
        F._equilibrium_temperature,
        D._heat,
        D._adiabatic,
        C._species,
        C._complete,
        C._table,
    ):
        f.cache_clear()
    G._thread.__dict__.pop("thermo_phases", None)


@pytest.fixture
def cold(monkeypatch):
    """No disk cache; the in-memory caches and this thread's phases emptied around."""
    monkeypatch.setenv("ROTARYKILN_CACHE_DIR", "off")
    _clear()
    yield
    _clear()


@pytest.fixture(scope="module")
def barr_t4() -> F.Burner:
    case = load_case(builtin_case_path("barr_T4"))
    return burner_from_case(case.burner, case.operation.counter_current)


def _variants(b: F.Burner) -> dict[str, F.Burner]:
    sec, prim = b.secondary_air, b.primary_air
    hot = dataclasses.replace(sec, temperature=1100.0)
    return {
        "as given": b,
        "hot secondary air": dataclasses.replace(b, secondary_air=hot),
        "ingress at the burner": dataclasses.replace(
            b,
            secondary_air=hot,
            primary_air=dataclasses.replace(prim, temperature=350.0),
            ingress_air=AirStream(0.002, 500.0),
            ingress_at_burner=True,
        ),
        "enriched": dataclasses.replace(
            b, secondary_air=AirStream(sec.flow, 800.0, "O2:0.3, N2:0.7")
        ),
        "burnout": dataclasses.replace(b, nozzle_diameter=0.04, combustion="burnout"),
        "complete": dataclasses.replace(b, products="complete"),
        "fuel mix": dataclasses.replace(b, fuel="CH4:0.9, C2H6:0.05, H2:0.03, N2:0.02"),
    }


def _numbers(f: F.Flame) -> list:
    """Every number of a flame (its products' table evaluated, transport included)."""
    p = f.products
    out = [p.composition, p.mass_flow, p.inlet_temperature, p.adiabatic_temperature]
    out += [p.heat_release, p.table.molar_mass, p.table.x_co2, p.table.x_h2o]
    out += [getattr(p.table, n).c for n in ("_cp", "_h", "_k", "_mu")]
    out += [getattr(p.table, m)(T) for m in ("cp", "enthalpy", "conductivity", "viscosity")]
    out += [f.fuel_lhv, f.fuel_hhv, f.sensible_input, f.excess_air, f.primary_excess_air]
    out += [f.equivalent_diameter, f.nozzle_velocity, f.thring_newby, f.entrainment_length]
    out += [f.recirculation_length, f.recirculating, f.flame_length, f.equilibrium_temperature]
    if f.dissociation is not None:
        out += [f.dissociation.spline.c, f.dissociation.enthalpy(T), f.dissociation.cp(T)]
    return out


def _assert_same(a: list, b: list):
    assert len(a) == len(b)
    for x, y in zip(a, b, strict=True):
        if isinstance(x, np.ndarray):
            assert x.dtype == y.dtype and np.array_equal(x, y)
        else:
            assert type(x) is type(y) and x == y


def _mixed_as_before(streams):
    """The mixing of the air streams as it was: Cantera's ``Quantity`` at ``HP``, one fresh
    GRI-Mech 3.0 solution per stream; with the streams' enthalpy flow (W)."""
    total = None
    enthalpy = 0.0
    for flow, temperature, composition in streams:
        g = ct.Solution(G.MECHANISM)
        g.TPX = temperature, 101325.0, composition
        enthalpy += g.enthalpy_mass * flow
        q = ct.Quantity(g, mass=flow, constant="HP")
        total = q if total is None else total + q
    return total, enthalpy


def test_air_streams_mix_as_with_a_fresh_solution_per_stream(cold):
    """:func:`~rotarykiln.materials.combustion.mixing_temperature` (NASA-7 polynomials, no
    Cantera) gives Cantera's mixed temperature within 1e-6 K (where Cantera's own solution of
    the enthalpy balance stops) and holds the streams' enthalpy within 1e-12 of it."""
    rng = np.random.default_rng(11)
    compositions = (G.AIR, "O2:0.3, N2:0.7", "O2:1", "O2:0.05, CO2:0.1, H2O:0.15, N2:0.7")
    for _ in range(30):
        n = int(rng.integers(2, 4))
        streams = tuple(
            (
                float(rng.uniform(1e-4, 0.5)),
                float(rng.uniform(250.0, 1400.0)),
                compositions[int(rng.integers(len(compositions)))],
            )
            for _ in range(n)
        )
        mixed, enthalpy = _mixed_as_before(streams)
        t = C.mixing_temperature(streams)
        assert type(t) is float and t == pytest.approx(mixed.T, abs=1e-6)
        mixed.TP = t, 101325.0
        assert mixed.enthalpy_mass * mixed.mass == pytest.approx(enthalpy, rel=1e-12, abs=1e-9)


def test_a_sweep_gives_what_cold_computations_give(cold, barr_t4):
    """Fuel flows and secondary air temperatures swept on the kept phases and caches give,
    case by case, the flame computed from nothing (caches, phases, solution all new)."""
    for base in _variants(barr_t4).values():
        cases = [dataclasses.replace(base, fuel_flow=base.fuel_flow * s) for s in (0.97, 1.03)]
        sec = base.secondary_air
        cases.append(
            dataclasses.replace(
                base,
                secondary_air=dataclasses.replace(
                    sec, flow=sec.flow * 1.1, temperature=sec.temperature + 55.0
                ),
            )
        )
        swept = [_numbers(fire(b, 0.411, 5.5)) for b in cases]
        for b, want in zip(cases, swept, strict=True):
            _clear()
            G._thread.__dict__.pop("gri30", None)
            _assert_same(_numbers(fire(b, 0.411, 5.5)), want)


def test_a_sweep_loads_no_mechanism_after_its_first_case(cold, barr_t4, monkeypatch):
    hot = dataclasses.replace(barr_t4.secondary_air, temperature=900.0)
    base = dataclasses.replace(barr_t4, secondary_air=hot)
    fire(base, 0.411, 5.5)  # the first case of this fuel and oxidiser
    built = []
    solution = ct.Solution

    def counting(*args, **kwargs):
        built.append((args, sorted(kwargs)))
        return solution(*args, **kwargs)

    monkeypatch.setattr(ct, "Solution", counting)
    species_sets = set()
    for i in range(1, 25):
        air = dataclasses.replace(hot, temperature=900.0 + 3.0 * i, flow=hot.flow * (1 + i / 50))
        f = fire(
            dataclasses.replace(base, fuel_flow=base.fuel_flow * (1 + i / 100), secondary_air=air),
            0.411,
            5.5,
        )
        species_sets.add(tuple(s for s, _ in f.products.composition))
    assert not [b for b in built if b[0]]  # no mechanism file loaded
    assert len(built) <= len(species_sets)  # a thermo-only phase per new species set at most


def test_two_fuels_or_oxidisers_never_share_an_entry(cold, barr_t4):
    sec = barr_t4.secondary_air
    burners = {
        (fuel, air): dataclasses.replace(
            barr_t4, fuel=fuel, secondary_air=AirStream(sec.flow, 700.0, air)
        )
        for fuel in ("CH4:1", "CH4:0.9, C2H6:0.05, H2:0.03, N2:0.02")
        for air in (G.AIR, "O2:0.3, N2:0.7")
    }
    flames = {k: fire(b, 0.411, 5.5) for k, b in burners.items()}
    temperatures = {f.products.inlet_temperature for f in flames.values()}
    compositions = {f.products.composition for f in flames.values()}
    assert len(temperatures) == len(compositions) == len(flames)
    for key, f in flames.items():
        _clear()
        _assert_same(_numbers(fire(burners[key], 0.411, 5.5)), _numbers(f))


def test_a_flame_pickles(cold, barr_t4):
    f = fire(dataclasses.replace(barr_t4, combustion="burnout", nozzle_diameter=0.04), 0.411, 5.5)
    _assert_same(_numbers(pickle.loads(pickle.dumps(f))), _numbers(f))
