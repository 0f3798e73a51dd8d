"""The kiln solution's temperature-profile plot, figure colours and heat-flow columns."""

from __future__ import annotations

import numpy as np

__all__ = ["COLOURS", "plot_temperature_profiles", "heat_flow_columns"]

#: The colours of the kiln's figures (the app's Plotly figures use the same): bed and wall in
#: hues a reader tells apart at a glance, also in grey print and with red-green blindness.
COLOURS = {
    "gas": "tab:red",
    "gas_wall": "tab:orange",
    "bed": "tab:brown",
    "wall": "tab:blue",
    "shell": "tab:gray",
}

_MEASURED = (
    ("gas", COLOURS["gas"], "o"),
    ("gas_wall", COLOURS["gas_wall"], "D"),
    ("bed", COLOURS["bed"], "s"),
    ("wall", COLOURS["wall"], "^"),
)


def plot_temperature_profiles(
    sol, ax=None, *, t_shell=None, measurements=None, t_gas_thermocouple=None
):
    """Gas, bed, inner wall (and shell) temperatures along the kiln, measured points if any.

    ``sol`` has ``z_nodes``, ``t_gas_nodes``, ``t_bed_nodes`` (faces), ``z``, ``t_wall``
    (cells) and ``name``; ``t_shell`` (K, cells), ``measurements`` (``z_gas``, ``t_gas``,
    ... arrays) and ``t_gas_thermocouple`` (K, faces: what a bare thermocouple would read) are
    drawn when given. Returns the Figure.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(sol.z_nodes, sol.t_gas_nodes, color=COLOURS["gas"], label="gas")
    ax.plot(sol.z_nodes, sol.t_bed_nodes, color=COLOURS["bed"], lw=2, label="bed")
    ax.plot(sol.z, sol.t_wall, color=COLOURS["wall"], ls="-.", label="inner wall")
    if t_shell is not None:
        ax.plot(sol.z, t_shell, color=COLOURS["shell"], ls="--", label="shell")
    m = measurements or {}
    if t_gas_thermocouple is not None:
        ax.plot(
            sol.z_nodes, t_gas_thermocouple, color=COLOURS["gas"], ls=":", label="gas, thermocouple"
        )
    for key, color, marker in _MEASURED:
        if len(m.get(f"z_{key}", ())) and len(m.get(f"t_{key}", ())):
            ax.plot(
                m[f"z_{key}"],
                m[f"t_{key}"],
                ls="none",
                marker=marker,
                mfc="none",
                color=color,
                label=f"{key.replace('_', ' near ')}, measured",
            )
    ax.set_xlabel("z from solids inlet (m)")
    ax.set_ylabel("temperature (K)")
    ax.set_title(sol.name)
    # below the axes: a legend inside could hide measured points
    ax.legend(fontsize=8, ncol=4, loc="upper center", bbox_to_anchor=(0.5, -0.16), frameon=False)
    return ax.figure


def heat_flow_columns(fluxes: dict, at=None) -> dict:
    """Columns ``<q_key>_W_m`` of the per-cell heat flows in ``fluxes``.

    ``at``: a callable mapping a per-cell array to the rows of the frame (e.g. interpolation to
    the faces), or None to keep one row per cell.

    Examples
    --------
    >>> heat_flow_columns({"q_shell_loss": np.array([1.0, 2.0]), "h_gw": 3.0})
    {'q_shell_loss_W_m': array([1., 2.])}
    """
    out = {}
    for key, value in fluxes.items():
        if key.startswith("q_"):
            v = np.asarray(value)
            out[f"{key}_W_m"] = v if at is None else at(v)
    return out
