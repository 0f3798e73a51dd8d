"""Solve the kiln (energy + species) at once by Newton, with continuation fallbacks."""

from __future__ import annotations

import functools
import logging

import numpy as np

from rotarykiln.chemistry.balance import ELEMENT_RTOL, check_stream_balance
from rotarykiln.chemistry.ratelaws import MOISTURE
from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.kiln.accounting import energy_sheet, exhaust_state, global_balance
from rotarykiln.kiln.inputs import Kiln
from rotarykiln.kiln.inputs.boundary import Scales
from rotarykiln.kiln.residual import KilnResidual
from rotarykiln.kiln.results.solution import KilnSolution
from rotarykiln.kiln.steady import continuation as steady
from rotarykiln.kiln.steady.newton import trial_point

log = logging.getLogger(__name__)

__all__ = ["solve_kiln", "finish_solution", "newton_options", "ENERGY_RTOL", "zigzag"]

#: Energy closure demanded of every reacting solve (issue 7).
ENERGY_RTOL = 1e-6
#: Floor of the finite-difference step of the scaled species unknowns (flow / inlet flow).
SPECIES_STEP_FLOOR = 1e-6
#: Bed temperature (K) above which the initial guess holds no liquid water (boiling drying).
BOILING_GUESS = 373.15
#: Rate-temperature continuation (the last fallback): the rates first see at most the feed
#: temperature plus RATE_CAP_START, or RATE_CAP_FLOOR if lower, then up to the hottest source
#: plus RATE_CAP_MARGIN, K. A hot feed (a precalcined meal at 875 degC) can react at once at
#: its own temperature (the clinker rates): its ramp starts where Arrhenius rates are still
#: negligible (at 500 K a rate of E = 100 kJ/mol is 1e-8 of its value at 1000 K).
RATE_CAP_START = 50.0
RATE_CAP_FLOOR = 500.0
RATE_CAP_MARGIN = 200.0
#: Grid sequencing (steady.newton_sequenced) for kilns with reactions, and for inert kilns
#: above this many cells (below it the linear guess converges in ~7 Newton steps anyway).
SEQUENCE_INERT_MIN = 200
#: Failed steps after which an adaptive continuation stage on the coarse grid of the sequence
#: gives up (the fine grid then solves from the guess, with its own continuation if needed):
#: a coarse grid stalling at a fold costs more than that (the lime kiln: 10 s in 30 failures).
COARSE_FAILURES = 6
#: Feed continuation (the last fallback of a reacting solve, :func:`_feed_continuation`): the
#: kiln first solved at its feed times these factors, in turn, until one converges (more feed:
#: the reactions end short of completion, no front to place); then the feed stepped back to
#: the kiln's own, halving a failed step down to FEED_MIN_STEP (a share of the feed), the
#: intermediate feeds solved to FEED_STEP_TOL.
FEED_START_FACTORS = (1.1, 1.25, 1.5)
FEED_MIN_STEP = 1e-3
FEED_STEP_TOL = 1e-8


def _initial_guess(res: KilnResidual) -> np.ndarray:
    k = res.kiln
    t_b, t_g, t_wall = steady.initial_temperatures(
        res.z_nodes, k.feed.temperature, res.hottest_source(), res.wall, k.gas.counter_current
    )
    i0 = res.i_species
    x = np.empty((res.n, res.nv))
    x[:, 0] = t_b
    x[:, 1] = t_g
    x[:, 2:i0] = t_wall
    xb = res.bed_in[res.bed_pos] / res.bed_scale
    x[:, i0 : i0 + res.nb] = np.where(res.sqrt_mask, np.sqrt(xb), xb)
    if MOISTURE in res.bed_var and any(
        r.law.name == "boiling_drying" for r in k.chemistry.mechanism.reactions
    ):
        # a bed held at its boiling point has no liquid water above it: start dry there
        j = res.bed_var.index(MOISTURE)
        hot = t_b > BOILING_GUESS
        dry = 1e-4 * xb[j]
        x[hot, i0 + j] = np.sqrt(dry) if res.sqrt_mask[j] else dry
    x[:, i0 + res.nb : i0 + res.nb + res.ng] = res.gas_inlet[res.gas_pos] / res.gas_scale
    if res.depth is not None:
        x[:, res.i_depth] = res.depth.initial_depth(k.drum.length, res.z_nodes[:-1], k.feed_flow)
    return x


