r"""Predicted RTD of a kiln: a mean residence time and a Peclet number give E(t).

The mean residence time and the Peclet number are given, or the Peclet number follows from a
dispersion coefficient D (:mod:`rotarykiln.rtd.correlations`) through :func:`tau_and_peclet`
(a case's ``rtd:`` section is read by :mod:`rotarykiln.commands.model_runs`):

.. math::

    Pe = \frac{uL}{D} = \frac{L^2}{D\,\tau}, \qquad \tau\,\bar\theta(Pe) = \bar t,

solved together for :math:`\tau` (for open-open boundaries :math:`\bar\theta = 1 + 2/Pe`), so
that the mean of the predicted E(t) is the given mean residence time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd
from scipy import optimize

from rotarykiln.errors import InputError, check_positive
from rotarykiln.rtd.dispersion import SHAPE_RANGE, get_model
from rotarykiln.tables import with_units

__all__ = ["RTDPrediction", "check_peclet", "predict_rtd", "tau_and_peclet"]


@dataclass(frozen=True)
class RTDPrediction:
    """Predicted residence time distribution of a kiln (times in s, E in 1/s)."""

    t: np.ndarray
    exit_age: np.ndarray
    cumulative: np.ndarray
    model: str
    tau: float
    peclet: float
    mean_residence_time: float
    variance: float
    length: float | None = None
    source: str = ""

    @property
    def dispersion(self) -> float | None:
        """D = L^2/(Pe tau) [m2/s] (None without a length)."""
        return None if self.length is None else self.length**2 / (self.peclet * self.tau)

    def summary(self) -> dict:
        out = {
            "rtd_model": self.model,
            "rtd_peclet": self.peclet,
            "rtd_peclet_source": self.source,
            "rtd_mean_residence_time_s": self.mean_residence_time,
            "rtd_variance_s2": self.variance,
            "rtd_tau_s": self.tau,
        }
        if self.dispersion is not None:
            out["rtd_dispersion_m2_s"] = self.dispersion
        return out

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd

        frame = pd.DataFrame({"t_s": self.t, "E_1_s": self.exit_age, "F": self.cumulative})
        return with_units(frame, "rtd.predict")

    def plot(self, ax=None, *, minutes: bool = True):
        """E(t) of the prediction. Returns the Figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        k = 60.0 if minutes else 1.0
        ax.plot(self.t / k, self.exit_age * k, "-", label=f"{self.model}, Pe = {self.peclet:.4g}")
        ax.axvline(self.mean_residence_time / k, color="0.5", linestyle=":", label="mean")
        ax.set_xlabel("t (min)" if minutes else "t (s)")
        ax.set_ylabel("E(t) (1/min)" if minutes else "E(t) (1/s)")
        ax.legend()
        return ax.figure


def predict_rtd(
    mean_residence_time: float,
    *,
    peclet: float | None = None,
    dispersion: float | None = None,
    length: float | None = None,
    model: str = "open-open",
    t=None,
    n_points: int = 400,
    source: str = "",
) -> RTDPrediction:
    """E(t) of a kiln with a given mean residence time and a Peclet number (or D and L).

    Parameters
    ----------
    mean_residence_time : float
        Mean of the predicted RTD [s].
    peclet : float, optional
        Peclet number uL/D [-] (give this, or ``dispersion`` with ``length``).
    dispersion : float, optional
        Axial dispersion coefficient D [m2/s].
    length : float, optional
        Kiln length [m] (needed with ``dispersion``; gives D otherwise).
    model : str
        Dispersion model with a Peclet number ("open-open", "closed-closed", ...).
    t : array_like, optional
        Times [s]; by default ``n_points`` from mean - 6 sd to mean + 8 sd.
    n_points : int
        Number of default times.
    source : str
        Free text recording where the Peclet number came from.

    Returns
    -------
    RTDPrediction

    Examples
    --------
    >>> p = predict_rtd(43.34 * 60, dispersion=2.8e-6, length=1.95)
    >>> round(p.peclet), round(p.tau / 60, 2)
    (524, 43.18)
    """
    check_positive("mean_residence_time", mean_residence_time, "s")
    spec = get_model(model)
    if spec.shape != "peclet":
        raise InputError("model", model, "a dispersion model with a Peclet number")
    if (peclet is None) == (dispersion is None):
        raise InputError("peclet", peclet, "given, or else dispersion with length (exactly one)")
    if isinstance(n_points, bool) or not isinstance(n_points, int) or not 2 <= n_points <= 100_000:
        raise InputError("n_points", n_points, "a whole number in [2, 100000]")
    if peclet is not None:
        check_peclet("peclet", peclet)
        tau = mean_residence_time / spec.moments(1.0, peclet)[0]
    else:
        check_positive("dispersion", dispersion, "m2/s")
        if length is None:
            raise InputError("length", None, "given with dispersion")
        check_positive("length", length, "m")
        tau, peclet = tau_and_peclet(spec, mean_residence_time, dispersion, length)
    mean, var = spec.moments(tau, peclet)
    if t is None:
        sd = np.sqrt(var)
        t = np.linspace(max(mean - 6 * sd, 0.0), mean + 8 * sd, n_points)
    t = np.asarray(t, dtype=float)
    return RTDPrediction(
        t,
        spec.exit_age(t, tau, peclet),
        spec.cdf(t, tau, peclet),
        model,
        float(tau),
        float(peclet),
        float(mean),
        float(var),
        length,
        source,
    )


