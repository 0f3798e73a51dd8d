r"""Correlations for the axial dispersion of solids in rotary kilns (seed 003 eqs. 15-19).

- :func:`sai_dispersion_number`: Sai et al. (1990), eq. 15, the dispersion number D/(uL).
- :func:`sherritt_dispersion`: Sherritt et al. (2003), eqs. 16-17, D in m2/s.
- :func:`bongo_njeng_dispersion`: Bongo Njeng et al. (2015), eqs. 18-19, D in m2/s, for kilns
  with lifters.

Eqs. 15 and 18 are not dimensionally homogeneous, so their input units matter. Seed 003 says
eq. 18 takes "the International System of Units", but with rad/s, rad and kg/s it gives D about
100-300 times below the paper's measured 1e-7 to 1e-4 m2/s; the units of its list of symbols
(feed in kg/h, speed in rpm, slope and angle of repose in degrees, lengths in m, areas in m2)
give values in that range (docs/validation.md). Those are the default here
(``convention="symbols"``); ``convention="si"`` evaluates the literal SI reading. All functions take
SI inputs and convert internally.
"""

from __future__ import annotations

import warnings

import numpy as np

from rotarykiln.errors import InputError, OutOfRangeWarning, check_positive, warn_out_of_range
from rotarykiln.regimes import fraction_of_critical

__all__ = [
    "BONGO_NJENG_CONSTANTS",
    "bongo_njeng_dispersion",
    "holdup_fraction",
    "sai_dispersion_number",
    "sherritt_dispersion",
]

_RPM = 2.0 * np.pi / 60.0
_KG_H = 1.0 / 3600.0

#: Table 4 of seed 003: k, a, b, c, d of eq. 18 (values; 95 % intervals in the data folder).
BONGO_NJENG_CONSTANTS = {"k": 1.2023e-7, "a": -0.8714, "b": 1.6736, "c": 0.4349, "d": 0.2062}
_BN_SOURCE = "Bongo Njeng et al. (2015)"
_BN_DIAMETER = 0.1013  # m, the only kiln of the data set


def sai_dispersion_number(
    tracer_repose_angle, slope, speed, tracer_density, *, density_unit: str = "kg/m3"
):
    r"""Dispersion number of Sai et al. (1990), seed 003 eq. 15.

    .. math::

        \frac{D}{uL} = \frac{1}{Pe} = 0.000562\,
            \frac{\theta_t^{0.79}}{S^{0.67}\,N^{1.06}\,\rho_t^{0.25}}

    with the tracer angle of repose :math:`\theta_t` and the slope S in degrees, the speed N in
    rpm and the tracer density :math:`\rho_t` in kg/m3 (or g/cm3 with ``density_unit``). Seed 003
    does not state the units; kg/m3 is the default because it gives the under-prediction of D
    the paper reports (Pe = 3112 against measured ~550 at its sand benchmark).

    Parameters
    ----------
    tracer_repose_angle : array_like
        Angle of repose of the tracer [rad].
    slope : array_like
        Kiln slope [rad].
    speed : array_like
        Rotational speed [rad/s].
    tracer_density : array_like
        Tracer density [kg/m3].
    density_unit : {"kg/m3", "g/cm3"}
        Unit in which the density enters the correlation.

    Returns
    -------
    numpy.ndarray or float
        D/(uL) [-].

    Notes
    -----
    Validity range not given in seed 003 (Sai et al. studied a kiln without lifters).

    Examples
    --------
    >>> import math
    >>> x = sai_dispersion_number(math.radians(35.4), math.radians(2), 3 * math.pi / 30, 1087)
    >>> round(1 / float(x))
    3112

    References
    ----------
    Sai, P. S. T. et al. (1990). Solids flow in rotary kilns. Cited as ref. [11] in seed 003.
    """
    for name, v in (
        ("tracer_repose_angle", tracer_repose_angle),
        ("slope", slope),
        ("speed", speed),
        ("tracer_density", tracer_density),
    ):
        check_positive(name, v)
    if density_unit not in ("kg/m3", "g/cm3"):
        raise InputError("density_unit", density_unit, "kg/m3 or g/cm3")
    rho = np.asarray(tracer_density, dtype=float) / (1000.0 if density_unit == "g/cm3" else 1.0)
    theta_deg = np.degrees(np.asarray(tracer_repose_angle, dtype=float))
    s_deg = np.degrees(np.asarray(slope, dtype=float))
    n_rpm = np.asarray(speed, dtype=float) / _RPM
    return (0.000562 * theta_deg**0.79 / (s_deg**0.67 * n_rpm**1.06 * rho**0.25))[()]


