r"""Kramers-Croockewit / Saeman bed-depth equation of a rotating drum.

With :math:`x` measured from the discharge end towards the feed, :math:`n = \omega/2\pi` the
speed in rev/s, :math:`q` the volumetric flow, :math:`\alpha` the dynamic angle of repose and
:math:`\psi` the slope (Saeman 1951; Kramers & Croockewit 1952; Scott 1986 eq. 2.10; Boateng
eq. 2.14):

.. math::

    \frac{dh}{dx} = \frac{3q\tan\alpha}{4\pi n R^3}
        \left[\frac{h}{R}\left(2-\frac{h}{R}\right)\right]^{-3/2} - \frac{\tan\psi}{\cos\alpha}
    \equiv K\,P(h)^{-1} - C

The equation is integrated upstream from the discharge: an open end starts at :math:`h = 0`
(Saeman; the singular start is removed by the state :math:`w = h^{5/2}`), a dam at its height.
Far from the discharge of an inclined drum the depth tends to the uniform depth

.. math::

    \frac{h_\infty}{R} = 1 - \sqrt{1 - (K/C)^{2/3}},

which exists only for :math:`K \le C`. Radius, angle of repose and flow may vary along the drum
(callables of :math:`z`, the distance from the feed end, or tables ``(z, values)``).
"""

from __future__ import annotations

import warnings

import numpy as np
from scipy.integrate import solve_ivp

from rotarykiln.errors import InputError, OutOfRangeWarning, check_nonnegative, check_positive
from rotarykiln.geometry import fill_from_half_angle
from rotarykiln.transport._common import (
    as_axial_function,
    check_slope_and_repose,
    critical_speed,
    march,
    warn_speed,
)
from rotarykiln.transport.result import BedProfile
from rotarykiln.transport.weirs import dam_radius_from_height

__all__ = [
    "kramers_dimensionless_flow",
    "kramers_dimensionless_length",
    "kramers_max_uniform_flow",
    "kramers_profile",
    "kramers_uniform_depth",
    "kramers_uniform_residence_time",
]

SOURCE = "Kramers & Croockewit (1952) / Scott (1986)"


def _kc(q, radius, omega, slope, repose):
    k = 1.5 * q * np.tan(repose) / (omega * radius**3)  # 3 q tan(a) / (4 pi n R^3), n = w/2pi
    c = np.tan(slope) / np.cos(repose)
    return k, c


def kramers_max_uniform_flow(radius, speed, slope, repose):
    r"""Largest flow a uniform bed can carry (at half fill), :math:`K = C`, m3/s.

    .. math:: q_{max} = \frac{2\omega R^3\tan\psi}{3\sin\alpha}

    Parameters
    ----------
    radius : float or array, m
    speed : float or array, rad/s
    slope : float or array, rad
    repose : float or array, rad
        Dynamic angle of repose.

    Returns
    -------
    float or array, m3/s

    Examples
    --------
    >>> round(float(kramers_max_uniform_flow(0.2, 0.314, np.radians(1), np.radians(35))), 7)
    5.1e-05

    References
    ----------
    Kramers, H., Croockewit, P. (1952) Chem. Eng. Sci. 1, 259; Saeman, W. C. (1951) Chem. Eng.
    Prog. 47, 508; Scott, W. J. (1986) PhD thesis, Edinburgh, eqs. 2.10, 2.17-2.18.
    """
    check_positive("radius", radius, "m")
    check_positive("speed", speed, "rad/s")
    check_slope_and_repose(slope, repose, field="repose")
    return (
        2.0 * np.asarray(speed) * np.asarray(radius) ** 3 * np.tan(slope) / (3.0 * np.sin(repose))
    )


