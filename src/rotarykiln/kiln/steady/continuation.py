"""Newton driver of the steady kiln (:func:`rotarykiln.kiln.steady.solve.solve_kiln`).

- :func:`initial_temperatures`: the linear bed/gas/wall guess the solver starts from;
- :func:`equation_names` and :func:`locator`: what each unknown's balance is called, for
  error messages;
- :func:`newton_with_continuation`: banded Newton from the guess, and on failure a
  continuation, given as a list of :func:`ramp` stages (a parameter of the residual ramped
  0 -> 1, in fixed or adaptive steps);
- :func:`newton_sequenced`: the same from a grid-sequenced start (the unknowns solved on a
  coarser grid, interpolated by :func:`interpolate_unknowns`), for kilns with reactions and
  fine grids of inert kilns: the damped first Newton iterations then run on the cheap coarse
  grid;
- :func:`check_finite`: no non-finite value leaves a solver;
- :func:`profile_fields`: the temperature profiles and solver figures a solution holds.
"""

from __future__ import annotations

import functools
import logging
from collections.abc import Callable, Sequence

import numpy as np

from rotarykiln.errors import ConvergenceError
from rotarykiln.kiln.steady import newton

log = logging.getLogger(__name__)

__all__ = [
    "initial_temperatures",
    "equation_names",
    "locator",
    "ramp",
    "scaled",
    "newton_with_continuation",
    "newton_sequenced",
    "interpolate_unknowns",
    "check_finite",
    "profile_fields",
    "FIXED_STEPS",
    "STEP_STALL",
]

#: Fixed continuation steps (radiation, heat release).
FIXED_STEPS = (0.0, 0.25, 0.5, 0.75, 1.0)
#: An adaptive continuation's intermediate steps are given up when after STEP_STALL[0] Newton
#: iterations the residual is not below STEP_STALL[1] times where the step started: a step too
#: long then fails fast and is halved (the cement kiln's rate-temperature ramp spent 60
#: iterations on each such failure).
STEP_STALL = (8, 1e-2)


def initial_temperatures(z_nodes, t_feed, t_hot, wall, counter_current=True):
    """Linear initial guess: bed (faces 1..n), gas (its n outlet faces), wall (cells), K.

    The bed warms from ``t_feed`` by 0.6 of the span to the hot gas ``t_hot`` along the kiln;
    the gas cools from ``t_hot`` by half the span; the inner wall sits between them and the
    wall model (``wall.initial_guess``) fills its other temperatures.

    Examples
    --------
    >>> from rotarykiln.kiln.wall.lining import ConstantUWall
    >>> tb, tg, tw = initial_temperatures(np.linspace(0, 1, 3), 300.0, 1300.0,
    ...                                   ConstantUWall(5.0, 1.0, 300.0))
    >>> tb.tolist(), tg.tolist(), tw[:, 0].tolist()
    ([600.0, 900.0], [800.0, 1050.0], [700.0, 975.0])
    """
    z_nodes = np.asarray(z_nodes, dtype=float)
    zeta = z_nodes / z_nodes[-1]
    t_b = t_feed + 0.6 * (t_hot - t_feed) * zeta[1:]
    if counter_current:
        t_g = t_hot - 0.5 * (t_hot - t_feed) * (1.0 - zeta[:-1])
    else:
        t_g = t_hot - 0.5 * (t_hot - t_feed) * zeta[1:]
    return t_b, t_g, wall.initial_guess(0.5 * (t_b + t_g))


def equation_names(wall, extra: Sequence[str] = ()) -> list[str]:
    """Names of the balances of a cell: bed and gas energy, the wall's, then ``extra``."""
    return ["bed energy", "gas energy", *wall.labels(), *extra]


def locator(z, names: Sequence[str]) -> Callable[[int, int], str]:
    """``where(j, v)`` -> "cell j (z = ... m), <names[v]>" for :class:`ConvergenceError`."""

    def where(j: int, v: int) -> str:
        return f"cell {j} (z = {z[j]:.4g} m), {names[v]}"

    return where