def holdup_fraction(mass_flow, mean_residence_time, bulk_density, diameter, length):
    r"""Volume fraction of the kiln occupied by solids, :math:`X = \dot M\bar t/(\rho_b \pi D^2 L/4)`.

    Parameters
    ----------
    mass_flow : array_like
        Solids mass flow [kg/s].
    mean_residence_time : array_like
        Mean residence time [s] (hold-up = mass flow x mean residence time).
    bulk_density : float
        Bulk density [kg/m3].
    diameter : float
        Kiln inner diameter [m].
    length : float
        Kiln length [m].

    Returns
    -------
    numpy.ndarray or float
        X [-].

    Examples
    --------
    >>> round(float(holdup_fraction(2.5 / 3600, 43.34 * 60, 1422, 0.1013, 1.95)), 4)
    0.0808

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565.
    """
    check_positive("mass_flow", mass_flow, "kg/s")
    check_positive("mean_residence_time", mean_residence_time, "s")
    check_positive("bulk_density", bulk_density, "kg/m3")
    check_positive("diameter", diameter, "m")
    check_positive("length", length, "m")
    volume = np.pi * diameter**2 / 4.0 * length
    return (np.asarray(mass_flow, float) * mean_residence_time / (bulk_density * volume))[()]


def sherritt_dispersion(speed, diameter, particle_size, holdup_fraction):
    r"""Axial dispersion coefficient of Sherritt et al. (2003), seed 003 eqs. 16-17.

    .. math::

        D = 0.0011\,(N/N_c)^{0.39}\,D_i^{1.15}\,d_p^{0.46}\,X^{-0.43},
        \qquad N_c = \frac{60}{2\pi}\sqrt{\frac{2g}{D_i}}

    (SI: D in m2/s, diameters in m; N/N_c = fraction of the critical speed).

    Parameters
    ----------
    speed : array_like
        Rotational speed [rad/s].
    diameter : float
        Kiln inner diameter D_i [m].
    particle_size : float
        Mean particle size d_p [m].
    holdup_fraction : array_like
        Solids volume fraction X [-] (see :func:`holdup_fraction`); fitted for X < 0.5.

    Returns
    -------
    numpy.ndarray or float
        D [m2/s].

    Notes
    -----
    Fitted by Sherritt et al. on published data for kiln diameters 0.076-0.144 m and all bed
    regimes; warns (:class:`~rotarykiln.errors.OutOfRangeWarning`) for X >= 0.5.

    Examples
    --------
    >>> d = sherritt_dispersion(3 * 3.14159265 / 30, 0.1013, 0.55e-3, 0.0808)
    >>> f"{float(d):.2g}"
    '1.7e-06'

    References
    ----------
    Sherritt, R. G. et al. (2003). Chem. Eng. Sci. 58, 401-415. Ref. [44] of seed 003.
    """
    check_positive("speed", speed, "rad/s")
    check_positive("diameter", diameter, "m")
    check_positive("particle_size", particle_size, "m")
    check_positive("holdup_fraction", holdup_fraction)
    warn_out_of_range("hold-up fraction X", holdup_fraction, 0.0, 0.5, "Sherritt et al. (2003)")
    ratio = fraction_of_critical(np.asarray(speed, float), diameter / 2.0)
    x = np.asarray(holdup_fraction, dtype=float)
    return (0.0011 * ratio**0.39 * diameter**1.15 * particle_size**0.46 * x**-0.43)[()]


