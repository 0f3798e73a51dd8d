"""The fired limestone kiln: a burner feeding the reacting kiln (issue 10, item 8)."""

from __future__ import annotations

import pytest
import yaml

from rotarykiln.case import load_case, parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.species import default_species
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case

SP = default_species()
M_CO2, M_CACO3 = SP["CO2"].molar_mass, SP["CaCO3"].molar_mass


@pytest.fixture(scope="module")
def solution():
    return run_kiln_case(load_case(builtin_case_path("limestone_fired")))


def test_calcines_fully_and_its_co2_leaves_with_the_flue_gas(solution):
    case = load_case(builtin_case_path("limestone_fired"))
    kiln, _ = kiln_from_case(case)
    feed_caco3 = case.operation.feed
    co2_in = kiln.gas.flows["CO2"]
    assert solution.summary()["conversion_CaCO3"] == pytest.approx(1.0, abs=1e-6)
    co2_out = solution.summary()
    frame = solution.to_frame()
    co2_exhaust = float(frame["gas_CO2_kg_s"].iloc[0])  # counter-current: gas leaves at z = 0
    assert co2_exhaust - co2_in == pytest.approx(feed_caco3 * M_CO2 / M_CACO3, rel=1e-6)
    assert abs(co2_out["energy_balance_closure"]) < 1e-6
    assert abs(co2_out["element_balance_closure"]) < 1e-8


def test_energy_sheet_of_the_fired_limestone_kiln(solution):
    s = solution.summary()
    # 12 Nm3/h of natural gas: about 125 kW LHV; the sheet closes and splits the heat to the
    # solids into sensible heat and the heat of calcination
    assert 1.1e5 < s["energy_fuel_lhv_input_W"] < 1.4e5
    assert s["energy_fuel_hhv_input_W"] > s["energy_fuel_lhv_input_W"]
    assert abs(s["energy_closure_relative"]) < 1e-6
    assert s["energy_heat_to_solids_reaction_W"] > 0.1 * s["energy_heat_to_solids_sensible_W"]
    assert 0 < s["thermal_efficiency"] < 1
    assert s["burner_adiabatic_temperature_K"] == pytest.approx(solution.t_gas_nodes[-1], abs=1e-6)


def test_burner_gas_enters_at_the_adiabatic_temperature():
    kiln, _ = kiln_from_case(load_case(builtin_case_path("limestone_fired")))
    assert 1800.0 < kiln.gas.temperature < 1950.0  # natural gas, 40 % excess air
    assert set(kiln.gas.flows) <= {"N2", "O2", "CO2", "H2O", "CO", "H2", "CH4", "AR"}


def test_burner_and_gas_inlet_together_refused():
    data = yaml.safe_load(builtin_case_path("limestone_fired").read_text())
    data["gas"]["temperature"] = "1800 K"
    with pytest.raises(InputError, match="gas.flow.*burner"):
        kiln_from_case(parse_case(data))


def test_co_current_variant_converges_and_closes():
    data = yaml.safe_load(builtin_case_path("limestone_fired").read_text())
    data["operation"]["counter_current"] = False
    sol = run_kiln_case(parse_case(data))
    s = sol.summary()
    assert abs(s["energy_balance_closure"]) < 1e-6
    assert abs(s["element_balance_closure"]) < 1e-8
    # gas enters with the solids at z = 0 and leaves at the discharge, cooler than it came in
    assert sol.t_gas_nodes[0] > sol.t_gas_nodes[-1]
    assert sol.gas_outlet_temperature == sol.t_gas_nodes[-1]
    assert s["conversion_CaCO3"] > 0.5


def test_co_current_inert_reacting_equals_heat_model_direction():
    # the counter-current solution is unchanged by the co-current code path
    a = run_kiln_case(load_case(builtin_case_path("limestone_fired")))
    assert a.gas_outlet_temperature == a.t_gas_nodes[0]


def test_limestone_summary_speaks_of_mass_loss_not_burn_off(solution):
    s = solution.summary()
    assert "burn_off_percent" not in s and "production_percent" not in s
    # CaCO3 -> CaO: 44 % of the dry feed leaves as CO2
    assert s["dry_mass_loss_percent"] == pytest.approx(100 * (1 - 56.077 / 100.087), abs=0.1)
    assert s["dry_mass_loss_percent"] + s["solids_yield_percent"] == pytest.approx(100.0)
