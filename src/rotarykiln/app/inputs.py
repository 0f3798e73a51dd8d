"""The main inputs the app lets a user edit: a table of dotted paths into the case file.

The app works on the case file's raw mapping (parsed YAML, values as written: ``"1.5 rpm"``), not
on the validated :class:`~rotarykiln.case.Case`: it shows the entries of :data:`MAIN_INPUTS` that the
loaded case has, writes edits back into the mapping and validates the result with
:func:`rotarykiln.case.parse_case`, so a case keeps every section the app does not show, and a
change of the case schema only changes the paths listed here.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass
from typing import Any

from rotarykiln.errors import InputError
from rotarykiln.units import EXAMPLES, to_si

__all__ = [
    "MAIN_INPUTS",
    "MainInput",
    "apply_edits",
    "check_value",
    "field_of_error",
    "get_path",
    "present_inputs",
    "value_text",
]


@dataclass(frozen=True)
class MainInput:
    """One editable input: its dotted ``path`` in the case file, a ``label`` and the quantity
    ``kinds`` it accepts (keys of :data:`rotarykiln.units.KINDS`; ``fraction``: a bare number;
    ``gas flow``: a mass, volumetric or normal flow, read by the case itself)."""

    path: str
    label: str
    kinds: tuple[str, ...]


def _row(path: str, label: str, *kinds: str) -> MainInput:
    return MainInput(path, label, kinds)


MAIN_INPUTS: tuple[MainInput, ...] = (
    _row("kiln.length", "Kiln length", "length"),
    _row("kiln.diameter", "Inner diameter", "length"),
    _row("kiln.slope", "Slope", "angle"),
    _row("operation.speed", "Rotation speed", "rotation rate"),
    _row("operation.feed", "Solids feed", "mass flow"),
    _row("operation.feed_temperature", "Solids inlet temperature", "temperature"),
    _row("bed.fill", "Fill fraction", "fraction"),
    _row("bed.residence_time", "Solids residence time", "time"),
    _row("material.bulk_density", "Bulk density", "density"),
    _row("gas.flow", "Gas flow", "gas flow"),
    _row("gas.temperature", "Gas inlet temperature", "temperature"),
    _row("burner.fuel_flow", "Fuel flow", "gas flow"),
    _row("burner.primary_air.flow", "Primary air flow", "gas flow"),
    _row("burner.secondary_air.flow", "Secondary air flow", "gas flow"),
    _row("wall.U", "Wall loss coefficient", "heat transfer coefficient"),
    _row("wall.ambient_temperature", "Ambient temperature", "temperature"),
)
"""The inputs the app shows, in this order, when the loaded case has them."""

_MISSING = object()


def get_path(raw: Any, path: str, default: Any = None) -> Any:
    """The value at a dotted ``path`` of a nested mapping, else ``default``.

    >>> get_path({"kiln": {"length": "5.5 m"}}, "kiln.length")
    '5.5 m'
    >>> get_path({"kiln": {}}, "kiln.slope") is None
    True
    """
    node = raw
    for key in path.split("."):
        if not isinstance(node, dict) or key not in node:
            return default
        node = node[key]
    return node


def value_text(value: Any) -> str:
    """A raw case value as the text of an input field (``0.17``, ``"1.5 rpm"``)."""
    if isinstance(value, float) and value.is_integer():
        return str(int(value)) if abs(value) < 1e15 else repr(value)
    return str(value)


def present_inputs(raw: Any) -> list[tuple[MainInput, str]]:
    """The main inputs a raw case mapping has, with the text of their values.

    >>> [(i.path, t) for i, t in present_inputs({"operation": {"speed": "2 rpm"}})]
    [('operation.speed', '2 rpm')]
    """
    out = []
    for item in MAIN_INPUTS:
        value = get_path(raw, item.path, _MISSING)
        if value is not _MISSING and value is not None and not isinstance(value, dict | list):
            out.append((item, value_text(value)))
    return out


def _by_path(path: str) -> MainInput:
    for item in MAIN_INPUTS:
        if item.path == path:
            return item
    raise KeyError(path)


def _bare_number(text: str) -> float | None:
    try:
        value = float(text)
    except ValueError:
        return None
    return value


def check_value(path: str, text: Any) -> str | float:
    """The value to write into the case for the text typed in the field of ``path``.

    A fraction is returned as a number; any other quantity as the text, once it is read with a
    unit of one of the input's kinds (:func:`rotarykiln.units.to_si`).

    Raises
    ------
    InputError
        One line naming the field: empty, a number without a unit, a unit of the wrong kind.

    Examples
    --------
    >>> check_value("operation.speed", " 2 rpm ")
    '2 rpm'
    >>> check_value("bed.fill", "0.15")
    0.15
    >>> check_value("operation.speed", "2")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: operation.speed: 2 has no unit (write it with one: rpm, rad/s)
    """
    item = _by_path(path)
    text = "" if text is None else str(text).strip()
    if not text:
        raise InputError(path, message=f"{path}: empty, expected {_expected(item)}")
    number = _bare_number(text)
    if item.kinds == ("fraction",):
        if number is not None:
            if not math.isfinite(number):
                raise InputError(path, text, "a finite number")
            return number
        to_si(path, text, "fraction")  # "15 %"
        return text
    if number is not None:
        raise InputError(
            path, message=f"{path}: {text} has no unit (write it with one: {_expected(item)})"
        )
    if any(kind in _CASE_READS for kind in item.kinds):
        return text  # the case reads it when the run validates it
    first = None
    for kind in item.kinds:
        try:
            to_si(path, text, kind)
            return text
        except InputError as exc:
            first = first or exc
    raise first


_EXAMPLES = {**EXAMPLES, "gas flow": "kg/h, m3/h, Nm3/h, L/s"}
_CASE_READS = ("gas flow",)  # kinds whose text only the case reads (normal volumes...)


def _expected(item: MainInput) -> str:
    return " or ".join(_EXAMPLES.get(k, k) for k in item.kinds)


def apply_edits(raw: dict, values: dict[str, Any]) -> dict:
    """A copy of the raw case with the fields' texts written in (each checked by
    :func:`check_value`; the first bad one raises its :class:`InputError`)."""
    out = copy.deepcopy(raw)
    for path, text in values.items():
        value = check_value(path, text)
        node = out
        *parents, last = path.split(".")
        for key in parents:
            node = node[key]
        node[last] = value
    return out


def field_of_error(error: InputError, paths: list[str]) -> str | None:
    """The shown input an :class:`InputError` is about (its field, or the message's first
    word), else None.

    >>> field_of_error(InputError("kiln.diameter", -1, "> 0"), ["kiln.length", "kiln.diameter"])
    'kiln.diameter'
    """
    head = str(error).split(":", 1)[0].strip()
    for name in (getattr(error, "field", None), head):
        if not isinstance(name, str):
            continue
        for path in paths:
            if name == path or name.startswith(path + ".") or name.startswith(path + "["):
                return path
    return None
