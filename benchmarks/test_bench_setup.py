"""Per-case set-up and start-up of the command line (issue 24 item 5, issue 25 item 2).

- ``test_bench_parse_build_per_case``: parse and build Barr T4 with a new feed and fuel flow
  every round (a sweep's per-case set-up: case validation, the burner's products by elements,
  their dissociation heat from the pair's table, the kiln); target: no more than a solve
  (~20-30 ms). A new fuel flow gives new products, so the in-memory caches of a flame do not
  help; since 2026-12-04 no Cantera is called for it. The disk cache is off.
- ``test_bench_run_barr_T4_process``: the whole ``rotarykiln run barr_T4 --no-plots`` as a
  subprocess with a warm disk cache (the second run of a case); target <= 1.0 s.
- ``test_bench_parse_build_cold_tables``: the same with every cache emptied, for reference
  (the fuel and oxidiser's dissociation table built again every round: the one-time cost).
- ``test_bench_case_with_build_tscheng_A16``: a study's variant of a hot-air kiln, made with
  :func:`rotarykiln.case.case_with` (a new speed and gas flow every round, texts never seen
  before) and built (:func:`kiln_from_case`); target: median <= 2 ms.
- ``test_bench_case_with_build_barr_T4``: the same for the fired Barr T4 with a new feed (the
  burner unchanged: its flame comes from the caches of the combustion code); the flame's share
  of the time is in the benchmark's ``extra_info`` (``flame_share``).
- ``test_bench_parse_merged_build_tscheng_A16``: the old way, for comparison: the whole case
  mapping with the new values parsed (``parse_case``) and built.

Run: ``.venv/bin/python -m pytest benchmarks/test_bench_setup.py --benchmark-enable
--benchmark-only -q --benchmark-columns=median,iqr,rounds``.
"""

from __future__ import annotations

import copy
import itertools
import os
import subprocess
import sys

import pytest

from rotarykiln.case import case_with, load_case, parse_case, read_case_yaml
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln import from_case
from rotarykiln.kiln.from_case import kiln_from_case


@pytest.fixture(scope="module")
def no_disk_cache():
    old = os.environ.get("ROTARYKILN_CACHE_DIR")
    os.environ["ROTARYKILN_CACHE_DIR"] = "off"
    yield
    if old is None:
        del os.environ["ROTARYKILN_CACHE_DIR"]
    else:
        os.environ["ROTARYKILN_CACHE_DIR"] = old


@pytest.fixture(scope="module")
def barr_cases(no_disk_cache):
    """An endless supply of Barr T4 case data, each with its own feed and fuel flow."""
    base = read_case_yaml(builtin_case_path("barr_T4"))
    kiln_from_case(parse_case(base))  # first-call costs (imports, species) outside the timing

    def cases():
        for i in itertools.count():
            d = copy.deepcopy(base)
            d["operation"]["feed"] = f"{50.0 + (i % 997) * 0.031:.4f} kg/h"
            d["burner"]["fuel_flow"] = f"{1.7 + (i % 991) * 5.3e-4:.6f} L/s"
            yield d

    return cases()


def _parse_build(data):
    kiln, cells = kiln_from_case(parse_case(data))
    return kiln


def test_bench_parse_build_per_case(benchmark, barr_cases):
    kiln = benchmark.pedantic(
        lambda: _parse_build(next(barr_cases)), rounds=200, iterations=1, warmup_rounds=2
    )
    assert kiln.firing.flame is not None


def test_bench_parse_build_cold_tables(benchmark, barr_cases):
    from rotarykiln.kiln.combustion import flame
    from rotarykiln.materials import combustion, dissociation, gas

    def cold():
        for f in (
            gas._cantera_table,
            gas._burn,
            dissociation._heat,
            dissociation._adiabatic,
            combustion._species,
            combustion._complete,
            combustion._table,
            flame._table_heat,
            flame._equilibrium_temperature,
        ):
            f.cache_clear()
        return _parse_build(next(barr_cases))

    kiln = benchmark.pedantic(cold, rounds=5, iterations=1)
    assert kiln.firing.flame is not None


