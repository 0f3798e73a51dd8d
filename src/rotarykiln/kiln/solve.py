"""Solve the steady kiln heat balances at once by Newton (see :mod:`.discretisation`)."""

from __future__ import annotations

import warnings

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.kiln import steady
from rotarykiln.kiln.discretisation import build_grid
from rotarykiln.kiln.model import HeatKiln
from rotarykiln.kiln.residual import HeatResidual
from rotarykiln.kiln.solution import KilnSolution
from rotarykiln.kiln.sources import SourceTerms

__all__ = ["solve_heat", "energy_sheet", "DEFAULT_CELLS"]

DEFAULT_CELLS = 100


def _hot_temperature(kiln: HeatKiln) -> float:
    """Temperature the gas would reach with all the heat release (for the initial guess)."""
    if kiln.heat_release <= 0:
        return kiln.gas_inlet_temperature
    target = kiln.gas.enthalpy(kiln.gas_inlet_temperature) + kiln.heat_release / kiln.gas_flow
    t = np.linspace(200.0, 3200.0, 601)
    return float(np.interp(target, kiln.gas.enthalpy(t), t))


def _initial_guess(kiln: HeatKiln, res: HeatResidual) -> np.ndarray:
    g = res.grid
    t_b, t_g, t_wall = steady.initial_temperatures(
        g.z_nodes,
        kiln.solids_inlet_temperature,
        _hot_temperature(kiln),
        res.wall,
        kiln.counter_current,
    )
    x = np.empty((g.n, res.nv))
    x[:, 0] = t_b
    x[:, 1] = t_g
    x[:, 2 : 3 + res.n_layers] = t_wall
    if res.n_extra:
        x[:, 3 + res.n_layers :] = np.asarray(res.sources.initial_extra(g.z), dtype=float).reshape(
            g.n, res.n_extra
        )
    return x


def energy_sheet(kiln: HeatKiln, tb_nodes, t_g_in, t_g_out, shell_loss, release) -> dict:
    """Energy balance sheet of a converged heat solve, W (and the efficiency, -).

    Inputs: the fuel (its LHV and, for information, its HHV), the sensible enthalpy of the
    gas and solids streams above 298.15 K, the heat of combustion as the model releases it
    (``combustion_heat_W``; it differs from the LHV input only by the dissociation of the
    products and the heat capacity of preheated streams); outputs: heat to the solids, shell
    loss, exhaust (sensible enthalpy of the flue gas leaving); ``closure_W`` = in - out.
    ``thermal_efficiency`` = heat to the solids / fuel LHV input (heat to the solids / heat
    given up by the gas for a kiln without a burner).
    """
    h_s, h_g = kiln.solid.enthalpy, kiln.gas.enthalpy
    m_s, m_g = kiln.solids_flow, kiln.gas_flow
    solids_in = m_s * float(h_s(tb_nodes[0]))
    to_solids = m_s * float(h_s(tb_nodes[-1]) - h_s(tb_nodes[0]))
    exhaust = m_g * float(h_g(t_g_out))
    flame = kiln.flame
    if flame is not None:
        gas_in = float(flame.sensible_input)
        combustion = float(flame.products.heat_release)
        lhv, hhv = float(flame.fuel_lhv), float(flame.fuel_hhv)
        efficiency = to_solids / lhv
    else:
        gas_in = m_g * float(h_g(t_g_in))
        combustion, lhv, hhv = float(release), 0.0, 0.0
        supplied = gas_in - exhaust + combustion
        efficiency = to_solids / supplied if supplied else float("nan")
    if flame is not None and flame.combustion != "instant":
        combustion = float(release)
    total_in = solids_in + gas_in + combustion
    total_out = solids_in + to_solids + shell_loss + exhaust
    return {
        "fuel_lhv_input_W": lhv,
        "fuel_hhv_input_W": hhv,
        "combustion_heat_W": combustion,
        "sensible_input_gas_W": gas_in,
        "sensible_input_solids_W": solids_in,
        "heat_to_solids_sensible_W": to_solids,
        "heat_to_solids_reaction_W": 0.0,
        "shell_loss_W": float(shell_loss),
        "exhaust_loss_W": exhaust,
        "closure_W": total_in - total_out,
        "closure_relative": (total_in - total_out) / max(total_in, 1.0),
        "thermal_efficiency": efficiency,
    }


