"""Segregated-flow conversion over a residence time distribution, side by side with plug flow.

In the segregated-flow model every parcel of bed keeps its identity; a parcel that stays a time
:math:`\\tau` reaches the conversion :math:`X(\\tau)` of a batch (plug-flow) path of that
duration, and the outlet conversion is the RTD average

.. math:: \\bar X_{seg} = \\int_0^\\infty X(\\tau)\\, E(\\tau)\\, d\\tau

In a kiln the temperature is a function of position: a parcel of residence time :math:`\\tau`
crosses the kiln of length L at the mean speed :math:`L/\\tau` and so sees :math:`T(z)` with
:math:`z = L t/\\tau` (:func:`kiln_segregated_conversion`). The plug-flow value is
:math:`X(\\bar\\tau)` with :math:`\\bar\\tau = \\int \\tau E\\, d\\tau`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy.integrate import trapezoid

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.chemistry.plugflow import integrate_plug_flow
from rotarykiln.errors import InputError, check_positive

__all__ = [
    "SegregatedResult",
    "rtd_arrays",
    "segregated_average",
    "kiln_segregated_conversion",
]


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
    """

    tau: np.ndarray
    E: np.ndarray
    conversion: np.ndarray
    segregated: float
    plug: float
    mean_residence_time: float

    def to_frame(self) -> pd.DataFrame:
        return pd.DataFrame({"tau [s]": self.tau, "E [1/s]": self.E, "X [-]": self.conversion})

    def plot(self, ax=None):
        """X(tau) with the RTD on a twin axis and both averages; returns the Axes."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        ax.plot(self.tau, self.conversion, label="X(tau), parcel")
        ax.axhline(self.segregated, ls="--", color="C1", label=f"segregated {self.segregated:.3f}")
        ax.axhline(self.plug, ls=":", color="C2", label=f"plug flow {self.plug:.3f}")
        ax.set_xlabel("residence time [s]")
        ax.set_ylabel("conversion [-]")
        ax2 = ax.twinx()
        ax2.fill_between(self.tau, self.E, alpha=0.2, color="C3")
        ax2.set_ylabel("E(t) [1/s]")
        ax.legend(loc="lower right")
        return ax


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
) -> SegregatedResult:
    r"""Segregated-flow vs plug-flow conversion of a bed species in a kiln with a given T(z).

    Each residence-time class :math:`\tau` is integrated with :func:`integrate_plug_flow` at the
    velocity :math:`L/\tau` through the profiles given as functions of z; the conversion
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
    Xc = np.empty_like(taus)
    for i, tau in enumerate(taus):
        res = integrate_plug_flow(
            mechanism,
            bed_mass_flow_in,
            length,
            length / tau,
            T_bed,
            T_gas,
            partial_pressure,
            inputs,
            n_points=2,
        )
        Xc[i] = float(res.conversion(species)[-1])
    # a parcel of zero residence time is unconverted; beyond hi (1e-5 of the weight) hold X
    X = np.interp(tt, np.concatenate([[0.0], taus]), np.concatenate([[0.0], Xc]), right=Xc[-1])
    xseg = float(trapezoid(X * E, tt))
    xplug = float(Xc[np.argmin(np.abs(taus - tmean))])
    return SegregatedResult(tt, E, X, xseg, xplug, tmean)
