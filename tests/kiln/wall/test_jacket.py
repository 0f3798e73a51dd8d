"""Heating jacket (kiln/wall/jacket.py): its own energy balance closes, co- and counter-current."""

import numpy as np
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import InputError
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.kiln.wall.jacket import Jacket, jacket_balance

pytestmark = pytest.mark.filterwarnings("ignore::rotarykiln.errors.OutOfRangeWarning")


@pytest.mark.parametrize(
    "jacket",
    [
        dict(htc=60.0),
        dict(htc=60.0, counter_current=True),
        dict(htc="annulus", gap=0.02),
        dict(htc=60.0, cp=None, composition="N2:0.72, CO2:0.09, H2O:0.17, O2:0.02"),
    ],
)
def test_jacket_gas_balance_closes(jacket):
    case = load_case(builtin_case_path("rotary_pyrolysis"))  # the pyrolysis kiln, plug flow
    kiln, _ = kiln_from_case(case.replace({"bed.axial_dispersion": "plug"}))
    j = kiln.wall.jacket
    spec = dict(
        mass_flow=j.mass_flow,
        inlet_temperature=900.0,
        cp=j.cp,
        casing_u=j.casing_u,
    )
    spec.update(jacket)

    kiln = kiln.replace(wall__jacket=Jacket(**spec))
    sol = solve_kiln(kiln, 40)
    jb = jacket_balance(kiln, sol)
    assert abs(jb["closure_relative"]) < 1e-6
    assert abs(sol.energy_closure) < 1e-6
    assert jb["duty_W"] == pytest.approx(sol.energy_sheet["electric_heating_W"], rel=1e-9)
    # the jacket gas cools along its flow and stays above the wall it heats
    x = sol.fluxes["x"]
    tj = x[:, 3]
    if spec.get("counter_current"):
        tj = tj[::-1]
    assert np.all(np.diff(tj) < 0)
    assert jb["outlet_temperature_K"] < 900.0


@pytest.mark.parametrize(
    "kw, match",
    [
        (dict(mass_flow=-1.0), "jacket.mass_flow"),
        (dict(htc="hot"), "jacket.htc"),
        (dict(htc=-5.0), "jacket.htc"),
        (dict(cp=None), "jacket.cp"),
        (dict(composition="N2:1"), "jacket.cp"),
        (dict(gap=0.0), "jacket.gap"),
        (dict(eps_drum=1.5), "jacket.eps_drum"),
    ],
)
def test_bad_jacket_refused(kw, match):
    spec = dict(mass_flow=0.05, inlet_temperature=833.0, cp=1200.0)
    spec.update(kw)
    with pytest.raises(InputError, match=match) as err:
        Jacket(**spec)
    assert "\n" not in str(err.value)