def test_bench_run_barr_T4_process(benchmark, tmp_path):
    env = {k: v for k, v in os.environ.items() if k != "ROTARYKILN_CACHE_DIR"}
    env["MPLBACKEND"] = "Agg"
    cmd = [sys.executable, "-m", "rotarykiln", "run", "barr_T4", "--no-plots"]
    cmd += ["--out", str(tmp_path / "out")]
    subprocess.run(cmd, env=env, check=True, capture_output=True)  # the disk cache filled

    def run():
        return subprocess.run(cmd, env=env, capture_output=True, text=True)

    done = benchmark.pedantic(run, rounds=7, iterations=1)
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize("argv", [["--version"], ["--help"]], ids=["version", "help"])
def test_bench_version_and_help_process(benchmark, argv):
    """``rotarykiln --version`` and ``--help`` as whole processes (target <= 0.5 s): no command
    module, numpy or pint is imported for them."""
    cmd = [sys.executable, "-m", "rotarykiln", *argv]

    def run():
        return subprocess.run(cmd, capture_output=True, text=True)

    done = benchmark.pedantic(run, rounds=9, iterations=1)
    assert done.returncode == 0 and "rotarykiln" in done.stdout


def _variants(name: str, changes):
    """An endless supply of (base case, changes) for the case ``name``: ``changes(i)`` gives
    the i-th variant's dotted fields (new texts every round, written with a number of digits
    no other test uses: pint parses each, as it would a study's values)."""
    base = load_case(builtin_case_path(name))
    kiln_from_case(base)  # first-call costs outside the timing
    return base, (changes(i) for i in itertools.count())


def test_bench_case_with_build_tscheng_A16(benchmark, no_disk_cache):
    base, changes = _variants(
        "tscheng_A16",
        lambda i: {
            "operation.speed": f"{1.0 + i * 1.3e-3:.7f} rpm",
            "gas.flow": f"{20.0 + i * 7.1e-3:.7f} kg/h",
        },
    )

    def variant():
        return kiln_from_case(case_with(base, next(changes)))

    kiln, cells = benchmark.pedantic(variant, rounds=500, iterations=1, warmup_rounds=5)
    assert cells == 100 and kiln.firing.flame is None


def test_bench_case_with_build_barr_T4(benchmark, no_disk_cache, monkeypatch):
    base, changes = _variants(
        "barr_T4", lambda i: {"operation.feed": f"{50.0 + i * 0.031:.7f} kg/h"}
    )
    import time

    spent = []
    fire = from_case.fire

    def timed_fire(*args, **kwargs):
        t0 = time.perf_counter()
        try:
            return fire(*args, **kwargs)
        finally:
            spent.append(time.perf_counter() - t0)

    monkeypatch.setattr(from_case, "fire", timed_fire)
    total = []

    def variant():
        t0 = time.perf_counter()
        out = kiln_from_case(case_with(base, next(changes)))
        total.append(time.perf_counter() - t0)
        return out

    kiln, cells = benchmark.pedantic(variant, rounds=300, iterations=1, warmup_rounds=5)
    assert kiln.firing.flame is not None
    benchmark.extra_info["flame_share"] = round(sum(spent[-300:]) / sum(total[-300:]), 3)


def test_bench_parse_merged_build_tscheng_A16(benchmark, no_disk_cache):
    data = read_case_yaml(builtin_case_path("tscheng_A16"))
    kiln_from_case(parse_case(data))
    counter = itertools.count()

    def variant():
        i = next(counter)
        d = copy.deepcopy(data)
        d["operation"]["speed"] = f"{1.0 + i * 1.3e-3:.8f} rpm"  # texts of no other test
        d["gas"]["flow"] = f"{20.0 + i * 7.1e-3:.8f} kg/h"
        return kiln_from_case(parse_case(d))

    kiln, cells = benchmark.pedantic(variant, rounds=300, iterations=1, warmup_rounds=5)
    assert cells == 100
