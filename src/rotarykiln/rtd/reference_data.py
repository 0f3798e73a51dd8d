"""Tables of the RTD sources shipped with the package (src/rotarykiln/data/bongo_njeng2015/)."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from rotarykiln.errors import InputError

__all__ = ["DATA_DIR", "bongo_njeng_table"]

DATA_DIR = Path(__file__).resolve().parent.parent / "data" / "bongo_njeng2015"


def bongo_njeng_table(name: str) -> pd.DataFrame:
    """One table of seed 003 as a DataFrame (see the README.md of the data folder).

    Examples
    --------
    >>> bongo_njeng_table("table3_replicates").shape
    (8, 10)
    """
    path = DATA_DIR / f"{name}.csv"
    if not path.is_file():
        names = sorted(p.stem for p in DATA_DIR.glob("*.csv"))
        raise InputError("table", name, "one of " + ", ".join(names))
    return pd.read_csv(path)
