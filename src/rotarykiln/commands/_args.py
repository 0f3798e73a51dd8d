"""Shared helpers for subcommands: quantity arguments with units, output of results.

Imported by every subcommand's module when its parser is built (``rotarykiln CMD --help``):
pint (:mod:`rotarykiln.units`) and pandas (:mod:`rotarykiln.outputs`) are imported only when
a quantity is converted or a result printed.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rotarykiln.errors import InputError

__all__ = [
    "add_quantity",
    "check_count",
    "check_out",
    "get_quantity",
    "out_dir",
    "plain",
    "print_json",
    "to_si_within",
]


def add_quantity(parser: argparse.ArgumentParser, name: str, help: str, **kwargs) -> None:
    """Add ``--name VALUE [UNIT]``: both ``--speed 5 rpm`` and ``--speed 5rpm`` work."""
    # usage reads "--speed VALUE [UNIT ...]" (a tuple metavar names the first and the rest)
    parser.add_argument(f"--{name}", nargs="+", metavar=("VALUE", "UNIT"), help=help, **kwargs)


def get_quantity(
    args: argparse.Namespace, name: str, kind: str, *, required: bool = False, within=None
):
    """The SI value of quantity option ``--name`` (``None`` when absent and not required).

    ``within``: a quantity type of :mod:`rotarykiln.case` (``Length``, ``RotationRate``...):
    the value must also lie in its physical range, the same as in a case file.
    """
    tokens = getattr(args, name.replace("-", "_"))
    if tokens is None:
        if required:
            raise InputError(f"--{name}", message=f"--{name}: missing (required)")
        return None
    text = " ".join(tokens) if isinstance(tokens, list) else str(tokens)
    if within is None:
        from rotarykiln.units import to_si

        return to_si(f"--{name}", text, kind)
    return to_si_within(f"--{name}", text, within)


def to_si_within(field: str, text: str, within) -> float:
    """``text`` (a number and a unit) as an SI float in the range of the case-file type
    ``within`` (e.g. :data:`rotarykiln.case.Length`); an InputError naming ``field`` otherwise."""
    from pydantic import TypeAdapter, ValidationError

    try:
        return float(TypeAdapter(within).validate_python(text))
    except ValidationError as exc:
        raise InputError(field, message=f"{field}: {exc.errors()[0]['msg']}") from None


def check_count(option: str, value, low: int, high: int, what: str = "a whole number"):
    """``value`` of an integer option (None passes) in [low, high], else a one-line InputError."""
    if value is not None and not low <= value <= high:
        raise InputError(option, message=f"{option}: {value} is not {what} in [{low}, {high}]")
    return value


def print_json(data) -> None:
    from rotarykiln.outputs import to_json

    print(to_json(data))


def out_dir(path: str | None, default: str) -> Path:
    """The output folder (created, and checked to be writable before any model runs)."""
    p = Path(path or default)
    try:
        if p.exists() and not p.is_dir():
            raise InputError("--out", str(p), message=f"--out: {p} is a file, not a folder")
        p.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(
            "--out", str(p), message=f"--out: cannot create {p} ({exc.strerror})"
        ) from None
    # check now, not after a long solve, that files can be written there
    import tempfile

    try:
        with tempfile.NamedTemporaryFile(dir=p, prefix=".rk-write-check-"):
            pass
    except OSError as exc:
        raise InputError(
            "--out", str(p), message=f"--out: cannot write in {p} ({exc.strerror})"
        ) from None
    return p


def check_out(path: str | None) -> None:
    """Check, before a long computation and without creating anything, that the folder ``path``
    could be created and written (:func:`out_dir` creates it once there is something to write)."""
    import os

    if path is None:
        return
    p = Path(path).absolute()
    try:
        os.stat(p)  # a name too long or a file in the way: refused here
    except FileNotFoundError:
        pass
    except OSError as exc:
        raise InputError(
            "--out", str(path), message=f"--out: cannot use {path} ({exc.strerror})"
        ) from None
    ancestor = p
    while not os.path.lexists(ancestor):
        ancestor = ancestor.parent
    if ancestor == p and not p.is_dir():
        raise InputError("--out", str(path), message=f"--out: {path} is a file, not a folder")
    if not ancestor.is_dir():
        raise InputError(
            "--out", str(path), message=f"--out: cannot create {path} ({ancestor} is a file)"
        )
    if not os.access(ancestor, os.W_OK | os.X_OK):
        raise InputError("--out", str(path), message=f"--out: cannot write in {ancestor}")


def plain(doc: str) -> str:
    """A module docstring as ``--help`` text: reST markup (````code````, ``::``) removed."""
    return doc.replace("``", "").replace("::\n", ":\n")
