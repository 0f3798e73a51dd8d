"""Input checks of the RTD helpers: InputError naming the argument instead of numpy errors."""

import pytest

from rotarykiln.errors import InputError
from rotarykiln.rtd.dispersion_pde import dirac_inlet, solve_dispersion_pde
from rotarykiln.rtd.internals import loading_lifter_area


@pytest.mark.parametrize(
    ("arg", "bad"), [("cells_per_length", 0), ("cells_per_length", 100.5), ("n_out", -3)]
)
def test_pde_grid_sizes_are_checked(arg, bad):
    # were ZeroDivisionError / TypeError / ValueError from numpy
    with pytest.raises(InputError, match=arg):
        solve_dispersion_pde(
            10.0, dirac_inlet(), 6.0, **{"cells_per_length": 200, "n_out": 601, arg: bad}
        )


def test_lifter_count_nan_is_an_input_error():
    # was "ValueError: cannot convert float NaN to integer"
    with pytest.raises(InputError, match="n_lifters"):
        loading_lifter_area(float("nan"), 3.9e-5)