def solve_kiln(
    kiln: Kiln,
    n_cells: int = 100,
    *,
    tol: float = 1e-11,
    max_iter: int = 60,
    initial: np.ndarray | None = None,
    check_balances: bool = True,
) -> KilnSolution:
    """Solve the steady energy and species balances of a kiln (inert or reacting).

    Parameters
    ----------
    kiln : Kiln
        The kiln's inputs (:class:`~rotarykiln.kiln.inputs.kiln.Kiln`).
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
    KilnSolution

    Raises
    ------
    ConvergenceError
        Newton fails after continuation in the reaction rates (and radiation), and again with
        every square-root unknown stepped in its square; the message names the cell (z) and
        equation with the largest residual of the last attempt. Also when a balance does
        not close or a result is not finite.

    Examples
    --------
    >>> from rotarykiln.kiln.inputs import Kiln
    >>> from rotarykiln.materials.solids import load_solid
    >>> k = Kiln.inert(solid=load_solid("sand"), solids_flow=0.004,
    ...     solids_inlet_temperature=298.15, gas_composition="O2:0.21, N2:0.79",
    ...     gas_flow=0.007, gas_inlet_temperature=535.0, length=2.44, radius=0.094,
    ...     omega=0.157, fill=0.17)
    >>> sol = solve_kiln(k, 20)
    >>> 298.15 < sol.bed_outlet_temperature < 535.0, abs(sol.energy_closure) < 1e-6
    (True, True)

    References
    ----------
    The finite-volume balances: docs/heat.md and docs/reacting.md; the closures: Tscheng &
    Watkinson, Can. J. Chem. Eng. 57 (1979) 433; Li et al., Powder Technol. 152 (2005) 113.
    """
    if int(n_cells) != n_cells or n_cells < 4:
        raise InputError("solver.cells", n_cells, "an integer >= 4")
    res = KilnResidual(kiln, int(n_cells))
    kw = newton_options(res, tol=tol, max_iter=max_iter)
    x0 = _initial_guess(res) if initial is None else np.array(initial, dtype=float)
    try:
        x, total = _solve_unknowns(res, x0, kw, sequenced=initial is None)
    except ConvergenceError:
        if not kiln.chemistry.mechanism.reactions:
            raise
        # the last resort of a reacting kiln: the same kiln at a larger feed, where its
        # reactions do not run to completion, stepped back to its own feed (the lime kiln
        # 5-10 % off its feed or coal: the end of its calcination front)
        try:
            x, total = _feed_continuation(res, kw)
        except ConvergenceError as exc:
            log.info("feed continuation failed: %s", exc)
            raise
    x, total = _polished(res, x, total, kw)
    return finish_solution(res, x, total, check_balances=check_balances)


def _polished(res: KilnResidual, x: np.ndarray, total: int, kw: dict):
    """``x`` taken on to the tolerance when its solve stalled just above it (accepted at
    round-off, :data:`~rotarykiln.kiln.steady.newton.STAGNATION_FACTOR`): Newton from its own
    Jacobian with Broyden's updates (:func:`~rotarykiln.kiln.steady.batch.newton_batch`),
    which correct the forward differences of a stiff rate (a calcination near its
    equilibrium, at a tolerance of 1e-13) along the steps taken, where a new Jacobian alone
    cannot lower the residual further. ``(x, iterations)``: unchanged if it did not stall, or
    if the polish does not converge."""
    from rotarykiln.kiln.steady.batch import BROYDEN_UPDATES, BatchResidual, newton_batch

    norm = float(np.max(np.abs(res.evaluate(x)))) / res.q_ref
    if norm <= kw["tol"]:
        return x, total
    F = BatchResidual([res])  # (its root unknowns on their positive branch: kw["roots"])
    x_p, its, _, ok = newton_batch(F, x[None], F.q_ref, broyden=BROYDEN_UPDATES, **kw)
    if not ok[0]:
        return x, total
    log.info("stalled at residual %.3g: polished in %d iterations", norm, int(its[0]))
    return x_p[0], total + int(its[0])


