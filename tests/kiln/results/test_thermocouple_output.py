"""The gas through a bare thermocouple beside the raw gas temperature, and the RMSE against the
measurements in the summary (measurements.thermocouple, issue 10 item 6)."""

from __future__ import annotations

import numpy as np
import pytest
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.heat.thermocouple import bare_thermocouple_temperature
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln


def _barr(thermocouple=None):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text())
    if thermocouple is not None:
        data["measurements"]["thermocouple"] = thermocouple
    return data


@pytest.fixture(scope="module")
def solution():
    kiln, _ = kiln_from_case(parse_case(_barr({"diameter": "3.2 mm", "emissivity": 0.8})))
    return solve_kiln(kiln, 50)


def test_the_reading_sits_beside_the_raw_gas_temperature(solution):
    df = solution.to_frame()
    assert {"T_gas_K", "T_gas_thermocouple_K"} <= set(df.columns)
    assert df.attrs["units"]["T_gas_thermocouple_K"] == "K"
    tc, gas, bed = df["T_gas_thermocouple_K"], df["T_gas_K"], df["T_bed_K"]
    # the junction sees the colder bed and wall: it reads below the gas, above the bed
    assert np.all(tc < gas) and np.all(tc > bed)


def test_the_reading_is_the_junction_balance_of_the_cell(solution):
    j = 20
    t_s = (0.5 * solution.t_bed[j] ** 4 + 0.5 * solution.t_wall[j] ** 4) ** 0.25
    u = solution.fluxes["gas_velocity"][j]
    expected = bare_thermocouple_temperature(solution.t_gas[j], t_s, u, 3.2e-3, 0.8)
    assert solution.gas_thermocouple(3.2e-3, 0.8)[j] == pytest.approx(expected, rel=1e-12)
    # the freeboard velocity of T4: about 62 NL/s of flue gas at ~1000 K over ~0.12 m2
    assert 1.0 < u < 3.0


def test_summary_scores_the_measurements_raw_and_through_the_thermocouple(solution):
    s = solution.summary()
    for key in ("rmse_bed_K", "rmse_gas_K", "rmse_gas_thermocouple_K", "rmse_wall_K"):
        assert s[key] > 0
    m = solution.measurements
    raw = np.sqrt(np.mean((solution.gas_temperature_at(m["z_gas"]) - m["t_gas"]) ** 2))
    assert s["rmse_gas_K"] == pytest.approx(raw, rel=1e-12)


def test_without_a_thermocouple_no_column_and_no_thermocouple_score():
    kiln, _ = kiln_from_case(parse_case(_barr()))
    sol = solve_kiln(kiln, 20)
    assert "T_gas_thermocouple_K" not in sol.to_frame().columns
    assert "rmse_gas_thermocouple_K" not in sol.summary()
    assert "rmse_bed_K" in sol.summary()


@pytest.mark.parametrize(
    ("tc", "match"),
    [
        ({"diameter": "0 mm"}, "thermocouple.diameter"),
        ({"diameter": "3 mm", "emissivity": 1.5}, "thermocouple.emissivity"),
        ({"diameter": "3 mm", "bed_view": 2}, "thermocouple.bed_view"),
        ({"emissivity": 0.8}, "thermocouple.diameter"),
    ],
)
def test_bad_thermocouple_refused_at_load(tc, match):
    with pytest.raises(InputError, match=match):
        parse_case(_barr(tc))