def scaled(F, scales):
    """The residual ``F`` (a :class:`~rotarykiln.kiln.residual.KilnResidual`) at the
    continuation parameters ``scales``, as the callable ``x -> F.evaluate(x, scales=scales)``
    Newton solves (``F`` itself is left as it is)."""
    return functools.partial(F.evaluate, scales=scales)


def ramp(
    scales_at: Callable[[float], object],
    steps=FIXED_STEPS,
    *,
    adaptive=False,
    max_failures: int | None = None,
):
    """A continuation stage: the residual solved at ``scales_at(value)`` (its
    :class:`~rotarykiln.kiln.inputs.boundary.Scales`) for ``value`` over ``steps`` (fixed
    values), or from 0 to 1 in adaptive steps (start 0.25, halved on failure down to 1/256,
    doubled on success up to 0.5) when ``adaptive``; ``max_failures`` failed steps end an
    adaptive stage with the last failure (a start on a coarse grid, where stalling at a fold
    costs more than the fine grid's own continuation). An adaptive stage gives an
    intermediate value (below 1) up when Newton stalls on it (``STEP_STALL``: a step too long
    then fails in a few iterations instead of 60, and is halved); its last value has the
    caller's iterations. Returns a callable ``stage(F, x, scale, kw) -> (x, iters)``.
    """

    def fixed(F, x, scale, kw):
        total = 0
        for value in steps:
            log.info("continuation: parameter %.4g", value)
            x, rep = newton.newton_banded(scaled(F, scales_at(value)), x, scale, **kw)
            total += rep.iterations
        return x, total

    def stepped(F, x, scale, kw):
        total, lam, step, failures = 0, 0.0, 0.25, 0
        start_kw = dict(kw, stall=STEP_STALL)
        while lam < 1.0:
            trial = min(1.0, lam + step)
            log.info("continuation: parameter %.4g (step %.4g)", trial, step)
            step_kw = kw if trial >= 1.0 else start_kw
            try:
                x_new, rep = newton.newton_banded(scaled(F, scales_at(trial)), x, scale, **step_kw)
            except ConvergenceError:
                step /= 2.0
                failures += 1
                if step < 1.0 / 256 or (max_failures is not None and failures >= max_failures):
                    raise
                continue
            total += rep.iterations
            x, lam = x_new, trial
            step = min(0.5, step * 2.0)
        return x, total

    return stepped if adaptive else fixed


def newton_with_continuation(F, x0, scale, continuation, **kw):
    """Newton from ``x0``; if it fails, ``continuation(F, x0, scale, kw) -> (x, iterations)``.

    Returns ``(x, total Newton iterations)``. ``kw`` go to
    :func:`rotarykiln.kiln.steady.newton.newton_banded`.
    """
    try:
        x, rep = newton.newton_banded(F, x0, scale, **kw)
        return x, rep.iterations
    except ConvergenceError as exc:
        log.info("Newton failed (%s): continuation", exc)
        return continuation(F, np.array(x0, dtype=float), scale, kw)


#: Grid sequencing: a grid of more than SEQUENCE_MIN cells starts from the solution on a grid
#: SEQUENCE_RATIO times coarser (itself sequenced), solved to SEQUENCE_TOL (only a start).
SEQUENCE_MIN = 30
SEQUENCE_RATIO = 5
SEQUENCE_TOL = 1e-6


#: A coarse cell holds a reaction front when a bed species flow falls across it by more than
#: FRONT_RATIO times (from above FRONT_FLOOR of the species' largest flow);
#: a stream's inlet cell holds a thermal front when its temperature changes across it by more
#: than INLET_JUMP_RATIO times as much as across the next cell. Solver-path constants (they
#: shape the fine grid's start, not the root it converges to): the first values tried, not
#: compared with others; the cement kiln's fronts exceed them by orders of magnitude (its meal
#: heated 80 times as much in the inlet cell of 40 as in the next, its Al2O3 falling 450 to
#: 5000 times a cell on 200).
FRONT_RATIO = 10.0
FRONT_FLOOR = 1e-6
INLET_JUMP_RATIO = 5.0


