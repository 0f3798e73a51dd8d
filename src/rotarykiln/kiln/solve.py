"""Solve the steady kiln heat balances at once by Newton (see :mod:`.discretisation`)."""

from __future__ import annotations

import warnings

import numpy as np

from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.kiln.discretisation import build_grid
from rotarykiln.kiln.model import HeatKiln
from rotarykiln.kiln.newton import newton_banded
from rotarykiln.kiln.residual import HeatResidual
from rotarykiln.kiln.solution import KilnSolution
from rotarykiln.kiln.sources import SourceTerms

__all__ = ["solve_heat", "DEFAULT_CELLS"]

DEFAULT_CELLS = 100
_EQ = ("bed energy", "gas energy", "inner wall")


def _hot_temperature(kiln: HeatKiln) -> float:
    """Temperature the gas would reach with all the heat release (for the initial guess)."""
    if kiln.heat_release <= 0:
        return kiln.gas_inlet_temperature
    target = kiln.gas.enthalpy(kiln.gas_inlet_temperature) + kiln.heat_release / kiln.gas_flow
    t = np.linspace(200.0, 3200.0, 601)
    return float(np.interp(target, kiln.gas.enthalpy(t), t))


def _initial_guess(kiln: HeatKiln, res: HeatResidual) -> np.ndarray:
    g = res.grid
    n = g.n
    zeta = g.z_nodes[1:] / kiln.length  # bed faces 1..n
    t_hot = _hot_temperature(kiln)
    tf = kiln.solids_inlet_temperature
    t_b = tf + 0.6 * (t_hot - tf) * zeta
    if kiln.counter_current:
        zg = g.z_nodes[:-1] / kiln.length  # gas unknowns at faces 0..n-1
        t_g = t_hot - 0.5 * (t_hot - tf) * (1.0 - zg)
    else:
        zg = g.z_nodes[1:] / kiln.length
        t_g = t_hot - 0.5 * (t_hot - tf) * zg
    t_w = 0.5 * (t_b + t_g)
    nl = res.n_layers
    x = np.empty((n, res.nv))
    x[:, 0] = t_b
    x[:, 1] = t_g
    ta = kiln.ambient_temperature
    for i in range(nl + 1):
        x[:, 2 + i] = t_w - (t_w - ta) * 0.8 * i / nl
    if res.n_extra:
        x[:, 3 + nl :] = np.asarray(res.sources.initial_extra(g.z), dtype=float).reshape(
            n, res.n_extra
        )
    return x


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

    def where(j, v):
        if v < 3:
            eq = _EQ[v]
        elif v < 2 + nl:
            eq = f"lining interface {v - 2}"
        elif v == 2 + nl:
            eq = "shell"
        else:
            eq = f"source unknown {v - 3 - nl}"
        return f"cell {j} (z = {grid.z[j]:.4g} m), {eq}"

    x0 = _initial_guess(kiln, res) if initial is None else np.array(initial, dtype=float)
    kwargs = dict(tol=tol, max_iter=max_iter, temperature_vars=3 + nl, where=where)
    try:
        x, rep = newton_banded(res, x0, q_ref, **kwargs)
        total_iter = rep.iterations
    except ConvergenceError:
        # continuation: ramp radiation and heat release from 0 to 1
        x = x0
        total_iter = 0
        for lam in (0.0, 0.25, 0.5, 0.75, 1.0):
            res.homotopy = lam
            x, rep = newton_banded(res, x, q_ref, **kwargs)
            total_iter += rep.iterations
    res.homotopy = 1.0
    R, fl = res.evaluate(x, full=True)
    tb_nodes, tg_nodes = res.unpack(x)
    for name, arr in (("T_bed", tb_nodes), ("T_gas", tg_nodes), ("T_wall", x[:, 2 : 3 + nl])):
        if not np.all(np.isfinite(arr)):
            raise ConvergenceError(f"non-finite {name} in the solution", iterations=total_iter)
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
    if abs(closure) > 1e-6:
        warnings.warn(
            f"energy balance closes only to {closure:.3g} of the heat to the solids",
            RuntimeWarning,
            stacklevel=2,
        )
    fluxes = {k: np.array(v, dtype=float) * np.ones(grid.n) for k, v in fl.items()}
    for key, arr in fluxes.items():
        if not np.all(np.isfinite(arr)):
            j = int(np.argmax(~np.isfinite(arr)))
            raise ConvergenceError(
                f"non-finite {key} in cell {j} (z = {grid.z[j]:.4g} m)", iterations=total_iter
            )
    # validity ranges of the closures, checked once on the converged state
    res.coefficients(fluxes["t_gas_mean"], fluxes["t_bed_mean"], x[:, 2], check=True)
    return KilnSolution(
        name=kiln.name,
        z_nodes=grid.z_nodes,
        t_bed_nodes=np.asarray(tb_nodes, dtype=float),
        t_gas_nodes=np.asarray(tg_nodes, dtype=float),
        z=grid.z,
        t_bed=fluxes.pop("t_bed_mean"),
        t_gas=fluxes.pop("t_gas_mean"),
        t_wall=x[:, 2].copy(),
        t_shell=x[:, 2 + nl].copy(),
        t_lining=x[:, 2 : 3 + nl].T.copy(),
        fill=grid.fill,
        fluxes=fluxes,
        extra=x[:, 3 + nl :].copy(),
        heat_to_solids=heat_to_solids,
        heat_from_gas=heat_from_gas,
        heat_release=release,
        shell_loss=shell_loss,
        energy_in=e_in,
        energy_out=e_out,
        balance_closure=float(closure),
        iterations=total_iter,
        residual=float(np.max(np.abs(R))) / q_ref,
        n_cells=grid.n,
        counter_current=kiln.counter_current,
        measurements=kiln.measurements,
    )