def bongo_njeng_dispersion(
    mass_flow,
    bulk_density,
    speed,
    slope,
    repose_angle,
    particle_size,
    loading_area,
    diameter,
    *,
    convention: str = "symbols",
):
    r"""Axial dispersion coefficient in a kiln with lifters, Bongo Njeng et al. (2015) eq. 18.

    .. math::

        D = k\left(\frac{\dot M}{\rho_b}\right)^a (N S)^b (\beta\,d_p)^c L_s^d\,D_i,

    k = 1.2023e-7, a = -0.8714, b = 1.6736, c = 0.4349, d = 0.2062 (Table 4), with
    :math:`L_s = (n_{lift} - 1) S_{lift}/2` (eq. 19, see
    :func:`rotarykiln.rtd.internals.loading_lifter_area`).

    Parameters
    ----------
    mass_flow : array_like
        Solids mass flow [kg/s].
    bulk_density : array_like
        Bulk density [kg/m3].
    speed : array_like
        Rotational speed [rad/s].
    slope : array_like
        Kiln slope [rad].
    repose_angle : array_like
        Angle of repose of the bulk solid [rad].
    particle_size : array_like
        Mean particle size [m].
    loading_area : array_like
        Ls, area of solids in the loading lifters [m2]; 0 (no lifters) gives D = 0 with a warning.
    diameter : float
        Kiln inner diameter [m] (enters with exponent 1; only 0.1013 m was tested).
    convention : {"symbols", "si"}
        Units in which the inputs enter: "symbols" (the paper's list of symbols: kg/h, rpm,
        deg, deg; the values the paper reports require it) or "si" (kg/s, rad/s, rad, rad).

    Returns
    -------
    numpy.ndarray or float
        D [m2/s].

    Notes
    -----
    Validity (seed 003 Table 1): N 2-12 rpm, S 2-5 deg, feed 0.68-2.5 kg/h, one kiln of
    0.1013 m x 1.95 m, sand and broken rice, straight or rectangular lifters. Outside, and without
    lifters, an :class:`~rotarykiln.errors.OutOfRangeWarning` is issued. Accuracy: "good
    agreement", within about +/-20 % on the paper's parity plot (Fig. 10c); no statistic given.

    Examples
    --------
    >>> import math
    >>> d = bongo_njeng_dispersion(2.5 / 3600, 1422, 3 * math.pi / 30, math.radians(2),
    ...                            math.radians(39), 0.55e-3, 5.833e-5, 0.1013)
    >>> f"{float(d):.3e}"
    '1.548e-06'

    References
    ----------
    Bongo Njeng, A. S. et al. (2015). Powder Technol. 269, 554-565, eqs. 18-19 and Table 4.
    """
    for name, v, unit in (
        ("mass_flow", mass_flow, "kg/s"),
        ("bulk_density", bulk_density, "kg/m3"),
        ("speed", speed, "rad/s"),
        ("slope", slope, "rad"),
        ("repose_angle", repose_angle, "rad"),
        ("particle_size", particle_size, "m"),
        ("diameter", diameter, "m"),
    ):
        check_positive(name, v, unit)
    ls = np.asarray(loading_area, dtype=float)
    if np.any(~np.isfinite(ls) | (ls < 0)):
        raise InputError("loading_area", ls, ">= 0 m2")
    if convention not in ("symbols", "si"):
        raise InputError("convention", convention, "symbols or si")
    m = np.asarray(mass_flow, dtype=float)
    n = np.asarray(speed, dtype=float)
    s = np.asarray(slope, dtype=float)
    beta = np.asarray(repose_angle, dtype=float)
    warn_out_of_range("speed [rpm]", n / _RPM, 2.0, 12.0, _BN_SOURCE)
    warn_out_of_range("slope [deg]", np.degrees(s), 2.0, 5.0, _BN_SOURCE)
    warn_out_of_range("feed [kg/h]", m / _KG_H, 0.68, 2.5, _BN_SOURCE)
    warn_out_of_range("kiln diameter [m]", diameter, 0.095, 0.105, _BN_SOURCE + " (one kiln)")
    if np.any(ls == 0):
        warnings.warn(
            "Bongo Njeng et al. (2015) eq. 18 is for kilns with lifters: without lifters "
            "(loading area 0) it gives D = 0",
            OutOfRangeWarning,
            stacklevel=2,
        )
    if convention == "symbols":
        m, n, s, beta = m / _KG_H, n / _RPM, np.degrees(s), np.degrees(beta)
    c = BONGO_NJENG_CONSTANTS
    d = (
        c["k"]
        * (m / np.asarray(bulk_density, float)) ** c["a"]
        * (n * s) ** c["b"]
        * (beta * np.asarray(particle_size, float)) ** c["c"]
        * ls ** c["d"]
        * diameter
    )
    return d[()]