def kramers_uniform_depth(q, radius, speed, slope, repose):
    r"""Uniform (far-from-discharge) bed depth of the Kramers-Croockewit equation, m.

    .. math:: h_\infty = R\left(1 - \sqrt{1 - (K/C)^{2/3}}\right),\quad
        K = \frac{3q\tan\alpha}{2\omega R^3},\quad C = \frac{\tan\psi}{\cos\alpha}

    Vectorised over all arguments.

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric flow.
    radius : float or array, m
    speed : float or array, rad/s
    slope : float or array, rad
        Must be > 0 (a horizontal drum has no uniform depth).
    repose : float or array, rad
        Dynamic angle of repose, > slope.

    Returns
    -------
    float or array, m

    Raises
    ------
    InputError
        Flow above :func:`kramers_max_uniform_flow` (no uniform bed can carry it), zero slope,
        or an angle of repose below the slope.

    Examples
    --------
    0.4 m drum at 3 rpm and 1 deg, 62 kg/h of a 1500 kg/m3 solid, 35 deg:

    >>> h = kramers_uniform_depth(62 / 3600 / 1500, 0.2, 3 * np.pi / 30, np.radians(1),
    ...                           np.radians(35))
    >>> round(float(h), 4)
    0.0413

    References
    ----------
    Kramers, H., Croockewit, P. (1952) Chem. Eng. Sci. 1, 259; Saeman, W. C. (1951) Chem. Eng.
    Prog. 47, 508.
    """
    q = np.asarray(q, dtype=float)
    radius = np.asarray(radius, dtype=float)
    check_positive("radius", radius, "m")
    check_positive("speed", speed, "rad/s")
    check_slope_and_repose(slope, repose)
    if np.any(np.asarray(slope) <= 0):
        raise InputError("slope", 0.0, "> 0 for a uniform depth (a horizontal drum has none)")
    check_nonnegative("feed", q, "m3/s")  # also NaN, which ``q < 0`` let through
    k, c = _kc(q, radius, speed, slope, repose)
    ratio = k / c
    if np.any(ratio > 1.0):
        qmax = kramers_max_uniform_flow(radius, speed, slope, repose)
        i = np.argmax(ratio > 1.0) if np.ndim(ratio) else ()
        raise InputError(
            "feed",
            f"{float(np.broadcast_to(q, ratio.shape)[i]):.6g} m3/s",
            f"<= {float(np.broadcast_to(qmax, ratio.shape)[i]):.6g} m3/s, the most a uniform bed "
            "can carry at this speed and slope (no steady solution)",
        )
    return radius * (1.0 - np.sqrt(1.0 - ratio ** (2.0 / 3.0)))


def kramers_uniform_residence_time(length, q, radius, speed, slope, repose):
    r"""Mean residence time of a drum at uniform Kramers depth, :math:`L A(h_\infty)/q`, s.

    At zero flow the limit :math:`L\sin\alpha/(\omega R\tan\psi)` (a thin bed: the particle time of
    Saeman's outermost path) is returned, not 0/0.

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    q, radius, speed, slope, repose : float or array, m3/s, m, rad/s, rad, rad
        As in :func:`kramers_uniform_depth`.

    Returns
    -------
    float or array, s

    Examples
    --------
    >>> t = kramers_uniform_residence_time(2.0, 62 / 3600 / 1500, 0.2, 3 * np.pi / 30,
    ...                                    np.radians(1), np.radians(35))
    >>> round(float(t / 60), 1)
    19.9

    References
    ----------
    Kramers, H., Croockewit, P. (1952) Chem. Eng. Sci. 1, 259; Saeman, W. C. (1951) Chem. Eng.
    Prog. 47, 508; Scott, W. J. (1986) PhD thesis, Edinburgh, eqs. 2.10, 2.17-2.18.
    """
    check_positive("length", length, "m")
    h = kramers_uniform_depth(q, radius, speed, slope, repose)
    radius = np.asarray(radius, dtype=float)
    q = np.asarray(q, dtype=float)
    theta = np.arccos(1.0 - h / radius)
    area = np.pi * radius**2 * fill_from_half_angle(theta)
    thin = np.sin(repose) / (np.asarray(speed) * radius * np.tan(slope))  # lim A/q at q -> 0
    with np.errstate(invalid="ignore", divide="ignore"):
        per_length = np.where(q > 0, area / q, thin)
    return np.asarray(length) * per_length


def kramers_dimensionless_flow(q, radius, speed, slope, repose):
    r"""Kramers & Croockewit's flow number :math:`N_q = q\sin\alpha/(\omega R^3\tan\psi)` (2.17).

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric solids flow, >= 0.
    radius : float or array, m
        Drum inner radius, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Drum slope, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2) and above the slope.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(kramers_dimensionless_flow(1e-5, 0.1, 1.0, 0.02, 0.7)), 4)
    0.3221

    References
    ----------
    Kramers, H., Croockewit, P. (1952) Chem. Eng. Sci. 1, 259; Saeman, W. C. (1951) Chem. Eng.
    Prog. 47, 508; Scott, W. J. (1986) PhD thesis, Edinburgh, eqs. 2.10, 2.17-2.18.
    """
    check_nonnegative("q", q, "m3/s")
    check_positive("radius", radius, "m")
    check_positive("speed", speed, "rad/s")
    check_positive("slope", slope, "rad")
    check_slope_and_repose(slope, repose, field="repose")
    return q * np.sin(repose) / (speed * np.asarray(radius) ** 3 * np.tan(slope))


