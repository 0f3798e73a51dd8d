"""The rotaryPyrolysis default case (Pichler et al. 2021) against the anchor script's profiles.

The kiln is the built-in case file, cases/rotary_pyrolysis.yaml, as users run it (``rotarykiln
run rotary_pyrolysis``): axial dispersion at the script's Pe 5 inside the balances; its plug-flow
variant is the override ``bed.axial_dispersion: plug``.

The anchor is a simulation, not a measurement (src/rotarykiln/data/rotary_pyrolysis/README.md):
agreement means "the same model". Its numbers are those of the data file
(``rotary_pyrolysis_anchor_profiles.csv``: the script's profiles at 20 positions, linearly
interpolated from its 0.2 mm grid, printed to 0.01 K and 1e-5 kg/h). Its known errors
(docs/pyrolysis.md: char c_p with +6.85e-3 T^2, a black yet transparent gas, drying scaled by the
moisture fraction, fill fraction and units in its gas-bed correlation) each move its bed by up
to ~15 K and its char yield by up to ~1 point; hence the targets of issue 11: char yield
(outlet char / wet feed) within 2 percentage points of 19.0 % (RTD) and 20.7 % (plug flow), bed
outlet temperature within 20 K of 684 K, bed temperature profile within 30 K along the kiln,
or a documented physical reason (docs/pyrolysis.md):

- plug flow: every target is met;
- the RTD as axial dispersion inside the balances (Pe 5): yield and outlet temperature are met;
  the bed temperature departs by up to ~180 K over the first 0.3 m, because dispersion mixes
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

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.residual import KilnResidual
from rotarykiln.kiln.results.yields import outlet_yield, segregated_yields
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.kiln.wall.jacket import jacket_balance

pytestmark = pytest.mark.filterwarnings("ignore::rotarykiln.errors.OutOfRangeWarning")

ANCHOR = pd.read_csv(
    files("rotarykiln.data") / "rotary_pyrolysis" / "rotary_pyrolysis_anchor_profiles.csv"
)
PLUG, RTD = "plug_flow_nt1", "adm_Pe5_nt40"
CASE = load_case(builtin_case_path("rotary_pyrolysis"))
PLUG_FLOW = {"bed.axial_dispersion": "plug"}


def _anchor(case):
    return ANCHOR[ANCHOR["case"] == case]


def _solved(changes=None):
    kiln, cells = kiln_from_case(CASE.replace(changes or {}))
    return kiln, solve_kiln(kiln, cells)


@pytest.fixture(scope="module")
def plug():
    return _solved(PLUG_FLOW)


@pytest.fixture(scope="module")
def dispersed():
    return _solved()  # the case as given: Pe 5 inside the balances


def _bed_deviation(sol, case, z_min=0.0):
    ref = _anchor(case)
    keep = ref["z_m"].to_numpy() >= z_min
    tb = np.interp(ref["z_m"].to_numpy(), sol.z_nodes, sol.t_bed_nodes)
    return np.abs(tb - ref["T_bed_K"].to_numpy())[keep]


def test_anchor_headline_numbers_as_read():
    """Provenance of the data file, not a validation: its last rows are the script's printed
    headline numbers (its README): char yield 19.04 % (RTD) and 20.72 % (plug flow) of the
    30 kg/h wet feed, bed outlet 684.08 and 684.79 K; read to their printed 0.01."""
    for case, yield_pct, t_out in ((RTD, 19.04, 684.08), (PLUG, 20.72, 684.79)):
        last = _anchor(case).iloc[-1]
        assert 100 * last["F_char_kg_h"] / 30.0 == pytest.approx(yield_pct, abs=0.01)
        assert last["T_bed_K"] == pytest.approx(t_out, abs=0.01)


def test_the_case_is_the_validated_model():
    """Provenance, not a validation: the case carries the script's inputs (data README): the
    25 mm dam, 30 kg/h of chips at the bulk density of 650 kg/m3 particles in a bed of porosity
    0.57, dispersion at Pe 5 (D = L^2 / (tau Pe), tau the fresh feed's Saeman time, 551.9 s in
    the script), the tar split psi = 0.57 + 0.06 x 2 rpm; and the model choices the validation
    needs: the jacket with its own balance and the script's zero resistance, the Saeman depth
    at the fresh feed's volume, the wood mechanism, penetration theory at the covered wall."""
    kiln, _ = kiln_from_case(CASE)
    depth = kiln.bed.depth
    assert depth.volume_law == "fresh_feed" and depth.shrinkage == 0.0
    assert depth.dam_height == pytest.approx(0.025)
    bulk = 650.0 * (1.0 - 0.57)  # particle density x (1 - bed porosity), the script's
    assert depth.volume_flow0 == pytest.approx(30.0 / 3600.0 / bulk, rel=1e-12)
    assert kiln.wall.jacket.htc == "wall_at_gas" and not kiln.wall.jacket.counter_current
    assert kiln.bed.dispersion == pytest.approx(2.0**2 / (551.9 * 5.0), rel=1e-3)
    assert kiln.closures.covered_wall == "wachters_kramers1964"
    tar = {r.name: r.params["A"] for r in kiln.chemistry.mechanism.reactions}
    assert tar["wood_to_tar_vapour"] == pytest.approx(1.08e10 * (0.57 + 0.06 * 2), rel=1e-12)


