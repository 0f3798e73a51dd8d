"""Air ingress at the feed end (burner.air_ingress, issue 10): it dilutes the exhaust of a
counter-current kiln outside the gas balance, and joins the burner's air in a co-current one."""

from __future__ import annotations

import cantera as ct
import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln

INGRESS = {"flow": "10 L/s", "temperature": "80 degC"}  # normal litres (the case's 0 degC)


def _solve(ingress=None, counter_current=True, n=40, **burner):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    data["operation"]["counter_current"] = counter_current
    if ingress is not None:
        data["burner"]["air_ingress"] = ingress
    data["burner"].update(burner)
    kiln, _ = kiln_from_case(parse_case(data))
    return solve_kiln(kiln, n)


@pytest.fixture(scope="module")
def counter():
    return _solve(), _solve(INGRESS)


def test_counter_current_ingress_leaves_the_kiln_profiles_alone(counter):
    plain, leaky = counter
    np.testing.assert_array_equal(plain.t_gas_nodes, leaky.t_gas_nodes)
    np.testing.assert_array_equal(plain.t_bed_nodes, leaky.t_bed_nodes)
    assert plain.exhaust["temperature_K"] == plain.gas_outlet_temperature
    assert plain.exhaust["air_ingress_kg_s"] == 0.0


def test_exhaust_after_ingress_matches_an_adiabatic_mixing_in_cantera(counter):
    # independent check: mix the outlet gas with the air in Cantera (GRI-Mech 3.0 thermo)
    _, leaky = counter
    n_air = 101325.0 * 10e-3 / (8.314462618 * 273.15)  # 10 NL/s (0 degC, 1 atm), mol/s
    air_flow = n_air * (0.2095 * 0.031998 + 0.7808 * 0.0280134 + 0.0097 * 0.039948)  # dry air
    # 1e-4: the atomic masses above are rounded differently from Cantera's
    assert leaky.exhaust["air_ingress_kg_s"] == pytest.approx(air_flow, rel=1e-4)
    air_flow = leaky.exhaust["air_ingress_kg_s"]
    out = {s: float(q[0]) for s, q in leaky.gas_flows.items() if q[0] > 0}
    m_air = {"O2": 0.2095 * 0.031998, "N2": 0.7808 * 0.0280134, "AR": 0.0097 * 0.039948}
    air = {s: air_flow * m / sum(m_air.values()) for s, m in m_air.items()}
    total = {s: out.get(s, 0.0) + air.get(s, 0.0) for s in set(out) | set(air)}
    gas = ct.Solution("gri30.yaml")

    def enthalpy(T, flows):  # W, absolute enthalpy flow of a stream (GRI-Mech 3.0)
        gas.TPY = T, 101325.0, flows
        return gas.enthalpy_mass * sum(flows.values())

    h = enthalpy(leaky.gas_outlet_temperature, out) + enthalpy(353.15, air)
    mix = ct.Solution("gri30.yaml")
    mix.HPY = h / sum(total.values()), 101325.0, total
    # 0.05 K: the kiln's gas tables are fits to the same thermo
    assert leaky.exhaust["temperature_K"] == pytest.approx(mix.T, abs=0.05)
    assert leaky.exhaust["flow_kg_s"] == pytest.approx(sum(total.values()), rel=1e-9)
    x = dict(zip(mix.species_names, mix.X, strict=True))
    o2_dry = x["O2"] / (1.0 - x["H2O"])
    # 1e-5: the species table's molar masses against Cantera's
    assert leaky.exhaust["O2_dry_mole_fraction"] == pytest.approx(o2_dry, rel=1e-5)
    assert leaky.exhaust["O2_dry_mole_fraction"] > counter[0].exhaust["O2_dry_mole_fraction"]


def test_energy_sheet_counts_the_ingress_and_closes(counter):
    plain, leaky = counter
    s0, s1 = plain.energy_sheet, leaky.energy_sheet
    assert s1["sensible_input_air_ingress_W"] > 0
    # the exhaust carries the ingress air's enthalpy; nothing else changes
    assert s1["exhaust_loss_W"] - s0["exhaust_loss_W"] == pytest.approx(
        s1["sensible_input_air_ingress_W"], rel=1e-9
    )
    assert abs(s1["closure_relative"]) < 1e-9
    assert leaky.thermal_efficiency == pytest.approx(plain.thermal_efficiency, rel=1e-12)
    assert leaky.summary()["exhaust_temperature_K"] < leaky.gas_outlet_temperature


def test_co_current_ingress_is_burner_air():
    # at the same temperature, an ingress at the (feed-end) burner is secondary air
    same_t = {"flow": "10 L/s", "temperature": "298.15 K"}
    leaky = _solve(same_t, counter_current=False)
    more_air = _solve(counter_current=False, secondary_air={"flow": "53.0 L/s"})
    np.testing.assert_allclose(leaky.t_gas_nodes, more_air.t_gas_nodes, rtol=0, atol=1e-6)
    assert leaky.burner["excess_air"] == pytest.approx(more_air.burner["excess_air"])
    assert leaky.exhaust["air_ingress_kg_s"] == 0.0  # it went through the kiln


@pytest.mark.parametrize(
    ("ingress", "match"),
    [
        ({"flow": "-2 L/s"}, "air_ingress.flow.*negative"),
        ({"flow": "2 L/s", "temperature": "-1 K"}, "air_ingress.temperature"),
        ({"flow": "lots"}, "air_ingress.flow"),
    ],
)
def test_bad_ingress_refused_at_load(ingress, match):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    data["burner"]["air_ingress"] = ingress
    with pytest.raises(InputError, match=match) as exc:
        parse_case(data)
    assert "\n" not in str(exc.value)


def test_ingress_volume_flow_needs_a_reference_state():
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    data["burner"].pop("reference_temperature")
    data["burner"]["fuel_flow"] = "1.97 NL/s"
    for air in ("primary_air", "secondary_air"):
        data["burner"][air]["flow"] = data["burner"][air]["flow"].replace("L/s", "NL/s")
    data["burner"]["air_ingress"] = {"flow": "5 L/s"}
    with pytest.raises(InputError, match="air_ingress.flow.*unstated temperature"):
        parse_case(data)
