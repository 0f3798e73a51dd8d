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

import numpy as np
import pint

from rotarykiln.errors import InputError, check_positive

__all__ = [
    "KINDS",
    "Kind",
    "ureg",
    "to_si",
    "format_quantity",
    "GasFlow",
    "gas_flow",
    "molar_volume",
    "R_GAS",
    "NORMAL_STATE",
    "STANDARD_STATE",
    "SCF_STATE",
]


def _registry() -> pint.UnitRegistry:
    """pint's registry, its parsed definitions cached in the user's cache folder (pint's
    ``cache_folder=":auto:"``: 0.03 s instead of 0.2 s at every start); without a writable cache
    (or with a damaged one) the definitions are parsed afresh, with the same result."""
    try:
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except Exception:  # pragma: no cover - no cache folder, or a cache file being written
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True)


ureg = _registry()
ureg.define("rpm_ = revolution / minute")  # "rpm" already exists; keep an alias harmless


@dataclass(frozen=True)
class Kind:
    """A kind of physical quantity: its human name, SI unit and pint dimensionality."""

    name: str
    si: str

    @property
    def dimensionality(self):
        return _dimensionality(self.si)


@lru_cache(maxsize=64)
def _dimensionality(unit: str):
    """pint's dimensionality of ``unit`` (an SI unit text such as ``"kg/s"``), computed once."""
    return ureg.Quantity(1.0, unit).dimensionality


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
_NOT_FINITE = re.compile(r"^\s*[-+]?(nan|inf|infinity)\b", re.I)

MAX_QUANTITY_CHARS = 64
"""Longest quantity text read ("0.406 m" has 7 characters): longer ones are refused unparsed."""

# In a unit (pint syntax, after _normalise) digits are only small powers after a unit name or a
# parenthesis ("m**3", "s^-1") or a leading "1/" ("1/min"); with no digits, "+" or "-" left,
# pint can only multiply and divide units: no arithmetic on numbers ("9**9**9 m", "1+2 m").
_UNIT_POWER = re.compile(r"(?:(?<=[^\W\d_])|(?<=\)))\s*(?:\*\*|\^)\s*-?\d(?![\d.])")
_UNIT_CHARS = re.compile(r"^(?:[^\W\d]|[\s/*.·()%°²³])*$")  # letters, _, joiners, no digit


def _plain_unit(unit: str) -> bool:
    """True when ``unit`` (pint syntax) names units joined by ``*``, ``/``, spaces, with small
    powers: no number, sum or difference that pint would evaluate."""
    rest = _UNIT_POWER.sub("", re.sub(r"^\s*1\s*/", "/", unit))
    if not _UNIT_CHARS.match(rest) or "**" in rest or not re.search(r"[^\W\d_]|%", rest):
        return False
    depth = 0
    for ch in rest:
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if depth < 0 or depth > 2:
            return False
    return depth == 0


def _is_unit(text: str, kind: str | None) -> bool:
    """True when ``text`` alone is a unit ("m", "kg/h"): a value that forgot its number."""
    unit = _normalise(f"1 {text}", kind)[0][2:]
    if not _plain_unit(unit):
        return False
    try:
        ureg.Unit(unit)
    except Exception:  # pint raises many types for garbage
        return False
    return True


