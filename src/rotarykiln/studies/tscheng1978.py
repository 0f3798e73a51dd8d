"""Tscheng's 44 pilot-kiln runs for studies and calibration: the built-in cases and the data.

Run ``A11`` ... ``A54`` is the built-in case ``tscheng_<run>`` (src/rotarykiln/cases/; written
from the data by docs/scripts/make_tscheng_cases.py, ``tscheng_A16`` the template);
:func:`tscheng_cases` reads those files. The measured table is
src/rotarykiln/data/tscheng1978/ (README.md there): :func:`tscheng_runs` reads it, and
:func:`tscheng_measurements` gives its bed and gas temperatures as a calibration table
(``case, quantity, z, value, uncertainty``), by default in the window 1.25-1.78 m that the thesis
recommends and where the validation scores the model (docs/validation.md).
"""

from __future__ import annotations

from importlib import resources

import pandas as pd

from rotarykiln.cases import builtin_case

__all__ = ["tscheng_case_name", "tscheng_cases", "tscheng_measurements", "tscheng_runs"]


def _data(name: str) -> pd.DataFrame:
    path = resources.files("rotarykiln") / "data" / "tscheng1978" / name
    with path.open("r", encoding="utf-8") as fh:
        return pd.read_csv(fh)


def tscheng_runs() -> pd.DataFrame:
    """The 44 measured runs as a DataFrame indexed by run id (columns as in the CSV).

    Examples
    --------
    >>> runs = tscheng_runs()
    >>> len(runs), float(runs.loc["A16", "Air flow (kg/hr)"]), float(runs.loc["A16", "T-s-3"])
    (44, 24.6, 374.0)
    """
    return _data("tscheng_pilot_kiln_A11-A54.csv").set_index("Experiment ID")


def tscheng_case_name(run: str) -> str:
    """The built-in case of run ``run``.

    Examples
    --------
    >>> tscheng_case_name("A16")
    'tscheng_A16'
    """
    return f"tscheng_{run}"


def tscheng_cases(runs=None) -> dict[str, dict]:
    """Run id -> the run's built-in case file as a plain nested dict (all 44 by default).

    Examples
    --------
    >>> cases = tscheng_cases()
    >>> len(cases), cases["A11"]["operation"]["speed"], cases["A11"]["gas"]["flow"]
    (44, '3 rpm', '24.6 kg/h')
    """
    return {str(run): builtin_case(tscheng_case_name(run)) for run in runs or tscheng_runs().index}


def tscheng_measurements(
    window: tuple[float, float] | None = (1.25, 1.78), uncertainty: float = 5.0, runs=None
) -> pd.DataFrame:
    """Measured bed and gas temperatures of the runs: case, quantity, z (m), value (K),
    uncertainty (K); positions inside ``window`` only (None: all five; the gas reading at
    2.32 m is the inlet temperature and is left out). Positions from the data folder's
    ``thermocouple_positions.csv``.

    Examples
    --------
    >>> m = tscheng_measurements()
    >>> len(m), sorted(set(m["z"]))
    (176, [1.25, 1.78])
    """
    table = tscheng_runs()
    positions = _data("thermocouple_positions.csv")
    inlet = positions.loc[positions["quantity"] == "gas", "z_m"].max()  # the inlet air reading
    rows = []
    for run in runs or list(table.index):
        r = table.loc[run]
        for z, at in positions.groupby("z_m", sort=True):
            if window is not None and not window[0] <= z <= window[1]:
                continue
            for quantity in ("bed", "gas"):
                if quantity == "gas" and z == inlet:
                    continue
                for column in at.loc[at["quantity"] == quantity, "column"]:
                    value = float(r[column])
                    rows.append((str(run), f"{quantity}_temperature", float(z), value, uncertainty))
    return pd.DataFrame(rows, columns=["case", "quantity", "z", "value", "uncertainty"])
