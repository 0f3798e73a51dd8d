r"""Transverse mixing of two granular materials in the rolling regime (Van Puyvelde 1999, ch. 6).

Mixing is measured by the *contact distance* l, the length of boundary between the two materials
in the cross-section. It rises linearly at the *mixing rate* α to the *final contact distance*
:math:`l_f` (eq 6.1), and both are correlated with active-layer quantities:

.. math::

    \psi = V_{AL}\,A_{AL}^{1/2}\,(d_{p,M} - d_p)\,(\varepsilon_M - \varepsilon), \qquad
    \alpha = k_\alpha \psi \quad (6.8, 6.9)

    \Omega = A_{BED}\,(d_{p,MAX} - d_p)\,(\varepsilon_{MAX} - \varepsilon), \qquad
    l_f = k_l\,\Omega \quad (6.10, 6.11)

with :math:`k_\alpha = 1.503\times10^{-3}` mm⁻² (1503 m⁻² in SI) and :math:`k_l = 5.280\times
10^{-2}` mm⁻² (5.28e4 m⁻²). The material ratio ε is taken >= 1 (a ratio r < 1 is inverted).

The four limiting constants are not printed in the thesis (they were in lost figures); the
defaults are the least-squares back-fit of the notes on seed 000 to Tables 6.2/6.3 (ψ reproduced
to 0.6 % mean, Ω to 0.8 % mean): :data:`D_LIMIT_RATE` = 6.62 mm, :data:`RATIO_LIMIT_RATE` = 4.43,
:data:`D_LIMIT_FINAL` = 7.17 mm, :data:`RATIO_LIMIT_FINAL` = 3.78. A size or ratio beyond its
limit would make the rate negative: the term is clamped at zero and an
:class:`~rotarykiln.errors.OutOfRangeWarning` is issued.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.errors import InputError, OutOfRangeWarning, check_nonnegative, check_positive
from rotarykiln.tables import with_units

__all__ = [
    "D_LIMIT_FINAL",
    "D_LIMIT_RATE",
    "K_FINAL",
    "K_RATE",
    "RATIO_LIMIT_FINAL",
    "RATIO_LIMIT_RATE",
    "MixingResult",
    "contact_distance",
    "material_ratio",
    "mixing_time",
    "vanpuyvelde_active_layer_parameter",
    "vanpuyvelde_final_contact",
    "vanpuyvelde_final_contact_parameter",
    "vanpuyvelde_mixing",
    "vanpuyvelde_mixing_rate",
]

#: Eq 6.9 constant, 1.503e-3 mm^-2 expressed in m^-2.
K_RATE = 1.503e-3 * 1e6
#: Eq 6.11 constant, 5.280e-2 mm^-2 expressed in m^-2.
K_FINAL = 5.280e-2 * 1e6
#: Limiting size of the mixing rate (back-fitted to Table 6.2), m.
D_LIMIT_RATE = 6.62e-3
#: Limiting material ratio of the mixing rate (back-fitted to Table 6.2), -.
RATIO_LIMIT_RATE = 4.43
#: Limiting size of the final contact (back-fitted to Table 6.3), m.
D_LIMIT_FINAL = 7.17e-3
#: Limiting material ratio of the final contact (back-fitted to Table 6.3), -.
RATIO_LIMIT_FINAL = 3.78


def material_ratio(ratio):
    r"""Material ratio as the thesis uses it, :math:`\varepsilon = \max(r, 1/r) \ge 1`.

    Parameters
    ----------
    ratio : float or array, -
        Amount of one material over the other (volume or mass basis), > 0.

    Returns
    -------
    float or array, -
        The ratio folded onto [1, inf).

    Examples
    --------
    >>> float(material_ratio(0.5))
    2.0

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    r = np.asarray(ratio, dtype=float)
    if np.any(~np.isfinite(r) | (r <= 0)):
        bad = r[~np.isfinite(r) | (r <= 0)] if r.ndim else r
        raise InputError(
            "material_ratio", float(np.ravel(bad)[0]), "> 0 (amount of one material over the other)"
        )
    return np.maximum(r, 1.0 / r)


