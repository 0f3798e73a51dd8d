"""Axial dispersion of the bed inside the balances (kiln/bed/dispersion.py; issue 11 item 4)."""

from __future__ import annotations

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln


def _limestone():
    kiln, _ = kiln_from_case(load_case(builtin_case_path("limestone_fired")))
    return kiln


def test_zero_dispersion_is_plug_flow_exactly():
    kiln = _limestone()
    a = solve_kiln(kiln)
    b = solve_kiln(kiln.replace(bed__dispersion=0.0))
    assert np.array_equal(a.t_bed_nodes, b.t_bed_nodes)


@pytest.mark.parametrize("peclet", [200.0, 20.0])
def test_dispersion_conserves_mass_elements_and_energy(peclet):
    kiln = _limestone()
    D = kiln.bed.velocity * kiln.drum.length / peclet
    sol = solve_kiln(kiln.replace(bed__dispersion=D))
    s = sol.summary()
    assert abs(s["energy_balance_closure"]) < 1e-6
    assert s["element_balance_closure"] < 1e-8
    assert s["conversion_CaCO3"] > 0.99


def test_dispersion_smooths_the_bed_and_converges_with_the_mesh():
    kiln = _limestone()
    plug = solve_kiln(kiln)
    D = kiln.bed.velocity * kiln.drum.length / 20.0  # strong mixing, Pe = 20
    mixed = solve_kiln(kiln.replace(bed__dispersion=D))
    # back-mixing carries heat upstream: the bed just inside the feed end jumps above the feed
    # temperature (Danckwerts), the feed end is warmer, and inside the kiln the profile is
    # smoother than in plug flow
    assert mixed.t_bed_nodes[1] - mixed.t_bed_nodes[0] > plug.t_bed_nodes[1] - 298.15
    assert mixed.t_bed_nodes[5] > plug.t_bed_nodes[5]
    assert np.max(np.diff(mixed.t_bed_nodes[1:])) < np.max(np.diff(plug.t_bed_nodes[1:]))
    fine = solve_kiln(kiln.replace(bed__dispersion=D), 200)
    assert np.max(np.abs(mixed.t_bed_nodes - fine.t_bed_nodes[::2])) < 10.0


def test_inert_bed_with_dispersion_closes():
    kiln, _ = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    sol = solve_kiln(kiln.replace(bed__dispersion=1e-5))
    assert abs(sol.energy_closure) < 1e-6


def test_case_key_of_the_reacting_kiln():
    import yaml

    from rotarykiln.case import parse_case
    from rotarykiln.commands.kiln_runs import run_kiln_case

    d = yaml.safe_load(builtin_case_path("limestone_calcination").read_text())
    kiln, _ = kiln_from_case(parse_case(d))
    assert kiln.bed.dispersion == 0.0  # seed 004: plug flow by default
    d["bed"]["axial_dispersion"] = 20
    case = parse_case(d)
    kiln, _ = kiln_from_case(case)
    assert kiln.bed.dispersion == pytest.approx(kiln.bed.velocity * kiln.drum.length / 20)
    s = run_kiln_case(case).summary()
    assert abs(s["energy_balance_closure"]) < 1e-6 and s["element_balance_closure"] < 1e-8


def _tracer_cdf(kiln, n, pulse=30.0):
    """F(t) of a short tracer pulse through the transient kiln (kiln/transient/integrate.py): the
    cumulative outlet tracer over the injected mass, at the output times."""
    from rotarykiln.kiln.transient.integrate import simulate
    from rotarykiln.transient_file import parse_transient

    until = 2.5 * kiln.residence_time
    wall = {
        "layers": [
            {"density": "1300 kg/m3", "specific_heat": "1000 J/kg/K"},
            {"density": "7850 kg/m3", "specific_heat": "490 J/kg/K"},
        ]
    }
    spec = {"wall": wall, "tracer": {"duration": f"{pulse} s"}, "output_every": "30 s"}
    sol = simulate(kiln, n, parse_transient(spec, kiln, until), until)
    c = np.array([o["tracer_outlet_kg_s"] for o in sol.outlet])
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (c[1:] + c[:-1]) * np.diff(sol.t))])
    return sol.t - 0.5 * pulse, cum / sol.tracer_mass


@pytest.mark.parametrize("peclet", [8.0, 40.0])
def test_tracer_through_the_dispersed_bed_follows_the_dispersion_model(peclet):
    """A tracer pulse through the dispersed (inert) bed gives the F(t) of the closed-closed
    dispersion model of rotarykiln.rtd (the bed's ends are closed, Danckwerts) to 1 %, with the
    dispersion of the balances plus that of the cell scheme (each cell a stirred tank: u dz / 2)."""
    from rotarykiln.rtd.dispersion import closed_closed_cdf

    barr, _ = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    u, L = barr.bed.velocity, barr.drum.length
    n = 200
    kiln = barr.replace(bed__dispersion=u * L / peclet)
    t, F = _tracer_cdf(kiln, n)
    pe_eff = u * L / (u * L / peclet + u * (L / n) / 2.0)
    model = closed_closed_cdf(np.maximum(t, 1e-9), kiln.residence_time, pe_eff)
    assert np.max(np.abs(F - model)) < 0.01


def test_as_the_peclet_number_grows_the_tracer_tends_to_plug_flow():
    barr, _ = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    u, L = barr.bed.velocity, barr.drum.length
    spreads = []
    for pe in (4.0, 40.0, 4000.0):
        t, F = _tracer_cdf(barr.replace(bed__dispersion=u * L / pe), 100)
        tau = barr.residence_time
        spreads.append(np.interp(0.9, F, t) - np.interp(0.1, F, t))  # 10-90 % spread
    assert spreads[0] > spreads[1] > spreads[2]
    assert np.interp(0.5, F, t) == pytest.approx(tau, rel=0.02)  # the median at Pe 4000
    # the limit is the scheme's own plug flow, 100 stirred tanks: 10-90 % over ~0.26 tau
    assert spreads[2] < 0.3 * barr.residence_time
