"""Issue 23 prototype options of the cross-section exchange: validated at construction, off by
default, and energy-consistent (every path flow leaves one node and enters another)."""

import dataclasses

import numpy as np
import pytest

from rotarykiln.errors import InputError
from rotarykiln.heat.bed_conductivity import radiative_bed_conductivity
from rotarykiln.kiln.exchange import BulkBed, CrossSectionExchange, TableGas
from rotarykiln.kiln.grid import cell_grid
from rotarykiln.kiln.inputs import Closures
from rotarykiln.materials.gas import air_table


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("near_bed_mixing", 0.0),
        ("near_bed_mixing", -5.0),
        ("near_bed_mixing", float("nan")),
    ],
)
def test_invalid_option_names_field_value_range(field, value):
    with pytest.raises(InputError) as err:
        Closures(**{field: value})
    msg = str(err.value)
    assert f"closures.{field}" in msg and "in (0" in msg


def test_radiative_bed_conductivity_is_damkohler_form():
    sigma = 5.670374419e-8
    k = radiative_bed_conductivity(2.5e-3, 1000.0, 0.9)
    assert k == pytest.approx(4 * sigma * 0.9 / (2 - 0.9) * 2.5e-3 * 1000.0**3, rel=1e-12)
    # the coarse sand conducts more than the fine one, in proportion to the size
    assert radiative_bed_conductivity(2.5e-3, 900.0, 0.9) / radiative_bed_conductivity(
        0.58e-3, 900.0, 0.9
    ) == pytest.approx(2.5 / 0.58)


def _exchange(**options):
    g = cell_grid(2.0, 0.2, 4, lambda z: np.full_like(z, 0.12))
    c = dataclasses.replace(Closures(gas_emissivity=0.2), **options)
    bed = BulkBed(1460.0, 1000.0, 2.5e-3, 0.9, 0.3)
    return CrossSectionExchange(c, g, 2.0, 0.2, 0.157, 0.85, bed), g


@pytest.mark.parametrize(
    "options",
    [{"near_bed_mixing": 20.0}, {"exposed_bed_penetration": True}, {"bed_radiation": True}],
)
def test_options_reduce_or_keep_bed_heating_and_stay_bounded(options):
    gas = TableGas(air_table(), 101325.0, 0.5)
    tg, tb, tw = np.full(4, 1100.0), np.full(4, 700.0), np.full(4, 900.0)
    base, g = _exchange()
    q0, _ = base.flows(gas, tg, tb, tw)
    ex, _ = _exchange(**options)
    q1, _ = ex.flows(gas, tg, tb, tw)
    into_bed0 = q0["q_gas_bed_conv"] + q0["q_rad_to_bed"]
    into_bed1 = q1["q_gas_bed_conv"] + q1["q_rad_to_bed"]
    if options.get("bed_radiation"):
        assert np.all(q1["q_covered_wall_bed"] >= q0["q_covered_wall_bed"])
    else:
        # a resistance in series: less heat into the exposed bed, never reversed
        assert np.all(into_bed1 < into_bed0) and np.all(into_bed1 > 0)
    assert np.all(q1["q_gas_wall_conv"] == q0["q_gas_wall_conv"])


def test_defaults_are_off():
    c = Closures()
    assert c.near_bed_mixing is None
    assert not c.bed_radiation and not c.exposed_bed_penetration
