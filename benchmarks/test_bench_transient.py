"""Speed of the transient kiln (issue 12 target: 10 h of simulated time of a 100-cell fired kiln,
median <= 10 s; issue 25: the documented cold start, median <= 3 s).

Barr's trial T4 (the fired pilot kiln, lined wall cut into 6 nodes) from its steady state, with
a fuel step at 1 h and a feed ramp at 4 h: 10 h in one run. The kiln is built, and its steady
state solved, outside the timing.

The documented cold start (``rotarykiln transient barr_T4 --events barr_T4_startup --until
"10 h"``): the same kiln from ambient, the shipped events file; the kiln and events are read
outside the timing, the outputs are not written.

Run: ``.venv/bin/python -m pytest benchmarks/test_bench_transient.py --benchmark-enable
--benchmark-only -q --benchmark-columns=median,iqr,rounds``.
"""

import warnings

import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.examples import example_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.transient.integrate import TransientKiln, simulate
from rotarykiln.transient_file import parse_transient, read_transient_file

SPEC = {
    "wall": {
        "layers": [
            {"density": "1300 kg/m3", "specific_heat": "1000 J/kg/K"},
            {"density": "7850 kg/m3", "specific_heat": "490 J/kg/K"},
        ]
    },
    "events": [
        {"at": "1 h", "variable": "fuel_flow", "to": "2.2 NL/s"},
        {"at": "4 h", "variable": "feed", "to": "70 kg/h", "over": "30 min"},
    ],
    "output_every": "5 min",
}


@pytest.fixture(scope="module")
def barr_t4():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kiln, _ = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    tr = parse_transient(SPEC, kiln, 36000.0)
    _, steady = TransientKiln(kiln, 100, tr.wall).steady_state()
    return kiln, tr, steady


def test_bench_transient_barr_T4_10_h(benchmark, barr_t4):
    kiln, tr, steady = barr_t4
    sol = benchmark.pedantic(
        simulate, args=(kiln, 100, tr, 36000.0), kwargs={"steady": steady}, rounds=3, iterations=1
    )
    assert sol.t[-1] == 36000.0
    assert abs(sol.energy_conservation()[-1]) < 1e-5


def test_bench_transient_barr_T4_cold_start_10_h(benchmark, barr_t4):
    kiln = barr_t4[0]
    data = read_transient_file(example_path("--events", "barr_T4_startup"))
    tr = parse_transient(data, kiln, 36000.0)
    assert tr.start == "cold"
    sol = benchmark.pedantic(simulate, args=(kiln, 100, tr, 36000.0), rounds=3, iterations=1)
    assert sol.t[-1] == 36000.0
    assert abs(sol.energy_conservation()).max() < 1e-5
    assert max(sol.element_conservation().values()) < 1e-10
