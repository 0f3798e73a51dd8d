"""Example input files shipped with rotarykiln, reachable by name from the command line.

``rotarykiln transient barr_T4 --events barr_T4_startup`` takes the events file
``barr_T4_startup.yaml`` of this folder when no file of that name exists where the user is.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from rotarykiln.errors import InputError

__all__ = ["example_path", "list_examples"]


def list_examples(suffix: str = ".yaml") -> list[str]:
    """Names (without the suffix) of the shipped example files ending in ``suffix``.

    Examples
    --------
    >>> "barr_T4_startup" in list_examples()
    True
    """
    root = Path(str(resources.files(__package__)))
    return sorted(p.stem for p in root.glob(f"*{suffix}"))


def example_path(field: str, name: str, suffix: str = ".yaml") -> Path:
    """The path a command-line option ``field`` names: an existing file as given, else the
    shipped example of that name (with or without ``suffix``); an InputError otherwise.

    Examples
    --------
    >>> example_path("--events", "barr_T4_startup").name
    'barr_T4_startup.yaml'
    """
    given = Path(name)
    if given.is_file():
        return given
    stem = name[: -len(suffix)] if name.endswith(suffix) else name
    names = list_examples(suffix)
    if stem in names:  # a name, never a path out of this folder
        return Path(str(resources.files(__package__))) / f"{stem}{suffix}"
    raise InputError(
        field, name, f"an existing file or a shipped example ({', '.join(names) or 'none'})"
    )
