"""Segregated-flow conversion over a residence time distribution, side by side with plug flow.

In the segregated-flow model every parcel of bed keeps its identity; a parcel that stays a time
:math:`\\tau` reaches the conversion :math:`X(\\tau)` of a batch (plug-flow) path of that
duration, and the outlet conversion is the RTD average

.. math:: \\bar X_{seg} = \\int_0^\\infty X(\\tau)\\, E(\\tau)\\, d\\tau

In a kiln the temperature is a function of position: a parcel of residence time :math:`\\tau`
crosses the kiln of length L at the mean speed :math:`L/\\tau` and so sees :math:`T(z)` with
:math:`z = L t/\\tau` (:func:`kiln_segregated_conversion`). The plug-flow value is
:math:`X(\\bar\\tau)` with :math:`\\bar\\tau = \\int \\tau E\\, d\\tau`.

All classes are integrated at once (:func:`batch_plug_flow_conversion`): in the kiln coordinate
z every class obeys the plug-flow equations of :mod:`~rotarykiln.chemistry.plugflow` with its own
hold-up :math:`m' = \\sum_j Q_j\\,\\tau/L`, so one vectorised rate evaluation serves every class.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.chemistry.mechanism import CellState, Mechanism
from rotarykiln.chemistry.plugflow import as_profile
from rotarykiln.errors import ConvergenceError, InputError, check_nonnegative, check_positive
from rotarykiln.progress import progress_bar
from rotarykiln.tables import with_units

# numpy's trapezoid rule gives the same numbers as scipy.integrate.trapezoid, which would import
# scipy.optimize and scipy.special with it
trapezoid = np.trapezoid

__all__ = [
    "SegregatedResult",
    "rtd_arrays",
    "segregated_average",
    "batch_plug_flow_conversion",
    "kiln_segregated_conversion",
]

log = logging.getLogger(__name__)


def rtd_arrays(rtd, t=None, t_max=None, n: int = 400) -> tuple[np.ndarray, np.ndarray]:
    """Tabulate an RTD given as arrays, a callable E(t) or an object with ``exitage(t)``.

    Parameters
    ----------
    rtd : (t, E) pair, callable or object with ``exitage``
        E in 1/s, t in s.
    t : array, optional
        Time grid for a callable RTD, s.
    t_max : float, optional
        End of a uniform grid (used if ``t`` is None), s.
    n : int
        Points of the uniform grid.

    Returns
    -------
    (t, E) : ndarrays
        E normalised to unit area on the grid (trapezoid rule).
    """
    if isinstance(rtd, tuple | list) and len(rtd) == 2:
        tt = np.asarray(rtd[0], dtype=float)
        E = np.asarray(rtd[1], dtype=float)
    else:
        f = getattr(rtd, "exitage", rtd)
        if not callable(f):
            raise InputError(
                "rtd", rtd, "(t, E) arrays, a callable E(t) or an object with exitage(t)"
            )
        if t is None:
            if t_max is None:
                raise InputError("rtd.t_max", None, "given (or a time grid t) for a callable RTD")
            check_positive("rtd.t_max", t_max, "s")
            if not isinstance(n, int | np.integer) or n < 2:
                raise InputError("rtd.n", n, "an integer >= 2")
            t = np.linspace(0.0, float(t_max), int(n))
        tt = np.asarray(t, dtype=float)
        E = np.asarray(f(tt), dtype=float)
    if tt.ndim != 1 or tt.shape != E.shape or tt.size < 3:
        raise InputError(
            "rtd", f"shapes {tt.shape} and {E.shape}", "1-D t and E of equal length >= 3"
        )
    if np.any(np.diff(tt) <= 0) or tt[0] < 0:
        raise InputError("rtd.t", "not increasing from >= 0", "increasing times >= 0")
    if not np.all(np.isfinite(E)) or np.any(E < 0):
        raise InputError("rtd.E", "negative or non-finite", "finite values >= 0")
    area = trapezoid(E, tt)
    check_positive("rtd.E (area)", area)
    return tt, E / area


@dataclass(frozen=True)
class SegregatedResult:
    """Conversion of each residence-time class, its RTD average and the plug-flow value.

    Attributes
    ----------
    tau : ndarray
        Residence times, s.
    E : ndarray
        Normalised RTD on ``tau``, 1/s.
    conversion : ndarray
        X(tau), [-].
    segregated : float
        RTD-averaged conversion, [-].
    plug : float
        Conversion at the mean residence time, [-].
    mean_residence_time : float
        s.
    class_tau : ndarray or None
        Residence times integrated (the classes, then any extra times asked for), s; None
        when X(t) was given as a function.
    class_conversion : ndarray or None
        Outlet conversion of each integrated residence time, [-].
    """

    tau: np.ndarray
    E: np.ndarray
    conversion: np.ndarray
    segregated: float
    plug: float
    mean_residence_time: float
    class_tau: np.ndarray | None = None
    class_conversion: np.ndarray | None = None

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd

        frame = pd.DataFrame({"tau_s": self.tau, "E_1_s": self.E, "conversion": self.conversion})
        return with_units(frame, "chemistry.segregated")

    def plot(self, ax=None):
        """X(tau) with the RTD on a twin axis and both averages; returns the Figure."""
        import matplotlib.pyplot as plt

        own = ax is None
        if own:
            _, ax = plt.subplots(figsize=(6.4, 4.6))
        ax.plot(self.tau, self.conversion, label="X(tau), parcel")
        ax.axhline(self.segregated, ls="--", color="C1", label=f"segregated {self.segregated:.3f}")
        ax.axhline(self.plug, ls=":", color="C2", label=f"plug flow {self.plug:.3f}")
        ax.set_xlabel("residence time (s)")
        ax.set_ylabel("conversion (-)")
        ax2 = ax.twinx()
        ax2.fill_between(self.tau, self.E, alpha=0.2, color="C3", label="E(t), RTD (right axis)")
        ax2.set_ylabel("E(t) (1/s)")
        # one legend for both axes, below them: inside it would hide a curve
        lines = ax.get_legend_handles_labels()
        shade = ax2.get_legend_handles_labels()
        ax.legend(
            lines[0] + shade[0],
            lines[1] + shade[1],
            fontsize=8,
            ncol=2,
            loc="upper center",
            bbox_to_anchor=(0.5, -0.14),
            frameon=False,
        )
        if own:
            ax.figure.tight_layout()
        return ax.figure


def segregated_average(
    conversion_of_time: Callable, rtd, t=None, t_max=None, n: int = 400
) -> SegregatedResult:
    r"""Segregated-flow average of a conversion history over an RTD.

    .. math:: \bar X = \int_0^{\infty} X(t) E(t)\,dt, \qquad X_{plug} = X(\bar t)

    Parameters
    ----------
    conversion_of_time : callable
        X(t) for an array of times t (s), [-].
    rtd : (t, E) arrays, callable E(t) or object with ``exitage(t)``
        Residence time distribution, 1/s.
    t : array, optional, s
        Time grid for a callable RTD (see :func:`rtd_arrays`).
    t_max : float, optional, s
        End of the default grid.
    n : int
        Points of the default grid.

    Returns
    -------
    SegregatedResult

    Examples
    --------
    First-order reaction (k = 0.01 1/s) in a well-mixed vessel (E = exp(-t/tau)/tau, tau = 100 s):
    the exact segregated conversion is k tau/(1 + k tau) = 0.5, plug flow 1 - e^-1 = 0.632.

    >>> k, tau = 0.01, 100.0
    >>> res = segregated_average(lambda t: 1 - np.exp(-k * t), lambda t: np.exp(-t / tau) / tau,
    ...                          t_max=3000.0, n=6001)
    >>> round(res.segregated, 3), round(res.plug, 3)
    (0.5, 0.632)

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., segregated-flow model (ch.
    15-16).
    """
    tt, E = rtd_arrays(rtd, t, t_max, n)
    X = np.asarray(conversion_of_time(tt), dtype=float)
    if X.shape != tt.shape or not np.all(np.isfinite(X)):
        raise InputError("conversion_of_time", "result", "finite values, one per time")
    tmean = float(trapezoid(tt * E, tt))
    xseg = float(trapezoid(X * E, tt))
    xplug = float(np.interp(tmean, tt, X))
    return SegregatedResult(tt, E, X, xseg, xplug, tmean)


# Dormand & Prince (1980) RK5(4)7M: nodes, stages, 5th-order weights, error weights (5th - 4th).
_DP_C = np.array([0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0])
_DP_A = (
    np.array([1 / 5]),
    np.array([3 / 40, 9 / 40]),
    np.array([44 / 45, -56 / 15, 32 / 9]),
    np.array([19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729]),
    np.array([9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656]),
)
_DP_B = np.array([35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84])
_DP_E = np.array([-71 / 57600, 0.0, 71 / 16695, -71 / 1920, 17253 / 339200, -22 / 525, 1 / 40])


class _Profiles:
    """Profiles of z evaluated at an array of positions; tabulated ones share one table.

    Tabulated profiles are linear between the union of their abscissae (the knots), so they are
    held as one table on the knots and interpolated together; constants are rows of that
    table; callables are called with the array (or point by point if they do not vectorise).
    """

    def __init__(self, profiles: Mapping, length: float):
        knots = [np.array([0.0, length])]
        self.tabulated, self.callables = {}, {}
        for key, value in profiles.items():
            f = as_profile(key, value)
            if isinstance(value, tuple | list) and len(value) == 2 and np.ndim(value[0]) == 1:
                z = np.asarray(value[0], dtype=float)
                knots.append(z[(z > 0) & (z < length)])
                self.tabulated[key] = f
            elif not callable(value):
                self.tabulated[key] = f
            else:
                self.callables[key] = self._vectorised(f, length)
        self.knots = np.unique(np.concatenate(knots))
        self.keys = list(self.tabulated)
        self.table = np.array(
            [np.broadcast_to(f(self.knots), self.knots.shape) for f in self.tabulated.values()]
        ).reshape(len(self.keys), -1)
        self.slope = np.diff(self.table, axis=1) / np.diff(self.knots)

    @staticmethod
    def _vectorised(f, length):
        probe = np.linspace(0.0, length, 11)
        scalar = np.array([float(f(x)) for x in probe])
        try:
            vec = np.broadcast_to(np.asarray(f(probe), dtype=float), probe.shape)
            if np.allclose(vec, scalar, rtol=1e-12, atol=0.0):
                return lambda zz: np.broadcast_to(np.asarray(f(zz), dtype=float), zz.shape)
        except (TypeError, ValueError):
            pass
        return lambda zz: np.array([float(f(x)) for x in zz])

    def __call__(self, z: np.ndarray) -> dict:
        i = np.clip(np.searchsorted(self.knots, z, side="right") - 1, 0, self.knots.size - 2)
        rows = self.table[:, i] + self.slope[:, i] * (z - self.knots[i])
        out = dict(zip(self.keys, rows, strict=True))
        for k, f in self.callables.items():
            out[k] = f(z)
        return out


def batch_plug_flow_conversion(
    mechanism: Mechanism,
    bed_mass_flow_in: Mapping[str, float],
    species: str,
    length: float,
    residence_times,
    T_bed,
    T_gas=None,
    partial_pressure: Mapping | None = None,
    inputs: Mapping | None = None,
    rtol: float = 1e-9,
) -> np.ndarray:
    r"""Outlet conversion of a bed species for many residence times, in one batched integration.

    Each residence time :math:`\tau_k` is a plug-flow path (velocity :math:`L/\tau_k`) through the
    same profiles of z; in the kiln coordinate all paths obey the equations of
    :func:`~rotarykiln.chemistry.plugflow.integrate_plug_flow`,

    .. math:: \frac{dQ_{i,k}}{dz} = \dot w_i\big(T_b(z), T_g(z), p(z), Q_{\cdot,k},
              m'_k = \textstyle\sum_j Q_{j,k}\,\tau_k/L\big),\qquad X_k = 1 - Q_{s,k}(L)/Q_{s,in}

    and are integrated together: one vectorised :meth:`Mechanism.rates` call per stage serves
    every path. The integrator is an explicit Dormand-Prince 5(4) pair with a step size and an
    error control of its own for each path (a path finishing its reactant, with the
    :math:`\sqrt{1-x}` singularity of an order-1/2 law, does not slow the others) that steps
    exactly onto the knots of tabulated profiles (their slope breaks there) with at most L/100
    per step. The local error of each path is held to ``rtol`` relative and :math:`10^{-12}`
    of the total feed absolute. The default rtol is ten times tighter than the 1e-8 of
    :func:`~rotarykiln.chemistry.plugflow.integrate_plug_flow`, because an explicit pair
    underestimates the error of a step across a jump of a rate (an onset temperature): the
    outlet conversions then agree with per-class LSODA to about 1e-7. Implicit solvers (BDF,
    Radau) with a finite-difference Jacobian fail at the square-root singularity.

    Parameters
    ----------
    mechanism : Mechanism
    bed_mass_flow_in : mapping
        Bed species -> inlet mass flow, kg/s.
    species : str
        Bed species whose conversion is returned (a positive inlet flow).
    length : float
        Path length (the kiln length), m.
    residence_times : array
        Residence times of the paths, s (> 0).
    T_bed : float, callable of z [m] or (z, T) arrays
        Bed temperature, K.
    T_gas : same types, optional
        Gas temperature, K (default: the bed temperature).
    partial_pressure : mapping, optional
        Gas species -> partial pressure (Pa) as float, callable of z or (z, p) arrays.
    inputs : mapping, optional
        Extra rate-law inputs (``steam_mass_flow`` kg/s, ``drying_conductance`` W/(m K),
        ``bed_heat_input`` W/m), same types.
    rtol : float, -
        Relative tolerance of each path.

    Returns
    -------
    ndarray
        Outlet conversion of ``species`` for each residence time, [-].

    Examples
    --------
    Order-1/2 calcination at 1100 K (k = 0.0177 1/s): X = 1 - (1 - k t/2)^2 while t < 2/k.

    >>> mech = Mechanism.builtin("calcination_luisser")
    >>> x = batch_plug_flow_conversion(mech, {"CaCO3": 0.01}, "CaCO3", 0.5, [10.0, 50.0], 1100.0)
    >>> np.round(x, 3)
    array([0.169, 0.69 ])

    References
    ----------
    Dormand, J. R. & Prince, P. J. (1980) A family of embedded Runge-Kutta formulae, J. Comput.
    Appl. Math. 6, 19-26. Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    sp = mechanism.species
    check_positive("batch_plug_flow.length", length, "m")
    length = float(length)
    taus = np.atleast_1d(np.asarray(residence_times, dtype=float))
    if taus.ndim != 1 or taus.size == 0:
        raise InputError("batch_plug_flow.residence_times", taus.shape, "a 1-D array, not empty")
    check_positive("batch_plug_flow.residence_times", taus, "s")
    check_positive("batch_plug_flow.rtol", rtol)
    if not isinstance(bed_mass_flow_in, Mapping) or not bed_mass_flow_in:
        raise InputError(
            "batch_plug_flow.bed_mass_flow_in", bed_mass_flow_in, "a mapping bed species -> kg/s"
        )
    bed = sp.bed_names
    for name, v in bed_mass_flow_in.items():
        if name not in bed:
            raise InputError(
                f"batch_plug_flow.bed_mass_flow_in.{name}",
                name,
                f"a bed species ({', '.join(bed)})",
            )
        check_nonnegative(f"batch_plug_flow.bed_mass_flow_in.{name}", v, "kg/s")
    ref = {k: float(v) for k, v in bed_mass_flow_in.items()}
    if ref.get(species, 0.0) <= 0:
        raise InputError("batch_plug_flow.species", species, "a bed species with a positive feed")
    # species that are fed or take part in a reaction; the others stay at zero
    S = mechanism.mass_stoichiometry
    active = [s for s in bed if ref.get(s, 0.0) > 0 or np.any(S[:, sp.index(s)] != 0)]
    ia = [sp.index(s) for s in active]
    nb, nc = len(active), taus.size
    q0 = np.array([ref.get(s, 0.0) for s in active])
    atol = 1e-12 * q0.sum()

    gas = sp.gas_names
    for k in partial_pressure or {}:
        if k not in gas:
            raise InputError(f"batch_plug_flow.partial_pressure.{k}", k, "a gas species")
    pre = "batch_plug_flow."
    prof = _Profiles(
        {
            pre + "T_bed": T_bed,
            pre + "T_gas": T_bed if T_gas is None else T_gas,
            **{f"{pre}partial_pressure.{k}": v for k, v in (partial_pressure or {}).items()},
            **{f"{pre}inputs.{k}": v for k, v in (inputs or {}).items()},
        },
        length,
    )
    at_check = prof(np.linspace(0.0, length, 11))
    check_positive(pre + "T_bed", at_check[pre + "T_bed"], "K")
    check_positive(pre + "T_gas", at_check[pre + "T_gas"], "K")
    p_keys = {f"{pre}partial_pressure.{k}": k for k in partial_pressure or {}}
    in_keys = {f"{pre}inputs.{k}": k for k in inputs or {}}
    knots = prof.knots
    hold = taus / length  # hold-up per flow, s/m

    def rhs(z, y):
        q = np.maximum(y, 0.0)
        v = prof(z)
        state = CellState(
            T_bed=v[pre + "T_bed"],
            T_gas=v[pre + "T_gas"],
            bed_mass_flow={s: q[i] for i, s in enumerate(active)},
            bed_mass_per_length=q.sum(axis=0) * hold,
            partial_pressure={k: v[key] for key, k in p_keys.items()},
            bed_mass_flow_in=ref,
            inputs={k: v[key] for key, k in in_keys.items()},
        )
        return mechanism.rates(state).production[:, ia].T

    def rms(e):
        return np.sqrt(np.mean(e * e, axis=0))

    z = np.zeros(nc)
    y = np.repeat(q0[:, None], nc, axis=1)
    f0 = rhs(z, y)
    max_step = length / 100.0
    # first step (Hairer, Norsett & Wanner, II.4): 1 % of the time scale y/y'
    scale = atol + rtol * np.abs(y)
    d0, d1 = rms(y / scale), rms(f0 / scale)
    h = np.where((d0 < 1e-5) | (d1 < 1e-5), 1e-6 * length, 0.01 * d0 / np.maximum(d1, 1e-300))
    h = np.minimum(h, max_step)
    rejected = np.zeros(nc, dtype=bool)
    K = np.empty((7, nb, nc))
    log.debug("batched plug flow: %d residence times, %d bed species", nc, nb)
    bar = progress_bar(length, desc=f"{nc} RTD classes", unit="m")
    shown = 0.0  # the bar: how far along the kiln the slowest class has come
    for _ in range(200_000):
        done = z >= length
        front = float(min(z.min(), length))
        if front > shown:
            bar.update(front - shown)
            shown = front
        if done.all():
            bar.close()
            break
        z_next = knots[np.minimum(np.searchsorted(knots, z, side="right"), knots.size - 1)]
        hs = np.minimum(h, max_step)
        clamped = hs >= z_next - z
        hs = np.where(done, 0.0, np.where(clamped, z_next - z, hs))
        K[0] = f0
        for i, a in enumerate(_DP_A, start=1):
            K[i] = rhs(z + _DP_C[i] * hs, y + hs * (a @ K[:i].reshape(i, -1)).reshape(nb, nc))
        y_new = y + hs * (_DP_B @ K[:6].reshape(6, -1)).reshape(nb, nc)
        z_new = np.where(clamped, z_next, z + hs)
        K[6] = rhs(z_new, y_new)
        scale = atol + rtol * np.maximum(np.abs(y), np.abs(y_new))
        err = rms(hs * (_DP_E @ K.reshape(7, -1)).reshape(nb, nc) / scale)
        ok = (err < 1.0) & ~done
        with np.errstate(divide="ignore"):
            factor = np.where(err > 0, 0.9 * err**-0.2, 10.0)
        grow = np.where(rejected, np.minimum(factor, 1.0), np.minimum(factor, 10.0))
        h_ok = np.where(clamped & (grow >= 1.0), np.maximum(hs * grow, h), hs * grow)
        h = np.where(done, h, np.where(ok, h_ok, hs * np.maximum(factor, 0.2)))
        rejected = ~ok & ~done
        z = np.where(ok, z_new, z)
        y = np.where(ok, y_new, y)
        f0 = np.where(ok, K[6], f0)
        small = ~done & ~ok & (h < 1e-12 * length)
        if small.any():
            bar.close()
            k = int(np.flatnonzero(small)[0])
            raise ConvergenceError(
                "batched plug-flow integration: step size underflow",
                where_z=float(z[k]),
                residence_time=float(taus[k]),
            )
    else:
        bar.close()
        k = int(np.flatnonzero(z < length)[0])
        raise ConvergenceError(
            "batched plug-flow integration: too many steps",
            where_z=float(z[k]),
            residence_time=float(taus[k]),
        )
    return 1.0 - np.maximum(y[active.index(species)], 0.0) / ref[species]


def kiln_segregated_conversion(
    mechanism: Mechanism,
    bed_mass_flow_in: Mapping[str, float],
    species: str,
    length: float,
    rtd,
    T_bed,
    T_gas=None,
    partial_pressure: Mapping | None = None,
    inputs: Mapping | None = None,
    n_tau: int = 40,
    t=None,
    t_max=None,
    n: int = 400,
    *,
    extra_residence_times=(),
) -> SegregatedResult:
    r"""Segregated-flow vs plug-flow conversion of a bed species in a kiln with a given T(z).

    Each residence-time class :math:`\tau` crosses the kiln at the velocity :math:`L/\tau`
    through the profiles given as functions of z; all classes are integrated together by
    :func:`batch_plug_flow_conversion` (the equations of
    :func:`~rotarykiln.chemistry.plugflow.integrate_plug_flow`), and the conversion
    :math:`X(\tau) = 1 - Q(L)/Q_{in}` is then averaged over the RTD. The plug-flow value is the
    class at the mean residence time.

    Parameters
    ----------
    mechanism : Mechanism
    bed_mass_flow_in : mapping
        Bed species -> inlet mass flow, kg/s.
    species : str
        Bed species whose conversion is reported.
    length : float
        Kiln length, m.
    rtd : (t, E) arrays, callable or object with ``exitage``
        Residence time distribution (1/s) of the bed.
    T_bed, T_gas, partial_pressure, inputs :
        Profiles along z as for :func:`integrate_plug_flow`.
    n_tau : int
        Number of residence-time classes integrated (X is interpolated between them).
    t, t_max, n :
        Grid of a callable RTD.
    extra_residence_times : array, optional
        More residence times (s) integrated in the same batch (at no extra cost) but not used in
        the average; their conversions end ``class_conversion``.

    Returns
    -------
    SegregatedResult
    """
    check_positive("segregated.length", length, "m")
    tt, E = rtd_arrays(rtd, t, t_max, n)
    tmean = float(trapezoid(tt * E, tt))
    # classes where E carries weight (plus the mean)
    cdf = np.concatenate([[0.0], np.cumsum(0.5 * (E[1:] + E[:-1]) * np.diff(tt))])
    lo = float(np.interp(1e-4, cdf, tt))
    hi = float(np.interp(1.0 - 1e-5, cdf, tt))
    lo = max(lo, tt[tt > 0][0] if np.any(tt > 0) else 1e-9)
    taus = np.unique(np.concatenate([np.geomspace(lo, hi, int(n_tau)), [tmean]]))
    extra = np.atleast_1d(np.asarray(extra_residence_times, dtype=float)).ravel()
    all_tau = np.concatenate([taus, extra])
    X_all = batch_plug_flow_conversion(
        mechanism,
        bed_mass_flow_in,
        species,
        length,
        all_tau,
        T_bed,
        T_gas,
        partial_pressure,
        inputs,
    )
    Xc = X_all[: taus.size]
    # a parcel of zero residence time is unconverted; beyond hi (1e-5 of the weight) hold X
    X = np.interp(tt, np.concatenate([[0.0], taus]), np.concatenate([[0.0], Xc]), right=Xc[-1])
    xseg = float(trapezoid(X * E, tt))
    xplug = float(Xc[np.argmin(np.abs(taus - tmean))])
    return SegregatedResult(tt, E, X, xseg, xplug, tmean, all_tau, X_all)
