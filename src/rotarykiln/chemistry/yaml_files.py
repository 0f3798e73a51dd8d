"""Reading the chemistry's YAML files (species, reactions) with one-line errors.

Species and reaction files are read as every YAML file of the program is
(:func:`rotarykiln.yaml_limits.read_yaml_file`): size, nesting, aliases, number lengths and
duplicate keys are limited, and every refusal is one line naming the file.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from rotarykiln.yaml_limits import read_yaml_file

__all__ = ["read_yaml"]


def read_yaml(path: str | Path, what: str = "YAML file") -> Any:
    """The parsed content of the YAML file ``path``, within the limits of
    :mod:`rotarykiln.yaml_limits`.

    Parameters
    ----------
    path : str or Path
        The file.
    what : str
        What the file is, in messages (``"species file"``, ``"reaction file"``).

    Raises
    ------
    InputError
        One line naming the file: missing, unreadable, too large, not UTF-8, malformed YAML,
        over a limit (nesting, aliases, values), a duplicate key.

    Examples
    --------
    >>> read_yaml("no/such/file.yaml", "reaction file")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: no/such/file.yaml: no such reaction file
    """
    return read_yaml_file(path, what=what)