def front_cells(flows) -> np.ndarray:
    """Which cells of a grid hold a reaction front: a bed species flow (columns of ``flows``,
    at the faces 0..n in the bed's direction, kg/s) falls across the cell by more than
    FRONT_RATIO times (a reactant used up), from above FRONT_FLOOR of the species' largest
    flow. Boolean, one per cell. (A product rising from nothing is not a front: its profile
    is as linear as its rate.)

    Examples
    --------
    >>> front_cells(np.array([[1.0, 0.0], [0.5, 0.5], [1e-3, 1.0], [2e-4, 1.0]])).tolist()
    [False, True, False]
    """
    q = np.abs(np.asarray(flows, dtype=float))
    big = q[:-1] > FRONT_FLOOR * q.max(axis=0, initial=0.0)
    return ((q[:-1] > FRONT_RATIO * q[1:]) & big).any(axis=1)


def inlet_front(t) -> bool:
    """Whether a stream's temperatures ``t`` (K, at its faces in the direction it flows, inlet
    first) jump across the inlet cell: by more than INLET_JUMP_RATIO times as much as across
    the next cell (the feed heated within a fraction of a cell, a flame's gas within its first
    metre).

    Examples
    --------
    >>> inlet_front([1148.0, 1456.0, 1460.0]), inlet_front([300.0, 320.0, 335.0])
    (True, False)
    """
    t = np.asarray(t, dtype=float)
    return bool(len(t) > 2 and abs(t[1] - t[0]) > INLET_JUMP_RATIO * abs(t[2] - t[1]))


def _fronted(zs, zd, values, front, forward: bool) -> np.ndarray:
    """``values`` (coarse faces ``zs``, one column each) at the faces ``zd``: linear, except
    that a face inside a coarse cell marked in ``front`` takes the value of the cell's far end
    in the stream's direction (``forward``: towards +z), its near end being the only face
    before the front."""
    out = np.empty((len(zd), values.shape[1]))
    for m in range(values.shape[1]):
        out[:, m] = np.interp(zd, zs, values[:, m])
    if front.any():
        eps = 1e-12 * zs[-1]  # the grids' shared faces are computed apart
        if forward:  # cell c holds (z_c, z_c+1]
            cell = np.searchsorted(zs, zd - eps, side="left") - 1
            far = cell + 1
        else:  # cell c holds [z_c, z_c+1)
            cell = np.searchsorted(zs, zd + eps, side="right") - 1
            far = cell
        inside = (cell >= 0) & (cell < len(front))
        take = np.zeros(len(zd), dtype=bool)
        take[inside] = front[cell[inside]]
        out[take] = values[far[take]]
    return out


