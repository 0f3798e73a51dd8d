r"""Tracer (pulse stimulus-response) data: E(t), F(t), moments, replicate statistics.

Seed 003 eqs. 1-7, with :math:`w_i` the integration weight of sample i:

.. math::

    E(t_i) = \frac{C_i}{\sum_j C_j w_j},\qquad
    \bar t = \frac{\sum_i t_i C_i w_i}{\sum_i C_i w_i},\qquad
    \sigma^2 = \frac{\sum_i (t_i - \bar t)^2 C_i w_i}{\sum_i C_i w_i},

    \theta = t/\bar t,\qquad E(\theta) = \bar t E(t),\qquad \sigma_\theta^2 = \sigma^2/\bar t^2 .

Weights: ``"trapezoid"`` (default; any sampling steps) or ``"rectangle"`` (:math:`w_i = \Delta t_i`,
the length of the collection window ending at :math:`t_i`; seed 003's eq. 2 with its constant
30 s windows). Both give the same moments for constant steps when the curve starts and ends at
the baseline.

Signals: a concentration or mass fraction (used as is), a conductivity (optionally mapped by a
linear calibration; seed 003 takes the NaCl concentration proportional to it), or the tracer mass
found in each collection window (divided by the window length to give a rate).
"""

from __future__ import annotations

import re
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.errors import InputError
from rotarykiln.tables import with_units
from rotarykiln.units import to_si

__all__ = [
    "ReplicateStats",
    "TracerResult",
    "TruncatedCurveWarning",
    "analyse_tracer",
    "read_tracer_csv",
    "replicate_statistics",
]

SIGNALS = ("concentration", "mass_fraction", "conductivity", "tracer_mass")
MAX_TIME = 1e10
"""Largest time of a tracer file, s (about 300 years; the longest mean residence time a case
accepts)."""
MAX_SIGNAL = 1e15
"""Largest magnitude of a tracer signal (any unit): sums of signal x time stay finite."""


class TruncatedCurveWarning(UserWarning):
    """The tracer curve does not return to the baseline: part of the tracer is unaccounted for."""


