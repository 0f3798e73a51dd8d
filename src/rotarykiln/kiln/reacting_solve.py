"""Solve the reacting kiln (energy + species) at once by Newton, with continuation fallbacks."""

from __future__ import annotations

import numpy as np

from rotarykiln.chemistry.balance import ELEMENT_RTOL, check_stream_balance
from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.kiln.newton import newton_banded
from rotarykiln.kiln.reacting_model import ReactingKiln
from rotarykiln.kiln.reacting_residual import ReactingResidual
from rotarykiln.kiln.reacting_solution import ReactingSolution
from rotarykiln.materials.gas import T_REF

__all__ = ["solve_reacting", "ENERGY_RTOL"]

#: Energy closure demanded of every reacting solve (issue 7).
ENERGY_RTOL = 1e-6
#: Floor of the finite-difference step of the scaled species unknowns (flow / inlet flow).
SPECIES_STEP_FLOOR = 1e-6
_EQ = ("bed energy", "gas energy", "inner wall")


def _initial_guess(res: ReactingResidual) -> np.ndarray:
    k = res.kiln
    zeta = res.z_nodes / k.length
    th, tf = k.gas_inlet_temperature, k.feed_temperature
    x = np.empty((res.n, res.nv))
    x[:, 0] = tf + 0.6 * (th - tf) * zeta[1:]
    x[:, 1] = th - 0.5 * (th - tf) * (1.0 - zeta[:-1])
    x[:, 2] = 0.5 * (x[:, 0] + x[:, 1])
    xb = res.bed_in[res.bed_pos] / res.bed_scale
    x[:, 3 : 3 + res.nb] = np.where(res.sqrt_mask, np.sqrt(xb), xb)
    x[:, 3 + res.nb :] = res.gas_inlet[res.gas_pos] / res.gas_scale
    return x


def _reference_heat(res: ReactingResidual) -> float:
    k = res.kiln
    th, tf = k.gas_inlet_temperature, k.feed_temperature
    hg = res.mixture.species_enthalpy(np.array([th, tf]))
    span_g = float(res.gas_inlet @ (hg[0] - hg[1]))
    span_s = float(res.bed_in @ res.cp_bed) * abs(th - tf)
    return max(abs(span_g), span_s, 1.0)


