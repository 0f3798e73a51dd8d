r"""Residence time distribution models: axial dispersion (three boundary conditions), the
small-dispersion Gaussian, tanks in series and plug flow.

Every model is a set of pure functions of time ``t`` [s], the space time ``tau`` = L/u [s] and
its shape parameter (the Peclet number ``peclet`` = uL/D, or the number of tanks), vectorised
over ``t``:

- ``<model>_exit_age(t, tau, p)``: the exit-age density E(t) [1/s];
- ``<model>_cdf(t, tau, p)``: the cumulative F(t) [-];
- ``<model>_moments(tau, p)``: the mean [s] and variance [s2] of E(t).

In normalised time :math:`\theta = t/\tau` the axial dispersion equation (seed 003, eq. 8) is

.. math::

    \frac{\partial C}{\partial\theta} = \frac{1}{Pe}\frac{\partial^2 C}{\partial z^2}
        - \frac{\partial C}{\partial z}, \qquad Pe = \frac{uL}{D}.

Its transfer functions (tracer injected at z = 0, measured at z = 1; :math:`q = \sqrt{1+4s/Pe}`):

.. math::

    G_{oo} = \frac{e^{Pe(1-q)/2}}{q},\quad
    G_{oc} = \frac{2e^{Pe(1-q)/2}}{1+q},\quad
    G_{cc} = \frac{4q\,e^{Pe(1-q)/2}}{(1+q)^2 - (1-q)^2 e^{-Pe q}}.

Moments (Levenspiel 1999), normalised by :math:`\tau`:

=================  ===============  ============================================
boundaries         mean             variance
=================  ===============  ============================================
open-open          1 + 2/Pe         2/Pe + 8/Pe^2
open-closed        1 + 1/Pe         2/Pe + 3/Pe^2
closed-closed      1                2/Pe - 2(1 - e^{-Pe})/Pe^2
Gaussian           1                2/Pe
tanks in series    1                1/N
plug flow          1                0
=================  ===============  ============================================

Note that only for closed-closed boundaries is the mean of E(t) equal to :math:`\tau`. Seed 003
writes :math:`\theta = t/\bar t` (eq. 10), i.e. it identifies :math:`\bar t` with :math:`\tau`;
the "mean residence time" it fits with eq. 14 is :math:`\tau` (see docs/rtd.md).

References
----------
Levenspiel, O. (1999). Chemical Reaction Engineering, 3rd ed., ch. 13-14. Wiley.
Bongo Njeng, A. S. et al. (2015). Powder Technol. 269, 554-565, eqs. 8-14.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy import special

from rotarykiln.errors import InputError, check_positive, check_range
from rotarykiln.rtd._laplace import talbot_inverse

__all__ = [
    "ASYMPTOTIC_PECLET",
    "MODELS",
    "SHAPE_RANGE",
    "ModelSpec",
    "closed_closed_cdf",
    "closed_closed_exit_age",
    "closed_closed_moments",
    "dispersion_coefficient",
    "gaussian_cdf",
    "gaussian_exit_age",
    "gaussian_moments",
    "get_model",
    "open_closed_cdf",
    "open_closed_exit_age",
    "open_closed_moments",
    "open_open_cdf",
    "open_open_exit_age",
    "open_open_moments",
    "peclet_number",
    "plug_flow_cdf",
    "plug_flow_exit_age",
    "plug_flow_moments",
    "tanks_in_series_cdf",
    "tanks_in_series_exit_age",
    "tanks_in_series_moments",
]

SERIES_MAX_PECLET = 20.0  # above this the closed-closed series cancels badly; use Laplace inversion
_SERIES_TERMS = 1000
_SERIES_CHUNK = 200_000  # most (time, term) pairs of the series evaluated at once (memory)

SHAPE_RANGE = (1e-6, 1e10)
"""Peclet numbers and numbers of tanks accepted by every model, [-]: from a fully mixed vessel
(the open-open mean is then 2e6 space times) to a plug flow with a spread of 1e-5 of the mean;
outside, the moments overflow or the densities are no longer representable."""

ASYMPTOTIC_PECLET = 1e5
"""Above this Peclet number the closed-closed and open-closed densities are the open-open one
with its 1/Pe and 1/Pe^2 corrections (:func:`_boundary_corrected`; relative error about
Pe^-3/2), instead of a Laplace inversion whose nodes grow as sqrt(Pe)."""


def _check_shape(name: str, value) -> None:
    check_range(name, value, *SHAPE_RANGE, closed_low=True, closed_high=True)


def _prepare(t, tau, shape, shape_name="peclet"):
    check_positive("tau", tau, "s")
    if shape_name:
        _check_shape(shape_name, shape)
    t = np.asarray(t, dtype=float)
    if not np.all(np.isfinite(t)):
        raise InputError("t", "a non-finite time", "finite")
    return t, float(tau), float(shape) if shape_name else None


# ----------------------------------------------------------------------------- open-open


def open_open_exit_age(t, tau, peclet):
    r"""Exit-age density of the axial dispersion model with open-open boundaries.

    .. math::

        E(t) = \frac{1}{2\tau}\sqrt{\frac{Pe}{\pi\theta}}
            \exp\left[-\frac{Pe(1-\theta)^2}{4\theta}\right], \qquad \theta = t/\tau

    (seed 003 eqs. 11 and 14, with :math:`\tau = L/u` in place of the paper's :math:`\bar t`).

    Parameters
    ----------
    t : array_like
        Time since injection [s]; E = 0 for t <= 0.
    tau : float
        Space time L/u [s].
    peclet : float
        Peclet number uL/D [-].

    Returns
    -------
    numpy.ndarray
        E(t) [1/s].

    Notes
    -----
    Valid for any Pe > 0; the mean of E(t) is :math:`\tau(1 + 2/Pe)`, not :math:`\tau`.

    Examples
    --------
    >>> round(float(open_open_exit_age(2400.0, 2400.0, 500.0)) * 60, 5)  # per minute
    0.1577

    References
    ----------
    Levenspiel (1999) eq. 14.19; Bongo Njeng et al. (2015) eq. 14.
    """
    t, tau, pe = _prepare(t, tau, peclet)
    theta = t / tau
    pos = theta > 0
    th = np.where(pos, theta, 1.0)
    with np.errstate(over="ignore"):  # exp(-inf) = 0 at theta -> 0
        log_e = 0.5 * np.log(pe / (4.0 * np.pi * th)) - pe * (1.0 - th) ** 2 / (4.0 * th)
        e = np.exp(log_e)
    return np.where(pos, e, 0.0) / tau


def open_open_cdf(t, tau, peclet):
    r"""Cumulative RTD F(t) of the open-open axial dispersion model.

    E(theta) is the length-biased inverse Gaussian with :math:`\mu = 1`, :math:`\lambda = Pe/2`:

    .. math::

        F = \Phi\left(\sqrt{\tfrac{Pe}{2\theta}}(\theta - 1)\right)
            - e^{Pe}\,\Phi\left(-\sqrt{\tfrac{Pe}{2\theta}}(\theta + 1)\right)

    (the second term evaluated with ``erfcx`` so that it never overflows).

    Parameters
    ----------
    t : array_like, s
        Time since injection.
    tau : float, s
        Space time L/u.
    peclet : float, -
        Peclet number uL/D, > 0.

    Returns
    -------
    numpy.ndarray, -
        F(t).

    Examples
    --------
    >>> round(float(open_open_cdf(1.0, 1.0, 100.0)), 4)
    0.4719

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. Bongo Njeng, A. S. et
    al. (2015) Powder Technol. 269, 554-565, eqs. 11-14.
    """
    t, tau, pe = _prepare(t, tau, peclet)
    theta = t / tau
    pos = theta > 0
    th = np.where(pos, theta, 1.0)
    a = np.sqrt(pe / (2.0 * th))
    first = 0.5 * special.erfc(-a * (th - 1.0) / np.sqrt(2.0))
    second = 0.5 * special.erfcx(a * (th + 1.0) / np.sqrt(2.0))
    second *= np.exp(-pe * (th - 1.0) ** 2 / (4.0 * th))
    return np.where(pos, first - second, 0.0)


def open_open_moments(tau, peclet):
    r"""Mean [s] and variance [s2] of the open-open model: :math:`\tau(1+2/Pe)`,
    :math:`\tau^2(2/Pe + 8/Pe^2)` (seed 003 eqs. 12-13).

    Parameters
    ----------
    tau : float, s
        Space time L/u.
    peclet : float, -
        Peclet number uL/D, > 0.

    Returns
    -------
    (float, float), (s, s2)
        Mean and variance of E(t).

    Examples
    --------
    >>> [round(v, 6) for v in open_open_moments(1.0, 100.0)]
    [1.02, 0.0208]

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. Bongo Njeng, A. S. et
    al. (2015) Powder Technol. 269, 554-565, eqs. 11-14.
    """
    check_positive("tau", tau, "s")
    _check_shape("peclet", peclet)
    return tau * (1.0 + 2.0 / peclet), tau**2 * (2.0 / peclet + 8.0 / peclet**2)


# ----------------------------------------------------------------------------- Laplace forms


def _q(s, pe):
    return np.sqrt(1.0 + 4.0 * s / pe)


def _log_g_open_closed(pe):
    def log_g(s):
        q = _q(s, pe)
        return np.log(2.0) + pe * (1.0 - q) / 2.0 - np.log(1.0 + q)

    return log_g


def _log_g_closed_closed(pe):
    def log_g(s):
        q = _q(s, pe)
        den = (1.0 + q) ** 2 - (1.0 - q) ** 2 * np.exp(-pe * q)
        return np.log(4.0 * q) + pe * (1.0 - q) / 2.0 - np.log(den)

    return log_g


def _log_g_open_open(pe):
    def log_g(s):
        q = _q(s, pe)
        return pe * (1.0 - q) / 2.0 - np.log(q)

    return log_g


def _invert(log_g, theta, pe, cumulative=False):
    """E(theta) (or F(theta)) by Talbot inversion on a contour around the branch point -Pe/4.

    F is the open-open F (closed form) plus the inverse of (G - G_oo)/s, which has no pole at
    s = 0, so the contour can pass through the saddle point without meeting a pole.
    """
    out = np.zeros_like(theta)
    pos = theta > 0
    if not np.any(pos):
        return out
    if not cumulative:
        out[pos] = talbot_inverse(log_g, theta[pos], shift=-pe / 4.0, sharpness=pe / 4.0)
        return out
    log_oo = _log_g_open_open(pe)

    def log_diff(s):
        ref = log_oo(s)
        return ref + np.log(np.expm1(log_g(s) - ref)) - np.log(s)

    diff = talbot_inverse(log_diff, theta[pos], shift=-pe / 4.0, sharpness=pe / 4.0)
    out[pos] = open_open_cdf(theta[pos], 1.0, pe) + diff
    return out


def _boundary_corrected(theta, pe, a, b, cumulative=False):
    r"""E(theta) (or F) of a dispersion model at a high Peclet number from the open-open form.

    For :math:`Pe \gg 1` the transfer function is :math:`G_{oo}(s)(1 + a u + b u^2 + O(u^3))`
    with :math:`u = s/Pe` (the :math:`e^{-Pe q}` term of :math:`G_{cc}` is negligible):
    closed-closed :math:`4q^2/(1+q)^2 = 1 + 2u - 3u^2`, open-closed :math:`2q/(1+q) = 1 + u -
    2u^2`. As :math:`E_{oo}` and :math:`E_{oo}'` vanish at 0, :math:`E = E_{oo} +
    (a/Pe)E_{oo}' + (b/Pe^2)E_{oo}''` and :math:`F = F_{oo} + (a/Pe)E_{oo} + (b/Pe^2)E_{oo}'`;
    the relevant :math:`s \sim \sqrt{Pe}`, so the error is of order :math:`Pe^{-3/2}`. The
    means and variances are those of the exact models to :math:`O(Pe^{-2})`.
    """
    out = np.zeros_like(theta)
    pos = theta > 0
    th = theta[pos]
    e = open_open_exit_age(th, 1.0, pe)
    # g = d ln E_oo / d theta = -1/(2 theta) + Pe (1/theta^2 - 1)/4, kept as h = g/Pe
    h = -0.5 / (th * pe) + 0.25 * (1.0 / th**2 - 1.0)
    with np.errstate(over="ignore", invalid="ignore"):
        if cumulative:
            corr = e * (a + b * h) / pe
            val = open_open_cdf(th, 1.0, pe) + corr
        else:
            dg = 0.5 / (th**2 * pe**2) - 0.5 / (th**3 * pe)  # g' / Pe^2
            val = e * (1.0 + a * h + b * (h * h + dg))
    out[pos] = np.where(e > 0, val, open_open_cdf(th, 1.0, pe) if cumulative else 0.0)
    return out


# ----------------------------------------------------------------------------- closed-closed


def _closed_closed_eigenvalues(pe, n):
    """Roots mu_k in ((k-1) pi, k pi) of Pe mu cos mu + (Pe^2/4 - mu^2) sin mu = 0."""
    k = np.arange(1, n + 1)
    lo = (k - 1) * np.pi + 1e-12
    hi = k * np.pi

    def h(mu):
        return pe * mu * np.cos(mu) + (pe**2 / 4.0 - mu**2) * np.sin(mu)

    h_lo = h(lo)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        h_mid = h(mid)
        same = np.sign(h_mid) == np.sign(h_lo)
        lo = np.where(same, mid, lo)
        h_lo = np.where(same, h_mid, h_lo)
        hi = np.where(same, hi, mid)
    return 0.5 * (lo + hi)


def closed_closed_series(theta, peclet, n_terms=_SERIES_TERMS):
    r"""Eigenfunction series of the closed-closed E(theta) (dimensionless, Danckwerts boundaries).

    With :math:`C = e^{Pe z/2 - Pe\theta/4} v` the problem becomes :math:`v_\theta = v_{zz}/Pe`
    with Robin conditions, and

    .. math::

        E(\theta) = e^{Pe/2 - Pe\theta/4}\sum_k \frac{X_k(1)}{\|X_k\|^2}e^{-\mu_k^2\theta/Pe},
        \quad X_k = \cos\mu_k z + \frac{Pe}{2\mu_k}\sin\mu_k z,

        \tan\mu_k = \frac{Pe\,\mu_k}{\mu_k^2 - Pe^2/4}.

    Accurate to about 1e-12 for Pe <= 20 and theta with :math:`\mu_{N}^2\theta/Pe > 40`; use
    :func:`closed_closed_exit_age` (which switches to Laplace inversion) otherwise.

    Parameters
    ----------
    theta : array_like
        Normalised time t/tau [-].
    peclet : float
        Peclet number [-].
    n_terms : int
        Number of eigenvalues.

    Returns
    -------
    numpy.ndarray
        E(theta) [-].

    Examples
    --------
    >>> round(float(closed_closed_series(1.0, 5.0)), 5)
    0.69956
    """
    theta = np.asarray(theta, dtype=float)
    pe = float(peclet)
    th = theta.reshape(-1, 1)
    # terms needed: exp(-mu_k^2 theta_min / Pe) < e^-40, mu_k ~ k pi
    theta_min = max(float(th.min(initial=1.0)), 1e-300)
    needed = int(np.ceil(np.sqrt(40.0 * pe / theta_min) / np.pi)) + 2
    mu, coef = _closed_closed_terms(pe, n_terms)
    mu, coef = mu[:needed], coef[:needed]
    step = max(1, _SERIES_CHUNK // mu.size)  # times per block: bounded memory
    e = np.concatenate(
        [
            (np.exp(pe / 2.0 - pe * b / 4.0 - mu**2 * b / pe) * coef).sum(axis=1)
            for b in (th[i : i + step] for i in range(0, th.shape[0], step))
        ]
        or [np.zeros(0)]
    )
    return e.reshape(theta.shape)


@lru_cache(maxsize=32)
def _closed_closed_terms(pe: float, n: int):
    """Eigenvalues and coefficients X_k(1)/||X_k||^2 of the closed-closed series (cached)."""
    mu = _closed_closed_eigenvalues(pe, n)
    b = pe / (2.0 * mu)
    norm = 0.5 + np.sin(2 * mu) / (4 * mu) + b**2 * (0.5 - np.sin(2 * mu) / (4 * mu))
    norm += b * np.sin(mu) ** 2 / mu
    x1 = np.cos(mu) + b * np.sin(mu)
    return mu, x1 / norm


def closed_closed_exit_age(t, tau, peclet, method="auto"):
    r"""Exit-age density of the axial dispersion model with closed-closed (Danckwerts) boundaries.

    Series solution (:func:`closed_closed_series`) for Pe <= 20, numerical inversion of

    .. math::

        G_{cc}(s) = \frac{4q\,e^{Pe(1-q)/2}}{(1+q)^2 - (1-q)^2 e^{-Pe q}},
        \quad q = \sqrt{1 + 4s/Pe}

    (fixed Talbot) above, and for very early times where the series would need too many terms.

    Parameters
    ----------
    t : array_like
        Time [s].
    tau : float
        Space time L/u = mean residence time [s].
    peclet : float
        Peclet number [-].
    method : {"auto", "series", "laplace"}
        Evaluation method.

    Returns
    -------
    numpy.ndarray
        E(t) [1/s].

    Examples
    --------
    >>> e = closed_closed_exit_age([30.0, 60.0], 60.0, 5.0)
    >>> np.round(e * 60.0, 5).tolist()
    [0.89996, 0.69956]
    >>> round(float(closed_closed_exit_age(60.0, 60.0, 5.0, method="laplace")) * 60, 5)
    0.69956

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. Bongo Njeng, A. S. et
    al. (2015) Powder Technol. 269, 554-565, eq. 8.
    """
    t, tau, pe = _prepare(t, tau, peclet)
    if method not in ("auto", "series", "laplace"):
        raise InputError("method", method, "one of auto, series, laplace")
    theta = t / tau
    use_series = method == "series" or (method == "auto" and pe <= SERIES_MAX_PECLET)
    if method == "auto" and pe > ASYMPTOTIC_PECLET:
        return _boundary_corrected(theta, pe, 2.0, -3.0) / tau
    if not use_series:
        return _invert(_log_g_closed_closed(pe), theta, pe) / tau
    theta_min = 40.0 * pe / (_SERIES_TERMS * np.pi) ** 2
    out = np.zeros_like(theta)
    ok = theta >= theta_min
    out[ok] = closed_closed_series(theta[ok], pe)
    early = (theta > 0) & ~ok
    if np.any(early):
        out[early] = _invert(_log_g_closed_closed(pe), theta[early], pe)
    return out / tau


def closed_closed_cdf(t, tau, peclet):
    """Cumulative F(t) [-] of the closed-closed model (Laplace inversion of G_cc(s)/s).

    Parameters
    ----------
    t : array_like, s
        Time since injection.
    tau : float, s
        Space time L/u.
    peclet : float, -
        Peclet number uL/D, > 0.

    Returns
    -------
    numpy.ndarray, -
        F(t).

    Examples
    --------
    >>> round(float(closed_closed_cdf(1.0, 1.0, 1000.0)), 4)
    0.5089

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. Bongo Njeng, A. S. et
    al. (2015) Powder Technol. 269, 554-565, eq. 8.
    """
    t, tau, pe = _prepare(t, tau, peclet)
    if pe > ASYMPTOTIC_PECLET:
        return np.clip(_boundary_corrected(t / tau, pe, 2.0, -3.0, cumulative=True), 0.0, 1.0)
    return np.clip(_invert(_log_g_closed_closed(pe), t / tau, pe, cumulative=True), 0.0, 1.0)


def closed_closed_moments(tau, peclet):
    r"""Mean [s] and variance [s2] of the closed-closed model: :math:`\tau`,
    :math:`\tau^2[2/Pe - 2(1 - e^{-Pe})/Pe^2]`.

    Parameters
    ----------
    tau : float, s
        Space time L/u.
    peclet : float, -
        Peclet number uL/D, > 0.

    Returns
    -------
    (float, float), (s, s2)
        Mean and variance of E(t).

    Examples
    --------
    >>> [round(v, 6) for v in closed_closed_moments(1.0, 10.0)]
    [1.0, 0.180001]

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. Bongo Njeng, A. S. et
    al. (2015) Powder Technol. 269, 554-565, eq. 8.
    """
    check_positive("tau", tau, "s")
    _check_shape("peclet", peclet)
    var = 2.0 / peclet - 2.0 * (1.0 - np.exp(-peclet)) / peclet**2
    return tau, tau**2 * float(var)


# ----------------------------------------------------------------------------- open-closed


def open_closed_exit_age(t, tau, peclet):
    r"""Exit-age density of the axial dispersion model, open inlet and closed outlet.

    Laplace inversion (fixed Talbot) of :math:`G_{oc} = 2e^{Pe(1-q)/2}/(1+q)`; by symmetry of
    the moments the closed-open model has the same mean and variance.

    Parameters
    ----------
    t : array_like
        Time [s].
    tau : float
        Space time L/u [s].
    peclet : float
        Peclet number [-].

    Returns
    -------
    numpy.ndarray
        E(t) [1/s].

    Examples
    --------
    >>> round(float(open_closed_exit_age(1.0, 1.0, 100.0)), 4)
    2.8348

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    t, tau, pe = _prepare(t, tau, peclet)
    if pe > ASYMPTOTIC_PECLET:
        return _boundary_corrected(t / tau, pe, 1.0, -2.0) / tau
    return _invert(_log_g_open_closed(pe), t / tau, pe) / tau


def open_closed_cdf(t, tau, peclet):
    """Cumulative F(t) [-] of the open-closed model (Laplace inversion).

    Parameters
    ----------
    t : array_like, s
        Time since injection.
    tau : float, s
        Space time L/u.
    peclet : float, -
        Peclet number uL/D, > 0.

    Returns
    -------
    numpy.ndarray, -
        F(t).

    Examples
    --------
    >>> round(float(open_closed_cdf(1.0, 1.0, 100.0)), 4)
    0.4997

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    t, tau, pe = _prepare(t, tau, peclet)
    if pe > ASYMPTOTIC_PECLET:
        return np.clip(_boundary_corrected(t / tau, pe, 1.0, -2.0, cumulative=True), 0.0, 1.0)
    return np.clip(_invert(_log_g_open_closed(pe), t / tau, pe, cumulative=True), 0.0, 1.0)


def open_closed_moments(tau, peclet):
    r"""Mean [s] and variance [s2] of the open-closed model: :math:`\tau(1+1/Pe)`,
    :math:`\tau^2(2/Pe + 3/Pe^2)`.

    Parameters
    ----------
    tau : float, s
        Space time L/u.
    peclet : float, -
        Peclet number uL/D, > 0.

    Returns
    -------
    (float, float), (s, s2)
        Mean and variance of E(t).

    Examples
    --------
    >>> [round(v, 6) for v in open_closed_moments(1.0, 100.0)]
    [1.01, 0.0203]

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    check_positive("tau", tau, "s")
    _check_shape("peclet", peclet)
    return tau * (1.0 + 1.0 / peclet), tau**2 * (2.0 / peclet + 3.0 / peclet**2)


# ----------------------------------------------------------------------------- Gaussian


def gaussian_exit_age(t, tau, peclet):
    r"""Small-dispersion (Gaussian) approximation of the axial dispersion model.

    .. math::

        E(t) = \frac{1}{\tau}\sqrt{\frac{Pe}{4\pi}}\exp\left[-\frac{Pe(1-\theta)^2}{4}\right]

    Parameters
    ----------
    t : array_like
        Time [s].
    tau : float
        Mean residence time [s].
    peclet : float
        Peclet number [-]; the approximation is meant for Pe >= 100 (Levenspiel 1999).

    Returns
    -------
    numpy.ndarray
        E(t) [1/s]. The density extends to t < 0; the mass there is
        erfc(sqrt(Pe)/2)/2 (3e-13 at Pe = 100).

    Examples
    --------
    >>> round(float(gaussian_exit_age(1.0, 1.0, 100.0)), 4)
    2.8209

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. Bongo Njeng, A. S. et
    al. (2015) Powder Technol. 269, 554-565, eq. 10.
    """
    t, tau, pe = _prepare(t, tau, peclet)
    theta = t / tau
    return np.sqrt(pe / (4.0 * np.pi)) * np.exp(-pe * (1.0 - theta) ** 2 / 4.0) / tau


def gaussian_cdf(t, tau, peclet):
    """Cumulative F(t) [-] of the Gaussian model.

    Parameters
    ----------
    t : array_like, s
        Time since injection.
    tau : float, s
        Space time L/u.
    peclet : float, -
        Peclet number uL/D, > 0.

    Returns
    -------
    numpy.ndarray, -
        F(t).

    Examples
    --------
    >>> round(float(gaussian_cdf(1.0, 1.0, 100.0)), 4)
    0.5

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. Bongo Njeng, A. S. et
    al. (2015) Powder Technol. 269, 554-565, eq. 10.
    """
    t, tau, pe = _prepare(t, tau, peclet)
    return 0.5 * special.erfc(-(t / tau - 1.0) * np.sqrt(pe) / 2.0)


def gaussian_moments(tau, peclet):
    """Mean [s] and variance [s2] of the Gaussian model: tau and 2 tau^2/Pe.

    Parameters
    ----------
    tau : float, s
        Space time L/u.
    peclet : float, -
        Peclet number uL/D, > 0.

    Returns
    -------
    (float, float), (s, s2)
        Mean and variance of E(t).

    Examples
    --------
    >>> [round(v, 6) for v in gaussian_moments(1.0, 100.0)]
    [1.0, 0.02]

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. Bongo Njeng, A. S. et
    al. (2015) Powder Technol. 269, 554-565, eq. 10.
    """
    check_positive("tau", tau, "s")
    _check_shape("peclet", peclet)
    return tau, 2.0 * tau**2 / peclet


# ----------------------------------------------------------------------------- tanks in series


def tanks_in_series_exit_age(t, tau, n_tanks):
    r"""Exit-age density of N equal stirred tanks in series (N may be non-integer: gamma density).

    .. math::

        E(t) = \frac{1}{\tau}\frac{N^N\theta^{N-1}e^{-N\theta}}{\Gamma(N)}

    Parameters
    ----------
    t : array_like
        Time [s].
    tau : float
        Mean residence time of the whole chain [s].
    n_tanks : float
        Number of tanks N > 0 [-].

    Returns
    -------
    numpy.ndarray
        E(t) [1/s].

    Examples
    --------
    >>> round(float(tanks_in_series_exit_age(1.0, 1.0, 1.0)), 6)  # one tank: exp(-1)
    0.367879

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. ch. 14
    (tanks-in-series model).
    """
    t, tau, n = _prepare(t, tau, n_tanks, "n_tanks")
    theta = t / tau
    pos = theta > 0
    th = np.where(pos, theta, 1.0)
    log_e = n * np.log(n) + (n - 1.0) * np.log(th) - n * th - special.gammaln(n)
    return np.where(pos, np.exp(log_e), 0.0) / tau


def tanks_in_series_cdf(t, tau, n_tanks):
    """Cumulative F(t) [-] of the tanks-in-series model (regularised incomplete gamma).

    Parameters
    ----------
    t : array_like, s
        Time since injection.
    tau : float, s
        Space time L/u.
    n_tanks : float, -
        Number of tanks N > 0.

    Returns
    -------
    numpy.ndarray, -
        F(t).

    Examples
    --------
    >>> round(float(tanks_in_series_cdf(1.0, 1.0, 1.0)), 6)
    0.632121

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. ch. 14
    (tanks-in-series model).
    """
    t, tau, n = _prepare(t, tau, n_tanks, "n_tanks")
    return special.gammainc(n, n * np.clip(t / tau, 0.0, None))


def tanks_in_series_moments(tau, n_tanks):
    """Mean [s] and variance [s2] of N tanks in series: tau and tau^2/N.

    Parameters
    ----------
    tau : float, s
        Space time L/u.
    n_tanks : float, -
        Number of tanks N > 0.

    Returns
    -------
    (float, float), (s, s2)
        Mean and variance of E(t).

    Examples
    --------
    >>> tanks_in_series_moments(2.0, 4.0)
    (2.0, 1.0)

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14. ch. 14
    (tanks-in-series model).
    """
    check_positive("tau", tau, "s")
    _check_shape("n_tanks", n_tanks)
    return tau, tau**2 / n_tanks


# ----------------------------------------------------------------------------- plug flow


def plug_flow_exit_age(t, tau, shape=None):
    """Plug flow: E(t) is a Dirac delta at t = tau; returned as 0 everywhere (its whole mass is
    the unit step of :func:`plug_flow_cdf`).

    Parameters
    ----------
    t : array_like, s
        Time since injection.
    tau : float, s
        Space time L/u.
    shape : None
        Unused (the common model interface).

    Returns
    -------
    numpy.ndarray, 1/s
        Zeros (the Dirac mass is not representable).

    Examples
    --------
    >>> plug_flow_exit_age([1.0, 2.0], 2.0).tolist()
    [0.0, 0.0]

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    t, tau, _ = _prepare(t, tau, None, "")
    return np.zeros_like(t)


def plug_flow_cdf(t, tau, shape=None):
    """Plug flow: F(t) = 0 for t < tau, 1 for t >= tau.

    Parameters
    ----------
    t : array_like, s
        Time since injection.
    tau : float, s
        Space time L/u.
    shape : None
        Unused (the common model interface).

    Returns
    -------
    numpy.ndarray, -
        F(t).

    Examples
    --------
    >>> plug_flow_cdf([1.0, 2.0, 3.0], 2.0).tolist()
    [0.0, 1.0, 1.0]

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    t, tau, _ = _prepare(t, tau, None, "")
    return np.where(t >= tau, 1.0, 0.0)


def plug_flow_moments(tau, shape=None):
    """Mean tau [s] and variance 0 of plug flow.

    Parameters
    ----------
    tau : float, s
        Space time L/u.
    shape : None
        Unused (the common model interface).

    Returns
    -------
    (float, float), (s, s2)
        Mean and variance of E(t).

    Examples
    --------
    >>> plug_flow_moments(3.0)
    (3.0, 0.0)

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14.
    """
    check_positive("tau", tau, "s")
    return float(tau), 0.0


# ----------------------------------------------------------------------------- helpers


def dispersion_coefficient(peclet, length, tau):
    r"""Axial dispersion coefficient from the Peclet number: :math:`D = uL/Pe = L^2/(Pe\,\tau)`
    (seed 003 eq. 9 with u = L/tau).

    Parameters
    ----------
    peclet : array_like
        Peclet number [-].
    length : float
        Kiln length [m].
    tau : array_like
        Space time L/u [s] (seed 003 uses the fitted or measured mean residence time).

    Returns
    -------
    numpy.ndarray or float
        D [m2/s].

    Examples
    --------
    >>> f"{dispersion_coefficient(549.0, 1.95, 43.39 * 60):.3g}"
    '2.66e-06'

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565, eq. 9.
    """
    check_positive("peclet", peclet)
    check_positive("length", length, "m")
    check_positive("tau", tau, "s")
    return length**2 / (np.asarray(peclet, dtype=float) * np.asarray(tau, dtype=float))[()]


def peclet_number(velocity, length, dispersion):
    """Peclet number uL/D [-] from the axial velocity [m/s], length [m] and D [m2/s].

    Parameters
    ----------
    velocity : float or array, m/s
        Mean axial solids velocity, > 0.
    length : float or array, m
        Kiln length, > 0.
    dispersion : float or array, m2/s
        Axial dispersion coefficient, > 0.

    Returns
    -------
    float or array, -
        Pe = uL/D.

    Examples
    --------
    >>> round(peclet_number(7.49e-4, 1.95, 2.66e-6), 1)
    549.1

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565, eq. 9.
    """
    check_positive("velocity", velocity, "m/s")
    check_positive("length", length, "m")
    check_positive("dispersion", dispersion, "m2/s")
    return velocity * length / dispersion


@dataclass(frozen=True)
class ModelSpec:
    """One RTD model: its functions and the name of its shape parameter (None for plug flow)."""

    name: str
    exit_age: object
    cdf: object
    moments: object
    shape: str | None
    description: str


MODELS: dict[str, ModelSpec] = {
    m.name: m
    for m in [
        ModelSpec(
            "open-open",
            open_open_exit_age,
            open_open_cdf,
            open_open_moments,
            "peclet",
            "axial dispersion, open-open boundaries (seed 003 eq. 14)",
        ),
        ModelSpec(
            "closed-closed",
            closed_closed_exit_age,
            closed_closed_cdf,
            closed_closed_moments,
            "peclet",
            "axial dispersion, closed-closed (Danckwerts) boundaries",
        ),
        ModelSpec(
            "open-closed",
            open_closed_exit_age,
            open_closed_cdf,
            open_closed_moments,
            "peclet",
            "axial dispersion, open inlet, closed outlet",
        ),
        ModelSpec(
            "gaussian",
            gaussian_exit_age,
            gaussian_cdf,
            gaussian_moments,
            "peclet",
            "small-dispersion Gaussian approximation (Pe >= 100)",
        ),
        ModelSpec(
            "tanks-in-series",
            tanks_in_series_exit_age,
            tanks_in_series_cdf,
            tanks_in_series_moments,
            "n_tanks",
            "N equal stirred tanks in series (gamma density)",
        ),
        ModelSpec(
            "plug-flow", plug_flow_exit_age, plug_flow_cdf, plug_flow_moments, None, "plug flow"
        ),
    ]
}


def get_model(name: str) -> ModelSpec:
    """The :class:`ModelSpec` called ``name`` (raises InputError listing the known names)."""
    try:
        return MODELS[name]
    except KeyError:
        raise InputError("model", name, "one of " + ", ".join(MODELS)) from None