def _clamped(what: str, limit, value, warn: bool):
    diff = np.asarray(limit, dtype=float) - np.asarray(value, dtype=float)
    if np.any(diff < 0) and warn:
        warnings.warn(
            f"{what} = {np.max(value):.4g} is beyond its limiting value {limit:.4g}: the "
            "correlation would give a negative result, clamped to zero (no mixing)",
            OutOfRangeWarning,
            stacklevel=3,
        )
    return np.maximum(diff, 0.0)


def vanpuyvelde_active_layer_parameter(
    v_al,
    a_al,
    d_p,
    ratio,
    *,
    d_limit: float = D_LIMIT_RATE,
    ratio_limit: float = RATIO_LIMIT_RATE,
    warn: bool = True,
):
    r"""Active-layer parameter ψ of the mixing-rate model, Van Puyvelde eq 6.8.

    .. math:: \psi = V_{AL}\,A_{AL}^{0.5}\,(d_{p,M} - d_p)\,(\varepsilon_M - \varepsilon)

    Parameters
    ----------
    v_al : float or array, m/s
        Mean active-layer velocity (eq 5.6, "tables" convention).
    a_al : float or array, m2
        Active-layer cross-section area.
    d_p : float or array, m
        Mean particle size.
    ratio : float or array, -
        Material ratio (inverted if < 1).
    d_limit : float, m
        Limiting size d_p,M beyond which the rate is zero (default back-fitted 6.62 mm).
    ratio_limit : float, -
        Limiting ratio ε_M (default back-fitted 4.43).
    warn : bool
        Warn when a term is clamped at zero.

    Returns
    -------
    float or array, m3/s

    Examples
    --------
    Experiment 3 of the thesis (Table 6.2 prints 1 397 108 mm3/s):

    >>> psi = vanpuyvelde_active_layer_parameter(0.792, 0.25 * 0.25 * np.pi * 0.285**2,
    ...                                          2.51e-3, 1.06)
    >>> round(float(psi) * 1e9, -3)
    1385000.0

    References
    ----------
    Van Puyvelde (1999), eq 6.8, Table 6.2.
    """
    check_nonnegative("v_al", v_al, "m/s")
    check_nonnegative("a_al", a_al, "m2")
    check_positive("d_p", d_p, "m")
    eps = material_ratio(ratio)
    dd = _clamped("particle size d_p [m]", d_limit, d_p, warn)
    de = _clamped("material ratio", ratio_limit, eps, warn)
    return np.asarray(v_al, dtype=float) * np.sqrt(np.asarray(a_al, dtype=float)) * dd * de


def vanpuyvelde_mixing_rate(v_al, a_al, d_p, ratio, *, k: float = K_RATE, **limits):
    r"""Mixing rate (growth rate of the contact distance), Van Puyvelde eq 6.9.

    .. math:: \alpha = k_\alpha\,\psi, \qquad k_\alpha = 1.503\times10^{-3}\ \mathrm{mm^{-2}}

    Parameters
    ----------
    v_al, a_al, d_p, ratio
        As in :func:`vanpuyvelde_active_layer_parameter` (m/s, m2, m, -).
    k : float, 1/m2
        Constant of eq 6.9 (1503 m^-2).
    **limits
        ``d_limit``, ``ratio_limit``, ``warn`` passed on.

    Returns
    -------
    float or array, m/s
        Rate of increase of the contact distance.

    Notes
    -----
    Fitted for N 5-19 rpm, L 6-40 %, d_p 0.89-5.08 mm, ε 1.0-2.7, 570 mm drum (average deviation
    14 %, max 49 %); validated on 200 and 400 mm drums (3 %).

    Examples
    --------
    >>> a = vanpuyvelde_mixing_rate(0.792, 0.25 * 0.25 * np.pi * 0.285**2, 2.51e-3, 1.06)
    >>> round(float(a), 2)
    2.08

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eq 6.9.
    """
    return k * vanpuyvelde_active_layer_parameter(v_al, a_al, d_p, ratio, **limits)


