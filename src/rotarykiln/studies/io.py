"""File outputs of sweeps: CSV, Parquet (when available) and figures, all written atomically."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from rotarykiln.outputs import atomic_path, save_figure_atomic, write_frame_atomic

__all__ = ["write_csv_atomic", "write_parquet_atomic", "save_figure_atomic", "parquet_available"]


def write_csv_atomic(frame: pd.DataFrame, path) -> Path:
    """Write a table to CSV atomically (rotarykiln.outputs.write_frame_atomic)."""
    return write_frame_atomic(path, frame)


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
    return atomic_path(path, lambda p: frame.to_parquet(p, index=False))
