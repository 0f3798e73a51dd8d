"""Barr's natural-gas-fired UBC pilot kiln, trials T3, T4, T6: prediction from measured inputs.

Nothing is fitted: the cases (src/rotarykiln/cases/barr_T*.yaml) hold the measured inputs
and the data note's lining and emissivities; the flows are read as normal litres (0 degC, an
assumption the same for every trial, see docs/validation.md). The default burner model is
instant burn-out at the burner (Hanein et al. 2017). Scored: RMSE of bed, gas 2.5 cm above the
bed (raw gas temperature, no thermocouple correction) and inner wall, mean of the three trials.

Issue 10 targets bed <= 25 K, gas <= 35 K, wall <= 30 K. This model reaches 30.3 / 24.6 / 29.3 K;
the bed target is not met (the feed-end bed readings at z = 0.11 m are 35-115 K above what a
feed at ambient can reach there, and T4's mid-kiln bed and wall are 35-45 K high). The bounds
below are the achieved values plus a margin of about 10 %, so that a regression fails.
"""

from __future__ import annotations

from importlib import resources

import numpy as np
import pytest
import yaml

from rotarykiln.case import load_case, parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import run_kiln_case

TRIALS = ("T3", "T4", "T6")


def _rmse(model, measured):
    return float(np.sqrt(np.mean((np.asarray(model) - np.asarray(measured)) ** 2)))


@pytest.fixture(scope="module")
def solutions():
    return {t: run_kiln_case(load_case(builtin_case_path(f"barr_{t}"))) for t in TRIALS}


def test_cases_hold_the_data_file_measurements():
    # the built-in cases are generated from the copied data file: check they agree
    path = resources.files("rotarykiln") / "data" / "barr1986" / "barr_pilot_kiln_T3_T4_T6.yaml"
    data = yaml.safe_load(path.read_text())
    for t in TRIALS:
        m = load_case(builtin_case_path(f"barr_{t}")).measurements
        src = data["cases"][t]["measured_K"]
        assert m.t_bed == pytest.approx([v for _, v in src["T_bed"]])
        assert m.t_gas == pytest.approx([v for _, v in src["T_gas_off_bed"]])
        assert m.t_wall == pytest.approx([v for _, v in src["T_wall"]])


def test_rmse_against_measurements(solutions):
    scores = {"bed": [], "gas": [], "wall": []}
    for sol in solutions.values():
        m = sol.measurements
        scores["bed"].append(_rmse(sol.bed_temperature_at(m["z_bed"]), m["t_bed"]))
        scores["gas"].append(_rmse(sol.gas_temperature_at(m["z_gas"]), m["t_gas"]))
        scores["wall"].append(_rmse(sol.wall_temperature_at(m["z_wall"]), m["t_wall"]))
    mean = {k: float(np.mean(v)) for k, v in scores.items()}
    assert mean["bed"] < 35.0
    assert mean["gas"] < 27.0
    assert mean["wall"] < 32.5


def test_bed_rises_to_the_discharge(solutions):
    # measured: the bed heats all the way to the burner end; a cold burner cell would cool it
    for sol in solutions.values():
        assert np.all(np.diff(sol.t_bed_nodes) > 0)
        assert sol.gas_temperature_at(5.5) > sol.bed_outlet_temperature


def test_balances_close_and_sheet_adds_up(solutions):
    for sol in solutions.values():
        assert abs(sol.energy_closure) < 1e-6
        s = sol.energy_sheet
        assert abs(s["closure_relative"]) < 1e-6
        # LHV input (Cantera) within 0.2 % of the heat the model releases (dissociation, NO)
        assert s["combustion_heat_W"] == pytest.approx(s["fuel_lhv_input_W"], rel=2e-3)
        assert s["fuel_hhv_input_W"] / s["fuel_lhv_input_W"] == pytest.approx(1.109, abs=2e-3)
        assert 0.1 < sol.thermal_efficiency < 0.35


def test_firing_rate_matches_the_reference_note():
    # flames.md section 6 (Cantera, 0 degC basis): Q = 50.8, 70.5, 32.2 kW LHV
    for t, q in zip(TRIALS, (50.8e3, 70.5e3, 32.2e3), strict=True):
        case = load_case(builtin_case_path(f"barr_{t}"))
        from rotarykiln.kiln.from_case import kiln_from_case

        kiln, _ = kiln_from_case(case)
        assert kiln.firing.flame.fuel_lhv == pytest.approx(q, rel=2e-3)


def test_mesh_doubling_changes_profiles_by_less_than_2_K():
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    sols = []
    for n in (100, 200):
        data["solver"] = {"cells": n}
        sols.append(run_kiln_case(parse_case(data)))
    a, b = sols
    assert np.max(np.abs(a.t_bed_nodes - b.t_bed_nodes[::2])) < 2.0
    assert np.max(np.abs(a.t_gas_nodes - b.t_gas_nodes[::2])) < 2.0


