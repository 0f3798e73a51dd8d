"""The summary of a run as a person reads it: the outlet temperature in words, and the summary
entries (``heat_residence_time_s``) as label, value and unit."""

from __future__ import annotations

import math
import re
from typing import Any

__all__ = ["KEY_FIGURES", "format_kelvin", "format_value", "split_unit", "summary_rows"]

_UNITS = (
    ("_W_per_m", "W/m"),
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

KEY_FIGURES = (
    "gas_outlet_temperature_K",
    "bed_max_temperature_K",
    "residence_time_s",
    "heat_to_solids_W",
    "shell_loss_W",
    "thermal_efficiency",
    "regime",
    "fill",
)
"""Summary entries shown beside the outlet temperature (matched at the end of the key)."""


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


def summary_rows(summary: dict, keys: tuple[str, ...] | None = None) -> list[tuple[str, str, str]]:
    """(label, value, unit) rows of a summary: every entry but the name, or those whose key ends
    with one of ``keys``, in the order of ``keys``."""
    if keys is None:
        chosen = [k for k in summary if k != "name"]
    else:
        chosen = []
        for end in keys:
            for k in summary:
                if re.search(rf"(^|_){re.escape(end)}$", k) and k not in chosen:
                    chosen.append(k)
                    break
    rows = []
    for key in chosen:
        label, unit = split_unit(key)
        rows.append((label, format_value(summary[key], unit), unit))
    return rows
