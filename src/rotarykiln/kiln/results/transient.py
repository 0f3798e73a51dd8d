"""The result of a transient kiln run: every variable against z and t, outlets, RTD, balances."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.tables import with_units

__all__ = ["TransientSolution", "tracer_moments"]


def tracer_moments(t, c, pulse=0.0):
    r"""Mean and variance of an outlet tracer curve, corrected for a square input pulse.

    .. math:: \bar t = \frac{\int t\,c\,dt}{\int c\,dt} - \frac{\delta}{2},\qquad
              \sigma^2 = \frac{\int (t - \bar t_c)^2 c\,dt}{\int c\,dt} - \frac{\delta^2}{12}

    (the moments of a convolution add: a square pulse of width :math:`\delta` started at
    t = 0 has mean :math:`\delta/2` and variance :math:`\delta^2/12`).

    Parameters
    ----------
    t : array, s
        Times since the start of the pulse.
    c : array, kg/s
        Outlet tracer flow (any unit: the moments do not depend on it).
    pulse : float, s
        Width of the square input pulse.

    Returns
    -------
    mean : float, s
    variance : float, s2
    recovered : float, kg
        The integral of c dt (in the unit of c times s).

    Examples
    --------
    >>> t = np.linspace(0.0, 50.0, 50001)
    >>> m, v, a = tracer_moments(t, np.exp(-t))  # one stirred tank, tau = 1 s
    >>> round(m, 4), round(v, 4), round(a, 4)
    (1.0, 1.0, 1.0)

    References
    ----------
    O. Levenspiel, Chemical Reaction Engineering, 3rd ed. (1999), ch. 11.
    """
    t = np.asarray(t, dtype=float)
    c = np.asarray(c, dtype=float)
    area = np.trapezoid(c, t)
    mean_c = np.trapezoid(t * c, t) / area
    var_c = np.trapezoid((t - mean_c) ** 2 * c, t) / area
    return float(mean_c - pulse / 2.0), float(var_c - pulse**2 / 12.0), float(area)


@dataclass(frozen=True)
class TransientSolution:
    """Profiles against time of a transient run (SI units).

    ``t`` (s, outputs); ``z_nodes`` (m, faces), ``z`` (m, cell centres); ``x`` (the unknowns,
    ``(nt, n, nv)``); ``t_bed_nodes``, ``t_gas_nodes`` (K, ``(nt, n + 1)``); ``tracer`` (kg per
    cell); ``accumulated`` (quadrature states: energy J, bed and gas species kg crossing the
    boundary, net in); ``inventory_*`` (energy J, species kg held); ``outlet`` (list of dicts
    per output time); ``steady``: the steady solution started from (or None); ``holdup``.
    """

    name: str
    t: np.ndarray
    z_nodes: np.ndarray
    z: np.ndarray
    x: np.ndarray
    t_bed_nodes: np.ndarray
    t_gas_nodes: np.ndarray
    tracer: np.ndarray
    accumulated: np.ndarray
    inventory_energy: np.ndarray
    inventory_bed: np.ndarray
    inventory_gas: np.ndarray
    outlet: list
    bed_names: tuple
    gas_names: tuple
    wall_labels: tuple
    i_species: int
    bed_scale: float
    gas_scale: float
    gas_out: slice
    species: object
    steady: object
    holdup: object
    tracer_mass: float
    wall_time: float
    rhs_calls: int
    counter_current: bool = True

    # --- profiles -------------------------------------------------------------------------
    @property
    def t_wall(self) -> np.ndarray:
        """Wall node temperatures (K, ``(nt, n, n_wall)``): inner surface ... shell."""
        return self.x[:, :, 2 : self.i_species]

    def bed_flows(self) -> dict:
        """Bed species flows at the cells' outlet faces held (kg/s, ``(nt, n)`` each)."""
        i0 = self.i_species
        return {s: self.x[:, :, i0 + i] * self.bed_scale for i, s in enumerate(self.bed_names)}

    def gas_flows(self) -> dict:
        """Gas species flows at the cells' gas outlet faces (kg/s, ``(nt, n)`` each)."""
        i0 = self.i_species + len(self.bed_names)
        return {s: self.x[:, :, i0 + i] * self.gas_scale for i, s in enumerate(self.gas_names)}

    def to_frame(self) -> pd.DataFrame:
        """Every variable against z and t, one row per (time, cell): the cell's outlet bed
        temperature (at its solids outlet face), gas temperature at its gas outlet face, wall
        node temperatures, species flows and tracer hold-up."""
        import pandas as pd

        nt, n = self.x.shape[:2]
        data = {
            "t_s": np.repeat(self.t, n),
            "cell": np.tile(np.arange(n), nt),
            "z_m": np.tile(self.z, nt),
            "z_bed_face_m": np.tile(self.z_nodes[1:], nt),
            "z_gas_face_m": np.tile(self.z_nodes[self.gas_out], nt),
            "T_bed_K": self.x[:, :, 0].ravel(),
            "T_gas_K": self.x[:, :, 1].ravel(),
        }
        for i, label in enumerate(self.wall_labels):
            data[f"T_{label.replace(' ', '_')}_K"] = self.t_wall[:, :, i].ravel()
        for s, q in self.bed_flows().items():
            data[f"bed_{s}_kg_s"] = q.ravel()
        for s, q in self.gas_flows().items():
            data[f"gas_{s}_kg_s"] = q.ravel()
        data["tracer_kg"] = self.tracer.ravel()
        return with_units(pd.DataFrame(data), "kiln.transient")

    def outlet_frame(self) -> pd.DataFrame:
        """Outlet quantities, boundary flows and inventories against time."""
        import pandas as pd

        rows = []
        for k, o in enumerate(self.outlet):
            row = {"t_s": self.t[k]}
            row.update({key: v for key, v in o.items() if not isinstance(v, dict)})
            row.update({f"bed_out_{s}_kg_s": v for s, v in o["bed_outlet"].items()})
            row.update({f"gas_out_{s}_kg_s": v for s, v in o["gas_outlet"].items()})
            row["inventory_energy_J"] = self.inventory_energy[k]
            rows.append(row)
        return with_units(pd.DataFrame(rows), "kiln.transient")

    # --- balances -------------------------------------------------------------------------
    def energy_conservation(self) -> np.ndarray:
        r"""Relative energy closure at every output time:
        :math:`[\Delta U - \int(\text{in} - \text{out} - \text{losses})\,dt] / \text{scale}`
        with the scale the larger of the throughput :math:`\int \text{in}\,dt` and
        :math:`|\Delta U|`."""
        d_inv = self.inventory_energy - self.inventory_energy[0]
        d_acc = self.accumulated[:, 0] - self.accumulated[0, 0]
        e_in = np.array([o["energy_in_W"] + o["heat_release_W"] for o in self.outlet])
        through = np.concatenate([[0.0], np.cumsum(0.5 * (e_in[1:] + e_in[:-1]) * np.diff(self.t))])
        scale = np.maximum(np.maximum(np.abs(through), np.abs(d_inv)), 1.0)
        return (d_inv - d_acc) / scale

    def element_conservation(self) -> dict:
        """Relative closure of each element at the last output time (held change less net
        inflow, over the elements' throughput)."""
        from rotarykiln.chemistry.balance import element_flows

        nb = len(self.bed_names)

        def elements(bed, gas):
            d = dict(zip(self.bed_names, bed, strict=True))
            d.update(zip(self.gas_names, gas, strict=True))
            return element_flows(d, self.species)

        held = elements(
            self.inventory_bed[-1] - self.inventory_bed[0],
            self.inventory_gas[-1] - self.inventory_gas[0],
        )
        acc = self.accumulated[-1] - self.accumulated[0]
        net = elements(acc[1 : 1 + nb], acc[1 + nb :])
        feed = np.array([o["feed_kg_s"] for o in self.outlet])
        gas = np.array([o["gas_outlet_flow_kg_s"] for o in self.outlet])
        through = float(np.trapezoid(feed + gas, self.t)) + 1e-300
        return {e: abs(held[e] - net[e]) / through for e in held if abs(held[e]) + abs(net[e]) > 0}

    # --- tracer ---------------------------------------------------------------------------
    def rtd(self, pulse_start: float, pulse_width: float):
        """Mean (s), variance (s2) and recovered fraction of the tracer pulse at the outlet."""
        c = np.array([o["tracer_outlet_kg_s"] for o in self.outlet])
        keep = self.t >= pulse_start
        m, v, area = tracer_moments(self.t[keep] - pulse_start, c[keep], pulse_width)
        return {
            "mean_residence_time_s": m,
            "variance_s2": v,
            "recovered_fraction": area / self.tracer_mass if self.tracer_mass else float("nan"),
        }

    # --- summary, plots, files ------------------------------------------------------------
    def summary(self) -> dict:
        """Scalars: outlet temperatures at the start and the end, residence times, wall heat
        capacity, the largest energy (and element) closure, solver figures."""
        o0, o1 = self.outlet[0], self.outlet[-1]
        out = {
            "name": self.name,
            "cells": int(self.x.shape[1]),
            "end_time_s": float(self.t[-1]),
            "outputs": int(self.t.size),
            "bed_outlet_temperature_start_K": o0["bed_outlet_temperature_K"],
            "bed_outlet_temperature_end_K": o1["bed_outlet_temperature_K"],
            "gas_outlet_temperature_start_K": o0["gas_outlet_temperature_K"],
            "gas_outlet_temperature_end_K": o1["gas_outlet_temperature_K"],
            "solids_residence_time_s": float(np.sum(self.holdup.tau_bed)),
            "gas_residence_time_s": float(np.sum(self.holdup.tau_gas)),
            "wall_heat_capacity_J_K": float(np.sum(self.holdup.wall)),
            "energy_conservation_max": float(np.max(np.abs(self.energy_conservation()))),
            "wall_time_s": self.wall_time,
            "rhs_calls": self.rhs_calls,
        }
        el = self.element_conservation()
        if el:
            out["element_conservation_max"] = float(max(el.values()))
        return out

    def plot_heatmap(self):
        """z-t maps of the bed and gas temperatures; returns the Figure."""
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
        th = self.t / 3600.0
        for ax, data, title in (
            (axes[0], self.t_bed_nodes, "bed temperature (K)"),
            (axes[1], self.t_gas_nodes, "gas temperature (K)"),
        ):
            mesh = ax.pcolormesh(self.z_nodes, th, data, shading="nearest", cmap="inferno")
            fig.colorbar(mesh, ax=ax)
            ax.set_xlabel("z from solids inlet (m)")
            ax.set_title(title)
        axes[0].set_ylabel("time (h)")
        fig.suptitle(self.name)
        fig.tight_layout()
        return fig

    def plot_outlets(self):
        """Outlet temperatures, and the heat flows across the boundary, against time; returns the
        Figure."""
        import matplotlib.pyplot as plt

        from rotarykiln.kiln.results.plots import COLOURS

        df = self.outlet_frame()
        th = df["t_s"] / 3600.0
        fig, (a0, a1) = plt.subplots(1, 2, figsize=(11, 4.2))
        a0.plot(th, df["bed_outlet_temperature_K"], color=COLOURS["bed"], label="solids discharge")
        a0.plot(th, df["gas_outlet_temperature_K"], color=COLOURS["gas"], label="gas outlet")
        shell = self.t_wall[:, :, -1].mean(-1)
        a0.plot(th, shell, color=COLOURS["shell"], ls="--", label="shell, mean")
        a0.set_xlabel("time (h)")
        a0.set_ylabel("temperature (K)")
        a0.legend(fontsize=8)
        a1.plot(th, df["shell_loss_W"] / 1e3, label="shell loss")
        a1.plot(th, (df["energy_out_W"]) / 1e3, label="enthalpy out (solids + gas)")
        a1.plot(th, df["reaction_heat_W"] / 1e3, label="heat of reaction")
        a1.set_xlabel("time (h)")
        a1.set_ylabel("heat flow (kW)")
        a1.legend(fontsize=8)
        fig.suptitle(self.name)
        fig.tight_layout()
        return fig

    def write(self, out, *, plots: bool = True) -> dict:
        """Write ``transient_profiles.parquet`` (every variable against z and t; as
        ``transient_profiles.csv`` when pyarrow, of ``rotarykiln[studies]``, is not installed),
        ``transient_outlets.csv``, ``transient_summary.json`` and the figures into ``out``."""
        import matplotlib.pyplot as plt

        from rotarykiln.outputs import (
            atomic_path,
            save_figure_atomic,
            write_frame_atomic,
            write_json_atomic,
        )

        out = Path(out)
        frame = self.to_frame()
        try:
            import pyarrow  # noqa: F401 - Parquet, compact for a long run
        except ImportError:  # a light install: the same table as CSV
            write_frame_atomic(out / "transient_profiles.csv", frame, index=False)
        else:
            atomic_path(
                out / "transient_profiles.parquet", lambda p: frame.to_parquet(p, index=False)
            )
        write_frame_atomic(out / "transient_outlets.csv", self.outlet_frame())
        summary = self.summary()
        write_json_atomic(out / "transient_summary.json", summary)
        if plots:
            for name, fig in (
                ("transient_heatmap.png", self.plot_heatmap()),
                ("transient_outlets.png", self.plot_outlets()),
            ):
                save_figure_atomic(out / name, fig, dpi=110)
                plt.close(fig)
        return summary
