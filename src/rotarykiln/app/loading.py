"""Cases into the app: a built-in case by name, or a file the user uploads.

Both give the case file's raw mapping (parsed YAML, not validated), read by
:func:`rotarykiln.case.read_case_yaml`, so the app refuses what the CLI refuses with the same
one-line messages (malformed YAML, not UTF-8, too large...), naming the file as the user knows it.
The case text the page sends back with a run is read the same way (:func:`read_case_text`).
A built-in case is one of :func:`builtin_cases` by its name, never a path.
"""

from __future__ import annotations

import base64
import binascii
import re
from pathlib import Path
from typing import Any

from rotarykiln.case import MAX_CASE_BYTES, read_case_yaml
from rotarykiln.cases import builtin_case_path, list_builtin_cases
from rotarykiln.errors import InputError
from rotarykiln.yaml_limits import load_yaml_text

__all__ = ["builtin_cases", "load_builtin", "load_upload", "read_case_text", "safe_name"]


def builtin_cases() -> list[str]:
    """Names of the built-in case files the app offers (``tscheng_A16``, ``retort/base``...)."""
    return list_builtin_cases()


def load_builtin(name: str) -> dict:
    """The raw mapping of a built-in case, by its name in :func:`builtin_cases`.

    >>> load_builtin("tscheng_A16")["operation"]["speed"]
    '1.5 rpm'

    Raises
    ------
    InputError
        Not the name of a built-in case (a path is not one).
    """
    cases = builtin_cases()
    if not isinstance(name, str) or name not in cases:
        shown = repr(name) if len(repr(name)) < 60 else repr(name)[:57] + "..."
        raise InputError(
            "case", message=f"case: {shown} is not a built-in case ({', '.join(cases)})"
        )
    return _mapping(read_case_yaml(builtin_case_path(name)), name)


def safe_name(filename: str | None) -> str:
    """A file name as the page may show it: its last part, plain characters, at most 100.

    >>> safe_name("../../etc/passwd")
    'passwd'
    """
    name = Path(str(filename or "upload.yaml").replace("\\", "/")).name
    name = re.sub(r"[^A-Za-z0-9._ -]", "_", name).strip(" .") or "upload.yaml"
    return name[:100]


def load_upload(contents: str | None, filename: str | None) -> dict:
    """The raw mapping of an uploaded case file.

    Parameters
    ----------
    contents : str
        The upload as a data URL (``data:<type>;base64,<bytes>``), as the browser sends it.
    filename : str
        The file's name on the user's machine (only its last part is used, in messages).

    Raises
    ------
    InputError
        One line naming the file: empty, too large, not UTF-8, not YAML, not a mapping.
    """
    name = safe_name(filename if isinstance(filename, str) else None)
    if not isinstance(contents, str) or "," not in contents:
        raise InputError(name, message=f"{name}: empty upload (choose a YAML case file)")
    encoded = contents.split(",", 1)[1]
    if len(encoded) > (MAX_CASE_BYTES * 4) // 3 + 8:
        raise InputError(
            name,
            message=f"{name}: too large for a case file (at most {MAX_CASE_BYTES / 1e6:g} MB; "
            "a case is a few kB)",
        )
    try:
        data = base64.b64decode(encoded, validate=True)
    except (binascii.Error, ValueError):
        raise InputError(name, message=f"{name}: the upload could not be decoded") from None
    return read_case_text(data, name)


def read_case_text(data: bytes, name: str) -> dict:
    """The raw mapping of a case file's bytes, read as :func:`rotarykiln.case.read_case_yaml`
    reads a file, within the limits of :mod:`rotarykiln.yaml_limits` (size, depth, aliases,
    values, UTF-8, duplicate keys); messages name the file ``name`` (a name the page shows:
    :func:`safe_name` or a built-in case's).

    Raises
    ------
    InputError
        One line naming the file: too large, not UTF-8, not YAML, over a limit, not a mapping.
    """
    return _mapping(load_yaml_text(data, name, what="case file"), name)


def _mapping(raw: Any, name: str) -> dict:
    if raw is None:
        raise InputError(
            name, message=f"{name}: the case is empty (it needs kiln: and operation: sections)"
        )
    if not isinstance(raw, dict):
        shown = repr(raw)
        shown = shown if len(shown) < 60 else shown[:57] + "..."
        raise InputError(
            name,
            message=f"{name}: not a case file (expected a YAML mapping of sections such as "
            f"kiln: and operation:, got {shown})",
        )
    return raw