def solve_heat(
    kiln: HeatKiln,
    n_cells: int = DEFAULT_CELLS,
    *,
    sources: SourceTerms | None = None,
    tol: float = 1e-11,
    max_iter: int = 60,
    initial: np.ndarray | None = None,
) -> KilnSolution:
    """Solve the steady heat balances of ``kiln`` on ``n_cells`` finite volumes.

    Parameters
    ----------
    kiln : HeatKiln
        Inputs (SI).
    n_cells : int
        Number of equal cells (default 100).
    sources : SourceTerms, optional
        Per-cell heat release and extra unknowns (reactions); see :mod:`.sources`.
    tol : float
        Newton tolerance on ``max|residual| / Q_ref`` with ``Q_ref`` the larger of the enthalpy
        spans of gas and solids plus the heat release (W).
    max_iter : int
    initial : array (n_cells, nv), optional
        Initial guess of the unknowns (e.g. a neighbouring solution).

    Returns
    -------
    KilnSolution

    Raises
    ------
    ConvergenceError
        When Newton fails, also after continuation in radiation and heat release; the
        message names the cell (z) and the equation with the largest residual.
    """
    if sources is not None and not isinstance(sources, SourceTerms):
        raise InputError("sources", type(sources).__name__, "a SourceTerms object")
    grid = build_grid(kiln, n_cells)
    res = HeatResidual(kiln, grid, sources)
    t_hot = _hot_temperature(kiln)
    tf = kiln.solids_inlet_temperature
    span_g = kiln.gas_flow * abs(kiln.gas.enthalpy(t_hot) - kiln.gas.enthalpy(tf))
    span_s = kiln.solids_flow * abs(kiln.solid.enthalpy(t_hot) - kiln.solid.enthalpy(tf))
    q_ref = float(max(span_g, span_s, 1.0))
    res.extra_scale = q_ref
    nl = res.n_layers
    extra = [f"source unknown {i}" for i in range(res.n_extra)]
    where = steady.locator(grid.z, steady.equation_names(res.wall, extra))

    def set_homotopy(lam):
        res.homotopy = lam

    # continuation if Newton fails: radiation and heat release ramped from 0 to 1
    x0 = _initial_guess(kiln, res) if initial is None else np.array(initial, dtype=float)
    kwargs = dict(tol=tol, max_iter=max_iter, temperature_vars=3 + nl, where=where)
    x, total_iter = steady.newton_with_continuation(
        res, x0, q_ref, steady.ramp(set_homotopy), **kwargs
    )
    res.homotopy = 1.0
    R, fl = res.evaluate(x, full=True)
    tb_nodes, tg_nodes = res.unpack(x)
    fluxes = {k: np.array(v, dtype=float) * np.ones(grid.n) for k, v in fl.items()}
    steady.check_finite(
        {"T_bed": tb_nodes, "T_gas": tg_nodes, "T_wall": x[:, 2 : 3 + nl]},
        fluxes,
        grid.z,
        total_iter,
    )
    h_s = kiln.solid.enthalpy
    h_g = kiln.gas.enthalpy
    t_g_in = kiln.gas_inlet_temperature
    t_g_out = tg_nodes[0] if kiln.counter_current else tg_nodes[-1]
    heat_to_solids = kiln.solids_flow * float(h_s(tb_nodes[-1]) - h_s(tb_nodes[0]))
    heat_from_gas = kiln.gas_flow * float(h_g(t_g_in) - h_g(t_g_out))
    dz = grid.dz
    shell_loss = float(np.sum(fl["q_shell_loss"]) * dz)
    src_bed = float(np.sum(fl["q_source_bed"]) * dz)
    src_gas = float(np.sum(fl["q_source_gas"]) * dz)
    release = src_bed + src_gas
    e_in = kiln.solids_flow * float(h_s(tb_nodes[0])) + kiln.gas_flow * float(h_g(t_g_in))
    e_in += release
    e_out = kiln.solids_flow * float(h_s(tb_nodes[-1])) + kiln.gas_flow * float(h_g(t_g_out))
    e_out += shell_loss
    denom = heat_to_solids if abs(heat_to_solids) > 0 else q_ref
    closure = (e_in - e_out) / denom
    sheet = energy_sheet(kiln, tb_nodes, t_g_in, t_g_out, shell_loss, release)
    if abs(closure) > 1e-6:
        warnings.warn(
            f"energy balance closes only to {closure:.3g} of the heat to the solids",
            RuntimeWarning,
            stacklevel=2,
        )
    # validity ranges of the closures, checked once on the converged state
    res.coefficients(fluxes["t_gas_mean"], fluxes["t_bed_mean"], x[:, 2], check=True)
    kiln.solid.check_range(tb_nodes)  # the solid's c_p fit (phases, ranges in solids.yaml)
    return KilnSolution(
        name=kiln.name,
        **steady.profile_fields(
            grid, tb_nodes, tg_nodes, x[:, 2 : 3 + nl], fluxes, R, q_ref, total_iter
        ),
        t_shell=x[:, 2 + nl].copy(),
        fill=grid.fill,
        extra=x[:, 3 + nl :].copy(),
        heat_to_solids=heat_to_solids,
        heat_from_gas=heat_from_gas,
        heat_release=release,
        shell_loss=shell_loss,
        energy_in=e_in,
        energy_out=e_out,
        balance_closure=float(closure),
        energy_sheet=sheet,
        n_cells=grid.n,
        counter_current=kiln.counter_current,
        measurements=kiln.measurements,
        burner=kiln.flame.summary() if kiln.flame is not None else {},
    )
