"""Shared helpers of the transport package: axial property providers, march, input checks."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from rotarykiln import regimes
from rotarykiln.errors import InputError, check_positive, warn_out_of_range

G = 9.81  # m/s2, the value used by Scott (1986)

__all__ = [
    "G",
    "as_axial_function",
    "critical_speed",
    "check_slope_and_repose",
    "warn_speed",
    "march",
    "MarchResult",
]


def critical_speed(radius):
    r"""Critical speed :math:`\omega_c = \sqrt{g/R}` (rad/s) with Scott's g = 9.81 m/s2.

    Thin wrapper of :func:`rotarykiln.regimes.critical_speed` (which defaults to standard g).

    Examples
    --------
    >>> round(float(critical_speed(0.0465)), 3)
    14.525
    """
    return regimes.critical_speed(radius, g=G)


def as_axial_function(name: str, value) -> tuple[Callable[[np.ndarray], np.ndarray], bool]:
    """Turn a float, a callable ``f(z)`` or a table ``(z_m, values)`` into a function of z.

    ``z`` is the distance from the feed end in m. Returns ``(function, is_constant)``.
    """
    if callable(value):
        return (lambda z: np.asarray(value(np.asarray(z, dtype=float)), dtype=float)), False
    if isinstance(value, tuple | list) and len(value) == 2 and np.ndim(value[0]) == 1:
        zt = np.asarray(value[0], dtype=float)
        vt = np.asarray(value[1], dtype=float)
        if zt.shape != vt.shape or zt.size < 2 or np.any(np.diff(zt) <= 0):
            raise InputError(name, value, "a table (z, values) with increasing z of equal length")
        return (lambda z: np.interp(z, zt, vt)), False
    v = float(value)
    return (lambda z: np.full_like(np.asarray(z, dtype=float), v)), True


def check_slope_and_repose(slope, repose, field: str = "dynamic_angle_of_repose") -> None:
    """InputError unless 0 <= slope < angle of repose < 90 deg (all in rad)."""
    if (
        isinstance(slope, float | int)
        and isinstance(repose, float | int)
        and 0.0 <= slope < repose < np.pi / 2  # False for NaN: the slow path below reports it
    ):
        return
    slope = np.asarray(slope, dtype=float)
    repose = np.asarray(repose, dtype=float)
    if np.any(~np.isfinite(slope)) or np.any(slope < 0) or np.any(slope >= np.pi / 2):
        raise InputError("slope", f"{np.degrees(np.max(slope)):.6g} deg", "in [0, 90) deg")
    check_positive(field, repose, "rad")
    if np.any(repose >= np.pi / 2):
        raise InputError(field, f"{np.degrees(np.max(repose)):.6g} deg", "< 90 deg")
    if np.any(repose <= slope):
        raise InputError(
            field,
            f"{np.degrees(np.min(repose)):.6g} deg",
            f"> the drum slope ({np.degrees(np.max(slope)):.6g} deg): a bed cannot rest "
            "at an angle of repose below the slope",
        )


def warn_speed(omega, radius, source: str) -> float:
    """Warn (OutOfRangeWarning) above half the critical speed; return omega/omega_c."""
    frac = float(np.max(np.asarray(omega) / critical_speed(radius)))
    warn_out_of_range("fraction of critical speed", frac, 0.0, 0.5, source)
    return frac


class MarchResult:
    """State y and axial distance x (from the start of the march) on a fine grid.

    ``reached`` is True when x reached the requested length; otherwise the march ended at the
    asymptote ``y_target`` (or at the cap). :meth:`y_at` interpolates y(x) to fourth order
    (cubic Hermite in the march variable, whose derivative ``du/dx = 1/f`` is known).
    """

    __slots__ = ("x", "y", "reached", "_xf", "_uf", "_ff", "_y_of_u")

    def __init__(self, x, y, reached, xf, uf, ff, y_of_u):
        self.x = x
        self.y = y
        self.reached = reached
        self._xf, self._uf, self._ff, self._y_of_u = xf, uf, ff, y_of_u

    def y_at(self, xq):
        """y at the distances ``xq`` (within [0, x[-1]])."""
        xf, uf, ff = self._xf, self._uf, self._ff
        k = np.clip(np.searchsorted(xf, xq, side="right") - 1, 0, xf.size - 2)
        h = xf[k + 1] - xf[k]
        t = (xq - xf[k]) / h
        t2, t3 = t * t, t * t * t
        secant = uf[k + 1] - uf[k]
        with np.errstate(divide="ignore", invalid="ignore"):
            m0 = h / ff[k]
            m1 = h / ff[k + 1]
        m0 = np.where(np.isfinite(m0), m0, secant)  # dx/du = 0 (e.g. h = 0): no slope info
        m1 = np.where(np.isfinite(m1), m1, secant)
        u = (
            (2 * t3 - 3 * t2 + 1) * uf[k]
            + (t3 - 2 * t2 + t) * m0
            + (-2 * t3 + 3 * t2) * uf[k + 1]
            + (t3 - t2) * m1
        )
        return self._y_of_u(u)


def _cumtrapz(f, t):
    out = np.empty_like(t)
    out[0] = 0.0
    np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t), out=out[1:])
    return out


def _cumsimpson(f, t):
    """Cumulative Simpson on a uniform grid (odd number of points); trapezoid in the middle."""
    n = t.size
    h = t[1] - t[0]
    out = np.empty(n)
    out[0] = 0.0
    # pairs of intervals with Simpson, and each single interval by a 3-point formula
    # (integral over [t0,t1] of the quadratic through t0,t1,t2): h/12 (5 f0 + 8 f1 - f2)
    if n < 3:
        return _cumtrapz(f, t)
    first = h / 12.0 * (5.0 * f[:-2] + 8.0 * f[1:-1] - f[2:])
    last = h / 12.0 * (-f[-3] + 8.0 * f[-2] + 5.0 * f[-1])
    steps = np.empty(n - 1)
    steps[:-1] = first
    steps[-1] = last
    np.cumsum(steps, out=out[1:])
    return out


def march(
    dxdy: Callable[[np.ndarray], np.ndarray],
    y0: float,
    length: float,
    *,
    y_target: float | None = None,
    y_cap: float | None = None,
    n_coarse: int = 97,
    n_fine: int = 257,
    eps: float = 1e-10,
) -> MarchResult:
    """Integrate ``x(y) = int dx/dy dy`` from ``y0`` until ``x = length``.

    The right-hand side of an autonomous first-order ODE ``dy/dx = 1/dxdy(y)`` is given as the
    (vectorised) reciprocal ``dxdy``. When the solution tends to an asymptote ``y_target``
    (``dxdy`` is singular there), the march uses ``u = -ln|y_target - y|`` as the independent
    variable so that the grid clusters towards the asymptote and ``dx/du`` stays finite.
    Otherwise it marches linearly in ``y`` up to ``y_cap``. Two passes: a coarse one locates the
    end, a fine one (odd point count, cumulative Simpson) resolves it.
    """
    if y_target is not None:
        d = 1.0 if y_target > y0 else -1.0
        u0 = -np.log(abs(y_target - y0))
        u_end = -np.log(eps * max(abs(y_target), 1e-300))

        def y_of_u(u):
            return y_target - d * np.exp(-u)

        def grid(u_hi, n):
            u = np.linspace(u0, u_hi, n)
            gap = np.exp(-u)
            y = y_target - d * gap
            return u, y, dxdy(y) * (d * gap)  # dx/du = dx/dy * dy/du, dy/du = d*gap

    else:
        if y_cap is None:
            raise ValueError("march needs y_target or y_cap")
        u0, u_end = y0, y_cap

        def y_of_u(u):
            return u

        def grid(u_hi, n):
            y = np.linspace(u0, u_hi, n)
            return y, y, dxdy(y)

    u, y, f = grid(u_end, n_coarse)
    if not np.all(np.isfinite(f)):  # no real solution beyond some state: march up to it only
        bad = int(np.argmax(~np.isfinite(f)))
        if bad < 2:
            raise ValueError("march: right-hand side not finite at the start")
        u_end = u[bad - 1]
        u, y, f = grid(u_end, n_coarse)
    x = _cumsimpson(f, u)
    if x[-1] < length:
        u, y, f = grid(u_end, n_fine)
        x = _cumsimpson(f, u)
        return MarchResult(x, y, False, x, u, f, y_of_u)
    k = int(np.searchsorted(x, length))
    u_hi = u[min(k + 1, u.size - 1)]
    u, y, f = grid(u_hi, n_fine)
    x = _cumsimpson(f, u)
    if x[-1] < length:  # coarse/fine disagreement: extend once more
        u, y, f = grid(u[-1] + 2 * (u[-1] - u[-2]) + 0.05 * (u[-1] - u0), n_fine)
        x = _cumsimpson(f, u)
    k = int(np.searchsorted(x, length))
    k = min(max(k, 1), x.size - 1)
    y_end = y[k - 1] + (y[k] - y[k - 1]) * (length - x[k - 1]) / (x[k] - x[k - 1])
    xs = np.append(x[:k], length)
    ys = np.append(y[:k], y_end)
    return MarchResult(xs, ys, True, x, u, f, y_of_u)
