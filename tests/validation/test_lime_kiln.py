"""The built-in long rotary lime kiln (``lime_kiln``) against what its sources say.

The case is the example kiln of the reference note cement_lime.md 6.2 (60 m x 3 m, 1 rpm,
about 2 h, counter-current, burner at the discharge), fed with a derived 20.07 t/h of limestone
(97 % CaCO3, 3 % inert) and fired with coal (Pittsburgh No. 8, burnt by its particles along the
kiln) at 6.0 GJ per tonne of ash-free lime. Every input, its source and every assumption
are in the header of ``src/rotarykiln/cases/lime_kiln.yaml``, written before the first run;
nothing was tuned to the quantities below. One solve (module fixture), then:

- its own balances: elements <= 1e-8 (relative), energy <= 1e-6 (relative);
- the case is what its header says (firing 6.0 GJ/t at the 1 % LOI product, 10 % excess air);
- the quantities a lime engineer reads (:func:`rotarykiln.kiln.results.product_balance.\
lime_kiln_balance`) against the ranges of the sources (keys of cement_lime.md section 8):

==========================================  ======================  ==========================
quantity (model)                            range                   source
==========================================  ======================  ==========================
specific heat consumption, fuel LHV per     6-9.2 GJ/t              BREF CLM 2013, long rotary
kg of product                                                       kilns [MEMORY, moderate]
residual CO2 (LOI) of the product           0.5-1 %                 [SEEN: MCD]
bed temperature at the discharge            1200 degC +- 100 K      [SEEN: MCD]
gas leaving at the feed end (exhaust)       1000 degC +- 100 K      [SEEN: MCD]
bed between 1 % and 99 % conversion         900-1200 degC           [SEEN: LRK]
hottest bed anywhere                        <= 1200 degC + 100 K    [SEEN: LRK], dead burning
                                                                    above it [SEEN: LIMEW]
hottest shell                               < 350 degC              [SEEN: WIKIRK]
==========================================  ======================  ==========================

The source (MCD) gives "1200 degC at the discharge end to 1000 degC at the feed end" without
saying whether gas or material: at the discharge the material is compared (what leaves the kiln
as product), at the feed end the gas (the stone enters cold, so only the gas can be at
1000 degC there). Its numbers are rounded to the hundred and not given with an uncertainty; the
tolerance, +-100 K, is half of the 200 K the source puts between its two ends: a model value
outside it would be nearer the other end's number. The specific heat consumption is set by the
firing (an input): its check shows the firing basis is consistent with the BREF, not that the
model predicts it.

The ranges the case misses are marked ``xfail(strict=True)`` with the measured value: the
discrepancies, not the inputs, are what these tests record (see the reasons and
docs/cement_lime.md).
"""

from __future__ import annotations

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.lime import lime_calcination_mass_balance
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.kiln.results.product_balance import lime_kiln_balance

C = 273.15  # K at 0 degC
MCD_TOLERANCE = 100.0  # K, see the module docstring


@pytest.fixture(scope="module")
def solution():
    return run_kiln_case(load_case(builtin_case_path("lime_kiln")))


@pytest.fixture(scope="module")
def balance(solution):
    return lime_kiln_balance(solution)


def test_the_solution_closes_its_balances(solution):
    assert max(solution.element_closure.values()) <= 1e-8
    assert abs(solution.energy_closure) <= 1e-6
    assert abs(solution.energy_sheet["closure_relative"]) <= 1e-6
    assert all(np.all(q >= 0.0) for q in solution.bed_flows.values())
    assert all(np.all(q >= 0.0) for q in solution.gas_flows.values())


