"""Sweep designs: full grids and one-at-a-time ranges over case field paths.

A design is a list of :class:`CaseSpec`: an id, the values to set (path -> value as given, a
number or a string with units such as ``"62 kg/h"``) and a group (``"base"``, ``"grid"`` or the
path varied one at a time).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from rotarykiln.errors import InputError

__all__ = ["CaseSpec", "grid", "one_at_a_time", "si_value"]


@dataclass(frozen=True)
class CaseSpec:
    """One case of a sweep."""

    case_id: int
    values: dict[str, Any] = field(default_factory=dict)
    group: str = "grid"


def _check_ranges(ranges: Mapping[str, Sequence]) -> dict[str, list]:
    if not isinstance(ranges, Mapping) or not ranges:
        raise InputError("sweep.parameters", ranges, "a non-empty mapping path -> list of values")
    out = {}
    for path, values in ranges.items():
        if isinstance(values, str | bytes) or not isinstance(values, Sequence) or len(values) == 0:
            raise InputError(f"sweep.parameters.{path}", values, "a non-empty list of values")
        out[path] = list(values)
    return out


def grid(ranges: Mapping[str, Sequence]) -> list[CaseSpec]:
    """Full factorial design: every combination of the given values.

    Examples
    --------
    >>> [c.values for c in grid({"a": [1, 2], "b": ["x", "y"]})]
    [{'a': 1, 'b': 'x'}, {'a': 1, 'b': 'y'}, {'a': 2, 'b': 'x'}, {'a': 2, 'b': 'y'}]
    """
    r = _check_ranges(ranges)
    paths = list(r)
    return [
        CaseSpec(i, dict(zip(paths, combo, strict=True)), "grid")
        for i, combo in enumerate(itertools.product(*(r[p] for p in paths)))
    ]


def one_at_a_time(ranges: Mapping[str, Sequence], include_base: bool = True) -> list[CaseSpec]:
    """One-at-a-time design: vary each path over its values, the others at the base case.

    Examples
    --------
    >>> [(c.group, c.values) for c in one_at_a_time({"a": [1, 2], "b": [5]})]
    [('base', {}), ('a', {'a': 1}), ('a', {'a': 2}), ('b', {'b': 5})]
    """
    r = _check_ranges(ranges)
    cases = [CaseSpec(0, {}, "base")] if include_base else []
    for path, values in r.items():
        for v in values:
            cases.append(CaseSpec(len(cases), {path: v}, path))
    return cases


def si_value(value: Any) -> float:
    """Numeric SI value of a sweep value: numbers as they are, "62 kg/h" -> 0.01722 (kg/s).

    Returns NaN for values that are not quantities (e.g. a model name); used for table columns
    and plot axes only.

    Examples
    --------
    >>> round(si_value("62 kg/h"), 5), si_value(3), si_value("1100 degC")
    (0.01722, 3.0, 1373.15)
    """
    if isinstance(value, bool):
        return float(value)
    if isinstance(value, int | float):
        return float(value)
    if isinstance(value, str):
        from rotarykiln.units import ureg

        try:
            q = ureg.Quantity(value.strip())
        except Exception:  # not a quantity: a label
            return math.nan
        try:
            return float(q.to_base_units().magnitude)
        except Exception:
            return math.nan
    return math.nan