def _solve_unknowns(res: KilnResidual, x0, kw: dict, *, sequenced: bool):
    """Newton from ``x0`` (grid-sequenced when ``sequenced`` and the kiln reacts or has more
    than SEQUENCE_INERT_MIN cells), the continuation fallbacks, and for a reacting kiln the
    continuation again with every root unknown stepped in its square: ``(x, iterations)``,
    or ConvergenceError (the last attempt's)."""
    kiln, q_ref = res.kiln, res.q_ref
    every = _every_root_squared(res, kw["squared"])
    sequenced = sequenced and bool(kiln.chemistry.mechanism.reactions or res.n > SEQUENCE_INERT_MIN)
    try:
        if sequenced:

            def make_residual(n):
                return KilnResidual(kiln, n, q_ref=q_ref)

            return steady.newton_sequenced(
                res,
                x0,
                q_ref,
                _continuation(res),
                make_residual=make_residual,
                continuation_of=functools.partial(_continuation, max_failures=COARSE_FAILURES),
                retry_options=every,
                **kw,
            )
        return steady.newton_with_continuation(res, x0, q_ref, _continuation(res), **kw)
    except ConvergenceError:
        if every is None:
            raise
        # the continuation again, every root unknown stepped in its square (a reactant of
        # order 1/2 used up within a cell: _every_root_squared)
        return steady.newton_with_continuation(
            res, x0, q_ref, _continuation(res), **dict(kw, **every)
        )


def _with_feed(kiln: Kiln, factor: float) -> Kiln:
    """The kiln with every feed flow times ``factor`` (all else as it is)."""
    return kiln.replace(feed__flows={s: q * factor for s, q in kiln.feed.flows.items()})


def _feed_continuation(res: KilnResidual, kw: dict):
    """Solve the reacting kiln of ``res`` from the same kiln at a larger feed: ``(x, iterations)``.

    A reaction front that runs to completion inside the kiln (the lime kiln's calcination:
    the bed pinned near 900 degC while its CaCO3 lasts, then 150 K hotter per cell) has, on a
    200-cell grid, a Newton basin of about 1/25 of a cell in the front's position: no start
    the continuations above make (the reaction-free kiln, the coarse grid's front) lies in it
    reliably. With more feed the reactions do not run to completion and the front is not
    there. The kiln is solved (:func:`_solve_unknowns`) at its feed times each
    FEED_START_FACTORS in turn until one converges, and the feed is then stepped back to the
    kiln's own: each step starts from the secant predictor of the last two solutions (the
    front moves nearly in proportion to the feed, so the predictor's error is of second
    order in the step) and runs Newton with the root unknowns lowered in their logarithm
    (``newton_banded(..., logged=...)``: the reactant's flow past the front falls by decades
    per cell) and the stall test STEP_STALL; a step that fails is halved (down to
    FEED_MIN_STEP of the feed), one that converges doubles the next. Intermediate steps are
    solved to FEED_STEP_TOL, the kiln's own feed to the caller's tolerance.
    """
    kiln, q_ref, n = res.kiln, res.q_ref, res.n
    logged = np.zeros(res.nv, dtype=bool)
    logged[res.i_species : res.i_species + res.nb] = res.sqrt_mask
    x, lam, failure = None, 1.0, None
    for factor in FEED_START_FACTORS:
        start = KilnResidual(_with_feed(kiln, factor), n, q_ref=q_ref)
        skw = newton_options(start, tol=FEED_STEP_TOL, max_iter=kw["max_iter"])
        try:
            x, total = _solve_unknowns(start, _initial_guess(start), skw, sequenced=True)
        except ConvergenceError as exc:
            failure = exc
            continue
        lam = factor
        break
    if x is None:
        raise failure
    log.info("feed continuation: from %.4g times the feed", lam)
    step, prev, iters = lam - 1.0, None, total
    lg = np.flatnonzero(logged)
    while lam > 1.0:
        trial = max(1.0, lam - step)
        last = trial <= 1.0
        F = res if last else KilnResidual(_with_feed(kiln, trial), n, q_ref=q_ref)
        xs = x
        if prev is not None:  # secant predictor (the roots kept positive: trial_point)
            xs = trial_point(x, x - prev[0], (lam - trial) / (prev[1] - lam), None, lg)
        step_kw = dict(kw, logged=logged, stall=steady.STEP_STALL)
        if not last:
            step_kw.update(tol=FEED_STEP_TOL, where=None)
        try:
            x_new, rep = steady.newton.newton_banded(F, xs, q_ref, **step_kw)
        except ConvergenceError:
            step /= 2.0
            if step < FEED_MIN_STEP:
                raise
            continue
        log.info("feed continuation: %.6g times the feed (%d iterations)", trial, rep.iterations)
        prev, x, lam = (x, lam), x_new, trial
        iters += rep.iterations
        step *= 2.0
    return x, iters


