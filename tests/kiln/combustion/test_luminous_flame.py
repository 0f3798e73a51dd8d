"""A luminous (sooting) flame: soot emissivity added to the gas's over the flame length."""

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.errors import InputError
from rotarykiln.heat.gas_radiation import combined_emissivity, soot_emissivity
from rotarykiln.kiln.from_case import kiln_from_case


def _barr(**burner):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    data["burner"].update(nozzle_diameter="40 mm", **burner)
    return data


def test_soot_emissivity_limits():
    # optically thin: eps_s -> kappa L with kappa = 1810 f_v T; thick: -> 1
    thin = soot_emissivity(1e-9, 1500.0, 0.1)
    assert thin == pytest.approx(1809.8 * 1e-9 * 1500.0 * 0.1, rel=1e-3)
    assert soot_emissivity(1e-4, 2000.0, 1.0) == pytest.approx(1.0)
    assert combined_emissivity(0.3, 0.0) == 0.3
    assert combined_emissivity(1.0, 0.4) == pytest.approx(1.0)
    with pytest.raises(InputError):
        soot_emissivity(-1e-8, 1500.0, 0.1)


def test_zero_soot_is_the_non_luminous_flame():
    a = run_kiln_case(parse_case(_barr()))
    b = run_kiln_case(parse_case(_barr(soot_volume_fraction=0.0)))
    assert np.array_equal(a.t_bed_nodes, b.t_bed_nodes)


def test_soot_raises_the_emissivity_in_the_flame_zone_only():
    plain = run_kiln_case(parse_case(_barr()))
    data = _barr(soot_volume_fraction=1e-6)
    kiln, _ = kiln_from_case(parse_case(data))
    f_v, z0, z1 = kiln.firing.soot
    assert f_v == 1e-6 and z1 == pytest.approx(kiln.drum.length)
    assert 0.3 < z1 - z0 < 1.0  # the Hawthorne-Weddell-Hottel length of the 40 mm nozzle
    sooty = run_kiln_case(parse_case(data))
    z = 0.5 * (plain.z_nodes[1:] + plain.z_nodes[:-1])
    inside = z > z0 + 0.06
    outside = z < z0 - 0.06
    eps0, eps1 = plain.fluxes["eps_gas"], sooty.fluxes["eps_gas"]
    assert np.all(eps1[inside] > eps0[inside] + 0.1)
    # outside the flame the emissivity changes only through the (slightly) changed gas state
    assert np.max(np.abs(eps1[outside] - eps0[outside])) < 0.01
    assert abs(sooty.energy_closure) < 1e-6
    # a brighter flame gives more heat to the bed near the burner
    assert sooty.t_bed_nodes[-1] > plain.t_bed_nodes[-1] + 10.0


def test_co_current_luminous_zone_sits_at_the_feed_end():
    data = _barr(soot_volume_fraction=5e-8)
    data["operation"]["counter_current"] = False
    kiln, _ = kiln_from_case(parse_case(data))
    assert kiln.firing.soot[1] == 0.0 and kiln.firing.soot[2] < 1.0
    assert abs(run_kiln_case(parse_case(data)).energy_closure) < 1e-6


@pytest.mark.parametrize(
    "burner, message",
    [
        ({"nozzle_diameter": None, "soot_volume_fraction": 5e-8}, "burner.soot_volume_fraction"),
        ({"soot_volume_fraction": -1e-8}, "burner.soot_volume_fraction"),
        ({"soot_volume_fraction": 0.01}, "burner.soot_volume_fraction"),
    ],
)
def test_bad_soot_inputs_are_refused(burner, message):
    data = _barr()
    for k, v in burner.items():
        if v is None:
            data["burner"].pop(k)
        else:
            data["burner"][k] = v
    with pytest.raises(InputError, match=message):
        kiln_from_case(parse_case(data))
