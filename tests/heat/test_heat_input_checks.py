"""Input checks of the heat closures, and the zero-area limits of the radiation network."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rotarykiln.errors import InputError
from rotarykiln.heat import contact, convection, gas_radiation, radiation, wall
from rotarykiln.materials.gas import air_table

NAN = float("nan")
RAD = {
    "t_gas": 1000.0,
    "t_wall": 1200.0,
    "t_bed": 900.0,
    "eps_gas": 0.2,
    "eps_wall": 0.8,
    "eps_bed": 0.9,
    "wall_area": 2.0,
    "bed_area": 0.5,
}
CASES = [
    (
        convection.gas_reynolds,
        {"mass_flux": 0.3, "hydraulic_diameter": 0.15, "viscosity": 2.7e-5},
        "mass_flux",
        -0.3,
    ),
    (
        convection.gas_reynolds,
        {"mass_flux": 0.3, "hydraulic_diameter": 0.15, "viscosity": 2.7e-5},
        "viscosity",
        0.0,
    ),
    (
        convection.rotational_reynolds,
        {"density": 0.7, "omega": 0.3, "hydraulic_diameter": 0.15, "viscosity": 2.7e-5},
        "hydraulic_diameter",
        NAN,
    ),
    (
        convection.gorog_gas_wall_h,
        {
            "conductivity": 0.07,
            "hydraulic_diameter": 0.3,
            "reynolds": 2e4,
            "prandtl": 0.7,
            "length": 5.5,
        },
        "hydraulic_diameter",
        -0.3,
    ),
    (
        convection.gorog_gas_wall_h,
        {
            "conductivity": 0.07,
            "hydraulic_diameter": 0.3,
            "reynolds": 2e4,
            "prandtl": 0.7,
            "length": 5.5,
        },
        "prandtl",
        NAN,
    ),
    (
        contact.li_covered_wall_h,
        {
            "gas_conductivity": 0.06,
            "particle_diameter": 1e-3,
            "bed_conductivity": 0.3,
            "rho_c": 1.6e6,
            "omega": 0.21,
            "full_angle": 2.0,
            "chi": 0.1,
        },
        "particle_diameter",
        -1e-3,
    ),
    (
        contact.li_covered_wall_h,
        {
            "gas_conductivity": 0.06,
            "particle_diameter": 1e-3,
            "bed_conductivity": 0.3,
            "rho_c": 1.6e6,
            "omega": 0.21,
            "full_angle": 2.0,
            "chi": 0.1,
        },
        "chi",
        NAN,
    ),
    (
        contact.tscheng_covered_wall_h,
        {"bed_conductivity": 0.3, "rho_c": 1.6e6, "omega": 0.21, "radius": 0.5, "full_angle": 2.0},
        "rho_c",
        -1.6e6,
    ),
    (
        contact.tscheng_covered_wall_h,
        {"bed_conductivity": 0.3, "rho_c": 1.6e6, "omega": 0.21, "radius": 0.5, "full_angle": 2.0},
        "radius",
        0.0,
    ),
    (gas_radiation.gorog_mean_beam_length, {"diameter": 0.4, "bed_depth": 0.05}, "diameter", -0.4),
    (gas_radiation.gorog_mean_beam_length, {"diameter": 0.4, "bed_depth": 0.05}, "bed_depth", 0.5),
    (
        gas_radiation.johansson_wsgg_emissivity,
        {"temperature": 1200.0, "p_h2o": 1e4, "p_co2": 1e4, "path_length": 1.0},
        "path_length",
        -1.0,
    ),
    (radiation.freeboard_radiation, RAD, "t_wall", -1200.0),
    (radiation.freeboard_radiation, RAD, "t_gas", NAN),
    (radiation.freeboard_radiation, RAD, "bed_area", -0.5),
    (
        wall.cylinder_layer_heat_flow,
        {"k_integral_inner": 500.0, "k_integral_outer": 400.0, "r_inner": 0.5, "r_outer": 0.6},
        "r_outer",
        0.4,
    ),
    (
        wall.cylinder_layer_heat_flow,
        {"k_integral_inner": 500.0, "k_integral_outer": 400.0, "r_inner": 0.5, "r_outer": 0.6},
        "k_integral_inner",
        NAN,
    ),
    (wall.churchill_chu_nusselt, {"rayleigh": 1e9, "prandtl": 0.7}, "rayleigh", -1e9),
    (wall.churchill_bernstein_nusselt, {"reynolds": 6000.0, "prandtl": 0.7}, "prandtl", 0.0),
]


@pytest.mark.parametrize(("func", "kwargs", "arg", "bad"), CASES)
def test_bad_value_raises_input_error_naming_the_argument(func, kwargs, arg, bad):
    assert np.all(np.isfinite(func(**kwargs)))
    with pytest.raises(InputError, match=arg):
        func(**{**kwargs, arg: bad})


def test_shell_heat_loss_rejects_a_negative_temperature():
    with pytest.raises(InputError, match="t_ambient"):
        wall.shell_heat_loss(400.0, -300.0, 0.5, 0.9, air_table())


def test_radiation_without_a_bed_surface_is_finite():
    # an empty kiln has no bed chord: the network matrix was singular (0/0 = NaN)
    qw, qb = radiation.freeboard_radiation(**{**RAD, "bed_area": 0.0})
    assert qb == 0.0
    # wall and gas alone: q = eps_g A sigma (Tg^4 - Jw), Jw from the two-node balance
    s = radiation.STEFAN_BOLTZMANN
    gw = 0.8 * 2.0 / 0.2
    ggw = 0.2 * 2.0
    jw = (gw * s * 1200.0**4 + ggw * s * 1000.0**4) / (gw + ggw)
    assert qw == pytest.approx(ggw * (s * 1000.0**4 - jw))
    # and it is the limit of a vanishing bed
    qw_small, qb_small = radiation.freeboard_radiation(**{**RAD, "bed_area": 1e-9})
    assert qw_small == pytest.approx(qw, rel=1e-6)
    assert abs(qb_small) < 1e-3


def test_radiation_without_exposed_wall_or_both_is_finite():
    qw, qb = radiation.freeboard_radiation(**{**RAD, "wall_area": 0.0})
    assert qw == 0.0 and np.isfinite(qb)
    qw, qb = radiation.freeboard_radiation(**{**RAD, "wall_area": 0.0, "bed_area": 0.0})
    assert qw == 0.0 and qb == 0.0


@settings(max_examples=80, deadline=None)
@given(
    areas=st.tuples(st.floats(0.0, 10.0), st.floats(0.0, 10.0)),
    eps_gas=st.floats(0.0, 0.99),
    temps=st.tuples(*(st.floats(300.0, 2000.0) for _ in range(3))),
)
def test_radiation_network_conserves_energy_and_stays_finite(areas, eps_gas, temps):
    t_gas, t_wall, t_bed = temps
    qw, qb = radiation.freeboard_radiation(
        t_gas, t_wall, t_bed, eps_gas, 0.8, 0.9, areas[0], areas[1]
    )
    assert np.isfinite(qw) and np.isfinite(qb)
    if eps_gas == 0.0:  # a transparent gas exchanges nothing: wall and bed balance
        assert qw + qb == pytest.approx(0.0, abs=1e-6 * (abs(qw) + 1.0))
