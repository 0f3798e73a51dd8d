import math
import re

import numpy as np
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


@pytest.mark.parametrize(
    ("text", "kind", "expected"),
    [
        # spellings engineers type that pint alone does not read
        ("1.5 RPM", "rotation rate", 1.5 * 2 * math.pi / 60),
        ("1.5 rev/min", "rotation rate", 1.5 * 2 * math.pi / 60),
        ("1.5 r/min", "rotation rate", 1.5 * 2 * math.pi / 60),
        ("1.5 U/min", "rotation rate", 1.5 * 2 * math.pi / 60),
        ("62 kg/hr", "mass flow", 62 / 3600),
        ("1.2 tph", "mass flow", 1200 / 3600),
        ("2 degrees", "angle", math.radians(2)),
        ("2 DEG", "angle", math.radians(2)),
        ("1100 C", "temperature", 1373.15),
        ("1100 deg C", "temperature", 1373.15),
        ("212 F", "temperature", 373.15),
        ("1.2 W/mK", "thermal conductivity", 1.2),
        ("1.2 W/m.K", "thermal conductivity", 1.2),
        ("10 W/m2K", "heat transfer coefficient", 10.0),
        ("10 W/m^2K", "heat transfer coefficient", 10.0),
        ("1 kJ/kgK", "specific heat", 1000.0),
        ("1 kJ/kg-K", "specific heat", 1000.0),
    ],
)
def test_to_si_common_spellings(text, kind, expected):
    assert to_si("x", text, kind) == pytest.approx(expected)


@pytest.mark.parametrize(
    ("text", "kind", "message"),
    [
        # "0,4 m" used to become 0 m silently (pint reads the comma as a separator)
        ("0,4 m", "length", 'x: "0,4 m" has a comma; use a decimal point'),
        ("1,500 kg/m3", "density", "has a comma"),
        # unknown unit: name it and say what is accepted
        (
            "1.5 rmp",
            "rotation rate",
            'x: "1.5 rmp" has an unknown unit "rmp", expected a rotation rate (rpm',
        ),
        # a number without unit is not silently "a fraction"
        ("1.5", "rotation rate", 'x: "1.5" needs a unit, expected a rotation rate (rpm'),
        ("1100", "temperature", 'x: "1100" needs a unit, expected a temperature (K, degC, degF)'),
        # pint counts radians as 1: "1/min" and "Hz" would be rad per time, 2 pi off from rpm
        ("1.5 1/min", "rotation rate", "does not say revolutions or radians"),
        ("0.1 Hz", "rotation rate", "does not say revolutions or radians"),
        # "C" is coulomb outside temperatures
        ("3 C", "length", "expected a length (m, cm, mm)"),
    ],
)
def test_to_si_errors_name_the_unit_and_what_is_accepted(text, kind, message):
    with pytest.raises(InputError, match=re.escape(message)):
        to_si("x", text, kind)


@pytest.mark.parametrize(("value", "kind"), [(1.5, "rotation rate"), (62, "mass flow")])
def test_bare_numbers_refused_where_the_habitual_unit_is_not_si(value, kind):
    with pytest.raises(InputError, match="needs a unit"):
        to_si("x", value, kind)
    assert to_si("x", 0, kind) == 0.0
    assert to_si("x", 0.3, "length") == 0.3  # other kinds: a bare number is SI


@pytest.mark.parametrize(
    ("unit", "kind"),
    [
        ("kg/h", "mass flow"),
        ("t/h", "mass flow"),
        ("rpm", "rotation rate"),
        ("degC", "temperature"),
        ("degF", "temperature"),
        ("L/s", "volumetric flow"),
        ("kW", "power"),
        ("%", "fraction"),
        ("W/m2K", "heat transfer coefficient"),
    ],
)
def test_a_unit_read_once_converts_its_next_texts_as_pint_does(unit, kind):
    """A study's sampled values are new texts with a known unit: converted by that unit's
    factor or offset, to the same float as pint's conversion of the whole text."""
    from rotarykiln.units import _convert_text

    rng = np.random.default_rng(0)
    for v in rng.uniform(0.0, 3000.0, 300):
        text = f"{v:.9g} {unit}"
        assert to_si("x", text, kind) == _convert_text("x", text, kind), text
    with pytest.raises(InputError, match="not a finite number"):
        to_si("x", f"1e400 {unit}", kind)