def _check_length(field: str, text: str, example: str = "0.4 m") -> None:
    if len(text) > MAX_QUANTITY_CHARS:
        raise InputError(
            field,
            message=f'{field}: "{text[:20]}..." ({len(text)} characters) is too long for a '
            f'quantity (at most {MAX_QUANTITY_CHARS}; a number and a unit such as "{example}")',
        )


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
    _check_length(field, text)
    if _DECIMAL_COMMA.match(text):
        raise InputError(
            field,
            message=f'{field}: "{text}" has a comma; use a decimal point and no thousands '
            'separator (e.g. "0.4 m", "1500 kg/m3")',
        )
    m = _NUMBER.match(text)
    if not m:
        if _NOT_FINITE.match(text):
            raise InputError(field, message=f'{field}: "{text}" is not a finite number with a unit')
        what = "has no number" if _is_unit(text, kind) else "is not a quantity with a unit"
        raise InputError(field, message=f'{field}: "{text}" {what}, {_expected(kind)}')
    normalised, unitless = _normalise(text, kind)
    if unitless and kind not in ("fraction", "angle"):
        raise InputError(field, message=f'{field}: "{text}" needs a unit, {_expected(kind)}')
    if not unitless and not _plain_unit(normalised.split(" ", 1)[1]):
        raise InputError(
            field,
            message=f'{field}: "{text}" is not a number followed by a unit (no arithmetic), '
            f"{_expected(kind)}",
        )
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

    Returns
    -------
    float
        The value in the kind's SI unit (:data:`KINDS`: m, rad, rad/s, kg/s, K ...).

    Notes
    -----
    pint parses a text in about 0.1 ms; the SI value of each distinct (text, kind) is kept
    (the last :data:`TEXT_CACHE_SIZE`), so the texts of a case, or of a study's variants, are
    parsed once per process. A refused text is not kept: it is refused again, naming ``field``.

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
    KINDS[kind]  # noqa: B018 (an unknown kind is a KeyError, whatever the value)
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
    if value is None:
        raise InputError(field, message=f"{field}: empty, {_expected(kind)}")
    if not isinstance(value, str):
        raise InputError(field, message=f"{field}: {value!r} is not a quantity with a unit")
    if type(value) is str and len(value) <= MAX_QUANTITY_CHARS:
        try:
            return _text_to_si(value, kind)
        except InputError:
            pass  # refused: converted again below, for the message naming the field
    return _convert_text(field, value, kind)


#: Distinct (text, kind) pairs whose SI value :func:`to_si` keeps (a sweep's values, the
#: fields of the cases loaded): pint parses a text in ~0.1 ms, a cached one is read in ~0.2 us.
TEXT_CACHE_SIZE = 8192


@lru_cache(maxsize=TEXT_CACHE_SIZE)
def _text_to_si(text: str, kind: str) -> float:
    """The SI value of a quantity ``text`` of ``kind`` (:func:`to_si`'s conversion of a text,
    cached per distinct text: the same float as converting it afresh; refusals are not cached,
    and are raised again, naming the field, by the caller).

    A number followed by a unit already read once for ``kind`` is converted by that unit's
    factor (or kelvin offset) without pint (:func:`_unit_conversion`): a study's sampled
    values are each a new text with one of a few units."""
    m = _NUMBER.match(text)
    if m and m.group(2) and kind != "angle":
        conversion = _unit_conversion(m.group(2), kind)
        if conversion is not None:
            si = converted(float(m.group(1)), conversion)
            if math.isfinite(si):
                return si
    return _convert_text("", text, kind)


def linear_conversion(zero: float, one: float) -> tuple[float, float] | None:
    """``(factor, offset)`` of a unit from its conversions of 0 and 1 (``zero``, ``one``, in
    the target unit): a factor (``zero`` 0) or a kelvin offset (``one - zero`` exactly 1, degC
    to K); None for anything else (degF: through pint each time) or a non-finite one."""
    if not (math.isfinite(zero) and math.isfinite(one)):
        return None
    if zero == 0.0:
        return one, 0.0
    if one - zero == 1.0:
        return 1.0, zero
    return None


def converted(number: float, conversion: tuple[float, float]) -> float:
    """``number`` times the factor, or plus the offset, of :func:`linear_conversion`: the
    same float as pint's conversion (which multiplies by the same factor or adds the same
    offset)."""
    factor, offset = conversion
    return number * factor if offset == 0.0 else number + offset


