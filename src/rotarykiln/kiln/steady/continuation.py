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


def interpolate_unknowns(src, x, dst) -> np.ndarray:
    """Unknowns of the kiln residual ``dst`` interpolated in z from the unknowns ``x`` of
    ``src`` (the same kiln on another grid), K and scaled flows.

    Face unknowns (bed temperature and species at faces 1..n, gas temperature and species
    where the gas leaves each cell) come from the face profiles of ``src.faces(x)``, inlet
    values included; the bed depth (if solved) from ``src.depth_faces(x)``; every other
    unknown (wall temperatures) is interpolated at the cell centres. Residuals need ``n``,
    ``nv``, ``z``, ``z_nodes``, ``faces``, ``gas_out``, ``i_species``, ``nb``, ``bed_pos``,
    ``gas_pos``, ``sqrt_mask``, ``bed_scale``, ``gas_scale`` (and ``depth``, ``i_depth``).
    """
    tb, tg, qb, qg = src.faces(x)
    zs, zd = src.z_nodes, dst.z_nodes
    out = np.empty((dst.n, dst.nv))
    for v in range(dst.nv):
        out[:, v] = np.interp(dst.z, src.z, x[:, v])
    out[:, 0] = np.interp(zd, zs, tb)[1:]
    out[:, 1] = np.interp(zd, zs, tg)[dst.gas_out]
    i0, nb = dst.i_species, dst.nb
    for m, p in enumerate(dst.bed_pos):
        q = np.interp(zd, zs, qb[:, p])[1:] / dst.bed_scale
        out[:, i0 + m] = np.sqrt(np.maximum(q, 0.0)) if dst.sqrt_mask[m] else q
    for m, p in enumerate(dst.gas_pos):
        out[:, i0 + nb + m] = np.interp(zd, zs, qg[:, p])[dst.gas_out] / dst.gas_scale
    if getattr(dst, "depth", None) is not None:
        out[:, dst.i_depth] = np.interp(zd, zs, src.depth_faces(x))[:-1]
    return out


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
                    x_start = interpolate_unknowns(C, xc, R)
            try:
                if coarsest and continuation_of is not None:
                    return newton_with_continuation(
                        R, x_start, scale, continuation_of(R), **coarse_kw
                    )[0]
                return newton.newton_banded(R, x_start, scale, **coarse_kw)[0]
            except ConvergenceError:
                return None

        C = make_residual(max(F.n // ratio, 4))
        log.info("grid sequencing: a start from %d cells for %d", C.n, F.n)
        xc = solved(C, interpolate_unknowns(F, np.asarray(x0, dtype=float), C))
        if xc is not None:
            start = interpolate_unknowns(C, xc, F)
            for options in ({}, retry_options) if retry_options else ({},):
                try:
                    x, rep = newton.newton_banded(F, start, scale, **dict(kw, **options))
                    return x, rep.iterations
                except ConvergenceError:
                    pass
    return newton_with_continuation(F, x0, scale, continuation, **kw)


def check_finite(profiles: dict, per_cell: dict, z, iterations: int) -> None:
    """Raise :class:`ConvergenceError` if a profile or a per-cell array is not finite."""
    for name, arr in profiles.items():
        if not np.all(np.isfinite(arr)):
            raise ConvergenceError(f"non-finite {name} in the solution", iterations=iterations)
    for key, arr in per_cell.items():
        if not np.all(np.isfinite(arr)):
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