@dataclass(frozen=True)
class TracerResult:
    """Residence time distribution measured with a tracer.

    Attributes
    ----------
    t : numpy.ndarray
        Sample times [s].
    signal : numpy.ndarray
        Baseline-corrected, calibrated tracer signal (arbitrary unit).
    exit_age : numpy.ndarray
        E(t_i) [1/s].
    cumulative : numpy.ndarray
        F(t_i) [-].
    mean : float
        Mean residence time of the data [s] (first moment, eq. 3).
    variance : float
        Variance of the data [s2] (eq. 4).
    unaccounted_fraction : float or None
        Estimated fraction of tracer after the last sample (0 when the curve is complete, None
        when the tail does not decay and no estimate is possible).
    recovery : float or None
        Recovered / injected tracer mass (``tracer_mass`` signals with an injected mass).
    """

    t: np.ndarray
    signal: np.ndarray
    exit_age: np.ndarray
    cumulative: np.ndarray
    mean: float
    variance: float
    unaccounted_fraction: float | None = 0.0
    recovery: float | None = None

    @property
    def sigma_theta2(self) -> float:
        """Normalised variance sigma^2 / t_mean^2 [-] (eq. 7)."""
        return self.variance / self.mean**2

    @property
    def theta(self) -> np.ndarray:
        """Normalised time t / t_mean [-] (eq. 5)."""
        return self.t / self.mean

    @property
    def exit_age_theta(self) -> np.ndarray:
        """E(theta) = t_mean E(t) [-] (eq. 6)."""
        return self.exit_age * self.mean

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd

        frame = pd.DataFrame(
            {
                "t_s": self.t,
                "signal": self.signal,
                "E_1_s": self.exit_age,
                "F": self.cumulative,
                "theta": self.theta,
                "E_theta": self.exit_age_theta,
            }
        )
        return with_units(frame, "rtd.tracer", {"signal": "a.u."})

    def plot(self, ax=None, *, minutes: bool = True, **kwargs):
        """E(t) points (per minute against minutes by default). Returns the Figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        k = 60.0 if minutes else 1.0
        kwargs.setdefault("marker", "o")
        kwargs.setdefault("linestyle", "none")
        kwargs.setdefault("label", "data")
        ax.plot(self.t / k, self.exit_age * k, **kwargs)
        ax.set_xlabel("t (min)" if minutes else "t (s)")
        ax.set_ylabel("E(t) (1/min)" if minutes else "E(t) (1/s)")
        return ax.figure


def _weights(t: np.ndarray, kind: str) -> np.ndarray:
    dt = np.diff(t)
    if kind == "trapezoid":
        w = np.zeros_like(t)
        w[:-1] += dt / 2
        w[1:] += dt / 2
        return w
    if kind == "rectangle":
        return np.concatenate([[dt[0]], dt])
    raise InputError("weights", kind, "trapezoid or rectangle")


def _check_samples(t, c) -> tuple[np.ndarray, np.ndarray]:
    t = np.asarray(t, dtype=float)
    c = np.asarray(c, dtype=float)
    if t.ndim != 1 or c.shape != t.shape:
        raise InputError("signal", f"{c.size} values for {t.size} times", "one value per time")
    if t.size < 3:
        raise InputError("t", f"{t.size} samples", "at least 3 samples")
    if not np.all(np.isfinite(t)):
        raise InputError("t", "a non-finite time", "finite")
    steps = np.diff(t)
    if np.any(steps <= 0):
        i = int(np.argmax(steps <= 0))
        raise InputError(
            "t",
            f"{t[i + 1]:g} s after {t[i]:g} s (sample {i + 2})",
            "strictly increasing",
        )
    if not np.all(np.isfinite(c)):
        i = int(np.argmax(~np.isfinite(c)))
        raise InputError("signal", f"{c[i]} at t = {t[i]:g} s", "a finite number")
    if np.any(c < 0):
        i = int(np.argmax(c < 0))
        raise InputError("signal", f"{c[i]:g} at t = {t[i]:g} s", ">= 0 (a tracer concentration)")
    return t, c


def _tail_fraction(t, c, area, tolerance) -> float | None:
    """Fraction of tracer after the last sample, by extrapolating the exponential decay of the
    last three samples (an overestimate for bell-shaped tails, which decay faster)."""
    peak = c.max()
    if c[-1] <= tolerance * peak:
        return 0.0
    i_peak = int(np.argmax(c))
    post = np.arange(i_peak, t.size)
    tail = post[-3:]
    tail = tail[c[tail] > 0]
    if tail.size >= 3:
        slope = np.polyfit(t[tail], np.log(c[tail]), 1)[0]
        if slope < 0:
            missing = c[-1] / -slope
            return float(missing / (area + missing))
    return None


def analyse_tracer(
    t,
    signal,
    *,
    kind: str = "concentration",
    baseline: float | str | None = None,
    calibration: tuple[float, float] | None = None,
    weights: str = "trapezoid",
    injected_mass: float | None = None,
    tail_tolerance: float = 0.01,
) -> TracerResult:
    """E(t), F(t), mean and variance of a tracer curve (seed 003 eqs. 1-7).

    Parameters
    ----------
    t : array_like
        Sample times since injection [s], strictly increasing.
    signal : array_like
        Tracer signal at the outlet, >= 0: concentration or mass fraction, conductivity
        [any unit], or tracer mass per collection window [kg] (see ``kind``).
    kind : {"concentration", "mass_fraction", "conductivity", "tracer_mass"}
        What ``signal`` is.
    baseline : float, "auto" or None
        Background signal (unit of ``signal``) subtracted first ("auto": median of the first
        three samples); small negative values left by the subtraction are set to 0.
    calibration : (slope, intercept), optional
        Linear map of a conductivity to a concentration, c = slope * signal + intercept.
    weights : {"trapezoid", "rectangle"}
        Integration weights (see module docstring).
    injected_mass : float, optional
        Injected tracer mass [kg] (``tracer_mass`` signals): gives the recovery.
    tail_tolerance : float
        The curve counts as complete when its last value is below this fraction of its peak;
        otherwise a :class:`TruncatedCurveWarning` gives the estimated fraction unaccounted for.

    Returns
    -------
    TracerResult

    Raises
    ------
    InputError
        Negative or non-finite signal, times not strictly increasing, fewer than 3 samples, or
        no tracer above the baseline.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0.0, 61.0) * 60.0
    >>> c = np.exp(-((t / 60.0 - 30.0) ** 2) / 8.0)
    >>> res = analyse_tracer(t, c)
    >>> round(res.mean / 60, 3), round(res.variance / 3600, 3)
    (30.0, 4.0)
    """
    if kind not in SIGNALS:
        raise InputError("kind", kind, "one of " + ", ".join(SIGNALS))
    t, c = _check_samples(t, signal)
    if isinstance(baseline, str):
        if baseline != "auto":
            raise InputError("baseline", baseline, 'a number, "auto" or None')
        baseline = float(np.median(c[:3]))
    if baseline is not None:
        c = np.clip(c - float(baseline), 0.0, None)
    if calibration is not None:
        slope, intercept = calibration
        c = slope * c + intercept
        if np.any(c < 0):
            raise InputError("calibration", calibration, "giving concentrations >= 0")
    if kind == "tracer_mass":
        recovered = float(c.sum())
        c = c / _weights(t, "rectangle")  # mass per window -> mass rate
    w = _weights(t, weights)
    area = float(np.sum(c * w))
    if not area > 0:
        raise InputError("signal", "zero everywhere (after baseline correction)", "a tracer pulse")
    e = c / area
    mean = float(np.sum(t * e * w))
    variance = float(np.sum((t - mean) ** 2 * e * w))
    if weights == "trapezoid":
        f = np.concatenate([[0.0], np.cumsum(0.5 * (e[1:] + e[:-1]) * np.diff(t))])
    else:
        f = np.cumsum(e * w)
    if c[0] > tail_tolerance * c.max():
        warnings.warn(
            f"the tracer curve starts at {100 * c[0] / c.max():.1f} % of its peak: sampling began "
            "after the first tracer left; the mean and variance are biased",
            TruncatedCurveWarning,
            stacklevel=2,
        )
    lost = _tail_fraction(t, c, area, tail_tolerance)
    if lost is None:
        warnings.warn(
            f"the tracer curve ends at {100 * c[-1] / c.max():.1f} % of its peak and its tail does "
            "not decay: an unknown fraction of the tracer is unaccounted for; the mean and variance "
            "are underestimated",
            TruncatedCurveWarning,
            stacklevel=2,
        )
    elif lost > 0:
        warnings.warn(
            f"the tracer curve ends at {100 * c[-1] / c.max():.1f} % of its peak: about "
            f"{100 * lost:.1f} % of the tracer is unaccounted for (exponential tail extrapolation); "
            "the mean and variance are underestimated",
            TruncatedCurveWarning,
            stacklevel=2,
        )
    recovery = None
    if kind == "tracer_mass" and injected_mass is not None:
        if not injected_mass > 0:
            raise InputError("injected_mass", injected_mass, "> 0 kg")
        recovery = recovered / injected_mass
    return TracerResult(t, c, e, f, mean, variance, lost, recovery)


@dataclass(frozen=True)
class ReplicateStats:
    """Mean, sample standard deviation (n - 1) and coefficient of variation of replicates."""

    mean: float
    std: float
    cv: float
    n: int


def replicate_statistics(values) -> ReplicateStats:
    """Replicate statistics as in seed 003 Table 3: mean, sample SD (n - 1), Cv = SD/mean.

    Parameters
    ----------
    values : array_like
        Two or more replicate values (e.g. mean residence times [s]).

    Returns
    -------
    ReplicateStats
        ``cv`` as a fraction (multiply by 100 for %).

    Examples
    --------
    >>> s = replicate_statistics([43.39, 43.64, 42.99])
    >>> round(100 * s.cv, 2)
    0.76
    """
    v = np.asarray(values, dtype=float)
    if v.ndim != 1 or v.size < 2:
        raise InputError("values", f"{v.size} value(s)", "at least 2 replicates")
    if not np.all(np.isfinite(v)):
        raise InputError("values", "a non-finite value", "finite")
    mean = float(v.mean())
    if mean == 0:
        raise InputError("values", "a zero mean", "a non-zero mean")
    std = float(v.std(ddof=1))
    return ReplicateStats(mean, std, std / abs(mean), int(v.size))


_UNIT = re.compile(r"^\s*(?P<name>[^\[\(]*?)\s*[\[\(](?P<unit>[^\]\)]+)[\]\)]\s*$")


def read_tracer_csv(path, *, time_unit: str | None = None) -> tuple[np.ndarray, np.ndarray, str]:
    """Read a tracer curve from a CSV file: first column time, second column signal.

    The time unit is taken from the header (``time [min]``, ``t (s)``) or from ``time_unit``.

    Parameters
    ----------
    path : path-like
        CSV file with a header row.
    time_unit : str, optional
        Unit of the time column when the header has none (e.g. "min").

    Returns
    -------
    (t, signal, signal_name)
        Times [s], signal values (as in the file), and the signal column header.

    Raises
    ------
    InputError
        One line naming the file: beyond the data-file limits of
        :func:`rotarykiln.studies.io.read_data_csv` (size, 100,000 rows, UTF-8), no unit of
        time, a cell that is not a number, a time beyond :data:`MAX_TIME` s or a signal beyond
        :data:`MAX_SIGNAL`.
    """
    import pandas as pd

    from rotarykiln.studies.io import read_data_csv, shown

    name = shown(str(path), 200)
    frame = read_data_csv(path, "", what="tracer file", comment="#", dtype=str)
    if frame.shape[1] < 2:
        raise InputError(str(path), message=f"{name}: needs two columns, time and tracer signal")
    time_header = str(frame.columns[0])
    m = _UNIT.match(time_header)
    unit = m.group("unit") if m else time_unit
    if unit is None:
        raise InputError(
            f"{name}: column {shown(time_header)}",
            message=f"{name}: the time column {shown(time_header)} has no unit; write it as "
            '"time [min]" or give the unit (--time-unit min)',
        )
    factor = to_si(f"{name}: time unit", f"1 {shown(unit)}", "time")
    columns = frame.iloc[:, :2]
    numeric = columns.apply(pd.to_numeric, errors="coerce")
    bad = numeric.isna().any(axis=1)
    if bad.any():
        row = int(np.argmax(bad.to_numpy()))
        cells = ", ".join(shown(v, 40) for v in columns.iloc[row].tolist())
        raise InputError(str(path), message=f"{name}: line {row + 2}: {cells} is not two numbers")
    values = numeric.to_numpy(float)
    t = values[:, 0] * factor
    limits = (("time", t, MAX_TIME, "s"), ("signal", values[:, 1], MAX_SIGNAL, ""))
    for what, x, high, unit_si in limits:
        out = ~(np.abs(x) <= high)  # NaN and inf too
        if out.any():
            row = int(np.argmax(out))
            raise InputError(
                str(path),
                message=f"{name}: line {row + 2}: {what} {x[row]:.6g}{' ' + unit_si if unit_si else ''}"
                f" is not a finite number in [-{high:g}, {high:g}]",
            )
    return t, values[:, 1], str(frame.columns[1])
