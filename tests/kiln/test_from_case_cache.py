"""``kiln_from_case`` keeps what it builds from unchanged sections (issue 25, item 2): shared,
immutable, and the same kiln, bit for bit, as one built afresh."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from rotarykiln.case import case_with, load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln import from_case
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln

pytestmark = pytest.mark.filterwarnings("ignore::rotarykiln.errors.OutOfRangeWarning")

CACHES = (
    from_case._cached_closures,
    from_case._cached_solid,
    from_case._cached_mechanism,
    from_case._cached_layers,
    from_case._mass_shares,
)


def _clear():
    for cache in CACHES:
        cache.cache_clear()


def test_variants_share_the_parts_of_unchanged_sections():
    base = load_case(builtin_case_path("tscheng_A16"))
    k0, _ = kiln_from_case(base)
    solids = from_case._cached_solid.cache_info()
    k1, _ = kiln_from_case(case_with(base, {"operation.speed": "2 rpm", "gas.flow": "30 kg/h"}))
    assert k1.wall.layers is k0.wall.layers
    assert k1.closures is k0.closures
    assert from_case._cached_solid.cache_info().hits == solids.hits + 1  # the library sand
    assert from_case._cached_solid.cache_info().misses == solids.misses
    assert k1.drum.omega != k0.drum.omega
    thicker = case_with(base, {"wall.lining[0].thickness": "20 mm"})
    k2, _ = kiln_from_case(thicker)
    assert k2.wall.layers is not k0.wall.layers
    assert k2.wall.layers[0].thickness == 0.02 and k2.wall.layers[1:] == k0.wall.layers[1:]
    k3, _ = kiln_from_case(case_with(base, {"material.particle_size": "1 mm"}))
    assert k3.bed.particle_diameter == 0.001 != k0.bed.particle_diameter
    k4, _ = kiln_from_case(case_with(base, {"closures.radiation_model": "banded"}))
    assert k4.closures.radiation_model == "banded" and k0.closures.radiation_model != "banded"


def test_reacting_variants_share_their_mechanism_read_only():
    base = load_case(builtin_case_path("charcoal_activation"))
    k0, _ = kiln_from_case(base)
    k1, _ = kiln_from_case(case_with(base, {"operation.feed": "13 kg/h"}))
    mech = k0.chemistry.mechanism
    assert k1.chemistry.mechanism is mech
    arrays = [v for v in vars(mech).values() if isinstance(v, np.ndarray)]
    assert arrays and not any(a.flags.writeable for a in arrays)
    with pytest.raises(ValueError, match="read-only"):
        arrays[0][...] = 0.0
    # a section whose reactions change gets its own mechanism
    k2, _ = kiln_from_case(case_with(base, {"chemistry.onset_width": 5.0}))
    assert k2.chemistry.mechanism is not mech
    widths = {r.name: r.params.get("width") for r in k2.chemistry.mechanism.reactions}
    assert 5.0 in widths.values()
    # the source's expected results do not enter the mechanism
    k3, _ = kiln_from_case(case_with(base, {"chemistry.expected": {}}))
    assert k3.chemistry.mechanism is mech


def _fields(kiln) -> dict:
    """The kiln's inputs as comparable plain values (arrays as bytes: bit for bit)."""

    def plain(v):
        if isinstance(v, np.ndarray):
            return (v.dtype.str, v.shape, v.tobytes())
        if dataclasses.is_dataclass(v) and not isinstance(v, type):
            return {f.name: plain(getattr(v, f.name)) for f in dataclasses.fields(v)}
        if isinstance(v, dict):
            return {k: plain(x) for k, x in v.items()}
        if isinstance(v, list | tuple):
            return [plain(x) for x in v]
        if isinstance(v, float):
            return v.hex()
        return repr(v) if not isinstance(v, str | int | bool | type(None)) else v

    return plain(kiln)


@pytest.mark.parametrize(
    ("name", "changes"),
    [
        ("tscheng_A16", {"operation.speed": "2.2 rpm", "gas.flow": "27 kg/h"}),
        ("barr_T4", {"operation.feed": "70 kg/h"}),
        ("limestone_calcination", {"operation.feed": "40 kg/h"}),
        ("rotary_pyrolysis", {"operation.feed": "25 kg/h"}),
    ],
)
def test_a_kiln_from_the_caches_equals_one_built_afresh(name, changes):
    base = load_case(builtin_case_path(name))
    kiln_from_case(base)  # the caches filled with the base's sections
    case = case_with(base, changes)
    warm, cells = kiln_from_case(case)
    _clear()
    fresh, _ = kiln_from_case(case)
    assert _fields(warm) == _fields(fresh)
    if name == "tscheng_A16":  # and the solution, bit for bit
        a, b = solve_kiln(warm, cells), solve_kiln(fresh, cells)
        for attr in ("t_bed_nodes", "t_gas_nodes"):
            assert np.array_equal(getattr(a, attr), getattr(b, attr))


def test_caches_are_bounded():
    for cache in CACHES:
        assert cache.cache_info().maxsize is not None


def test_a_sections_content_key_is_worked_out_once_and_the_kept_ones_bounded():
    from rotarykiln.case import LiningLayer

    layer = LiningLayer(material="fireclay_brick", thickness="0.1 m")
    twin = LiningLayer(material="fireclay_brick", thickness="0.1 m")
    other = LiningLayer(material="fireclay_brick", thickness="0.2 m")
    key = from_case._content_key(layer)
    assert from_case._content_key(layer) is key  # the same section: its key kept
    assert from_case._content_key(twin) == key and from_case._content_key(other) != key
    for i in range(2 * from_case.KEYS_KEPT):
        from_case._content_key(LiningLayer(material="fireclay_brick", thickness=f"{i + 1} mm"))
    assert len(from_case._KEYS) <= from_case.KEYS_KEPT
    assert from_case._content_key(layer) == key
