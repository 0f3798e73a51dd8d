"""Drying with a boiling point (issue 10, item 7): the default law ``drying`` keeps no liquid
water in a bed above its boiling point; seed 004's ``drying_ahmad`` stays selectable and
reproduces the documented seed-004 behaviour (moisture up to ~1000 K, docs/validation.md).

The kiln tests run the built-in limestone case (feed 550 K: the superheated wet feed flashes
in the first cell) and the same case with a 300 K feed (a boiling plateau over several cells).
"""

import warnings

import cantera as ct
import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.drying import (
    ahmad_critical_moisture_drying_rate,
    boiling_drying_rate,
    boiling_evaporation_rate,
    water_boiling_temperature,
)
from rotarykiln.chemistry.mechanism import CellState, Mechanism
from rotarykiln.chemistry.reaction import builtin_reactions, reaction_from_dict
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.errors import InputError, OutOfRangeWarning

T_BOIL = 373.15
DRYING = {
    "name": "my_drying",
    "stoichiometry": {"H2O(l)": -1, "H2O": 1},
    "basis": "H2O(l)",
    "rate": {"law": "boiling_drying"},
    "heat": 2257200.0,
}


def _case(drying="drying", feed_temperature=None):
    data = yaml.safe_load(builtin_case_path("limestone_calcination").read_text(encoding="utf-8"))
    data["chemistry"]["reactions"] = [drying, "calcination_luisser"]
    if feed_temperature is not None:
        data["operation"]["feed_temperature"] = feed_temperature
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutOfRangeWarning)  # Gorog gas-wall Re (documented)
        return run_kiln_case(parse_case(data))


def _moisture_fraction(sol):
    q = sol.bed_flows["H2O(l)"]
    return q / q[0]


@pytest.fixture(scope="module")
def limestone():
    return _case()


@pytest.fixture(scope="module")
def cold_feed():
    return _case(feed_temperature="300 K")


# --- the law ------------------------------------------------------------------------------------
@pytest.mark.parametrize("p", [2.0e4, 5.0e4, 101325.0, 2.0e5, 5.0e5])
def test_boiling_temperature_follows_the_saturation_line(p):
    water = ct.Water()  # IAPWS-based pure-fluid model of Cantera
    water.PQ = p, 0.0
    assert water_boiling_temperature(p) == pytest.approx(water.T, abs=1.3)
    assert water_boiling_temperature(101325.0) == pytest.approx(T_BOIL, abs=1e-9)


def test_boiling_temperature_warns_outside_its_range():
    with pytest.warns(OutOfRangeWarning, match="drying.pressure"):
        water_boiling_temperature(5.0e3)
    with pytest.raises(InputError, match="drying.pressure"):
        water_boiling_temperature(-1.0)


def test_boiling_term_is_a_stiff_heat_sink_above_the_boiling_point():
    T = np.array([353.15, 368.15, 373.15, 375.15, 393.15, 1373.15])
    r = boiling_evaporation_rate(T, 1.0)
    assert np.all(np.diff(r) > 0)
    assert r[0] < 1e-20 and r[1] < 1e-4  # 20 K and 5 K below: nothing worth counting
    # above: k_b m' (T - T_boil) (hinge limit, error w ln 2 / ...)
    assert r[3:] == pytest.approx(1.0e3 * (T[3:] - T_BOIL), rel=1e-6, abs=0.1)
    assert boiling_evaporation_rate(400.0, -1e-3) == 0.0
    assert boiling_evaporation_rate(400.0, 2.0) == pytest.approx(
        2 * boiling_evaporation_rate(400.0, 1.0)
    )


def test_default_law_is_seed004_below_the_boiling_point():
    args = (20.0, 750.0, np.array([320.0, 350.0, 360.0]), 3.33e-4, 3.33e-3)
    seed = ahmad_critical_moisture_drying_rate(*args)
    r = boiling_drying_rate(*args, 0.3)
    assert r == pytest.approx(seed, rel=1e-9)
    only = boiling_drying_rate(*args, 0.3, below_boiling=False)
    assert np.all(only < 1e-9 * seed)
    # the boiling term at the outlet-face temperature when given
    hot = boiling_drying_rate(*args, 0.3, T_bed_out=380.0)
    assert hot == pytest.approx(seed + boiling_evaporation_rate(380.0, 0.3))