def solve_reacting(
    kiln: ReactingKiln,
    n_cells: int = 100,
    *,
    tol: float = 1e-11,
    max_iter: int = 60,
    initial: np.ndarray | None = None,
    check_balances: bool = True,
) -> ReactingSolution:
    """Solve the steady energy and species balances of a reacting kiln.

    Parameters
    ----------
    kiln : ReactingKiln
    n_cells : int
        Number of equal cells (>= 4).
    tol : float
        Newton tolerance on ``max|R| / Q_ref`` (energy rows in W; species rows are flows over
        the phase's inlet flow times ``Q_ref``).
    max_iter : int
    initial : array (n_cells, nv), optional
        Initial guess (e.g. the unknowns of a neighbouring solution, ``solution.fluxes["x"]``).
    check_balances : bool
        Raise :class:`ConvergenceError` if the element balance exceeds 1e-8 or the energy
        balance 1e-6 (relative).

    Returns
    -------
    ReactingSolution

    Raises
    ------
    ConvergenceError
        Newton fails after continuation in the reaction rates (and radiation); the message
        names the cell (z) and equation with the largest residual. Also when a balance does
        not close or a result is not finite.
    """
    if int(n_cells) != n_cells or n_cells < 4:
        raise InputError("chemistry.cells", n_cells, "an integer >= 4")
    res = ReactingResidual(kiln, int(n_cells))
    q_ref = _reference_heat(res)
    res.q_ref = q_ref
    names = [f"bed {s}" for s in res.bed_var] + [f"gas {s}" for s in res.gas_var]

    def where(j, v):
        eq = _EQ[v] if v < 3 else f"{names[v - 3]} flow"
        return f"cell {j} (z = {res.z[j]:.4g} m), {eq}"

    floor = np.concatenate([np.ones(3), np.full(res.nv - 3, SPECIES_STEP_FLOOR)])
    kw = dict(tol=tol, max_iter=max_iter, temperature_vars=3, where=where, step_floor=floor)
    total = 0
    x0 = _initial_guess(res) if initial is None else np.array(initial, dtype=float)
    try:
        x, rep = newton_banded(res, x0, q_ref, **kw)
        total += rep.iterations
    except ConvergenceError:
        x, total = _continuation(res, x0, q_ref, kw)
    R, fl, prod, rate, (tb_n, tg_n, qb, qg) = res.evaluate(x[None], full=True)
    R, prod, rate = R[0], prod[0], rate[0]
    tb_n, tg_n, qb, qg = tb_n[0], tg_n[0], qb[0], qg[0]
    fl = {key: np.asarray(v)[0] * np.ones(res.n) for key, v in fl.items()}
    for label, arr in (("T_bed", tb_n), ("T_gas", tg_n), ("T_wall", x[:, 2]), ("flows", qb)):
        if not np.all(np.isfinite(arr)):
            raise ConvergenceError(f"non-finite {label} in the solution", iterations=total)
    for key, arr in fl.items():
        if not np.all(np.isfinite(arr)):
            j = int(np.argmax(~np.isfinite(arr)))
            raise ConvergenceError(f"non-finite {key} in cell {j} (z = {res.z[j]:.4g} m)")
    # validity ranges of the heat-transfer closures, checked once on the converged state
    g_mean = 0.5 * (np.maximum(qg[:-1], 0.0) + np.maximum(qg[1:], 0.0))
    res.coefficients(fl["t_gas_mean"], fl["t_bed_mean"], x[:, 2], g_mean, check=True)
    # global balances
    dz = res.dz
    hb = res.cp_bed * (tb_n[:, None] - T_REF)
    hg = res.mixture.species_enthalpy(tg_n)
    e_in = float(qb[0] @ hb[0] + qg[-1] @ hg[-1])
    e_out = float(qb[-1] @ hb[-1] + qg[0] @ hg[0])
    loss = float(np.sum(fl["q_shell_loss"]) * dz)
    w_all = prod
    h_all = np.zeros_like(prod)
    h_all[:, res.bed_idx] = res.cp_bed * (fl["t_bed_mean"][:, None] - T_REF)
    h_all[:, res.gas_idx] = res.mixture.species_enthalpy(fl["t_bed_mean"])
    reaction_heat = float(np.sum(fl["q_reaction_absorbed"] - (w_all * h_all).sum(-1)) * dz)
    heat_to_solids = float(qb[-1] @ hb[-1] - qb[0] @ hb[0])
    denom = max(abs(heat_to_solids), abs(reaction_heat), 1.0)
    closure = (e_in - e_out - loss - reaction_heat) / denom
    inlets = {s: float(qb[0, i]) for i, s in enumerate(res.bed_names)}
    inlets.update({s: float(qg[-1, i]) for i, s in enumerate(res.gas_names)})
    outlets = {s: float(max(qb[-1, i], 0.0)) for i, s in enumerate(res.bed_names)}
    outlets.update({s: float(max(qg[0, i], 0.0)) for i, s in enumerate(res.gas_names)})
    if check_balances:
        elements = check_stream_balance(inlets, outlets, res.species, rtol=ELEMENT_RTOL)
        if not abs(closure) <= ENERGY_RTOL:
            raise ConvergenceError(
                "energy balance of the reacting kiln does not close",
                relative_closure=closure,
                tolerance=ENERGY_RTOL,
                iterations=total,
            )
    else:
        from rotarykiln.chemistry.balance import element_flows

        fin, fout = element_flows(inlets, res.species), element_flows(outlets, res.species)
        elements = {e: abs(fin[e] - fout[e]) / max(abs(fin[e]), abs(fout[e]), 1e-300) for e in fin}
    fl["x"] = x.copy()
    return ReactingSolution(
        name=kiln.name,
        z_nodes=res.z_nodes,
        t_bed_nodes=np.asarray(tb_n, dtype=float),
        t_gas_nodes=np.asarray(tg_n, dtype=float),
        bed_flows={s: np.maximum(qb[:, i], 0.0) for i, s in enumerate(res.bed_names)},
        gas_flows={s: np.maximum(qg[:, i], 0.0) for i, s in enumerate(res.gas_names)},
        z=res.z,
        t_bed=fl.pop("t_bed_mean"),
        t_gas=fl.pop("t_gas_mean"),
        t_wall=x[:, 2].copy(),
        reaction_rates={r: rate[:, i].copy() for i, r in enumerate(kiln.mechanism.names)},
        fluxes=fl,
        energy_in=e_in,
        energy_out=e_out,
        shell_loss=loss,
        reaction_heat=reaction_heat,
        heat_to_solids=heat_to_solids,
        energy_closure=float(closure),
        element_closure={e: float(v) for e, v in elements.items()},
        iterations=total,
        residual=float(np.max(np.abs(R))) / q_ref,
        residence_time=kiln.residence_time,
        fill=kiln.fill,
        feed=dict(kiln.feed),
    )


def _continuation(res: ReactingResidual, x0, q_ref, kw):
    """Reaction rates (and radiation) ramped from 0 to 1 with adaptive steps."""
    total = 0
    res.reaction_scale = 0.0
    try:
        x, rep = newton_banded(res, x0, q_ref, **kw)
        total += rep.iterations
    except ConvergenceError:
        x = x0
        for r in (0.0, 0.25, 0.5, 0.75, 1.0):
            res.radiation_scale = r
            x, rep = newton_banded(res, x, q_ref, **kw)
            total += rep.iterations
    lam, step = 0.0, 0.25
    while lam < 1.0:
        trial = min(1.0, lam + step)
        res.reaction_scale = trial
        try:
            x_new, rep = newton_banded(res, x, q_ref, **kw)
        except ConvergenceError:
            step /= 2.0
            if step < 1.0 / 256:
                res.reaction_scale = 1.0
                raise
            continue
        total += rep.iterations
        x, lam = x_new, trial
        step = min(0.5, step * 2.0)
    res.reaction_scale = 1.0
    return x, total
