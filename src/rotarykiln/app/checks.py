"""What the app accepts from a browser: every value a callback receives is checked here first.

A browser posts the page's state with every callback (the loaded case as YAML text, the fields'
texts and ids, the last run's inputs), and any client can post anything in its place: none of it
is trusted. Each value is checked for its type and size before it is used, and the case text is
read again with the case loader's limits (:func:`rotarykiln.case.read_case_yaml`), exactly as an
upload is; a bad value is refused in one line naming it.

A case in the app names no file: ``chemistry.species`` given as a path is refused (the app would
otherwise read files of the server for any client), and the case is validated without a case
folder (``base_dir=None`` of :func:`rotarykiln.case.parse_case`). The app runs at most :data:`MAX_APP_CELLS` cells.
"""

from __future__ import annotations

import json
import math
from typing import Any

from rotarykiln.app.inputs import MAIN_INPUTS
from rotarykiln.case import MAX_CASE_BYTES, parse_case
from rotarykiln.errors import InputError

__all__ = [
    "MAX_APP_CELLS",
    "MAX_FIELD_CHARS",
    "MAX_REQUEST_BYTES",
    "case_from_state",
    "check_run_size",
    "clicks",
    "fields_from_state",
    "inputs_from_state",
    "outlet_from_state",
    "parse_app_case",
    "shown_paths",
    "source_label",
]

MAX_REQUEST_BYTES = 3_000_000
"""Largest request body the server reads, bytes (an upload of a 1 MB case is 1.4 MB)."""
MAX_APP_CELLS = 2_000
"""Most cells along the kiln (``solver.cells``) and transport points (``transport.n_points``)
the app runs (``rotarykiln run`` takes up to 20,000 cells)."""
MAX_FIELD_CHARS = 200
"""Longest text of an input field."""
_PATHS = frozenset(item.path for item in MAIN_INPUTS)
_STATE = "the page's state"


def _shown(value: Any, limit: int = 60) -> str:
    """A value as one short line (quotes and escapes: never a newline)."""
    try:
        text = json.dumps(value, ensure_ascii=True, default=lambda v: type(v).__name__)
    except (ValueError, RecursionError):
        text = type(value).__name__
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _refuse_files(raw: dict) -> None:
    """Refuse a case that names a file (``chemistry.species`` given as a path)."""
    chem = raw.get("chemistry")
    spec = chem.get("species") if isinstance(chem, dict) else None
    if isinstance(spec, str):
        raise InputError(
            "chemistry.species",
            message=f"chemistry.species: {_shown(spec)} names a file, and the app reads no "
            "file: give the species in the case (chemistry.species: {bed: ..., gas: ...}), or "
            "run it with `rotarykiln run`",
        )


def parse_app_case(raw: Any, source: str = "case"):
    """Validate a raw case as the app does: as :func:`rotarykiln.case.parse_case`, with no case
    folder, so that no file is read (a case naming one is refused).

    Raises
    ------
    InputError
        The case is not valid, or names a file.
    """
    if isinstance(raw, dict):
        _refuse_files(raw)
    return parse_case(raw, source=source, base_dir=None)


def check_run_size(case, max_cells: int = MAX_APP_CELLS) -> None:
    """Refuse a case with more cells (or transport points) than the app runs.

    Raises
    ------
    InputError
        ``solver.cells`` or ``transport.n_points`` over ``max_cells``.
    """
    sizes = [("solver.cells", case.solver.cells, "cells")]
    if case.transport is not None:
        sizes.append(("transport.n_points", case.transport.n_points, "points"))
    for field, n, what in sizes:
        if n > max_cells:
            raise InputError(
                field,
                n,
                message=f"{field}: {n} {what} is more than the app runs (at most {max_cells}; "
                "`rotarykiln run` takes more)",
            )