def vanpuyvelde_final_contact_parameter(
    a_bed,
    d_p,
    ratio,
    *,
    d_limit: float = D_LIMIT_FINAL,
    ratio_limit: float = RATIO_LIMIT_FINAL,
    warn: bool = True,
):
    r"""Final-contact parameter Ω, Van Puyvelde eq 6.10.

    .. math:: \Omega = A_{BED}\,(d_{p,MAX} - d_p)\,(\varepsilon_{MAX} - \varepsilon)

    Parameters
    ----------
    a_bed : float or array, m2
        Bed cross-section area.
    d_p : float or array, m
        Mean particle size.
    ratio : float or array, -
        Material ratio (inverted if < 1).
    d_limit : float, m
        Limiting size (default back-fitted 7.17 mm).
    ratio_limit : float, -
        Limiting ratio (default back-fitted 3.78).
    warn : bool
        Warn when a term is clamped at zero.

    Returns
    -------
    float or array, m3

    Examples
    --------
    >>> om = vanpuyvelde_final_contact_parameter(0.25 * np.pi * 0.285**2, 2.51e-3, 1.06)
    >>> round(float(om) * 1e9, -3)  # Table 6.3: 815 327 mm3
    809000.0

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eq 6.10.
    """
    check_nonnegative("a_bed", a_bed, "m2")
    check_positive("d_p", d_p, "m")
    eps = material_ratio(ratio)
    dd = _clamped("particle size d_p [m]", d_limit, d_p, warn)
    de = _clamped("material ratio", ratio_limit, eps, warn)
    return np.asarray(a_bed, dtype=float) * dd * de


def vanpuyvelde_final_contact(a_bed, d_p, ratio, *, k: float = K_FINAL, **limits):
    r"""Final (steady) contact distance, Van Puyvelde eq 6.11.

    .. math:: l_f = k_l\,\Omega, \qquad k_l = 5.280\times10^{-2}\ \mathrm{mm^{-2}}

    Parameters
    ----------
    a_bed, d_p, ratio
        As in :func:`vanpuyvelde_final_contact_parameter` (m2, m, -).
    k : float, 1/m2
        Constant of eq 6.11 (5.28e4 m^-2).
    **limits
        ``d_limit``, ``ratio_limit``, ``warn`` passed on.

    Returns
    -------
    float or array, m
        Final contact distance (independent of drum speed).

    Notes
    -----
    Average deviation 10 % (max 33 %) on the fitting set; over-predicts 16-34 % on exps 25-27.

    Examples
    --------
    >>> round(float(vanpuyvelde_final_contact(0.25 * np.pi * 0.285**2, 2.51e-3, 1.06)), 1)
    42.7

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eq 6.11.
    """
    return k * vanpuyvelde_final_contact_parameter(a_bed, d_p, ratio, **limits)


def mixing_time(final_contact, rate, initial_contact=0.0):
    r"""Time to reach the final contact at a constant rate, :math:`t_m = (l_f - l_0)/\alpha`.

    Parameters
    ----------
    final_contact : float or array, m
    rate : float or array, m/s
        Must be > 0.
    initial_contact : float or array, m

    Returns
    -------
    float or array, s

    Examples
    --------
    >>> round(float(mixing_time(41.2, 1.656)), 1)
    24.9

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    check_positive("rate", rate, "m/s")
    check_nonnegative("final_contact", final_contact, "m")
    check_nonnegative("initial_contact", initial_contact, "m")
    return (np.asarray(final_contact, dtype=float) - initial_contact) / np.asarray(rate)


def contact_distance(t, rate, final_contact, initial_contact=0.0):
    r"""Contact distance against time, :math:`l(t) = \min(l_f, l_0 + \alpha t)` (eqs 6.1, 8.1).

    Parameters
    ----------
    t : float or array, s
    rate : float, m/s
    final_contact : float, m
    initial_contact : float, m

    Returns
    -------
    float or array, m

    Examples
    --------
    >>> contact_distance(np.array([0.0, 10.0, 100.0]), 2.0, 40.0).tolist()
    [0.0, 20.0, 40.0]

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eqs 6.1, 8.1.
    """
    check_nonnegative("t", t, "s")
    check_nonnegative("rate", rate, "m/s")
    check_nonnegative("final_contact", final_contact, "m")
    check_nonnegative("initial_contact", initial_contact, "m")
    return np.minimum(final_contact, initial_contact + rate * np.asarray(t, dtype=float))


@dataclass(frozen=True)
class MixingResult:
    """Mixing-model prediction for one operating point (SI units)."""

    t: np.ndarray
    contact: np.ndarray
    rate: float
    final_contact: float
    mixing_time: float
    psi: float
    omega_parameter: float

    def to_frame(self) -> pd.DataFrame:
        """Time series of the contact distance."""
        import pandas as pd

        return with_units(
            pd.DataFrame({"t_s": self.t, "contact_m": self.contact}), "transverse.mixing"
        )

    def plot(self, ax=None):
        """Contact distance against time; returns the Figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        ax.plot(self.t, self.contact)
        ax.axhline(self.final_contact, ls=":", c="k")
        ax.set_xlabel("time (s)")
        ax.set_ylabel("contact distance (m)")
        return ax.figure


