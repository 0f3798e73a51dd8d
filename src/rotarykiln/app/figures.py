"""Interactive figures of a run (Plotly): temperature profiles with the measured points, and the
solids composition along the kiln of a reacting case."""

from __future__ import annotations

import re
from typing import Any

import plotly.graph_objects as go
from matplotlib.colors import to_hex

from rotarykiln.errors import InputError
from rotarykiln.kiln.profiles import COLOURS as PROFILE_COLOURS
from rotarykiln.units import to_si

__all__ = ["composition_figure", "measured_points", "temperature_figure"]

# the colours of the matplotlib figures, as Plotly takes them: one palette for both
COLOURS = {key: to_hex(colour) for key, colour in PROFILE_COLOURS.items()}
SYMBOLS = {"gas": "circle-open", "bed": "square-open", "wall": "triangle-up-open"}
NAMES = {
    "bed": "bed",
    "gas": "gas",
    "wall": "inner wall",
    "shell": "shell",
    "gas_wall": "gas (wall)",
}


def _layout(fig: go.Figure, title: str, ytitle: str) -> go.Figure:
    fig.update_layout(
        title={"text": title, "x": 0.01, "font": {"size": 15}},
        xaxis_title="distance from the solids inlet, z (m)",
        yaxis_title=ytitle,
        template="plotly_white",
        height=400,
        margin={"l": 60, "r": 20, "t": 50, "b": 50},
        legend={"orientation": "h", "y": -0.2, "x": 0},
        hovermode="x unified",
    )
    return fig


def _find_measurements(raw: Any, depth: int = 0) -> dict | None:
    if not isinstance(raw, dict) or depth > 3:
        return None
    found = raw.get("measurements")
    if isinstance(found, dict):
        return found
    for value in raw.values():
        inner = _find_measurements(value, depth + 1)
        if inner is not None:
            return inner
    return None


def measured_points(raw: Any) -> dict[str, tuple[list[float], list[float]]]:
    """Measured temperatures of a raw case (a ``measurements:`` mapping of ``z_<name>`` and
    ``t_<name>`` lists, anywhere in the case), SI: name -> (z in m, T in K). Lists that do not
    read are left out (the run reports them).

    >>> measured_points({"measurements": {"z_bed": ["1 m"], "t_bed": ["300 K"]}})
    {'bed': ([1.0], [300.0])}
    """
    found = _find_measurements(raw) or {}
    out = {}
    for key, zs in found.items():
        match = re.fullmatch(r"z_(\w+)", str(key))
        ts = found.get(f"t_{match.group(1)}") if match else None
        if not (isinstance(zs, list) and isinstance(ts, list) and len(zs) == len(ts) and zs):
            continue
        try:
            z = [to_si(key, v, "length") for v in zs]
            t = [to_si(key, v, "temperature") for v in ts]
        except (InputError, TypeError, ValueError):
            continue
        out[match.group(1)] = (z, t)
    return out


def temperature_figure(profiles: dict[str, list], title: str, raw: Any = None) -> go.Figure:
    """Temperatures along the kiln (``T_<name>_K`` columns against ``z_m``), with the measured
    points of the case as markers of the same colour."""
    fig = go.Figure()
    z = profiles.get("z_m") or profiles.get("Z_m") or []
    for column, values in profiles.items():
        match = re.fullmatch(r"T_(\w+)_K", column)
        if not match:
            continue
        name = match.group(1)
        fig.add_trace(
            go.Scatter(
                x=z,
                y=values,
                mode="lines",
                name=f"{NAMES.get(name, name)}",
                line={
                    "color": COLOURS.get(name),
                    "width": 2.5,
                    "dash": {"shell": "dash", "wall": "dashdot"}.get(name, "solid"),
                },
                hovertemplate="%{y:.1f} K",
            )
        )
    for name, (zm, tm) in measured_points(raw).items():
        fig.add_trace(
            go.Scatter(
                x=zm,
                y=tm,
                mode="markers",
                name=f"{name.replace('_', ' near ')}, measured",  # as the report's figure
                marker={
                    "color": COLOURS.get(name, "#333"),
                    "size": 9,
                    "symbol": SYMBOLS.get(name, "diamond-open"),
                },
                marker_line_width=2,
                hovertemplate="%{y:.1f} K (measured)",
            )
        )
    return _layout(fig, f"Temperatures: {title}", "temperature (K)")


def composition_figure(profiles: dict[str, list], title: str) -> go.Figure | None:
    """Solids species flows along the kiln (``bed_<species>_kg_s`` columns, in kg/h), or None
    when the bed has a single species (nothing reacts)."""
    z = profiles.get("z_m") or profiles.get("Z_m") or []
    columns = [c for c in profiles if re.fullmatch(r"bed_(.+)_kg_s", c)]
    if len(columns) < 2:
        return None
    fig = go.Figure()
    for column in columns:
        species = column[4:-5]
        fig.add_trace(
            go.Scatter(
                x=z,
                y=[None if v is None else 3600.0 * v for v in profiles[column]],
                mode="lines",
                name=species,
                hovertemplate="%{y:.3g} kg/h",
            )
        )
    return _layout(fig, f"Solids composition: {title}", "solids species flow (kg/h)")
