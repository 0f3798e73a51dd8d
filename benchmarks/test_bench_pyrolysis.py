"""Pyrolysis kiln speed: the rotaryPyrolysis default case (cases/rotary_pyrolysis.yaml) with axial
dispersion (Pe 5) inside the balances, 100 cells (issue 11 target: median <= 0.3 s; the anchor
script takes 45-50 s).

The kiln is built once, outside the timing (gas tables, Cantera); each round is a full solve
from the default initial guess.
"""

import warnings

import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import OutOfRangeWarning
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.results.yields import outlet_yield
from rotarykiln.kiln.steady.solve import solve_kiln


@pytest.fixture(scope="module")
def pyrolysis_kiln():
    kiln, _ = kiln_from_case(load_case(builtin_case_path("rotary_pyrolysis")))  # Pe 5
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutOfRangeWarning)
        solve_kiln(kiln, 100)  # gas tables built once, outside the timing
    return kiln


def _solve(kiln):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutOfRangeWarning)
        return solve_kiln(kiln, 100)


def test_bench_pyrolysis_default_case_dispersion_100_cells(benchmark, pyrolysis_kiln):
    sol = benchmark(_solve, pyrolysis_kiln)
    assert abs(sol.energy_closure) <= 1e-6
    assert 0.15 < outlet_yield(sol, "char") < 0.22
