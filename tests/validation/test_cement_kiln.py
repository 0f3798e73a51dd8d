"""The built-in dry-process cement kiln (``cement_kiln``) against the ranges its sources give.

The case (src/rotarykiln/cases/cement_kiln.yaml; every input's source or assumption is in its
header, written before the first run) is a 70 m x 4.4 m precalciner kiln making 4257 t/d of
clinker, fed with a 92.5 % precalcined raw meal at 875 degC, its burner firing 40 % of a plant
SHC of 3515 MJ/t (Pittsburgh No. 8 coal, its burn-out along the kiln) with secondary air at 1050 degC, with the
clinker mechanism of reactions/clinker.yaml (recalled Mastorakos constants). Nothing in it was
fitted to the quantities below. Keys: cement_lime.md section 8; [MEMORY] ranges are recalled
typical values (the note's section 6.1 "Temperatures", moderate confidence).

Computed at 200 cells (a check the case misses is an ``xfail(strict=True)`` with its value):

| quantity | computed | range | source | result |
|---|---|---|---|---|
| element closure; energy closure | 1.7e-16; 6.6e-12 | <= 1e-8; <= 1e-6 | the solver | pass |
| kiln-burner heat per t clinker | 1400 MJ/t (coal ash in the clinker) | 1200-1600 MJ/t (40 % of 3000-4000) | PHYS, CN60 | pass |
| exhaust (kiln-inlet) gas | 1242 degC | 1000-1200 degC | MEMORY | xfail |
| burning-zone material, peak bed | 1978 degC (at the discharge) | 1400-1450 degC | MEMORY | xfail |
| burning-zone gas, mean over z = 45-68 m | 2091 degC (peak 2315) | 1700-2000 degC | MEMORY | xfail |
| clinker free lime | 0.00 % | <= 2 % (held at about 1-2 % or less) | MEMORY (note 1.4) | pass |
| clinker phases vs Bogue of its oxides | C3S 56.96, C2S 21.43, C3A 9.18, C4AF 10.26 % (Bogue the same) | within Taylor's spread of Bogue | TAY89 via CLK | pass |
| shell under full coating (z = 45-68 m) | 271-309 degC | 200-300 degC | MEMORY | xfail |
| shell, hottest | 423 degC (z = 40.1 m, coating starting) | < 350 degC | WIKIRK | xfail |
| shell loss / kiln-burner fuel (LHV) | 12.2 % | 5-15 % | FARAG, ENGIN (MAST: about 10 %) | pass |

The burning zone is the stretch the case puts a priori under full coating (z = 45-68 m, the last
25 m less the nose). What the misses say: with 40 % of 3515 MJ/t at the burner, 1050 degC
secondary air and the meal at 875 degC, the kiln receives about 0.7 MJ per kg of clinker (35 MW)
more than heating the clinker to 1450 degC, the residual calcination, the shell and an exhaust
at 1100 degC take (the solution's energy sheet moved to those temperatures with mean heat
capacities; the clinker reactions are exothermic, -0.31 MJ/kg from this feed); the model
has no melt latent heat, no dust or bypass and no alkali cycle, and the surplus heats bed, wall
and exhaust. The burning coal particles radiate (their grey emissivity added to the gas's over
the first metres from the burner, where they burn out at these temperatures): that moved the
numbers by under 10 K, as the surplus, not the flame's emissivity, sets them. With the recalled constants the clinker burns
through at that temperature: belite, aluminate and ferrite form in the first 0.5 m (the bed
jumps from 1148 to 1460 K on their heat), alite from 1598 K at z = 19.8 m, the lime is 99 %
combined at z = 41 m (bed 1968 K).
"""

import numpy as np
import pytest
from clinker_checks import assert_phases_within_taylor

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry import clinker as ck
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln

pytestmark = pytest.mark.filterwarnings("ignore::rotarykiln.errors.OutOfRangeWarning")

C = 273.15
#: the burning zone of the case: the stretch under full coating (its header), m
BURNING_ZONE = (45.0, 68.0)


@pytest.fixture(scope="module")
def solved():
    case = load_case(builtin_case_path("cement_kiln"))
    kiln, cells = kiln_from_case(case)
    return case, kiln, solve_kiln(kiln, cells)


