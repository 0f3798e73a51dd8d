"""Built-in cases from the sources, as YAML data (see README.md in this folder)."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from rotarykiln.errors import InputError

__all__ = ["builtin_case", "builtin_case_path", "list_builtin_cases"]


def list_builtin_cases() -> list[str]:
    """Names of the built-in cases (YAML files in this package, subfolders as ``dir/name``)."""
    root = Path(str(resources.files(__package__)))
    return sorted(str(p.relative_to(root).with_suffix("")) for p in root.rglob("*.yaml"))


def builtin_case_path(name: str) -> Path:
    """Path of a built-in case by name (``"demo"``, ``"retort/base"``)."""
    names = list_builtin_cases()
    root = Path(str(resources.files(__package__)))
    path = root / f"{name}.yaml"
    if name not in names or not path.is_file():  # a name, never a path out of this folder
        raise InputError("case", name, f"a built-in case ({', '.join(names)})")
    return path


def builtin_case(name: str) -> dict:
    """A built-in case file by name, as the plain nested dict of its YAML (not validated).

    Examples
    --------
    >>> builtin_case("charcoal_activation")["kiln"]["length"]
    '3.7 m'
    """
    import yaml

    with open(builtin_case_path(name), encoding="utf-8") as fh:
        return yaml.safe_load(fh)