def vanpuyvelde_mixing(
    radius,
    omega,
    fill,
    d_p,
    ratio,
    *,
    duration: float | None = None,
    n_points: int = 201,
    **limits,
) -> MixingResult:
    """Mixing rate, final contact, mixing time and l(t) for a drum (eqs 5.2, 5.6, 6.8-6.11).

    Warns (OutOfRangeWarning) outside the fitted ranges N 5-19 rpm, fill 6-40 %, d_p 0.89-5.08 mm,
    ratio 1-2.7.

    Parameters
    ----------
    radius : float, m
    omega : float, rad/s
    fill : float, -
    d_p : float, m
    ratio : float, -
    duration : float, s, optional
        Length of the time series (default 1.5 mixing times).
    n_points : int
        Points of the time series.
    **limits
        Limiting constants: ``d_limit_rate``, ``ratio_limit_rate``, ``d_limit_final``,
        ``ratio_limit_final``.

    Returns
    -------
    MixingResult

    Examples
    --------
    >>> r = vanpuyvelde_mixing(0.285, 9 / 60 * 2 * np.pi, 0.25, 2.51e-3, 1.06)
    >>> round(r.rate, 2), round(r.final_contact, 1), round(r.mixing_time, 1)
    (2.09, 42.7, 20.5)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eqs 5.2, 5.6,
    6.8-6.11.
    """
    from rotarykiln.errors import warn_out_of_range
    from rotarykiln.transverse.active_layer import active_layer, warn_if_not_rolling

    warn_if_not_rolling(omega, radius, fill)
    al = active_layer(radius, omega, fill)
    warn_out_of_range("drum speed [rpm]", omega * 60 / (2 * np.pi), 5.0, 19.0, "Van Puyvelde ch 6")
    warn_out_of_range("fill", fill, 0.06, 0.40, "Van Puyvelde ch 6")
    warn_out_of_range("particle size [m]", d_p, 0.89e-3, 5.08e-3, "Van Puyvelde ch 6")
    warn_out_of_range("material ratio", material_ratio(ratio), 1.0, 2.7, "Van Puyvelde ch 6")
    psi = vanpuyvelde_active_layer_parameter(
        al.active_velocity,
        al.active_area,
        d_p,
        ratio,
        d_limit=limits.get("d_limit_rate", D_LIMIT_RATE),
        ratio_limit=limits.get("ratio_limit_rate", RATIO_LIMIT_RATE),
    )
    om = vanpuyvelde_final_contact_parameter(
        al.bed_area,
        d_p,
        ratio,
        d_limit=limits.get("d_limit_final", D_LIMIT_FINAL),
        ratio_limit=limits.get("ratio_limit_final", RATIO_LIMIT_FINAL),
    )
    rate = float(K_RATE * psi)
    lf = float(K_FINAL * om)
    tm = lf / rate if rate > 0 else np.inf
    if duration is None:
        duration = 1.5 * tm if np.isfinite(tm) and tm > 0 else 60.0
    t = np.linspace(0.0, duration, n_points)
    return MixingResult(
        t=t,
        contact=np.minimum(lf, rate * t),
        rate=rate,
        final_contact=lf,
        mixing_time=float(tm),
        psi=float(psi),
        omega_parameter=float(om),
    )
