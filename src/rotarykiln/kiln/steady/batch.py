r"""Steady solves of many kilns at once: a leading case axis through the one residual.

A study solves one kiln at many operating points. Every point is its own Newton system, but
the residual of one kiln costs about as much for one cell as for a hundred (numpy's call
overhead), so the points are solved together: the unknowns of B kilns of one *model
structure* (the same grid, sections, species, closures and wall: the same
:class:`~rotarykiln.kiln.residual.KilnResidual` but for its inputs) form one array ``(B, n,
nv)``, and one residual evaluation serves them all (their
:class:`~rotarykiln.kiln.inputs.boundary.BoundaryInputs` stacked along the case axis: feed,
gas inlet, heat released and its profile, rotation, solids speed and dispersion).

The Newton iteration is :func:`~rotarykiln.kiln.steady.newton.newton_banded`'s, per case:
the coloured banded finite-difference Jacobian (all cases' colours in one residual call), a
banded solve per case, a backtracking line search per case (the cases still searching
re-evaluated together), each case's own convergence test; converged and failed cases leave
the batch. Each case's unknowns are scaled by its own inlet flows and its rows by its own
reference heat, so the iterates are those of the case solved alone (to round-off).

Cases start from the nearest solved case (in their scaled inputs), the first of each
structure solved alone with the full continuation; a case whose Newton iteration fails in the
batch is retried alone by :func:`~rotarykiln.kiln.steady.solve.solve_kiln` (continuation,
grid sequencing) and, if that fails too, returns its own
:class:`~rotarykiln.errors.ConvergenceError`, never the batch's.
"""

from __future__ import annotations

import contextlib
import dataclasses
import logging
import math
import warnings
from collections.abc import Callable, Sequence

import numpy as np
from scipy.linalg import lapack

from rotarykiln.errors import ConvergenceError, InputError, OutOfRangeWarning
from rotarykiln.kiln.gas_mixture import CaseMixtures
from rotarykiln.kiln.inputs import Kiln
from rotarykiln.kiln.inputs.boundary import BoundaryInputs
from rotarykiln.kiln.residual import KilnResidual, cell_evaluations
from rotarykiln.kiln.results.solution import KilnSolution
from rotarykiln.kiln.steady.newton import (
    SQUARED_FLOOR,
    STAGNATION_FACTOR,
    coloured_pattern,
    positive_roots,
)
from rotarykiln.kiln.steady.solve import finish_solution, newton_options, solve_kiln

log = logging.getLogger(__name__)

__all__ = [
    "solve_batch",
    "same_structure",
    "structure_groups",
    "batch_residuals",
    "batch_size_for",
    "BatchResidual",
]

#: Memory the batched Jacobian may take, bytes (the batch size is reduced to fit it).
BATCH_MEMORY = 256 * 2**20
#: Bytes per Jacobian entry ``(case, colour, cell, unknown)`` a residual evaluation needs at
#: its peak (its temporaries). Measured with tracemalloc on a batch of 20 cases (2026-12-04,
#: the local unknowns one colour each): 95 (Tscheng A16), 137 (Barr T4), 242
#: (limestone_fired), 141 (the cement kiln); 400 leaves room for a kiln with more species or
#: reactions.
BYTES_PER_ENTRY = 400
#: A kept Jacobian (chord iteration) is evaluated again after a step that reduced the
#: residual by less than this factor.
CHORD_RATE = 0.1
#: With Broyden updates, a kept Jacobian is evaluated again after a step that reduced the
#: residual by less than this factor. Chosen among 0.1, 0.3, 0.5 and 0.8 by the residual
#: evaluations a case needed (Tscheng A16 at 500 operating points, Barr T4 at 200: 0.5 and 0.8
#: close, 0.1 the most); it changes the path, not the root each case converges to.
BROYDEN_RATE = 0.5
#: Broyden updates of a kept Jacobian in a batch's Newton iteration (:func:`newton_batch`),
#: not compared with other values.
BROYDEN_UPDATES = 12
#: Kiln fields that are the boundary inputs of a batch (they may differ between its cases).
BOUNDARY_FIELDS = frozenset(
    {
        "name",
        "measurements",
        "feed.flows",
        "feed.temperature",
        "gas.flows",
        "gas.temperature",
        "firing.heat_release",
        "firing.profile",
        "firing.flame",
        "drum.omega",
        "bed.velocity",
        "bed.dispersion",
    }
)


def _equal(a, b, path: str = "") -> bool:
    """Deep equality of two kiln input trees, but for the :data:`BOUNDARY_FIELDS`."""
    if path in BOUNDARY_FIELDS or a is b:
        return True
    if dataclasses.is_dataclass(a) and not isinstance(a, type):
        if type(a) is not type(b):
            return False
        return all(
            _equal(getattr(a, f.name), getattr(b, f.name), f"{path}.{f.name}".lstrip("."))
            for f in dataclasses.fields(a)
        )
    if isinstance(a, dict):
        return (
            isinstance(b, dict)
            and a.keys() == b.keys()
            and all(_equal(a[k], b[k], f"{path}.{k}") for k in a)
        )
    if isinstance(a, tuple | list):
        return (
            isinstance(b, tuple | list)
            and len(a) == len(b)
            and all(_equal(u, v, path) for u, v in zip(a, b, strict=True))
        )
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.shape(a) == np.shape(b) and bool(np.array_equal(a, b, equal_nan=True))
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    if callable(a) or callable(b):
        return False  # two different functions: assume they differ
    try:
        return bool(a == b)
    except (TypeError, ValueError):
        return False


def _dissociation(kiln: Kiln):
    flame = kiln.firing.flame
    return None if flame is None else getattr(flame, "dissociation", None)


