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
    assert sum(c.chemistry.feed.composition.values()) == pytest.approx(1.0)
    assert sum(c.chemistry.gas.composition.values()) == pytest.approx(1.0)
    Mechanism.builtin(*c.chemistry.reactions)
    assert c.chemistry.residence_time > 0 and c.chemistry.wall_loss.U > 0


def test_values_given_by_seed_004():
    # Issue 7 item 3 lists the seed-004 inputs of both cases.
    ch = load_case(builtin_case_path("charcoal_activation"))
    assert (ch.kiln.length, ch.kiln.diameter) == pytest.approx((3.7, 0.3))
    assert ch.operation.speed == pytest.approx(2 * RPM)
    assert ch.operation.feed == pytest.approx(0.00333)
    assert ch.chemistry.gas.steam_flow == pytest.approx(0.005)
    assert ch.chemistry.feed.temperature == pytest.approx(500.0)
    ls = load_case(builtin_case_path("limestone_calcination"))
    assert (ls.kiln.length, ls.kiln.diameter) == pytest.approx((5.5, 0.406))
    assert ls.operation.speed == pytest.approx(1.5 * RPM)
    assert ls.operation.feed == pytest.approx(42 / 3600)


def _minimal(**chem):
    base = {
        "reactions": ["calcination_luisser"],
        "feed": {"temperature": "550 K", "composition": {"CaCO3": 1.0}},
    }
    base.update(chem)
    return {
        "kiln": {"length": "5 m", "diameter": "0.4 m"},
        "operation": {"speed": "1 rpm"},
        "chemistry": base,
    }


@pytest.mark.parametrize(
    "chem, match",
    [
        (
            {"feed": {"temperature": "550 K", "composition": {"CaCO3": 0.5}}},
            "the fractions sum to 0.5, expected 1",
        ),
        (
            {"feed": {"temperature": "550 K", "composition": {"CaCO3": 1.2, "CaO": -0.2}}},
            "mass fraction",
        ),
        ({"feed": {"temperature": "550 K", "composition": {"stone": 1.0}}}, "not a known species"),
        ({"feed": {"temperature": "550 K", "composition": {"CO2": 1.0}}}, "a bed species"),
        ({"reactions": ["nope"]}, "not a built-in reaction"),
    ],
)
def test_bad_chemistry_sections_refused(chem, match):
    with pytest.raises(InputError, match=match):
        parse_case(_minimal(**chem))
