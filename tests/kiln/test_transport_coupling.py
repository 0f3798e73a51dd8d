"""The kiln model takes its bed fill from the axial transport model when the case has a
``transport:`` section (Kramers or Scott, with a dam)."""

import numpy as np
import pytest

from rotarykiln.case import parse_case
from rotarykiln.commands.kiln_runs import run_kiln_case
from rotarykiln.commands.model_runs import bed_fill_profile
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.transport.kramers import kramers_uniform_depth

CASE = {
    "name": "coupled",
    "kiln": {"length": "2.44 m", "diameter": "0.1885 m", "slope": "1.2 deg"},
    "operation": {"speed": "1.5 rpm", "feed": "14.2 kg/h"},
    "material": {
        "bulk_density": "1650 kg/m3",
        "repose_angle": "27 deg",
        "particle_size": "0.73 mm",
        "solid": "sand",
    },
    "transport": {"model": "kramers", "dam_height": "6 cm"},
    "gas": {"flow": "24.6 kg/h", "temperature": "535 K"},
    "wall": {
        "lining": [
            {"material": "refractory_cement", "thickness": "12.7 mm"},
            {"material": "carbon_steel", "thickness": "6.35 mm"},
        ],
    },
}


def test_fill_follows_the_bed_profile():
    case = parse_case(CASE)
    z, fill = bed_fill_profile(case)
    kiln, _ = kiln_from_case(case)
    assert np.allclose(kiln.fill_at(z), fill)
    # the 6 cm dam holds the bed above the uniform (closed-form) depth, which the profile
    # approaches from above towards the feed end
    r = case.kiln.diameter / 2
    q = case.operation.feed / case.material.bulk_density
    h_uniform = kramers_uniform_depth(
        q, r, case.operation.speed, case.kiln.slope, case.material.repose_angle
    )
    from rotarykiln.geometry import fill_from_depth

    uniform = float(fill_from_depth(h_uniform, r))
    assert fill[-1] == pytest.approx(float(fill_from_depth(0.06, r)), rel=1e-6)
    assert np.all(np.diff(fill) >= -1e-12)
    assert uniform < fill[0] < fill[-1]


@pytest.mark.parametrize("model", ["kramers", "scott"])
def test_coupled_solve_closes_energy(model):
    data = {**CASE, "transport": {"model": model, "dam_height": "6 cm"}}
    sol = run_kiln_case(parse_case(data))
    assert abs(sol.energy_closure) < 1e-6
    assert 298 < sol.summary()["bed_outlet_temperature_K"] < 535


def test_rtd_prediction_uses_the_transport_mean_residence_time(tmp_path):
    from rotarykiln.commands.model_runs import rtd_runner, transport_mean_residence_time

    data = {
        "name": "rtd from transport",
        "kiln": {"length": "1.95 m", "diameter": "0.1013 m", "slope": "2 deg"},
        "operation": {"speed": "3 rpm", "feed": "2.5 kg/h"},
        "material": {
            "bulk_density": "1422 kg/m3",
            "repose_angle": "35 deg",
            "particle_size": "0.55 mm",
        },
        "transport": {"model": "kramers", "dam_height": "23.5 mm"},
        "rtd": {"correlation": "bongo_njeng2015", "model": "open-open", "peclet": 50},
    }
    case = parse_case(data)
    mrt = transport_mean_residence_time(case)
    summary = rtd_runner(case, tmp_path)
    assert summary["rtd_mean_residence_time_s"] == pytest.approx(mrt, rel=1e-9)
    # mean residence time = hold-up / volumetric feed, by another route
    from rotarykiln.commands.model_runs import bed_profile_from_case

    holdup = bed_profile_from_case(case).holdup_volume
    assert holdup == pytest.approx(mrt * case.operation.feed / case.material.bulk_density, rel=1e-6)
