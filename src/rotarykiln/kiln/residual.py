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

from rotarykiln.heat.bed_conductivity import (
    maxwell_bed_conductivity,
    zehner_schlunder_bed_conductivity,
)
from rotarykiln.heat.contact import (
    li_covered_wall_h,
    tscheng_covered_wall_h,
    wachters_kramers_covered_wall_h,
)
from rotarykiln.heat.convection import (
    gas_reynolds,
    gorog_gas_bed_h,
    gorog_gas_wall_h,
    rotational_reynolds,
    tscheng_watkinson_gas_bed_nusselt,
    tscheng_watkinson_gas_wall_nusselt,
)
from rotarykiln.heat.gas_radiation import johansson_wsgg_emissivity, smith_wsgg_emissivity
from rotarykiln.heat.radiation import freeboard_radiation
from rotarykiln.heat.wall import cylinder_layer_heat_flow, shell_heat_loss
from rotarykiln.kiln.discretisation import Grid
from rotarykiln.kiln.model import HeatKiln
from rotarykiln.kiln.sources import CellState, SourceTerms
from rotarykiln.materials.gas import air_table

__all__ = ["HeatResidual"]

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
        self.air = air_table()
        self.homotopy = 1.0  # scales radiation and heat release (continuation)
        self._prepare()

    # constant parts of the closures
    def _prepare(self):
        k, g = self.kiln, self.grid
        c = k.closures
        s = k.solid
        self.gas_mass_flux = k.gas_flow / g.freeboard_area
        if c.bed_conductivity == "given" and s.bed_conductivity is not None:
            self.k_bed = lambda tg: s.bed_conductivity
        elif c.bed_conductivity == "maxwell":
            self.k_bed = lambda tg: maxwell_bed_conductivity(
                k.gas.conductivity(tg), s.solid_conductivity, 1.0 - s.void_fraction
            )
        else:
            self.k_bed = lambda tg: zehner_schlunder_bed_conductivity(
                k.gas.conductivity(tg), s.solid_conductivity, s.void_fraction
            )
        self.p_h2o = k.gas.x_h2o * k.pressure
        self.p_co2 = k.gas.x_co2 * k.pressure
        self.has_participating_gas = (self.p_h2o + self.p_co2) > 0

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
        k, g, c = self.kiln, self.grid, self.kiln.closures
        gas = k.gas
        mu = gas.viscosity(tg)
        kg = gas.conductivity(tg)
        rho = gas.density(tg, k.pressure)
        De = g.hydraulic_diameter
        re = gas_reynolds(self.gas_mass_flux, De, mu)
        if c.gas_wall == "tscheng1979" or c.gas_bed == "tscheng1979":
            re_w = rotational_reynolds(rho, k.omega, De, mu)
        if c.gas_wall == "tscheng1979":
            h_gw = tscheng_watkinson_gas_wall_nusselt(re, re_w, check=check) * kg / De
        else:
            pr = gas.prandtl(tg)
            h_gw = gorog_gas_wall_h(kg, De, re, pr, k.length, check=check)
        if c.gas_bed == "tscheng1979":
            h_gb = tscheng_watkinson_gas_bed_nusselt(re, re_w, g.fill, check=check) * kg / De
        else:
            h_gb = gorog_gas_bed_h(self.gas_mass_flux, check=check) * np.ones_like(tg)
        t_film = 0.5 * (tw + tb)
        kb = self.k_bed(t_film)
        rho_c = k.solid.bulk_density * k.solid.cp(tb)
        if c.covered_wall == "li2005":
            h_cw = li_covered_wall_h(
                gas.conductivity(t_film),
                k.solid.particle_diameter,
                kb,
                rho_c,
                k.omega,
                g.full_angle,
                check=check,
            )
        elif c.covered_wall == "tscheng1979":
            h_cw = tscheng_covered_wall_h(kb, rho_c, k.omega, k.radius, g.full_angle, check=check)
        else:
            h_cw = wachters_kramers_covered_wall_h(kb, rho_c, k.omega, g.full_angle, check=check)
        if not c.radiation:
            eps_g = 0.0
        elif not isinstance(c.gas_emissivity, str):
            eps_g = float(c.gas_emissivity)
        elif not self.has_participating_gas:
            eps_g = 0.0
        elif c.gas_emissivity == "johansson2011":
            eps_g = johansson_wsgg_emissivity(
                tg, self.p_h2o, self.p_co2, g.beam_length, check=check
            )
        else:
            eps_g = smith_wsgg_emissivity(
                tg, (self.p_h2o + self.p_co2) * g.beam_length, "pw/pc=2", check=check
            )
        eps_g = np.clip(eps_g, 0.0, 0.95)
        return {"h_gw": h_gw, "h_gb": h_gb, "h_cw": h_cw, "eps_gas": eps_g, "Re": re}

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
        co = self.coefficients(tg, tb, tw)
        q_gw = co["h_gw"] * g.exposed_wall * (tg - tw)
        q_gb = co["h_gb"] * g.chord * (tg - tb)
        q_cw = co["h_cw"] * g.covered_wall * (tw - tb)
        if k.closures.radiation:
            q_rw, q_rb = freeboard_radiation(
                tg,
                tw,
                tb,
                co["eps_gas"],
                k.eps_wall,
                k.solid.emissivity,
                g.exposed_wall,
                g.chord,
                check=False,
            )
            q_rw = self.homotopy * q_rw
            q_rb = self.homotopy * q_rb
        else:
            q_rw = q_rb = 0.0 * tg
        # lining: flow through each layer (W/m, outwards)
        q_layers = []
        for i, layer in enumerate(k.layers):
            mat = layer.material
            q_layers.append(
                cylinder_layer_heat_flow(
                    mat.conductivity_integral(tl[..., i]),
                    mat.conductivity_integral(tl[..., i + 1]),
                    g.radii[i],
                    g.radii[i + 1],
                )
            )
        q_loss = shell_heat_loss(
            tl[..., -1],
            k.ambient_temperature,
            2.0 * g.radii[-1],
            k.eps_shell,
            self.air,
            k.wind_speed,
        )
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
        parts = [r_bed, r_gas, dz * (q_gw + q_rw - q_cw - q_layers[0])]
        for i in range(1, self.n_layers):
            parts.append(dz * (q_layers[i - 1] - q_layers[i]))
        parts.append(dz * (q_layers[-1] - q_loss))
        R = np.stack(parts, axis=-1)
        if self.n_extra:
            R = np.concatenate([R, np.asarray(extra_res) * self.extra_scale], axis=-1)
        if not full:
            return R
        fluxes = {
            "t_bed_mean": tb,
            "t_gas_mean": tg,
            "q_gas_wall_conv": q_gw,
            "q_gas_bed_conv": q_gb,
            "q_covered_wall_bed": q_cw,
            "q_rad_to_wall": q_rw,
            "q_rad_to_bed": q_rb,
            "q_shell_loss": q_loss,
            "q_source_bed": np.broadcast_to(s_bed, tg.shape) * 1.0,
            "q_source_gas": np.broadcast_to(s_gas, tg.shape) * 1.0,
            **co,
        }
        return R, fluxes

    extra_scale = 1.0

    def __call__(self, x):
        return self.evaluate(x)