@lru_cache(maxsize=256)
def _unit_conversion(unit: str, kind: str) -> tuple[float, float] | None:
    """``(factor, offset)`` such that ``number unit`` is ``number * factor`` (offset 0) or
    ``number + offset`` (factor 1: degC to K) in the SI unit of ``kind``: the same floats as
    pint's conversion of the whole text (pint multiplies the magnitude by the same factor, or
    adds the same offset). None for a unit that is neither (degF, angles: their texts go
    through pint each time) or that ``kind`` refuses (the text is then refused by pint, with
    its message)."""
    try:
        return linear_conversion(
            _convert_text("", f"0 {unit}", kind), _convert_text("", f"1 {unit}", kind)
        )
    except InputError:
        return None


@lru_cache(maxsize=256)
def _units_text(units) -> str:
    """``str(units)`` of a quantity's pint units, formatted once per distinct units."""
    return str(units)


def _convert_text(field: str, value: str, kind: str) -> float:
    """:func:`to_si` of a text ``value``: parsed by pint and checked against ``kind``."""
    target = KINDS[kind]
    q = _parse(field, value, kind)
    if kind == "angle":
        units = _units_text(q.units)
        if q.dimensionless and not any(a in units for a in _ANGLE_UNITS):
            if _normalise(value)[1]:
                raise InputError(
                    field,
                    message=f'{field}: "{value}" needs a unit (deg, rad, or % / m/m for a grade)',
                )
            return math.atan(float(q.to("dimensionless").magnitude))  # a grade, rise over run
    if q.dimensionality != target.dimensionality:
        raise InputError(field, message=f'{field}: "{value}" is {_describe(q)}, {_expected(kind)}')
    if kind == "rotation rate" and not any(a in _units_text(q.units) for a in _ANGLE_UNITS):
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


# --------------------------------------------------------------------------------------------
# Gas flows as engineers type them: mass, molar, normal/standard volume, or volume at a stated
# reference state. Kept apart from to_si because the result is not one SI kind but two.

R_GAS = 8.31446261815324
"""Molar gas constant, J/(mol K) (CODATA 2018, exact)."""

NORMAL_STATE = (273.15, 101325.0)
"""Normal conditions of DIN 1343 (0 degC, 1 atm), K and Pa: the "N" of Nm3/h, NL/min."""

STANDARD_STATE = (288.15, 101325.0)
"""Standard conditions of ISO 13443 (15 degC, 1 atm), K and Pa: the "S" of Sm3/h, SL/s."""

SCF_STATE = ((60.0 - 32.0) / 1.8 + 273.15, 14.696 * 6894.757293168361)
"""Standard cubic foot (scfm, scfh): 60 degF and 14.696 psia (288.706 K, 101325.35 Pa), the US
convention of the compressed-air and process industries; the US natural-gas industry's
14.73 psia differs by 0.2 %: give such flows as plain ft3/min with a reference state."""

GAS_FLOW_ACCEPTED = (
    "a mass flow (kg/h, g/s, t/h), a molar flow (mol/s, kmol/h), a normal volume flow "
    "(Nm3/h, NL/min: 0 degC, 1 atm), a standard volume flow (Sm3/h, SL/s: 15 degC, 1 atm; "
    "scfm, scfh: 60 degF, 14.696 psia)"
)
"""What :func:`gas_flow` accepts, as quoted in its error messages."""

_REFERENCED_UNIT = re.compile(r"^(?P<ref>[NS])(?P<vol>(?i:m3|l|ml|cm3|dm3))(?P<per>/.+)?$")
_NANO_LOOKALIKE = re.compile(r"^[ns](?i:m3|l|ml|cm3|dm3)/")
_SCF_UNITS = {
    "scfs": "s",
    "scfm": "min",
    "scfh": "h",
    "scfd": "day",
    "scf/s": "s",
    "scf/min": "min",
    "scf/h": "h",
    "scf/hr": "h",
    "scf/d": "day",
    "scf/day": "day",
}
_INSTRUMENT_UNITS = {"sccm", "sccs", "slm", "slpm", "slph", "smlpm", "sclm"}
_STATE_NAMES = {
    "N": "a normal volume flow (0 degC, 101325 Pa, DIN 1343)",
    "S": "a standard volume flow (15 degC, 101325 Pa, ISO 13443)",
    "scf": "a standard volume flow (60 degF, 14.696 psia)",
}


