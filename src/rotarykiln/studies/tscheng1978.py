"""Tscheng's 44 pilot-kiln runs as case dicts and measured data, for studies and calibration.

Each run's case is the built-in ``tscheng_A16`` case with the run's measured inputs (air
flow, speed, incline, fill, solids flow, inlet air temperature = the gas reading at 2.32 m) and
its measured profiles; :func:`tscheng_measurements` gives the bed and gas temperatures as a
calibration table (``case, quantity, z, value, uncertainty``), by default in the window
1.25-1.78 m where the validation scores the model (docs/validation.md).
"""

from __future__ import annotations

import copy

import pandas as pd

from rotarykiln.studies.ahmad2006 import builtin_case

__all__ = ["tscheng_cases", "tscheng_measurements"]

_Z = (0.21, 0.72, 1.25, 1.78, 2.32)


def _runs():
    from rotarykiln.kiln.tscheng import load_tscheng_runs

    return load_tscheng_runs()


def tscheng_cases(runs=None) -> dict[str, dict]:
    """Run id -> case dict (A16's case with the run's inputs and measurements).

    Examples
    --------
    >>> cases = tscheng_cases()
    >>> len(cases), cases["A11"]["operation"]["speed"], cases["A11"]["gas"]["flow"]
    (44, '3.0 rpm', '24.6 kg/h')
    """
    table = _runs()
    base = builtin_case("tscheng_A16")
    out = {}
    for run in runs or list(table.index):
        r = table.loc[run]
        c = copy.deepcopy(base)
        c["name"] = f"Tscheng 1978 run {run}"
        c["kiln"]["slope"] = f"{float(r['Incline (degree)'])} deg"
        c["operation"]["speed"] = f"{float(r['RPM'])} rpm"
        c["operation"]["feed"] = f"{float(r['Solid flow (kg/hr)'])} kg/h"
        c["bed"]["fill"] = float(r["Solid loading (%)"]) / 100.0
        c["gas"]["flow"] = f"{float(r['Air flow (kg/hr)'])} kg/h"
        c["gas"]["temperature"] = f"{float(r['T-g-5'])} K"
        m = c["measurements"]
        m["t_gas"] = [f"{float(r[f'T-g-{i}'])} K" for i in range(1, 6)]
        m["t_bed"] = [f"{float(r[f'T-s-{i}'])} K" for i in range(1, 6)]
        m["t_wall"] = [f"{float(r[f'T-w-{i}'])} K" for i in range(1, 5)]
        out[str(run)] = c
    return out


def tscheng_measurements(
    window: tuple[float, float] | None = (1.25, 1.78), uncertainty: float = 5.0, runs=None
) -> pd.DataFrame:
    """Measured bed and gas temperatures of the runs: case, quantity, z (m), value (K),
    uncertainty (K); positions inside ``window`` only (None: all five; the gas reading at
    2.32 m is the inlet temperature and is left out).

    Examples
    --------
    >>> m = tscheng_measurements()
    >>> len(m), sorted(set(m["z"]))
    (176, [1.25, 1.78])
    """
    table = _runs()
    rows = []
    for run in runs or list(table.index):
        r = table.loc[run]
        for i, z in enumerate(_Z, start=1):
            if window is not None and not window[0] <= z <= window[1]:
                continue
            rows.append((str(run), "bed_temperature", z, float(r[f"T-s-{i}"]), uncertainty))
            if i < 5:
                rows.append((str(run), "gas_temperature", z, float(r[f"T-g-{i}"]), uncertainty))
    return pd.DataFrame(rows, columns=["case", "quantity", "z", "value", "uncertainty"])