def kramers_dimensionless_length(length, radius, slope, repose):
    r"""Kramers & Croockewit's length number :math:`N_L = R\cos\alpha/(L\tan\psi)` (2.18).

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    radius : float or array, m
        Drum inner radius, > 0.
    slope : float or array, rad
        Drum slope, > 0.
    repose : float or array, rad
        Dynamic angle of repose, in (0, pi/2) and above the slope.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(kramers_dimensionless_length(1.78, 0.0985, np.radians(1), np.radians(40))), 3)
    2.429

    References
    ----------
    Kramers, H., Croockewit, P. (1952) Chem. Eng. Sci. 1, 259; Saeman, W. C. (1951) Chem. Eng.
    Prog. 47, 508; Scott, W. J. (1986) PhD thesis, Edinburgh, eqs. 2.10, 2.17-2.18.
    """
    check_positive("length", length, "m")
    check_positive("radius", radius, "m")
    check_positive("slope", slope, "rad")
    check_slope_and_repose(slope, repose, field="repose")
    return np.asarray(radius) * np.cos(repose) / (np.asarray(length) * np.tan(slope))


def kramers_profile(
    feed,
    *,
    length,
    radius,
    speed,
    slope,
    repose,
    density=None,
    dam_height=None,
    n_points=1000,
):
    r"""Axial bed-depth profile by the Kramers-Croockewit / Saeman equation.

    Parameters
    ----------
    feed : float, callable or table
        Mass flow in kg/s if ``density`` is given, else volumetric flow in m3/s; may vary
        along z (e.g. mass loss by reaction).
    length : float, m
    radius : float, callable or table, m
    speed : float, rad/s
    slope : float, rad
    repose : float, callable or table, rad
        Dynamic angle of repose.
    density : float, kg/m3, optional
        Bulk density (constant).
    dam_height : float, m, optional
        Height of the discharge dam above the wall, < radius. None or 0: open end (h = 0).
    n_points : int
        Number of output points, uniformly spaced from the feed to the discharge end.

    Returns
    -------
    BedProfile

    Raises
    ------
    InputError
        Dam at or above the drum radius, angle of repose below the slope, or a feed the drum
        cannot carry (the bed would fill the drum before the feed end).

    Examples
    --------
    >>> p = kramers_profile(62 / 3600, density=1500, length=2.0, radius=0.2,
    ...     speed=3 * np.pi / 30, slope=np.radians(1), repose=np.radians(35))
    >>> round(100 * float(p.fill[0]), 2), round(p.mean_residence_time / 60, 1)
    (4.75, 13.0)

    References
    ----------
    Kramers, H., Croockewit, P. (1952) Chem. Eng. Sci. 1, 259; Saeman, W. C. (1951) Chem. Eng.
    Prog. 47, 508; Scott, W. J. (1986) PhD thesis, Edinburgh, eqs. 2.10, 2.17-2.18.
    """
    check_positive("length", length, "m")
    check_positive("speed", speed, "rad/s")
    if density is not None:
        check_positive("density", density, "kg/m3")
    f_r, const_r = as_axial_function("radius", radius)
    f_a, const_a = as_axial_function("repose", repose)
    f_q, const_q = as_axial_function("feed", feed)
    scale = 1.0 / float(density) if density is not None else 1.0
    z = np.linspace(0.0, float(length), int(n_points))
    r_z = f_r(z)
    a_z = f_a(z)
    q_z = f_q(z) * scale
    check_positive("radius", r_z, "m")
    check_slope_and_repose(slope, a_z, "dynamic_angle_of_repose")
    if np.any(~np.isfinite(q_z)) or np.any(q_z <= 0):
        raise InputError("feed", float(np.min(q_z)), "> 0")
    r_dis = float(r_z[-1])
    h0 = 0.0
    if dam_height:
        dam_radius_from_height(float(dam_height), r_dis, "dam")
        h0 = float(dam_height)
    warn_speed(speed, float(np.min(r_z)), SOURCE)
    x = float(length) - z
    h_inf = None
    if const_r and const_a and const_q:
        h, h_inf = _profile_constant(
            x, h0, float(q_z[0]), r_dis, float(speed), float(slope), float(a_z[0])
        )
    else:
        h = _profile_variable(x, h0, f_q, f_r, f_a, scale, float(length), float(speed), slope)
    hr = np.clip(h / r_z, 0.0, 2.0)
    theta = np.arccos(1.0 - hr)
    fill = fill_from_half_angle(theta)
    area = np.pi * r_z**2 * fill
    dz = np.diff(z)
    vol = np.concatenate([[0.0], np.cumsum(0.5 * (area[1:] + area[:-1]) * dz)])
    aq = area / q_z
    t = np.concatenate([[0.0], np.cumsum(0.5 * (aq[1:] + aq[:-1]) * dz)])
    drum = np.trapezoid(np.pi * r_z**2, z)
    if np.max(fill) > 0.5:
        warnings.warn(
            f"fill up to {100 * np.max(fill):.1f} % is above the 50 % for which the Kramers "
            "equation holds",
            OutOfRangeWarning,
            stacklevel=2,
        )
    region = np.zeros(z.size, dtype=np.int8)
    if h_inf is not None:
        region[np.abs(h - h_inf) <= 1e-3 * h_inf] = 1
    return BedProfile(
        model="kramers",
        z=z,
        depth=h,
        radius=r_z,
        half_angle=theta,
        fill=fill,
        bed_area=area,
        residence_time=t,
        region=region,
        length=float(length),
        volumetric_flow=float(q_z[0]),
        holdup_volume=float(vol[-1]),
        mean_fill=float(vol[-1] / drum),
        mean_residence_time=float(t[-1]),
        density=None if density is None else float(density),
        discharge_radius=r_dis - h0,
        limiting_depth=h_inf,
        info={"fraction_of_critical": float(speed / critical_speed(r_dis))},
    )