@dataclass(frozen=True)
class GasFlow:
    """A gas flow read by :func:`gas_flow`: a mass flow (kg/s) or a molar flow (mol/s).

    Attributes
    ----------
    kind : str
        ``"mass"`` (``value`` in kg/s) or ``"molar"`` (``value`` in mol/s).
    value : float
        The flow, kg/s or mol/s according to ``kind``.
    reference_temperature, reference_pressure : float or None, K and Pa
        The state a volume flow was converted at (273.15 K and 101325 Pa for Nm3/h); None for a
        flow given as mass or moles.
    """

    kind: str
    value: float
    reference_temperature: float | None = None
    reference_pressure: float | None = None

    def mass_flow(self, molar_mass: float) -> float:
        """The flow in kg/s, given the molar mass of the gas in kg/mol."""
        return self.value if self.kind == "mass" else self.value * molar_mass

    def molar_flow(self, molar_mass: float) -> float:
        """The flow in mol/s, given the molar mass of the gas in kg/mol."""
        return self.value if self.kind == "molar" else self.value / molar_mass


def molar_volume(T, p=101325.0):
    """Molar volume of an ideal gas, :math:`V_m = R T / p`.

    At 1 atm: 22.414 L/mol at 0 degC (normal conditions, DIN 1343), 23.645 L/mol at 15 degC
    (standard conditions, ISO 13443), 24.465 L/mol at 25 degC.

    Parameters
    ----------
    T : float or array, K
        Temperature.
    p : float or array, Pa
        Pressure (default 101325 Pa, 1 atm).

    Returns
    -------
    float or array, m3/mol
        Molar volume.

    Examples
    --------
    >>> round(molar_volume(273.15), 6)  # m3/mol
    0.022414
    >>> round(molar_volume(288.15) * 1e3, 3), round(molar_volume(298.15) * 1e3, 3)
    (23.645, 24.465)

    References
    ----------
    R from CODATA 2018 (exact in the SI since 2019); DIN 1343:1990 (normal conditions);
    ISO 13443:1996 (standard reference conditions for natural gas).
    """
    check_positive("T", T, "K")
    check_positive("p", p, "Pa")
    v = R_GAS * np.asarray(T, dtype=float) / np.asarray(p, dtype=float)
    return float(v) if v.ndim == 0 else v


def _sibling(field: str, name: str) -> str:
    """``"burner.air_flow"`` -> ``"burner.<name>"``: the key beside ``field`` in its section."""
    return f"{field.rsplit('.', 1)[0]}.{name}" if "." in field else name


def _reference(field: str, value, kind: str) -> float | None:
    if value is None:
        return None
    si = to_si(field, value, kind)
    if not (math.isfinite(si) and si > 0):
        raise InputError(field, message=f"{field}: {value!r} is not > 0 {KINDS[kind].si}")
    return si


