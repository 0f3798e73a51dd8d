"""Solve the reacting kiln (energy + species) at once by Newton, with continuation fallbacks."""

from __future__ import annotations

import numpy as np

from rotarykiln.chemistry.balance import ELEMENT_RTOL, check_stream_balance
from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.kiln import steady
from rotarykiln.kiln.reacting_model import ReactingKiln
from rotarykiln.kiln.reacting_residual import ReactingResidual
from rotarykiln.kiln.reacting_solution import ReactingSolution
from rotarykiln.materials.gas import T_REF

__all__ = ["solve_reacting", "ENERGY_RTOL"]

#: Energy closure demanded of every reacting solve (issue 7).
ENERGY_RTOL = 1e-6
#: Floor of the finite-difference step of the scaled species unknowns (flow / inlet flow).
SPECIES_STEP_FLOOR = 1e-6


def _initial_guess(res: ReactingResidual) -> np.ndarray:
    k = res.kiln
    t_b, t_g, t_wall = steady.initial_temperatures(
        res.z_nodes, k.feed_temperature, k.gas_inlet_temperature, res.wall, k.counter_current
    )
    i0 = res.i_species
    x = np.empty((res.n, res.nv))
    x[:, 0] = t_b
    x[:, 1] = t_g
    x[:, 2:i0] = t_wall
    xb = res.bed_in[res.bed_pos] / res.bed_scale
    x[:, i0 : i0 + res.nb] = np.where(res.sqrt_mask, np.sqrt(xb), xb)
    x[:, i0 + res.nb : i0 + res.nb + res.ng] = res.gas_inlet[res.gas_pos] / res.gas_scale
    if res.depth is not None:
        x[:, res.i_depth] = res.depth.initial_depth(k.length, res.z_nodes[:-1], k.feed_flow)
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
    i0 = res.i_species
    species = [f"bed {s} flow" for s in res.bed_var] + [f"gas {s} flow" for s in res.gas_var]
    if res.depth is not None:
        species.append("bed depth (Kramers)")
    where = steady.locator(res.z, steady.equation_names(res.wall, species))
    floor = np.concatenate([np.ones(i0), np.full(res.nv - i0, SPECIES_STEP_FLOOR)])
    kw = dict(tol=tol, max_iter=max_iter, temperature_vars=i0, where=where, step_floor=floor)
    x0 = _initial_guess(res) if initial is None else np.array(initial, dtype=float)
    x, total = steady.newton_with_continuation(res, x0, q_ref, _continuation(res), **kw)
    R, fl, prod, rate, (tb_n, tg_n, qb, qg) = res.evaluate(x[None], full=True)
    R, prod, rate = R[0], prod[0], rate[0]
    tb_n, tg_n, qb, qg = tb_n[0], tg_n[0], qb[0], qg[0]
    fl = {key: np.broadcast_to(v, (1, res.n))[0] * np.ones(res.n) for key, v in fl.items()}
    steady.check_finite(
        {"T_bed": tb_n, "T_gas": tg_n, "T_wall": x[:, 2:i0], "flows": qb}, fl, res.z, total
    )
    # validity ranges of the heat-transfer closures, checked once on the converged state
    g_mean = 0.5 * (np.maximum(qg[:-1], 0.0) + np.maximum(qg[1:], 0.0))
    geo = res.geometry(x)
    res.coefficients(fl["t_gas_mean"], fl["t_bed_mean"], x[:, 2], g_mean, check=True, geo=geo)
    # global balances
    dz = res.dz
    hb = res.cp_bed * (tb_n[:, None] - T_REF)
    hg = res.mixture.species_enthalpy(tg_n)
    gi, go = (-1, 0) if kiln.counter_current else (0, -1)  # gas inlet and outlet faces
    e_in = float(qb[0] @ hb[0] + qg[gi] @ hg[gi])
    e_out = float(qb[-1] @ hb[-1] + qg[go] @ hg[go])
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
    inlets.update({s: float(qg[gi, i]) for i, s in enumerate(res.gas_names)})
    outlets = {s: float(max(qb[-1, i], 0.0)) for i, s in enumerate(res.bed_names)}
    outlets.update({s: float(max(qg[go, i], 0.0)) for i, s in enumerate(res.gas_names)})
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
        **steady.profile_fields(res.grid, tb_n, tg_n, x[:, 2:i0], fl, R, q_ref, total),
        bed_flows={s: np.maximum(qb[:, i], 0.0) for i, s in enumerate(res.bed_names)},
        gas_flows={s: np.maximum(qg[:, i], 0.0) for i, s in enumerate(res.gas_names)},
        reaction_rates={r: rate[:, i].copy() for i, r in enumerate(kiln.mechanism.names)},
        energy_in=e_in,
        energy_out=e_out,
        shell_loss=loss,
        reaction_heat=reaction_heat,
        heat_to_solids=heat_to_solids,
        energy_closure=float(closure),
        element_closure={e: float(v) for e, v in elements.items()},
        residence_time=_residence_time(res, geo, qb),
        fill=kiln.fill if res.depth is None else float(np.mean(geo.fill)),
        feed=dict(kiln.feed),
        counter_current=kiln.counter_current,
    )


def _residence_time(res: ReactingResidual, geo, qb) -> float:
    """Mean solids residence time, s: the kiln's L/v, or with the bed depth solved the integral
    of hold-up over local mass flow, :math:`\\int \rho_b A_{bed}/\\dot m\\,dz`."""
    k = res.kiln
    if res.depth is None:
        return k.residence_time
    m = np.maximum(0.5 * (qb[1:].sum(-1) + qb[:-1].sum(-1)), 1e-300)
    return float(np.sum(k.bulk_density * geo.bed_area / m) * res.dz)


def _continuation(res: ReactingResidual):
    """Reaction rates off (with radiation ramped 0 -> 1 if needed), then ramped 0 -> 1 in
    adaptive steps."""

    def set_reactions(value):
        res.reaction_scale = value

    def set_radiation(value):
        res.radiation_scale = value

    radiation_ramp = steady.ramp(set_radiation)
    reactions = steady.ramp(set_reactions, adaptive=True)

    def run(F, x0, scale, kw):
        set_reactions(0.0)
        x, total = steady.newton_with_continuation(F, x0, scale, radiation_ramp, **kw)
        x, more = reactions(F, x, scale, kw)
        set_reactions(1.0)
        return x, total + more

    return run
