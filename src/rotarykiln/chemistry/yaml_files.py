"""Reading the chemistry's YAML files (species, reactions) with one-line errors."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from rotarykiln.errors import InputError

__all__ = ["read_yaml"]


def read_yaml(path: str | Path) -> Any:
    """The parsed content of the YAML file ``path``.

    Raises
    ------
    InputError
        One line naming the file: unreadable (with the system's reason) or not valid YAML.

    Examples
    --------
    >>> read_yaml("no/such/file.yaml")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: no/such/file.yaml: unreadable is not a readable YAML file (No such file or directory)
    """
    path = Path(path)
    try:
        with open(path, encoding="utf-8") as fh:
            return yaml.safe_load(fh)
    except OSError as exc:
        raise InputError(
            str(path), "unreadable", f"a readable YAML file ({exc.strerror})"
        ) from None
    except yaml.YAMLError as exc:
        raise InputError(str(path), "invalid YAML", f"valid YAML ({exc})") from None
