"""The burner's recirculation zone as a well-stirred reactor (burner.combustion: stirred;
flames.md section 7): the fuel's heat enters with the products, the zone's gas is mixed over
the recirculation length, energy closes, and the zone leaves below the adiabatic temperature."""

from __future__ import annotations

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln


def _barr(counter_current=True, **burner):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    data["operation"]["counter_current"] = counter_current
    data["burner"].update(burner)
    return data


@pytest.fixture(scope="module")
def stirred():
    kiln, _ = kiln_from_case(parse_case(_barr(combustion="stirred", nozzle_diameter="40 mm")))
    return kiln, solve_kiln(kiln, 100)


def test_zone_is_the_recirculation_length_from_the_burner(stirred):
    kiln, _ = stirred
    z0, z1, k = kiln.firing.stirred_zone
    assert z1 == kiln.drum.length
    assert z1 - z0 == pytest.approx(kiln.firing.flame.recirculation_length)
    assert 0.5 < z1 - z0 < 1.5  # Thring-Newby x_w of a 40 mm nozzle in the 0.411 m kiln
    assert k > 0 and kiln.firing.heat_release == 0.0  # the heat enters with the products


def test_zone_gas_is_well_mixed_and_below_the_adiabatic_temperature(stirred):
    kiln, sol = stirred
    z0 = kiln.firing.stirred_zone[0]
    zone = (sol.z_nodes >= z0) & (sol.z_nodes < kiln.drum.length)
    t = sol.t_gas_nodes[zone]
    t_ad = kiln.firing.flame.adiabatic_temperature
    assert np.ptp(t) < 5.0  # stirred: a few K across the zone
    assert np.all(t < t_ad)  # the zone loses heat to wall and bed
    assert t_ad - t.mean() < 80.0
    # plug flow beyond the zone: the gas keeps cooling towards the feed end
    assert np.all(np.diff(sol.t_gas_nodes[sol.z_nodes < z0]) > 0)


def test_energy_and_elements_close(stirred):
    _, sol = stirred
    assert abs(sol.energy_closure) < 1e-6
    assert max(sol.element_closure.values()) < 1e-8
    s = sol.energy_sheet
    assert s["combustion_heat_W"] == pytest.approx(s["fuel_lhv_input_W"], rel=2e-3)


def test_co_current_zone_at_the_feed_end():
    data = _barr(counter_current=False, combustion="stirred", recirculation_length="0.8 m")
    kiln, _ = kiln_from_case(parse_case(data))
    assert kiln.firing.stirred_zone[:2] == (0.0, 0.8)
    sol = solve_kiln(kiln, 50)
    assert abs(sol.energy_closure) < 1e-6
    zone = (sol.z_nodes > 0.0) & (sol.z_nodes <= 0.8)
    assert np.ptp(sol.t_gas_nodes[zone]) < 5.0


@pytest.mark.parametrize(
    ("burner", "match"),
    [
        ({"combustion": "stirred"}, "burner.recirculation_length"),
        ({"combustion": "stirred", "recirculation_length": "6 m"}, "<= the kiln length"),
        ({"combustion": "stirred", "recirculation_length": "0 m"}, "recirculation_length"),
    ],
)
def test_bad_stirred_input_refused(burner, match):
    with pytest.raises(InputError, match=match):
        kiln_from_case(parse_case(_barr(**burner)))
