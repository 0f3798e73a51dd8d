"""Input checks of the user-facing chemistry functions: InputError naming the argument."""

import numpy as np
import pytest

from rotarykiln.chemistry import pyrolysis, segregated
from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.chemistry.plugflow import integrate_plug_flow
from rotarykiln.errors import InputError

NAN = float("nan")
CASES = [
    (
        pyrolysis.berkovich_conversion,
        {"T": 793.0, "T_low": 743.0, "decay_constant": 21.71},
        "T",
        NAN,
    ),
    (
        pyrolysis.berkovich_conversion,
        {"T": 793.0, "T_low": 743.0, "decay_constant": 21.71},
        "T_low",
        NAN,
    ),
    (pyrolysis.berkovich_reaction_enthalpy, {"T": 900.0}, "T", -900.0),
    (pyrolysis.wen_yen_kerogen_rates, {"x1": 1.0, "x2": 0.0, "T": 723.0}, "x1", NAN),
    (pyrolysis.wen_yen_kerogen_rates, {"x1": 1.0, "x2": 0.0, "T": 723.0}, "x2", -0.1),
]


@pytest.mark.parametrize(("func", "kwargs", "arg", "bad"), CASES)
def test_bad_value_raises_input_error_naming_the_argument(func, kwargs, arg, bad):
    assert np.all(np.isfinite(func(**kwargs)))
    with pytest.raises(InputError, match=arg):
        func(**{**kwargs, arg: bad})


def test_berkovich_conversion_no_longer_turns_nan_into_zero():
    # np.where(T > T_low, ...) sent a NaN temperature to the "not started" branch: X = 0
    with pytest.raises(InputError):
        pyrolysis.berkovich_conversion(np.array([800.0, NAN]), 743.0, 21.71)


def test_plug_flow_rejects_a_negative_bed_temperature():
    mech = Mechanism.builtin("calcination_luisser")
    with pytest.raises(InputError, match="T_bed"):
        integrate_plug_flow(mech, {"CaCO3": 1e-3}, length=1.0, velocity=1e-3, T_bed=-1100.0)


def test_segregated_average_rejects_a_non_integer_grid():
    with pytest.raises(InputError, match="rtd.n"):
        segregated.segregated_average(
            lambda t: 1 - np.exp(-t), lambda t: np.exp(-t), t_max=10.0, n=float("nan")
        )


def test_empty_mechanism_is_an_inert_one():
    # an inert kiln is a kiln without reactions: the empty mechanism gives zero rates
    from rotarykiln.chemistry.mechanism import CellState, Mechanism

    mech = Mechanism([])
    out = mech.rates(
        CellState.build(
            T_bed=500.0, T_gas=600.0, bed_mass_flow={"inert": 1.0}, bed_mass_per_length=10.0
        )
    )
    assert out.production.shape[0] == 1 and not out.production.any()
    assert not np.any(out.heat_absorbed)
