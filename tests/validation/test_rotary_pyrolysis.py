"""The rotaryPyrolysis default case (Pichler et al. 2021) against the anchor script's profiles.

The anchor is a simulation, not a measurement (src/rotarykiln/data/rotary_pyrolysis/README.md):
agreement means "the same model". Targets of issue 11: char yield (outlet char / wet feed)
within 2 percentage points of 19.0 % (RTD) and 20.7 % (plug flow), bed outlet temperature within
20 K of 684 K, bed temperature profile within 30 K along the kiln, or a documented physical
reason (docs/pyrolysis.md):

- plug flow: every target is met;
- the RTD as axial dispersion inside the balances (Pe 5): yield and outlet temperature are met;
  the bed temperature departs by up to ~150 K over the first 0.3 m, because dispersion mixes
  the bed's enthalpy as well as its composition (hot particles travel back to the feed; the
  Danckwerts inlet jumps), while the script's segregated classes all share one temperature
  profile. Beyond 0.3 m the 30 K holds;
- the RTD as segregated classes over the frozen plug-flow temperatures (the script's own
  treatment) is computed too: within 2 points of 19.0 %.
"""

from importlib.resources import files

import numpy as np
import pandas as pd
import pytest

from rotarykiln.kiln.pyrolysis import (
    char_yield,
    mean_residence_time,
    rotary_pyrolysis_kiln,
    segregated_yields,
)
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.kiln.wall.jacket import jacket_balance

pytestmark = pytest.mark.filterwarnings("ignore::rotarykiln.errors.OutOfRangeWarning")

ANCHOR = pd.read_csv(
    files("rotarykiln.data") / "rotary_pyrolysis" / "rotary_pyrolysis_anchor_profiles.csv"
)
PLUG, RTD = "plug_flow_nt1", "adm_Pe5_nt40"


def _anchor(case):
    return ANCHOR[ANCHOR["case"] == case]


@pytest.fixture(scope="module")
def plug():
    kiln = rotary_pyrolysis_kiln(dispersion=False)
    return kiln, solve_kiln(kiln, 100)


@pytest.fixture(scope="module")
def dispersed():
    kiln = rotary_pyrolysis_kiln()  # Pe 5 inside the balances
    return kiln, solve_kiln(kiln, 100)


def _bed_deviation(sol, case, z_min=0.0):
    ref = _anchor(case)
    keep = ref["z_m"].to_numpy() >= z_min
    tb = np.interp(ref["z_m"].to_numpy(), sol.z_nodes, sol.t_bed_nodes)
    return np.abs(tb - ref["T_bed_K"].to_numpy())[keep]


def test_anchor_headline_numbers_as_read():
    for case, yield_pct, t_out in ((RTD, 19.04, 684.08), (PLUG, 20.72, 684.79)):
        last = _anchor(case).iloc[-1]
        assert 100 * last["F_char_kg_h"] / 30.0 == pytest.approx(yield_pct, abs=0.01)
        assert last["T_bed_K"] == pytest.approx(t_out, abs=0.01)


def test_saeman_bed_and_residence_time_match_exactly(plug):
    """No thermal closure involved: tau 551.9 s, depth 51.68 mm at the feed, 25 mm at the dam."""
    kiln, sol = plug
    assert mean_residence_time(kiln, sol) == pytest.approx(551.9, abs=0.3)
    from rotarykiln.kiln.residual import KilnResidual

    res = KilnResidual(kiln, 100)
    h = res.depth_faces(sol.fluxes["x"])
    assert h[0] == pytest.approx(0.05168, abs=2e-4)
    assert h[-1] == pytest.approx(0.025)


def test_plug_flow_char_yield_outlet_and_profile(plug):
    kiln, sol = plug
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    assert 100 * char_yield(sol) == pytest.approx(20.72, abs=2.0)
    assert sol.t_bed_nodes[-1] == pytest.approx(684.79, abs=20.0)
    assert _bed_deviation(sol, PLUG).max() < 30.0


def test_dispersed_bed_char_yield_and_outlet(dispersed):
    kiln, sol = dispersed
    assert abs(sol.energy_closure) < 1e-6
    assert 100 * char_yield(sol) == pytest.approx(19.04, abs=2.0)
    assert sol.t_bed_nodes[-1] == pytest.approx(684.08, abs=20.0)
    # enthalpy dispersion heats the feed end (docs/pyrolysis.md); beyond 0.3 m within 30 K
    assert _bed_deviation(sol, RTD, z_min=0.3).max() < 30.0
    assert _bed_deviation(sol, RTD).max() > 30.0  # the documented departure is real


def test_segregated_classes_as_the_script(plug):
    kiln, sol = plug
    r = segregated_yields(kiln, sol, peclet=5.0)
    assert 100 * r["rtd"]["char"] == pytest.approx(19.04, abs=2.0)
    # the RTD lowers the yield, mainly by intermediate solid carried out by early classes
    assert r["rtd"]["char"] < r["plug"]["char"]
    assert r["rtd"]["intermediate_solid"] > r["plug"]["intermediate_solid"]


def test_jacket_gas_balance_closes(plug):
    kiln, sol = plug
    jb = jacket_balance(kiln, sol)
    assert abs(jb["closure_relative"]) < 1e-6
    # its duty is what the energy sheet books as heating
    assert jb["duty_W"] == pytest.approx(sol.energy_sheet["electric_heating_W"], rel=1e-9)
    # the anchor's flue-gas duty: 9.11 kW in plug flow (its wall is the flue gas, as here)
    assert jb["duty_W"] == pytest.approx(9110.0, rel=0.05)


def test_builtin_case_file():
    """cases/rotary_pyrolysis.yaml: the flue-gas jacket given in the case file (wall.jacket)
    and the Saeman fill profile: the same targets in plug flow, the jacket balance closed."""
    from rotarykiln.case import load_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.kiln.from_case import kiln_from_case

    kiln, cells = kiln_from_case(load_case(builtin_case_path("rotary_pyrolysis")))
    assert kiln.wall.jacket is not None and kiln.wall.jacket.htc == "wall_at_gas"
    sol = solve_kiln(kiln, cells)
    assert abs(sol.energy_closure) < 1e-6
    assert abs(jacket_balance(kiln, sol)["closure_relative"]) < 1e-6
    assert 100 * char_yield(sol) == pytest.approx(20.72, abs=2.0)
    assert sol.t_bed_nodes[-1] == pytest.approx(684.79, abs=20.0)
    assert _bed_deviation(sol, PLUG).max() < 30.0
