"""The two built-in case files of seed 004 validate against the case schema."""

import pytest

from rotarykiln.case import load_case, parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.errors import InputError

RPM = 2 * 3.141592653589793 / 60  # rad/s per rpm


@pytest.mark.parametrize("name", ["charcoal_activation", "limestone_calcination"])
def test_case_file_validates_and_builds_a_mechanism(name):
    c = load_case(builtin_case_path(name))
    assert sum(c.material.composition.values()) == pytest.approx(1.0)
    assert sum(c.gas.mass_fractions.values()) == pytest.approx(1.0)
    Mechanism.builtin(*c.chemistry.reactions)
    assert c.bed.residence_time > 0 and c.wall.U > 0


def test_values_given_by_seed_004():
    # Issue 7 item 3 lists the seed-004 inputs of both cases.
    ch = load_case(builtin_case_path("charcoal_activation"))
    assert (ch.kiln.length, ch.kiln.diameter) == pytest.approx((3.7, 0.3))
    assert ch.operation.speed == pytest.approx(2 * RPM)
    assert ch.operation.feed == pytest.approx(0.00333)
    assert ch.gas.steam_flow == pytest.approx(0.005)
    assert ch.operation.feed_temperature == pytest.approx(500.0)
    ls = load_case(builtin_case_path("limestone_calcination"))
    assert (ls.kiln.length, ls.kiln.diameter) == pytest.approx((5.5, 0.406))
    assert ls.operation.speed == pytest.approx(1.5 * RPM)
    assert ls.operation.feed == pytest.approx(42 / 3600)


def _minimal(composition=None, reactions=None):
    return {
        "kiln": {"length": "5 m", "diameter": "0.4 m"},
        "operation": {"speed": "1 rpm", "feed_temperature": "550 K"},
        "material": {"composition": composition or {"CaCO3": 1.0}},
        "chemistry": {"reactions": reactions or ["calcination_luisser"]},
    }


@pytest.mark.parametrize(
    "edit, match",
    [
        ({"composition": {"CaCO3": 0.5}}, "the fractions sum to 0.5, expected 1"),
        ({"composition": {"CaCO3": 1.2, "CaO": -0.2}}, "mass fraction"),
        ({"composition": {"stone": 1.0}}, "not a known species"),
        ({"composition": {"CO2": 1.0}}, "a bed species"),
        ({"reactions": ["nope"]}, "not a built-in reaction"),
    ],
)
def test_bad_chemistry_sections_refused(edit, match):
    with pytest.raises(InputError, match=match):
        parse_case(_minimal(**edit))
