"""Seed 004 (Ahmad 2006) chapter 4: what the text records about its two reacting kilns.

Seed 004's figures are lost in the OCR; the checks below are the prose statements (notes 004,
section 6) with tolerances that reflect "about"/"near" in the text and the inputs seed 004 does
not give (gas flow, wall loss: calibration knobs, see docs/validation.md). Departures
(the Luisser kinetics start below 900 K) are asserted as documented, not hidden.
"""

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import run_kiln_case


def _data(name):
    return yaml.safe_load(builtin_case_path(name).read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def charcoal():
    return run_kiln_case(parse_case(_data("charcoal_activation")))


@pytest.fixture(scope="module")
def limestone():
    return run_kiln_case(parse_case(_data("limestone_calcination")))


def test_charcoal_onset_near_2p5_m_at_1073_k(charcoal):
    # "the reaction starts at 1073 K, reached at about 2.5 m": the full rate (end of the 10 K
    # ramp) at T_bed = 1073 K; position within 0.4 m of 2.5 m ("about", figure lost)
    z_full = float(np.interp(1073.0, charcoal.t_bed_nodes, charcoal.z_nodes))
    assert 2.1 <= z_full <= 2.9
    z_on, t_on = charcoal.onset("activation_ortiz")
    assert 1063.0 <= t_on <= 1073.0  # the ramp 1063-1073 K
    assert np.all(charcoal.reaction_rates["activation_ortiz"][charcoal.t_bed < 1063.0] == 0.0)


def test_charcoal_solid_below_1273_k_and_gas_range(charcoal):
    assert charcoal.t_bed_nodes.max() <= 1273.0  # "the solid never exceeds 1273 K"
    # gas between ~750 and 1381 K: inlet 1381 K (proposed), outlet within 25 K of 750 K
    assert charcoal.t_gas_nodes.max() == pytest.approx(1381.0)
    assert charcoal.gas_outlet_temperature == pytest.approx(750.0, abs=25.0)


def test_charcoal_burn_off_order_of_seed_estimate(charcoal):
    # notes 004 8.4: ~5 % burn-off over a 1.2 m zone at ~1100 K (order of magnitude)
    assert 3.0 <= charcoal.burn_off <= 10.0


def test_limestone_reaction_zone_1_to_3_m(limestone):
    s = limestone.summary()
    # "solid flow starts to fall at about 1 m ... calcination stops at about 3 m": +-0.3 m
    assert s["z_conversion_1pct_CaCO3_m"] == pytest.approx(1.0, abs=0.3)
    assert s["z_conversion_99pct_CaCO3_m"] == pytest.approx(3.0, abs=0.3)


def test_limestone_onset_temperature_departure_documented(limestone):
    # seed 004: decomposition begins "around 900 K"; Luisser's rate as printed is already
    # 1.8e-4 1/s at 850 K, so 1 % conversion is reached near 800 K (docs/validation.md)
    t1 = limestone.summary()["T_bed_conversion_1pct_CaCO3_K"]
    assert 750.0 <= t1 <= 900.0


def test_limestone_peaks_and_full_calcination(limestone):
    assert limestone.t_bed_nodes.max() == pytest.approx(1600.0, rel=0.05)  # "about 1600 K"
    assert limestone.t_gas_nodes.max() == pytest.approx(1800.0, rel=0.01)  # "about 1800 K"
    assert limestone.conversion("CaCO3")[-1] == pytest.approx(1.0, abs=1e-9)  # issue 7


def test_limestone_equilibrium_rate_starts_above_equilibrium_temperature():
    data = _data("limestone_calcination")
    data["chemistry"]["reactions"] = ["drying_ahmad", "calcination_equilibrium"]
    sol = run_kiln_case(parse_case(data))
    r0 = sol.reaction_rates["calcination_equilibrium"]
    t_on = float(sol.t_bed[np.argmax(r0 > 0)])
    # p_CO2 in the flue gas is ~0.1 atm here: Baker's T_eq(0.1 atm) = 1033 K; nothing calcines
    # below it, and the 1 atm value (1173.6 K) bounds T_eq for any local CO2 pressure
    assert t_on >= 1033.0 - 5.0
    assert sol.conversion("CaCO3")[-1] == pytest.approx(1.0, abs=1e-9)
    pure = _data("limestone_calcination")
    pure["chemistry"]["reactions"] = ["calcination_equilibrium"]
    pure["gas"]["mass_fractions"] = {"CO2": 1.0}  # dry feed: the gas stays pure CO2
    pure["material"]["composition"] = {"CaCO3": 1.0}
    sol1 = run_kiln_case(parse_case(pure))
    r = sol1.reaction_rates["calcination_equilibrium"]
    assert np.all(r[sol1.t_bed < 1173.6] == 0.0)  # ~1170 K at 1 atm CO2 (issue 7)
    assert r.max() > 0
