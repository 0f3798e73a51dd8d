"""Quantities with units at the edges, SI floats inside.

Case files and the command line give physical values as strings with units ("1.5 rpm",
"0.8 deg", "62 kg/h", "0.406 m", "1100 degC"). :func:`to_si` converts such a string once to an
SI float for a named *kind* of quantity, and raises :class:`~rotarykiln.errors.InputError` naming
the field when the string is not a quantity of that kind.

Kinds and their SI units are listed in :data:`KINDS`. Angles are radians; rotation rates rad/s;
temperatures kelvin. A slope may also be given as a grade ("3 %", "0.05 m/m"), converted with
arctan.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import lru_cache

import pint

from rotarykiln.errors import InputError

__all__ = ["KINDS", "Kind", "ureg", "to_si", "format_quantity"]

ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
ureg.define("rpm_ = revolution / minute")  # "rpm" already exists; keep an alias harmless


@dataclass(frozen=True)
class Kind:
    """A kind of physical quantity: its human name, SI unit and pint dimensionality."""

    name: str
    si: str

    @property
    def dimensionality(self):
        return ureg.Quantity(1.0, self.si).dimensionality


KINDS: dict[str, Kind] = {
    k.name: k
    for k in [
        Kind("length", "m"),
        Kind("area", "m**2"),
        Kind("volume", "m**3"),
        Kind("time", "s"),
        Kind("mass", "kg"),
        Kind("angle", "rad"),
        Kind("rotation rate", "rad/s"),
        Kind("velocity", "m/s"),
        Kind("mass flow", "kg/s"),
        Kind("volumetric flow", "m**3/s"),
        Kind("temperature", "K"),
        Kind("density", "kg/m**3"),
        Kind("pressure", "Pa"),
        Kind("power", "W"),
        Kind("power per length", "W/m"),
        Kind("heat flux", "W/m**2"),
        Kind("heat transfer coefficient", "W/m**2/K"),
        Kind("thermal conductivity", "W/m/K"),
        Kind("specific heat", "J/kg/K"),
        Kind("specific energy", "J/kg"),
        Kind("molar energy", "J/mol"),
        Kind("diffusivity", "m**2/s"),
        Kind("frequency", "1/s"),
        Kind("fraction", "dimensionless"),
    ]
}

UNIT_REQUIRED = {"rotation rate": "rpm", "mass flow": "kg/h", "volumetric flow": "m3/h"}
"""Kinds whose bare numbers are refused: an engineer's habitual unit (rpm, kg/h) is not SI, so a
bare number would be silently misread by a factor of 2 pi / 60 or 3600. Zero is accepted."""

_ANGLE_UNITS = (
    "degree",
    "radian",
    "arcminute",
    "arcsecond",
    "revolution",
    "turn",
    "gradian",
    "rpm",
)

#: Units an engineer would type for each kind, quoted in error messages.
EXAMPLES: dict[str, str] = {
    "length": "m, cm, mm",
    "area": "m2, cm2",
    "volume": "m3, L",
    "time": "s, min, h",
    "mass": "kg, t",
    "angle": "deg, rad, or % / m/m for a grade",
    "rotation rate": "rpm, rad/s",
    "velocity": "m/s",
    "mass flow": "kg/h, kg/s, t/h",
    "volumetric flow": "m3/h, m3/s",
    "temperature": "K, degC, degF",
    "density": "kg/m3",
    "pressure": "Pa, kPa, bar, atm",
    "power": "W, kW, MW",
    "power per length": "W/m, kW/m",
    "heat flux": "W/m2, kW/m2",
    "heat transfer coefficient": "W/m2/K",
    "thermal conductivity": "W/m/K",
    "specific heat": "J/kg/K, kJ/kg/K",
    "specific energy": "J/kg, kJ/kg, MJ/kg",
    "molar energy": "J/mol, kJ/mol",
    "diffusivity": "m2/s",
    "frequency": "1/s, Hz",
    "fraction": "a number such as 0.15, or 15 %",
}

# Whole unit strings engineers type that pint does not know (matched ignoring case and spaces).
_ALIASES = {
    "rpm": "rpm",
    "r/min": "rpm",
    "rev/min": "rpm",
    "revs/min": "rpm",
    "u/min": "rpm",
    "rev/s": "revolution/s",
    "r/s": "revolution/s",
    "deg": "deg",
    "degs": "deg",
    "degree": "deg",
    "degrees": "deg",
    "tph": "t/h",
    "t/hr": "t/h",
    "kg/hr": "kg/h",
}
# Temperature only: "C" is coulomb and "F" farad to pint, never a temperature.
_TEMPERATURE_ALIASES = {
    "c": "degC",
    "°c": "degC",
    "degc": "degC",
    "degreec": "degC",
    "degreesc": "degC",
    "celsius": "degC",
    "f": "degF",
    "°f": "degF",
    "degf": "degF",
    "degreesf": "degF",
    "fahrenheit": "degF",
    "k": "K",
    "kelvin": "K",
}
# "W/mK", "W/m.K", "W/m2K", "J/kgK", "kJ/kg-K": per (length, area or mass) times kelvin.
_PER_X_KELVIN = re.compile(r"/\s*\(?\s*(kg|g|m\*\*2|m\^2|m²|m)\s*[.·*\-]?\s*K\s*\)?$")
_PER_KELVIN_KINDS = ("thermal conductivity", "heat transfer coefficient", "specific heat")


@lru_cache(maxsize=64)
def _kind_of_dimensionality(dim_str: str) -> str:
    for kind in KINDS.values():
        if str(kind.dimensionality) == dim_str and kind.name not in ("angle", "frequency"):
            return kind.name
    return f"a quantity of dimension {dim_str}"


def _describe(q: pint.Quantity) -> str:
    name = _kind_of_dimensionality(str(q.dimensionality))
    if name.startswith("a quantity"):
        return name
    article = "an" if name[0] in "aeiou" else "a"
    return f"{article} {name}"


_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
_BARE_POWER = re.compile(r"(?<=[A-Za-z])([23])(?![\d.])")
_DECIMAL_COMMA = re.compile(r"^\s*[-+]?\d*,\d")


def _alias(unit: str, kind: str | None) -> str:
    key = re.sub(r"\s+", "", unit).lower()
    if kind == "temperature" and key in _TEMPERATURE_ALIASES:
        return _TEMPERATURE_ALIASES[key]
    return _ALIASES.get(key, unit)


def _normalise(text: str, kind: str | None = None) -> tuple[str, bool]:
    """Engineer-typed units to pint syntax ("kg/m3" -> "kg/m**3"); also says if unit-less."""
    m = _NUMBER.match(text)
    if not m:
        return text.strip(), False
    number, unit = m.group(1), m.group(2)
    if not unit:
        return number, True
    unit = _BARE_POWER.sub(r"**\1", _alias(unit, kind))
    if kind in _PER_KELVIN_KINDS:
        unit = _PER_X_KELVIN.sub(r"/(\1*K)", unit)
    return f"{number} {unit}", False


def _expected(kind: str) -> str:
    return f"expected {_article(kind)} {kind} ({EXAMPLES[kind]})"


def _parse(field: str, text: str, kind: str) -> pint.Quantity:
    if _DECIMAL_COMMA.match(text):
        raise InputError(
            field,
            message=f'{field}: "{text}" has a comma; use a decimal point and no thousands '
            'separator (e.g. "0.4 m", "1500 kg/m3")',
        )
    normalised, unitless = _normalise(text, kind)
    if unitless and kind not in ("fraction", "angle"):
        raise InputError(field, message=f'{field}: "{text}" needs a unit, {_expected(kind)}')
    try:
        q = ureg.Quantity(normalised)
    except Exception:  # pint raises many types for garbage: report them all the same way
        m = _NUMBER.match(text)
        what = f'has an unknown unit "{m.group(2)}"' if m else "is not a quantity with a unit"
        raise InputError(
            field,
            f'"{text}"',
            accepted="",
            message=f'{field}: "{text}" {what}, {_expected(kind)}',
        ) from None
    if not isinstance(q.magnitude, int | float) or not math.isfinite(float(q.magnitude)):
        raise InputError(field, message=f'{field}: "{text}" is not a finite number with a unit')
    return q


def to_si(field: str, value: str | float | int, kind: str) -> float:
    """Convert ``value`` (a string with unit, or a bare number already in SI) to an SI float.

    Parameters
    ----------
    field : str
        Name used in error messages (``"operation.speed"``).
    value : str or number
        ``"1.5 rpm"``; a bare number is taken as SI, except for angles and the kinds of
        :data:`UNIT_REQUIRED` (rotation rates, flows), which need a unit (zero excepted).
    kind : str
        A key of :data:`KINDS`.

    Examples
    --------
    >>> round(to_si("speed", "60 rpm", "rotation rate"), 6)
    6.283185
    >>> to_si("T", "1100 degC", "temperature")
    1373.15
    >>> round(to_si("slope", "2 deg", "angle"), 6)
    0.034907
    >>> to_si("speed", "3 m", "rotation rate")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: speed: "3 m" is a length, expected a rotation rate (rpm, rad/s)
    """
    target = KINDS[kind]
    if isinstance(value, bool):
        raise InputError(field, message=f"{field}: {value!r} is not a quantity")
    if isinstance(value, int | float):
        if not math.isfinite(value):
            raise InputError(field, message=f"{field}: {value} is not a finite number")
        if kind == "angle":
            raise InputError(
                field,
                message=f'{field}: bare number {value} needs a unit (e.g. "{value} deg", "{value} rad"'
                ', or "% " / "m/m" for a grade)',
            )
        if kind in UNIT_REQUIRED and value != 0:
            raise InputError(
                field,
                message=f'{field}: bare number {value} needs a unit (e.g. "{value} {UNIT_REQUIRED[kind]}")',
            )
        return float(value)
    if not isinstance(value, str):
        raise InputError(field, message=f"{field}: {value!r} is not a quantity with a unit")
    q = _parse(field, value, kind)
    if kind == "angle":
        units = str(q.units)
        if q.dimensionless and not any(a in units for a in _ANGLE_UNITS):
            if _normalise(value)[1]:
                raise InputError(
                    field,
                    message=f'{field}: "{value}" needs a unit (deg, rad, or % / m/m for a grade)',
                )
            return math.atan(float(q.to("dimensionless").magnitude))  # a grade, rise over run
    if q.dimensionality != target.dimensionality:
        raise InputError(field, message=f'{field}: "{value}" is {_describe(q)}, {_expected(kind)}')
    if kind == "rotation rate" and not any(a in str(q.units) for a in _ANGLE_UNITS):
        # pint counts radians as 1, so "1.5 1/min" or "0.1 Hz" would silently be rad per time;
        # engineers mean revolutions. Ask rather than guess.
        raise InputError(
            field,
            message=f'{field}: "{value}" does not say revolutions or radians, {_expected(kind)}',
        )
    return float(q.to(target.si).magnitude)


def _article(name: str) -> str:
    return "an" if name[0] in "aeiou" else "a"


def format_quantity(value: float, kind: str, unit: str | None = None, digits: int = 4) -> str:
    """Format an SI value in ``unit`` (default: the kind's SI unit), e.g. ``"66.9 rpm"``."""
    target = KINDS[kind]
    q = ureg.Quantity(value, target.si)
    if unit:
        q = q.to(unit)
    return f"{q.magnitude:.{digits}g} {unit or target.si}"
