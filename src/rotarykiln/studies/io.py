"""File inputs and outputs of studies.

Outputs: CSV, Parquet (when available) and figures, all written atomically. Inputs: the data
files the program reads besides case files (calibration data, tracer curves), read by
:func:`read_data_csv` within the same kind of limits as the case loader: a size limit checked
before parsing (:data:`MAX_DATA_BYTES`), a row limit (:data:`MAX_DATA_ROWS`), a column limit,
UTF-8 text, and one-line refusals that never echo a value raw (:func:`shown`).
"""

from __future__ import annotations

import io
import re
from pathlib import Path

import pandas as pd

from rotarykiln.errors import InputError
from rotarykiln.outputs import atomic_path, save_figure_atomic, write_frame_atomic
from rotarykiln.yaml_limits import read_file_within

__all__ = [
    "MAX_DATA_BYTES",
    "MAX_DATA_COLUMNS",
    "MAX_DATA_ROWS",
    "parquet_available",
    "read_data_csv",
    "save_figure_atomic",
    "shown",
    "write_csv_atomic",
    "write_parquet_atomic",
]

MAX_DATA_BYTES = 20_000_000
"""Largest data file read, bytes (checked before parsing; 100,000 rows of text fit in it)."""
MAX_DATA_ROWS = 100_000
"""Most data rows of a data file (a tracer curve or a plant data set has far fewer)."""
MAX_DATA_COLUMNS = 100
"""Most columns of a data file."""

_PLAIN = re.compile(r"[\w .,:;/+\-\[\]()%=@*^']*")


def shown(value, limit: int = 60) -> str:
    """``value`` as it may appear in a one-line message: as is when it is short printable text,
    else its ``repr`` (newlines and control characters escaped), shortened to ``limit``.

    Examples
    --------
    >>> print(shown("1.5 m"), shown("1" + chr(10) + "2"), shown("x" * 100, 10))
    1.5 m '1\\n2' 'xxxxxx...
    """
    text = value if isinstance(value, str) else str(value)
    if len(text) <= limit and _PLAIN.fullmatch(text):
        return text
    text = repr(text)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def read_data_csv(
    path,
    option: str,
    *,
    what: str = "data file",
    max_bytes: int = MAX_DATA_BYTES,
    max_rows: int = MAX_DATA_ROWS,
    **read_csv,
) -> pd.DataFrame:
    """Read a CSV data file into a table, within limits, refusing a bad file in one line.

    The size is checked before anything is parsed (at most ``max_bytes`` + 1 bytes are read:
    a growing file or a device cannot exhaust memory); the text must be UTF-8 (a byte-order
    mark is allowed); at most :data:`MAX_DATA_COLUMNS` columns and ``max_rows`` data rows.

    Parameters
    ----------
    path : path-like
        The file.
    option : str
        The option or field that named the file (``--data``), used in the messages ("": the
        messages start with the file name).
    what : str
        What the file is, in the messages ("tracer file").
    max_bytes, max_rows : int
        Limits.
    **read_csv
        Passed to :func:`pandas.read_csv` (e.g. ``comment="#"``).

    Returns
    -------
    pandas.DataFrame
        As read (not validated: the caller checks its columns and values).

    Raises
    ------
    InputError
        One line naming the file: missing, unreadable, too large, not UTF-8, not a CSV table,
        too many columns or rows.
    """
    name = shown(str(path), 200)
    where = f"{option}: {name}" if option else name
    option = option or name
    raw = read_file_within(
        path, max_bytes, label=where, what=what, field=option, note=f" and {max_rows:,} rows"
    )
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise InputError(
            option,
            message=f"{where}: not UTF-8 text (byte 0x{raw[exc.start]:02x} at line "
            f"{line}); save the {what} as UTF-8",
        ) from None
    if "\x00" in text:
        raise InputError(option, message=f"{where}: not a text file (a NUL byte)")
    comment = read_csv.get("comment")
    for line in text.splitlines():  # the header: the first line with something on it
        if line.strip() and not (comment and line.lstrip().startswith(comment)):
            if line.count(",") >= MAX_DATA_COLUMNS:
                raise InputError(
                    option,
                    message=f"{where}: more than {MAX_DATA_COLUMNS} columns",
                )
            break
    try:
        frame = pd.read_csv(io.StringIO(text), nrows=max_rows + 1, **read_csv)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, ValueError) as exc:
        problem = shown(str(exc).strip().splitlines()[0] if str(exc).strip() else "empty", 120)
        raise InputError(option, message=f"{where}: not a readable CSV table ({problem})") from None
    if frame.shape[1] > MAX_DATA_COLUMNS:
        raise InputError(option, message=f"{where}: more than {MAX_DATA_COLUMNS} columns")
    if len(frame) > max_rows:
        raise InputError(
            option, message=f"{where}: more than {max_rows:,} rows (at most {max_rows:,})"
        )
    return frame


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
