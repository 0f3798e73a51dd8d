r"""Classical correlations for solids transport in rotating drums (reviewed by Scott 1986,
chapter 2, and Boateng, chapter 2).

Every function takes SI inputs (m, rad, rad/s, m3/s, kg/s) and returns SI outputs (s, m3/s, -),
converting internally to the units in which the correlation was fitted (minutes, rpm, degrees,
feet, inches per foot). Each is vectorised with numpy and warns (OutOfRangeWarning) outside the
range its source validated, where a range is known.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import (
    InputError,
    check_nonnegative,
    check_positive,
    check_range,
    warn_out_of_range,
)
from rotarykiln.transport._common import check_slope_and_repose

__all__ = [
    "abouzeid_fuerstenau_mean_fill",
    "abouzeid_fuerstenau_weir_fill",
    "austin_flemmer_minimum_fill",
    "bayard_residence_time",
    "gibbs_capacity",
    "gilbert_residence_time",
    "ginstling_residence_time",
    "hogg_constricted_mean_fill",
    "hogg_local_fill",
    "hogg_mean_fill",
    "karra_fuerstenau_discharge_fill",
    "perry_residence_time",
    "sullivan_residence_time",
    "vahl_kingma_flow",
    "vahl_kingma_residence_time",
    "van_krevelen_residence_time",
]

_RPM = 30.0 / np.pi  # rad/s -> rpm
_FT = 0.3048
_LB = 0.45359237


def _fill_from_theta(th):
    return (th - np.sin(th) * np.cos(th)) / np.pi


_UNITS = {"speed": "rad/s", "q": "m3/s", "g": "m/s2", "a": "", "b": "", "k": "", "k3": "", "k4": ""}


def _check(*, slope=None, repose=None, nonnegative=(), **positive):
    """InputError for a non-finite or non-positive input (or a negative one in ``nonnegative``,
    given as ``(name, value)`` pairs), and for slope/angle of repose outside their ranges.
    Vectorised: a few reductions per argument, no Python loop over elements."""
    for name, value in positive.items():
        check_positive(name, value, _UNITS.get(name, "m"))
    for name, value in nonnegative:
        check_nonnegative(name, value, _UNITS.get(name, "m"))
    if slope is not None:
        check_positive("slope", slope, "rad")
    if repose is not None:
        if slope is not None:
            check_slope_and_repose(slope, repose, field="repose")
        else:
            check_range("repose", repose, 0.0, np.pi / 2, unit="rad")


def _level_bed_limit(coef, f0, ratio, power=1.64):
    """``coef/ratio * ((1 + ratio)**power - 1)`` without 0/0 at zero flow (limit coef*power)
    nor cancellation at small ``ratio``."""
    ratio = np.asarray(ratio, dtype=float)
    safe = np.where(ratio > 0, ratio, 1.0)
    value = np.expm1(power * np.log1p(safe)) / safe
    return coef * np.where(ratio > 0, value, power) * f0


def sullivan_residence_time(length, diameter, speed, slope, repose):
    r"""Sullivan, Maier & Ralston (1927) mean residence time (Scott eq. 2.1), s.

    .. math:: t\,[\mathrm{min}] = \frac{1.77\,L\sqrt{\alpha_d}}{\psi N D}

    with :math:`\alpha_d` and :math:`\psi` in degrees, N in rpm, L and D in m (the constant is
    dimensional only through the degrees: L/D is a ratio).

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Drum slope, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2) and above the slope.

    Returns
    -------
    float or array, s
        Mean residence time.

    Examples
    --------
    >>> t = sullivan_residence_time(10.0, 1.0, 2 * np.pi / 60, np.radians(2), np.radians(35))
    >>> round(float(t / 60), 2)
    52.36

    References
    ----------
    Sullivan, J. D., Maier, C. G., Ralston, O. C. (1927) US Bureau of Mines Tech. Paper 384.
    """
    _check(length=length, diameter=diameter, speed=speed, slope=slope, repose=repose)
    minutes = (
        1.77
        * np.asarray(length)
        * np.sqrt(np.degrees(repose))
        / (np.degrees(slope) * np.asarray(speed) * _RPM * np.asarray(diameter))
    )
    return 60.0 * minutes


def gilbert_residence_time(length, diameter, speed):
    r"""Gilbert (1932): the charge advances 23.3 % of D per revolution (Scott eq. 2.2), s.

    .. math:: t\,[\mathrm{min}] = \frac{L}{0.233\,DN} = 4.29\frac{L}{DN}

    Validity: sand, bench drums D 5-7 cm at a slope of 2.29 deg, fill up to 9 %.

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.

    Returns
    -------
    float or array, s
        Mean residence time.

    Examples
    --------
    >>> round(float(gilbert_residence_time(0.762, 0.0635, 2 * np.pi / 60 * 10) / 60), 3)
    5.15

    References
    ----------
    Gilbert (1932) [G1 of Scott], reviewed in Scott, W. J. (1986) The transport of solids in
    rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.2.
    """
    _check(length=length, diameter=diameter, speed=speed)
    return 60.0 * np.asarray(length) / (0.233 * np.asarray(diameter) * np.asarray(speed) * _RPM)


def ginstling_residence_time(length, diameter, speed, slope):
    r"""Ginstling, Zil'berman & Gvozdev (1939), slumping beds (Scott eq. 2.4), s.

    .. math:: t\,[\mathrm{min}] = \frac{26.81\,L}{\psi N D}

    with :math:`\psi` in degrees (the reading for which it is ~2.5 x Sullivan, as Scott states).

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Drum slope, > 0.

    Returns
    -------
    float or array, s
        Mean residence time.

    Examples
    --------
    >>> t = ginstling_residence_time(10.0, 1.0, 2 * np.pi / 60, np.radians(2))
    >>> round(float(t / 60), 1)
    134.1

    References
    ----------
    Ginstling, Zil'berman & Gvozdev (1939) [G2 of Scott, via Friedman & Marshall], reviewed in
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 2,
    eq. 2.4.
    """
    _check(length=length, diameter=diameter, speed=speed, slope=slope)
    return (
        60.0
        * 26.81
        * np.asarray(length)
        / (np.degrees(slope) * np.asarray(speed) * _RPM * np.asarray(diameter))
    )


def van_krevelen_residence_time(length, diameter, speed, slope, k):
    r"""Van Krevelen & Hoftijzer, slumping beds (Scott eq. 2.5), s.

    .. math:: t\,[\mathrm{min}] = \frac{kL}{DN\tan\psi}

    ``k`` is empirical (no value printed); N in rpm.

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Drum slope, > 0.
    k : float or array, -
        Empirical constant, > 0.

    Returns
    -------
    float or array, s
        Mean residence time.

    Examples
    --------
    >>> t = van_krevelen_residence_time(10.0, 1.0, 2 * np.pi / 60, np.radians(2), 0.2)
    >>> round(float(t / 60), 2)
    57.27

    References
    ----------
    Van Krevelen & Hoftijzer [V1 of Scott], reviewed in Scott, W. J. (1986) The transport of solids
    in rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.5.
    """
    _check(length=length, diameter=diameter, speed=speed, slope=slope, k=k)
    return (
        60.0
        * k
        * np.asarray(length)
        / (np.asarray(diameter) * np.asarray(speed) * _RPM * np.tan(slope))
    )


def gibbs_capacity(length, diameter, k):
    r"""Gibbs (1942) kiln capacity :math:`T_d = kLD^2/100` (Scott eq. 2.6), kg/s.

    :math:`T_d` in (short) tons of finished material per day with L and D in feet (assumed:
    the thesis gives no units; Gibbs worked in US units). ``k`` is a material constant.

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    k : float or array, -
        Material constant, > 0 (US units: tons/day with L, D in ft).

    Returns
    -------
    float or array, kg/s
        Capacity (finished material).

    Examples
    --------
    >>> round(float(gibbs_capacity(60 * 0.3048, 8 * 0.3048, 1.0)), 4)
    0.4032

    References
    ----------
    Gibbs (1942) [G3 of Scott], reviewed in Scott, W. J. (1986) The transport of solids in rotating
    drums, PhD thesis, Edinburgh, ch. 2, eq. 2.6.
    """
    _check(length=length, diameter=diameter, k=k)
    tons_per_day = k * (np.asarray(length) / _FT) * (np.asarray(diameter) / _FT) ** 2 / 100.0
    return tons_per_day * 2000.0 * _LB / 86400.0


def bayard_residence_time(length, diameter, speed, slope, repose):
    r"""Bayard (1945) mean residence time (Scott eqs. 2.7-2.8), s.

    .. math:: t\,[\mathrm{min}] = \frac{0.176(\alpha_d + 24)L}{\psi N D}

    :math:`\alpha_d`, :math:`\psi` in degrees (the inches-per-foot form 2.7 has 0.037). Within
    2 % of Sullivan's for :math:`\alpha_d` = 30-45 deg.

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Drum slope, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2) and above the slope.

    Returns
    -------
    float or array, s
        Mean residence time.

    Examples
    --------
    >>> t = bayard_residence_time(10.0, 1.0, 2 * np.pi / 60, np.radians(2), np.radians(35))
    >>> round(float(t / 60), 2)
    51.92

    References
    ----------
    Bayard (1945) [B1 of Scott], reviewed in Scott, W. J. (1986) The transport of solids in
    rotating drums, PhD thesis, Edinburgh, ch. 2, eqs. 2.7-2.8.
    """
    _check(length=length, diameter=diameter, speed=speed, slope=slope, repose=repose)
    minutes = (
        0.176
        * (np.degrees(repose) + 24.0)
        * np.asarray(length)
        / (np.degrees(slope) * np.asarray(speed) * _RPM * np.asarray(diameter))
    )
    return 60.0 * minutes


def vahl_kingma_flow(inlet_depth, diameter, length, speed, repose):
    r"""Vahl & Kingma (1952), horizontal drum (Scott eq. 2.11), m3/s.

    .. math:: q = 0.68\,(h_i/D)^{2.08} D^4 N\cot\alpha_d / L

    N in rev/s. Validity :math:`0.15 \le h_i/D \le 0.45` (drum L 0.63 m, D 0.11 m, 8-32 %
    critical, sand and rye; under-predicts their flows by 13 % on average).

    Parameters
    ----------
    inlet_depth : float or array, m
        Bed depth at the feed end, in [0, D].
    diameter : float or array, m
        Drum inner diameter, > 0.
    length : float or array, m
        Drum length, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2).

    Returns
    -------
    float or array, m3/s
        Volumetric flow.

    Examples
    --------
    >>> round(float(vahl_kingma_flow(0.03, 0.11, 0.63, 2 * np.pi * 0.5, np.radians(35)) * 1e6), 3)
    7.565

    References
    ----------
    Vahl, L., Kingma, W. G. (1952) Chem. Eng. Sci. 1, 253; Scott, W. J. (1986) The transport of
    solids in rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.11.
    """
    _check(diameter=diameter, length=length, speed=speed, repose=repose)
    ratio = np.asarray(inlet_depth) / np.asarray(diameter)
    check_range("inlet_depth/diameter", ratio, 0.0, 1.0, closed_low=True, closed_high=True)
    warn_out_of_range("h_i/D", ratio, 0.15, 0.45, "Vahl & Kingma (1952)")
    n = np.asarray(speed) / (2 * np.pi)
    return 0.68 * ratio**2.08 * np.asarray(diameter) ** 4 * n / np.tan(repose) / np.asarray(length)


def vahl_kingma_residence_time(inlet_depth, diameter, length, speed, repose):
    r"""Vahl & Kingma mean residence time (Scott eq. 2.15), s.

    .. math:: t = 0.91\,(L/D)^2 (D/h_i)^{0.6}\tan\alpha_d / N

    Parameters
    ----------
    inlet_depth : float or array, m
        Bed depth at the feed end, in (0, D].
    diameter : float or array, m
        Drum inner diameter, > 0.
    length : float or array, m
        Drum length, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2).

    Returns
    -------
    float or array, s
        Mean residence time.

    Examples
    --------
    >>> round(float(vahl_kingma_residence_time(0.03, 0.11, 0.63, np.pi, np.radians(35))), 1)
    91.2

    References
    ----------
    Vahl, L., Kingma, W. G. (1952) Chem. Eng. Sci. 1, 253; Scott, W. J. (1986) The transport of
    solids in rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.15.
    """
    _check(diameter=diameter, length=length, speed=speed, repose=repose)
    check_range(
        "inlet_depth/diameter", np.asarray(inlet_depth) / diameter, 0.0, 1.0, closed_high=True
    )
    n = np.asarray(speed) / (2 * np.pi)
    d = np.asarray(diameter)
    return (
        0.91
        * (np.asarray(length) / d) ** 2
        * (d / np.asarray(inlet_depth)) ** 0.6
        * (np.tan(repose) / n)
    )


def _hogg_group(q, x, radius, speed, repose, b):
    return np.asarray(q) * np.asarray(x) / (b / np.tan(repose) * np.asarray(speed) * radius**4)


def hogg_local_fill(q, x, radius, speed, repose, b=0.51):
    r"""Hogg, Shoji & Austin (1974) local filling of a horizontal open drum (Scott eq. 2.24).

    .. math:: f_c = 0.875\left[\frac{qx}{B\cot\alpha\,\omega R^4}\right]^{0.64}

    x from the discharge. B = 0.51 was fitted with the static angle (38 deg) for alpha. Valid
    for :math:`0.04 \le f_c \le 0.4`.

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric solids flow, >= 0.
    x : float or array, m
        Distance from the discharge, >= 0.
    radius : float or array, m
        Drum inner radius, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2).
    b : float, -
        Hogg's constant B (0.51 fitted with the static angle), > 0.

    Returns
    -------
    float or array, -
        Local filling.

    Examples
    --------
    >>> round(float(hogg_local_fill(2e-6, 0.2, 0.0475, 6.6, np.radians(38))), 4)
    0.0675

    References
    ----------
    Hogg, R., Shoji, K., Austin, L. G. (1974) Powder Technol. 9, 99; Scott, W. J. (1986) The
    transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.24.
    """
    _check(radius=radius, speed=speed, repose=repose, b=b, nonnegative=(("q", q), ("x", x)))
    fc = 0.875 * _hogg_group(q, x, radius, speed, repose, b) ** 0.64
    warn_out_of_range("local fill", fc, 0.04, 0.4, "Hogg et al. (1974)")
    return fc


def hogg_mean_fill(q, length, radius, speed, repose, b=0.51):
    r"""Hogg et al. mean filling of an open horizontal drum (Scott eq. 2.25, L restored).

    .. math:: F_C = 0.534\left[\frac{qL}{B\cot\alpha\,\omega R^4}\right]^{0.64}

    (0.534 = 0.875/1.64, the length average of eq. 2.24.)

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric solids flow, >= 0.
    length : float or array, m
        Drum length, > 0.
    radius : float or array, m
        Drum inner radius, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2).
    b : float, -
        Hogg's constant B (0.51 fitted with the static angle), > 0.

    Returns
    -------
    float or array, -
        Mean filling.

    Examples
    --------
    >>> round(float(hogg_mean_fill(2e-6, 0.248, 0.0475, 6.6, np.radians(38))), 4)
    0.0472

    References
    ----------
    Hogg, R., Shoji, K., Austin, L. G. (1974) Powder Technol. 9, 99; Scott, W. J. (1986) The
    transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.25.
    """
    _check(length=length, radius=radius, speed=speed, repose=repose, b=b, nonnegative=(("q", q),))
    return 0.534 * _hogg_group(q, length, radius, speed, repose, b) ** 0.64


def hogg_constricted_mean_fill(q, length, radius, speed, repose, discharge_fill, b=0.51):
    r"""Hogg et al. mean filling with a constricted discharge of filling :math:`f_c(0)`
    (Scott eq. 2.35):

    .. math:: F_C = \frac{0.751 K' f_0^{2.56}}{qL}
        \left[\left(1 + \frac{0.812\,qL}{K' f_0^{1.56}}\right)^{1.64} - 1\right],
        \quad K' = B\cot\alpha\,\omega R^4

    At zero flow the bed is level: the limit :math:`F_C = f_0` is returned.

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric solids flow, >= 0.
    length : float or array, m
        Drum length, > 0.
    radius : float or array, m
        Drum inner radius, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2).
    discharge_fill : float or array, -
        Filling at the discharge, in (0, 1).
    b : float, -
        Hogg's constant B (0.51 fitted with the static angle), > 0.

    Returns
    -------
    float or array, -
        Mean filling.

    Examples
    --------
    >>> round(float(hogg_constricted_mean_fill(2e-6, 0.248, 0.0475, 6.6, np.radians(38), 0.1)),
    ...       4)
    0.1199

    References
    ----------
    Hogg, R., Shoji, K., Austin, L. G. (1974) Powder Technol. 9, 99; Scott, W. J. (1986) The
    transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.35.
    """
    _check(length=length, radius=radius, speed=speed, repose=repose, b=b, nonnegative=(("q", q),))
    check_range("discharge_fill", discharge_fill, 0.0, 1.0)
    kp = b / np.tan(repose) * np.asarray(speed) * np.asarray(radius) ** 4
    f0 = np.asarray(discharge_fill, dtype=float)
    ql = np.asarray(q) * np.asarray(length)
    return _level_bed_limit(0.751 * 0.812, f0, 0.812 * ql / (kp * f0**1.56))


def austin_flemmer_minimum_fill(q, radius, speed, repose, b=1.0):
    r"""Austin & Flemmer's minimum (discharge) filling of a horizontal drum, -.

    The flow :math:`q = K\sin^3\theta\,\tan\beta/(1+\tan^2\beta)`, :math:`K = \frac{2}{3}B\omega
    R^3\cot\alpha` is largest at :math:`\beta = 45^\circ`, so :math:`\sin^3\theta_{min} = 2q/K`
    (Austin & Flemmer's form; Scott's printed "2.5" is wrong, see docs).

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric solids flow, >= 0.
    radius : float or array, m
        Drum inner radius, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2).
    b : float, -
        Constant B, > 0.

    Returns
    -------
    float or array, -
        Minimum filling at the discharge.

    Examples
    --------
    >>> round(float(austin_flemmer_minimum_fill(1e-6, 0.0475, 6.6, np.radians(38))), 4)
    0.0007

    References
    ----------
    Austin & Flemmer (1974) [A2 of Scott], reviewed in Scott, W. J. (1986) The transport of solids
    in rotating drums, PhD thesis, Edinburgh, ch. 2, ch. 2 (printed 2.5 corrected to 2).
    """
    _check(radius=radius, speed=speed, repose=repose, b=b, nonnegative=(("q", q),))
    k = 2.0 / 3.0 * b * np.asarray(speed) * np.asarray(radius) ** 3 / np.tan(repose)
    s3 = 2.0 * np.asarray(q) / k
    if np.any(s3 > 1.0):
        raise InputError("feed", float(np.max(q)), "<= K/2 (no bed below the axis can carry it)")
    return _fill_from_theta(np.arcsin(np.cbrt(s3)))


def karra_fuerstenau_discharge_fill(q, diameter, k3, k4, g=9.81):
    r"""Karra & Fuerstenau (1978) grate-discharge filling (Scott eq. 2.38, :math:`D^3`
    restored): :math:`f_c(0) = K_3 (q/(\omega_c D^3))^{K_4}`, -. K3 and K4 are fitted per
    plate geometry (no values printed); Scott notes the fit exceeds the mean fill, so the value
    has no physical meaning.

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric solids flow, >= 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    k3, k4 : float, -
        Fitted constants, > 0.
    g : float, m/s2
        Gravitational acceleration.

    Returns
    -------
    float or array, -
        Filling at the grate discharge.

    Examples
    --------
    >>> round(float(karra_fuerstenau_discharge_fill(1e-6, 0.127, 2.0, 0.5)), 4)
    0.0125

    References
    ----------
    Karra & Fuerstenau (1978) [K2 of Scott], reviewed in Scott, W. J. (1986) The transport of
    solids in rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.38.
    """
    _check(diameter=diameter, k3=k3, k4=k4, g=g, nonnegative=(("q", q),))
    d = np.asarray(diameter)
    return k3 * (np.asarray(q) / (np.sqrt(g / (d / 2.0)) * d**3)) ** k4


def abouzeid_fuerstenau_mean_fill(q, length, diameter, speed, discharge_fill, a, g=9.81):
    r"""Abouzeid & Fuerstenau (1980) mean filling of a constricted horizontal drum (2.39).

    .. math:: F_C = \frac{f_0^{2.56}}{21.31}\frac{A\omega^* D}{F^* L}
        \left[\left(1 + \frac{12.99 F^* L}{f_0^{1.56} A\omega^* D}\right)^{1.64} - 1\right]

    with :math:`F^* = q/(\omega_c D^3)`, :math:`\omega^* = \omega/\omega_c` and
    :math:`A = B\cot\alpha_d` (fitted as :math:`-K_1\omega^* + K_2`). Note that A&F's filling
    excludes a core cylinder of radius :math:`R_c` (never stated; Scott).

    At zero flow the bed is level: the limit :math:`F_C = f_0` is returned.

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric solids flow, >= 0.
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    discharge_fill : float or array, -
        Filling at the discharge, in (0, 1).
    a : float or array, -
        :math:`A = B\cot\alpha_d`, > 0.
    g : float, m/s2
        Gravitational acceleration.

    Returns
    -------
    float or array, -
        Mean filling.

    Examples
    --------
    >>> round(float(abouzeid_fuerstenau_mean_fill(1e-6, 0.24, 0.08, 4.4, 0.15, 1.2)), 4)
    0.1629

    References
    ----------
    Abouzeid, A.-Z. M. A., Fuerstenau, D. W. (1980) Ind. Eng. Chem. Proc. Des. Dev. 19, 201; Scott,
    W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 2, eq. 2.39.
    """
    _check(length=length, diameter=diameter, speed=speed, a=a, g=g, nonnegative=(("q", q),))
    check_range("discharge_fill", discharge_fill, 0.0, 1.0)
    d = np.asarray(diameter)
    wc = np.sqrt(g / (d / 2.0))
    fstar = np.asarray(q) / (wc * d**3)
    wstar = np.asarray(speed) / wc
    f0 = np.asarray(discharge_fill, dtype=float)
    aw = a * wstar * d
    fl = fstar * np.asarray(length)
    return _level_bed_limit(12.99 / 21.31, f0, 12.99 * fl / (f0**1.56 * aw))


def abouzeid_fuerstenau_weir_fill(height_over_weir, weir_radius, drum_radius):
    r"""Filling of the drum cross-section for a bed :math:`Z` above a weir of radius
    :math:`R_c` (Scott eq. 2.45): :math:`\frac{1}{\pi}[\cos^{-1}c - c\sqrt{1-c^2}]`,
    :math:`c = (R_c - Z)/R_d`. With ``drum_radius = weir_radius`` this is eq. 2.44 (filling of
    the constriction circle).

    Parameters
    ----------
    height_over_weir : float or array, m
        Bed height Z above the weir crest; (R_c - Z)/R_d must lie in [-1, 1].
    weir_radius : float or array, m
        Radius of the weir opening R_c, > 0.
    drum_radius : float or array, m
        Drum radius R_d, > 0.

    Returns
    -------
    float or array, -
        Filling of the cross-section.

    Examples
    --------
    >>> round(float(abouzeid_fuerstenau_weir_fill(0.0, 0.037, 0.0465)), 4)
    0.0537

    References
    ----------
    Abouzeid & Fuerstenau (1980) [A4 of Scott], reviewed in Scott, W. J. (1986) The transport of
    solids in rotating drums, PhD thesis, Edinburgh, ch. 2, eqs. 2.44-2.45.
    """
    _check(weir_radius=weir_radius, drum_radius=drum_radius)
    c = (np.asarray(weir_radius) - np.asarray(height_over_weir)) / np.asarray(drum_radius)
    check_range(
        "height_over_weir, as (weir_radius - height)/drum_radius",
        c,
        -1.0,
        1.0,
        closed_low=True,
        closed_high=True,
    )
    return (np.arccos(c) - c * np.sqrt(1.0 - c * c)) / np.pi


def perry_residence_time(
    length,
    diameter,
    speed,
    slope,
    *,
    gas_mass_flux=0.0,
    feed_flux=None,
    particle_size=None,
    flow="counter",
):
    r"""Friedman & Marshall (1949) / Perry correlation ("US Geological Survey", Boateng eq. 2.1).

    .. math:: \bar\tau\,[\mathrm{min}] = \frac{0.23L}{sN^{0.9}D} \pm 0.6\frac{BLG}{F},
        \quad B = 5 d_p^{-0.5}

    in imperial units: L, D in ft, s the slope in ft/ft, N in rpm, G and F in lb/(h ft2), d_p in
    micrometres; "+" for counter-current gas, "-" for co-current. Inputs and result are SI
    (G and F in kg/(s m2), d_p in m); the conversion is done here.

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Drum slope, > 0.
    gas_mass_flux : float or array, kg/(s m2)
        Gas mass flux G, >= 0 (0: no gas term).
    feed_flux : float or array, kg/(s m2)
        Feed mass flux F, > 0 (needed with a gas flux).
    particle_size : float or array, m
        Particle size d_p, > 0 (needed with a gas flux).
    flow : {"counter", "co"}
        Gas flow direction relative to the solids.

    Returns
    -------
    float or array, s
        Mean residence time; InputError if a co-current gas term would make it <= 0.

    Examples
    --------
    Boateng's design kiln (12 ft, L/D 10, 3 deg, 1 rpm), no gas: 43.9 min

    >>> round(float(perry_residence_time(36.6, 3.66, np.pi / 30, np.radians(3)) / 60), 1)
    43.9

    References
    ----------
    Friedman, S. J., Marshall, W. R. (1949) Chem. Eng. Prog. 45, 482; Perry's Chemical Engineers'
    Handbook; Boateng, A. A., Rotary Kilns, eq. 2.1.
    """
    _check(length=length, diameter=diameter, speed=speed, slope=slope)
    check_nonnegative("gas_mass_flux", gas_mass_flux, "kg/(s m2)")
    l_ft = np.asarray(length) / _FT
    d_ft = np.asarray(diameter) / _FT
    n = np.asarray(speed) * _RPM
    minutes = 0.23 * l_ft / (np.tan(slope) * n**0.9 * d_ft)
    if np.any(np.asarray(gas_mass_flux) != 0):
        if feed_flux is None or particle_size is None:
            raise InputError("perry", "gas term", "given with feed_flux and particle_size")
        if flow not in ("counter", "co"):
            raise InputError("flow", flow, "counter or co")
        check_positive("feed_flux", feed_flux, "kg/(s m2)")
        check_positive("particle_size", particle_size, "m")
        to_imp = 3600.0 / _LB * _FT**2  # kg/(s m2) -> lb/(h ft2)
        g_imp = np.asarray(gas_mass_flux) * to_imp
        f_imp = np.asarray(feed_flux) * to_imp
        b = 5.0 * (np.asarray(particle_size) * 1e6) ** -0.5
        sign = 1.0 if flow == "counter" else -1.0
        minutes = minutes + sign * 0.6 * b * l_ft * g_imp / f_imp
        if np.any(minutes <= 0):
            raise InputError(
                "gas_mass_flux",
                float(np.max(gas_mass_flux)),
                "small enough that the co-current gas term leaves a positive residence time",
            )
    return 60.0 * minutes
