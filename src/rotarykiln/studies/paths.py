"""Dotted field paths into a nested case mapping: ``"operation.speed"``, ``"kiln.layers.0.k"``."""

from __future__ import annotations

import copy
import difflib
from collections.abc import Mapping, MutableMapping
from typing import Any

from rotarykiln.errors import InputError

__all__ = ["get_path", "set_path", "with_values"]


def _split(path: str) -> list[str]:
    if not isinstance(path, str) or not path or any(p == "" for p in path.split(".")):
        raise InputError("sweep.parameter", path, 'a dotted field path such as "operation.speed"')
    return path.split(".")


def _missing(node: Mapping, key: str, upto: str) -> InputError:
    keys = [str(k) for k in node]
    hint = difflib.get_close_matches(key, keys, n=1, cutoff=0.6)
    mean = (
        f"; did you mean {upto.rpartition('.')[0] + '.' if '.' in upto else ''}{hint[0]}?"
        if hint
        else ""
    )
    return InputError("sweep.parameter", upto, f"an existing field (keys: {', '.join(keys)}){mean}")


def _child(node: Any, key: str, path: str, upto: str):
    if isinstance(node, Mapping):
        if key not in node:
            raise _missing(node, key, upto)
        return node[key]
    if isinstance(node, list):
        try:
            return node[int(key)]
        except (ValueError, IndexError):
            raise InputError("sweep.parameter", upto, f"a list index < {len(node)}") from None
    raise InputError("sweep.parameter", upto, "a mapping or list to descend into")


def get_path(case: Mapping, path: str) -> Any:
    """Value of the field at ``path`` in a nested mapping; :class:`InputError` if absent.

    Examples
    --------
    >>> get_path({"operation": {"speed": "1.5 rpm"}}, "operation.speed")
    '1.5 rpm'
    """
    node: Any = case
    keys = _split(path)
    for i, k in enumerate(keys):
        node = _child(node, k, path, ".".join(keys[: i + 1]))
    return node


def set_path(case: MutableMapping, path: str, value: Any, *, create: bool = False) -> None:
    """Set the field at ``path`` in place. The field must exist unless ``create`` is True.

    Examples
    --------
    >>> c = {"operation": {"speed": "1.5 rpm"}}
    >>> set_path(c, "operation.speed", "3 rpm"); c
    {'operation': {'speed': '3 rpm'}}
    >>> set_path(c, "operation.sped", "3 rpm")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: sweep.parameter: operation.sped is not an existing field ...
    """
    keys = _split(path)
    node: Any = case
    for i, k in enumerate(keys[:-1]):
        if create and isinstance(node, MutableMapping) and k not in node:
            node[k] = {}
        node = _child(node, k, path, ".".join(keys[: i + 1]))
    last = keys[-1]
    if isinstance(node, MutableMapping):
        if last not in node and not create:
            raise _missing(node, last, path)
        node[last] = value
    elif isinstance(node, list):
        try:
            node[int(last)] = value
        except (ValueError, IndexError):
            raise InputError("sweep.parameter", path, f"a list index < {len(node)}") from None
    else:
        raise InputError("sweep.parameter", path, "a field of a mapping or list")


def with_values(base: Mapping, values: Mapping[str, Any], *, create: bool = False) -> dict:
    """Deep copy of ``base`` with the fields of ``values`` (path -> value) set."""
    case = copy.deepcopy(dict(base))
    for path, v in values.items():
        set_path(case, path, v, create=create)
    return case
