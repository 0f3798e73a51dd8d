"""Dotted field paths into a nested case mapping: ``"operation.speed"``, ``"kiln.layers.0.k"``."""

from __future__ import annotations

import copy
from collections.abc import Mapping, MutableMapping
from typing import Any

from rotarykiln.errors import InputError

__all__ = ["get_path", "set_path", "with_values"]


def _split(path: str) -> list[str]:
    if not isinstance(path, str) or not path or any(p == "" for p in path.split(".")):
        raise InputError("sweep.parameter", path, 'a dotted field path such as "operation.speed"')
    return path.split(".")


def _child(node: Any, key: str, path: str, upto: str):
    if isinstance(node, Mapping):
        if key not in node:
            raise InputError(
                "sweep.parameter",
                upto,
                f"an existing field (keys: {', '.join(map(str, node))})",
            )
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
            raise InputError(
                "sweep.parameter",
                path,
                f"an existing field (keys: {', '.join(map(str, node))})",
            )
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
