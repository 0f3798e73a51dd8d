"""The grey particle cloud of a burning solid fuel (heat/gas_radiation.py)."""

import numpy as np
import pytest

from rotarykiln.errors import InputError
from rotarykiln.heat.gas_radiation import (
    combined_emissivity,
    particle_absorption_coefficient,
    particle_cloud_emissivity,
)


def test_absorption_of_large_particles_is_their_projected_area_per_volume():
    # 1e8 spheres of 100 um per m3: 1e8 x pi/4 x 1e-8 m2 = 0.7854 1/m
    assert particle_absorption_coefficient(1e8, 100e-6) == pytest.approx(np.pi / 4.0, rel=1e-12)
    # classes add; Q_abs scales
    two = particle_absorption_coefficient(np.array([1e8, 4e8]), np.array([100e-6, 50e-6]))
    assert two == pytest.approx(np.pi / 2.0, rel=1e-12)
    assert particle_absorption_coefficient(1e8, 100e-6, 0.6) == pytest.approx(
        0.6 * np.pi / 4.0, rel=1e-12
    )
    # per position (rows), summed over the classes (last axis)
    rows = particle_absorption_coefficient(
        np.array([1e8, 4e8]), np.array([[100e-6, 50e-6], [0, 0]])
    )
    assert rows.tolist() == pytest.approx([np.pi / 2.0, 0.0], rel=1e-12)


def test_cloud_emissivity_is_beer_lambert_and_combines_as_independent_absorbers():
    assert particle_cloud_emissivity(0.5, 2.0) == pytest.approx(1.0 - np.exp(-1.0), rel=1e-12)
    assert particle_cloud_emissivity(0.0, 2.0) == 0.0
    # two grey absorbers over the same path: their kappas add
    e = combined_emissivity(
        particle_cloud_emissivity(0.3, 2.0), particle_cloud_emissivity(0.2, 2.0)
    )
    assert e == pytest.approx(particle_cloud_emissivity(0.5, 2.0), rel=1e-12)


@pytest.mark.parametrize(
    "args",
    [(-1.0, 50e-6), (1e8, -1e-6), (1e8, 50e-6, 1.2)],
)
def test_bad_cloud_inputs_are_refused(args):
    with pytest.raises(InputError):
        particle_absorption_coefficient(*args)
