r"""Model parameters from tracer data: moment method and nonlinear least squares.

**Moment method** (seed 003 "case 1", "theoretical" parameters). The data give :math:`\bar t` and
:math:`\sigma_\theta^2 = \sigma^2/\bar t^2`; the model's normalised variance is matched to it.
For open-open boundaries with the paper's convention (:math:`\tau \equiv \bar t`, eq. 13):

.. math::

    \sigma_\theta^2 = \frac{2}{Pe} + \frac{8}{Pe^2} \;\Rightarrow\;
    Pe = \frac{8}{\sqrt{1 + 8\sigma_\theta^2} - 1}.

With ``convention="rigorous"`` both moments of the model are matched instead:
:math:`\tau\,\bar\theta(Pe) = \bar t` and :math:`\tau^2\sigma^2_\theta(Pe) = \sigma^2` (for open-open
:math:`\bar\theta = 1 + 2/Pe`), solved numerically; the two conventions coincide for closed-closed.

**Least squares** (seed 003 "case 2", "fitted" parameters): minimise
:math:`\sum_i [E_{model}(t_i;\tau, p) - E_i]^2` over the space time :math:`\tau` and the shape
parameter p (Pe, or the number of tanks). The fitted :math:`\tau` is L/u, *not* the mean of the data:
for open-open boundaries the model mean is :math:`\tau(1 + 2/Pe)`. Seed 003 calls its fitted
:math:`\tau` "MRT"; both are reported here (``tau`` and ``model_mean``) next to ``data_mean``.

The dispersion coefficient is :math:`D = uL/Pe = L^2/(Pe\,\tau)` (eq. 9).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd
from scipy import optimize, stats

from rotarykiln.errors import ConvergenceError, InputError, check_positive
from rotarykiln.rtd.dispersion import MODELS, SHAPE_RANGE, get_model
from rotarykiln.rtd.tracer import TracerResult
from rotarykiln.tables import with_units

__all__ = [
    "FitResult",
    "MomentResult",
    "fit_rtd",
    "fit_tracer",
    "moment_method",
    "open_open_peclet_from_variance",
]


def open_open_peclet_from_variance(sigma_theta2):
    r"""Peclet number from the normalised variance, open-open model with :math:`\tau = \bar t`.

    .. math::

        Pe = \frac{8}{\sqrt{1 + 8\sigma_\theta^2} - 1}

    (the positive root of seed 003 eq. 13).

    Parameters
    ----------
    sigma_theta2 : array_like
        Normalised variance sigma^2 / t_mean^2 [-], > 0.

    Returns
    -------
    numpy.ndarray or float
        Pe [-].

    Examples
    --------
    >>> round(float(open_open_peclet_from_variance(6.91 / 43.39**2)), 1)
    548.9

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565, eq. 13; Levenspiel, O. (1999)
    Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    check_positive("sigma_theta2", sigma_theta2)
    s = np.asarray(sigma_theta2, dtype=float)
    return (8.0 / (np.sqrt(1.0 + 8.0 * s) - 1.0))[()]


class _ModelParameters:
    """Quantities shared by results that carry ``model``, ``tau``, ``shape`` and ``length``."""

    @property
    def peclet(self) -> float | None:
        return self.shape if MODELS[self.model].shape == "peclet" else None

    @property
    def velocity(self) -> float | None:
        """Axial velocity L/tau [m/s] (None without a length)."""
        return None if self.length is None else self.length / self.tau

    @property
    def dispersion(self) -> float | None:
        """D = L^2/(Pe tau) [m2/s] (None without a length or a Peclet number)."""
        if self.length is None or self.peclet is None:
            return None
        return self.length**2 / (self.peclet * self.tau)

    def exit_age(self, t) -> np.ndarray:
        return MODELS[self.model].exit_age(t, self.tau, self.shape)


@dataclass(frozen=True)
class MomentResult(_ModelParameters):
    """Parameters of a model matched to the mean and variance of the data."""

    model: str
    convention: str
    mean: float
    variance: float
    tau: float
    shape: float | None
    length: float | None = None

    @property
    def sigma_theta2(self) -> float:
        return self.variance / self.mean**2


def _normalised_variance_ratio(spec, p):
    mean, var = spec.moments(1.0, p)
    return var / mean**2