def gas_flow(
    value,
    field: str,
    *,
    reference_temperature=None,
    reference_pressure=None,
    allow_zero: bool = False,
) -> GasFlow:
    """Read a burner or air flow as an engineer types it: mass, molar or volume at a known state.

    Accepted: mass flows (``"2.2 kg/h"``, ``"0.5 g/s"``, ``"1 t/h"``); molar flows
    (``"0.1 mol/s"``, ``"3 kmol/h"``); normal volume flows, 0 degC and 101325 Pa (DIN 1343)
    (``"12 Nm3/h"``, ``"12 Nm³/h"``, ``"0.83 NL/s"``, ``"5 Nl/min"``); standard volume flows,
    15 degC and 101325 Pa (ISO 13443) (``"12 Sm3/h"``, ``"0.8 SL/s"``), or 60 degF and 14.696
    psia for standard cubic feet (``"10 scfm"``, ``"600 scfh"``); plain volume flows
    (``"1.42 L/s"``, ``"3 m3/h"``) only when ``reference_temperature`` is given, converted with
    :math:`\\dot n = p_{ref} \\dot V / (R T_{ref})`. A volume is returned as a molar flow.
    Refused with :class:`~rotarykiln.errors.InputError` naming ``field``: bare numbers (zero
    excepted when allowed), NaN and infinities, negative flows, zero unless ``allow_zero``, a
    plain volume flow without a reference temperature, a normal or standard volume flow whose
    own reference state contradicts ``reference_temperature`` or ``reference_pressure``, and
    instrument units whose reference state varies by maker (sccm, slm).

    Parameters
    ----------
    value : str
        The flow with its unit, e.g. ``"12 Nm3/h"``.
    field : str
        Dotted path of the field (``"burner.air_flow"``), named in error messages; its section
        (``"burner"``) names the reference keys (``"burner.reference_temperature"``).
    reference_temperature : float or str, K
        Temperature at which a plain volume flow was measured (a float in K, or a string with a
        unit such as ``"25 degC"``); None (default) refuses plain volume flows.
    reference_pressure : float or str, Pa
        Pressure of that state (default 101325 Pa when ``reference_temperature`` is given).
    allow_zero : bool
        Accept a zero flow (default False: zero is refused).

    Returns
    -------
    GasFlow
        ``kind`` ``"mass"`` with ``value`` in [kg/s], or ``"molar"`` with ``value`` in [mol/s];
        the reference state [K, Pa] a volume was converted at (None for mass and molar flows).

    Notes
    -----
    The flow read from each distinct text and reference state is kept (a frozen
    :class:`GasFlow`; the last 1024): a burner's flows are read by its checks at load and
    again when the kiln is built. Refusals are not kept.

    Examples
    --------
    >>> f = gas_flow("12 Nm3/h", "burner.air_flow")
    >>> f.kind, round(f.value, 6), f.reference_temperature
    ('molar', 0.148717, 273.15)
    >>> gas_flow("2.2 kg/h", "burner.fuel_flow")
    GasFlow(kind='mass', value=0.0006111111111111112, reference_temperature=None, reference_pressure=None)
    >>> round(gas_flow("1.42 L/s", "burner.air_flow", reference_temperature=298.15).value, 5)
    0.05804
    >>> gas_flow("3 m3/h", "burner.air_flow")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: burner.air_flow: "3 m3/h" is a volume flow at an unstated temperature and pressure; expected a normal volume flow such as 12 Nm3/h, a mass flow (kg/h) or a molar flow (mol/s), or give burner.reference_temperature

    References
    ----------
    DIN 1343:1990 (normal conditions, 273.15 K and 101325 Pa); ISO 13443:1996 (standard
    reference conditions, 288.15 K and 101325 Pa); CODATA 2018 for R.
    """
    key = (value, reference_temperature, reference_pressure)
    if type(value) is str and all(
        type(x) in (float, int, type(None)) or (type(x) is str and len(x) <= MAX_QUANTITY_CHARS)
        for x in key
    ):
        try:
            return _cached_gas_flow(*_typed(key), bool(allow_zero))
        except InputError:
            pass  # refused: read again below, for the message naming the field
    return _gas_flow(
        value,
        field,
        reference_temperature=reference_temperature,
        reference_pressure=reference_pressure,
        allow_zero=allow_zero,
    )


def _typed(values) -> tuple:
    """``(type, repr)`` of each value: a cache key that tells 1 from 1.0 and 0.0 from -0.0."""
    return tuple((type(v), repr(v), v) for v in values)


@lru_cache(maxsize=1024)
def _cached_gas_flow(value, reference_temperature, reference_pressure, allow_zero) -> GasFlow:
    """:func:`gas_flow` of a text flow, cached per distinct text and reference state (a frozen
    :class:`GasFlow`: the same as reading it afresh; refusals are not cached)."""
    return _gas_flow(
        value[2],
        "",
        reference_temperature=reference_temperature[2],
        reference_pressure=reference_pressure[2],
        allow_zero=allow_zero,
    )


