"""The lime product and fuel balance of a solved kiln (rotarykiln.kiln.results.product_balance).

Synthetic solutions with hand-computed numbers (a limestone partly burnt, a dolomite
half-burnt, a kiln without burner or lining), then the fired limestone case, where the CO2 the
stone released must be the CO2 the gas gained beyond the burner's.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.lime import lime_calcination_mass_balance
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.results.product_balance import lime_kiln_balance

# IUPAC molar masses (g/mol): CaCO3 100.086, CaO 56.077, CO2 44.009
W_CC = 44.009 / 100.086  # CO2 in calcite, 0.43971
Y_CAO = 56.077 / 100.086  # CaO per CaCO3, 0.56029


def _solution(bed, *, lhv=None, shell=None, exhaust=None, counter_current=True):
    return SimpleNamespace(
        bed_flows={s: np.asarray(v, dtype=float) for s, v in bed.items()},
        t_bed_nodes=np.array([298.15, 900.0, 1450.0, 1380.0]),
        t_gas_nodes=np.array([1150.0, 1500.0, 2000.0, 600.0]),
        burner={} if lhv is None else {"fuel_lhv_input_W": lhv},
        exhaust=exhaust or {},
        t_shell=None if shell is None else np.asarray(shell, dtype=float),
        counter_current=counter_current,
    )


def test_a_partly_burnt_limestone_by_hand():
    # 2 kg/s of stone, 95 % CaCO3 + 5 % inert, 2 % of the CaCO3 left: 1.9 kg/s CaCO3 in,
    # 0.038 out, 1.862 kg/s decomposed -> 1.862 x 0.56029 = 1.04326 kg/s CaO
    caco3_out = 0.02 * 1.9
    cao = (1.9 - caco3_out) * Y_CAO
    sol = _solution(
        {
            "CaCO3": [1.9, 1.9, 0.5, caco3_out],
            "CaO": [0.0, 0.0, 0.8, cao],
            "inert": [0.1, 0.1, 0.1, 0.1],
        },
        lhv=7.0e6,
        shell=[420.0, 600.0, 550.0],
    )
    b = lime_kiln_balance(sol)
    product = caco3_out + cao + 0.1  # 1.18126 kg/s
    assert b["product_flow_kg_s"] == pytest.approx(1.18126, abs=1e-5)
    assert b["product_flow_kg_s"] == pytest.approx(product, rel=1e-12)
    assert b["CaO_mass_fraction"] == pytest.approx(cao / product, rel=1e-12)
    assert b["CaCO3_mass_fraction"] == pytest.approx(caco3_out / product, rel=1e-12)
    # residual CO2 = 0.038 x 0.43971 / 1.18126 = 1.4145 %; no water: LOI = residual CO2
    assert b["residual_CO2_mass_fraction"] == pytest.approx(0.014145, abs=2e-6)
    assert b["loss_on_ignition"] == b["residual_CO2_mass_fraction"]
    assert b["conversion_CaCO3"] == pytest.approx(0.98, rel=1e-12)
    assert b["CO2_released_kg_s"] == pytest.approx(1.862 * W_CC, rel=1e-4)  # 0.81874 kg/s
    assert b["CO2_released_per_feed"] == pytest.approx(1.862 * W_CC / 2.0, rel=1e-4)
    # 7 MW over 1.18126 kg/s: 5.926 MJ/kg of product
    assert b["specific_heat_consumption_J_kg"] == pytest.approx(5.9259e6, rel=1e-4)
    assert b["fuel_lhv_input_W"] == 7.0e6
    # temperatures: counter-current exhaust at z = 0, bed at the discharge and its maximum
    assert b["exhaust_temperature_K"] == 1150.0
    assert b["bed_outlet_temperature_K"] == 1380.0
    assert b["bed_max_temperature_K"] == 1450.0
    assert b["shell_max_temperature_K"] == 600.0
    # the same product as lime.py's mass balance of the stone (per kg of stone, x 2 kg/s)
    ref = lime_calcination_mass_balance(0.95, 0.0, 0.05, conversion_ca=0.98)
    assert b["product_flow_kg_s"] == pytest.approx(2.0 * ref["yield"], rel=2e-5)
    assert b["residual_CO2_mass_fraction"] == pytest.approx(ref["residual_CO2"], rel=2e-5)
    assert b["CO2_released_per_feed"] == pytest.approx(ref["CO2_released"], rel=2e-5)


def test_a_half_burnt_dolomite_counts_the_carbonate_co2_it_lost():
    # 1 kg/s dolomite (CO2 0.47732), out: 0.2 dolomite, 0.3 CaCO3 made in the kiln, MgO, CaO;
    # the CO2 released is the carbonate CO2 in minus out, wherever the carbonate was made
    w_dol, w_cc = 2 * 44.009 / 184.399, W_CC
    bed = {
        "dolomite": [1.0, 0.8, 0.5, 0.2],
        "CaCO3": [0.0, 0.1, 0.2, 0.3],
        "MgO": [0.0, 0.05, 0.1, 0.17],
        "CaO": [0.0, 0.0, 0.05, 0.07],
        "H2O(l)": [0.02, 0.0, 0.0, 0.001],
    }
    b = lime_kiln_balance(_solution(bed))
    product = 0.2 + 0.3 + 0.17 + 0.07 + 0.001
    left = 0.2 * w_dol + 0.3 * w_cc
    assert b["product_flow_kg_s"] == pytest.approx(product, rel=1e-12)
    assert b["CO2_released_kg_s"] == pytest.approx(1.0 * w_dol - left, rel=1e-4)
    assert b["residual_CO2_mass_fraction"] == pytest.approx(left / product, rel=1e-4)
    # the water left in the bed is part of the loss on ignition
    assert b["loss_on_ignition"] == pytest.approx(left / product + 0.001 / product, rel=1e-4)
    assert math.isnan(b["conversion_CaCO3"])  # no CaCO3 fed
    # no burner: no specific heat consumption; no lining: no shell temperature
    assert math.isnan(b["fuel_lhv_input_W"])
    assert math.isnan(b["specific_heat_consumption_J_kg"])
    assert math.isnan(b["shell_max_temperature_K"])


def test_exhaust_after_an_air_ingress_and_a_co_current_outlet():
    bed = {"CaCO3": [1.0, 0.5, 0.2, 0.0], "CaO": [0.0, 0.28, 0.45, 0.56]}
    mixed = lime_kiln_balance(_solution(bed, exhaust={"temperature_K": 1010.0}))
    assert mixed["exhaust_temperature_K"] == 1010.0  # the exhaust after the leak has mixed in
    co = lime_kiln_balance(_solution(bed, counter_current=False))
    assert co["exhaust_temperature_K"] == 600.0  # co-current: the gas leaves at z = L


@pytest.mark.filterwarnings("ignore::rotarykiln.errors.OutOfRangeWarning")  # its header's Gorog
def test_the_fired_limestone_kiln_releases_its_co2_into_the_gas():
    case = load_case(builtin_case_path("limestone_fired"))
    kiln, _ = kiln_from_case(case)
    sol = run_kiln_case(case)
    b = lime_kiln_balance(sol)
    gained = float(sol.gas_flows["CO2"][0] - kiln.gas.flows["CO2"])  # counter-current: z = 0
    assert b["CO2_released_kg_s"] == pytest.approx(gained, rel=1e-8)
    assert b["product_flow_kg_s"] == pytest.approx(sol.summary()["solids_outlet_flow_kg_s"])
    assert b["specific_heat_consumption_J_kg"] == pytest.approx(
        sol.energy_sheet["fuel_lhv_input_W"] / b["product_flow_kg_s"], rel=1e-12
    )
    assert b["loss_on_ignition"] < 1e-6  # the case calcines fully
    assert b["bed_max_temperature_K"] == pytest.approx(sol.summary()["bed_max_temperature_K"])