def test_the_case_fires_what_its_header_says(solution):
    # 6.0 GJ per tonne of the product at 1 % LOI: the stone's product at that LOI times the feed
    case = load_case(builtin_case_path("lime_kiln"))
    x = 0.9864186541964807  # conversion at 1 % residual CO2 for 97 % CaCO3 + 3 % inert
    stone = lime_calcination_mass_balance(0.97, 0.0, 0.03, conversion_ca=x)
    assert stone["residual_CO2"] == pytest.approx(0.01, rel=1e-9)
    product = case.operation.feed * stone["yield"]
    assert product == pytest.approx(3.229, abs=1e-3)  # kg/s, as in the header
    # 1940 Nm3/h is 6.0 GJ/t rounded to 10 Nm3/h (0.05 %)
    assert solution.burner["fuel_lhv_input_W"] / product == pytest.approx(6.0e6, rel=2e-3)
    assert solution.burner["excess_air"] == pytest.approx(0.10, abs=0.005)
    assert solution.fill == pytest.approx(0.075, rel=1e-3)  # the 7.5 % volume loading


@pytest.mark.xfail(
    strict=True,
    reason="5.94 GJ/t of product: the coal's ash (0.059 kg/s) joins the 3.20 kg/s of lime, and "
    "the firing was set a priori at the range's lower end, 6.0 GJ per t of ash-free lime",
)
def test_specific_heat_consumption_within_the_bref_range(balance):
    shc = balance["specific_heat_consumption_J_kg"] / 1e6  # GJ/t
    assert 6.0 <= shc <= 9.2, shc


@pytest.mark.xfail(
    strict=True,
    reason="the product is burnt through: residual CO2 about 3e-29 (LOI 0 %), not 0.5-1 % "
    "(MCD): calcination ends 3 m before the discharge, and the lumped rate has no unburnt "
    "core of a 30 mm stone",
)
def test_residual_co2_of_the_product(balance):
    assert 0.005 <= balance["loss_on_ignition"] <= 0.01, balance["loss_on_ignition"]


@pytest.mark.xfail(
    strict=True,
    reason="bed leaves at 1772 K (1499 degC), 299 K above the 1200 degC of MCD: the coal "
    "burns out over the last metres, where the burnt lime passes under the flame",
)
def test_material_temperature_at_the_discharge(solution):
    t = solution.bed_outlet_temperature - C
    assert abs(t - 1200.0) <= MCD_TOLERANCE, t


@pytest.mark.xfail(
    strict=True,
    reason="gas leaves the feed end at 821 K (548 degC), 452 K below the 1000 degC of MCD",
)
def test_gas_temperature_at_the_feed_end(balance):
    t = balance["exhaust_temperature_K"] - C
    assert abs(t - 1000.0) <= MCD_TOLERANCE, t


@pytest.mark.xfail(
    strict=True,
    reason="bed at 804-847 degC from 1 % to 99 % conversion (z 34.7-57.0 m), below the "
    "900-1200 degC of LRK: the rate's driving force takes the freeboard CO2 (0.14-0.24 atm, "
    "Baker equilibrium at about 1060-1080 K), not the CO2 near 1 atm in the bed",
)
def test_material_temperature_in_the_calcining_zone(solution):
    s = solution.summary()
    z1, z99 = s["z_conversion_1pct_CaCO3_m"], s["z_conversion_99pct_CaCO3_m"]
    inside = (solution.z_nodes >= z1) & (solution.z_nodes <= z99)
    t = np.concatenate([solution.bed_temperature_at([z1, z99]), solution.t_bed_nodes[inside]])
    assert 900.0 <= t.min() - C and t.max() - C <= 1200.0, (t.min() - C, t.max() - C)


@pytest.mark.xfail(
    strict=True,
    reason="hottest bed 1920 K (1647 degC) at z = 59.4 m, under the flame, after calcination "
    "has ended: the mixed-cup flame gas reaches 2342 K and the burnt lime has no heat "
    "sink; LRK's lime-kiln material is 900-1200 degC",
)
def test_hottest_material_is_not_dead_burning(balance):
    t = balance["bed_max_temperature_K"] - C
    assert t <= 1200.0 + MCD_TOLERANCE, t


@pytest.mark.xfail(
    strict=True,
    reason="shell up to 647 K (374 degC) at z = 59 m under the 2002 K inner wall of the flame "
    "zone (200 mm brick, k 1.6 W/(m K), no coating), above WIKIRK's 350 degC",
)
def test_shell_temperature_below_350_degC(balance):
    t = balance["shell_max_temperature_K"] - C
    assert t < 350.0, t
