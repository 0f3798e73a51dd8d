"""Electric heater zones on the shell (issue 11, heating modes): a power, or a shell set-point."""

from __future__ import annotations

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.kiln.wall.lining import HeaterZone


def _tscheng_a16():
    """Tscheng's run A16 as its built-in case builds it (the kiln users run)."""
    kiln, _ = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    return kiln


@pytest.fixture(scope="module")
def plain():
    return solve_kiln(_tscheng_a16())


def test_power_zone_heats_and_the_balance_counts_it(plain):
    kiln = _tscheng_a16().replace(wall__heaters=(HeaterZone(1.0, 2.0, power=500.0),))
    sol = solve_kiln(kiln)
    dz = sol.z[1] - sol.z[0]
    assert np.sum(sol.fluxes["q_electric_heating"]) * dz == pytest.approx(500.0, rel=1e-9)
    assert sol.energy_sheet["electric_heating_W"] == pytest.approx(500.0, rel=1e-9)
    assert abs(sol.energy_closure) < 1e-6 and abs(sol.energy_sheet["closure_relative"]) < 1e-6
    assert sol.bed_outlet_temperature > plain.bed_outlet_temperature + 5.0
    inside = (sol.z > 1.1) & (sol.z < 1.9)
    assert np.all(sol.t_shell[inside] > plain.t_shell[inside] + 20.0)


def test_setpoint_zone_holds_the_shell_and_reports_its_power(plain):
    zone = HeaterZone(0.5, 2.0, shell_temperature=600.0)
    sol = solve_kiln(_tscheng_a16().replace(wall__heaters=(zone,)))
    held = (sol.z > 0.5) & (sol.z < 2.0)
    assert np.allclose(sol.t_shell[held], 600.0, atol=1e-6)
    q = sol.fluxes["q_electric_heating"]
    assert np.all(q[held] > 0) and np.all(q[~held] == 0)
    assert abs(sol.energy_closure) < 1e-6
    assert sol.bed_outlet_temperature > plain.bed_outlet_temperature


def test_setpoint_at_the_unheated_shell_temperature_needs_no_power(plain):
    j = 60
    zone = HeaterZone(
        float(plain.z[j] - 0.01),
        float(plain.z[j] + 0.01),
        shell_temperature=float(plain.t_shell[j]),
    )
    sol = solve_kiln(_tscheng_a16().replace(wall__heaters=(zone,)))
    assert abs(sol.fluxes["q_electric_heating"][j]) < 1e-3  # W/m
    assert np.max(np.abs(sol.t_bed_nodes - plain.t_bed_nodes)) < 1e-6


@pytest.mark.parametrize(
    ("kw", "match"),
    [
        (dict(start=1.0, end=0.5, power=10.0), "0 <= start < end"),
        (dict(start=0.0, end=1.0), "either a power or a shell_temperature"),
        (dict(start=0.0, end=1.0, power=10.0, shell_temperature=500.0), "either a power"),
        (dict(start=0.0, end=1.0, power=-1.0), "heaters.power"),
    ],
)
def test_bad_zones(kw, match):
    with pytest.raises(InputError, match=match):
        HeaterZone(**kw)


def test_zone_beyond_the_kiln_or_without_lining():
    kiln = _tscheng_a16()
    with pytest.raises(InputError, match="heaters.*kiln length"):
        kiln.replace(wall__heaters=(HeaterZone(1.0, 3.0, power=10.0),))
    with pytest.raises(InputError, match="heaters.*lining"):
        kiln.replace(wall__layers=(), wall__heaters=(HeaterZone(1.0, 2.0, power=10.0),))
    with pytest.raises(InputError, match="heaters.*do not overlap"):
        kiln.replace(
            wall__heaters=(HeaterZone(1.0, 2.0, power=10.0), HeaterZone(0.5, 1.5, power=5.0))
        )
    touching = (HeaterZone(0.0, 1.0, power=10.0), HeaterZone(1.0, 2.0, power=5.0))
    assert kiln.replace(wall__heaters=touching).wall.heaters == touching


def test_heaters_from_a_case_file():
    import yaml

    from rotarykiln.case import parse_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.commands.kiln_runs import run_kiln_case

    data = yaml.safe_load(builtin_case_path("tscheng_A16").read_text())
    data["wall"]["heaters"] = [
        {"start": "1 m", "end": "2 m", "power": "0.5 kW"},
        {"start": "0.2 m", "end": "0.6 m", "shell_temperature": "150 degC"},
    ]
    sol = run_kiln_case(parse_case(data))
    s = sol.summary()
    assert s["energy_electric_heating_W"] > 500.0  # the set-point zone adds its own power
    held = (sol.z > 0.2) & (sol.z < 0.6)
    assert np.allclose(sol.t_shell[held], 423.15, atol=1e-6)
    data["wall"]["heaters"] = [{"start": "1 m", "end": "2 m"}]
    with pytest.raises(InputError, match="heaters"):
        run_kiln_case(parse_case(data))
