"""Per-case set-up and start-up of the command line (issue 24 item 5, issue 25 item 2).

- ``test_bench_parse_build_per_case``: parse and build Barr T4 with a new feed and fuel flow
  every round (a sweep's per-case set-up: case validation, the burner's products and their
  Cantera gas table, the dissociation heat, the kiln); target: no more than a solve (~20-30 ms).
  A new fuel flow gives new products, so the in-memory caches do not help: what is timed is
  Cantera's work on the shared per-thread solution. The disk cache is off.
- ``test_bench_run_barr_T4_process``: the whole ``rotarykiln run barr_T4 --no-plots`` as a
  subprocess with a warm disk cache (the second run of a case); target <= 1.0 s.
- ``test_bench_parse_build_cold_tables``: the same with every cache emptied, for reference.

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

from rotarykiln.case import parse_case, read_case_yaml
from rotarykiln.cases import builtin_case_path
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
    from rotarykiln.materials import dissociation, gas

    def cold():
        for f in (gas._cantera_table, gas._burn, dissociation._heat, dissociation._adiabatic):
            f.cache_clear()
        return _parse_build(next(barr_cases))

    kiln = benchmark.pedantic(cold, rounds=20, iterations=1)
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
