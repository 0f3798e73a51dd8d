"""Cases into the app: a built-in case by name, or a file the user uploads.

Both give the case file's raw mapping (parsed YAML, not validated), read by
:func:`rotarykiln.case.read_case_yaml`, so the app refuses what the CLI refuses with the same
one-line messages (malformed YAML, not UTF-8, too large...), naming the file as the user knows it.
"""

from __future__ import annotations

import base64
import binascii
import re
import tempfile
from pathlib import Path
from typing import Any

from rotarykiln.case import MAX_CASE_BYTES, read_case_yaml
from rotarykiln.cases import builtin_case_path, list_builtin_cases
from rotarykiln.errors import InputError

__all__ = ["builtin_cases", "load_builtin", "load_upload"]


def builtin_cases() -> list[str]:
    """Names of the built-in case files the app offers (``tscheng_A16``, ``retort/base``...)."""
    return list_builtin_cases()


def load_builtin(name: str) -> dict:
    """The raw mapping of a built-in case.

    >>> load_builtin("tscheng_A16")["operation"]["speed"]
    '1.5 rpm'
    """
    return _mapping(read_case_yaml(builtin_case_path(name)), name)


def _safe_name(filename: str | None) -> str:
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
    name = _safe_name(filename)
    if not contents or "," not in contents:
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
    with tempfile.TemporaryDirectory(prefix="rotarykiln-upload-") as folder:
        path = Path(folder) / name
        path.write_bytes(data)
        try:
            raw = read_case_yaml(path)
        except InputError as exc:
            raise InputError(name, message=str(exc).replace(str(path), name)) from None
    return _mapping(raw, name)


def _mapping(raw: Any, name: str) -> dict:
    if raw is None:
        raise InputError(
            name, message=f"{name}: the case is empty (it needs kiln: and operation: sections)"
        )
    if not isinstance(raw, dict):
        shown = repr(raw) if len(repr(raw)) < 60 else repr(raw)[:57] + "..."
        raise InputError(
            name,
            message=f"{name}: not a case file (expected a YAML mapping of sections such as "
            f"kiln: and operation:, got {shown})",
        )
    return raw