def source_label(source: Any) -> str:
    """The name a case is shown under: a built-in case's name, else a plain file name (never a
    path of the server's, which the page's state could otherwise make it)."""
    from rotarykiln.app.loading import builtin_cases, safe_name

    if isinstance(source, str) and source in builtin_cases():
        return source
    return safe_name(source if isinstance(source, str) else None)


def case_from_state(case_data: Any) -> tuple[dict, str]:
    """The raw case and its name from the page's case store, read as an upload is.

    Raises
    ------
    InputError
        Not a loaded case, its text over the size of a case file, or not a valid case file
        (malformed YAML, nested too deeply, too many values...).
    """
    from rotarykiln.app.loading import read_case_text

    if not isinstance(case_data, dict) or not isinstance(case_data.get("yaml"), str):
        raise InputError(
            "case-store",
            message=f"case-store: {_STATE} holds no loaded case ({_shown(case_data)}); "
            "load the case again",
        )
    text = case_data["yaml"]
    source = source_label(case_data.get("source"))
    if len(text) > MAX_CASE_BYTES:  # characters; read_case_text counts the bytes
        raise InputError(
            source,
            message=f"{source}: too large for a case file (at most "
            f"{MAX_CASE_BYTES / 1e6:g} MB; a case is a few kB)",
        )
    return read_case_text(text.encode("utf-8", "surrogatepass"), source), source


def fields_from_state(values: Any, ids: Any) -> dict[str, Any]:
    """The fields' texts by path, from the page's values and ids of the main inputs.

    Raises
    ------
    InputError
        Not lists of the same length, an id that is not a main input's (or given twice), a value
        that is not a text or a number, a text over :data:`MAX_FIELD_CHARS` characters.
    """
    if not isinstance(values, list) or not isinstance(ids, list) or len(values) != len(ids):
        raise InputError(
            "main-input",
            message=f"main-input: {_STATE} has no list of field values and ids of the same "
            "length; reload the page",
        )
    out: dict[str, Any] = {}
    for ident, value in zip(ids, values, strict=True):
        path = ident.get("path") if isinstance(ident, dict) else None
        if not isinstance(path, str) or path not in _PATHS or path in out:
            raise InputError(
                "main-input",
                message=f"main-input: {_shown(ident)} is not a main input of the page "
                "(or is given twice); reload the page",
            )
        if isinstance(value, str) and len(value) > MAX_FIELD_CHARS:
            raise InputError(
                path,
                message=f"{path}: a text of {len(value)} characters (at most {MAX_FIELD_CHARS})",
            )
        if value is not None and (
            isinstance(value, bool) or not isinstance(value, str | int | float)
        ):
            raise InputError(path, message=f"{path}: {_shown(value)} is not a text or a number")
        out[path] = value
    return out


def shown_paths(ids: Any) -> list[str]:
    """The paths of the main inputs among the page's field ids (where an error can be shown)."""
    if not isinstance(ids, list):
        return []
    paths = (ident.get("path") if isinstance(ident, dict) else None for ident in ids)
    return [p for p in paths if isinstance(p, str) and p in _PATHS]


def clicks(value: Any) -> int:
    """A button's click count from the page (0 for anything that is not a count)."""
    if isinstance(value, int) and not isinstance(value, bool) and 0 <= value < 10**9:
        return value
    return 0


def outlet_from_state(previous: Any) -> float | None:
    """The previous run's outlet temperature, K, from the page's result store, else None."""
    value = previous.get("outlet") if isinstance(previous, dict) else None
    if isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value):
        return float(value)
    return None


def inputs_from_state(result: Any) -> dict | None:
    """The inputs of the last run from the page's result store (texts and numbers by path, and
    the case's name), else None."""
    inputs = result.get("inputs") if isinstance(result, dict) else None
    if not isinstance(inputs, dict) or len(inputs) > len(_PATHS) + 1:
        return None
    for value in inputs.values():
        if value is not None and (
            isinstance(value, bool) or not isinstance(value, str | int | float)
        ):
            return None
    return inputs