def _clinker_flow(sol):
    return sum(float(np.asarray(q)[-1]) for q in sol.bed_flows.values())


def _in_burning_zone(sol):
    z = np.asarray(sol.z)
    return (z >= BURNING_ZONE[0]) & (z <= BURNING_ZONE[1])


def test_cement_kiln_balances_close(solved):
    _, _, sol = solved
    assert max(sol.element_closure.values()) <= 1e-8
    assert abs(sol.energy_closure) <= 1e-6
    assert abs(sol.energy_sheet["closure_relative"]) <= 1e-6
    for flows in (sol.bed_flows, sol.gas_flows):
        for name, q in flows.items():
            assert np.all(np.asarray(q) >= 0.0), name


def test_cement_kiln_burner_heat_per_tonne(solved):
    # 40 % of the fuel at the kiln burner [CN60] of a 3000-4000 MJ/t precalciner plant [PHYS]
    _, _, sol = solved
    q = sol.energy_sheet["fuel_lhv_input_W"] / _clinker_flow(sol) / 1e3  # MJ/t = kJ/kg
    assert 0.40 * 3000.0 <= q <= 0.40 * 4000.0, q


@pytest.mark.xfail(strict=True, reason="exhaust 1242 degC (1515 K), above 1000-1200 degC")
def test_cement_kiln_exhaust_temperature(solved):
    _, _, sol = solved
    t = sol.exhaust["temperature_K"] - C
    assert 1000.0 <= t <= 1200.0, t


@pytest.mark.xfail(strict=True, reason="peak bed 1978 degC (2251 K), above 1400-1450 degC")
def test_cement_kiln_burning_zone_material(solved):
    _, _, sol = solved
    t = float(np.max(sol.t_bed_nodes)) - C
    assert 1400.0 <= t <= 1450.0, t


@pytest.mark.xfail(
    strict=True, reason="burning-zone gas 2091 degC (mean, z = 45-68 m), above 1700-2000 degC"
)
def test_cement_kiln_burning_zone_gas(solved):
    _, _, sol = solved
    t = float(np.mean(np.asarray(sol.t_gas)[_in_burning_zone(sol)])) - C  # uniform cells
    assert 1700.0 <= t <= 2000.0, t


def test_cement_kiln_clinker_outlet(solved):
    _, kiln, sol = solved
    rep = ck.clinker_report(sol, feed=kiln.feed.flows)
    # free lime held at about 1-2 % or less [MEMORY, cement_lime.md 1.4]
    assert rep.free_lime <= 0.02, rep.free_lime
    assert rep.loss_on_ignition <= 1e-3, rep.loss_on_ignition
    # each phase within what separates real phases from Bogue's pure ones (Taylor 1989 rows)
    assert_phases_within_taylor(rep)


def _shell_under_coating(case, sol):
    zk, tk = zip(*case.wall.lining[0].thickness_profile, strict=True)
    coating = np.interp(sol.z, zk, tk)
    return np.asarray(sol.t_shell)[coating >= max(tk) - 1e-9] - C


@pytest.mark.xfail(strict=True, reason="shell under full coating 271-309 degC, above 200-300 degC")
def test_cement_kiln_shell_under_coating(solved):
    case, _, sol = solved
    t = _shell_under_coating(case, sol)
    assert t.size > 0
    assert 200.0 <= t.min() and t.max() <= 300.0, (t.min(), t.max())


@pytest.mark.xfail(
    strict=True, reason="hottest shell 423 degC (z = 40.1 m, coating starting), not < 350"
)
def test_cement_kiln_shell_below_350(solved):
    _, _, sol = solved
    t = float(np.max(sol.t_shell)) - C
    assert t < 350.0, t


def test_cement_kiln_shell_loss_share(solved):
    # 12 % of input [FARAG], 15.11 % [ENGIN], about 10 % [MAST]
    _, _, sol = solved
    share = sol.energy_sheet["shell_loss_W"] / sol.energy_sheet["fuel_lhv_input_W"]
    assert 0.05 <= share <= 0.15, share