def _every_root_squared(res: KilnResidual, squared: np.ndarray) -> dict | None:
    """Newton options stepping every square-root unknown in its square (None if they all do
    already): the retry of a fine grid whose Newton failed from its coarse start. A reactant of
    order 1/2 used up within a cell or two (the cement kiln's remaining CaCO3 in its hot meal)
    has, below the rate floor, a rate first order in its flow: Newton in the square root only
    halves it per iteration there (:func:`_consumed_at_first_order`)."""
    every = squared.copy()
    every[res.i_species : res.i_species + res.nb] |= res.sqrt_mask
    return {"squared": every} if (every != squared).any() else None


def newton_options(res: KilnResidual, *, tol: float, max_iter: int) -> dict:
    """The keyword options of :func:`~rotarykiln.kiln.steady.newton.newton_banded` for the
    residual ``res``: tolerance, iterations, which unknowns are temperatures, where each
    unknown lies (for errors), the finite-difference step floors, the squared unknowns, the
    local ones (one colour of the Jacobian each) and the roots (kept positive)."""
    kiln, i0 = res.kiln, res.i_species
    species = [f"bed {s} flow" for s in res.bed_var] + [f"gas {s} flow" for s in res.gas_var]
    if res.depth is not None:
        species.append("bed depth (Kramers)")
    where = steady.locator(res.z, steady.equation_names(res.wall, species))
    floor = np.concatenate([np.ones(i0), np.full(res.nv - i0, SPECIES_STEP_FLOOR)])
    squared = np.zeros(res.nv, dtype=bool)
    squared[i0 : i0 + res.nb] = res.sqrt_mask & _consumed_at_first_order(kiln, res.bed_var)
    roots = np.zeros(res.nv, dtype=bool)
    roots[i0 : i0 + res.nb] = res.sqrt_mask
    return dict(
        tol=tol,
        max_iter=max_iter,
        temperature_vars=i0,
        where=where,
        step_floor=floor,
        squared=squared,
        local=res.local,
        roots=roots,
    )


