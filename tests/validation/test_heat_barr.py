"""Barr's natural-gas-fired UBC pilot kiln, trials T3, T4, T6: prediction from measured inputs.

Nothing is fitted: the cases (src/rotarykiln/cases/barr_T*.yaml) hold the measured inputs
and the data note's lining and emissivities; the flows are read as normal litres (0 degC, an
assumption the same for every trial, see docs/validation.md). The default burner model is
instant burn-out at the burner (Hanein et al. 2017). Scored: RMSE of bed, gas 2.5 cm above the
bed (raw gas temperature, no thermocouple correction) and inner wall, mean of the three trials.

Where the bounds come from. The source states no accuracy for its thermocouples (the data README,
src/rotarykiln/data/barr1986/README.md, gives none), so no bound here rests on a measurement
accuracy. The RMSE bounds are the targets issue 10 set for these three trials (docs/validation.md,
"target" row of the Barr table): bed <= 25 K, gas <= 35 K, wall <= 30 K. The model reaches
30.3 / 24.6 / 29.3 K: gas and wall are asserted; the bed target is not met (the feed-end bed
readings at z = 0.11 m are 35-115 K above what a feed at ambient can reach there, and T4's
mid-kiln bed and wall are 35-45 K high), so it is a strict xfail. The exact numbers of each trial
are held, as regression, by tests/test_golden_outputs.py, not by bounds here.
"""

from __future__ import annotations

import math
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


DATA_FILES = {
    "T2": "barr_pilot_kiln_T2_T9.yaml",
    "T3": "barr_pilot_kiln_T3_T4_T6.yaml",
    "T4": "barr_pilot_kiln_T3_T4_T6.yaml",
    "T6": "barr_pilot_kiln_T3_T4_T6.yaml",
    "T9": "barr_pilot_kiln_T2_T9.yaml",
}


def _litres_per_second(flow: str) -> float:
    value, unit = flow.split()
    assert unit == "L/s", flow  # the source's unit, read as normal litres (reference_temperature)
    return float(value)


@pytest.mark.parametrize("trial", sorted(DATA_FILES))
def test_provenance_cases_carry_the_data_files_inputs_and_measurements(trial):
    """Provenance, not a validation: each built-in case carries the measured inputs (CH4,
    primary and secondary air, feed, sand size and bulk density, kiln, fill, speed) and the
    measured temperatures with their positions of its trial in the shipped copy of the source's
    table (src/rotarykiln/data/barr1986/, Barr 1986 via Hanein et al. 2017), which the case
    files were generated from; compared with that data file, not with the case's own YAML."""
    path = resources.files("rotarykiln") / "data" / "barr1986" / DATA_FILES[trial]
    data = yaml.safe_load(path.read_text())
    src, kiln = data["cases"][trial], data["kiln"]
    case = load_case(builtin_case_path(f"barr_{trial}"))
    b = case.burner
    assert b.fuel == "CH4:1"
    assert _litres_per_second(b.fuel_flow) == pytest.approx(src["CH4_L_s"], rel=1e-12)
    assert _litres_per_second(b.primary_air.flow) == pytest.approx(src["primary_air_L_s"])
    assert _litres_per_second(b.secondary_air.flow) == pytest.approx(src["secondary_air_L_s"])
    assert case.operation.feed * 3600 == pytest.approx(src["feed_kg_h"], rel=1e-12)
    assert case.material.particle_size * 1000 == pytest.approx(src["particle_mm"], rel=1e-12)
    grade = "coarse_2.5mm" if src["particle_mm"] == 2.5 else "fine_0.58mm"
    assert case.material.bulk_density == data["sand"]["bulk_density_kg_m3"][grade]
    assert case.kiln.length == kiln["length_m"]
    assert case.kiln.diameter == pytest.approx(2 * kiln["inner_radius_m"], rel=1e-12)
    assert case.bed.fill == kiln["fill_fraction"]
    assert case.operation.speed * 30 / math.pi == pytest.approx(kiln["speed_rpm"], rel=1e-8)
    m = case.measurements
    for key, column in (
        ("bed", "T_bed"),
        ("gas", "T_gas_off_bed"),
        ("gas_wall", "T_gas_off_wall"),
        ("wall", "T_wall"),
    ):
        assert getattr(m, f"z_{key}") == pytest.approx([z for z, _ in src["measured_K"][column]])
        assert getattr(m, f"t_{key}") == pytest.approx([t for _, t in src["measured_K"][column]])


def _mean_rmse(solutions):
    scores = {"bed": [], "gas": [], "wall": []}
    for sol in solutions.values():
        m = sol.measurements
        scores["bed"].append(_rmse(sol.bed_temperature_at(m["z_bed"]), m["t_bed"]))
        scores["gas"].append(_rmse(sol.gas_temperature_at(m["z_gas"]), m["t_gas"]))
        scores["wall"].append(_rmse(sol.wall_temperature_at(m["z_wall"]), m["t_wall"]))
    return {k: float(np.mean(v)) for k, v in scores.items()}


def test_gas_and_wall_rmse_meet_the_issue_10_targets(solutions):
    """Mean RMSE of the three trials: gas 2.5 cm above the bed <= 35 K and inner wall <= 30 K,
    the targets of issue 10 (docs/validation.md, "target" row); the source gives no measurement
    accuracy (module docstring)."""
    mean = _mean_rmse(solutions)
    assert mean["gas"] <= 35.0, mean  # issue 10 target
    assert mean["wall"] <= 30.0, mean  # issue 10 target


@pytest.mark.xfail(
    strict=True,
    reason="the bed target of issue 10 is not met (30.3 K; docs/validation.md, Barr: the "
    "feed-end readings and T4's mid-kiln bias); when it is, strict xfail fails: remove the mark",
)
def test_bed_rmse_meets_the_issue_10_target(solutions):
    """Mean bed RMSE of the three trials <= 25 K, the target of issue 10."""
    mean = _mean_rmse(solutions)
    assert mean["bed"] <= 25.0, mean  # issue 10 target


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
    """Not a validation: an independent check of the front end's conversion of the measured
    flows to a firing rate. flames.md section 6 computed it separately (Cantera, 0 degC basis):
    Q = 50.8, 70.5, 32.2 kW LHV, printed to 3 digits (2e-3)."""
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
