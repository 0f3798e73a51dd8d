"""Interactive figures of a run (Plotly): temperature profiles with the measured points, the
solids composition along the kiln of a reacting case, the transport model's bed profile, the
predicted residence time distribution and the transverse (retort-zone) time series.

The figures set no size: the page draws them responsive, as wide as the panel (a phone's
screen too), at the height it gives them (:data:`HEIGHTS`)."""

from __future__ import annotations

import re
from typing import Any

import plotly.graph_objects as go
from matplotlib.colors import to_hex

from rotarykiln.errors import InputError
from rotarykiln.kiln.results.plots import COLOURS as PROFILE_COLOURS
from rotarykiln.units import to_si

__all__ = [
    "HEIGHTS",
    "bed_profile_figure",
    "composition_figure",
    "measured_points",
    "rtd_figure",
    "temperature_figure",
    "transverse_figure",
]

HEIGHTS = {"transverse": 560}
"""Height of a figure on the page, px, by kind (400 px for the others)."""

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


_Z_TITLE = "distance from the solids inlet, z (m)"


def _layout(fig: go.Figure, title: str, ytitle: str, xtitle: str = _Z_TITLE) -> go.Figure:
    fig.update_layout(
        title={"text": title, "x": 0.01, "font": {"size": 15}},
        xaxis_title=xtitle,
        yaxis_title=ytitle,
        template="plotly_white",
        autosize=True,
        margin={"l": 60, "r": 20, "t": 50, "b": 50},
        legend={"orientation": "h", "y": -0.2, "x": 0, "yanchor": "top"},
        hovermode="x unified",
    )
    return fig


def _title(kind: str, title: str) -> str:
    """A figure's title: its kind, then ``title`` (a case or a profile's name) if any."""
    return f"{kind}: {title}" if title else kind


def _scaled(values: list, factor: float) -> list:
    return [None if v is None else factor * v for v in values]


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
    return _layout(fig, _title("Temperatures", title), "temperature (K)")


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
    return _layout(fig, _title("Solids composition", title), "solids species flow (kg/h)")


def bed_profile_figure(bed: dict[str, list], title: str) -> go.Figure:
    """The bed depth along the kiln from the transport model (``z_m``, ``depth_m``, with the
    local ``fill`` and the solids' ``residence_time_s`` from the inlet in the hover), mm."""
    fill = [None if v is None else 100 * v for v in bed.get("fill", [])]
    minutes = _scaled(bed.get("residence_time_s", []), 1 / 60)
    fig = go.Figure(
        go.Scatter(
            x=bed.get("z_m", []),
            y=_scaled(bed.get("depth_m", []), 1e3),
            mode="lines",
            name="bed depth",
            line={"color": COLOURS.get("bed"), "width": 2.5},
            fill="tozeroy",
            customdata=list(zip(fill, minutes, strict=False)) if fill and minutes else None,
            hovertemplate="%{y:.1f} mm deep"
            + (
                "<br>fill %{customdata[0]:.2f} %<br>%{customdata[1]:.1f} min from the inlet"
                if fill and minutes
                else ""
            )
            + "<extra></extra>",
        )
    )
    _layout(fig, _title("Bed profile", title), "bed depth (mm)")
    fig.update_layout(showlegend=False, yaxis_rangemode="tozero")
    return fig


def rtd_figure(rtd: dict[str, list], title: str, mean_s: float | None = None) -> go.Figure:
    """The predicted exit-age distribution E(t) (``t_s``, ``E_1_s``; ``F`` in the hover), in
    minutes, with the mean residence time ``mean_s`` (s) marked."""
    cumulative = rtd.get("F") or []
    fig = go.Figure(
        go.Scatter(
            x=_scaled(rtd.get("t_s", []), 1 / 60),
            y=_scaled(rtd.get("E_1_s", []), 60),
            mode="lines",
            name="E(t), predicted",
            line={"color": COLOURS.get("bed"), "width": 2.5},
            customdata=cumulative or None,
            hovertemplate="E = %{y:.4g} 1/min"
            + ("<br>F = %{customdata:.3f}" if cumulative else "")
            + "<extra>%{x:.1f} min</extra>",
        )
    )
    _layout(fig, _title("Residence time distribution", title), "E(t) (1/min)", "time, t (min)")
    if mean_s is not None:
        fig.add_vline(
            x=mean_s / 60,
            line={"color": "#5f6670", "dash": "dot"},
            annotation_text=f"mean {mean_s / 60:.1f} min",
            annotation_position="top right",
        )
    fig.update_layout(hovermode="closest", showlegend=False)
    return fig


def transverse_figure(series: dict[str, list], title: str) -> go.Figure:
    """The transverse run against time: the mean temperatures of the shale and the ash (K,
    above), the extent of mixing and the volatiles evolved (% , below)."""
    from plotly.subplots import make_subplots

    t = series.get("t_s", [])
    fig = make_subplots(rows=2, cols=1, shared_xaxes=True, vertical_spacing=0.08)
    for column, name, row, line in (
        ("T_shale_K", "shale, mean temperature", 1, {"color": COLOURS.get("bed"), "width": 2.5}),
        ("T_ash_K", "ash, mean temperature", 1, {"color": COLOURS.get("gas"), "width": 2.5}),
        ("extent_percent", "extent of mixing", 2, {"width": 2, "dash": "solid"}),
        ("volatiles_percent", "volatiles evolved", 2, {"width": 2, "dash": "dash"}),
    ):
        if column in series:
            fig.add_trace(
                go.Scatter(
                    x=t,
                    y=series[column],
                    mode="lines",
                    name=name,
                    line=line,
                    hovertemplate="%{y:.1f} " + ("K" if row == 1 else "%"),
                ),
                row=row,
                col=1,
            )
    _layout(fig, _title("Transverse run", title), "mean temperature (K)", "")
    fig.update_yaxes(title_text="mean temperature (K)", row=1, col=1)
    fig.update_yaxes(title_text="percent (%)", row=2, col=1)
    fig.update_xaxes(title_text="time, t (s)", row=2, col=1)
    fig.update_layout(legend={"y": -0.12})
    return fig