def finish_solution(
    res: KilnResidual,
    x: np.ndarray,
    total: int,
    *,
    check_balances: bool = True,
    evaluated=None,
    check_closures: bool = True,
) -> KilnSolution:
    """The :class:`KilnSolution` of the converged unknowns ``x`` (n, nv) of ``res`` after
    ``total`` Newton iterations: the profiles, the bound and oscillation checks, the closures'
    validity ranges, the global balances (checked with ``check_balances``: ConvergenceError
    beyond 1e-8 for the elements, 1e-6 for the energy) and the energy sheet. ``evaluated``:
    ``res.evaluate(x[None], full=True)`` when already computed (a batch evaluates all its
    cases at once); ``check_closures`` False: the closures' ranges are known to hold (a
    batch checked all its cases at once, :meth:`~rotarykiln.kiln.steady.batch.BatchResidual.
    full`)."""
    kiln, q_ref, i0 = res.kiln, res.q_ref, res.i_species
    if evaluated is None:
        evaluated = res.evaluate(x[None], full=True)
    R, fl, prod, rate, (tb_n, tg_n, qb, qg) = evaluated
    R, prod, rate = R[0], prod[0], rate[0]
    tb_n, tg_n, qb, qg = tb_n[0], tg_n[0], qb[0], qg[0]
    fl = {key: _per_cell(v, res.n) for key, v in fl.items()}
    steady.check_finite(
        {"T_bed": tb_n, "T_gas": tg_n, "T_wall": x[:, 2:i0], "flows": qb}, fl, res.z, total
    )
    _check_no_hotter_than_sources(res, tb_n, tg_n, x[:, 2:i0], total)
    _check_within_partners(res, tb_n, tg_n, x[:, 2:i0], total)
    _check_no_oscillation(res, {"T_bed": tb_n, "T_gas": tg_n, "T_wall": x[:, 2]}, total)
    # validity ranges of the heat-transfer closures, checked once on the converged state
    g_mean = 0.5 * (np.maximum(qg[:-1], 0.0) + np.maximum(qg[1:], 0.0))
    geo = res.geometry(x)
    if check_closures:
        res.coefficients(fl["t_gas_mean"], fl["t_bed_mean"], x[:, 2], g_mean, check=True, geo=geo)
    gas = res.gas_state(g_mean, geo)
    fl["gas_velocity"] = gas.mass_flux / gas.density(fl["t_gas_mean"])  # m/s, cells
    for solid in {id(s): s for s in kiln.bed.solids.values()}.values():
        solid.check_range(tb_n)  # a library solid's c_p fit extrapolated: OutOfRangeWarning
    if hasattr(res.wall, "check_service_limits"):  # a lining above its t_max: a warning
        res.wall.check_service_limits(x[:, 2:i0], res.z)
    # global balances
    bal = {key: float(v) for key, v in global_balance(res, fl, prod, tb_n, tg_n, qb, qg).items()}
    e_in, e_out, loss = bal["energy_in"], bal["energy_out"], bal["shell_loss"]
    release, heating, reaction_heat = bal["release"], bal["heating"], bal["reaction_heat"]
    heat_to_solids = bal["solids_out"] - bal["solids_in"]
    denom = max(abs(heat_to_solids), abs(reaction_heat), 1.0)
    closure = bal["net"] / denom
    gi, go = (-1, 0) if kiln.gas.counter_current else (0, -1)  # gas inlet and outlet faces
    inlets = {s: float(qb[0, i]) for i, s in enumerate(res.bed_names)}
    inlets.update({s: float(qg[gi, i]) for i, s in enumerate(res.gas_names)})
    for name, flow in res.bed_sources.items():  # a burner's ash, fallen into the bed
        inlets[name] += flow
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
    exhaust, ingress_in = exhaust_state(res, qg[go], float(tg_n[go]))
    sheet = energy_sheet(
        kiln,
        solids_in=bal["solids_in"],
        to_solids=heat_to_solids,
        reaction_heat=reaction_heat,
        gas_in=bal["gas_in"],
        exhaust=bal["gas_out"] + ingress_in,
        shell_loss=loss,
        release=release,
        heating=heating,
        ingress=ingress_in,
    )
    return KilnSolution(
        name=kiln.name,
        **steady.profile_fields(res.grid, tb_n, tg_n, x[:, 2:i0], fl, R, q_ref, total),
        bed_flows={s: np.maximum(qb[:, i], 0.0) for i, s in enumerate(res.bed_names)},
        gas_flows={s: np.maximum(qg[:, i], 0.0) for i, s in enumerate(res.gas_names)},
        reaction_rates={r: rate[:, i].copy() for i, r in enumerate(kiln.chemistry.mechanism.names)},
        energy_in=e_in,
        energy_out=e_out,
        shell_loss=loss,
        reaction_heat=reaction_heat,
        heat_to_solids=heat_to_solids,
        energy_closure=float(closure),
        element_closure={e: float(v) for e, v in elements.items()},
        residence_time=_residence_time(res, geo, qb),
        fill=float(np.mean(geo.fill)),
        feed=dict(kiln.feed.flows),
        counter_current=kiln.gas.counter_current,
        heat_release=release,
        energy_sheet=sheet,
        burner=kiln.firing.flame.summary() if kiln.firing.flame is not None else {},
        measurements=kiln.measurements,
        fill_profile=res.geometry(x).fill * np.ones(res.n),
        exhaust=exhaust,
    )


