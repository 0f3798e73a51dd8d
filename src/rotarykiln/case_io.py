"""Case files for editors and round trips: the JSON Schema of a case, and a case written back.

:func:`case_json_schema` is the JSON Schema (draft 2020-12) of the case file, generated from the
pydantic model :class:`rotarykiln.case.Case`; quantity fields accept a number or a string with a
unit (``"1.5 rpm"``), as the loader does. The schema is shipped as
``rotarykiln/case.schema.json`` (``rotarykiln schema`` regenerates it). An editor with the YAML
language server checks a case file against it with a first line::

    # yaml-language-server: $schema=<path or URL of case.schema.json>
"""

from __future__ import annotations

import inspect
from importlib import resources
from typing import Any

from pydantic.json_schema import GenerateJsonSchema
from pydantic_core import core_schema

from rotarykiln.units import EXAMPLES, UNIT_REQUIRED

__all__ = ["SCHEMA_DIALECT", "case_json_schema", "shipped_schema_path"]

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


def case_json_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of a case file.

    Generated from :class:`rotarykiln.case.Case` in validation mode: unknown keys are refused
    (``additionalProperties: false``) and every quantity field accepts a number (SI) or a string
    with a unit. The loader checks more than the schema says (units of the right kind, ranges,
    library names); the schema is what an editor can check while typing.

    Returns
    -------
    dict
        The schema, a JSON-compatible mapping (``$schema``, ``title``, ``$defs``...).

    Examples
    --------
    >>> schema = case_json_schema()
    >>> schema["$defs"]["Kiln"]["additionalProperties"]
    False
    >>> schema["$defs"]["Kiln"]["properties"]["length"]["anyOf"]
    [{'type': 'number'}, {'type': 'string'}]
    """
    from rotarykiln.case import Case

    body = _flatten(Case.model_json_schema(mode="validation", schema_generator=_CaseSchema))
    body["title"] = "rotarykiln case"
    return {"$schema": SCHEMA_DIALECT, **body}


def shipped_schema_path():
    """Path of the schema shipped with the package (``rotarykiln/case.schema.json``)."""
    return resources.files("rotarykiln") / "case.schema.json"
