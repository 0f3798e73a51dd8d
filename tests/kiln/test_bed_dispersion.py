"""Axial dispersion of the bed inside the balances (kiln/dispersion.py; issue 11 item 4)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.build import kiln_from_case
from rotarykiln.kiln.solve import solve_kiln
from rotarykiln.kiln.tscheng import tscheng_kiln


def _limestone():
    kiln, _ = kiln_from_case(load_case(builtin_case_path("limestone_fired")))
    return kiln


def test_zero_dispersion_is_plug_flow_exactly():
    kiln = _limestone()
    a = solve_kiln(kiln)
    b = solve_kiln(dataclasses.replace(kiln, bed_dispersion=0.0))
    assert np.array_equal(a.t_bed_nodes, b.t_bed_nodes)


@pytest.mark.parametrize("peclet", [200.0, 20.0])
def test_dispersion_conserves_mass_elements_and_energy(peclet):
    kiln = _limestone()
    D = kiln.bed_velocity * kiln.length / peclet
    sol = solve_kiln(dataclasses.replace(kiln, bed_dispersion=D))
    s = sol.summary()
    assert abs(s["energy_balance_closure"]) < 1e-6
    assert s["element_balance_closure"] < 1e-8
    assert s["conversion_CaCO3"] > 0.99


def test_dispersion_smooths_the_bed_and_converges_with_the_mesh():
    kiln = _limestone()
    plug = solve_kiln(kiln)
    D = kiln.bed_velocity * kiln.length / 20.0  # strong mixing, Pe = 20
    mixed = solve_kiln(dataclasses.replace(kiln, bed_dispersion=D))
    # back-mixing carries heat upstream: the bed just inside the feed end jumps above the feed
    # temperature (Danckwerts), the feed end is warmer, and inside the kiln the profile is
    # smoother than in plug flow
    assert mixed.t_bed_nodes[1] - mixed.t_bed_nodes[0] > plug.t_bed_nodes[1] - 298.15
    assert mixed.t_bed_nodes[5] > plug.t_bed_nodes[5]
    assert np.max(np.diff(mixed.t_bed_nodes[1:])) < np.max(np.diff(plug.t_bed_nodes[1:]))
    fine = solve_kiln(dataclasses.replace(kiln, bed_dispersion=D), 200)
    assert np.max(np.abs(mixed.t_bed_nodes - fine.t_bed_nodes[::2])) < 10.0


def test_inert_bed_with_dispersion_closes():
    kiln = tscheng_kiln("A16")
    sol = solve_kiln(dataclasses.replace(kiln, bed_dispersion=1e-5))
    assert abs(sol.energy_closure) < 1e-6


def test_case_key_of_the_reacting_kiln():
    import yaml

    from rotarykiln.case import parse_case
    from rotarykiln.kiln.run import run_kiln_case

    d = yaml.safe_load(builtin_case_path("limestone_calcination").read_text())
    kiln, _ = kiln_from_case(parse_case(d))
    assert kiln.bed_dispersion == 0.0  # seed 004: plug flow by default
    d["bed"]["axial_dispersion"] = 20
    case = parse_case(d)
    kiln, _ = kiln_from_case(case)
    assert kiln.bed_dispersion == pytest.approx(kiln.bed_velocity * kiln.length / 20)
    s = run_kiln_case(case).summary()
    assert abs(s["energy_balance_closure"]) < 1e-6 and s["element_balance_closure"] < 1e-8
