"""The summary of a run as a person reads it: the outlet temperature in words, the summary
entries (``heat_residence_time_s``) as label, value and unit, and the results of each model of
the case (transport bed profile, RTD, transverse run) as rows with units."""

from __future__ import annotations

import math
import re
from typing import Any

__all__ = [
    "KEY_FIGURES",
    "bed_rows",
    "format_kelvin",
    "format_value",
    "headline",
    "key_figures",
    "models_run",
    "rtd_rows",
    "split_unit",
    "summary_rows",
    "transverse_rows",
]

_UNITS = (
    ("_m2_s", "m²/s"),
    ("_m_s", "m/s"),
    ("_s2", "s²"),
    ("_min", "min"),
    ("_kg", "kg"),
    ("_mm", "mm"),
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


Row = tuple[str, str, str]


def _num(summary: dict, key: str) -> float | None:
    value = summary.get(key)
    if isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value):
        return float(value)
    return None


def _rows(summary: dict, spec) -> list[Row]:
    """Rows of the (label, key, scale, unit, format) entries a summary has."""
    rows = []
    for label, key, scale, unit, fmt in spec:
        value = _num(summary, key)
        if value is not None:
            rows.append((label, format(scale * value, fmt), unit))
    return rows


def bed_rows(summary: dict) -> list[Row]:
    """The transport model's bed: model, fills, hold-up and mean residence time, with units.

    >>> bed_rows({"transport_model": "kramers", "transport_mean_fill": 0.0266,
    ...           "transport_holdup_kg": 6.0088, "transport_mean_residence_time_min": 30.07})
    [('Transport model', 'kramers', ''), ('Mean fill', '2.66', '%'), ('Hold-up', '6.009', 'kg'), ('Mean residence time', '30.1', 'min')]
    """
    rows: list[Row] = []
    if summary.get("transport_model"):
        rows.append(("Transport model", str(summary["transport_model"]), ""))
    return rows + _rows(
        summary,
        (
            ("Mean fill", "transport_mean_fill", 100, "%", ".3g"),
            ("Fill at the discharge", "transport_discharge_fill", 100, "%", ".3g"),
            ("Hold-up", "transport_holdup_kg", 1, "kg", ".4g"),
            ("Mean residence time", "transport_mean_residence_time_min", 1, "min", ".1f"),
        ),
    )


def rtd_rows(summary: dict) -> list[Row]:
    """The predicted RTD's model and moments, with units (times in minutes).

    >>> rtd_rows({"rtd_mean_residence_time_s": 2600.4, "rtd_variance_s2": 18142.0})[1:]
    [('Variance, σ²', '5.04', 'min²'), ('Standard deviation, σ', '2.24', 'min'), ('Dimensionless variance, σ²/t̄²', '0.00268', '')]
    """
    rows: list[Row] = _rows(
        summary, (("Mean residence time, t̄", "rtd_mean_residence_time_s", 1 / 60, "min", ".2f"),)
    )
    mean, variance = _num(summary, "rtd_mean_residence_time_s"), _num(summary, "rtd_variance_s2")
    if variance is not None and variance >= 0:
        rows.append(("Variance, σ²", f"{variance / 3600:.3g}", "min²"))
        rows.append(("Standard deviation, σ", f"{math.sqrt(variance) / 60:.3g}", "min"))
        if mean:
            rows.append(("Dimensionless variance, σ²/t̄²", f"{variance / mean**2:.3g}", ""))
    if summary.get("rtd_model"):
        rows.append(("Dispersion model (boundaries)", str(summary["rtd_model"]), ""))
    peclet = _num(summary, "rtd_peclet")
    if peclet is not None:
        source = summary.get("rtd_peclet_source")
        rows.append(("Péclet number, Pe", f"{peclet:.4g}", f"from {source}" if source else ""))
    return rows + _rows(
        summary,
        (
            ("Space time, τ = L/u", "rtd_tau_s", 1 / 60, "min", ".2f"),
            ("Axial dispersion, D", "rtd_dispersion_m2_s", 1, "m²/s", ".3g"),
        ),
    )