#: The SI unit of each kind of gas flow (:func:`_flow_unit`).
_FLOW_KINDS = (("mass", "kg/s"), ("molar", "mol/s"), ("volume", "m**3/s"))


@lru_cache(maxsize=256)
def _flow_unit(pint_unit: str) -> tuple[str, tuple[float, float]] | None:
    """The kind of a gas flow unit (``"mass"``, ``"molar"``, ``"volume"``) and its
    :func:`linear_conversion` to kg/s, mol/s or m3/s, from pint's conversions of 0 and 1 of
    it; None for a unit pint does not know, or of another dimension (its texts then go through
    pint, which words the refusal)."""
    try:
        zero, one = ureg.Quantity(0.0, pint_unit), ureg.Quantity(1.0, pint_unit)
        for kind, si in _FLOW_KINDS:
            if one.dimensionality == _dimensionality(si):
                conversion = linear_conversion(
                    float(zero.to(si).magnitude), float(one.to(si).magnitude)
                )
                return None if conversion is None else (kind, conversion)
    except Exception:  # pint raises many types for garbage
        return None
    return None


def _gas_flow(
    value,
    field: str,
    *,
    reference_temperature=None,
    reference_pressure=None,
    allow_zero: bool = False,
) -> GasFlow:
    """:func:`gas_flow`, uncached."""
    t_field = _sibling(field, "reference_temperature")
    p_field = _sibling(field, "reference_pressure")
    t_ref = _reference(t_field, reference_temperature, "temperature")
    p_ref = _reference(p_field, reference_pressure, "pressure")
    bound = ">= 0" if allow_zero else "> 0"
    examples = '"2.2 kg/h", "12 Nm3/h"'

    if isinstance(value, bool) or not isinstance(value, str | int | float):
        raise InputError(
            field, message=f"{field}: {value!r} is not a gas flow with a unit ({examples})"
        )
    if isinstance(value, int | float):
        if not math.isfinite(value):
            raise InputError(field, message=f"{field}: {value} is not a finite number")
        if value == 0:
            if allow_zero:
                return GasFlow("mass", 0.0)
            raise InputError(field, message=f"{field}: {value} is zero, expected a flow > 0")
        raise InputError(
            field,
            message=f'{field}: bare number {value} needs a unit (e.g. "{value} kg/h", '
            f'"{value} Nm3/h")',
        )
    text = value
    _check_length(field, text, "12 Nm3/h")
    if _DECIMAL_COMMA.match(text):
        raise InputError(
            field,
            message=f'{field}: "{text}" has a comma; use a decimal point and no thousands '
            'separator (e.g. "12.5 Nm3/h")',
        )
    if _NOT_FINITE.match(text):
        raise InputError(field, message=f'{field}: "{text}" is not a finite number with a unit')
    m = _NUMBER.match(text)
    if not m:
        what = "has no number" if _is_unit(text, "mass flow") else "is not a flow with a unit"
        raise InputError(field, message=f'{field}: "{text}" {what}, expected {GAS_FLOW_ACCEPTED}')
    number, unit = float(m.group(1)), m.group(2)
    if not unit:
        raise InputError(
            field,
            message=f'{field}: "{text}" needs a unit, expected {GAS_FLOW_ACCEPTED}',
        )
    if not math.isfinite(number):
        raise InputError(field, message=f'{field}: "{text}" is not a finite number with a unit')
    if number < 0 or (number == 0 and not allow_zero):
        what = "negative" if number < 0 else "zero"
        raise InputError(field, message=f'{field}: "{text}" is {what}, expected a flow {bound}')

    compact = re.sub(r"\s+", "", unit).replace("³", "3").replace("**", "").replace("^", "")
    state = None  # "N", "S" or "scf" for a volume whose unit states its reference
    if compact.lower() in _INSTRUMENT_UNITS:
        raise InputError(
            field,
            message=f'{field}: "{text}": the reference state of {unit} differs between makers; '
            f"write NmL/min or NL/min (0 degC, 1 atm), SmL/min or SL/min (15 degC, 1 atm), or "
            f"mL/min with {t_field}",
        )
    if compact.lower() in _SCF_UNITS:
        state, pint_unit = "scf", f"ft**3/{_SCF_UNITS[compact.lower()]}"
    elif r := _REFERENCED_UNIT.match(compact):
        state = r.group("ref")
        pint_unit = _BARE_POWER.sub(r"**\1", r.group("vol").lower()) + (r.group("per") or "")
    elif _NANO_LOOKALIKE.match(compact):
        raise InputError(
            field,
            message=f'{field}: "{text}" has a lower-case reference prefix (N and S are capitals: '
            f'"nm3" would be cubic nanometres); write '
            f'"{compact[0].upper()}{compact[1:]}" for {_STATE_NAMES[compact[0].upper()]}',
        )
    else:
        pint_unit = _normalise(f"1 {unit}", "mass flow")[0][2:]
    if not _plain_unit(pint_unit):
        raise InputError(
            field,
            message=f'{field}: "{text}" is not a number followed by a unit (no arithmetic), '
            f"expected {GAS_FLOW_ACCEPTED}",
        )
    known = _flow_unit(pint_unit)
    if known is not None:  # a unit read before: its factor (the same float as pint's)
        kind, conversion = known
        if kind != "volume":
            return GasFlow(kind, converted(number, conversion))
        volume = converted(number, conversion)
    else:
        try:
            q = ureg.Quantity(number, pint_unit)
        except Exception:  # pint raises many types for garbage: report them all the same way
            raise InputError(
                field,
                message=f'{field}: "{text}" has an unknown unit "{unit}", expected '
                f"{GAS_FLOW_ACCEPTED}",
            ) from None

        dims = q.dimensionality
        if dims == _dimensionality("kg/s"):
            return GasFlow("mass", float(q.to("kg/s").magnitude))
        if dims == _dimensionality("mol/s"):
            return GasFlow("molar", float(q.to("mol/s").magnitude))
        if dims != _dimensionality("m**3/s"):
            if state:
                raise InputError(
                    field,
                    message=f'{field}: "{text}" is not a normal or standard volume per time, '
                    f'expected e.g. "12 Nm3/h", "0.8 SL/s", "10 scfm"',
                )
            raise InputError(
                field,
                message=f'{field}: "{text}" is {_describe(q)}, expected {GAS_FLOW_ACCEPTED}',
            )
        volume = float(q.to("m**3/s").magnitude)
    if state is not None:
        own_t, own_p = {"N": NORMAL_STATE, "S": STANDARD_STATE, "scf": SCF_STATE}[state]
        for given, own, key, unit_si in (
            (t_ref, own_t, t_field, "K"),
            (p_ref, own_p, p_field, "Pa"),
        ):
            if given is not None and not math.isclose(given, own, rel_tol=1e-6):
                raise InputError(
                    field,
                    message=f'{field}: "{text}" is {_STATE_NAMES[state]} but {key} is '
                    f"{given:.6g} {unit_si}: ambiguous; give either a plain volume flow (e.g. "
                    f'"{m.group(1)} m3/h") with {key}, or drop {key}',
                )
        t_ref, p_ref = own_t, own_p
    elif t_ref is None:
        raise InputError(
            field,
            message=f'{field}: "{text}" is a volume flow at an unstated temperature and '
            "pressure; expected a normal volume flow such as 12 Nm3/h, a mass flow (kg/h) or a "
            f"molar flow (mol/s), or give {t_field}",
        )
    elif p_ref is None:
        p_ref = 101325.0
    return GasFlow("molar", p_ref * volume / (R_GAS * t_ref), t_ref, p_ref)
