"""The burner's set-up of a new case (issue 25 item 2): Barr T4 swept over its fuel flow.

A sweep of a fired kiln over its fuel flow, air flows or air temperatures (the same fuel and
oxidiser compositions) gives a new flame every case: new products, so the in-memory caches of
the products do not help. What is timed is the work that is left once the first case of that
fuel and oxidiser has been computed (imports, the species' data, the fuel's heating values, the
dissociation table of the pair: all warmed up outside the timing). Since 2026-12-04 that work
needs no Cantera (:mod:`rotarykiln.materials.combustion`: products by elements, the
dissociation heat from the pair's table).

- ``test_bench_burner_new_fuel_flow``: :func:`~rotarykiln.kiln.combustion.flame.fire` of Barr
  T4's burner with a new fuel flow every round (products at equilibrium, the default: the
  dissociation heat of the new products is part of it);
- ``test_bench_burner_new_fuel_flow_complete``: the same with ``products: complete`` (no
  dissociation heat);
- ``test_bench_burner_new_air_temperature``: a new secondary air temperature every round (the
  streams mixed at constant enthalpy; fuel flow as given);
- ``test_bench_burner_new_air_flow``: a new secondary air flow every round;
- ``test_bench_burner_new_fuel_flow_nozzle``: a new fuel flow of a burner with a nozzle
  diameter (the jet numbers and the nozzle fluid's adiabatic flame: a second combustion);
- ``test_bench_burner_new_fuel_flow_disk_cache``: the first with the disk cache on (a
  temporary folder), as a user's sweep runs;
- ``test_bench_burner_same_case``: the same burner again (the in-memory caches);
- ``test_bench_burner_dissociation_table``: the one-time cost of a fuel and oxidiser pair, the
  dissociation table built from Cantera (its memory and disk caches emptied);
- ``test_bench_kiln_from_case_new_fuel_flow``: the whole set-up of a case with a new fuel
  flow, :func:`~rotarykiln.kiln.from_case.kiln_from_case` of a parsed case.

The disk cache is off except where said. Target: the burner's set-up of a new case well under
1 ms.

Run: ``.venv/bin/python -m pytest benchmarks/test_bench_burner.py --benchmark-enable
--benchmark-only -q --benchmark-columns=median,iqr,rounds``.
"""

from __future__ import annotations

import copy
import dataclasses
import itertools
import os

import pytest

from rotarykiln.case import load_case, parse_case, read_case_yaml
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.combustion.flame import fire
from rotarykiln.kiln.from_case import burner_from_case, kiln_from_case

ROUNDS = 200
#: One counter for every test of the module: no flow is ever given twice in a process (a flow
#: seen before would be read from the in-memory caches).
_NEW = itertools.count(1)


@pytest.fixture
def disk_cache(monkeypatch, tmp_path):
    """``disk_cache(on)``: the disk cache in an empty temporary folder, or off."""

    def set_to(on: bool):
        monkeypatch.setenv("ROTARYKILN_CACHE_DIR", str(tmp_path / "cache") if on else "off")

    set_to(False)
    return set_to


@pytest.fixture(scope="module")
def barr_t4():
    """Barr T4's burner, kiln diameter (m) and length (m), warmed up (its fuel, the phases)."""
    case = load_case(builtin_case_path("barr_T4"))
    burner = burner_from_case(case.burner, case.operation.counter_current)
    old = os.environ.get("ROTARYKILN_CACHE_DIR")
    os.environ["ROTARYKILN_CACHE_DIR"] = "off"
    try:
        for scale in (0.999, 0.998):  # first-call costs outside the timing
            fire(dataclasses.replace(burner, fuel_flow=burner.fuel_flow * scale), 0.411, 5.5)
    finally:
        if old is None:
            del os.environ["ROTARYKILN_CACHE_DIR"]
        else:
            os.environ["ROTARYKILN_CACHE_DIR"] = old
    return burner, case.kiln.diameter, case.kiln.length


def _fuel_flows(burner, **changes):
    """Barr T4's burner with a new fuel flow (kg/s) every time (never twice the same)."""
    base = dataclasses.replace(burner, **changes)
    for i in _NEW:
        yield dataclasses.replace(base, fuel_flow=burner.fuel_flow * (1.0 + 1.0e-5 * i))