def test_co_current_variant_converges():
    # every built-in fired heat case (the fired limestone kiln: tests/kiln/combustion/test_fired_reacting.py)
    for name in [f"barr_{t}" for t in TRIALS] + ["ubc_pilot_flame"]:
        data = yaml.safe_load(builtin_case_path(name).read_text())
        data["operation"]["counter_current"] = False
        sol = run_kiln_case(parse_case(data))
        assert abs(sol.energy_closure) < 1e-6
        assert sol.t_gas_nodes[0] == pytest.approx(sol.burner["adiabatic_temperature_K"])


@pytest.mark.parametrize("counter_current", [True, False])
def test_mixing_limited_burnout_option_converges_and_closes(counter_current):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    data["burner"].update(combustion="burnout", nozzle_diameter="40 mm")
    data["operation"]["counter_current"] = counter_current
    sol = run_kiln_case(parse_case(data))
    s = sol.energy_sheet
    assert abs(sol.energy_closure) < 1e-6 and abs(s["closure_relative"]) < 1e-6
    assert s["combustion_heat_W"] == pytest.approx(s["fuel_lhv_input_W"], rel=2e-3)
    assert 0.3 < sol.burner["flame_length_m"] < 1.0  # Hawthorne-Weddell-Hottel, 40 mm nozzle


ALL_TRIALS = ("T2", "T3", "T4", "T6", "T9")


def test_new_cases_hold_the_second_data_file_measurements():
    # T2 and T9 (issue 23) come from barr_pilot_kiln_T2_T9.yaml
    path = resources.files("rotarykiln") / "data" / "barr1986" / "barr_pilot_kiln_T2_T9.yaml"
    data = yaml.safe_load(path.read_text())
    for t in ("T2", "T9"):
        m = load_case(builtin_case_path(f"barr_{t}")).measurements
        src = data["cases"][t]["measured_K"]
        assert m.t_bed == pytest.approx([v for _, v in src["T_bed"]])
        assert m.t_gas == pytest.approx([v for _, v in src["T_gas_off_bed"]])
        assert m.t_gas_wall == pytest.approx([v for _, v in src["T_gas_off_wall"]])
        assert m.t_wall == pytest.approx([v for _, v in src["T_wall"]])


@pytest.mark.xfail(
    strict=True,
    reason="the campaign targets are not met yet (docs/validation.md, Barr: five trials); "
    "when they are, this test passes and strict xfail fails it: remove the mark",
)
def test_five_trials_meet_the_campaign_targets():
    # targets: mean RMSE bed <= 25 K, gas 2.5 cm above the bed <= 30 K, inner wall <= 25 K, and
    # no trend with firing: the mean bed bias of T2 and of T9 each within 15 K of zero
    scores = {"bed": [], "gas": [], "wall": []}
    bias = {}
    for t in ALL_TRIALS:
        case = load_case(builtin_case_path(f"barr_{t}"))
        sol = run_kiln_case(case)
        r = sol.measured_rmse()
        for k in scores:
            scores[k].append(r[k])
        m = case.measurements
        bias[t] = float(np.mean(np.interp(m.z_bed, sol.z, sol.t_bed) - np.asarray(m.t_bed)))
    mean = {k: float(np.mean(v)) for k, v in scores.items()}
    assert mean["bed"] <= 25.0 and mean["gas"] <= 30.0 and mean["wall"] <= 25.0, mean
    assert abs(bias["T2"]) <= 15.0 and abs(bias["T9"]) <= 15.0, bias


def test_banded_exchange_closes_and_passes_less_heat_at_the_highest_firing():
    # the WSGG grey gases in the network (closures.radiation_model: banded): the gas absorbs
    # the cooler surfaces' radiation with its absorptivity at their temperature, so at T9's
    # hot, low-excess-air flame it hands less heat to the bed and wall than one grey gas

    from rotarykiln.kiln.from_case import kiln_from_case
    from rotarykiln.kiln.steady.solve import solve_kiln

    kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T9")))
    grey = solve_kiln(kiln, cells)
    banded_kiln = kiln.replace(closures__radiation_model="banded")
    banded = solve_kiln(banded_kiln, cells)
    assert abs(banded.energy_closure) < 1e-6
    assert abs(banded.energy_sheet["closure_relative"]) < 1e-6
    mid = (banded.z > 1.83) & (banded.z < 3.67)
    assert np.all(banded.t_bed[mid] < grey.t_bed[mid])
    assert np.all(banded.t_wall[mid] < grey.t_wall[mid])
    assert banded.gas_outlet_temperature > grey.gas_outlet_temperature
