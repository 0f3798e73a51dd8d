r"""A heating jacket: a hot gas flowing along the shell in an annulus, with its own energy balance.

Indirectly heated kilns (biomass and plastics pyrolysis, activated carbon, calciners) are heated
through the drum wall by flue gas in a jacket around it. The jacket gas flows co-current with
the solids (entering at the feed end, z = 0) or counter-current (entering at z = L). Per metre
of kiln, with :math:`T_j` the jacket gas, :math:`T_w` the drum wall and
:math:`Q_{in} = Q_{gw} + Q_{rw} - Q_{cw}` the heat the inner wall receives from the freeboard and
the bed (negative when the wall heats them):

.. math::
    0 = U_{jw} P_w (\bar T_j - T_w) + Q_{in}

    0 = \pm\frac{\dot m_j\,[h_j(T_{j,out}) - h_j(T_{j,in})]}{\Delta z}
        + U_{jw} P_w (\bar T_j - T_w) + U_{c} P_c (\bar T_j - T_a)

with :math:`\bar T_j` the cell mean of the jacket gas, :math:`P_w = 2\pi R` the drum perimeter,
:math:`U_{c} P_c` the loss of the jacket casing to ambient, and :math:`U_{jw}` the jacket gas to
wall coefficient: given, or from the annulus closure: forced convection in the annular gap
(:func:`~rotarykiln.heat.jacket.annulus_heat_transfer_coefficient`, Gnielinski 2009 with the
laminar limit of Shah & London), the radiation of the gas and of the re-radiating casing
(:func:`~rotarykiln.heat.jacket.jacket_radiation_conductance`), and the drum wall's
conduction. ``htc="wall_at_gas"`` is the rotaryPyrolysis assumption: no resistance at all, the
wall at the jacket gas temperature (:math:`T_w = \bar T_j`), which overstates the heat input.

The jacket is a wall model (:mod:`rotarykiln.kiln.wall.lining`): two temperatures per cell, the inner
wall and the jacket gas at the cell's jacket outlet face, closed by the two rows above; the
jacket enthalpy given up in each cell is reported as the kiln's heating (W/m,
``q_electric_heating`` of the profiles: the energy sheet's ``electric_heating_W`` is then the
jacket duty) and the casing loss as the shell loss, so the kiln's energy balance closes over
the jacket too. A kiln is heated by a jacket when its wall branch holds one
(``Kiln.wall.jacket``, :class:`~rotarykiln.kiln.inputs.kiln.Wall`).

References
----------
V. Gnielinski, Int. J. Heat Mass Transfer 52 (2009) 4447-4456 (turbulent annuli) and VDI Heat
Atlas, 2nd ed. (2010) G2 (laminar and transition); R.K. Shah, A.L. London, Laminar Flow Forced
Convection in Ducts (1978) (fully developed laminar annulus); M. Pichler et al., J. Anal. Appl.
Pyrolysis 158 (2021) 105171 (the co-current flue-gas jacket with the wall at its temperature).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import InputError, check_nonnegative, check_positive
from rotarykiln.heat.jacket import annulus_heat_transfer_coefficient, jacket_radiation_conductance

__all__ = ["Jacket", "JacketWall", "jacket_balance"]

T_REF = 298.15


@dataclass(frozen=True)
class Jacket:
    """A heating jacket around the drum (SI units).

    ``mass_flow`` (kg/s) of jacket gas entering at ``inlet_temperature`` (K), co-current with
    the solids (``counter_current=False``: enters at z = 0) or not; its specific heat ``cp``
    (J/(kg K), constant, the rotaryPyrolysis choice) or, with ``composition`` (mole fractions,
    e.g. ``"N2:0.72, CO2:0.09, H2O:0.17, O2:0.02"``), its enthalpy from the gas tables.
    ``htc``: the jacket gas to drum coefficient, W/(m2 K) on the drum perimeter; ``"annulus"``
    (default) for :func:`~rotarykiln.heat.jacket.annulus_heat_transfer_coefficient` with
    ``gap`` (m) and the drum wall
    conduction (``wall_thickness`` m, ``wall_conductivity`` W/(m K)), plus with ``radiation``
    (default True) the radiation of the gas (WSGG of Johansson et al. 2011 when a
    ``composition`` gives its H2O and CO2) and of the re-radiating casing
    (:func:`~rotarykiln.heat.jacket.jacket_radiation_conductance`, emissivities ``eps_drum``
    and ``eps_casing``);
    ``"wall_at_gas"`` for no resistance (the wall at the jacket gas temperature,
    rotaryPyrolysis). Casing loss
    ``casing_u`` (W/(m2 K)) on ``casing_perimeter`` (m; default the drum perimeter, as the
    rotaryPyrolysis script) to the kiln's ambient temperature.

    Examples
    --------
    >>> j = Jacket(175 / 3600, 833.15, cp=1226.9, htc="wall_at_gas", casing_u=2.5)
    >>> round(float(j.enthalpy(833.15)) / 1e3, 1)   # kJ/kg above 298.15 K
    656.4
    """

    mass_flow: float
    inlet_temperature: float
    cp: float | None = None
    composition: str | None = None
    counter_current: bool = False
    htc: float | str = "annulus"
    gap: float = 0.05
    wall_thickness: float = 0.005
    wall_conductivity: float = 45.0
    casing_u: float = 0.0
    casing_perimeter: float | None = None
    radiation: bool = True
    eps_drum: float = 0.8
    eps_casing: float = 0.8
    pressure: float = 101325.0

    def __post_init__(self):
        check_positive("jacket.mass_flow", self.mass_flow, "kg/s")
        check_positive("jacket.inlet_temperature", self.inlet_temperature, "K")
        if (self.cp is None) == (self.composition is None):
            raise InputError("jacket.cp", self.cp, "given, or a composition instead (not both)")
        if self.cp is not None:
            check_positive("jacket.cp", self.cp, "J/(kg K)")
        if isinstance(self.htc, str):
            if self.htc not in ("annulus", "wall_at_gas"):
                raise InputError(
                    "jacket.htc", self.htc, "a number (W/(m2 K)), annulus or wall_at_gas"
                )
        else:
            check_positive("jacket.htc", self.htc, "W/(m2 K)")
        check_positive("jacket.gap", self.gap, "m")
        check_nonnegative("jacket.wall_thickness", self.wall_thickness, "m")
        check_positive("jacket.wall_conductivity", self.wall_conductivity, "W/(m K)")
        check_nonnegative("jacket.casing_u", self.casing_u, "W/(m2 K)")
        if self.casing_perimeter is not None:
            check_positive("jacket.casing_perimeter", self.casing_perimeter, "m")
        for name in ("eps_drum", "eps_casing"):
            v = getattr(self, name)
            if not (np.isfinite(v) and 0.0 < v <= 1.0):
                raise InputError(f"jacket.{name}", v, "in (0, 1]")

    def _table(self):
        from rotarykiln.materials.gas import gas_table

        return gas_table(self.composition)

    def enthalpy(self, T):
        """Sensible enthalpy of the jacket gas above 298.15 K, J/kg."""
        T = np.asarray(T, dtype=float)
        if self.cp is not None:
            return self.cp * (T - T_REF)
        tab = self._table()
        return tab.enthalpy(T) - tab.enthalpy(T_REF)

    def wall(self, kiln, grid) -> JacketWall:
        """The wall model of this jacket on a kiln's ``grid`` (used by the kiln residual)."""
        R = kiln.drum.radius
        p_w = 2.0 * np.pi * R
        if self.htc == "wall_at_gas":
            u = None
        elif self.htc == "annulus":
            u = "annulus"
        else:
            u = float(self.htc)
        return JacketWall(
            self,
            p_w,
            self.casing_perimeter or p_w,
            kiln.wall.ambient_temperature,
            grid.dz,
            u,
            2.0 * (R + self.wall_thickness),
        )


