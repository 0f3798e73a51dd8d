"""Residual of the discretised steady kiln heat balances (see :mod:`.discretisation`).

Unknowns per cell ``j`` (last axis of ``x``): 0 ``T_bed`` at the solids-outlet face of the cell
(face j+1); 1 ``T_gas`` at the gas-outlet face (face j when counter-current, j+1 when
co-current); 2 inner wall surface; 3 ... 2+n_layers the lining interfaces outwards, the last
being the outer shell surface; then the extra unknowns of a source term. Residuals are heat
flows per cell in W (bed, gas, wall, each lining interface, shell), then the source's extra
residuals. All functions broadcast over leading batch axes of ``x``.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.kiln.discretisation import Grid
from rotarykiln.kiln.exchange import FLOW_KEYS, CrossSectionExchange, TableGas, cell_report
from rotarykiln.kiln.model import HeatKiln
from rotarykiln.kiln.sources import CellState, SourceTerms
from rotarykiln.kiln.wall import LinedWall

__all__ = ["HeatResidual", "T_FLOOR"]

T_FLOOR = 150.0  # K, temperatures are clipped here inside property evaluations


class HeatResidual:
    """Callable residual ``F(x)`` of a kiln on a grid, with an optional source term."""

    def __init__(self, kiln: HeatKiln, grid: Grid, sources: SourceTerms | None = None):
        self.kiln = kiln
        self.grid = grid
        self.sources = sources
        self.n_layers = len(kiln.layers)
        self.n_extra = int(getattr(sources, "n_extra", 0)) if sources is not None else 0
        self.nv = 3 + self.n_layers + self.n_extra
        self.homotopy = 1.0  # scales radiation and heat release (continuation)
        self.exchange = CrossSectionExchange.of(kiln, grid, kiln.solid)
        self.wall = LinedWall.of(kiln, grid)
        self.gas = TableGas(kiln.gas, kiln.pressure, kiln.gas_flow / grid.freeboard_area)

    def unpack(self, x):
        """Face and cell temperatures from the unknowns ``x`` (..., n, nv)."""
        k = self.kiln
        batch = x.shape[:-2]
        tb_in = np.broadcast_to(k.solids_inlet_temperature, batch + (1,))
        tg_in = np.broadcast_to(k.gas_inlet_temperature, batch + (1,))
        tb_nodes = np.concatenate([tb_in, x[..., 0]], axis=-1)
        if k.counter_current:
            tg_nodes = np.concatenate([x[..., 1], tg_in], axis=-1)
        else:
            tg_nodes = np.concatenate([tg_in, x[..., 1]], axis=-1)
        return tb_nodes, tg_nodes

    def coefficients(self, tg, tb, tw, check=False):
        """Heat transfer coefficients (W/(m2 K)) and gas emissivity at cell-mean states.

        With ``check`` the closures validate their inputs and warn
        (:class:`~rotarykiln.errors.OutOfRangeWarning`) outside their validated ranges; the
        solver does this once on the converged state, not inside the Newton loop.
        """
        return self.exchange.coefficients(self.gas, tg, tb, tw, check=check)

    def evaluate(self, x, full: bool = False):
        """Residual (..., n, nv) in W per cell; with ``full`` also a dict of per-cell fluxes."""
        k, g = self.kiln, self.grid
        tb_nodes, tg_nodes = self.unpack(x)
        tbn = np.maximum(tb_nodes, T_FLOOR)
        tgn = np.maximum(tg_nodes, T_FLOOR)
        tb = 0.5 * (tbn[..., :-1] + tbn[..., 1:])
        tg = 0.5 * (tgn[..., :-1] + tgn[..., 1:])
        tl = np.maximum(x[..., 2 : 3 + self.n_layers], T_FLOOR)  # inner wall .. shell
        tw = tl[..., 0]
        fl, co = self.exchange.flows(self.gas, tg, tb, tw, self.homotopy)
        q_gw, q_gb, q_cw, q_rw, q_rb = (fl[key] for key in FLOW_KEYS)
        wall_rows, q_loss = self.wall.balance(q_gw + q_rw - q_cw, tl)
        s_bed = 0.0
        s_gas = self.homotopy * g.heat_release
        extra_res = None
        if self.sources is not None:
            state = CellState(
                z=g.z,
                dz=g.dz,
                t_gas=tg,
                t_bed=tb,
                t_wall=tw,
                t_bed_nodes=tb_nodes,
                t_gas_nodes=tg_nodes,
                extra=x[..., 3 + self.n_layers :],
                fill=g.fill,
                bed_area=g.bed_area,
                chord=g.chord,
                solids_flow=k.solids_flow,
                gas_flow=k.gas_flow,
            )
            src = self.sources(state)
            s_bed = s_bed + np.asarray(src.q_bed)
            s_gas = s_gas + np.asarray(src.q_gas)
            extra_res = src.extra_residual
        dz = g.dz
        hs = k.solid.enthalpy(tbn)
        hg = k.gas.enthalpy(tgn)
        r_bed = k.solids_flow * (hs[..., 1:] - hs[..., :-1]) - dz * (q_gb + q_rb + q_cw + s_bed)
        to_gas_out = q_gw + q_gb + q_rw + q_rb - s_gas
        if k.counter_current:
            r_gas = k.gas_flow * (hg[..., :-1] - hg[..., 1:]) + dz * to_gas_out
        else:
            r_gas = k.gas_flow * (hg[..., 1:] - hg[..., :-1]) + dz * to_gas_out
        parts = [r_bed, r_gas] + [dz * row for row in wall_rows]
        R = np.stack(parts, axis=-1)
        if self.n_extra:
            R = np.concatenate([R, np.asarray(extra_res) * self.extra_scale], axis=-1)
        if not full:
            return R
        sources = {
            "q_source_bed": np.broadcast_to(s_bed, tg.shape) * 1.0,
            "q_source_gas": np.broadcast_to(s_gas, tg.shape) * 1.0,
        }
        return R, cell_report(tb, tg, fl, q_loss, co, **sources)

    extra_scale = 1.0

    def __call__(self, x):
        return self.evaluate(x)