def _per_cell(value, n: int) -> np.ndarray:
    """A per-cell quantity of one case's evaluation (shape ``(1, n)``, ``(n,)`` or one
    value for every cell) as a new float array of ``n`` values."""
    a = np.asarray(value, dtype=float)
    out = np.empty(n)
    out[...] = a.reshape(a.shape[-1:]) if a.ndim else a
    return out


def _consumed_at_first_order(kiln: Kiln, species) -> np.ndarray:
    """For each bed species: is every reaction that consumes it of order >= 1 in its flow?

    Those reactants are solved for as the square root of their flow (positive flows), but
    stepped by Newton in the flow itself: near complete conversion a first-order consumption
    is linear in the flow, while in its square root the solution is a double root that Newton
    only halves per iteration (the shrinking-core order 1/2 is linear in the square root, and
    keeps its steps there).
    """
    out = []
    for s in species:
        orders = [
            r.law.flow_order(r.params) for r in kiln.chemistry.mechanism.reactions if r.basis == s
        ]
        out.append(bool(orders) and min(orders) >= 1.0)
    return np.array(out, dtype=bool)


def _check_no_hotter_than_sources(res: KilnResidual, tb_n, tg_n, t_wall, iterations) -> None:
    """Refuse a solution hotter than every heat source it has (ConvergenceError).

    Without exothermic reactions the hottest a kiln can be is its hottest inlet (gas, solids,
    ambient, a heater set-point); a face above that by more than 1 K is a discretisation
    artefact (an under-resolved front), never physics. Not checked with exothermic chemistry,
    heat released along a flame or heaters of given power.
    """
    k = res.kiln
    if any(r.heat < 0 for r in k.chemistry.mechanism.reactions):
        return  # exothermic chemistry: the bound is an adiabatic temperature, not checked here
    if any(z.power is not None for z in k.wall.heaters):
        return  # a heater of given power has no temperature bound
    if k.firing.heat_release > 0:
        return  # heat released inside: a counter-current kiln recuperates heat into the
        # unburnt gas (super-adiabatic temperatures are physical there), no simple bound
    set_points = [z.shell_temperature for z in k.wall.heaters]
    bound = max(k.gas.temperature, k.feed.temperature, k.wall.ambient_temperature, *set_points)
    bound = max(bound, res.hottest_source()) + 1.0
    for name, arr in (("T_bed", tb_n), ("T_gas", tg_n), ("T_wall", t_wall)):
        arr = np.asarray(arr)
        if np.any(arr > bound):
            flat = int(np.argmax(arr.max(axis=-1) if arr.ndim > 1 else arr))
            raise ConvergenceError(
                f"unphysical solution: {name} reaches {float(arr.max()):.6g} K, above every "
                f"heat source ({bound - 1.0:.6g} K), near z = {res.z_nodes[min(flat, res.n)]:.4g} m;"
                " refine the grid (cells)",
                iterations=iterations,
            )


def _temperature_tolerance(hottest: float) -> float:
    """Slack of the bound checks, K: 1 K plus 0.1 % of the hottest temperature ``hottest``
    (K; the cells' means and faces are not exactly what the closures saw)."""
    return 1.0 + 1e-3 * hottest