@dataclass(frozen=True)
class JacketWall:
    """Wall model of a jacketed drum: inner wall and jacket gas temperature per cell.

    ``jacket``, ``perimeter`` (m, drum), ``casing_perimeter`` (m), ``ambient_temperature`` (K),
    ``dz`` (m), ``u``: jacket to wall coefficient (W/(m2 K)), ``"annulus"``, or None (wall at
    the jacket gas temperature), ``outer_diameter`` (m, of the drum wall).
    """

    jacket: Jacket
    perimeter: float
    casing_perimeter: float
    ambient_temperature: float
    dz: float
    u: float | str | None
    outer_diameter: float

    n_temperatures = 2
    #: which wall temperatures act on their own cell's balances only (the inner wall; the
    #: jacket gas flows along the drum)
    local = (True, False)
    #: conductance (W/(m2 K)) of the row holding the wall at the jacket temperature
    TIE = 100.0

    def labels(self) -> list[str]:
        """Name of each wall balance (inner wall, jacket gas)."""
        return ["inner wall", "jacket gas"]

    def faces(self, tj):
        """Jacket gas temperatures at the faces (K, ``(..., n + 1)``)."""
        j = self.jacket
        t_in = np.broadcast_to(j.inlet_temperature, tj.shape[:-1] + (1,))
        parts = [tj, t_in] if j.counter_current else [t_in, tj]
        return np.concatenate(parts, axis=-1)

    def coefficient(self, t_mean, t_wall=None):
        """Jacket gas to inner wall coefficient, W/(m2 K) on the drum's inner perimeter.

        ``annulus``: convection on the drum's outer surface, in parallel with the gas radiation
        and with the casing path (convection to the casing in series with its re-radiation),
        then in series with the drum wall's conduction; ``t_wall`` (K) the drum temperature
        for the linearised radiation (default: the gas temperature less 50 K)."""
        j = self.jacket
        if self.u == "annulus":
            d_o = self.outer_diameter
            h = annulus_heat_transfer_coefficient(j.mass_flow, d_o, j.gap, t_mean, check=False)
            p_o = np.pi * d_o
            g = h * p_o  # W/(m K), convection to the drum
            if j.radiation:
                td = t_mean - 50.0 if t_wall is None else t_wall
                eps_g = self._gas_emissivity(t_mean)
                g_gas, g_cas = jacket_radiation_conductance(
                    t_mean,
                    td,
                    d_o,
                    j.gap,
                    eps_drum=j.eps_drum,
                    eps_casing=j.eps_casing,
                    eps_gas=eps_g,
                )
                p_c = np.pi * (d_o + 2.0 * j.gap)
                g = g + g_gas + 1.0 / (1.0 / (h * p_c) + 1.0 / g_cas)
            r_wall = 0.0
            if j.wall_thickness > 0:
                d_i = self.perimeter / np.pi
                r_wall = np.log(d_o / d_i) / (2.0 * np.pi * j.wall_conductivity)
            return 1.0 / (self.perimeter * (1.0 / g + r_wall))
        return self.u

    def _gas_emissivity(self, t_gas):
        """Grey emissivity of the jacket gas over the beam length 1.8 gap (0 without a
        composition)."""
        j = self.jacket
        if j.composition is None:
            return 0.0
        from rotarykiln.heat.gas_radiation import johansson_wsgg_emissivity

        tab = j._table()
        p_w, p_c = tab.x_h2o * j.pressure, tab.x_co2 * j.pressure
        if p_w + p_c <= 0:
            return 0.0
        return johansson_wsgg_emissivity(
            np.maximum(t_gas, 500.0), p_w, p_c, 1.8 * j.gap, check=False
        )

    def _terms(self, q_in, t_wall):
        j = self.jacket
        tf = self.faces(t_wall[..., 1])
        tj = 0.5 * (tf[..., 1:] + tf[..., :-1])
        hf = j.enthalpy(tf)
        drop = hf[..., :-1] - hf[..., 1:]  # downstream minus upstream, co-current
        if j.counter_current:
            drop = -drop
        duty = j.mass_flow * drop / self.dz  # W/m given up by the jacket gas in the cell
        casing = j.casing_u * self.casing_perimeter * (tj - self.ambient_temperature)
        if self.u is None:
            q_jw = -q_in  # all the wall passes on comes from the jacket
            wall_row = self.TIE * self.perimeter * (t_wall[..., 0] - tj)
        else:
            q_jw = self.coefficient(tj, t_wall[..., 0]) * self.perimeter * (tj - t_wall[..., 0])
            wall_row = q_jw + q_in
        return wall_row, duty, q_jw, casing

    def balance(self, q_in, t_wall):
        """Rows (W/m): inner wall, jacket gas; and the casing loss (W/m)."""
        wall_row, duty, q_jw, casing = self._terms(q_in, t_wall)
        return [wall_row, duty - q_jw - casing], casing

    def heating(self, t_wall):
        """Heat given up by the jacket gas per metre of each cell (W/m): the kiln's heating."""
        tf = self.faces(np.asarray(t_wall, dtype=float)[..., 1])
        hf = self.jacket.enthalpy(tf)
        drop = hf[..., :-1] - hf[..., 1:]
        if self.jacket.counter_current:
            drop = -drop
        return self.jacket.mass_flow * drop / self.dz

    def initial_guess(self, t_wall):
        """Inner wall and jacket gas guesses, K: the jacket from its inlet temperature cooling
        by a third of its span to the kiln towards its outlet."""
        t_wall = np.asarray(t_wall, dtype=float)
        n = t_wall.shape[-1]
        j = self.jacket
        zeta = (np.arange(n) + 1.0) / n
        if j.counter_current:
            zeta = 1.0 - np.arange(n) / n
        tj = j.inlet_temperature - (j.inlet_temperature - t_wall) * 0.35 * zeta
        tw = 0.5 * (tj + t_wall) if self.u is not None else tj
        return np.stack([tw, tj], axis=-1)


