r"""Damped Newton solver for block-tridiagonal systems with a banded, coloured FD Jacobian.

The unknowns are arranged as ``x[j, v]`` (cell ``j``, variable ``v``) and the residual of cell
``j`` depends on cells ``j-1, j, j+1`` only. The Jacobian is then banded with half-bandwidth
``2 nv - 1`` in the flattened ordering. It is built by finite differences with ``3 nv``
colours (cells ``j = c mod 3`` perturbed together for one variable), all colours evaluated in
one vectorised residual call (the residual broadcasts over a leading batch axis), and factorised
by :func:`scipy.linalg.solve_banded`. Steps are damped by a backtracking line search on the
residual norm and limited to ``max_step`` kelvin per unknown.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy.linalg import solve_banded

from rotarykiln.errors import ConvergenceError

log = logging.getLogger(__name__)

__all__ = [
    "NewtonReport",
    "band_entries",
    "colour_batch",
    "coloured_pattern",
    "newton_banded",
    "positive_roots",
    "relax_local",
    "trial_point",
]

#: A Newton iteration whose line search cannot reduce a residual already within this factor of
#: the tolerance has reached round-off: it is accepted as converged.
STAGNATION_FACTOR = 10.0
#: A squared unknown (x = sqrt(q)) steps as q, by Newton in q, and keeps at least this
#: fraction of its q when that step would cross zero.
SQUARED_FLOOR = 1e-3
#: The line search halves a step at most HALVINGS times (down to 2^-30 of it); with ``stall``
#: (a continuation's intermediate step, given up when it does not converge fast) at most
#: STALL_HALVINGS (2^-10): a step that needs less is too long and is halved by the
#: continuation, and every halving costs a residual evaluation (the cement kiln's 8-cell start:
#: 92 evaluations, 80 ms, mostly on steps that failed; 52 with this). Such a step whose Newton
#: step would move a temperature by more than max_step 2^STALL_HALVINGS is given up at once.
#: STALL_HALVINGS is a solver-path constant, tried at one value only (the smallest step a
#: continuation step of the cement kiln was seen to take is 0.0074, about 2^-7).
HALVINGS = 30
STALL_HALVINGS = 10
#: A logged unknown's decrease is taken in its logarithm, x exp(dx/x), with dx/x not below
#: this (exp(-600) ~ 1e-261: far below any flow a kiln carries, and no underflow).
LOG_STEP_FLOOR = -600.0


@dataclass(frozen=True)
class NewtonReport:
    """How the Newton solve went: ``iterations``, ``residual`` (max scaled), ``history``."""

    iterations: int
    residual: float
    history: tuple[float, ...]
    jacobian_evaluations: int


@lru_cache(maxsize=16)
def _jacobian_pattern(n: int, nv: int):
    """Flat indices of the coloured FD Jacobian of ``n`` cells of ``nv`` unknowns.

    ``perturbed``: the entries of the batch ``X[c, v, j, w]`` (colour ``c = j mod 3``,
    variable ``v``) that carry the step; ``src``, ``dst``, ``step``: for every band entry
    d R[r, w] / d x[j, v] (``r = j - 1, j, j + 1``), its place in the flattened residual
    differences ``dR[c, v, r, w]``, in the flattened banded matrix (``solve_banded`` layout,
    ``ab[bw + r nv + w - j nv - v, j nv + v]``) and in the flattened steps ``h[j, v]``.
    """
    cells = np.arange(n)
    var = np.arange(nv)
    colour = cells % 3
    perturbed = ((colour[:, None] * nv + var[None, :]) * n + cells[:, None]) * nv + var[None, :]
    size = n * nv
    bw = 2 * nv - 1
    src, dst, step = [], [], []
    for off in (-1, 0, 1):
        j = cells[max(0, -off) : n - max(0, off)][:, None, None]
        v = var[None, :, None]
        w = var[None, None, :]
        c = j % 3
        src.append((((c * nv + v) * n + (j + off)) * nv + w).ravel())
        dst.append(((bw + off * nv + w - v) * size + (j * nv + v)).ravel())
        step.append(np.broadcast_to(j * nv + v, (j.shape[0], nv, nv)).ravel())
    return perturbed.ravel(), np.concatenate(src), np.concatenate(dst), np.concatenate(step)


def colour_batch(x, h):
    """The ``3 nv`` coloured perturbations of ``x`` (n, nv) by the steps ``h`` (n, nv): colour
    ``(c, v)`` perturbs variable ``v`` of the cells ``j = c mod 3``, ``X[c nv + v, j, v] =
    x[j, v] + h[j, v]``; a residual of the batch gives every band entry once."""
    n, nv = x.shape
    perturbed = _jacobian_pattern(n, nv)[0]
    X = np.broadcast_to(x, (3 * nv, n, nv)).copy()
    X.ravel()[perturbed] = (x + h).ravel()
    return X


@lru_cache(maxsize=16)
def band_entries(n: int, nv: int):
    """``src``, ``rows``, ``cols``, ``step`` of every band entry of the coloured Jacobian of
    :func:`colour_batch`: its place in the flattened differences ``dR[c, v, r, w]``, its row
    ``r nv + w`` and column ``j nv + v`` in the flattened unknowns, and its step in ``h``
    flattened (for a sparse matrix; :func:`_banded_jacobian` fills the banded layout)."""
    _, src, dst, step = _jacobian_pattern(n, nv)
    size, bw = n * nv, 2 * nv - 1
    cols = dst % size
    rows = cols + dst // size - bw
    return src, rows, cols, step


@lru_cache(maxsize=16)
def coloured_pattern(n: int, nv: int, local: tuple[bool, ...]):
    """Colouring of the banded Jacobian of ``n`` cells of ``nv`` unknowns when the unknowns
    ``local`` act on their own cell's rows only: 3 colours (cells ``j mod 3``) per other
    unknown, one (every cell) per local one.

    Returns ``colours``, ``perturbed`` (flat indices into the perturbed unknowns ``(colours,
    n, nv)``, one per unknown ``(j, v)``), and for every band entry its place in the
    flattened differences ``dR[colour, r, w]`` (``src``), in the flattened banded matrix
    (``dst``, the layout of :func:`scipy.linalg.solve_banded` with half-bandwidth ``2 nv -
    1``) and in the flattened steps ``h[j, v]`` (``step``).
    """
    local = np.asarray(local, dtype=bool)
    first = np.cumsum([0] + [1 if loc else 3 for loc in local])[:-1]  # first colour of v
    colours = int(sum(1 if loc else 3 for loc in local))
    cells, var = np.arange(n), np.arange(nv)
    colour = np.where(local[None, :], first[None, :], first[None, :] + cells[:, None] % 3)
    perturbed = ((colour * n + cells[:, None]) * nv + var[None, :]).ravel()
    size, bw = n * nv, 2 * nv - 1
    src, dst, step = [], [], []
    for off in (-1, 0, 1):
        j = cells[max(0, -off) : n - max(0, off)][:, None, None]
        for v in range(nv):
            if off and local[v]:
                continue  # a local unknown: no entry outside its own cell's rows
            w = var[None, None, :]
            c = colour[j[:, 0, 0], v][:, None, None]
            src.append((((c * n) + (j + off)) * nv + w).ravel())
            dst.append(((bw + off * nv + w - v) * size + (j * nv + v)).ravel())
            step.append(np.broadcast_to(j * nv + v, (j.shape[0], 1, nv)).ravel())
    return colours, perturbed, np.concatenate(src), np.concatenate(dst), np.concatenate(step)


def _banded_jacobian(F, x, R0, rel_step=1e-7, step_floor=1.0, local=None):
    """The banded Jacobian of ``F`` at ``x`` by coloured forward differences, the unknowns
    ``local`` (bool per variable, :func:`coloured_pattern`) one colour each: the same
    entries."""
    n, nv = x.shape
    h = rel_step * np.maximum(np.abs(x), step_floor)
    loc = tuple(bool(v) for v in (np.zeros(nv, bool) if local is None else local))
    colours, perturbed, src, dst, step = coloured_pattern(n, nv, loc)

    X = np.broadcast_to(x, (colours, n, nv)).copy()
    X.ravel()[perturbed] = (x + h).ravel()
    dR = F(X) - R0  # [colour, row cell, equation]
    bw = 2 * nv - 1
    ab = np.zeros((2 * bw + 1, n * nv))
    ab.ravel()[dst] = dR.ravel()[src] / h.ravel()[step]
    return ab, bw


def positive_roots(x: np.ndarray, roots) -> np.ndarray | None:
    """The root unknowns ``roots`` of ``x`` set to their absolute values in place: the same
    flows, :math:`q = s^2`, on the branch where a forward difference does not straddle zero
    (:func:`newton_banded`, ``roots``).

    Parameters
    ----------
    x : array (..., nv)
        Unknowns (K for temperatures, - for scaled flows and their roots), changed in place.
    roots : array of bool (nv,) or of int, or None
        The root unknowns (-): a mask per variable or their column indices.

    Returns
    -------
    array of int or None
        The roots' column indices (-), None without roots.

    Examples
    --------
    >>> x = np.array([[300.0, -2e-9], [310.0, 1e-3]])
    >>> positive_roots(x, np.array([False, True])).tolist(), x[:, 1].tolist()
    ([1], [2e-09, 0.001])

    References
    ----------
    P. Deuflhard, Newton Methods for Nonlinear Problems, Springer (2004), sec. 3.2 (Newton
    steps in transformed variables).
    """
    if roots is None:
        return None
    cols = np.asarray(roots)
    if cols.dtype == bool:
        cols = np.flatnonzero(cols)
    if cols.size == 0:
        return None
    x[..., cols] = np.abs(x[..., cols])
    return cols


def trial_point(x, dx, lam, sq, lg):
    """The trial point ``x + lam dx`` of a Newton step, the squared unknowns ``sq`` stepped in
    their square (kept above ``SQUARED_FLOOR`` of it) and the logged ones ``lg`` lowered in
    their logarithm (:func:`newton_banded`).

    Parameters
    ----------
    x : array (n, nv)
        Unknowns (K for temperatures, - for scaled flows).
    dx : array (n, nv)
        Newton step (K, -).
    lam : float
        Step length, - (1: the full step).
    sq : array of int or None
        Columns stepped in their square (-).
    lg : array of int or None
        Columns lowered in their logarithm, ``x exp(lam dx / x)`` where ``dx / x < 0`` (-).

    Returns
    -------
    array (n, nv)
        The trial unknowns (K, -).

    Examples
    --------
    >>> x = np.array([[2.0, 1e-3]])
    >>> trial_point(x, np.array([[-4.0, -2e-3]]), 1.0, None, np.array([1])).round(8).tolist()
    [[-2.0, 0.00013534]]

    References
    ----------
    P. Deuflhard, Newton Methods for Nonlinear Problems, Springer (2004), sec. 3.2 (damped
    Newton steps in transformed variables).
    """
    xt = x + lam * dx
    if sq is not None:
        s = x[:, sq]
        q = np.maximum(s * s + lam * 2.0 * s * dx[:, sq], SQUARED_FLOOR * s * s)
        xt[:, sq] = np.copysign(np.sqrt(q), s)
    if lg is not None:
        s = x[:, lg]
        safe = np.where(s != 0.0, s, 1.0)
        r = np.where(s != 0.0, lam * dx[:, lg] / safe, 0.0)
        down = s * np.exp(np.maximum(r, LOG_STEP_FLOOR))
        xt[:, lg] = np.where(r < 0.0, down, xt[:, lg])
    return xt


def relax_local(
    F,
    x,
    scale: float,
    local,
    *,
    iterations: int = 3,
    rel_step: float = 1e-7,
    max_step: float = 300.0,
    lower: float = 160.0,
):
    """``x`` with its local unknowns (``local``: bool per variable, the unknowns that act on
    their own cell's rows only, such as a lining's radial temperatures) relaxed by
    ``iterations`` Newton steps on their own rows, every other unknown held: block-Jacobi
    Newton, each cell's small block solved apart (the local unknowns are temperatures, K).
    The blocks come from one residual call of one perturbation per local variable (all cells
    at once), so a step costs
    ``1 + sum(local)`` cell-wise evaluations, not a banded Jacobian's ``3 nv``. Temperature
    steps are limited to ``max_step`` and kept above ``lower`` (K), as in
    :func:`newton_banded`. Returns ``x`` unchanged when the relaxed point does not lower the
    largest residual (``max|F| / scale``) or a block is singular.

    The start of a fine grid interpolated from a coarse one (grid sequencing): a wall whose
    layers change within a coarse cell (a coating starting at 40 m of the cement kiln) is
    interpolated across the change, and its rows then hold the largest residual; relaxed
    first, Newton takes full steps from the start.

    Parameters
    ----------
    F : callable
        Residual, broadcasting over a leading batch axis (as :func:`newton_banded`'s).
    x : array (n, nv)
        Unknowns (K for temperatures, - for scaled flows).
    scale : float
        Residuals are judged as ``max|F| / scale`` (W for the kiln).
    local : array of bool (nv,)
        The local unknowns (temperatures, K).
    iterations : int
        Newton steps on the local rows.
    rel_step : float
        Finite-difference steps ``rel_step max(|x|, 1)``, K.
    max_step, lower : float
        Largest temperature step, and the floor of a temperature, K.

    Returns
    -------
    array (n, nv)
        The unknowns, the local ones relaxed (K, -).

    Examples
    --------
    Two cells of one bed temperature and one local wall temperature relaxed to the wall's
    own balance (the wall halfway between the bed and 300 K):

    >>> def F(x):
    ...     return np.stack([x[..., 0] - 500.0, x[..., 1] - 0.5 * (x[..., 0] + 300.0)], -1)
    >>> x = relax_local(F, np.array([[500.0, 900.0], [500.0, 350.0]]), 1.0, [False, True])
    >>> x.round(6).tolist()
    [[500.0, 400.0], [500.0, 400.0]]

    References
    ----------
    J.M. Ortega, W.C. Rheinboldt, Iterative Solution of Nonlinear Equations in Several
    Variables, Academic Press (1970), sec. 7.4 (nonlinear block-Jacobi and Newton-Jacobi
    iterations).
    """
    loc = np.flatnonzero(np.asarray(local, dtype=bool))
    x = np.array(x, dtype=float)
    R = F(x)
    norm0 = float(np.max(np.abs(R))) / scale
    if loc.size == 0 or not np.isfinite(norm0):
        return x
    xt, Rt = x, R
    for _ in range(iterations):
        h = rel_step * np.maximum(np.abs(xt[:, loc]), 1.0)
        X = np.broadcast_to(xt, (loc.size, *xt.shape)).copy()
        X[np.arange(loc.size), :, loc] += h.T
        dR = F(X)[..., loc] - Rt[:, loc]  # [variable, cell, row]
        J = np.transpose(dR, (1, 2, 0)) / h[:, None, :]  # [cell, row, variable]
        try:
            dx = np.linalg.solve(J, -Rt[:, loc, None])[..., 0]
        except np.linalg.LinAlgError:
            return x
        big = float(np.max(np.abs(dx)))
        if not np.isfinite(big):
            return x
        lam = min(1.0, max_step / big) if big > 0 else 1.0
        xt = xt.copy()
        xt[:, loc] = np.maximum(xt[:, loc] + lam * dx, lower)
        Rt = F(xt)
    norm = float(np.max(np.abs(Rt))) / scale
    return xt if np.isfinite(norm) and norm < norm0 else x


def newton_banded(
    F,
    x0,
    scale: float,
    *,
    tol: float = 1e-10,
    max_iter: int = 60,
    max_step: float = 300.0,
    lower: float = 160.0,
    temperature_vars: int | None = None,
    where=None,
    step_floor=1.0,
    squared=None,
    stall=None,
    local=None,
    logged=None,
    roots=None,
):
    """Solve ``F(x) = 0`` for ``x`` of shape ``(n, nv)``.

    Parameters
    ----------
    F : callable
        Residual, broadcasting over a leading batch axis.
    x0 : array (n, nv)
        Initial guess.
    scale : float
        Residuals are judged as ``max|F| / scale`` (W for the kiln: a reference heat flow).
    tol : float
        Convergence when ``max|F|/scale <= tol``.
    max_iter : int
        Largest number of Newton iterations.
    max_step : float
        Largest change of a temperature unknown per iteration, K.
    lower : float
        Temperatures are kept above this value, K.
    temperature_vars : int
        The first ``temperature_vars`` variables are temperatures (step limited, floored).
    where : callable(j, v) -> str
        Describes unknown ``(j, v)`` for error messages.
    step_floor : float or array (nv,)
        Finite-difference steps are ``1e-7 max(|x|, step_floor)`` (per variable): a small
        floor resolves unknowns that approach 0 (species flows near full conversion).
    squared : array of bool (nv,), optional
        Variables that are the square root ``s`` of a positive quantity ``q = s^2``: they step
        by Newton in ``q`` (``q + 2 s ds``, the same linear solve), kept above
        ``SQUARED_FLOOR q``. For a residual linear in ``q`` whose root is near ``q = 0`` (a
        first-order reactant used up), Newton in ``s`` only halves ``s`` per iteration.
    stall : (int, float), optional
        ``(k, f)``: give up after ``k`` iterations if the residual is not below ``f`` times
        where it started (a continuation step too long for Newton then costs ``k`` iterations,
        not ``max_iter``; one that converges slowly still may); its line search halves a step
        at most STALL_HALVINGS times.
    local : array of bool (nv,), optional
        Variables acting on their own cell's rows only (a wall's radial temperatures): one
        colour of the Jacobian each instead of three (the same Jacobian, fewer residual
        evaluations; :func:`coloured_pattern`).
    logged : array of bool (nv,), optional
        Variables that are positive and may fall by orders of magnitude within a cell (a
        reactant's root flow across the end of its reaction front): a step that lowers one
        is taken in its logarithm, ``x exp(dx / x)`` (the same linear solve; an increase
        stays ``x + dx``), so it never crosses zero and can fall by decades in one step where
        Newton's straight step would overshoot through zero. The line search tries these
        steps first and, if none of them lowers the residual, the straight ones
        (:func:`trial_point`).
    roots : array of bool (nv,), optional
        Variables that enter ``F`` only through their square (the root ``s`` of a flow
        ``s^2``): ``F`` is even in each, so its sign is arbitrary. They are kept on the
        positive branch, ``|s|`` (the same residual), at the start and at every trial point:
        a root that a straight step carried below zero near the end of its reaction front
        would otherwise be differenced across the kink of its rate in ``|s|`` at zero (a
        forward step larger than ``|s|``), and its Jacobian column would have the wrong sign
        (the cement kiln's CaCO3 rows: two extra Newton iterations at round-off).

    Returns
    -------
    x : array (n, nv)
    report : NewtonReport

    Raises
    ------
    ConvergenceError
        With the iterations, the residual and the cell/equation where it is largest.

    Examples
    --------
    Six nodes of a conducting chain between 300 K and 1000 K (one unknown per cell, each
    residual coupling a cell to its neighbours):

    >>> def F(x):
    ...     ends = np.ones(x.shape[:-2] + (1, 1))
    ...     t = np.concatenate([300.0 * ends, x, 1000.0 * ends], axis=-2)
    ...     return t[..., :-2, :] - 2.0 * t[..., 1:-1, :] + t[..., 2:, :]
    >>> x, report = newton_banded(F, np.full((6, 1), 600.0), 1.0)
    >>> x[:, 0].round(6).tolist(), report.iterations
    ([400.0, 500.0, 600.0, 700.0, 800.0, 900.0], 1)

    References
    ----------
    A.R. Curtis, M.J.D. Powell, J.K. Reid, J. Inst. Math. Appl. 13 (1974) 117-119 (coloured
    finite-difference Jacobians); J.E. Dennis, R.B. Schnabel, Numerical Methods for
    Unconstrained Optimization and Nonlinear Equations, Prentice-Hall (1983), ch. 6
    (backtracking line search).
    """
    x = np.array(x0, dtype=float)
    n, nv = x.shape
    nt = nv if temperature_vars is None else temperature_vars
    sq = None if squared is None or not np.any(squared) else np.flatnonzero(squared)
    lg = None if logged is None or not np.any(logged) else np.flatnonzero(logged)
    rt = positive_roots(x, roots)
    R = F(x)
    norm = float(np.max(np.abs(R))) / scale
    history = [norm]
    n_jac = 0
    log.info("Newton on %d cells x %d unknowns: residual %.3g (tolerance %.3g)", n, nv, norm, tol)
    for it in range(1, max_iter + 1):
        if norm <= tol:
            log.info("Newton converged in %d iterations: residual %.3g", it - 1, norm)
            return x, NewtonReport(it - 1, norm, tuple(history), n_jac)
        if not np.isfinite(norm):
            break
        ab, bw = _banded_jacobian(F, x, R, step_floor=step_floor, local=local)
        n_jac += 1
        try:
            dx = solve_banded((bw, bw), ab, -R.ravel(), check_finite=False).reshape(n, nv)
        except (np.linalg.LinAlgError, ValueError):
            break
        if not np.all(np.isfinite(dx)):
            break
        big = np.max(np.abs(dx[:, :nt])) if nt else 0.0
        lam = min(1.0, max_step / big) if big > 0 else 1.0
        if stall is not None and lam < 0.5**STALL_HALVINGS:
            # a continuation's step whose Newton step moves a temperature by more than
            # max_step 2^STALL_HALVINGS (3e5 K): too long a step, given up at once
            break
        accepted = False
        lam0 = lam
        for logs in (lg, None) if lg is not None else (None,):
            lam = lam0
            for _ in range(STALL_HALVINGS if stall is not None else HALVINGS):
                xt = trial_point(x, dx, lam, sq, logs)
                xt[:, :nt] = np.maximum(xt[:, :nt], lower)
                positive_roots(xt, rt)
                Rt = F(xt)
                nt_norm = float(np.max(np.abs(Rt))) / scale
                if np.isfinite(nt_norm) and (nt_norm < (1 - 1e-4 * lam) * norm or nt_norm <= tol):
                    accepted = True
                    break
                lam *= 0.5
            if accepted:
                break
        if not accepted:
            if norm <= STAGNATION_FACTOR * tol:
                # Newton stalls at round-off just above the tolerance (e.g. the rows of a
                # species consumed to ~1e-70 kg/s): the solution is as converged as the
                # arithmetic allows; the callers' balance checks still apply
                return x, NewtonReport(it - 1, norm, tuple(history), n_jac)
            # take the smallest step anyway if it does not blow up; else give up
            if not np.isfinite(nt_norm) or nt_norm > 10 * norm:
                break
        x, R, norm = xt, Rt, nt_norm
        history.append(norm)
        log.info("  Newton iteration %d: residual %.3g (step %.3g)", it, norm, lam)
        if stall is not None and it >= stall[0] and norm > tol and norm > stall[1] * history[0]:
            log.info("Newton stalls: residual %.3g after %d iterations", norm, it)
            break
    j, v = (
        np.unravel_index(int(np.argmax(np.abs(R))), R.shape) if np.all(np.isfinite(R)) else (0, 0)
    )
    loc = where(int(j), int(v)) if where is not None else f"cell {j}, equation {v}"
    raise ConvergenceError(
        f"steady kiln solve did not converge; largest residual at {loc}",
        iterations=len(history) - 1,
        residual=norm,
        tolerance=tol,
        location=loc,
    )