def _check_within_partners(res: KilnResidual, tb_n, tg_n, t_wall, iterations) -> None:
    """Refuse a phase hotter (colder) than everything it exchanges heat with (ConvergenceError).

    Heat flows from hot to cold: a phase without a heat source of its own cannot become hotter
    than the hottest temperature it exchanges with anywhere in the kiln, nor colder than the
    coldest. The gas exchanges with the wall and the bed, takes the bed's volatiles at the bed
    temperature, and enters at its inlet (air ingress at ambient); the wall (lining, shell,
    jacket gas) with the gas, the bed, the ambient, a jacket's inlet and heater set-points; the
    bed with the gas, the wall and its feed. Sources that lift the bound: heat released in the
    gas (a flame) or gas-phase reactions for the gas, heaters of given power for the wall,
    exothermic bed reactions for the bed (and endothermic ones below). This check holds with
    exothermic chemistry, where the bound on the hottest source does not apply: a gas hotter
    than both the wall and the bed it lies between is never physics.
    """
    k = res.kiln
    reactions = list(k.chemistry.mechanism.reactions)
    gas_sources = k.firing.heat_release > 0 or any(r.phase == "gas" for r in reactions)
    bed_exo = any(r.phase != "gas" and r.heat < 0 for r in reactions)
    bed_endo = any(r.phase != "gas" and r.heat > 0 for r in reactions)
    powered = any(z.power is not None for z in k.wall.heaters)
    jacket = k.wall.jacket
    outside = [k.wall.ambient_temperature, *(z.shell_temperature for z in k.wall.heaters)]
    outside = [t for t in outside if t is not None]
    if jacket is not None:
        outside.append(float(jacket.inlet_temperature))
    t_wall = np.asarray(t_wall, dtype=float).reshape(res.n, -1)
    tb_n, tg_n = np.asarray(tb_n, dtype=float), np.asarray(tg_n, dtype=float)
    inner = t_wall[:, 0]
    # each profile's extremes once (the checks compare them; the cells only for a message)
    top = {"bed": float(tb_n.max()), "gas": float(tg_n.max()), "wall": float(t_wall.max())}
    low = {"bed": float(tb_n.min()), "gas": float(tg_n.min()), "wall": float(t_wall.min())}
    top["inner"], low["inner"] = float(inner.max()), float(inner.min())
    gas_in = [float(k.gas.temperature), float(k.wall.ambient_temperature)]
    feed = [float(k.feed.temperature)]
    outside = [float(t) for t in outside]
    checks = []  # (name, values, its key, partners' hottest and coldest, check hot, check cold)
    if not gas_sources:
        hot = max(*gas_in, top["inner"], top["bed"])
        cold = min(*gas_in, low["inner"], low["bed"])
        checks.append(("T_gas", tg_n, "gas", hot, cold, True, True))
    hot = max(top["gas"], top["bed"], *outside)
    cold = min(low["gas"], low["bed"], *outside)
    checks.append(("T_wall", t_wall, "wall", hot, cold, not powered, True))
    hot, cold = max(*feed, top["gas"], top["inner"]), min(*feed, low["gas"], low["inner"])
    checks.append(("T_bed", tb_n, "bed", hot, cold, not bed_exo, not bed_endo))
    tol = _temperature_tolerance(max(top["bed"], top["gas"], top["wall"]))
    for name, values, key, hottest, coldest, check_hot, check_cold in checks:
        for check, beyond, word, bound in (
            (check_hot, top[key] > hottest + tol, "hotter", hottest),
            (check_cold, low[key] < coldest - tol, "colder", coldest),
        ):
            if not (check and beyond):
                continue
            per_cell = values.reshape(values.shape[0], -1)
            worst = per_cell.max(-1) if word == "hotter" else per_cell.min(-1)
            j = int(np.argmax(worst) if word == "hotter" else np.argmin(worst))
            z = res.z_nodes[j] if values.shape[0] == res.n + 1 else res.z[j]
            raise ConvergenceError(
                f"unphysical solution (bound check): {name} reaches {float(worst[j]):.6g} K at "
                f"z = {z:.4g} m, {word} than everything it exchanges heat with "
                f"({bound:.6g} K); refine the grid (solver.cells)",
                iterations=iterations,
            )


#: A profile zigzagging cell to cell (each difference against the sign of the previous one,
#: each larger than the amplitude) over this many successive nodes is a failed solve.
ZIGZAG_NODES = 4
#: Amplitude of a zigzag: at least this many K and this share of the profile's span. Below it
#: a ripple is tolerated: a stiff equilibrium reaction that pins the bed's cell means (pure
#: CaCO3 under pure CO2 at 1,175 K) leaves its faces rippling by a few K around them.
ZIGZAG_AMPLITUDE = 2.0
ZIGZAG_SPAN_SHARE = 0.02