def jacket_balance(kiln, solution) -> dict:
    r"""Energy balance of the jacket gas of a solved kiln heated by a jacket, W.

    The jacket duty :math:`\dot m_j [h_j(T_{in}) - h_j(T_{out})]` against what the jacket gas
    gave to the drum and lost through the casing (sums over the cells of the converged state):
    the balance closes to the solver tolerance.

    Parameters
    ----------
    kiln : Kiln
        A kiln heated by a jacket (``kiln.wall.jacket``).
    solution : KilnSolution
        Its steady solution (:func:`~rotarykiln.kiln.steady.solve.solve_kiln`).

    Returns
    -------
    dict
        ``duty_W``, ``to_drum_W``, ``casing_loss_W`` (W), ``outlet_temperature_K`` (K) and
        ``closure_relative`` (-, ``(duty - to_drum - casing) / duty``).

    Examples
    --------
    The rotaryPyrolysis kiln (built-in case ``rotary_pyrolysis``), plug flow, 10 cells:

    >>> import warnings
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> from rotarykiln.kiln.from_case import kiln_from_case
    >>> from rotarykiln.kiln.steady.solve import solve_kiln
    >>> case = load_case(builtin_case_path("rotary_pyrolysis"))
    >>> kiln, _ = kiln_from_case(case.replace({"bed.axial_dispersion": "plug"}))
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     jb = jacket_balance(kiln, solve_kiln(kiln, 10))
    >>> round(jb["duty_W"] / 1e3, 1), abs(jb["closure_relative"]) < 1e-9
    (9.2, True)

    References
    ----------
    M. Pichler et al., J. Anal. Appl. Pyrolysis 158 (2021) 105171 (the flue-gas jacket of the
    rotaryPyrolysis kiln).
    """
    x = solution.fluxes["x"]
    j = kiln.wall.jacket
    from rotarykiln.kiln.residual import KilnResidual

    res = KilnResidual(kiln, x.shape[0])
    wall = res.wall
    tl = x[:, 2 : 2 + wall.n_temperatures]
    # q_in of the converged state: recompute through the residual's exchange
    _, fl, *_ = res.evaluate(x[None], full=True)
    q_in = (fl["q_gas_wall_conv"] + fl["q_rad_to_wall"] - fl["q_covered_wall_bed"])[0]
    _, duty, q_jw, casing = wall._terms(q_in, tl)
    tf = wall.faces(tl[:, 1])
    t_out = tf[0] if j.counter_current else tf[-1]
    total = float(j.mass_flow * (j.enthalpy(j.inlet_temperature) - j.enthalpy(t_out)))
    to_drum = float(np.sum(q_jw) * wall.dz)
    loss = float(np.sum(casing) * wall.dz)
    return {
        "duty_W": total,
        "to_drum_W": to_drum,
        "casing_loss_W": loss,
        "outlet_temperature_K": float(t_out),
        "closure_relative": (total - to_drum - loss) / max(abs(total), 1e-300),
    }
