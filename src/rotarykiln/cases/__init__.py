"""Built-in cases from the sources, as YAML data (see README.md in this folder)."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from rotarykiln.errors import InputError

__all__ = ["builtin_case_path", "list_builtin_cases"]


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
