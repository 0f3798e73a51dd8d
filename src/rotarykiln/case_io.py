"""Case files for editors and round trips: the JSON Schema of a case, and a case written back.

:func:`dump_case` turns a validated :class:`~rotarykiln.case.Case` back into a mapping with units
(``"5.5 m"``, ``"1.5 rpm"``, ``"62 kg/h"``, ``"298.15 K"``) and :func:`case_to_yaml` /
:func:`write_case` into YAML; loading that YAML gives an equal case (the shortest number that
converts back to the same SI float is written, else the SI value in full).

:func:`case_json_schema` is the JSON Schema (draft 2020-12) of the case file, generated from the
pydantic model :class:`rotarykiln.case.Case`; quantity fields accept a number or a string with a
unit (``"1.5 rpm"``), as the loader does. The schema is shipped as
``rotarykiln/case.schema.json`` (``rotarykiln schema`` regenerates it). An editor with the YAML
language server checks a case file against it with a first line::

    # yaml-language-server: $schema=<path or URL of case.schema.json>
"""

from __future__ import annotations

import inspect
import math
import os
import types
import typing
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Union

import yaml
from pydantic import BaseModel, BeforeValidator
from pydantic.json_schema import GenerateJsonSchema
from pydantic_core import core_schema

from rotarykiln.units import EXAMPLES, KINDS, UNIT_REQUIRED, to_si

__all__ = [
    "DISPLAY_UNITS",
    "SCHEMA_DIALECT",
    "case_hash",
    "json_schema_of",
    "case_to_yaml",
    "dump_case",
    "format_si",
    "shipped_schema_path",
    "write_case",
]

SCHEMA_DIALECT = "https://json-schema.org/draft/2020-12/schema"
"""The JSON Schema dialect of :func:`case_json_schema`."""

_QUANTITY_CONVERTERS = ("quantity.<locals>.convert", "_quantity.<locals>.convert")


def _quantity_kind(function: Any) -> str | None:
    """The kind ("length", "rotation rate"...) of a quantity field's converter, else None."""
    if getattr(function, "__qualname__", "") not in _QUANTITY_CONVERTERS:
        return None
    try:
        kind = inspect.getclosurevars(function).nonlocals.get("kind")
    except (TypeError, ValueError):  # pragma: no cover - not a plain closure
        return None
    return kind if isinstance(kind, str) else None


class _CaseSchema(GenerateJsonSchema):
    """pydantic's schema generator, with quantity fields as "a number or a unit string"."""

    def function_before_schema(self, schema: core_schema.BeforeValidatorFunctionSchema):
        kind = _quantity_kind(schema["function"]["function"])
        if kind is None:
            return super().function_before_schema(schema)
        if kind == "angle":
            bare = "a bare number is refused"
        elif kind in UNIT_REQUIRED:
            bare = "a bare number is refused (0 excepted)"
        else:
            bare = "a bare number is taken as SI"
        article = "an" if kind[0] in "aeiou" else "a"
        return {
            "anyOf": [{"type": "number"}, {"type": "string"}],
            "description": f"{article} {kind} with a unit ({EXAMPLES.get(kind, 'SI')}); {bare}",
        }


def _flatten(node: Any) -> Any:
    """``anyOf: [{anyOf: [a, b], description}, c]`` -> ``anyOf: [a, b, c]`` (description kept)."""
    if isinstance(node, list):
        return [_flatten(x) for x in node]
    if not isinstance(node, dict):
        return node
    node = {k: _flatten(v) for k, v in node.items()}
    options = node.get("anyOf")
    if isinstance(options, list):
        flat = []
        for option in options:
            if (
                isinstance(option, dict)
                and set(option) <= {"anyOf", "description"}
                and "anyOf" in option
            ):
                flat.extend(option["anyOf"])
                if "description" in option:
                    node.setdefault("description", option["description"])
            else:
                flat.append(option)
        node["anyOf"] = flat
    return node


