"""Bound and oscillation checks of every steady kiln solve (issue 21).

The rotary_pyrolysis case in a 1 m long, 6 m diameter drum "succeeded" with its gas at 1,074 K in
the first cell (the jacket enters at 833 K, the wall was 786 K, the bed 466 K), then 457 / 662 K
from cell to cell, its energy closing to 2e-12. The cause: 1 kg/h of sweep gas exchanging with
square metres of wall and bed holds tens of transfer units per cell, and the cell mean taken as
the average of its faces let the outlet face overshoot (2 x the mean - the inlet) and zigzag.
The cell mean now weighs the faces by the cell's transfer units beyond one per cell
(exchange.upwind_weight), and
every solve checks that no phase is hotter or colder than everything it exchanges heat with and
that no profile zigzags.
"""

from __future__ import annotations

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import ConvergenceError
from rotarykiln.kiln import residual as residual_module
from rotarykiln.kiln.accounting import exhaust_state
from rotarykiln.kiln.exchange import upwind_weight
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.residual import KilnResidual
from rotarykiln.kiln.steady import solve as solve_module
from rotarykiln.kiln.steady.solve import solve_kiln, zigzag

JACKET_INLET = 833.15  # K, the case's flue gas


def _big_drum_kiln():
    data = yaml.safe_load(builtin_case_path("rotary_pyrolysis").read_text())
    data["kiln"]["length"] = "1 m"
    data["kiln"]["diameter"] = "6 m"
    kiln, n = kiln_from_case(parse_case(data))
    return kiln, n


@pytest.fixture(scope="module")
def big_drum():
    kiln, n = _big_drum_kiln()
    return kiln, solve_kiln(kiln, n)


def test_a_big_drum_swept_by_little_gas_stays_between_its_wall_and_bed(big_drum):
    kiln, sol = big_drum
    hottest_partner = max(sol.t_wall.max(), sol.t_bed_nodes.max(), JACKET_INLET)
    assert sol.t_gas_nodes.max() <= hottest_partner + 1.0
    assert sol.t_gas_nodes.max() < JACKET_INLET  # was 1,074 K
    for profile in (sol.t_gas_nodes, sol.t_bed_nodes):
        assert zigzag(profile, 1.0)[0] < solve_module.ZIGZAG_NODES
    assert abs(sol.energy_closure) < 1e-6


def test_the_face_average_overshoots_and_the_checks_refuse_it(monkeypatch):
    # the scheme before issue 21: the cell mean is the average of the faces, whatever the
    # cell's transfer units; the solve must now fail, naming the check, not exit 0
    monkeypatch.setattr(residual_module, "upwind_weight", lambda ntu: 0.5 + 0.0 * ntu)
    kiln, n = _big_drum_kiln()
    with pytest.raises(ConvergenceError, match=r"unphysical solution \((bound|oscillation) check"):
        solve_kiln(kiln, n)


def test_the_weight_goes_from_the_face_average_to_the_outlet():
    n = np.linspace(0.0, 1e3, 200001)
    w = upwind_weight(n)
    assert np.all(w[n <= 1.0] == 0.5)  # ordinary cells: the face average, results unchanged
    assert np.all(np.diff(w) >= 0.0) and np.all(w < 1.0)
    assert np.max(np.abs(np.diff(w))) < 0.3 * (n[1] - n[0])  # no jump (slope < 0.3)
    assert np.all(n * (1.0 - w) <= 1.0 + 1e-12)  # bounded: no overshoot at any cell size
    assert float(upwind_weight(1e6)) == pytest.approx(1.0, abs=1e-5)
    # a cell approaching a fixed 800 K from 300 K: the outlet face stays below 800 K
    for ntu in (0.5, 3.0, 30.0, 3000.0):
        theta = float(upwind_weight(ntu))
        t_out = 300.0 + ntu * (800.0 - 300.0) / (1.0 + ntu * theta)
        assert 300.0 < t_out <= 800.0 + 1e-9


def test_a_zigzag_or_a_phase_beyond_its_partners_is_a_failed_solve(big_drum):
    kiln, sol = big_drum
    res = KilnResidual(kiln, len(sol.t_bed_nodes) - 1)
    z = np.linspace(0.0, 1.0, res.n + 1)
    smooth = 500.0 + 200.0 * z
    wall = np.full((res.n, res.n_wall), 700.0)
    solve_module._check_no_oscillation(res, {"T_gas": smooth}, 0)  # fine
    rough = smooth.copy()
    rough[10:20:2] += 30.0  # 457 / 662 K in the report; here +-30 K over 10 cells
    with pytest.raises(
        ConvergenceError, match=r"oscillation check.*T_gas.* over \d+ nodes from z = 0\.1 m"
    ):
        solve_module._check_no_oscillation(res, {"T_gas": rough}, 0)
    # a gas at 1,074 K between a 786 K wall and a 466 K bed, no source of its own
    tg = np.full(res.n + 1, 600.0)
    tg[1] = 1074.0
    tb = np.full(res.n + 1, 466.0)
    with pytest.raises(ConvergenceError, match=r"bound check.*T_gas reaches 1074 K at z = 0\.01"):
        solve_module._check_within_partners(res, tb, tg, wall, 0)
    # a gas colder than anything around it
    tg[1] = 250.0
    with pytest.raises(ConvergenceError, match="T_gas reaches 250 K.*colder"):
        solve_module._check_within_partners(res, tb, tg, wall, 0)
    solve_module._check_within_partners(res, tb, np.full(res.n + 1, 600.0), wall, 0)
    # a wall layer colder than everything around it
    cold_wall = wall.copy()
    cold_wall[3, -1] = 100.0
    with pytest.raises(ConvergenceError, match=r"T_wall reaches 100 K at z = 0\.035.*colder"):
        solve_module._check_within_partners(res, tb, np.full(res.n + 1, 600.0), cold_wall, 0)


def test_exhaust_dry_o2_is_zero_without_o2_and_never_nan(big_drum):
    kiln, sol = big_drum
    assert sol.exhaust["O2_dry_mole_fraction"] == 0.0  # N2 sweep and pyrolysis gases: no O2
    assert sol.summary()["exhaust_O2_dry_mole_fraction"] == 0.0
    res = KilnResidual(kiln, 8)
    steam_only = np.array([1.0 if s == "H2O" else 0.0 for s in res.gas_names])
    state, _ = exhaust_state(res, steam_only, 500.0)
    assert state["O2_dry_mole_fraction"] is None  # no dry gas: undefined, said so
    assert "no dry gas" in state["O2_dry_note"]


def test_an_inert_bed_hotter_than_its_gas_wall_and_feed_is_a_failed_solve():
    """Without reactions the bed is checked both ways (here: Tscheng A16, 10 cells)."""
    kiln, _ = kiln_from_case(
        parse_case(yaml.safe_load(builtin_case_path("tscheng_A16").read_text()))
    )
    res = KilnResidual(kiln, 10)
    tg = np.full(res.n + 1, 500.0)
    wall = np.full((res.n, res.n_wall), 450.0)
    tb = np.full(res.n + 1, 400.0)
    solve_module._check_within_partners(res, tb, tg, wall, 0)
    tb[4] = 700.0
    with pytest.raises(ConvergenceError, match=r"T_bed reaches 700 K at z = .*hotter.*\(500 K\)"):
        solve_module._check_within_partners(res, tb, tg, wall, 0)
    tb[4] = 200.0  # below the feed (298 K) and everything else
    with pytest.raises(ConvergenceError, match=r"T_bed reaches 200 K.*colder"):
        solve_module._check_within_partners(res, tb, tg, wall, 0)
