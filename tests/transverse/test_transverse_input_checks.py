"""Input checks of the transverse-motion functions: InputError naming the argument."""

import numpy as np
import pytest

from rotarykiln.errors import InputError
from rotarykiln.transverse import active_layer, heating, mixing, pyrolysis

NAN = float("nan")
CASES = [
    (
        active_layer.vanpuyvelde_centre_of_rotation,
        {"apex_a": (0.0, 0.0), "apex_b": (0.5, 0.0), "r_a": 0.25, "theta_a": 0.17},
        "theta_a",
        NAN,
    ),
    (
        active_layer.vanpuyvelde_centre_of_rotation,
        {"apex_a": (0.0, 0.0), "apex_b": (0.5, 0.0), "r_a": 0.25, "theta_a": 0.17},
        "apex_b",
        (NAN, 0.0),
    ),
    (heating.thomas_sphere_nusselt, {"rayleigh": 1e3, "prandtl": 0.7}, "rayleigh", NAN),
    (heating.thomas_sphere_nusselt, {"rayleigh": 1e3, "prandtl": 0.7}, "prandtl", -0.7),
    (
        heating.natural_convection_coefficient,
        {"d_p": 2e-3, "t_particle": 1050.0, "t_gas": 800.0},
        "t_particle",
        NAN,
    ),
    (
        heating.natural_convection_coefficient,
        {"d_p": 2e-3, "t_particle": 1050.0, "t_gas": 800.0},
        "t_gas",
        -800.0,
    ),
    (
        heating.radiation_to_shale,
        {
            "a_ash": 1.0,
            "t_ash_mean": 1000.0,
            "a_shale_class": np.array([0.5, 0.5]),
            "t_shale_class": np.array([500.0, 500.0]),
            "extent": 1.0,
        },
        "extent",
        1.5,
    ),
    (
        heating.radiation_to_shale,
        {
            "a_ash": 1.0,
            "t_ash_mean": 1000.0,
            "a_shale_class": np.array([0.5, 0.5]),
            "t_shale_class": np.array([500.0, 500.0]),
            "extent": 1.0,
        },
        "t_ash_mean",
        NAN,
    ),
    (
        heating.radiation_to_shale,
        {
            "a_ash": 1.0,
            "t_ash_mean": 1000.0,
            "a_shale_class": np.array([0.5, 0.5]),
            "t_shale_class": np.array([500.0, 500.0]),
            "extent": 1.0,
        },
        "a_ash",
        -1.0,
    ),
    (mixing.mixing_time, {"final_contact": 41.2, "rate": 1.656}, "final_contact", NAN),
    (mixing.contact_distance, {"t": 10.0, "rate": 2.0, "final_contact": 40.0}, "rate", NAN),
    (
        mixing.contact_distance,
        {"t": 10.0, "rate": 2.0, "final_contact": 40.0},
        "final_contact",
        -40.0,
    ),
    (
        pyrolysis.reaction_extent,
        {"temperature": 793.0, "t_low": 743.0, "tau": 21.7},
        "temperature",
        NAN,
    ),
    (
        pyrolysis.reaction_extent,
        {"temperature": 793.0, "t_low": 743.0, "tau": 21.7},
        "t_low",
        -743.0,
    ),
]


@pytest.mark.parametrize(("func", "kwargs", "arg", "bad"), CASES)
def test_bad_value_raises_input_error_naming_the_argument(func, kwargs, arg, bad):
    assert np.all(np.isfinite(func(**kwargs)))
    with pytest.raises(InputError, match=arg):
        func(**{**kwargs, arg: bad})


def test_cell_heat_exchange_rejects_a_non_positive_time_step():
    n, k = 2, 3
    shape = (n, 2, k)
    args = (
        np.ones(shape),
        np.full(shape, 1000.0),
        np.full(shape, 1e-3),
        np.full(shape, 600.0),
        np.array([1e-3, 2e-3, 4e-3]),
        np.full(n, 0.5),
    )
    assert np.all(np.isfinite(heating.cell_heat_exchange(*args, 0.1)))
    with pytest.raises(InputError, match="dt"):
        heating.cell_heat_exchange(*args, 0.0)
    with pytest.raises(InputError, match="emissivity"):
        heating.cell_heat_exchange(*args, 0.1, emissivity=NAN)
