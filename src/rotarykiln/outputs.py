"""Atomic output writers: a file is either written whole or not at all.

Each writer writes to a temporary file in the destination folder, then ``os.replace`` s it over the
target, so an interrupted run never leaves a truncated result behind.
"""

from __future__ import annotations

import contextlib
import contextvars
import json
import os
import tempfile
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from rotarykiln.errors import InputError

__all__ = [
    "atomic_path",
    "save_figure_atomic",
    "write_frame_atomic",
    "write_json_atomic",
    "write_text_atomic",
]


def atomic_path(path: str | os.PathLike, writer: Callable[[Path], None]) -> Path:
    """Call ``writer(tmp_path)`` then move ``tmp_path`` onto ``path`` atomically."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=path.suffix, dir=path.parent)
    os.close(fd)
    try:
        writer(Path(tmp))
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600 files; give the usual mode
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_text_atomic(path: str | os.PathLike, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    return atomic_path(path, lambda p: p.write_text(text, encoding="utf-8"))


def _jsonable(obj: Any) -> Any:
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [_jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _jsonable(obj.tolist())
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, float) and not np.isfinite(obj):
        return None
    return obj


def to_json(data: Any) -> str:
    """JSON text of ``data`` (numpy arrays and scalars converted, non-finite floats as null)."""
    return json.dumps(_jsonable(data), indent=2, sort_keys=False)


def write_json_atomic(path: str | os.PathLike, data: Any) -> Path:
    """Write ``data`` as indented JSON atomically."""
    return write_text_atomic(path, to_json(data) + "\n")


def write_frame_atomic(path: str | os.PathLike, frame: pd.DataFrame, **to_csv_kwargs) -> Path:
    """Write a DataFrame to CSV atomically (index omitted unless asked)."""
    to_csv_kwargs.setdefault("index", False)
    return atomic_path(path, lambda p: frame.to_csv(p, **to_csv_kwargs))


#: False inside :func:`no_figures`: :func:`save_figure_atomic` then writes nothing.
_FIGURES = contextvars.ContextVar("rotarykiln_figures", default=True)


@contextlib.contextmanager
def no_figures():
    """Within this context :func:`save_figure_atomic` writes no figure (``--no-plots``)."""
    token = _FIGURES.set(False)
    try:
        yield
    finally:
        _FIGURES.reset(token)


def save_figure_atomic(path: str | os.PathLike, fig, **savefig_kwargs) -> Path | None:
    """Save a matplotlib figure atomically; the format follows the suffix of ``path``.

    Inside :func:`no_figures` nothing is written (returns None). A figure that fails to render
    is reported as a warning and skipped: the tables written before it are kept.
    """
    if not _FIGURES.get():
        return None
    savefig_kwargs.setdefault("dpi", 120)
    savefig_kwargs.setdefault("bbox_inches", "tight")
    fmt = Path(path).suffix.lstrip(".").lower() or "png"
    supported = fig.canvas.get_supported_filetypes()
    if fmt not in supported:
        raise InputError(
            str(path),
            message=f'{path}: ".{fmt}" is not a figure format (use .png, .pdf or .svg)',
        )
    try:
        return atomic_path(path, lambda p: fig.savefig(p, format=fmt, **savefig_kwargs))
    except (OSError, InputError):
        raise
    except Exception as exc:  # a rendering failure must not lose the run's tables
        warnings.warn(f"figure {Path(path).name} not written: {exc}", RuntimeWarning, stacklevel=2)
        return None
