"""Atomic file writes for sweep results (switch to rotarykiln.outputs when it lands on main)."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pandas as pd

__all__ = ["write_csv_atomic", "write_parquet_atomic", "save_figure_atomic", "parquet_available"]


def _atomic(path: Path, write) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    try:
        write(tmp)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp creates 0600; give the usual permissions
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path


def write_csv_atomic(frame: pd.DataFrame, path) -> Path:
    """Write a table to CSV atomically (temp file in the same folder, then os.replace)."""
    return _atomic(Path(path), lambda tmp: frame.to_csv(tmp, index=False))


def parquet_available() -> bool:
    """True if pandas can write Parquet (pyarrow or fastparquet importable)."""
    for mod in ("pyarrow", "fastparquet"):
        try:
            __import__(mod)
            return True
        except ImportError:
            continue
    return False


def write_parquet_atomic(frame: pd.DataFrame, path) -> Path:
    """Write a table to Parquet atomically (needs pyarrow or fastparquet)."""
    return _atomic(Path(path), lambda tmp: frame.to_parquet(tmp, index=False))


def save_figure_atomic(fig, path, **kwargs) -> Path:
    """Save a matplotlib figure atomically; the format follows the file suffix."""
    path = Path(path)
    fmt = path.suffix.lstrip(".") or "png"
    return _atomic(path, lambda tmp: fig.savefig(tmp, format=fmt, **kwargs))