def json_schema_of(model) -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of a case file, from its pydantic ``model``.

    Generated from the model (:class:`rotarykiln.case.Case`:
    :func:`rotarykiln.case.case_json_schema`) in validation mode: unknown keys are refused
    (``additionalProperties: false``) and every quantity field accepts a number (SI) or a string
    with a unit. The loader checks more than the schema says (units of the right kind, ranges,
    library names); the schema is what an editor can check while typing.

    Returns
    -------
    dict
        The schema, a JSON-compatible mapping (``$schema``, ``title``, ``$defs``...).

    Examples
    --------
    >>> from rotarykiln.case import Case
    >>> schema = json_schema_of(Case)
    >>> schema["$defs"]["Kiln"]["additionalProperties"]
    False
    >>> schema["$defs"]["Kiln"]["properties"]["length"]["anyOf"]
    [{'type': 'number'}, {'type': 'string'}]
    """
    body = _flatten(model.model_json_schema(mode="validation", schema_generator=_CaseSchema))
    body["title"] = "rotarykiln case"
    return {"$schema": SCHEMA_DIALECT, **body}


def shipped_schema_path():
    """Path of the schema shipped with the package (``rotarykiln/case.schema.json``)."""
    return resources.files("rotarykiln") / "case.schema.json"


# --------------------------------------------------------------------------------------------
# A validated case written back with units.

DISPLAY_UNITS: dict[str, tuple[str, ...]] = {
    "length": ("m", "mm"),
    "angle": ("deg", "%"),
    "rotation rate": ("rpm",),
    "mass flow": ("kg/h", "kg/s", "t/h"),
    "volumetric flow": ("m3/h", "m3/s"),
    "temperature": ("K",),
    "time": ("s", "min", "h"),
    "density": ("kg/m3",),
    "velocity": ("m/s",),
    "pressure": ("Pa", "kPa", "bar"),
    "power": ("W", "kW", "MW"),
    "thermal conductivity": ("W/m/K",),
    "specific heat": ("J/kg/K", "kJ/kg/K"),
    "heat transfer coefficient": ("W/m2/K",),
    "fraction": (),
}
"""Units in which :func:`format_si` may write each kind (the shortest text wins; none: a bare
number)."""


def _si_text(kind: str) -> str:
    return KINDS[kind].si.replace("**", "")


def format_si(value: float, kind: str) -> str | float:
    """An SI value as the text a case file would hold, converting back to the same float.

    Parameters
    ----------
    value : float
        The SI value (m, rad, rad/s, kg/s, K...).
    kind : str
        A key of :data:`rotarykiln.units.KINDS` (``"rotation rate"``).

    Returns
    -------
    str or float
        ``"1.5 rpm"``-style text in a unit of :data:`DISPLAY_UNITS`, the shortest that
        :func:`rotarykiln.units.to_si` reads back as exactly ``value``; the SI value in full with
        its SI unit when no such text does; a bare float for fractions.

    Examples
    --------
    >>> format_si(0.15707963267948966, "rotation rate")
    '1.5 rpm'
    >>> format_si(62 / 3600, "mass flow")
    '62 kg/h'
    >>> format_si(0.0025, "length")
    '2.5 mm'
    >>> format_si(0.12, "fraction")
    0.12
    """
    from rotarykiln.units import ureg

    value = float(value)
    units = DISPLAY_UNITS.get(kind, (_si_text(kind),))
    if not units or not math.isfinite(value):
        return value
    best = None
    for unit in units:
        try:
            if unit == "%":  # a grade, rise over run (as "5 %" is read for a slope)
                shown = 100 * math.tan(value)
            else:
                shown = ureg.Quantity(value, KINDS[kind].si).to(_pint_unit(unit)).magnitude
        except Exception:  # pragma: no cover - a display unit pint does not know
            continue
        for digits in (6, 9, 12, 15, 17):
            text = f"{shown:.{digits}g} {unit}"
            if _reads_back(text, kind, value):
                if best is None or len(text) < len(best):
                    best = text
                break
    if best is not None:
        return best
    text = f"{value!r} {_si_text(kind)}"
    return text if _reads_back(text, kind, value) else value


def _pint_unit(unit: str) -> str:
    names = {"rpm": "revolution/minute", "deg": "degree", "t/h": "metric_ton/hour"}
    return names.get(unit, unit.replace("m3", "m**3").replace("m2", "m**2"))


def _reads_back(text: str, kind: str, value: float) -> bool:
    try:
        return to_si("", text, kind) == value
    except Exception:
        return False


def _arms(annotation: Any) -> list:
    """The alternatives of a union annotation (itself when it is not a union)."""
    if typing.get_origin(annotation) in (Union, types.UnionType):
        return list(typing.get_args(annotation))
    return [annotation]


def _kind_of(annotation: Any) -> str | None:
    """The quantity kind of an ``Annotated[float, BeforeValidator(convert)]`` annotation."""
    if typing.get_origin(annotation) is Annotated:
        for meta in annotation.__metadata__:
            if isinstance(meta, BeforeValidator):
                return _quantity_kind(meta.func)
    return None


def _dump_value(value: Any, annotation: Any) -> Any:
    if value is None:
        return None
    if isinstance(value, BaseModel):
        return dump_case(value)
    own_kind = _kind_of(annotation)
    if typing.get_origin(annotation) is Annotated:
        annotation = annotation.__origin__
    arms = _arms(annotation)
    if isinstance(value, float | int) and not isinstance(value, bool):
        if own_kind is not None:
            return format_si(value, own_kind)
        for arm in arms:
            kind = _kind_of(arm)
            if kind is not None:
                return format_si(value, kind)
        return value
    if isinstance(value, list | tuple):
        for arm in arms:
            inner = arm.__origin__ if typing.get_origin(arm) is Annotated else arm
            origin, args = typing.get_origin(inner), typing.get_args(inner)
            if origin is list and args:
                return [_dump_value(v, args[0]) for v in value]
            if origin is tuple and args:
                items = args if len(args) == len(value) else [args[0]] * len(value)
                return [_dump_value(v, a) for v, a in zip(value, items, strict=True)]
        return [_dump_value(v, Any) for v in value]
    if isinstance(value, dict):
        return {k: _dump_value(v, Any) for k, v in value.items()}
    return value


def dump_case(case: BaseModel) -> dict[str, Any]:
    """A validated case (or one of its sections) as a mapping with units, ready for YAML.

    Only the keys given when the case was loaded are written (defaults stay implicit); every
    quantity is written with a unit (:func:`format_si`), so ``parse_case(dump_case(case))``
    equals ``case``.

    Parameters
    ----------
    case : Case
        A validated :class:`rotarykiln.case.Case`, or any section model of it.

    Returns
    -------
    dict
        Plain data (str, float, int, bool, list, dict, None): the case file's mapping.

    Examples
    --------
    >>> from rotarykiln.case import load_case, parse_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> case = load_case(builtin_case_path("barr_T4"))
    >>> data = dump_case(case)
    >>> data["operation"]
    {'speed': '1.5 rpm', 'feed': '62 kg/h', 'feed_temperature': '298.15 K'}
    >>> parse_case(data) == case
    True
    """
    out = {}
    for name, info in type(case).model_fields.items():
        if name in case.model_fields_set:
            # pydantic keeps a field's own Annotated metadata (the unit converter) apart
            annotation = info.annotation
            if info.metadata:
                annotation = Annotated[(annotation, *info.metadata)]
            out[name] = _dump_value(getattr(case, name), annotation)
    return out


class _CaseDumper(yaml.SafeDumper):
    """Safe YAML with lists of plain values on one line (``z_gas: [0.21 m, 0.72 m]``)."""

    def represent_list(self, data):
        flow = all(isinstance(x, str | int | float | bool) or x is None for x in data)
        return self.represent_sequence("tag:yaml.org,2002:seq", data, flow_style=flow)


_CaseDumper.add_representer(list, _CaseDumper.represent_list)


def case_to_yaml(case: BaseModel) -> str:
    """The YAML text of a validated case, with units (see :func:`dump_case`).

    Parameters
    ----------
    case : Case
        A validated :class:`rotarykiln.case.Case`.

    Returns
    -------
    str
        YAML text, keys in the order of the case model.

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> print(case_to_yaml(load_case(builtin_case_path("barr_T4"))).splitlines()[3])
    kiln:
    """
    return yaml.dump(
        dump_case(case), Dumper=_CaseDumper, sort_keys=False, allow_unicode=True, width=100
    )


def write_case(case: BaseModel, path: str | os.PathLike) -> Path:
    """Write a validated case as a YAML case file (atomically), with units.

    Parameters
    ----------
    case : Case
        A validated :class:`rotarykiln.case.Case`.
    path : str or Path
        The file to write.

    Returns
    -------
    Path
        The path written.
    """
    from rotarykiln.outputs import write_text_atomic

    return write_text_atomic(path, case_to_yaml(case))


def case_hash(case: BaseModel) -> str:
    """The SHA-256 of a validated case: the same for every file that gives the same case.

    The hash is taken over the canonical JSON of the validated values (SI floats, every field
    including defaults, keys sorted), so comments, units and key order of the file do not matter.

    Parameters
    ----------
    case : Case
        A validated :class:`rotarykiln.case.Case`.

    Returns
    -------
    str
        64 hexadecimal digits.

    Examples
    --------
    >>> from rotarykiln.case import load_case, parse_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> case = load_case(builtin_case_path("barr_T4"))
    >>> case_hash(parse_case(dump_case(case))) == case_hash(case)
    True
    """
    import hashlib
    import json

    text = json.dumps(case.model_dump(mode="json"), sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()