def _no_steady(q, where):
    return InputError(
        "feed",
        f"{q:.6g} m3/s",
        f"carried by this drum: the bed fills the drum {where:.4g} m from the discharge "
        "(no steady solution)",
    )


def _profile_constant(x, h0, q, radius, omega, slope, repose):
    """Constant properties: x(h) by quadrature (vectorised), then h(x) by interpolation."""
    k, c = _kc(q, radius, omega, slope, repose)
    length = float(x[0])

    def dxdh(h):
        hr = h / radius
        p = np.power(np.maximum(hr * (2.0 - hr), 0.0), 1.5)
        return p / (k - c * p)

    h_inf = None
    if c > 0 and k <= c:
        h_inf = radius * (1.0 - np.sqrt(1.0 - (k / c) ** (2.0 / 3.0)))
    if h_inf is not None and abs(h0 - h_inf) <= 1e-12 * radius:
        return np.full(x.size, h_inf), h_inf
    if h_inf is not None:
        res = march(dxdh, h0, length, y_target=h_inf)
    else:
        res = march(dxdh, h0, length, y_cap=2.0 * radius * (1.0 - 1e-9))
        if not res.reached:
            raise _no_steady(q, float(res.x[-1]))
    inside = x <= res.x[-1]
    h = np.full(x.size, np.nan if h_inf is None else h_inf)
    h[inside] = res.y_at(x[inside])
    return h, None if h_inf is None else float(h_inf)


def _profile_variable(x_out, h0, f_q, f_r, f_a, scale, length, omega, slope):
    """Varying properties: integrate w = h^(5/2) upstream with an adaptive RK (solve_ivp)."""
    tps = np.tan(slope)

    def rhs(x, w):
        z = length - x
        r = float(f_r(z))
        a = float(f_a(z))
        q = float(f_q(z)) * scale
        h = max(w[0], 0.0) ** 0.4
        k, _ = _kc(q, r, omega, slope, a)
        hr = min(h / r, 2.0 - 1e-12)
        return [2.5 * (k * r**1.5 * (2.0 - hr) ** -1.5 - tps / np.cos(a) * h**1.5)]

    def full(x, w):
        r = float(f_r(length - x))
        return max(w[0], 0.0) ** 0.4 - 2.0 * r * (1.0 - 1e-6)

    full.terminal = True
    sol = solve_ivp(
        rhs,
        (0.0, length),
        [h0**2.5],
        t_eval=x_out[::-1],
        events=full,
        rtol=1e-9,
        atol=1e-14 * max(h0, 1e-3) ** 2.5,
        method="LSODA",
    )
    if sol.status == 1:
        q_feed = float(f_q(0.0)) * scale
        raise _no_steady(q_feed, float(sol.t_events[0][0]))
    return np.maximum(sol.y[0][::-1], 0.0) ** 0.4
