"""Burner air streams of any composition: O2-enriched air, pure oxygen (issue 26, "any
oxidiser"). Checked against complete-combustion stoichiometry by hand, the air ratio by its
definition (O2 supplied over O2 needed) and the kiln's balances."""

from __future__ import annotations

import warnings

import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.kiln.combustion.flame import AirStream, Burner, fire, mixed_oxidiser
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.materials.gas import AIR, burn_fuel, parse_composition

M_CH4, M_O2, M_N2 = 0.016043, 0.031998, 0.0280134  # kg/mol


def test_enriched_air_burns_to_the_products_of_its_stoichiometry():
    # 1 mol/s CH4 with 30 % O2 enriched air at an air ratio of 1.2, by hand: CH4 + 2.4 O2 +
    # 5.6 N2 -> CO2 + 2 H2O + 0.4 O2 + 5.6 N2 (9 mol)
    oxidiser = "O2:0.3, N2:0.7"
    n_ox = 2.4 / 0.3
    air_flow = n_ox * (0.3 * M_O2 + 0.7 * M_N2)
    b = burn_fuel("CH4:1", M_CH4, air_flow, air=oxidiser)
    assert b.table.x_co2 == pytest.approx(1 / 9, rel=2e-3)  # Cantera's NO and OH traces
    assert b.table.x_h2o == pytest.approx(2 / 9, rel=2e-3)
    assert b.heat_release / M_CH4 == pytest.approx(50.0e6, rel=0.005)  # the LHV of CH4
    # less nitrogen to heat: hotter than the same fuel with air at the same air ratio
    with_air = burn_fuel("CH4:1", M_CH4, 2.4 / 0.2095 * 0.028964, air=AIR)
    assert b.adiabatic_temperature > with_air.adiabatic_temperature + 200.0


def test_the_air_ratio_counts_the_oxygen_supplied():
    # 1 mol/s CH4 needs 2 mol/s O2: 2.2 mol/s of pure O2 is an air ratio of 1.1
    burner = Burner("CH4:1", M_CH4, AirStream(2.2 * M_O2, 298.15, "O2:1"))
    flame = fire(burner, 0.4)
    assert flame.excess_air == pytest.approx(0.1, rel=1e-9)
    # the same O2 as air: the same air ratio
    air = AirStream(2.2 / 0.2095 * AirStream(1.0).molar_mass)
    assert fire(Burner("CH4:1", M_CH4, air), 0.4).excess_air == pytest.approx(0.1, rel=1e-9)


def test_streams_of_air_mix_to_air_and_others_by_moles():
    assert mixed_oxidiser((AirStream(1.0), AirStream(2.0, 400.0))) == AIR
    o2 = AirStream(M_O2, 298.15, "O2:1")  # 1 mol/s
    n2 = AirStream(M_N2, 298.15, "N2:1, O2:0")  # 1 mol/s, no O2 (a diluent)
    mixed = dict(parse_composition(mixed_oxidiser((o2, n2))))
    assert mixed["O2"] == pytest.approx(0.5, rel=1e-4)  # molar masses rounded above
    assert mixed["N2"] == pytest.approx(0.5, rel=1e-4)


def _barr_t4(primary_composition=None, primary_flow=None):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    if primary_composition is not None:
        data["burner"]["primary_air"]["composition"] = primary_composition
    if primary_flow is not None:
        data["burner"]["primary_air"]["flow"] = primary_flow
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return data, kiln_from_case(parse_case(data))[0]


def test_a_kiln_fired_with_enriched_primary_air_runs_and_closes():
    data, air = _barr_t4()
    primary = float(str(data["burner"]["primary_air"]["flow"]).split()[0])  # NL/s of air
    # the primary air's O2 (20.95 %) brought as 30 % enriched air: the same O2, less N2 to
    # heat, so the same air ratio and a hotter gas
    flow = f"{primary * 0.2095 / 0.3:.6g} NL/s"
    _, enriched = _barr_t4("O2:0.3, N2:0.7", flow)
    fl_a, fl_e = air.firing.flame, enriched.firing.flame
    assert fl_e.excess_air == pytest.approx(fl_a.excess_air, rel=1e-3)
    assert enriched.gas.temperature > air.gas.temperature + 10.0
    assert enriched.gas.total < air.gas.total
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sol = solve_kiln(enriched, 60)
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8


def test_an_air_stream_without_oxygen_is_refused_with_its_field():
    data, _ = _barr_t4()
    data["burner"]["primary_air"]["composition"] = "N2:1"
    with pytest.raises(InputError, match=r"burner\.primary_air\.composition.*no O2"):
        parse_case(data)


def test_a_normal_flow_of_oxygen_is_converted_with_its_molar_mass():
    data, _ = _barr_t4()
    data["burner"]["secondary_air"] = {"flow": "22.414 NL/s", "composition": "O2:1"}
    section = parse_case(data).burner
    _, _, secondary = section.mass_flows()
    # 22.414 NL at 0 degC and 1 atm is 0.99998 mol (R = 8.314462618 J/(mol K))
    n = 101325.0 * 22.414e-3 / (8.314462618 * 273.15)
    assert secondary == pytest.approx(n * M_O2, rel=1e-4)