def interpolate_unknowns(src, x, dst) -> np.ndarray:
    """Unknowns of the kiln residual ``dst`` interpolated in z from the unknowns ``x`` of
    ``src`` (the same kiln on another grid), K and scaled flows.

    Face unknowns (bed temperature and species at faces 1..n, gas temperature and species
    where the gas leaves each cell) come from the face profiles of ``src.faces(x)``, inlet
    values included; the bed depth (if solved) from ``src.depth_faces(x)``; every other
    unknown (wall temperatures) is interpolated at the cell centres. Profiles are
    interpolated linearly, except across a front that ``src`` spreads over one of its cells:
    on a finer grid the front stands in the first fine cell (a rate or an exchange too fast
    for the coarse cell is faster still for a shorter one), so every face of ``dst`` inside
    such a cell takes the value past the front (:func:`_fronted`). Fronts are the cells where
    a bed species flow falls by decades (:func:`front_cells`; the gas species with them) and a
    stream's inlet cell when its temperature jumps there (:func:`inlet_front`). The cement
    kiln on 40 cells, carried to 200: the ferrite formed within the first metre of its hot
    meal, the meal heated by 300 K and the burner's gas by 1100 K within a cell leave a
    residual of 7e5 and Newton steps of 1500 K when interpolated linearly; these starts
    converge in 6-9 iterations.
    Residuals need ``n``, ``nv``, ``z``, ``z_nodes``, ``faces``, ``gas_out``, ``i_species``,
    ``nb``, ``bed_pos``, ``gas_pos``, ``sqrt_mask``, ``bed_scale``, ``gas_scale``,
    ``gas_in_face`` (and ``depth``, ``i_depth``).
    """
    tb, tg, qb, qg = src.faces(x)
    zs, zd = src.z_nodes, dst.z_nodes
    out = np.empty((dst.n, dst.nv))
    for v in range(dst.nv):
        out[:, v] = np.interp(dst.z, src.z, x[:, v])
    counter = dst.gas_in_face == -1
    bed, gas = qb[:, list(dst.bed_pos)], qg[:, list(dst.gas_pos)]
    species_front = front_cells(bed)
    bed_inlet, gas_inlet = np.zeros(src.n, dtype=bool), np.zeros(src.n, dtype=bool)
    bed_inlet[0] = inlet_front(tb[:3])
    gas_inlet[-1 if counter else 0] = inlet_front(tg[::-1][:3] if counter else tg[:3])

    out[:, 0] = _fronted(zs, zd, tb[:, None], bed_inlet, True)[1:, 0]
    out[:, 1] = _fronted(zs, zd, tg[:, None], gas_inlet, not counter)[dst.gas_out, 0]
    i0, nb = dst.i_species, dst.nb
    q = _fronted(zs, zd, bed, species_front, True)[1:] / dst.bed_scale
    mask = np.asarray(dst.sqrt_mask, dtype=bool)
    q[:, mask] = np.sqrt(np.maximum(q[:, mask], 0.0))
    out[:, i0 : i0 + nb] = q
    # a bed front's gas (the CO2 it releases) enters the gas at the front: gas faces past it
    # in the bed's direction have not had it if the gas flows against the bed, have if with it
    gas_faces = _fronted(zs, zd, gas, species_front, True)
    out[:, i0 + nb : i0 + nb + len(dst.gas_pos)] = gas_faces[dst.gas_out] / dst.gas_scale
    if getattr(dst, "depth", None) is not None:
        out[:, dst.i_depth] = np.interp(zd, zs, src.depth_faces(x))[:-1]
    return out


def _relaxed(F, x, scale, kw) -> np.ndarray:
    """The start ``x`` of ``F`` interpolated from a coarser grid, its local unknowns (the
    Newton option ``local``) relaxed first (:func:`~rotarykiln.kiln.steady.newton.relax_local`)."""
    local = kw.get("local")
    if local is None or not np.any(local):
        return x
    return newton.relax_local(
        F, x, scale, local, max_step=kw.get("max_step", 300.0), lower=kw.get("lower", 160.0)
    )


def _newton_retried(F, x, scale, kw, retry_options):
    """Newton on ``F`` from ``x`` with the options ``kw``, and if it fails once more with
    ``retry_options`` over them (when given): ``(x, report)``, or None if both fail."""
    for options in ({}, retry_options) if retry_options else ({},):
        try:
            return newton.newton_banded(F, x, scale, **dict(kw, **options))
        except ConvergenceError:
            pass
    return None


