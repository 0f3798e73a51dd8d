"""The summary of a run as a person reads it: the outlet temperature in words, and the summary
entries (``heat_residence_time_s``) as label, value and unit."""

from __future__ import annotations

import math
import re
from typing import Any

__all__ = [
    "KEY_FIGURES",
    "format_kelvin",
    "format_value",
    "key_figures",
    "split_unit",
    "summary_rows",
]

_UNITS = (
    ("_W_m", "W/m"),
    ("_kg_s", "kg/s"),
    ("_kg_h", "kg/h"),
    ("_m2", "m²"),
    ("_percent", "%"),
    ("_rpm", "rpm"),
    ("_deg", "deg"),
    ("_rad", "rad"),
    ("_K", "K"),
    ("_W", "W"),
    ("_s", "s"),
    ("_m", "m"),
)

KEY_FIGURES = {
    "gas_outlet_temperature_K": "Gas outlet temperature",
    "bed_max_temperature_K": "Bed maximum temperature",
    "residence_time_s": "Residence time",
    "heat_to_solids_W": "Heat to the solids",
    "shell_loss_W": "Shell loss",
    "thermal_efficiency": "Thermal efficiency",
    "energy_balance_closure": "Energy balance closure",
    "regime": "Bed regime",
    "froude": "Froude number",
    "fill": "Fill fraction",
}
"""Summary entries shown beside the outlet temperature (matched at the end of the key, the
first key that matches), with their labels."""


def split_unit(key: str) -> tuple[str, str]:
    """A summary key as a label and a unit.

    >>> split_unit("heat_residence_time_s")
    ('heat residence time', 's')
    >>> split_unit("froude")
    ('froude', '')
    """
    for suffix, unit in _UNITS:
        if key.endswith(suffix) and len(key) > len(suffix):
            return key[: -len(suffix)].replace("_", " "), unit
    return key.replace("_", " "), ""


def format_kelvin(value: float) -> str:
    """A temperature as shown in the app: kelvin to 0.1 K, then degrees Celsius.

    >>> format_kelvin(445.91242041542665)
    '445.9 K (172.8 °C)'
    """
    return f"{value:.1f} K ({value - 273.15:.1f} °C)"


def format_value(value: Any, unit: str = "") -> str:
    """A summary value as text: temperatures to 0.1 K, other numbers to 4 significant digits.

    >>> format_value(4842.274874333477, "s")
    '4842'
    >>> format_value(-2.3e-15)
    '-2.3e-15'
    """
    if isinstance(value, bool) or value is None:
        return "" if value is None else str(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            return str(value)
        if unit == "K":
            return f"{value:.1f}"
        return f"{value:.4g}"
    return str(value)


def summary_rows(summary: dict) -> list[tuple[str, str, str]]:
    """(label, value, unit) rows of every summary entry but the name."""
    rows = []
    for key, value in summary.items():
        if key != "name":
            label, unit = split_unit(key)
            rows.append((label, format_value(value, unit), unit))
    return rows


def key_figures(summary: dict) -> list[tuple[str, str, str]]:
    """(label, value, unit) rows of the :data:`KEY_FIGURES` a summary has, in readable units.

    >>> key_figures({"heat_residence_time_s": 4842.3, "heat_thermal_efficiency": 0.4936})
    [('Residence time', '80.7', 'min'), ('Thermal efficiency', '49.4', '%')]
    """
    found = {}
    for end in KEY_FIGURES:
        key = next((k for k in summary if re.search(rf"(^|_){re.escape(end)}$", k)), None)
        if key is not None and summary[key] is not None:
            found[end] = key
    powers = [summary[k] for k in found.values() if k.endswith("_W")]
    kilowatts = any(isinstance(p, float) and abs(p) >= 1e4 for p in powers)  # one unit for all
    rows = []
    for end, key in found.items():
        label, value, unit = KEY_FIGURES[end], summary[key], split_unit(key)[1]
        if isinstance(value, float) and math.isfinite(value):
            if unit == "s" and value >= 120:
                value, unit = value / 60, "min"
            elif unit == "W" and kilowatts:
                value, unit = value / 1e3, "kW"
            elif end == "thermal_efficiency":
                value, unit = 100 * value, "%"
            if unit in ("K", "min", "%", "kW"):
                rows.append((label, f"{value:.1f}" if unit != "kW" else f"{value:.2f}", unit))
                continue
        rows.append((label, format_value(value, unit), unit))
    return rows
