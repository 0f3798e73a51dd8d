"""Result of a steady kiln heat solve: profiles, heat flows per path, balance and summary."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from rotarykiln.kiln.profiles import heat_flow_columns, plot_temperature_profiles

__all__ = ["KilnSolution"]


@dataclass(frozen=True)
class KilnSolution:
    """Steady kiln heat-transfer solution (SI units).

    Face (node) profiles: ``z_nodes`` (m), ``t_bed_nodes``, ``t_gas_nodes`` (K).
    Cell profiles: ``z`` (m), ``t_bed``, ``t_gas`` (cell means, K), ``t_wall`` (inner wall
    surface, K), ``t_shell`` (outer shell surface, K), ``t_lining`` (interfaces, inner to
    outer, shape ``(n_layers + 1, n)``, K), ``fill`` (-), ``fluxes`` (dict of W/m per cell:
    gas->wall and gas->bed convection, covered wall->bed, radiation to wall and to bed, shell
    loss, sources; and the coefficients h_gw, h_gb, h_cw in W/(m2 K) and the gas emissivity).
    Summary: ``heat_to_solids``, ``heat_from_gas``, ``heat_release``, ``shell_loss`` (W),
    ``energy_sheet`` (dict: fuel LHV/HHV input, sensible inputs, heat to solids, shell and
    exhaust losses, closure, W; thermal efficiency), ``burner`` (dict of the burner's figures:
    flame length, jet numbers, excess air; empty without a burner),
    ``energy_in``, ``energy_out`` (W, enthalpy flows relative to 298.15 K plus heat release and
    shell loss), ``balance_closure`` = (in - out)/heat_to_solids (-).
    Solver: ``iterations``, ``residual`` (max scaled residual), ``n_cells``.
    """

    name: str
    z_nodes: np.ndarray
    t_bed_nodes: np.ndarray
    t_gas_nodes: np.ndarray
    z: np.ndarray
    t_bed: np.ndarray
    t_gas: np.ndarray
    t_wall: np.ndarray
    t_shell: np.ndarray
    t_lining: np.ndarray
    fill: np.ndarray
    fluxes: dict
    extra: np.ndarray
    heat_to_solids: float
    heat_from_gas: float
    heat_release: float
    shell_loss: float
    energy_in: float
    energy_out: float
    balance_closure: float
    iterations: int
    residual: float
    n_cells: int
    counter_current: bool
    measurements: dict | None = field(default=None, repr=False)
    energy_sheet: dict = field(default_factory=dict, repr=False)
    burner: dict = field(default_factory=dict, repr=False)

    @property
    def bed_outlet_temperature(self) -> float:
        """Bed temperature at the solids discharge (z = L), K."""
        return float(self.t_bed_nodes[-1])

    @property
    def gas_outlet_temperature(self) -> float:
        """Gas temperature where the gas leaves (z = 0 counter-current, z = L co-current), K."""
        return float(self.t_gas_nodes[0] if self.counter_current else self.t_gas_nodes[-1])

    @property
    def thermal_efficiency(self) -> float:
        """Heat to the solids over the fuel's LHV input (fired kilns), or over the heat given
        up by the gas plus the heat release (kilns without a burner), -."""
        if "thermal_efficiency" in self.energy_sheet:
            return float(self.energy_sheet["thermal_efficiency"])
        supplied = self.heat_from_gas + self.heat_release
        return float(self.heat_to_solids / supplied) if supplied else float("nan")

    def bed_temperature_at(self, z):
        """Bed temperature (K) at positions ``z`` (m), linear between faces."""
        return np.interp(z, self.z_nodes, self.t_bed_nodes)

    def gas_temperature_at(self, z):
        """Gas temperature (K) at positions ``z`` (m), linear between faces."""
        return np.interp(z, self.z_nodes, self.t_gas_nodes)

    def wall_temperature_at(self, z, interface: int = 0):
        """Lining temperature (K) at ``z`` (m) at ``interface`` (0 inner surface, -1 shell)."""
        return np.interp(z, self.z, self.t_lining[interface])

    def summary(self) -> dict:
        """Outlet temperatures, heat flows, efficiency, balance and solver figures."""
        return {
            "name": self.name,
            "bed_outlet_temperature_K": self.bed_outlet_temperature,
            "gas_outlet_temperature_K": self.gas_outlet_temperature,
            "heat_to_solids_W": self.heat_to_solids,
            "heat_from_gas_W": self.heat_from_gas,
            "heat_release_W": self.heat_release,
            "shell_loss_W": self.shell_loss,
            "thermal_efficiency": self.thermal_efficiency,
            "energy_balance_closure": self.balance_closure,
            "newton_iterations": self.iterations,
            "residual": self.residual,
            "cells": self.n_cells,
            **{f"energy_{k}": v for k, v in self.energy_sheet.items() if k != "thermal_efficiency"},
            **{f"burner_{k}": v for k, v in self.burner.items()},
        }

    def to_frame(self) -> pd.DataFrame:
        """One row per cell: position, temperatures, fill and the heat flow of each path."""
        data = {
            "z_m": self.z,
            "T_gas_K": self.t_gas,
            "T_bed_K": self.t_bed,
            "T_wall_K": self.t_wall,
            "T_shell_K": self.t_shell,
            "fill": self.fill,
        }
        data.update(heat_flow_columns(self.fluxes))
        for key, value in self.fluxes.items():
            if key.startswith("h_"):
                data[f"{key}_W_per_m2K"] = np.asarray(value)
            elif key == "eps_gas":
                data["eps_gas"] = np.broadcast_to(np.asarray(value), self.z.shape)
        return pd.DataFrame(data)

    def plot(self, ax=None):
        """Temperature profiles (gas, bed, wall, shell), with measured points if any."""
        return plot_temperature_profiles(
            self, ax, t_shell=self.t_shell, measurements=self.measurements
        )