def same_structure(a: KilnResidual, b: KilnResidual) -> bool:
    """Can the kilns of the residuals ``a`` and ``b`` share a batch? Their grids, sections,
    species, closures and walls equal; only their boundary inputs (feed, feed temperature,
    gas inlet, heat released and its profile, rotation, solids speed) differ.

    Examples
    --------
    >>> from rotarykiln.kiln.inputs import Kiln
    >>> from rotarykiln.materials.solids import load_solid
    >>> def kiln(gas_temperature, length=2.44):
    ...     return Kiln.inert(solid=load_solid("sand"), solids_flow=0.004,
    ...         solids_inlet_temperature=298.15, gas_composition="O2:0.21, N2:0.79",
    ...         gas_flow=0.007, gas_inlet_temperature=gas_temperature, length=length,
    ...         radius=0.094, omega=0.157, fill=0.17)
    >>> same_structure(KilnResidual(kiln(535.0), 20), KilnResidual(kiln(600.0), 20))
    True
    >>> same_structure(KilnResidual(kiln(535.0), 20), KilnResidual(kiln(535.0, 3.0), 20))
    False
    """
    if a is b:
        return True
    attrs = ("n", "nv", "bed_names", "gas_names", "bed_var", "gas_var", "i_species")
    if any(getattr(a, s) != getattr(b, s) for s in attrs):
        return False
    if not np.array_equal(a.sqrt_mask, b.sqrt_mask):
        return False
    ka, kb = a.kiln, b.kiln
    if (ka.firing.heat_release > 0) != (kb.firing.heat_release > 0):
        return False
    if (ka.bed.dispersion > 0) != (kb.bed.dispersion > 0):
        return False
    if a.bed_sources != b.bed_sources:  # a burner's ash: a source of its own
        return False
    if (_dissociation(ka) is None) != (_dissociation(kb) is None):
        return False  # (two dissociation heats: each case's own, CaseMixtures)
    return _equal(ka, kb)


def structure_groups(residuals: Sequence[KilnResidual]) -> list[list[int]]:
    """The cases (indices into ``residuals``) grouped by :func:`same_structure`, each group in
    the order of the cases."""
    groups: list[list[int]] = []
    for i, r in enumerate(residuals):
        for g in groups:
            if same_structure(residuals[g[0]], r):
                g.append(i)
                break
        else:
            groups.append([i])
    return groups


def _positive(flows) -> frozenset:
    return frozenset(s for s, v in flows.items() if v > 0)


def _fits(base: KilnResidual, kiln: Kiln) -> bool:
    """Does ``kiln`` share the model structure of the residual ``base``
    (:func:`same_structure` of ``base`` and ``KilnResidual(kiln, base.n)``), judged on the
    kiln's inputs: the same species fed and flowing in, the same fields but the boundary ones,
    a burner's ash the same, and a dissociation heat in both or in neither (each case's own:
    :class:`~rotarykiln.kiln.gas_mixture.CaseMixtures`)."""
    kb = base.kiln
    if _positive(kb.feed.flows) != _positive(kiln.feed.flows):
        return False
    if _positive(kb.gas.flows) != _positive(kiln.gas.flows):
        return False
    if (kb.firing.heat_release > 0) != (kiln.firing.heat_release > 0):
        return False
    if (kb.bed.dispersion > 0) != (kiln.bed.dispersion > 0):
        return False
    ash = float(getattr(kiln.firing.flame, "ash_flow", 0.0) or 0.0)
    if base.bed_sources != ({"ash": ash} if ash > 0 else {}):
        return False
    if (_dissociation(kb) is None) != (_dissociation(kiln) is None):
        return False
    return _equal(kb, kiln)


def batch_residuals(kilns: Sequence[Kiln], n_cells: int):
    """The residuals of ``kilns`` on ``n_cells`` cells and their structure groups (indices
    into ``kilns``, as :func:`structure_groups` gives): the first kiln of each structure
    built, the others its :meth:`~rotarykiln.kiln.residual.KilnResidual.with_kiln` (the same
    residual as building theirs, at a fraction of the cost)."""
    residuals: list[KilnResidual] = []
    groups: list[list[int]] = []
    for i, kiln in enumerate(kilns):
        for g in groups:
            base = residuals[g[0]]
            if _fits(base, kiln):
                residuals.append(base.with_kiln(kiln))
                g.append(i)
                break
        else:
            residuals.append(KilnResidual(kiln, n_cells))
            groups.append([i])
    return residuals, groups