def moment_method(
    mean: float,
    variance: float,
    *,
    model: str = "open-open",
    convention: str = "paper",
    length: float | None = None,
) -> MomentResult:
    """Match a model to the mean [s] and variance [s2] of a tracer curve (seed 003 case 1).

    Parameters
    ----------
    mean : float
        Mean residence time of the data [s].
    variance : float
        Variance of the data [s2].
    model : str
        A model of :data:`rotarykiln.rtd.dispersion.MODELS` with a shape parameter.
    convention : {"paper", "rigorous"}
        "paper": tau = mean and sigma_theta^2 = variance/mean^2 is the model's normalised
        variance (seed 003, eqs. 7 and 13); "rigorous": both moments of the model match the data.
    length : float, optional
        Kiln length [m], for the velocity and the dispersion coefficient.

    Returns
    -------
    MomentResult

    Examples
    --------
    >>> r = moment_method(43.39 * 60, 6.91 * 3600, length=1.95)
    >>> round(r.peclet), f"{r.dispersion:.3g}"
    (549, '2.66e-06')

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565, eqs. 7 and 12-13; Levenspiel, O.
    (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    check_positive("mean", mean, "s")
    check_positive("variance", variance, "s2")
    if length is not None:
        check_positive("length", length, "m")
    if convention not in ("paper", "rigorous"):
        raise InputError("convention", convention, "paper or rigorous")
    spec = get_model(model)
    if spec.shape is None:
        raise InputError("model", model, "a model with a shape parameter (not plug flow)")
    s2 = variance / mean**2

    def shape_in_range(p):
        if not SHAPE_RANGE[0] <= p <= SHAPE_RANGE[1]:
            raise InputError(
                "variance",
                f"{variance:g} s2 (sigma_theta^2 = {s2:.4g}, {spec.shape} = {p:.4g})",
                f"reachable by the {model} model ({spec.shape} in "
                f"[{SHAPE_RANGE[0]:g}, {SHAPE_RANGE[1]:g}])",
            )
        return p

    if model == "open-open" and convention == "paper":
        p = shape_in_range(float(open_open_peclet_from_variance(s2)))
        return MomentResult(model, convention, mean, variance, mean, p, length)
    if model == "tanks-in-series":
        p = shape_in_range(1.0 / s2)
        return MomentResult(model, convention, mean, variance, mean, p, length)
    if convention == "paper":

        def g(logp):
            p = np.exp(logp)
            _, var = spec.moments(1.0, p)
            return var - s2

    else:

        def g(logp):
            return _normalised_variance_ratio(spec, np.exp(logp)) - s2

    lo, hi = np.log(1e-6), np.log(1e9)
    if g(lo) * g(hi) > 0:
        raise InputError(
            "variance",
            f"{variance:g} s2 (sigma_theta^2 = {s2:.4g})",
            f"reachable by the {model} model",
        )
    p = float(np.exp(optimize.brentq(g, lo, hi, xtol=1e-14, rtol=1e-13)))
    tau = mean if convention == "paper" else mean / spec.moments(1.0, p)[0]
    return MomentResult(model, convention, mean, variance, tau, p, length)


@dataclass(frozen=True)
class FitResult(_ModelParameters):
    """Least-squares fit of an RTD model to E(t) data.

    ``tau`` is the fitted space time L/u [s]; ``model_mean`` the mean of the fitted E(t) [s];
    ``data_mean`` the first moment of the data [s] (seed 003 calls its fitted tau "MRT").
    ``ci_tau`` and ``ci_shape`` are (low, high) confidence intervals at ``confidence``.
    """

    model: str
    tau: float
    shape: float
    ci_tau: tuple[float, float]
    ci_shape: tuple[float, float]
    t: np.ndarray
    data: np.ndarray
    fitted: np.ndarray
    sse: float
    nfev: int
    confidence: float
    data_mean: float
    data_variance: float
    length: float | None = None
    moments: MomentResult | None = None

    @property
    def residuals(self) -> np.ndarray:
        """Fitted minus measured E(t_i) [1/s]."""
        return self.fitted - self.data

    @property
    def mse(self) -> float:
        return self.sse / self.t.size

    @property
    def r_squared(self) -> float:
        return 1.0 - self.sse / float(np.sum((self.data - self.data.mean()) ** 2))

    @property
    def model_mean(self) -> float:
        return MODELS[self.model].moments(self.tau, self.shape)[0]

    @property
    def model_variance(self) -> float:
        return MODELS[self.model].moments(self.tau, self.shape)[1]

    def summary(self) -> dict:
        """Plain numbers for reports and JSON (SI units)."""
        out = {
            "model": self.model,
            "tau_s": self.tau,
            "tau_ci_s": list(self.ci_tau),
            MODELS[self.model].shape: self.shape,
            f"{MODELS[self.model].shape}_ci": list(self.ci_shape),
            "model_mean_s": self.model_mean,
            "model_variance_s2": self.model_variance,
            "data_mean_s": self.data_mean,
            "data_variance_s2": self.data_variance,
            "sse": self.sse,
            "r_squared": self.r_squared,
            "confidence": self.confidence,
        }
        if self.dispersion is not None:
            out["dispersion_m2_s"] = self.dispersion
        if self.moments is not None:
            out["moment_method"] = {
                "tau_s": self.moments.tau,
                MODELS[self.model].shape: self.moments.shape,
                "dispersion_m2_s": self.moments.dispersion,
            }
        return out

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd

        frame = pd.DataFrame(
            {"t_s": self.t, "E_data_1_s": self.data, "E_fit_1_s": self.fitted}
        ).assign(residual_1_s=self.residuals)
        return with_units(frame, f"rtd.fit.{self.model}")

    def plot(self, ax=None, *, minutes: bool = True):
        """Data points, fitted curve (solid) and moment-method curve (dashed), as seed 003 Fig. 7."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        k = 60.0 if minutes else 1.0
        grid = np.linspace(self.t.min(), self.t.max(), 400)
        ax.plot(self.t / k, self.data * k, "o", label="data")
        name = MODELS[self.model].shape
        label = (
            f"fit: tau = {self.tau / k:.4g} {'min' if minutes else 's'}, {name} = {self.shape:.4g}"
        )
        ax.plot(grid / k, self.exit_age(grid) * k, "-", label=label)
        if self.moments is not None:
            ax.plot(
                grid / k,
                self.moments.exit_age(grid) * k,
                "--",
                label=f"moments: {name} = {self.moments.shape:.4g}",
            )
        ax.set_xlabel("t (min)" if minutes else "t (s)")
        ax.set_ylabel("E(t) (1/min)" if minutes else "E(t) (1/s)")
        ax.legend(
            fontsize="small", ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.15), frameon=False
        )
        return ax.figure


