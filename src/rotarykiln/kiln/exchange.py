r"""Heat exchange across a kiln cross-section: every closure dispatched in one place.

The kiln's residual (:class:`~rotarykiln.kiln.residual.KilnResidual`, for every kiln, inert or
reacting, steady or transient) computes the heat flows per metre of kiln between gas, exposed
wall, bed and covered wall with :class:`CrossSectionExchange`, given the cell-mean temperatures
and a :class:`FreeboardGas` (the gas properties: the mixture of changing composition the
residual uses, :class:`~rotarykiln.kiln.gas_mixture.MixtureGas`, or a table of fixed
composition, :class:`TableGas`):

.. math::
    Q_{gw} = h_{gw} A_w (T_g - T_w),\quad Q_{gb} = h_{gb} L_c (T_g - T_b),\quad
    Q_{cw} = h_{cw} A_c (T_w - T_b),\quad (Q_{rw}, Q_{rb}) = \text{grey network}(\varepsilon_g)

with the closures chosen by name in :class:`~rotarykiln.kiln.inputs.closures.Closures`: gas-wall and
gas-bed convection (``tscheng1979``, ``gorog1982``), covered wall (``li2005``,
``tscheng1979``, ``wachters_kramers1964``), bed conductivity (``given``, ``maxwell``,
``zehner_schlunder``), gas emissivity (``johansson2011``, ``smith1982``, a constant, or seed
004's line :math:`\max(a + bT, \varepsilon_{min})`). See docs/heat.md.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.heat.bed_conductivity import (
    maxwell_bed_conductivity,
    radiative_bed_conductivity,
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
from rotarykiln.heat.gas_radiation import (
    combined_emissivity,
    johansson_wsgg_emissivity,
    particle_cloud_emissivity,
    smith_wsgg_emissivity,
    soot_emissivity,
    wsgg_bands,
)
from rotarykiln.heat.radiation import (
    freeboard_radiation,
    freeboard_radiation_bands,
    freeboard_radiation_paths,
)
from rotarykiln.kiln.inputs import Closures
from rotarykiln.materials.gas import GasPropertyTable

__all__ = [
    "FreeboardGas",
    "TableGas",
    "BulkBed",
    "CrossSectionExchange",
    "cell_report",
    "gas_conductance",
    "upwind_weight",
    "FLOW_KEYS",
    "EPS_GAS_MAX",
]

#: Keys of the heat flows (W/m) returned by :meth:`CrossSectionExchange.flows`.
FLOW_KEYS = (
    "q_gas_wall_conv",
    "q_gas_bed_conv",
    "q_covered_wall_bed",
    "q_rad_to_wall",
    "q_rad_to_bed",
)
#: Cap of the gas emissivity (grey gas, absorptivity = emissivity).
EPS_GAS_MAX = 0.95


class FreeboardGas(Protocol):
    """Gas properties in the cells, as the exchange closures need them (SI units).

    ``mass_flux`` (kg/(m2 s), over the freeboard area); ``transport(T)`` -> conductivity
    (W/(m K)) and viscosity (Pa s); ``conductivity(T)``; ``density(T)`` (kg/m3); ``cp(T)``
    (J/(kg K)); ``partial_pressures()`` -> H2O and CO2 partial pressures (Pa). ``T`` has the
    shape of the cell-mean temperatures (any leading batch axes).
    """

    mass_flux: np.ndarray | float

    def transport(self, T) -> tuple[np.ndarray, np.ndarray]:
        """Conductivity (W/(m K)) and viscosity (Pa s) at ``T`` (K)."""

    def conductivity(self, T) -> np.ndarray:
        """Conductivity at ``T`` (K), W/(m K)."""

    def density(self, T) -> np.ndarray:
        """Density at ``T`` (K), kg/m3."""

    def cp(self, T) -> np.ndarray:
        """Specific heat at ``T`` (K), J/(kg K)."""

    def partial_pressures(self) -> tuple:
        """H2O and CO2 partial pressures, Pa."""


@dataclass(frozen=True)
class TableGas:
    """A gas of fixed composition (:class:`~rotarykiln.materials.gas.GasPropertyTable`).

    ``table``, ``pressure`` (Pa), ``mass_flux`` (kg/(m2 s)).

    Examples
    --------
    >>> from rotarykiln.materials.gas import air_table
    >>> g = TableGas(air_table(), 101325.0, 1.0)
    >>> round(float(g.density(300.0)), 3), g.partial_pressures()
    (1.177, (0.0, 0.0))
    """

    table: GasPropertyTable
    pressure: float
    mass_flux: np.ndarray | float

    def transport(self, T):
        """Conductivity (W/(m K)) and viscosity (Pa s) at ``T`` (K)."""
        return self.table.conductivity(T), self.table.viscosity(T)

    def conductivity(self, T):
        """Conductivity at ``T`` (K), W/(m K)."""
        return self.table.conductivity(T)

    def density(self, T):
        """Density at ``T`` (K) and the gas pressure, kg/m3."""
        return self.table.density(T, self.pressure)

    def cp(self, T):
        """Specific heat at ``T`` (K), J/(kg K)."""
        return self.table.cp(T)

    def partial_pressures(self):
        """H2O and CO2 partial pressures, Pa."""
        return self.table.x_h2o * self.pressure, self.table.x_co2 * self.pressure


@dataclass(frozen=True)
class BulkBed:
    """A bed of constant properties (the reacting kiln's), read like a
    :class:`~rotarykiln.materials.solids.Solid` by :class:`CrossSectionExchange`.

    ``bulk_density`` (kg/m3), ``specific_heat`` (J/(kg K)), ``particle_diameter`` (m),
    ``emissivity`` (-), ``bed_conductivity`` (W/(m K), the given bulk value). Without a solid
    conductivity and void fraction only the ``given`` bed-conductivity closure applies.

    Examples
    --------
    >>> BulkBed(1680.0, 1040.0, 5e-3, 0.95, 0.69).cp(1000.0)
    1040.0
    """

    bulk_density: float
    specific_heat: float
    particle_diameter: float
    emissivity: float
    bed_conductivity: float
    solid_conductivity = None
    void_fraction = None

    def cp(self, T):
        """Specific heat, J/(kg K) (constant)."""
        return self.specific_heat

    def phase_cp(self, T):
        """Specific heat without latent heat, J/(kg K): the same constant."""
        return self.specific_heat


@dataclass(frozen=True)
class CrossSectionExchange:
    """Heat flows per metre between gas, exposed wall, bed and covered wall of every cell.

    The constant parts, built once per solve (:meth:`of` a kiln). ``closures``
    (:class:`~rotarykiln.kiln.inputs.closures.Closures`); ``geometry``: the cell geometry
    (:class:`~rotarykiln.kiln.grid.Grid`: ``fill``, ``full_angle``, ``chord``,
    ``exposed_wall``, ``covered_wall``, ``hydraulic_diameter``, ``beam_length``; arrays over
    cells); ``length``, ``radius`` (m), ``omega`` (rad/s); ``eps_wall`` (-); ``bed``: a
    :class:`~rotarykiln.materials.solids.Solid` or a :class:`BulkBed` (``emissivity``,
    ``bulk_density`` kg/m3, ``cp(T)`` J/(kg K), ``particle_diameter`` m, ``bed_conductivity``
    W/(m K) or None, ``solid_conductivity`` W/(m K) and ``void_fraction`` for the
    bed-conductivity models); ``emissivity_law`` (a, b 1/K, min) for
    :math:`\\varepsilon_g = \\max(a + bT, min)`, which replaces the closure's gas emissivity when
    given; ``soot_fv`` (-, per cell, or None): the soot volume fraction of a luminous flame,
    whose soot emissivity combines with the gas's; ``particle_kappa`` (1/m, per cell, or
    None): the absorption coefficient of a solid fuel's burning particles, a grey absorber
    combined the same way.

    Examples
    --------
    >>> from rotarykiln.kiln.grid import cell_grid
    >>> from rotarykiln.materials.gas import air_table
    >>> g = cell_grid(2.0, 0.1, 4, lambda z: np.full_like(z, 0.15))
    >>> c = Closures(gas_bed="gorog1982", radiation=False)
    >>> ex = CrossSectionExchange(c, g, 2.0, 0.1, 0.16, 0.9,
    ...                           BulkBed(1650.0, 800.0, 7e-4, 0.9, 0.27))
    >>> t = np.full(4, 500.0)
    >>> q, co = ex.flows(TableGas(air_table(), 101325.0, 1.0), t, t - 100.0, t - 50.0)
    >>> round(float(co["h_gb"][0]), 2)  # Gorog: 0.4 (3600 kg/(m2 h))^0.62
    64.12
    >>> round(float(q["q_gas_bed_conv"][0] / (co["h_gb"][0] * g.chord[0] * 100.0)), 12)
    1.0
    """

    closures: Closures
    geometry: object
    length: float
    radius: float
    omega: float
    eps_wall: float
    bed: object
    emissivity_law: tuple[float, float, float] | None = None
    soot_fv: np.ndarray | None = None
    particle_kappa: np.ndarray | None = None

    @classmethod
    def of(cls, kiln, grid, bed, emissivity_law=None) -> CrossSectionExchange:
        """For a kiln model with ``closures``, ``length``, ``radius``, ``omega``, ``eps_wall``
        and ``soot`` (f_v, z_start, z_end) or None: each cell's soot volume fraction is f_v
        times the share of the cell inside the luminous zone; with ``particles`` (z, kappa)
        each cell's particle absorption coefficient is kappa's mean over the cell (trapezoids
        of the table)."""
        soot = kiln.firing.soot
        fv = None
        lo, hi = grid.z_nodes[:-1], grid.z_nodes[1:]
        if soot is not None and soot[0] > 0:
            f_v, z0, z1 = soot
            inside = np.clip(np.minimum(hi, z1) - np.maximum(lo, z0), 0.0, None) / (hi - lo)
            fv = f_v * inside
        kp = None
        if kiln.firing.particles is not None:
            z, kappa = (np.asarray(v, dtype=float) for v in kiln.firing.particles)
            area = np.concatenate([[0.0], np.cumsum(0.5 * (kappa[1:] + kappa[:-1]) * np.diff(z))])
            kp = (np.interp(hi, z, area) - np.interp(lo, z, area)) / (hi - lo)
        return cls(
            kiln.closures,
            grid,
            kiln.drum.length,
            kiln.drum.radius,
            kiln.drum.omega,
            kiln.wall.inner_emissivity,
            bed,
            emissivity_law,
            fv,
            kp,
        )

    def __post_init__(self):
        c, b = self.closures, self.bed
        if not isinstance(c, Closures):
            raise InputError("closures", c, "a Closures object")
        modelled = c.bed_conductivity != "given" or b.bed_conductivity is None
        if modelled and (b.solid_conductivity is None or b.void_fraction is None):
            raise InputError(
                "closures.bed_conductivity",
                c.bed_conductivity,
                "given (with a bulk bed conductivity): this kiln has no solid conductivity "
                "and void fraction for a bed-conductivity model",
            )

    def bed_conductivity_at(self, gas: FreeboardGas, t_film):
        """Bed thermal conductivity (W/(m K)) by the ``bed_conductivity`` closure."""
        c, b = self.closures.bed_conductivity, self.bed
        if c == "given" and b.bed_conductivity is not None:
            k = b.bed_conductivity
        elif c == "maxwell":
            k = maxwell_bed_conductivity(
                gas.conductivity(t_film), b.solid_conductivity, 1.0 - b.void_fraction
            )
        else:
            k = zehner_schlunder_bed_conductivity(
                gas.conductivity(t_film), b.solid_conductivity, b.void_fraction
            )
        if self.closures.bed_radiation:
            k = k + radiative_bed_conductivity(b.particle_diameter, t_film, b.emissivity)
        return k

    def gas_emissivity(self, gas: FreeboardGas, t_gas, check=False):
        """Gas emissivity (-) by the ``gas_emissivity`` closure, combined with the soot of a
        luminous zone (``soot_fv``), capped at 0.95 (the number 0 without radiation, or without
        CO2, H2O and soot)."""
        c = self.closures
        if not c.radiation:
            return 0.0
        eps = self._molecular_emissivity(gas, t_gas, check)
        eps_s = self.soot(t_gas)
        if eps_s is not None:
            eps = combined_emissivity(eps, eps_s)
        return np.minimum(np.maximum(eps, 0.0), EPS_GAS_MAX)  # np.clip without its overhead

    def _molecular_emissivity(self, gas: FreeboardGas, t_gas, check=False):
        """Emissivity (-) of the CO2 and H2O of the gas (or the given law or constant)."""
        c = self.closures
        if self.emissivity_law is not None:
            a, b, lo = self.emissivity_law
            return np.maximum(a + b * t_gas, lo)
        if not isinstance(c.gas_emissivity, str):
            return float(c.gas_emissivity) * np.ones_like(t_gas)
        p_w, p_c = gas.partial_pressures()
        L = self.geometry.beam_length
        p_sum = p_w + p_c
        if p_sum <= 0 if np.ndim(p_sum) == 0 else not (p_sum > 0).any():
            return 0.0  # no CO2 and no H2O: transparent
        if c.gas_emissivity == "johansson2011":
            return johansson_wsgg_emissivity(t_gas, p_w, p_c, L, check=check)
        return smith_wsgg_emissivity(t_gas, (p_w + p_c) * L, "pw/pc=2", check=check)

    def bands(self, gas: FreeboardGas):
        """The grey gases of the WSGG model (:func:`~rotarykiln.heat.gas_radiation.wsgg_bands`)
        for the ``banded`` radiation model, or None (one grey gas: the ``grey`` model, a
        constant or line emissivity, or a gas without CO2 and H2O)."""
        c = self.closures
        if (
            c.radiation_model != "banded"
            or self.emissivity_law is not None
            or not isinstance(c.gas_emissivity, str)
        ):
            return None
        p_w, p_c = gas.partial_pressures()
        p_sum = p_w + p_c
        if not np.any(np.asarray(p_sum) > 0):
            return None
        return wsgg_bands(c.gas_emissivity, p_w, p_c, self.geometry.beam_length)

    def soot(self, t_gas):
        """Grey emissivity (-) per cell of the soot of a luminous zone and the burning
        particles of a solid fuel together, :math:`1 - (1 - \\varepsilon_s)(1 -
        \\varepsilon_p)`, or None without either."""
        L = self.geometry.beam_length
        eps = None
        if self.soot_fv is not None:
            eps = soot_emissivity(self.soot_fv, np.maximum(t_gas, 1.0), L)
        if self.particle_kappa is not None:
            eps_p = particle_cloud_emissivity(self.particle_kappa, L)
            eps = eps_p if eps is None else combined_emissivity(eps, eps_p)
        return eps

    def radiation(self, gas: FreeboardGas, t_gas, t_bed, t_wall, eps_gas=None, paths=False):
        """Net radiation absorbed by the exposed wall and the bed (W/m), by the
        ``radiation_model``: one grey gas of emissivity ``eps_gas`` (computed when not given)
        or the WSGG grey gases. With ``paths``: the three path flows gas -> wall, gas -> bed,
        wall -> bed (direct) instead (W/m, :func:`freeboard_radiation_paths`)."""
        g = self.geometry
        bands = self.bands(gas)
        if bands is None:
            if eps_gas is None:
                eps_gas = self.gas_emissivity(gas, t_gas)
            args = (t_gas, t_wall, t_bed, eps_gas, self.eps_wall, self.bed.emissivity)
            if paths:
                return freeboard_radiation_paths(*args, g.exposed_wall, g.chord)
            return freeboard_radiation(*args, g.exposed_wall, g.chord, check=False)
        soot = self.soot(t_gas)
        if paths:
            if soot is not None:
                raise NotImplementedError("paths of a banded exchange with soot")
            return freeboard_radiation_paths(
                t_gas,
                t_wall,
                t_bed,
                None,
                self.eps_wall,
                self.bed.emissivity,
                g.exposed_wall,
                g.chord,
                bands=bands,
            )
        return freeboard_radiation_bands(
            t_gas,
            t_wall,
            t_bed,
            bands,
            self.eps_wall,
            self.bed.emissivity,
            g.exposed_wall,
            g.chord,
            soot=soot,
            check=False,
        )

    def coefficients(self, gas: FreeboardGas, t_gas, t_bed, t_wall, check=False) -> dict:
        """Heat transfer coefficients (W/(m2 K)), gas emissivity and Reynolds number.

        With ``check`` the closures validate their inputs and warn
        (:class:`~rotarykiln.errors.OutOfRangeWarning`) outside their validated ranges; the
        solvers do this once on the converged state, not inside the Newton loop.
        """
        c, g = self.closures, self.geometry
        tg, tb, tw = t_gas, t_bed, t_wall
        kg, mu = gas.transport(tg)
        De = g.hydraulic_diameter
        re = gas_reynolds(gas.mass_flux, De, mu, check=check)
        if "tscheng1979" in (c.gas_wall, c.gas_bed):
            re_w = rotational_reynolds(gas.density(tg), self.omega, De, mu, check=check)
        if c.gas_wall == "tscheng1979":
            h_gw = tscheng_watkinson_gas_wall_nusselt(re, re_w, check=check) * kg / De
        else:
            pr = gas.cp(tg) * mu / kg
            h_gw = gorog_gas_wall_h(kg, De, re, pr, self.length, check=check)
        if c.gas_bed == "tscheng1979":
            h_gb = tscheng_watkinson_gas_bed_nusselt(re, re_w, g.fill, check=check) * kg / De
        else:
            h_gb = gorog_gas_bed_h(gas.mass_flux, check=check) * np.ones_like(tg)
        if c.convection_factor != 1.0:
            h_gw = c.convection_factor * h_gw
            h_gb = c.convection_factor * h_gb
        t_film = 0.5 * (tw + tb)
        kb = self.bed_conductivity_at(gas, t_film)
        rho_c = self.bed.bulk_density * self.bed.phase_cp(tb)
        if c.covered_wall == "li2005":
            h_cw = li_covered_wall_h(
                gas.conductivity(t_film),
                self.bed.particle_diameter,
                kb,
                rho_c,
                self.omega,
                g.full_angle,
                check=check,
            )
        elif c.covered_wall == "tscheng1979":
            h_cw = tscheng_covered_wall_h(
                kb, rho_c, self.omega, self.radius, g.full_angle, check=check
            )
        else:
            h_cw = wachters_kramers_covered_wall_h(kb, rho_c, self.omega, g.full_angle, check=check)
        eps = self.gas_emissivity(gas, tg, check=check)
        if np.shape(h_cw) != np.shape(tg):
            h_cw = h_cw * np.ones_like(tg)
        return {
            "h_gw": h_gw,
            "h_gb": h_gb,
            "h_cw": h_cw,
            "eps_gas": eps,
            "Re": re,
        }

    def flows(self, gas: FreeboardGas, t_gas, t_bed, t_wall, radiation_scale=1.0, co=None):
        """Heat flows per metre (W/m, keys :data:`FLOW_KEYS`) and the coefficients.

        ``q_gas_wall_conv`` gas -> exposed wall, ``q_gas_bed_conv`` gas -> bed surface,
        ``q_covered_wall_bed`` covered wall -> bed, ``q_rad_to_wall`` and ``q_rad_to_bed``
        net radiation absorbed by the exposed wall and the bed (their sum is the gas's loss),
        scaled by ``radiation_scale`` (continuation). ``co``: the coefficients when already
        computed (:meth:`coefficients`), else computed at these temperatures.
        """
        g = self.geometry
        tg, tb, tw = t_gas, t_bed, t_wall
        if co is None:
            co = self.coefficients(gas, tg, tb, tw)
        q_gw = co["h_gw"] * g.exposed_wall * (tg - tw)
        q_gb = co["h_gb"] * g.chord * (tg - tb)
        q_cw = co["h_cw"] * g.covered_wall * (tw - tb)
        c = self.closures
        if not (c.near_bed_mixing is not None or c.exposed_bed_penetration):
            if c.radiation:
                q_rw, q_rb = self.radiation(gas, tg, tb, tw, co["eps_gas"])
                q_rw = radiation_scale * q_rw
                q_rb = radiation_scale * q_rb
            else:
                q_rw = q_rb = 0.0 * tg
            flows = dict(zip(FLOW_KEYS, (q_gw, q_gb, q_cw, q_rw, q_rb), strict=True))
            return flows, co
        # the paths into the bed surface, scaled by the resistances in series
        if c.radiation:
            p_gw, p_gb, p_wb = (
                radiation_scale * p
                for p in self.radiation(gas, tg, tb, tw, co["eps_gas"], paths=True)
            )
        else:
            p_gw = p_gb = p_wb = 0.0 * tg
        sigma = 5.670374419e-8
        if c.near_bed_mixing is not None:
            # layered freeboard: core -> near-bed gas (h_m) in series with near-bed gas ->
            # bed (convection + gas radiation, linearised)
            dt = tg - tb
            safe = np.where(np.abs(dt) > 1e-3, dt, 1e-3)
            h_rad = np.where(np.abs(dt) > 1e-3, p_gb / (g.chord * safe), 0.0)
            h_b = np.maximum(co["h_gb"] + np.maximum(h_rad, 0.0), 1e-9)
            layer = c.near_bed_mixing / (c.near_bed_mixing + h_b)
            q_gb = layer * q_gb
            p_gb = layer * p_gb
        if c.exposed_bed_penetration:
            # the exposed surface's heat penetrates the bed over its circulation time
            kb = self.bed_conductivity_at(gas, tb)
            rho_c = self.bed.bulk_density * self.bed.phase_cp(tb)
            h_pen = wachters_kramers_covered_wall_h(kb, rho_c, self.omega, g.full_angle)
            h_in = co["h_gb"] + 4.0 * sigma * self.bed.emissivity * tb**3
            share = h_pen / (h_pen + h_in)
            q_gb, p_gb, p_wb = share * q_gb, share * p_gb, share * p_wb
        q_rw, q_rb = p_gw - p_wb, p_gb + p_wb
        flows = dict(zip(FLOW_KEYS, (q_gw, q_gb, q_cw, q_rw, q_rb), strict=True))
        return flows, co


def gas_conductance(co: dict, geometry, t_max, radiation_scale=1.0):
    r"""Upper bound of the gas's heat conductance to its surroundings, W/(m K) per metre.

    Convection to the exposed wall and the bed surface plus radiation bounded by
    :math:`4\sigma\varepsilon_g T_{max}^3 (A_w + L_c)`: a grey gas exchanges at most
    :math:`\varepsilon_g\sigma(T_g^4 - T_s^4)` per unit area with the surfaces it sees, and
    the secant of :math:`\sigma(T_g^4 - T_s^4)` never exceeds :math:`4\sigma T_{max}^3`. The
    number of transfer units of a cell (:func:`upwind_weight`) is this times the cell length
    over the gas's heat capacity flow.

    Parameters
    ----------
    co : dict
        The coefficients of :meth:`CrossSectionExchange.coefficients`: ``h_gw``, ``h_gb``
        (W/(m2 K)) and ``eps_gas`` (-), per cell.
    geometry : Grid
        Cell geometry: ``exposed_wall`` and ``chord`` (m2/m, per cell).
    t_max : float or array, K
        The highest temperature of the gas and its surroundings in the cell.
    radiation_scale : float, -
        Factor on the radiation (the continuation's ramp; 1: full radiation).

    Returns
    -------
    float or array, W/(m K)
        Per metre of kiln, per cell.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> geometry = SimpleNamespace(exposed_wall=1.0, chord=0.5)
    >>> co = {"h_gw": 10.0, "h_gb": 20.0, "eps_gas": 0.2}
    >>> round(float(gas_conductance(co, geometry, 1000.0)), 2)  # 20 convection + 68.04 radiation
    88.04

    References
    ----------
    H.C. Hottel, A.F. Sarofim, Radiative Transfer, McGraw-Hill (1967) (exchange of a grey gas
    with its enclosure).
    """
    g = geometry
    k = co["h_gw"] * g.exposed_wall + co["h_gb"] * g.chord
    eps = np.asarray(co["eps_gas"], dtype=float)
    sigma = 5.670374419e-8
    return k + radiation_scale * 4.0 * sigma * eps * t_max**3 * (g.exposed_wall + g.chord)


def upwind_weight(ntu):
    r"""Weight :math:`\theta` of a cell's outlet face in its mean temperature,
    :math:`\bar T = (1-\theta) T_{in} + \theta T_{out}`, for a cell of ``ntu`` transfer units.

    A stream exchanging with surroundings at :math:`T_\infty` leaves a cell at
    :math:`T_{out} - T_{in} = N (T_\infty - T_{in}) / (1 + N\theta)`: it never overshoots
    :math:`T_\infty` when :math:`N(1-\theta) \le 1`. The face average (:math:`\theta = 1/2`,
    second order) holds that up to 2 transfer units per cell and is kept exactly up to 1; from 2
    on, the weight is the exact one of an exponential approach,
    :math:`\theta_e = 1/(1 - e^{-N}) - 1/N` (tending to the outlet face: bounded for any cell
    size), joined smoothly (a cubic step) between 1 and 2. Without it a cell of many transfer
    units (a large drum swept by a little gas) lets its outlet face overshoot the wall and bed it
    exchanges with, and the faces oscillate from cell to cell.

    Parameters
    ----------
    ntu : float or array, -
        Number of transfer units of the cell: its conductance to the surroundings times its
        length over the stream's heat capacity flow (:func:`gas_conductance`).

    Returns
    -------
    float or array, -
        Weight :math:`\theta` of the outlet face, in [0.5, 1).

    Examples
    --------
    >>> [round(float(upwind_weight(n)), 4) for n in (0.0, 1.0, 2.0, 50.0)]
    [0.5, 0.5, 0.6565, 0.98]

    References
    ----------
    S.V. Patankar, Numerical Heat Transfer and Fluid Flow, Hemisphere (1980), ch. 5 (the
    exponential scheme); F.P. Incropera et al., Fundamentals of Heat and Mass Transfer, 6th ed.
    (2007), section 8.3 (a stream at constant surface temperature: exponential approach).
    """
    n = np.maximum(np.asarray(ntu, dtype=float), 0.0)
    safe = np.maximum(n, 1.0)
    exact = -1.0 / np.expm1(-safe) - 1.0 / safe
    t = np.minimum(np.maximum(n - 1.0, 0.0), 1.0)  # np.clip without its overhead
    return 0.5 + (exact - 0.5) * t * t * (3.0 - 2.0 * t)


def cell_report(t_bed, t_gas, flows: dict, q_loss, coefficients: dict, **sources) -> dict:
    """The per-cell dict a kiln residual reports: cell-mean temperatures (``t_bed_mean``,
    ``t_gas_mean``, K), the exchange ``flows`` and the shell loss ``q_shell_loss`` (W/m), the
    model's own ``sources`` (W/m), then the ``coefficients``."""
    return {
        "t_bed_mean": t_bed,
        "t_gas_mean": t_gas,
        **flows,
        "q_shell_loss": q_loss,
        **sources,
        **coefficients,
    }