def transverse_rows(summary: dict) -> list[Row]:
    """The transverse run's results (``rotarykiln transverse``'s summary), with units.

    >>> transverse_rows({"mixing_time_s": 37.105, "final_shale_temperature_K": 870.67})
    [('Mixing time (95 % of the peak contact)', '37.1', 's'), ('Final shale temperature', '870.7', 'K')]
    """
    return _rows(
        summary,
        (
            ("Mixing time (95 % of the peak contact)", "mixing_time_s", 1, "s", ".1f"),
            ("Final shale temperature", "final_shale_temperature_K", 1, "K", ".1f"),
            ("Final ash temperature", "final_ash_temperature_K", 1, "K", ".1f"),
            ("Volatiles evolved at 30 s", "volatiles_at_30s_percent", 1, "%", ".2f"),
            ("Volatiles evolved at the end", "final_volatiles_percent", 1, "%", ".2f"),
            (
                "Peak contact over the final contact",
                "peak_contact_over_final_contact_percent",
                1,
                "%",
                ".1f",
            ),
            ("Active-layer velocity", "active_layer_velocity_m_s", 1, "m/s", ".3g"),
            ("Time step", "time_step_s", 1e3, "ms", ".3g"),
            (
                "Mass balance, largest relative error",
                "mass_balance_max_relative_error",
                1,
                "",
                ".2g",
            ),
            (
                "Energy balance, largest relative error",
                "energy_balance_max_relative_error",
                1,
                "",
                ".2g",
            ),
        ),
    )


def models_run(summary: dict, models: dict, kiln: bool) -> str:
    """The models a run ran, in one sentence.

    >>> models_run({"regime": "rolling"}, {"rtd": {}}, False)
    'Models of this case: the bed geometry and regime, the residence time distribution (rtd:).'
    """
    names = []
    if "regime" in summary or "fill" in summary:
        names.append("the bed geometry and regime")
    if kiln:
        names.append("the kiln's heat and mass balances")
    if "transport_model" in summary or "bed" in models:
        names.append("the transport model's bed profile (transport:)")
    if "rtd_model" in summary or "rtd" in models:
        names.append("the residence time distribution (rtd:)")
    if "transverse" in models:
        names.append("the transverse mixing and heating of the retort zone (transverse:)")
    if not names:
        return "This case has only the kiln's geometry: its summary is below."
    return f"Models of this case: {', '.join(names)}."


def headline(summary: dict, models: dict) -> tuple[str, str, str]:
    """The headline of a run without a bed outlet temperature: (label, value, note), from the
    case's models (RTD, transport, transverse run), else its bed regime.

    >>> headline({"rtd_mean_residence_time_s": 2600.4, "rtd_peclet": 745.44}, {})
    ('Mean residence time (RTD)', '43.3 min', 'Péclet number 745')
    """
    rtd_mean = _num(summary, "rtd_mean_residence_time_s")
    if rtd_mean is not None:
        peclet = _num(summary, "rtd_peclet")
        note = f"Péclet number {peclet:.3g}" if peclet is not None else ""
        return "Mean residence time (RTD)", f"{rtd_mean / 60:.1f} min", note
    transport = _num(summary, "transport_mean_residence_time_min")
    if transport is not None:
        holdup = _num(summary, "transport_holdup_kg")
        note = f"hold-up {holdup:.4g} kg" if holdup is not None else ""
        return "Mean residence time (transport model)", f"{transport:.1f} min", note
    result = (models.get("transverse") or {}).get("summary") or {}
    mixing = _num(result, "mixing_time_s")
    if mixing is not None:
        shale = _num(result, "final_shale_temperature_K")
        note = f"final shale temperature {format_kelvin(shale)}" if shale is not None else ""
        return "Mixing time (transverse run)", f"{mixing:.1f} s", note
    if summary.get("regime"):
        froude = _num(summary, "froude")
        note = f"Froude number {froude:.3g}" if froude is not None else ""
        return "Bed regime", str(summary["regime"]), note
    return "Case", str(summary.get("name") or ""), ""
