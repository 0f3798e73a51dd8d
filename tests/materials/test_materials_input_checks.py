"""burn_fuel: extreme air/fuel ratios give InputError (too little air) or a value (very lean),
not the ValueError of scipy's bracket."""

import pytest

from rotarykiln.errors import InputError
from rotarykiln.materials.gas import burn_fuel


def test_too_little_air_is_an_input_error_naming_air_flow():
    with pytest.raises(InputError, match="air_flow"):
        burn_fuel("CH4:1", 1.0e-3, 1.9e-8)


def test_a_trace_of_fuel_leaves_the_products_near_the_inlet_temperature():
    # was "ValueError: f(a) and f(b) must have different signs": the products (equilibrium
    # at 1200 K, with a little endothermic NO) sit a hair below the inlet temperature
    burnt = burn_fuel("CH4:1", 1.0e-9, 1.9e-2)
    assert abs(burnt.adiabatic_temperature - burnt.inlet_temperature) < 2.0
