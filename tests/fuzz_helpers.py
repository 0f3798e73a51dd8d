"""Mutation helpers shared by the seeded fuzz tests (test_fuzz_cases.py, test_fuzz_input_files.py)
and, through them, the campaign scripts of docs/scripts: one value of a parsed YAML structure
replaced by a value of a list, or deleted."""

from __future__ import annotations

import copy

#: The value that deletes the key or item instead of replacing it.
DELETE = "DELETE"


def paths(x, p=()):
    """Every path (tuple of keys and indices) into the nested dicts and lists ``x``."""
    if isinstance(x, dict):
        for k, v in x.items():
            yield p + (k,)
            yield from paths(v, p + (k,))
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield p + (i,)
            yield from paths(v, p + (i,))


def set_path(d, p, v):
    """Set the item at path ``p`` of ``d`` to ``v`` in place, or delete it when ``v`` is DELETE."""
    for k in p[:-1]:
        d = d[k]
    if v == DELETE:
        if isinstance(d, dict):
            del d[p[-1]]
        else:
            d.pop(p[-1])
    else:
        d[p[-1]] = v


def mutate(base, values, rng):
    """A copy of ``base`` with one item replaced by one of ``values`` or deleted, drawn with
    ``rng`` (path first, then value): (the copy, the path, the value)."""
    data = copy.deepcopy(base)
    path = rng.choice(list(paths(base)))
    value = rng.choice(list(values) + [DELETE])
    set_path(data, path, value)
    return data, path, value
