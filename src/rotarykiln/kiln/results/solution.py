"""Result of a kiln solve: temperatures, species flows, rates, balances."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.chemistry.ratelaws import MOISTURE
from rotarykiln.kiln.results.plots import heat_flow_columns, plot_temperature_profiles
from rotarykiln.tables import with_units

__all__ = ["KilnSolution"]


@dataclass(frozen=True)
class KilnSolution:
    """Steady kiln solution, inert or reacting (SI units).

    Face profiles (``n + 1`` values, z = 0 at the solids inlet): ``z_nodes`` (m),
    ``t_bed_nodes``, ``t_gas_nodes`` (K), ``bed_flows`` and ``gas_flows`` (species -> kg/s).
    Cell profiles: ``z`` (m), ``t_bed``, ``t_gas`` (cell means), ``t_wall`` (inner wall, K),
    ``t_lining`` (wall temperatures, inner surface to shell, shape ``(n_wall, n)``, K; one row
    for the constant-U wall),
    ``reaction_rates`` (reaction -> kg basis/(s m)), ``fluxes`` (W/m per path, coefficients).
    Balances: ``energy_closure`` = (enthalpy in - out - shell loss - reaction heat) / heat to the
    solids (-), ``element_closure`` (element -> relative |in - out|), ``reaction_heat`` (W,
    absorbed at 298.15 K basis), ``shell_loss`` (W), ``energy_in``/``energy_out`` (W, sensible
    enthalpy flows relative to 298.15 K), ``heat_release`` (W released in the gas by a
    burner's flame), ``energy_sheet`` (dict, W: fuel LHV/HHV input, sensible inputs, heat to
    the solids, shell and exhaust losses, closure; thermal efficiency), ``burner`` (dict of
    the burner's figures; empty without one). ``fill_profile`` (-, cells), ``measurements``
    (measured profiles drawn by :meth:`plot`). Solver: ``iterations``, ``residual``.
    ``exhaust``: the gas leaving, after an air ingress at the feed end has mixed into it
    (``temperature_K``, ``flow_kg_s``, ``O2_dry_mole_fraction``, ``air_ingress_kg_s``).
    """

    name: str
    z_nodes: np.ndarray
    t_bed_nodes: np.ndarray
    t_gas_nodes: np.ndarray
    bed_flows: dict
    gas_flows: dict
    z: np.ndarray
    t_bed: np.ndarray
    t_gas: np.ndarray
    t_wall: np.ndarray
    reaction_rates: dict
    fluxes: dict
    energy_in: float
    energy_out: float
    shell_loss: float
    reaction_heat: float
    heat_to_solids: float
    energy_closure: float
    element_closure: dict
    iterations: int
    residual: float
    residence_time: float
    fill: float
    feed: dict = field(repr=False, default_factory=dict)
    t_lining: np.ndarray | None = field(repr=False, default=None)
    counter_current: bool = True
    heat_release: float = 0.0
    energy_sheet: dict = field(repr=False, default_factory=dict)
    burner: dict = field(repr=False, default_factory=dict)
    measurements: dict | None = field(repr=False, default=None)
    fill_profile: np.ndarray | None = field(repr=False, default=None)
    exhaust: dict = field(repr=False, default_factory=dict)

    def __repr__(self) -> str:
        """One line: the case, the grid, the outlet temperatures and the balances (the profiles
        are in :meth:`to_frame`, every scalar in :meth:`summary`)."""
        return (
            f"<KilnSolution {self.name!r}: {len(self.z)} cells, bed "
            f"{self.t_bed_nodes[0]:.1f} -> {self.bed_outlet_temperature:.1f} K, gas out "
            f"{self.gas_outlet_temperature:.1f} K, heat to solids {self.heat_to_solids:.4g} W, "
            f"energy closure {self.energy_closure:.2g}, {self.iterations} Newton iterations>"
        )

    @property
    def t_shell(self) -> np.ndarray | None:
        """Outer shell temperature (K, cells) of a lined wall; None for the constant-U wall."""
        if self.t_lining is None or len(self.t_lining) < 2:
            return None
        return self.t_lining[-1]

    # --- performance --------------------------------------------------------------------------
    def _dry(self, i: int) -> float:
        return float(sum(v[i] for s, v in self.bed_flows.items() if s != MOISTURE))

    @property
    def burn_off(self) -> float:
        """Dry-basis loss of solid mass, % (seed 004's burn-off, moisture excluded)."""
        d0, d1 = self._dry(0), self._dry(-1)
        return 100.0 * (d0 - d1) / d0 if d0 > 0 else 0.0

    @property
    def production(self) -> float:
        """Dry solids out per dry solids in, % (100 - burn-off)."""
        return 100.0 - self.burn_off

    def conversion(self, species: str) -> np.ndarray:
        """1 - Q(z)/Q_in of a bed species along the faces, -."""
        q = self.bed_flows[species]
        return 1.0 - q / q[0] if q[0] > 0 else np.zeros_like(q)

    def position_of_conversion(self, species: str, conversion: float) -> float:
        """First z (m) where the conversion of ``species`` reaches ``conversion``."""
        x = np.maximum.accumulate(self.conversion(species))
        if conversion > x[-1]:
            return float("nan")
        j = int(np.argmax(x >= conversion))
        if j == 0:
            return 0.0
        x0, x1 = x[j - 1], x[j]
        f = (conversion - x0) / (x1 - x0) if x1 > x0 else 1.0
        return float(self.z_nodes[j - 1] + f * (self.z_nodes[j] - self.z_nodes[j - 1]))

    def onset(self, reaction: str, fraction: float = 0.01) -> tuple[float, float]:
        """First cell (z, T_bed) where ``reaction`` exceeds ``fraction`` of its peak rate."""
        r = self.reaction_rates[reaction]
        if r.max() <= 0:
            return float("nan"), float("nan")
        j = int(np.argmax(r >= fraction * r.max()))
        return float(self.z[j]), float(self.t_bed[j])

    def end(self, reaction: str, fraction: float = 0.01) -> float:
        """Last cell centre z where ``reaction`` exceeds ``fraction`` of its peak rate, m."""
        r = self.reaction_rates[reaction]
        if r.max() <= 0:
            return float("nan")
        j = len(r) - 1 - int(np.argmax(r[::-1] >= fraction * r.max()))
        return float(self.z[j])

    @property
    def thermal_efficiency(self) -> float:
        """Heat to the solids (sensible + reaction) over the fuel's LHV input (fired kilns) or
        the heat the gas gives up, -."""
        return float(self.energy_sheet.get("thermal_efficiency", float("nan")))

    def bed_temperature_at(self, z):
        """Bed temperature (K) at positions ``z`` (m), linear between faces."""
        return np.interp(z, self.z_nodes, self.t_bed_nodes)

    def gas_temperature_at(self, z):
        """Gas temperature (K) at positions ``z`` (m), linear between faces."""
        return np.interp(z, self.z_nodes, self.t_gas_nodes)

    def wall_temperature_at(self, z, interface: int = 0):
        """Wall temperature (K) at ``z`` (m) at ``interface`` (0 inner surface, -1 shell)."""
        rows = self.t_lining if self.t_lining is not None else self.t_wall[None, :]
        return np.interp(z, self.z, rows[interface])

    def gas_thermocouple(self, diameter, emissivity=0.8, bed_view=0.5) -> np.ndarray:
        """What a bare thermocouple in the gas would read, K (cells): the cell's gas at its
        velocity, the junction seeing the bed over ``bed_view`` of its view and the inner wall
        over the rest (:func:`rotarykiln.heat.thermocouple.bare_thermocouple_temperature`, air
        properties; ``diameter`` m, ``emissivity`` -).
        """
        from rotarykiln.heat.thermocouple import bare_thermocouple_temperature

        t_s = (bed_view * self.t_bed**4 + (1.0 - bed_view) * self.t_wall**4) ** 0.25
        u = np.asarray(self.fluxes["gas_velocity"], dtype=float)
        return bare_thermocouple_temperature(self.t_gas, t_s, u, diameter, emissivity)

    def _thermocouple_nodes(self) -> np.ndarray | None:
        """The thermocouple reading of the case's ``measurements.thermocouple`` at the faces."""
        tc = (self.measurements or {}).get("thermocouple")
        if not tc or "gas_velocity" not in self.fluxes:
            return None
        cells = self.gas_thermocouple(tc["diameter"], tc["emissivity"], tc["bed_view"])
        return np.interp(self.z_nodes, self.z, cells)

    def measured_rmse(self) -> dict:
        """RMSE (K) of the solution at the measured positions, per measured profile: bed, gas
        and gas near the wall (raw gas temperature), the gas readings through the case's
        thermocouple (``gas_thermocouple``, when given), inner wall (or the measured wall
        interface). Empty without measurements."""
        m = self.measurements or {}
        out = {}
        tc = self._thermocouple_nodes()
        model = {
            "bed": self.bed_temperature_at,
            "gas": self.gas_temperature_at,
            "gas_wall": self.gas_temperature_at,
            "wall": lambda z: self.wall_temperature_at(z, int(m.get("wall_interface", 0))),
        }
        for key, at in model.items():
            z, t = m.get(f"z_{key}", ()), m.get(f"t_{key}", ())
            if len(z) and len(t):
                out[key] = float(np.sqrt(np.mean((at(np.asarray(z)) - np.asarray(t)) ** 2)))
                if tc is not None and key == "gas":  # the readings the thermocouple is for
                    reading = np.interp(z, self.z_nodes, tc)
                    out[f"{key}_thermocouple"] = float(np.sqrt(np.mean((reading - t) ** 2)))
        return out

    @property
    def gas_outlet_temperature(self) -> float:
        """Gas temperature where the gas leaves (z = 0 counter-current, z = L co-current), K."""
        return float(self.t_gas_nodes[0 if self.counter_current else -1])

    @property
    def bed_outlet_temperature(self) -> float:
        """Bed temperature at the solids discharge (z = L), K."""
        return float(self.t_bed_nodes[-1])

    def summary(self) -> dict:
        """Scalars: outlet states, burn-off, conversions, onsets, balances, solver figures."""
        out = {
            "name": self.name,
            "bed_outlet_temperature_K": self.bed_outlet_temperature,
            "gas_outlet_temperature_K": self.gas_outlet_temperature,
            "bed_max_temperature_K": float(self.t_bed_nodes.max()),
            "gas_max_temperature_K": float(self.t_gas_nodes.max()),
            "gas_min_temperature_K": float(self.t_gas_nodes.min()),
            "gas_outlet_flow_kg_s": float(
                sum(v[0 if self.counter_current else -1] for v in self.gas_flows.values())
            ),
            "solids_outlet_flow_kg_s": float(sum(v[-1] for v in self.bed_flows.values())),
            **{f"exhaust_{k}": v for k, v in self.exhaust.items()},
            **{f"rmse_{k}_K": v for k, v in self.measured_rmse().items()},
            "reaction_heat_W": self.reaction_heat,
            "shell_loss_W": self.shell_loss,
            "heat_to_solids_W": self.heat_to_solids,
            "energy_balance_closure": self.energy_closure,
            "element_balance_closure": max(self.element_closure.values(), default=0.0),
            "residence_time_s": self.residence_time,
            "fill": self.fill,
            "newton_iterations": self.iterations,
            "residual": self.residual,
            "cells": len(self.z),
            "thermal_efficiency": self.thermal_efficiency,
            **{f"energy_{k}": v for k, v in self.energy_sheet.items() if k != "thermal_efficiency"},
            **{f"burner_{k}": v for k, v in self.burner.items()},
        }
        if self.reaction_rates and self.feed.get("C", 0.0) > 0:  # a carbon bed (seed 004)
            out["burn_off_percent"] = self.burn_off
            out["production_percent"] = self.production
        elif self.reaction_rates:  # any other reacting bed: the neutral words
            out["dry_mass_loss_percent"] = self.burn_off
            out["solids_yield_percent"] = self.production
        for s, q in self.bed_flows.items():
            if s != MOISTURE and q[0] > 0 and q[-1] < q[0]:
                x = self.conversion(s)
                out[f"conversion_{s}"] = float(x[-1])
                for label, frac in (("1pct", 0.01), ("99pct", 0.99)):
                    z = self.position_of_conversion(s, frac * x[-1])
                    out[f"z_conversion_{label}_{s}_m"] = z
                    out[f"T_bed_conversion_{label}_{s}_K"] = float(
                        np.interp(z, self.z_nodes, self.t_bed_nodes)
                    )
        for r in self.reaction_rates:
            z_on, t_on = self.onset(r)
            out[f"{r}_onset_z_m"] = z_on
            out[f"{r}_onset_T_bed_K"] = t_on
            out[f"{r}_end_z_m"] = self.end(r)
        return out

    def to_frame(self) -> pd.DataFrame:
        """One row per face: position, temperatures (wall, rates at cell centres interpolated)."""
        import pandas as pd

        return with_units(pd.DataFrame(self.columns()), "kiln")

    def columns(self) -> dict[str, np.ndarray]:
        """The columns of :meth:`to_frame` (name -> values per face), without pandas."""
        data = {
            "z_m": self.z_nodes,
            "T_bed_K": self.t_bed_nodes,
            "T_gas_K": self.t_gas_nodes,
            "T_wall_K": np.interp(self.z_nodes, self.z, self.t_wall),
        }
        if self.t_shell is not None:
            data["T_shell_K"] = np.interp(self.z_nodes, self.z, self.t_shell)
        tc = self._thermocouple_nodes()
        if tc is not None:  # beside the raw gas temperature, never instead of it
            data["T_gas_thermocouple_K"] = tc
        for s, q in self.bed_flows.items():
            data[f"bed_{s}_kg_s"] = q
        for s, q in self.gas_flows.items():
            data[f"gas_{s}_kg_s"] = q
        for r, v in self.reaction_rates.items():
            data[f"rate_{r}_kg_s_m"] = np.interp(self.z_nodes, self.z, v)
        data.update(heat_flow_columns(self.fluxes, lambda v: np.interp(self.z_nodes, self.z, v)))
        return data

    def plot(self, ax=None):
        """Temperatures (left) and, when the bed reacts, solids and gas flows (right); returns
        the Figure."""
        import matplotlib.pyplot as plt

        reacting = bool(self.reaction_rates)
        if ax is None:
            fig, ax = plt.subplots(
                1, 2 if reacting else 1, figsize=(11, 4.2) if reacting else (7, 4.2)
            )
        else:
            fig = np.atleast_1d(ax)[0].figure
        axes = np.atleast_1d(ax)
        plot_temperature_profiles(
            self,
            axes[0],
            t_shell=self.t_shell,
            measurements=self.measurements,
            t_gas_thermocouple=self._thermocouple_nodes(),
        )
        if not reacting or len(axes) < 2:
            fig.tight_layout()
            return fig
        a1 = axes[1]
        for s, q in self.bed_flows.items():
            if np.ptp(q) > 0 or q[0] > 0:
                a1.plot(self.z_nodes, q * 1e3, label=f"bed {s}")
        for s, q in self.gas_flows.items():
            if np.ptp(q) > 0:
                a1.plot(self.z_nodes, q * 1e3, ls="--", label=f"gas {s}")
        a1.set_xlabel("z from solids inlet (m)")
        a1.set_ylabel("mass flow (g/s)")
        a1.set_title(f"species flows; dry solids mass loss {self.burn_off:.2f} %")
        a1.legend(
            fontsize=8, ncol=4, loc="upper center", bbox_to_anchor=(0.5, -0.16), frameon=False
        )
        axes[0].set_title("temperatures")
        fig.suptitle(self.name)
        fig.tight_layout()
        return fig
