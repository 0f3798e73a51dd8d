"""A Parquet dataset of study results that grows as cases finish and survives a kill.

The dataset is a folder of part files ``part-<time>-<pid>-<n>.parquet``, one row per case: the
case hash, id and group, the values set (as text) and their SI values, the outputs, the error
text ("" for a case that ran) and the run time. Each part is written under a temporary name
(``.part-....tmp``, ignored by readers) in the same folder, flushed to disk and renamed with
``os.replace``: a part is there whole or not at all. Stale temporary files of a killed run are
removed when the store is opened again. Read the dataset with :meth:`ResultStore.read` or
``pandas.read_parquet(folder)``.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import os
import time
from collections.abc import Mapping, Sequence
from pathlib import Path

import pandas as pd

from rotarykiln.errors import InputError

__all__ = ["ResultStore", "case_hash", "FIXED_COLUMNS"]

#: Columns of every stored row besides parameters and outputs.
FIXED_COLUMNS = (
    "hash",
    "case_id",
    "group",
    "error",
    "warnings",
    "elapsed_s",
    "output_names",
)

_counter = itertools.count()


def _canonical(obj) -> str:
    return json.dumps(obj, sort_keys=True, default=str, separators=(",", ":"))


def case_hash(base_digest: str, values: Mapping, model: str = "") -> str:
    """Hash (16 hex digits) of a case: the base case's digest, the values set, the model.

    Parameters
    ----------
    base_digest : str
        ``hashlib.sha256`` hex digest of the base case (see :meth:`ResultStore.digest`).
    values : mapping
        Path -> value set by the design.
    model : str
        The model's ``module:qualname``: the same case run by another model is another row.

    Returns
    -------
    str
        16 hexadecimal characters.

    Examples
    --------
    >>> h = case_hash(ResultStore.digest({"a": 1}), {"a": 2}, "m:f")
    >>> len(h), h == case_hash(ResultStore.digest({"a": 1}), {"a": 2}, "m:f")
    (16, True)
    """
    text = base_digest + _canonical(dict(sorted(values.items()))) + model
    return hashlib.sha256(text.encode()).hexdigest()[:16]


class ResultStore:
    """Append-only Parquet dataset of study rows in a folder (see the module docstring).

    Parameters
    ----------
    folder : path
        Created if absent. Part files of earlier runs are kept and read.
    """

    def __init__(self, folder):
        from rotarykiln.extras import require

        require("pyarrow", "a study's result store (Parquet)")
        self.folder = Path(folder)
        if self.folder.exists() and not self.folder.is_dir():
            raise InputError("study.store", str(self.folder), "a folder (it is a file)")
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise InputError(
                "study.store", str(self.folder), f"a folder that can be created ({exc.strerror})"
            ) from None
        for stale in self.folder.glob(".part-*.tmp"):  # left by a killed run: never whole
            stale.unlink(missing_ok=True)

    @staticmethod
    def digest(case: Mapping) -> str:
        """sha256 hex digest of a case mapping (keys sorted, values as text)."""
        return hashlib.sha256(_canonical(case).encode()).hexdigest()

    def parts(self) -> list[Path]:
        """The complete part files, oldest first."""
        return sorted(self.folder.glob("part-*.parquet"))

    def hashes(self) -> set[str]:
        """Hashes of every stored case (the hash column only is read)."""
        out: set[str] = set()
        for p in self.parts():
            out.update(pd.read_parquet(p, columns=["hash"])["hash"].tolist())
        return out

    def read(self) -> pd.DataFrame:
        """All stored rows (parts concatenated; columns absent from a part are empty)."""
        parts = [pd.read_parquet(p) for p in self.parts()]
        parts = [p for p in parts if len(p)]
        if not parts:
            return pd.DataFrame(columns=list(FIXED_COLUMNS))
        return pd.concat(parts, ignore_index=True, sort=False)

    def append(self, records: Sequence[dict]) -> Path | None:
        """Write ``records`` as one new part, atomically; returns its path (None if empty)."""
        if not records:
            return None
        frame = pd.DataFrame.from_records(list(records))
        for col in frame.columns:  # mixed numbers and text (values as given, labels) -> text
            if frame[col].dtype == object:
                kinds = {type(v) for v in frame[col] if v is not None}
                if len(kinds) > 1 or (kinds and not kinds <= {str}):
                    frame[col] = frame[col].map(lambda v: None if v is None else str(v))
        name = f"part-{time.time_ns():020d}-{os.getpid()}-{next(_counter):06d}.parquet"
        final = self.folder / name
        tmp = self.folder / f".{name}.tmp"
        try:
            frame.to_parquet(tmp, index=False)
            with open(tmp, "rb") as fh:
                os.fsync(fh.fileno())
            os.replace(tmp, final)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
        return final
