"""The non-grey (WSGG grey-gas set) freeboard exchange: heat/gas_radiation.wsgg_bands,
heat/radiation.freeboard_radiation_bands and the ``radiation_model`` closure (issue 23)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from rotarykiln.errors import InputError
from rotarykiln.heat.gas_radiation import (
    WsggBands,
    johansson_wsgg_emissivity,
    smith_wsgg_emissivity,
    wsgg_bands,
)
from rotarykiln.heat.radiation import (
    freeboard_radiation,
    freeboard_radiation_bands,
    freeboard_radiation_paths,
)
from rotarykiln.kiln.inputs import Closures

ATM = 101325.0
# natural-gas products at about 2.5 times the stoichiometric air, the UBC pilot kiln's freeboard
PW, PC, L = 0.079 * ATM, 0.039 * ATM, 0.31


@pytest.mark.parametrize("t", [600.0, 900.0, 1250.0])
def test_band_weights_at_the_gas_temperature_give_the_emissivity(t):
    j = wsgg_bands("johansson2011", PW, PC, L)
    assert float(j.total(t)) == pytest.approx(
        float(johansson_wsgg_emissivity(t, PW, PC, L, check=False)), rel=1e-12
    )
    s = wsgg_bands("smith1982", PW, PC, L)
    assert float(s.total(t)) == pytest.approx(
        float(smith_wsgg_emissivity(t, (PW + PC) * L, "pw/pc=2", check=False)), rel=1e-12
    )


def test_weights_stay_a_partition_far_outside_the_fit():
    b = wsgg_bands("johansson2011", PW, PC, L)
    for t in (250.0, 300.0, 3000.0):
        a = b.weights(t)
        assert np.all(a >= 0.0) and a.sum() <= 1.0 + 1e-12


def test_absorptivity_of_a_cooler_surface_exceeds_the_gas_emissivity():
    # Hottel: the CO2/H2O bands absorb a cooler source's radiation more strongly
    b = wsgg_bands("johansson2011", PW, PC, L)
    assert float(b.total(800.0)) > float(b.total(1200.0))


def test_one_band_of_weight_one_is_the_grey_network():
    eps = 0.2
    grey = WsggBands("smith1982", np.array([eps]))
    one = dataclasses.replace(grey)
    object.__setattr__(one, "weights", lambda t: np.ones((1,) + np.shape(t)))
    a = freeboard_radiation_bands(1100.0, 950.0, 900.0, one, 0.85, 0.9, 1.0, 0.3)
    b = freeboard_radiation(1100.0, 950.0, 900.0, eps, 0.85, 0.9, 1.0, 0.3)
    assert np.allclose(a, b, rtol=1e-12)


def test_banded_exchange_conserves_and_vanishes_at_equilibrium():
    b = wsgg_bands("johansson2011", np.full(3, PW), np.full(3, PC), L)
    t = np.array([700.0, 1000.0, 1300.0])
    qw, qb = freeboard_radiation_bands(t, t, t, b, 0.85, 0.9, 1.0, 0.3)
    assert np.allclose(qw, 0.0, atol=1e-9) and np.allclose(qb, 0.0, atol=1e-9)
    gw, gb, wb = freeboard_radiation_paths(
        1100.0,
        1000.0,
        900.0,
        None,
        0.85,
        0.9,
        1.0,
        0.3,
        bands=wsgg_bands("johansson2011", PW, PC, L),
    )
    qw, qb = freeboard_radiation_bands(
        1100.0, 1000.0, 900.0, wsgg_bands("johansson2011", PW, PC, L), 0.85, 0.9, 1.0, 0.3
    )
    assert float(gw - wb) == pytest.approx(float(qw)) and float(gb + wb) == pytest.approx(float(qb))
    assert float(wb) > 0  # the hotter wall radiates to the bed through the windows


def test_hot_gas_over_cooler_surfaces_passes_less_than_the_grey_gas():
    b = wsgg_bands("johansson2011", PW, PC, L)
    grey = sum(freeboard_radiation(1100.0, 950.0, 950.0, float(b.total(1100.0)), 0.85, 0.9, 1, 0.3))
    banded = sum(freeboard_radiation_bands(1100.0, 950.0, 950.0, b, 0.85, 0.9, 1.0, 0.3))
    assert 0.6 * grey < banded < 0.9 * grey


def test_radiation_model_names_are_checked():
    assert Closures().radiation_model == "grey"
    assert Closures(radiation_model="banded").radiation_model == "banded"
    with pytest.raises(InputError, match="closures.radiation_model.*grey, banded"):
        Closures(radiation_model="nongrey")
    with pytest.raises(InputError, match="closures.gas_emissivity"):
        wsgg_bands("leckner1972", PW, PC, L)