def _data_moments(t, e):
    w = np.zeros_like(t)
    dt = np.diff(t)
    w[:-1] += dt / 2
    w[1:] += dt / 2
    area = float(np.sum(e * w))
    if not area > 0:
        raise InputError("E", "zero everywhere", "a curve with a positive area")
    mean = float(np.sum(t * e * w) / area)
    return mean, float(np.sum((t - mean) ** 2 * e * w) / area)


def fit_rtd(
    t,
    e,
    *,
    model: str = "open-open",
    guess: tuple[float, float] | None = None,
    length: float | None = None,
    confidence: float = 0.95,
    max_nfev: int = 200,
) -> FitResult:
    r"""Fit an RTD model to E(t) data by nonlinear least squares (seed 003 case 2).

    Minimises :math:`\sum_i [E(t_i; \tau, p) - E_i]^2` over :math:`\log\tau` and :math:`\log p`
    (Levenberg-Marquardt); confidence intervals from the Jacobian at the optimum,
    :math:`\mathrm{cov} = s^2 (J^TJ)^{-1}`, :math:`s^2 = SSE/(n - 2)`, with Student's t.

    Parameters
    ----------
    t : array_like
        Times [s], strictly increasing.
    e : array_like
        Measured E(t) [1/s], normalised over the whole curve (e.g. ``TracerResult.exit_age``);
        not renormalised here, so that a curve sampled over part of its range keeps its scale.
    model : str
        Model name (see :data:`rotarykiln.rtd.dispersion.MODELS`), not plug flow.
    guess : (tau, shape), optional
        Starting point; by default the moment method ("rigorous" convention).
    length : float, optional
        Kiln length [m], for the dispersion coefficient.
    confidence : float
        Confidence level of the intervals, in (0, 1).
    max_nfev : int
        Maximum number of model evaluations.

    Returns
    -------
    FitResult

    Raises
    ------
    ConvergenceError
        The optimiser stopped without converging, or the parameters are not identifiable.

    Examples
    --------
    >>> import numpy as np
    >>> from rotarykiln.rtd.dispersion import open_open_exit_age
    >>> t = np.linspace(30.0, 60.0, 61) * 60
    >>> fit = fit_rtd(t, open_open_exit_age(t, 2520.0, 600.0), length=1.95)
    >>> round(fit.tau), round(fit.peclet)
    (2520, 600)
    """
    t = np.asarray(t, dtype=float)
    e = np.asarray(e, dtype=float)
    if t.shape != e.shape or t.ndim != 1 or t.size < 4:
        raise InputError("E", f"{e.size} values for {t.size} times", "at least 4 (t, E) pairs")
    if not (np.all(np.isfinite(t)) and np.all(np.diff(t) > 0)):
        raise InputError("t", "not finite and strictly increasing", "strictly increasing times")
    if not np.all(np.isfinite(e)) or np.any(e < 0):
        raise InputError("E", "negative or non-finite values", ">= 0")
    if not 0 < confidence < 1:
        raise InputError("confidence", confidence, "in (0, 1)")
    spec = get_model(model)
    if spec.shape is None:
        raise InputError("model", model, "a model with a shape parameter (not plug flow)")
    data_mean, data_var = _data_moments(t, e)
    moments = moment_method(data_mean, data_var, model=model, convention="paper", length=length)
    if guess is None:
        start = moment_method(data_mean, data_var, model=model, convention="rigorous")
        guess = (start.tau, start.shape)
    check_positive("guess", guess)
    scale = float(e.max())

    def residual(x):
        # far from the data the trial parameters may overflow or leave the models' range
        # (SHAPE_RANGE): a large residual steers back, without evaluating the model there
        with np.errstate(all="ignore"):
            tau, shape = np.exp(x[0]), np.exp(x[1])
            if not (0 < tau < np.inf and SHAPE_RANGE[0] <= shape <= SHAPE_RANGE[1]):
                return np.full(t.size, 1e6)
            r = (spec.exit_age(t, tau, shape) - e) / scale
        return np.where(np.isfinite(r), r, 1e6)

    x0 = np.log(np.asarray(guess, dtype=float))
    try:
        sol = optimize.least_squares(residual, x0, method="lm", max_nfev=max_nfev, xtol=1e-12)
    except (ValueError, ConvergenceError) as exc:
        raise ConvergenceError(f"{model} fit failed: {exc}", where="least squares") from None
    where = f"least-squares fit of the {model} model"
    if sol.status <= 0 or not np.all(np.isfinite(sol.x)):
        raise ConvergenceError(
            f"{where} did not converge: {sol.message}",
            evaluations=int(sol.nfev),
            residual=float(np.sqrt(2 * sol.cost)) * scale,
        )
    tau, shape = np.exp(sol.x)
    if not (1e-3 < shape < 1e7):
        raise ConvergenceError(
            f"{where} ran away ({spec.shape} = {shape:.3g}): the data do not look like this model",
            evaluations=int(sol.nfev),
        )
    jac = sol.jac * scale
    dof = t.size - 2
    sse = float(2 * sol.cost) * scale**2
    jtj = jac.T @ jac
    if np.linalg.cond(jtj) > 1e14:
        raise ConvergenceError(
            f"{where}: parameters not identifiable (singular Jacobian)", evaluations=int(sol.nfev)
        )
    cov = sse / dof * np.linalg.inv(jtj)
    half = stats.t.ppf(0.5 + confidence / 2, dof) * np.sqrt(np.diag(cov))
    ci_tau = (float(tau * (1 - half[0])), float(tau * (1 + half[0])))  # delta method on log tau
    ci_shape = (float(shape * (1 - half[1])), float(shape * (1 + half[1])))
    fitted = spec.exit_age(t, tau, shape)
    return FitResult(
        model,
        float(tau),
        float(shape),
        ci_tau,
        ci_shape,
        t,
        e,
        fitted,
        sse,
        int(sol.nfev),
        confidence,
        data_mean,
        data_var,
        length,
        moments,
    )


def fit_tracer(tracer: TracerResult, **kwargs) -> FitResult:
    """:func:`fit_rtd` applied to a :class:`~rotarykiln.rtd.tracer.TracerResult`."""
    return fit_rtd(tracer.t, tracer.exit_age, **kwargs)