def test_rate_law_parameters_checked_and_boiling_point_from_pressure():
    r = reaction_from_dict({**DRYING, "rate": {"law": "boiling_drying", "pressure": 2.0e5}})
    assert r.params["T_boil"] == pytest.approx(water_boiling_temperature(2.0e5))
    assert builtin_reactions()["drying"].params["T_boil"] == pytest.approx(T_BOIL)
    bad = [
        ({"T_boil": 380.0, "pressure": 2.0e5}, "pressure"),
        ({"width": 0.0}, "width"),
        ({"k_boil": -1.0}, "k_boil"),
        ({"T_boil": -5.0}, "T_boil"),
    ]
    for params, field in bad:
        with pytest.raises(InputError, match=field):
            reaction_from_dict({**DRYING, "rate": {"law": "boiling_drying", **params}})


def test_mechanism_rates_balance_with_the_default_drying():
    mech = Mechanism.builtin("drying", "calcination_luisser")
    st = CellState.build(
        T_bed=np.linspace(300.0, 1400.0, 12),
        T_gas=1500.0,
        bed_mass_flow={"H2O(l)": 1e-3, "CaCO3": 9e-3},
        bed_mass_per_length=10.0,
        bed_mass_flow_in={"CaCO3": 9e-3},
        inputs={"drying_conductance": 20.0},
    )
    out = mech.rates(st, check=True)
    drying = out.reaction_rate[:, 0]
    assert np.all(drying >= 0) and np.all(np.diff(drying[1:]) > 0)


# --- the kiln -----------------------------------------------------------------------------------
def test_no_liquid_water_above_the_boiling_point(limestone):
    sol = limestone
    x = _moisture_fraction(sol)
    hot_faces = sol.t_bed_nodes[1:] > T_BOIL + 2.0  # the feed face z = 0 is the given inlet
    assert hot_faces.all()  # the 550 K wet feed flashes in the first cell (402 K there)
    assert np.max(x[1:][hot_faces]) < 1e-6
    hot_cells = sol.t_bed > T_BOIL + 2.0  # the temperature the rate law sees
    assert np.max(x[1:][hot_cells]) < 1e-6
    # the flash takes the sensible heat of the feed: the first face is far below 550 K
    assert sol.t_bed_nodes[1] < 420.0


def test_balances_close_with_the_default_law(limestone, cold_feed):
    for sol in (limestone, cold_feed):
        assert max(sol.element_closure.values()) < 1e-8
        assert abs(sol.energy_closure) < 1e-6
        assert sol.conversion("CaCO3")[-1] == pytest.approx(1.0, abs=1e-9)


def test_bed_temperature_plateaus_near_the_boiling_point(cold_feed):
    sol = cold_feed
    x = _moisture_fraction(sol)
    T = sol.t_bed_nodes
    boiling = (x < 0.9) & (x > 1e-6)  # faces past the sub-boiling drying, still wet
    assert boiling.sum() >= 3  # a plateau over several cells (0.055 m each)
    assert np.all(T[boiling] >= T_BOIL - 8.0)
    assert np.all(T[boiling] <= T_BOIL + 2.0)
    # wherever the bed is hotter than the boiling point by 2 K, it is dry
    hot = T[1:] > T_BOIL + 2.0
    assert np.max(x[1:][hot]) < 1e-6
    # below the plateau the bed heats (sub-boiling drying by the seed-004 term) ...
    first = int(np.argmax(boiling))
    assert np.all(np.diff(T[: first + 1]) > 0) and x[first - 1] < 1.0
    # ... and once dry it heats again
    last = len(T) - 1 - int(np.argmax(boiling[::-1]))
    assert T[last + 1] > T_BOIL + 20.0 and x[last + 1] < 1e-6


def test_seed004_option_reproduces_the_documented_behaviour():
    sol = _case("drying_ahmad")  # the built-in case file as shipped
    x = _moisture_fraction(sol)
    s = sol.summary()
    # docs/validation.md, case II (Luisser rate): 1 % conversion at 0.94 m (798 K), 99 % at
    # 3.02 m, bed outlet 1651 K; the critical-moisture law never completes drying
    assert s["z_conversion_1pct_CaCO3_m"] == pytest.approx(0.939, abs=0.02)
    assert s["T_bed_conversion_1pct_CaCO3_K"] == pytest.approx(797.6, abs=2.0)
    assert s["z_conversion_99pct_CaCO3_m"] == pytest.approx(3.021, abs=0.02)
    assert sol.bed_outlet_temperature == pytest.approx(1650.8, abs=1.0)
    assert x[-1] == pytest.approx(9.83e-3, rel=0.02)  # ~1 % of the moisture leaves at 1651 K
    assert np.all(x[sol.t_bed_nodes > 1000.0] > 5e-3)  # liquid water above 1000 K