def test_saeman_bed_and_residence_time_match(plug):
    """No thermal closure involved: the script's mean residence time 551.96 s (tau_cum_s at its
    last node) and bed depth (bed_depth_m, printed to 0.01 mm: 51.68 mm at the feed, 25 mm at
    the dam). Tolerances: 0.3 s and 0.05 mm, the script's 0.2 mm grid against our 100 cells'
    box scheme, and the fresh feed's volume counted here at the bulk density (the script counts
    the 0.1 % moisture as water in the voids: 0.035 % less volume, 0.02 mm less depth)."""
    kiln, sol = plug
    assert sol.residence_time == pytest.approx(551.96, abs=0.3)
    h = KilnResidual(kiln, sol.z.size).depth_faces(sol.fluxes["x"])
    assert h[0] == pytest.approx(0.05168, abs=5e-5)
    assert h[-1] == pytest.approx(0.025)
    ref = _anchor(PLUG)
    depth = np.interp(ref["z_m"].to_numpy(), sol.z_nodes, h)
    assert np.abs(depth - ref["bed_depth_m"].to_numpy()).max() < 5e-5


def test_plug_flow_char_yield_outlet_and_profile(plug):
    """Plug flow against the script's plug-flow run (one class at the Saeman time): char yield
    20.72 % within 2 points, bed outlet 684.79 K within 20 K, the bed profile within 30 K
    (the tolerances of the module docstring: the script's known errors move its bed by up to
    ~15 K, its char c_p the most); the balances close to the solver's accuracy."""
    kiln, sol = plug
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    assert 100 * outlet_yield(sol, "char") == pytest.approx(20.72, abs=2.0)
    assert sol.t_bed_nodes[-1] == pytest.approx(684.79, abs=20.0)
    assert _bed_deviation(sol, PLUG).max() < 30.0


def test_dispersed_bed_char_yield_and_outlet(dispersed):
    """The case as given (dispersion at Pe 5 inside the balances) against the script's RTD run
    (41 segregated classes of the Pe 5 closed-closed RTD): char yield 19.04 % within 2 points,
    bed outlet 684.08 K within 20 K (the module docstring's tolerances); the profile within
    30 K beyond 0.3 m, and the documented departure near the feed (dispersion carries the bed's
    enthalpy back, which the script's classes cannot) is real."""
    kiln, sol = dispersed
    assert abs(sol.energy_closure) < 1e-6
    assert 100 * outlet_yield(sol, "char") == pytest.approx(19.04, abs=2.0)
    assert sol.t_bed_nodes[-1] == pytest.approx(684.08, abs=20.0)
    assert _bed_deviation(sol, RTD, z_min=0.3).max() < 30.0
    assert _bed_deviation(sol, RTD).max() > 30.0


def test_segregated_classes_as_the_script(plug):
    """The script's own RTD treatment (segregated classes of the Pe 5 closed-closed RTD over one
    bed temperature profile) over our plug-flow profile: char yield 19.04 % within 2 points
    (the module docstring's tolerance); the RTD lowers the yield, as in the script (by 1.68
    points there), mainly by intermediate solid carried out by early classes."""
    kiln, sol = plug
    r = segregated_yields(kiln, sol, peclet=5.0)
    assert r["tau"] == pytest.approx(551.96, abs=0.3)
    assert 100 * r["rtd"]["char"] == pytest.approx(19.04, abs=2.0)
    assert r["rtd"]["char"] < r["plug"]["char"]
    assert r["rtd"]["intermediate_solid"] > r["plug"]["intermediate_solid"]


def test_jacket_gas_balance_closes(plug):
    """The jacket's own balance closes to round-off and its duty is the energy sheet's
    heating; the duty against the script's flue-gas duty in plug flow, 9.11 kW (heat to bed,
    gas and loss: 6.06 + 0.47 + 2.58 kW), within 5 %: the script's wall is its flue gas as here,
    and its heat flows differ from ours by the closures of its known errors (a few per cent)."""
    kiln, sol = plug
    jb = jacket_balance(kiln, sol)
    assert abs(jb["closure_relative"]) < 1e-6
    assert jb["duty_W"] == pytest.approx(sol.energy_sheet["electric_heating_W"], rel=1e-9)
    assert jb["duty_W"] == pytest.approx(9110.0, rel=0.05)


def test_shrinking_bed_is_an_override():
    """``transport.shrinkage: 30 %`` (chips that lose 30 % of their volume when charred, a
    variant the script has not): a thinner, faster bed, the yield within the plug-flow target
    of the script (20.72 % within 2 points: shrinkage is not one of its known errors, and
    shortens the hold-up by only ~3 %)."""
    kiln, sol = _solved({**PLUG_FLOW, "transport.shrinkage": "30 %"})
    assert kiln.bed.depth.shrinkage == pytest.approx(0.3)
    assert abs(sol.energy_closure) < 1e-6
    assert sol.residence_time < 551.96 - 10.0
    h = KilnResidual(kiln, sol.z.size).depth_faces(sol.fluxes["x"])
    assert h[0] < 0.05168 - 2e-3  # the feed end's depth: 48.4 mm against 51.7 mm
    assert 100 * outlet_yield(sol, "char") == pytest.approx(20.72, abs=2.0)
