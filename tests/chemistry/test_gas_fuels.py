"""Heating values of gaseous fuels (chemistry/gas_fuels.py)."""

import pytest

from rotarykiln.chemistry.gas_fuels import heating_values
from rotarykiln.materials.gas import fuel_data, parse_composition


def test_methane_heating_values_of_the_flames_note():
    lhv, hhv = heating_values("CH4:1")
    assert lhv == pytest.approx(50.03e6, rel=2e-4)
    # HHV - LHV: 2 mol of water condensed per mol of CH4, 44.004 kJ/mol
    assert hhv - lhv == pytest.approx(2 * 44.004e3 / 0.016043, rel=1e-3)


def test_heating_values_are_those_of_the_fuel_data():
    fuel = "CH4:0.9, C2H6:0.05, N2:0.05"
    assert heating_values(fuel) == fuel_data(parse_composition(fuel))[2:]


def test_a_fuel_without_hydrogen_has_equal_heating_values():
    lhv, hhv = heating_values("CO:1")
    assert lhv == pytest.approx(hhv, rel=1e-12)
    assert lhv == pytest.approx(10.1e6, rel=0.01)  # 283 kJ/mol / 28.01 g/mol
