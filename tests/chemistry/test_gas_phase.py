"""Gas-phase (freeboard) reactions: kinetics against the reference note, YAML checks, kiln balances."""

from __future__ import annotations

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.gas_phase import R_GAS, gas_arrhenius_rate, shift_equilibrium_constant
from rotarykiln.chemistry.reaction import builtin_reactions, reaction_from_dict
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.errors import InputError

P = 101325.0


def _tau(name, T, x):
    """Time constant c_basis / r (s) of a built-in gas reaction at mole fractions ``x``."""
    r = builtin_reactions()[name]
    c = {k: v * P / (R_GAS * T) for k, v in x.items()}
    p = r.params
    rate = gas_arrhenius_rate(np.array([T]), c, p["A"], p["b"], p["E"], p["orders"], p["c_floor"])
    return float(c[r.basis] / rate[0])


@pytest.mark.parametrize(
    ("T", "tau"), [(800.0, 4.9), (900.0, 0.33), (1000.0, 0.04), (1200.0, 1.5e-3)]
)
def test_co_oxidation_time_scales_of_the_reference_note(T, tau):
    # flames.md section 3 (Cantera-free computation of the same Westbrook-Dryer rate)
    got = _tau("co_oxidation_westbrook_dryer", T, {"CO": 0.01, "O2": 0.1, "H2O": 0.1})
    assert got == pytest.approx(tau, rel=0.12)


@pytest.mark.parametrize(("T", "tau"), [(1000.0, 15.0), (1200.0, 0.26)])
def test_methane_time_scales_of_the_reference_note(T, tau):
    got = _tau("ch4_oxidation_westbrook_dryer", T, {"CH4": 0.01, "O2": 0.1})
    assert got == pytest.approx(tau, rel=0.12)


def test_shift_equilibrium_constant_against_cantera():
    import cantera as ct

    g = ct.Solution("gri30.yaml")
    for T in (800.0, 1100.0, 1400.0):
        mu = {}
        for s in ("CO", "H2O", "CO2", "H2"):
            g.TPX = T, ct.one_atm, f"{s}:1"
            mu[s] = g.gibbs_mole  # J/kmol, pure species at 1 atm
        dg = mu["CO2"] + mu["H2"] - mu["CO"] - mu["H2O"]
        k_cantera = np.exp(-dg / (ct.gas_constant * T))
        # the table is interpolated in ln K every 10 K
        assert float(shift_equilibrium_constant(T)) == pytest.approx(k_cantera, rel=1e-3)


def test_heats_are_the_standard_heats_of_formation():
    for name in ("co_oxidation_westbrook_dryer", "ch4_oxidation_westbrook_dryer"):
        r = builtin_reactions()[name]
        assert r.phase == "gas"
        assert r.heat == pytest.approx(r.standard_heat(), rel=1e-4)


def test_negative_order_rate_vanishes_with_the_species():
    r = gas_arrhenius_rate(
        np.array([1200.0, 1200.0]),
        {"CH4": np.array([0.0, 1e-3]), "O2": np.array([1.0, 1.0])},
        1.3e8,
        0.0,
        202870.0,
        {"CH4": -0.3, "O2": 1.3},
    )
    assert r[0] == 0.0 and np.isfinite(r[1]) and r[1] > 0


@pytest.mark.parametrize(
    ("change", "match"),
    [
        ({"stoichiometry": {"CO": -2, "C": 1, "CO2": 1}}, "stoichiometry.C.*a gas species"),
        ({"heat": {"value": "-283 kJ/mol", "T_ref": 500}}, "heat.T_ref.*298.15"),
        ({"phase": "liquid"}, "phase.*bed or gas"),
    ],
)
def test_gas_reaction_yaml_refused(change, match):
    data = {
        "name": "co_burn",
        "phase": "gas",
        "stoichiometry": {"CO": -1, "O2": -0.5, "CO2": 1},
        "basis": "CO",
        "rate": {"law": "gas_arrhenius", "A": 1e10, "E": 1.6e5, "orders": {"CO": 1, "O2": 0.25}},
        "heat": "-283 kJ/mol",
    }
    data.update(change)
    with pytest.raises(InputError, match=match):
        reaction_from_dict(data)


def test_co_in_the_kiln_gas_burns_in_the_freeboard_with_closed_balances():
    d = yaml.safe_load(builtin_case_path("limestone_calcination").read_text())
    ch = d["chemistry"]
    d["gas"]["mass_fractions"] = {"N2": 0.70, "CO2": 0.12, "H2O": 0.10, "O2": 0.05, "CO": 0.03}
    base = run_kiln_case(parse_case(d))
    ch["reactions"] = ch["reactions"] + [
        "co_oxidation_westbrook_dryer",
        "water_gas_shift_jones_lindstedt",
        "water_gas_shift_reverse",
    ]
    sol = run_kiln_case(parse_case(d))
    s = sol.summary()
    assert abs(s["energy_balance_closure"]) < 1e-6
    assert abs(s["element_balance_closure"]) < 1e-8
    co_in = sol.gas_flows["CO"][-1]
    assert co_in > 0 and sol.gas_flows["CO"][0] < 1e-6 * co_in  # burnt out in excess O2
    # the heat of combustion appears in the gas: hotter than without the reaction, but never
    # above the adiabatic temperature of the inlet gas burning its CO (about +260 K)
    assert s["gas_max_temperature_K"] > base.summary()["gas_max_temperature_K"] + 100.0
    assert s["gas_max_temperature_K"] < 1800.0 + 300.0