def newton_sequenced(
    F,
    x0,
    scale,
    continuation,
    *,
    make_residual: Callable[[int], object],
    continuation_of: Callable[[object], Callable] | None = None,
    min_cells: int = SEQUENCE_MIN,
    ratio: int = SEQUENCE_RATIO,
    coarse_tol: float = SEQUENCE_TOL,
    retry_options: dict | None = None,
    **kw,
):
    """:func:`newton_with_continuation` on the kiln residual ``F`` from a grid-sequenced start.

    For more than ``min_cells`` cells the guess ``x0`` is carried to a grid ``ratio`` times
    coarser (``make_residual(n)`` builds the residual of the same kiln on ``n`` cells, its
    ``q_ref`` set), solved there by plain Newton to ``coarse_tol`` (itself from a sequenced
    start) and interpolated back (:func:`interpolate_unknowns`); Newton on ``F`` then starts
    there and converges to ``kw["tol"]`` as usual. The coarsest grid, where Newton from the
    guess fails, is solved with the continuation ``continuation_of(R)`` of its own residual
    (when given: cheap there, and the finer grids then start from its solution). If the fine
    Newton fails from the coarse start, it is tried once more with ``retry_options`` (other
    keyword options of the Newton solver) when given. If the coarse or the fine Newton fails,
    the solve falls back to :func:`newton_with_continuation` from ``x0`` (the path without
    sequencing), so only the time changes.

    Returns ``(x, Newton iterations on the grid of F)``.
    """
    if F.n > min_cells:
        coarse_kw = dict(kw, tol=coarse_tol, where=None, max_iter=min(kw.get("max_iter", 60), 25))

        def solved(R, x_start):
            """Unknowns of R (Newton from a sequenced start), None if Newton fails."""
            coarsest = R.n <= min_cells
            if not coarsest:
                C = make_residual(max(R.n // ratio, 4))
                xc = solved(C, interpolate_unknowns(R, x_start, C))
                if xc is not None:
                    x_start = _relaxed(R, interpolate_unknowns(C, xc, R), scale, kw)
            if coarsest and continuation_of is not None:
                try:
                    return newton_with_continuation(
                        R, x_start, scale, continuation_of(R), **coarse_kw
                    )[0]
                except ConvergenceError:
                    return None
            done = _newton_retried(R, x_start, scale, coarse_kw, retry_options)
            return None if done is None else done[0]

        C = make_residual(max(F.n // ratio, 4))
        log.info("grid sequencing: a start from %d cells for %d", C.n, F.n)
        xc = solved(C, interpolate_unknowns(F, np.asarray(x0, dtype=float), C))
        if xc is not None:
            start = _relaxed(F, interpolate_unknowns(C, xc, F), scale, kw)
            done = _newton_retried(F, start, scale, kw, retry_options)
            if done is not None:
                return done[0], done[1].iterations
    return newton_with_continuation(F, x0, scale, continuation, **kw)


def check_finite(profiles: dict, per_cell: dict, z, iterations: int) -> None:
    """Raise :class:`ConvergenceError` if a profile or a per-cell array is not finite."""
    for name, arr in profiles.items():
        if not np.isfinite(arr).all():
            raise ConvergenceError(f"non-finite {name} in the solution", iterations=iterations)
    for key, arr in per_cell.items():
        if not np.isfinite(arr).all():
            j = int(np.argmax(~np.isfinite(arr)))
            raise ConvergenceError(
                f"non-finite {key} in cell {j} (z = {z[j]:.4g} m)", iterations=iterations
            )


def profile_fields(grid, t_bed_nodes, t_gas_nodes, t_wall, fluxes: dict, R, scale, iterations):
    """Fields of a kiln solution from the solver: faces and cells, temperatures, fluxes, solver.

    ``t_wall``: the wall unknowns (K, ``(n, n_wall)``, inner surface first); ``fluxes``: the
    per-cell dict of the residual (its ``t_bed_mean`` and ``t_gas_mean`` become ``t_bed`` and
    ``t_gas``); ``R``: the final residual, judged against ``scale``.
    """
    return dict(
        z_nodes=grid.z_nodes,
        t_bed_nodes=np.asarray(t_bed_nodes, dtype=float),
        t_gas_nodes=np.asarray(t_gas_nodes, dtype=float),
        z=grid.z,
        t_bed=fluxes.pop("t_bed_mean"),
        t_gas=fluxes.pop("t_gas_mean"),
        t_wall=t_wall[:, 0].copy(),
        t_lining=t_wall.T.copy(),
        fluxes=fluxes,
        iterations=iterations,
        residual=float(np.max(np.abs(R))) / scale,
    )
