"""Seed 004 (Ahmad 2006) chapter 4: what the text records about its two reacting kilns.

Seed 004's figures are lost in the OCR; the checks below are the prose statements (notes 004,
section 6) with tolerances that reflect "about"/"near" in the text. Departures (the Luisser
kinetics start below 900 K) are asserted as documented, not hidden.

Seed 004 does not give the gas inlet or the wall loss: the gas inlet temperatures are taken from
the text and the wall U of each case was calibrated with this model on the text's statements
(docs/validation.md, "Departures from Ahmad (2006)", item 1). What a taken-over or calibrated
number gives is not a validation: those are provenance checks of how the numbers were chosen
(the ``test_provenance_*`` below). The charcoal solid maximum and gas outlet, and the limestone
reaction zone and solid maximum, are therefore not validated here.
"""

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.kiln.from_case import kiln_from_case


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
    # not a validation: the onset temperature is an input (Ahmad's 1073 K and the proposed 10 K
    # ramp of the case); the kiln must honour it
    z_on, t_on = charcoal.onset("activation_ortiz")
    assert 1063.0 <= t_on <= 1073.0  # the ramp 1063-1073 K
    assert np.all(charcoal.reaction_rates["activation_ortiz"][charcoal.t_bed < 1063.0] == 0.0)


def _with_u(name, u):
    data = _data(name)
    data["wall"]["U"] = f"{u} W/m2/K"
    return run_kiln_case(parse_case(data))


def test_provenance_gas_inlets_are_the_text_s_gas_extremes():
    """Provenance, not a validation: seed 004 gives no gas inlet (docs/validation.md, "Inputs
    Ahmad (2006) omits"); case I takes the top of the text's gas range 750-1381 K, case II the
    text's gas peak "about 1800 K" (no burner model: the hottest gas is the gas entering)."""
    for name, text_value in (("charcoal_activation", 1381.0), ("limestone_calcination", 1800.0)):
        kiln, _ = kiln_from_case(parse_case(_data(name)))
        assert kiln.gas.temperature == text_value, name


def test_provenance_charcoal_wall_loss_calibration(charcoal):
    """Provenance of the charcoal case's wall U = 5 W/(m2 K), not a validation: seed 004 gives
    none, so it was calibrated on the text (docs/validation.md, departures, item 1): the
    lowest whole-number U that keeps the solid at or below the 1273 K it "never exceeds" (U = 4
    gives 1282 K), and of its neighbours the one that lets the gas leave nearest the 750 K of the
    text's gas range."""
    assert charcoal.t_bed_nodes.max() <= 1273.0
    low, high = _with_u("charcoal_activation", 4), _with_u("charcoal_activation", 6)
    assert low.t_bed_nodes.max() > 1273.0
    miss = [abs(s.gas_outlet_temperature - 750.0) for s in (low, charcoal, high)]
    assert miss[1] == min(miss), miss


def test_provenance_limestone_wall_loss_calibration(limestone):
    """Provenance of the limestone case's wall U = 7 W/(m2 K), not a validation: calibrated on
    the text's reaction zone, "starts at about 1 m ... stops at about 3 m" (docs/validation.md,
    departures, item 1): of the whole-number U 6, 7 and 8 the one whose 1 % and 99 % conversion
    points lie nearest 1 m and 3 m."""

    def miss(sol):
        s = sol.summary()
        start, end = s["z_conversion_1pct_CaCO3_m"], s["z_conversion_99pct_CaCO3_m"]
        return abs(start - 1.0) + abs(end - 3.0)

    others = [miss(_with_u("limestone_calcination", u)) for u in (6, 8)]
    assert miss(limestone) < min(others), (miss(limestone), others)


def test_charcoal_burn_off_order_of_seed_estimate(charcoal):
    # notes 004 8.4: ~5 % burn-off over a 1.2 m zone at ~1100 K (order of magnitude)
    assert 3.0 <= charcoal.burn_off <= 10.0


def test_limestone_onset_temperature_departure_documented(limestone):
    # seed 004: decomposition begins "around 900 K"; Luisser's rate as printed is already
    # 1.8e-4 1/s at 850 K, so 1 % conversion is reached near 800 K (docs/validation.md)
    t1 = limestone.summary()["T_bed_conversion_1pct_CaCO3_K"]
    assert 750.0 <= t1 <= 900.0


def test_limestone_full_calcination(limestone):
    # the requirement of issue 7: the limestone is fully calcined at the outlet (to round-off)
    assert limestone.conversion("CaCO3")[-1] == pytest.approx(1.0, abs=1e-9)


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