def check_peclet(field: str, peclet, source: str = "") -> None:
    """Refuse a Peclet number outside the models' range (:data:`~.dispersion.SHAPE_RANGE`)."""
    lo, hi = SHAPE_RANGE
    if not (isinstance(peclet, int | float) and lo <= peclet <= hi):
        shown = f"{peclet:.3g}" if isinstance(peclet, int | float) else str(peclet)
        raise InputError(field, f"{shown}{source}", f"in [{lo:g}, {hi:g}]")


def tau_and_peclet(
    spec, mrt: float, dispersion: float, length: float, field: str = "peclet", source: str = ""
) -> tuple[float, float]:
    r"""Space time and Peclet number of a model whose mean is ``mrt`` with D = ``dispersion``.

    .. math:: Pe = \frac{L^2}{D\,\tau},\qquad \tau\,\bar\theta(Pe) = \bar t

    solved over the Peclet numbers of :data:`~.dispersion.SHAPE_RANGE` in logarithms (no
    overflow for any D, L and mrt > 0).

    Parameters
    ----------
    spec : object
        The dispersion model (:func:`rotarykiln.rtd.dispersion.get_model`).
    mrt : float, s
        Mean residence time.
    dispersion : float, m2/s
        Axial dispersion coefficient.
    length : float, m
        Kiln length.
    field : str
        Field named in an error.
    source : str
        Where D came from, for an error.

    Returns
    -------
    (float, float)
        Space time tau (s) and Peclet number (dimensionless).

    Examples
    --------
    >>> from rotarykiln.rtd.dispersion import get_model
    >>> tau, pe = tau_and_peclet(get_model("open-open"), 1200.0, 1e-4, 2.0)
    >>> round(pe, 2), round(tau * (1 + 2 / pe), 6)  # Pe^2 - Pe L^2/(D mrt) - 2 L^2/(D mrt) = 0
    (35.23, 1200.0)

    References
    ----------
    O. Levenspiel, Chemical Reaction Engineering, 3rd ed. (1999), ch. 13.
    """
    log_l2_d = 2.0 * math.log(length) - math.log(dispersion)

    def excess(log_pe):  # log(tau mean(Pe) / mrt), decreasing in Pe
        pe = min(max(math.exp(log_pe), SHAPE_RANGE[0]), SHAPE_RANGE[1])
        return log_l2_d - log_pe + math.log(spec.moments(1.0, pe)[0]) - math.log(mrt)

    lo, hi = (math.log(v) for v in SHAPE_RANGE)
    if excess(lo) < 0 or excess(hi) > 0:
        estimate = (log_l2_d - math.log(mrt)) / math.log(10.0)  # log10 of L^2/(D mrt)
        raise InputError(
            field,
            f"about 1e{estimate:+.1f}{source} (D = {dispersion:.3g} m2/s, L = {length:.3g} m, "
            f"mean residence time {mrt:.3g} s)",
            f"in [{SHAPE_RANGE[0]:g}, {SHAPE_RANGE[1]:g}]",
        )
    log_pe = optimize.brentq(excess, lo, hi, xtol=1e-13, rtol=1e-14)
    peclet = min(max(math.exp(log_pe), SHAPE_RANGE[0]), SHAPE_RANGE[1])
    return mrt / spec.moments(1.0, peclet)[0], peclet