def zigzag(values, amplitude: float) -> tuple[int, int]:
    """Longest run of successive interior nodes where a profile turns back (the differences on
    either side of opposite signs, both larger than ``amplitude``): (length, first node).

    Examples
    --------
    >>> zigzag([1.0, 9.0, 2.0, 8.0, 3.0, 7.0, 7.5, 8.0], 1.0)
    (4, 1)
    >>> zigzag([1.0, 2.0, 3.0, 2.5, 2.0], 1.0)
    (0, 0)
    """
    d = np.diff(np.asarray(values, dtype=float))
    big = np.abs(d) > amplitude
    turn = (d[:-1] * d[1:] < 0.0) & big[:-1] & big[1:]
    if not turn.any():
        return 0, 0
    # runs of turns: starts and ends of the True stretches, the first longest one
    edges = np.diff(np.concatenate([[0], turn.astype(np.int8), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    k = int(np.argmax(ends - starts))
    return int(ends[k] - starts[k]), int(starts[k] + 1)


def _check_no_oscillation(res: KilnResidual, profiles: dict, iterations) -> None:
    """Refuse a profile that oscillates from cell to cell (ConvergenceError): a sign of a grid
    too coarse for the exchange it resolves (e.g. a cell of more transfer units than the scheme
    bounds), never of physics; the message names the profile, the cells and z."""
    for name, values in profiles.items():
        values = np.asarray(values, dtype=float)
        amplitude = max(ZIGZAG_AMPLITUDE, ZIGZAG_SPAN_SHARE * float(np.ptp(values)))
        length, first = zigzag(values, amplitude)
        if length >= ZIGZAG_NODES:
            z = res.z_nodes if values.size == res.n + 1 else res.z
            raise ConvergenceError(
                f"unphysical solution (oscillation check): {name} zigzags cell to cell over "
                f"{length} nodes from z = {z[first]:.4g} m (amplitude above {amplitude:.3g} K); "
                "refine the grid (solver.cells)",
                iterations=iterations,
            )


def _residence_time(res: KilnResidual, geo, qb) -> float:
    r"""Mean solids residence time, s: the kiln's L/v, or with the bed depth solved the integral
    of hold-up over local mass flow, :math:`\int \rho A_{bed}/\dot m\,dz`, with the bed
    density :math:`\rho` of the depth's volume law (:meth:`KilnResidual.bed_density`: the bulk
    density, or with the fresh feed's volume :math:`\int A_{bed}/\dot V_0\,dz`)."""
    k = res.kiln
    if res.depth is None:
        return k.residence_time
    m = np.maximum(0.5 * (qb[1:].sum(-1) + qb[:-1].sum(-1)), 1e-300)
    rho = res.bed_density(0.5 * (qb[1:] + qb[:-1]))
    return float(np.sum(rho * geo.bed_area / m) * res.dz)


def _continuation(res: KilnResidual, max_failures: int | None = None):
    """Reaction rates off (with radiation and the heat release ramped 0 -> 1 if needed), then
    the rates ramped 0 -> 1 in adaptive steps; if that fails, the full rates with the
    temperature they see ramped from just above the feed (at most RATE_CAP_FLOOR) to the
    hottest source. Each stage
    solves the residual at its :class:`~rotarykiln.kiln.inputs.boundary.Scales`; an adaptive
    stage gives up after ``max_failures`` failed steps (None: down to the smallest step)."""
    t_low = min(res.kiln.feed.temperature + RATE_CAP_START, RATE_CAP_FLOOR)
    t_high = res.hottest_source() + RATE_CAP_MARGIN
    radiation_ramp = steady.ramp(lambda v: Scales(reaction=0.0, radiation=v, release=v))
    reactions = steady.ramp(lambda v: Scales(reaction=v), adaptive=True, max_failures=max_failures)

    def capped(value):
        cap = np.inf if value >= 1.0 else t_low + value * (t_high - t_low)
        return Scales(rate_temperature_cap=cap)

    temperatures = steady.ramp(capped, adaptive=True, max_failures=max_failures)

    def run(F, x0, scale, kw):
        off = steady.scaled(F, Scales(reaction=0.0))
        x, total = steady.newton_with_continuation(
            off, x0, scale, lambda _, x, s, k: radiation_ramp(F, x, s, k), **kw
        )
        try:
            x_r, more = reactions(F, x, scale, kw)
        except ConvergenceError:
            # a kiln hot enough to react at once where the reaction-free bed is hottest: ramp
            # instead the temperature the rates see, from just above the feed to the hottest
            # source, with the full rates (each stage heats the bed a little further)
            x_r, more = temperatures(F, x, scale, kw)
        return x_r, total + more

    return run
