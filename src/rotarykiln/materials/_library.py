"""Loading the YAML material libraries shipped beside this module."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import yaml

from rotarykiln.errors import InputError

_HERE = Path(__file__).parent


@lru_cache(maxsize=8)
def load_library(filename: str) -> dict:
    """The parsed YAML library ``filename`` (e.g. ``"solids.yaml"``)."""
    with open(_HERE / filename, encoding="utf-8") as fh:
        return yaml.safe_load(fh)


def library_entry(filename: str, name: str, field: str) -> dict:
    """One entry of a library; :class:`InputError` naming ``field`` if it is unknown."""
    lib = load_library(filename)
    if name not in lib:
        raise InputError(field, name, "one of " + ", ".join(sorted(lib)))
    return dict(lib[name])
