"""Shared helpers for subcommands: quantity arguments with units, output of results."""

from __future__ import annotations

import argparse
from pathlib import Path

from rotarykiln.errors import InputError
from rotarykiln.outputs import to_json
from rotarykiln.units import to_si

__all__ = ["add_quantity", "get_quantity", "print_json", "out_dir", "plain"]


def add_quantity(parser: argparse.ArgumentParser, name: str, help: str, **kwargs) -> None:
    """Add ``--name VALUE [UNIT]``: both ``--speed 5 rpm`` and ``--speed 5rpm`` work."""
    # usage reads "--speed VALUE [UNIT ...]" (a tuple metavar names the first and the rest)
    parser.add_argument(f"--{name}", nargs="+", metavar=("VALUE", "UNIT"), help=help, **kwargs)


def get_quantity(args: argparse.Namespace, name: str, kind: str, *, required: bool = False):
    """The SI value of quantity option ``--name`` (``None`` when absent and not required)."""
    tokens = getattr(args, name.replace("-", "_"))
    if tokens is None:
        if required:
            raise InputError(f"--{name}", message=f"--{name}: missing (required)")
        return None
    text = " ".join(tokens) if isinstance(tokens, list) else str(tokens)
    return to_si(f"--{name}", text, kind)


def print_json(data) -> None:
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


def plain(doc: str) -> str:
    """A module docstring as ``--help`` text: reST markup (````code````, ``::``) removed."""
    return doc.replace("``", "").replace("::\n", ":\n")