def _fire_each(benchmark, burners, diameter, length):
    flame = benchmark.pedantic(
        fire,
        setup=lambda: ((next(burners), diameter, length), {}),  # outside the timing
        rounds=ROUNDS,
        iterations=1,
        warmup_rounds=2,
    )
    benchmark.extra_info["median_ms"] = benchmark.stats.stats.median * 1e3
    return flame


def test_bench_burner_new_fuel_flow(benchmark, barr_t4, disk_cache):
    burner, diameter, length = barr_t4
    flame = _fire_each(benchmark, _fuel_flows(burner), diameter, length)
    assert flame.dissociation is not None and flame.products.mass_flow > 0


def test_bench_burner_new_fuel_flow_complete(benchmark, barr_t4, disk_cache):
    burner, diameter, length = barr_t4
    flame = _fire_each(benchmark, _fuel_flows(burner, products="complete"), diameter, length)
    assert flame.dissociation is None


def test_bench_burner_new_air_temperature(benchmark, barr_t4, disk_cache):
    burner, diameter, length = barr_t4
    sec = burner.secondary_air

    def burners():
        for i in _NEW:
            air = dataclasses.replace(sec, temperature=400.0 + 0.037 * i)
            yield dataclasses.replace(burner, secondary_air=air)

    flame = _fire_each(benchmark, burners(), diameter, length)
    assert flame.products.inlet_temperature > 298.15


def test_bench_burner_new_air_flow(benchmark, barr_t4, disk_cache):
    burner, diameter, length = barr_t4
    sec = burner.secondary_air

    def burners():
        for i in _NEW:
            air = dataclasses.replace(sec, flow=sec.flow * (1.0 + 1.0e-5 * i))
            yield dataclasses.replace(burner, secondary_air=air)

    flame = _fire_each(benchmark, burners(), diameter, length)
    assert flame.dissociation is not None


def test_bench_burner_new_fuel_flow_nozzle(benchmark, barr_t4, disk_cache):
    burner, diameter, length = barr_t4
    burners = _fuel_flows(burner, nozzle_diameter=0.04, combustion="burnout")
    flame = _fire_each(benchmark, burners, diameter, length)
    assert flame.flame_length is not None


def test_bench_burner_dissociation_table(benchmark, disk_cache):
    from rotarykiln.materials import combustion
    from rotarykiln.materials.gas import AIR, parse_composition

    fuel, air = parse_composition("CH4:1"), parse_composition(AIR)
    combustion.dissociation_table(fuel, air)  # imports, Cantera's solution, the species

    def build():
        combustion._table.cache_clear()
        return combustion.dissociation_table(fuel, air)

    table = benchmark.pedantic(build, rounds=3, iterations=1)
    assert table.values.shape == (combustion.TABLE_NODES, 121)


def test_bench_burner_new_fuel_flow_disk_cache(benchmark, barr_t4, disk_cache):
    disk_cache(True)
    burner, diameter, length = barr_t4
    flame = _fire_each(benchmark, _fuel_flows(burner), diameter, length)
    assert flame.dissociation is not None


def test_bench_burner_same_case(benchmark, barr_t4, disk_cache):
    burner, diameter, length = barr_t4
    fire(burner, diameter, length)
    flame = benchmark(fire, burner, diameter, length)
    assert flame.products.mass_flow > 0


def test_bench_kiln_from_case_new_fuel_flow(benchmark, barr_t4, disk_cache):
    base = read_case_yaml(builtin_case_path("barr_T4"))
    kiln_from_case(parse_case(base))  # first-call costs outside the timing

    def cases():
        for i in _NEW:
            data = copy.deepcopy(base)
            data["burner"]["fuel_flow"] = f"{1.97 * (1.0 + 1.0e-5 * i):.12g} L/s"
            yield parse_case(data)

    supply = cases()
    kiln, _ = benchmark.pedantic(
        kiln_from_case,
        setup=lambda: ((next(supply),), {}),  # the case parsed outside the timing
        rounds=ROUNDS,
        iterations=1,
        warmup_rounds=2,
    )
    benchmark.extra_info["median_ms"] = benchmark.stats.stats.median * 1e3
    assert kiln.firing.flame is not None
