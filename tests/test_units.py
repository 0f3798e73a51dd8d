import math

import pytest

from rotarykiln.errors import InputError
from rotarykiln.units import to_si


@pytest.mark.parametrize(
    ("text", "kind", "expected"),
    [
        ("1.5 rpm", "rotation rate", 1.5 * 2 * math.pi / 60),
        ("0.8 deg", "angle", math.radians(0.8)),
        ("62 kg/h", "mass flow", 62 / 3600),
        ("0.406 m", "length", 0.406),
        ("40.6 cm", "length", 0.406),
        ("1100 degC", "temperature", 1373.15),
        ("1780 kg/m3", "density", 1780.0),
        ("5 %", "angle", math.atan(0.05)),
        ("0.03 m/m", "angle", math.atan(0.03)),
        ("30 %", "fraction", 0.3),
        ("0.3", "fraction", 0.3),
        ("2 W/m2/K", "heat transfer coefficient", 2.0),
        ("1e5 Pa", "pressure", 1e5),
    ],
)
def test_to_si(text, kind, expected):
    assert to_si("x", text, kind) == pytest.approx(expected)


@pytest.mark.parametrize(
    ("text", "kind", "message"),
    [
        ("3 m", "rotation rate", 'x: "3 m" is a length, expected a rotation rate'),
        ("2 kg", "length", 'x: "2 kg" is a mass, expected a length'),
        ("fast", "rotation rate", 'x: "fast" is not a quantity with a unit'),
        ("0.05", "angle", "needs a unit"),
        ("nan m", "length", "not a finite number"),
    ],
)
def test_to_si_errors(text, kind, message):
    with pytest.raises(InputError, match=message.replace("(", r"\(")):
        to_si("x", text, kind)