def batch_size_for(res: KilnResidual, requested: int | None = None, memory=BATCH_MEMORY) -> int:
    """The number of cases of ``res``'s structure solved together: ``requested`` (all the
    cases when None), reduced, with a logged note, to what fits in ``memory`` bytes."""
    if requested is not None and (int(requested) != requested or requested < 1):
        raise InputError("batch", requested, "an integer >= 1 (cases solved together)")
    colours = coloured_pattern(res.n, res.nv, tuple(bool(v) for v in res.local))[0]
    per_case = colours * res.n * res.nv * BYTES_PER_ENTRY
    fits = max(1, int(memory // per_case))
    if requested is None:
        return fits
    if requested > fits:
        log.info(
            "batch of %d cases reduced to %d: %d cells x %d unknowns take about %.0f MB a case",
            requested,
            fits,
            res.n,
            res.nv,
            per_case / 2**20,
        )
        return fits
    return int(requested)


class BatchResidual:
    """The residual of B kilns of one structure (:func:`same_structure`), unknowns ``(B, C,
    n, nv)`` (C perturbations of each case, 1 for the plain residual).

    The first kiln's :class:`KilnResidual` evaluates every case at its own stacked
    :class:`BoundaryInputs`; each case's unknowns are in its own scaling (species flows over
    its own inlet flows) and its rows scaled by its own reference heat, as when solved alone.
    """

    def __init__(self, residuals: Sequence[KilnResidual]):
        self.residuals = list(residuals)
        self.base = base = self.residuals[0]
        i0, nb, ng = base.i_species, base.nb, base.ng
        self.inputs = BoundaryInputs.stack(
            dataclasses.replace(
                r.inputs,
                bed_velocity=r.kiln.bed.velocity,
                dispersion=r.kiln.bed.dispersion,
                release_cells=r.grid.heat_release * 1.0,
            )
            for r in self.residuals
        )
        B = len(self.residuals)
        # unknowns: case scaling -> the base's; rows: the base's -> the case's
        self.x_factor = np.ones((B, base.nv))
        self.row_factor = np.ones((B, base.nv))
        for b, r in enumerate(self.residuals):
            q = r.q_ref / base.q_ref
            fb = r.bed_scale / base.bed_scale if base.bed_scale > 0 else 1.0
            fg = r.gas_scale / base.gas_scale if base.gas_scale > 0 else 1.0
            self.x_factor[b, i0 : i0 + nb] = np.where(base.sqrt_mask, np.sqrt(fb), fb)
            self.x_factor[b, i0 + nb : i0 + nb + ng] = fg
            self.row_factor[b, i0 : i0 + nb] = q / fb
            self.row_factor[b, i0 + nb : i0 + nb + ng] = q / fg
            if base.depth is not None:
                self.row_factor[b, base.i_depth] = q
        self.q_ref = np.array([r.q_ref for r in self.residuals])
        # burnt gases of other compositions (another fuel or air flow): each case's own
        # dissociation heat, one gather for all (its enthalpy and c_p, to the last bit)
        self.mixtures = None
        if any(r.mixture is not base.mixture for r in self.residuals):
            self.mixtures = CaseMixtures([r.mixture for r in self.residuals])

    def _of(self, cases):
        """The residual evaluating the cases ``cases``: the base's, with each case's own gas
        mixture when they differ."""
        if self.mixtures is None:
            return self.base
        return self.base.with_mixture(self.mixtures.take(cases))

    def full(self, x, cases, flags: list | None = None, shared: list | None = None) -> list:
        """Per case of ``cases``, what ``KilnResidual.evaluate(x[None], full=True)`` of its
        own residual gives at its unknowns ``x`` (b, n, nv): all evaluated in one call.

        ``flags`` and ``shared``: filled with one bool per case, whether the closures'
        validity ranges may warn for it, and with the warnings every case has
        (:meth:`closures_may_warn`)."""
        xf = self.x_factor[cases][:, None, :]
        inputs = self.inputs.take(cases)
        xs = (x * xf)[:, None]
        R, fl, prod, rate, faces = self._of(cases).evaluate(xs, full=True, inputs=inputs)
        R = R * self.row_factor[cases][:, None, None, :]
        n = self.base.n
        if flags is not None:
            flags[:], found = self.closures_may_warn(xs, fl, faces[3], inputs, cases)
            if shared is not None:
                shared[:] = found
        wide = {k: np.broadcast_to(v, R.shape[:2] + (n,)) for k, v in fl.items()}
        return [
            (R[b], {k: v[b] for k, v in wide.items()}, prod[b], rate[b], tuple(f[b] for f in faces))
            for b in range(len(cases))
        ]

    def closures_may_warn(self, xs, fl, qg, inputs, cases) -> tuple[np.ndarray, list]:
        """Whether each case's closures may be outside their validated ranges (bool per case),
        and the warnings every case has: the ranges checked once for all the cases (their
        unknowns ``xs`` (b, 1, n, nv), cell fluxes ``fl``, face gas flows ``qg``, inputs
        ``inputs``; their indices ``cases``). A warning of values with a leading case axis
        names its cases by its mask of the values outside; one of a single value (a property
        of the kiln's structure, the same in every case: a particle size outside a fit) is
        every case's, the same warning; any other flags every case. A case not flagged would
        warn, checked alone, of the shared warnings only; a flagged one is checked alone, for
        its own warnings."""
        b = xs.shape[0]
        g_mean = 0.5 * (np.maximum(qg[..., :-1, :], 0.0) + np.maximum(qg[..., 1:, :], 0.0))
        base = self._of(cases)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            base.coefficients(
                fl["t_gas_mean"],
                fl["t_bed_mean"],
                xs[..., 2],
                g_mean,
                check=True,
                geo=base.geometry(xs),
                omega=inputs.omega,
            )
        flags = np.zeros(b, dtype=bool)
        shared = []
        for w in caught:
            if not isinstance(w.message, OutOfRangeWarning):
                flags[:] = True
                continue
            mask = w.message.mask
            if mask is None:
                shared.append(w)
            elif np.ndim(mask) >= 2 and np.shape(mask)[0] == b:
                flags |= np.asarray(mask).reshape(b, -1).any(1)
            else:
                flags[:] = True
        return flags, shared

    def __call__(self, x, cases) -> np.ndarray:
        """Residual of the cases ``cases`` (index array) at their unknowns ``x`` (b, C, n,
        nv), W (energy rows) and scaled flows (species rows)."""
        xf = self.x_factor[cases][:, None, None, :]
        R = self._of(cases).evaluate(x * xf, inputs=self.inputs.take(cases))
        return R * self.row_factor[cases][:, None, None, :]


def local_unknowns(F, x: np.ndarray, case: int = 0, rel_step: float = 1e-7) -> np.ndarray:
    """Which unknowns of a batched residual ``F`` act on their own cell's rows only (bool,
    nv): those whose coloured finite differences (3 colours, cells ``j mod 3``) leave every
    row of the cells of the other colours exactly unchanged at ``x`` (n, nv) of case
    ``case`` (a wall temperature: its cell's exchange and conduction only)."""
    n, nv = x.shape
    none = tuple([False] * nv)
    colours, perturbed, *_ = coloured_pattern(n, nv, none)
    h = rel_step * np.maximum(np.abs(x), 1.0)
    X = np.broadcast_to(x, (colours, n, nv)).copy()
    X.ravel()[perturbed] = (x + h).ravel()
    dR = F(X[None], np.array([case]))[0] - F(x[None, None], np.array([case]))[0]
    local = np.zeros(nv, dtype=bool)
    other = np.arange(n)[None, :] % 3 != np.arange(3)[:, None]  # (colour c, cell k)
    for v in range(nv):
        d = dR[3 * v : 3 * v + 3]  # (c, k, w)
        local[v] = not np.any(d[other])
    return local


def jacobian_factors(F, x, cases, R, *, local=None, step_floor=1.0, rel_step=1e-7) -> list:
    """LU factors (LAPACK gbtrf; None where singular) of the banded finite-difference
    Jacobians of the cases ``cases`` of a batched residual ``F`` at ``x`` (b, n, nv), their
    residuals ``R`` (b, n, nv), all colours of all cases in one residual call: steps
    ``rel_step max(|x|, step_floor)``, the unknowns ``local`` one colour each
    (:func:`~rotarykiln.kiln.steady.newton.coloured_pattern`)."""
    b, n, nv = x.shape
    loc = tuple(bool(v) for v in (np.zeros(nv, bool) if local is None else local))
    colours, perturbed, src, dst, step_idx = coloured_pattern(n, nv, loc)
    floor = np.broadcast_to(np.asarray(step_floor, dtype=float), (nv,))
    h = rel_step * np.maximum(np.abs(x), floor)
    X = np.broadcast_to(x[:, None], (b, colours, n, nv)).copy()
    X.reshape(b, -1)[:, perturbed] = (x + h).reshape(b, -1)
    dR = F(X, cases) - R[:, None]
    bw = 2 * nv - 1
    ab = np.zeros((b, 2 * bw + 1, n * nv))
    ab.reshape(b, -1)[:, dst] = dR.reshape(b, -1)[:, src] / h.reshape(b, -1)[:, step_idx]
    return [_factor(ab[i], bw) for i in range(b)]


def _factor(ab: np.ndarray, bw: int):
    """LU of one banded matrix (``solve_banded`` layout), LAPACK gbtrf; None if singular."""
    work = np.zeros((3 * bw + 1, ab.shape[1]))
    work[bw:] = ab
    lu, piv, info = lapack.dgbtrf(work, bw, bw, overwrite_ab=1)
    return (lu, piv) if info == 0 else None


def _solve(factors, rhs: np.ndarray, bw: int, trans: int = 0):
    x, info = lapack.dgbtrs(factors[0], bw, bw, rhs, factors[1], trans=trans)
    return x if info == 0 else None


def _solve_cases(factors: list, cases: np.ndarray, rhs: np.ndarray, bw: int):
    """The banded solves of the cases ``cases`` with their factors (``factors[c]``) for the
    right-hand sides ``rhs`` (k, N): (solutions (k, N), bool (k,) where the solve worked).
    Cases that share their factors (a neighbour's, kept: the usual start of a batch) are
    solved in one LAPACK call of several right-hand sides."""
    out = np.full(rhs.shape, np.nan)
    ok = np.zeros(len(cases), dtype=bool)
    groups: dict[int, list[int]] = {}
    for i, c in enumerate(cases):
        if factors[c] is not None:
            groups.setdefault(id(factors[c]), []).append(i)
    for rows in groups.values():
        x = _solve(factors[cases[rows[0]]], rhs[rows].T, bw)
        if x is not None:
            out[rows] = x.T
            ok[rows] = True
    return out, ok


class _Broyden:
    r"""Broyden's (good) updates of the inverse of a kept Jacobian, for the cases of a batch
    at once.

    .. math:: H_{k+1} = H_k + c_k\,s_k^T H_k,\qquad
              c_k = \frac{s_k - H_k y_k}{s_k^T H_k y_k}

    with :math:`s_k` the step taken and :math:`y_k` the change of the residual; :math:`H_0` the
    kept LU factors. :math:`H_k w` is :math:`H_0 w` followed by :math:`w \leftarrow w + c_j
    (s_j^T w)` for the pairs kept, and :math:`H_k y_k = H_k F_{k+1} - H_k F_k = -z_k - d_k`
    from the direction :math:`d_k = -H_k F_k` of the step and :math:`z_k = -H_k F_{k+1}`, which
    also gives the next direction :math:`d_{k+1} = z_k + c_k (s_k^T z_k)`: one banded solve
    per iteration (as C.T. Kelley's ``brsola`` stores its steps). The iteration stays on the
    secant of each step: superlinear where a kept Jacobian (a neighbour's, or its own from
    earlier iterates) alone contracts linearly.

    Each case's pairs are rows of arrays (case, pair, unknown), applied to all the cases of
    an iteration together; the banded solves of cases that share their factors are one call
    (:func:`_solve_cases`).

    References
    ----------
    C.G. Broyden, Math. Comp. 19 (1965) 577-593; J.E. Dennis, R.B. Schnabel (1983), ch. 8;
    C.T. Kelley, Iterative Methods for Linear and Nonlinear Equations, SIAM (1995), ch. 7-8.
    """

    def __init__(self, cases: int, size: int, bw: int, limit: int):
        self.c = np.zeros((cases, max(limit, 1), size))
        self.s = np.zeros((cases, max(limit, 1), size))
        self.count = np.zeros(cases, dtype=int)
        self.next = np.zeros((cases, size))  # the direction of each case's next step ...
        self.known = np.zeros(cases, dtype=bool)  # ... where its last update gave it
        self.bw = bw

    def reset(self, cases: np.ndarray) -> None:
        self.count[cases] = 0
        self.known[cases] = False

    def apply(self, factors: list, cases: np.ndarray, r: np.ndarray):
        """:math:`H_k r` of the cases ``cases`` (r (k, N)): (values, bool (k,) where the
        banded solve worked)."""
        out, ok = _solve_cases(factors, cases, r, self.bw)
        m = self.count[cases]
        for j in range(int(m.max(initial=0))):
            w = np.einsum("kn,kn->k", self.s[cases, j], out)
            out += self.c[cases, j] * np.where(m > j, w, 0.0)[:, None]
        return out, ok

    def directions(self, factors: list, cases: np.ndarray, f: np.ndarray):
        """:math:`-H_k F` of the cases ``cases`` at their residuals ``f`` (k, N): the ones
        their last updates gave, else computed; (directions, bool (k,) where found)."""
        d = np.empty(f.shape)
        ok = np.ones(len(cases), dtype=bool)
        known = self.known[cases]
        d[known] = self.next[cases[known]]
        if not known.all():
            d[~known], ok[~known] = self.apply(factors, cases[~known], -f[~known])
        self.known[cases] = False
        return d, ok

    def update(self, factors: list, cases, d: np.ndarray, s: np.ndarray, f_new: np.ndarray):
        """The secants of the steps ``s`` (k, N) the cases ``cases`` took along the
        directions ``d`` to the residuals ``f_new``: a pair kept and the next direction found
        (no pair where a secant is degenerate: the next direction is then the solve's)."""
        z, ok = self.apply(factors, cases, -f_new)
        cases, d, s, z = cases[ok], d[ok], s[ok], z[ok]
        dz = d - z
        denom = np.einsum("kn,kn->k", s, dz)
        size = np.linalg.norm(s, axis=1) * np.linalg.norm(dz, axis=1)
        secant = np.isfinite(denom) & (np.abs(denom) > 1e-12 * size)
        self.next[cases[~secant]] = z[~secant]
        self.known[cases[~secant]] = True
        cases, s, z, dz, denom = cases[secant], s[secant], z[secant], dz[secant], denom[secant]
        cj = (s - dz) / denom[:, None]
        slot = self.count[cases]
        self.c[cases, slot] = cj
        self.s[cases, slot] = s
        self.count[cases] += 1
        self.next[cases] = z + cj * np.einsum("kn,kn->k", s, z)[:, None]
        self.known[cases] = True


def newton_batch(
    F: Callable,
    x0: np.ndarray,
    scale: np.ndarray,
    *,
    tol: float = 1e-10,
    max_iter: int = 60,
    max_step: float = 300.0,
    lower: float = 160.0,
    temperature_vars: int | None = None,
    step_floor=1.0,
    squared=None,
    rel_step: float = 1e-7,
    local=None,
    roots=None,
    start_factors=None,
    factors_out: list | None = None,
    broyden: int = 0,
    **_,
):
    """Damped Newton on B block-tridiagonal systems at once: per case the iteration of
    :func:`~rotarykiln.kiln.steady.newton.newton_banded` (its coloured finite-difference
    Jacobian, step limit, line search, convergence and stagnation tests), each case's
    Jacobian kept (its LU factors) while its iteration contracts fast.

    A case's Jacobian is evaluated again when its last step reduced its residual by less
    than :data:`CHORD_RATE`, or when its line search fails on a kept Jacobian; the
    Jacobians of the cases that need one come from one residual call.

    Parameters
    ----------
    F : callable
        ``F(x, cases)``: residual of the cases ``cases`` (index array) at ``x`` (b, C, n,
        nv), as :class:`BatchResidual`.
    x0 : array (B, n, nv)
        Initial guesses.
    scale : array (B,)
        Each case's residual is judged as ``max|F| / scale``.
    tol, max_iter, max_step, lower, temperature_vars, step_floor, squared
        As :func:`~rotarykiln.kiln.steady.newton.newton_banded` (``max_step``, ``lower``
        in K).
    local : array of bool (nv,), optional
        Unknowns acting on their own cell's rows only (:func:`local_unknowns`): one colour
        each instead of three.
    roots : array of bool (nv,), optional
        Root unknowns kept on their positive branch, as
        :func:`~rotarykiln.kiln.steady.newton.newton_banded`'s.
    start_factors : optional
        LU factors of a Jacobian every case starts with (a neighbouring solution's), instead
        of evaluating its own at its start; or a list of them, one per case.
    factors_out : list, optional
        Filled with each case's last LU factors (those its last step was taken with).
    broyden : int
        Up to this many Broyden updates of a kept Jacobian (:class:`_Broyden`): its own is
        evaluated again only when a step reduced the residual by less than
        :data:`BROYDEN_RATE`, or after that many updates (0: the chord iteration, a new
        Jacobian below :data:`CHORD_RATE`).

    Returns
    -------
    x : array (B, n, nv)
        The last iterates.
    iterations : array of int (B,)
    residual : array (B,)
        Each case's ``max|F| / scale`` at ``x`` (-).
    converged : array of bool (B,)

    Examples
    --------
    Two conducting chains with different end temperatures (K):

    >>> def F(x, cases):
    ...     hot = np.array([1000.0, 700.0])[cases].reshape(-1, 1, 1, 1)
    ...     ends = np.ones(x.shape[:-2] + (1, 1))
    ...     t = np.concatenate([300.0 * ends, x, hot * ends], axis=-2)
    ...     return t[..., :-2, :] - 2.0 * t[..., 1:-1, :] + t[..., 2:, :]
    >>> x, its, res, ok = newton_batch(F, np.full((2, 6, 1), 600.0), np.ones(2))
    >>> x[:, :, 0].round(6).tolist(), ok.tolist()
    ([[400.0, 500.0, 600.0, 700.0, 800.0, 900.0], [357.142857, 414.285714, 471.428571, 528.571429, 585.714286, 642.857143]], [True, True])

    References
    ----------
    A.R. Curtis, M.J.D. Powell, J.K. Reid, J. Inst. Math. Appl. 13 (1974) 117-119;
    J.E. Dennis, R.B. Schnabel, Numerical Methods for Unconstrained Optimization and
    Nonlinear Equations, Prentice-Hall (1983), ch. 6; the chord (kept Jacobian) iteration:
    C.T. Kelley, Iterative Methods for Linear and Nonlinear Equations, SIAM (1995), ch. 5.
    """
    x = np.array(x0, dtype=float)
    B, n, nv = x.shape
    nt = nv if temperature_vars is None else temperature_vars
    sq = None if squared is None or not np.any(squared) else np.flatnonzero(squared)
    rt = positive_roots(x, roots)
    jkw = dict(local=local, step_floor=step_floor, rel_step=rel_step)
    bw = 2 * nv - 1
    every = np.arange(B)
    R = F(x[:, None], every)[:, 0]
    norm = np.max(np.abs(R), axis=(1, 2)) / scale
    iterations = np.zeros(B, dtype=int)
    status = np.zeros(B, dtype=int)  # 0 running, 1 converged, -1 failed
    factors: list = list(start_factors) if isinstance(start_factors, list) else [start_factors] * B
    fresh = np.array([f is None for f in factors])  # needs its Jacobian now
    secant = _Broyden(B, n * nv, bw, broyden)
    rate = BROYDEN_RATE if broyden else CHORD_RATE
    for it in range(1, max_iter + 1):
        status[(status == 0) & (norm <= tol)] = 1
        status[(status == 0) & ~np.isfinite(norm)] = -1
        act = np.flatnonzero(status == 0)
        if act.size == 0:
            break
        need = act[fresh[act]]
        if need.size:
            for c, f in zip(need, jacobian_factors(F, x[need], need, R[need], **jkw), strict=True):
                factors[c] = f
                if f is None:
                    status[c] = -1
            fresh[need] = False
            secant.reset(need)
            act = np.flatnonzero(status == 0)
            if act.size == 0:
                continue
        d, ok = secant.directions(factors, act, R[act].reshape(act.size, -1))
        ok &= np.isfinite(d).all(axis=1)
        dx = d.reshape(act.size, n, nv)
        kept = ~np.isin(act, need)
        fresh[act[~ok & kept]] = True  # a kept Jacobian that fails: the case's own, then
        status[act[~ok & ~kept]] = -1
        act, dx = act[ok], dx[ok]
        if act.size == 0:
            continue
        xa = x[act]
        big = np.max(np.abs(dx[:, :, :nt]), axis=(1, 2)) if nt else np.zeros(act.size)
        lam = np.where(big > 0, np.minimum(1.0, max_step / np.where(big > 0, big, 1.0)), 1.0)
        xt_all = np.empty_like(xa)
        Rt_all = np.empty((act.size, n, nv))
        nt_norm = np.full(act.size, np.inf)
        accepted = np.zeros(act.size, dtype=bool)
        searching = np.arange(act.size)
        for _ in range(30):
            s_ = searching
            lm = lam[s_][:, None, None]
            xt = xa[s_] + lm * dx[s_]
            if sq is not None:
                s = xa[s_][:, :, sq]
                q = np.maximum(s * s + lm * 2.0 * s * dx[s_][:, :, sq], SQUARED_FLOOR * s * s)
                xt[:, :, sq] = np.copysign(np.sqrt(q), s)
            xt[:, :, :nt] = np.maximum(xt[:, :, :nt], lower)
            positive_roots(xt, rt)
            Rt = F(xt[:, None], act[s_])[:, 0]
            tn = np.max(np.abs(Rt), axis=(1, 2)) / scale[act[s_]]
            xt_all[s_], Rt_all[s_], nt_norm[s_] = xt, Rt, tn
            good = np.isfinite(tn) & ((tn < (1 - 1e-4 * lam[s_]) * norm[act[s_]]) | (tn <= tol))
            accepted[s_[good]] = True
            searching = s_[~good]
            if searching.size == 0:
                break
            lam[searching] *= 0.5
        old = norm[act].copy()
        own = np.isin(act, need)  # Jacobians evaluated at these very iterates
        move = accepted.copy()
        for i in np.flatnonzero(~accepted):
            c = act[i]
            if not own[i]:
                fresh[c] = True  # a kept Jacobian: evaluate the case's own and try again
            elif norm[c] <= STAGNATION_FACTOR * tol:
                status[c] = 1  # round-off reached just above the tolerance
            elif not np.isfinite(nt_norm[i]) or nt_norm[i] > 10 * norm[c]:
                status[c] = -1
            else:
                move[i] = True  # the smallest step, as newton_banded takes it
        moved = act[move]
        if broyden:
            full = secant.count[moved] >= broyden
            fresh[moved[full]] = True
            upd = ~full
            if upd.any():
                k = int(upd.sum())
                secant.update(
                    factors,
                    moved[upd],
                    dx[move][upd].reshape(k, -1),
                    (xt_all[move][upd] - x[moved[upd]]).reshape(k, -1),
                    Rt_all[move][upd].reshape(k, -1),
                )
        x[moved], R[moved], norm[moved] = xt_all[move], Rt_all[move], nt_norm[move]
        iterations[moved] = it
        slow = moved[norm[moved] > rate * old[move]]
        fresh[slow] = True
    status[(status == 0) & (norm <= tol)] = 1
    if factors_out is not None:
        factors_out[:] = factors
    return x, iterations, norm, status == 1


def _scaled_inputs(res: KilnResidual) -> np.ndarray:
    """The inputs of a case as one vector, each entry over a typical size, for distances."""
    u = res.inputs
    v = [
        np.atleast_1d(u.feed) / max(res.bed_scale, 1e-30),
        [u.feed_temperature / 1000.0],
        np.atleast_1d(u.gas) / max(res.gas_scale, 1e-30) if res.gas_scale > 0 else [0.0],
        [res.gas_scale],
        [u.gas_temperature / 1000.0, u.omega, res.kiln.bed.velocity * 1e3],
        [res.kiln.firing.heat_release / max(res.q_ref, 1.0)],
    ]
    return np.concatenate([np.asarray(a, float).ravel() for a in v])


def _physical(res: KilnResidual, x: np.ndarray) -> np.ndarray:
    """Unknowns of ``res`` with its species as flows (kg/s), for a start of another case."""
    i0, nb, ng = res.i_species, res.nb, res.ng
    p = x.copy()
    xb = x[:, i0 : i0 + nb]
    p[:, i0 : i0 + nb] = np.where(res.sqrt_mask, xb * xb, xb) * res.bed_scale
    p[:, i0 + nb : i0 + nb + ng] *= res.gas_scale
    return p


def _unknowns(res: KilnResidual, p: np.ndarray) -> np.ndarray:
    """The inverse of :func:`_physical`: the unknowns of ``res`` from physical ones."""
    i0, nb, ng = res.i_species, res.nb, res.ng
    x = p.copy()
    qb = np.maximum(p[:, i0 : i0 + nb], 0.0) / res.bed_scale
    x[:, i0 : i0 + nb] = np.where(res.sqrt_mask, np.sqrt(qb), qb)
    if ng:
        x[:, i0 + nb : i0 + nb + ng] = p[:, i0 + nb : i0 + nb + ng] / res.gas_scale
    return x


def solve_batch(
    kilns: Sequence[Kiln],
    n_cells: int = 100,
    *,
    tol: float = 1e-11,
    max_iter: int = 60,
    batch: int | None = None,
    check_balances: bool = True,
    warnings_out: list | None = None,
) -> list[KilnSolution | ConvergenceError]:
    """Solve the steady balances of many kilns, those of one model structure together.

    Parameters
    ----------
    kilns : sequence of Kiln
        The kilns (operating points of a study, or anything: kilns of different structures
        are split into groups solved one after the other).
    n_cells : int
        Number of equal cells of every kiln (>= 4).
    tol, max_iter, check_balances
        As :func:`~rotarykiln.kiln.steady.solve.solve_kiln`.
    batch : int, optional
        Largest number of cases solved together (default: as many as fit in
        :data:`BATCH_MEMORY`; a larger request is reduced to that, with a logged note).
    warnings_out : list, optional
        Filled with one list per kiln of the warnings of its own solve (its closures' ranges
        checked on its solution), instead of letting them propagate.

    Returns
    -------
    list
        Per kiln, in order, its :class:`KilnSolution` (temperatures in K, flows in kg/s,
        heat flows in W), or the :class:`~rotarykiln.errors.ConvergenceError` of its own
        solve alone.

    Examples
    --------
    >>> from rotarykiln.kiln.inputs import Kiln
    >>> from rotarykiln.materials.solids import load_solid
    >>> kilns = [Kiln.inert(solid=load_solid("sand"), solids_flow=0.004,
    ...     solids_inlet_temperature=298.15, gas_composition="O2:0.21, N2:0.79",
    ...     gas_flow=0.007, gas_inlet_temperature=t, length=2.44, radius=0.094,
    ...     omega=0.157, fill=0.17) for t in (500.0, 535.0, 570.0)]
    >>> [round(s.bed_outlet_temperature, 3) for s in solve_batch(kilns, 20)] == [
    ...     round(solve_kiln(k, 20).bed_outlet_temperature, 3) for k in kilns]
    True

    References
    ----------
    The Newton iteration: :func:`~rotarykiln.kiln.steady.newton.newton_banded`; batching
    over operating points: docs/studies.md.
    """
    if int(n_cells) != n_cells or n_cells < 4:
        raise InputError("solver.cells", n_cells, "an integer >= 4")
    n_cells = int(n_cells)
    residuals, groups = batch_residuals(kilns, n_cells)
    out: list = [None] * len(residuals)
    caught: list[list] = [[] for _ in residuals]
    opts = dict(tol=tol, max_iter=max_iter, check_balances=check_balances)
    solved: list[int] = []
    for group in groups:
        size = batch_size_for(residuals[group[0]], batch)
        _solve_group(residuals, group, size, out, caught, opts, solved)
    if warnings_out is not None:
        warnings_out[:] = caught
    else:
        for w in (w for ws in caught for w in ws):
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return out


def _recorded(caught: list, run: Callable):
    """``run()``, its warnings appended to ``caught``; a ConvergenceError returned."""
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        try:
            result = run()
        except ConvergenceError as err:
            result = err
    caught.extend(w)
    return result


def _alone(res: KilnResidual, caught: list, opts: dict, cost: _Cost | None = None):
    """The case of ``res`` solved alone (:func:`solve_kiln`), its work counted in ``cost``."""
    kw = {k: opts[k] for k in ("tol", "max_iter", "check_balances")}
    with cost.alone() if cost is not None else contextlib.nullcontext():
        return _recorded(caught, lambda: solve_kiln(res.kiln, res.n, **kw))


def _layout(res: KilnResidual) -> tuple:
    return (res.n, res.nv, res.i_species, res.bed_var, res.gas_var, res.depth is None)


def same_layout(a: KilnResidual, b: KilnResidual) -> bool:
    """Whether the unknowns of ``a`` and ``b`` mean the same things cell by cell (cells,
    wall nodes, species, bed depth), so that a solution of one is a start for the other
    even when their models differ (another fuel flow: another burnt gas)."""
    return _layout(a) == _layout(b) and np.array_equal(a.sqrt_mask, b.sqrt_mask)


def _from_neighbour(residuals, i, solved, out, caught, opts):
    """The solution of case ``i`` by Newton from the nearest solved case of the same layout
    (:func:`same_layout`), or None when there is none or that Newton fails (the case is
    then solved alone, with the continuation)."""
    res = residuals[i]
    near = [j for j in solved if same_layout(residuals[j], res)]
    if not near:
        return None
    key = _scaled_inputs(res)
    sizes = [_scaled_inputs(residuals[j]) for j in near]
    j = min(
        range(len(near)),
        key=lambda m: (
            float(np.sum((sizes[m] - key) ** 2)) if sizes[m].shape == key.shape else np.inf
        ),
    )
    start = _unknowns(res, _physical(residuals[near[j]], out[near[j]].fluxes["x"]))
    F = BatchResidual([res])
    kw = newton_options(res, tol=opts["tol"], max_iter=opts["max_iter"])
    x, its, _, ok = newton_batch(F, start[None], F.q_ref, **kw)
    if not ok[0]:
        return None
    evaluated = F.full(x, np.array([0]))[0]
    result = _recorded(
        caught,
        lambda: finish_solution(
            res, x[0], int(its[0]), check_balances=opts["check_balances"], evaluated=evaluated
        ),
    )
    if isinstance(result, ConvergenceError):
        caught.clear()
        return None
    return result


#: When a group's batched Newton iterations have cost more than this many times its solves
#: alone, a case on average (cells x states of every residual evaluation; the solves alone are
#: its first case's and those of cases that failed in the batch), the group's remaining cases
#: are solved alone, each with the grid sequencing of a single solve. A reaction front that
#: moves between operating points makes Newton from a neighbour crawl: the limestone
#: calcination kiln's first wave took 38-46 iterations a case, 4.7 times the cells of a solve
#: alone (2.8 times its time: 60 ms a case against 30 ms), the fired limestone kiln's 2.7 times
#: (1.75 times the time). The cement kiln's first wave costs 1.7 times, its later ones
#: 0.1-0.9; the lime kiln's solves alone need its feed continuation, and its batched cases cost
#: a fraction of them; every other built-in kiln's 0.16-0.6.
SLOW_BATCH_FACTOR = 2.0

#: The second wave of a chunk (:func:`_solve_group`): one case in LEVEL2 of those left after
#: its seeds, spread over the inputs, solved before the rest so that these start nearer.
LEVEL2 = 4


def _seeds(chunk: list, key: dict, known: list, k: int | None = None) -> list:
    """The cases of ``chunk`` solved first (:func:`_solve_group`): about the square root of
    its size, spread over its inputs (``key``: each case's scaled inputs) by farthest-point
    sampling from the cases ``known`` already (their scaled inputs)."""
    k = int(math.isqrt(len(chunk))) if k is None else k
    if k < 2:
        return []
    points = np.array([key[i] for i in chunk])
    gap = np.min(((points[:, None, :] - np.array(known)[None, :, :]) ** 2).sum(-1), axis=1)
    picked = []
    for _ in range(k):
        m = int(np.argmax(gap))
        picked.append(chunk[m])
        gap = np.minimum(gap, ((points - points[m]) ** 2).sum(-1))
    return picked


def _solve_chunk(residuals, chunk, key, lu, out, caught, opts, solved, cost=None):
    """Solve the cases ``chunk`` of one structure together, each from the nearest case with
    kept LU factors (``lu``: case -> factors; its solution the start, its Jacobian the
    first); a case that fails there is solved alone. The solved cases are appended to
    ``solved``; the chunk's last factors are kept in ``lu`` when it is a chunk's seeds (less
    than a tenth of the cases)."""
    with_lu = list(lu)
    wanted = np.array([key[i] for i in chunk])

    def nearest(among):
        known = np.array([key[j] for j in among])
        return [among[m] for m in ((known[None] - wanted[:, None]) ** 2).sum(-1).argmin(1)]

    starts, start_factors = [], []
    for i, near, near_lu in zip(chunk, nearest(solved), nearest(with_lu), strict=True):
        p = _physical(residuals[near], out[near].fluxes["x"])
        starts.append(_unknowns(residuals[i], p))
        start_factors.append(lu[near_lu])
    rs = [residuals[i] for i in chunk]
    F = BatchResidual(rs)
    kw = newton_options(rs[0], tol=opts["tol"], max_iter=opts["max_iter"])
    factors: list = []
    x, its, _, ok = newton_batch(
        F,
        np.stack(starts),
        F.q_ref,
        start_factors=start_factors,
        factors_out=factors,
        broyden=BROYDEN_UPDATES,
        **kw,
    )
    done = np.flatnonzero(ok)
    flags: list = []
    shared: list = []
    evaluated = (
        dict(zip(done, F.full(x[done], done, flags, shared), strict=True)) if done.size else {}
    )
    check = dict(zip(done, flags, strict=True))
    keep = len(chunk) <= max(1, len(residuals) // 10)
    for b, i in enumerate(chunk):
        if ok[b]:
            res = residuals[i]
            out[i] = _recorded(
                caught[i],
                lambda res=res, xb=x[b], n_it=int(its[b]), ev=evaluated[b], c=check[b]: (
                    finish_solution(
                        res,
                        xb,
                        n_it,
                        check_balances=opts["check_balances"],
                        evaluated=ev,
                        check_closures=c,
                    )
                ),
            )
            if not check[b]:  # its closures' warnings are those every case of the chunk has
                caught[i].extend(shared)
        if not ok[b] or isinstance(out[i], ConvergenceError):
            caught[i].clear()
            out[i] = _alone(residuals[i], caught[i], opts, cost)
        if not isinstance(out[i], ConvergenceError):
            solved.append(i)
            if keep and ok[b] and factors[b] is not None:
                lu[i] = factors[b]


class _Cost:
    """The work of a group's solves alone (its first case's, and those of cases that fail in
    the batch or follow a slow one) and of its batched Newton iterations, in cells evaluated
    (:func:`~rotarykiln.kiln.residual.cell_evaluations`): whether a batched case costs more than
    :data:`SLOW_BATCH_FACTOR` times a solve alone on average (a count of work, not a time: the
    same choice on every run)."""

    def __init__(self):
        self.alone_cells = self.alone_count = 0
        self.batch_cells = self.batch_cases = 0

    @contextlib.contextmanager
    def alone(self):
        start = cell_evaluations()
        yield
        self.alone_cells += cell_evaluations() - start
        self.alone_count += 1

    @contextlib.contextmanager
    def batched(self, cases: int):
        """The batched solve of ``cases`` cases (the solves alone inside it counted as such)."""
        start, inside = cell_evaluations(), self.alone_cells
        yield
        self.batch_cells += cell_evaluations() - start - (self.alone_cells - inside)
        self.batch_cases += cases

    def slow(self) -> bool:
        if not self.alone_count or not self.batch_cases:
            return False
        per_alone = self.alone_cells / self.alone_count
        return self.batch_cells / self.batch_cases > SLOW_BATCH_FACTOR * per_alone


def _solve_group(residuals, group, size, out, caught, opts, solved_before=()):
    """Solve the cases ``group`` of one structure into ``out`` (their warnings into
    ``caught``): the first from the nearest case ``solved_before`` (other structures) of the
    same layout, else alone; the others in batches of ``size`` from the nearest solved case
    of the group; a case that fails there alone. The solved cases are appended to
    ``solved_before``."""
    first = group[0]
    cost = _Cost()
    out[first] = _from_neighbour(residuals, first, solved_before, out, caught[first], opts)
    if out[first] is None:
        out[first] = _alone(residuals[first], caught[first], opts, cost)
    if isinstance(out[first], ConvergenceError):
        for i in group[1:]:  # no start to share: each case alone
            out[i] = _alone(residuals[i], caught[i], opts)
        if isinstance(solved_before, list):
            solved_before.extend(i for i in group if not isinstance(out[i], ConvergenceError))
        return
    solved = [first]
    rest = group[1:]
    if not rest:  # a structure of one case: nothing to start from it
        if isinstance(solved_before, list):
            solved_before.append(first)
        return
    anchor = BatchResidual([residuals[first]])
    x_first = out[first].fluxes["x"][None]
    kw0 = newton_options(residuals[first], tol=opts["tol"], max_iter=opts["max_iter"])
    R_first = anchor(x_first[:, None], np.array([0]))[:, 0]
    start_lu = jacobian_factors(
        anchor, x_first, np.array([0]), R_first, local=kw0["local"], step_floor=kw0["step_floor"]
    )[0]
    key = {i: _scaled_inputs(residuals[i]) for i in group}
    lu = {first: start_lu}  # the LU factors kept: the first case's and each chunk's seeds'
    for first_case in range(0, len(rest), size):
        chunk = rest[first_case : first_case + size]
        seeds = _seeds(chunk, key, [key[j] for j in lu])
        others = [i for i in chunk if i not in set(seeds)]
        second = _seeds(others, key, [key[j] for j in [*lu, *seeds]], len(others) // LEVEL2)
        others = [i for i in others if i not in set(second)]
        for part in (seeds, second, others):
            if not part:
                continue
            if cost.slow():  # the batch costs more than the cases alone: the rest alone
                for i in part:
                    out[i] = _alone(residuals[i], caught[i], opts, cost)
                    if not isinstance(out[i], ConvergenceError):
                        solved.append(i)
                continue
            with cost.batched(len(part)):
                _solve_chunk(residuals, part, key, lu, out, caught, opts, solved, cost)
    if isinstance(solved_before, list):
        solved_before.extend(solved)
