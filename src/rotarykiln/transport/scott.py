r"""Scott's (1986) model of solids transport in rotating drums, with dams and internal weirs.

The axial velocity of a particle path of radius :math:`r` is its advance per cascade over its
cycle time, the time locked in the bed plus an explicit cascade time (no fitted constant):

.. math::

    q = Y\,I(\theta_x)\,\frac{\tan\beta}{1+\tan^2\beta}\left(1 + \frac{C}{\tan\beta}\right),
    \quad I = \int_b^{R} \frac{r^2\theta_r\sin\theta_r}{2\theta_r + \omega t_c(r)}\,dr,
    \quad Y = 4\omega\cot\alpha_d,\quad C = \frac{\tan\psi}{\cos\alpha_d}

with :math:`\theta_r = \arccos(b/r)`, :math:`b = R\cos\theta_x` and the cascade time
:math:`t_c = \sqrt{2c/(g(\sin\alpha_d - \mu\cos\alpha_d))}` over the chord
:math:`c = 2\sqrt{r^2-b^2}` (eqs. 3.4-3.8, 3.26). The quadratic (3.8) is solved for the surface
slope (negative root, 3.9) and :math:`d\theta_x/dx = \tan\beta/(R\sin\theta_x)` (3.10) is marched
from the discharge (x = 0) towards the feed. Discharge condition: the bed collapses at the static
angle, :math:`\beta = E = \alpha_s - \psi`, through the opening radius :math:`R_c` (3.40).
Inclined drums reach a limiting (uniform) filling :math:`I = q/(YC)` (3.42); behind a dam that
is higher than the limiting depth the surface is a horizontal pool of length
:math:`(H_d - H_{lim})/\tan\psi` (3.43, printed with "x tan psi", corrected). Internal weirs split
the drum into sections (3.7).

Internally every function works with the *capacity*
:math:`\Phi(b) = q\,(1+\tan^2\beta)/(\tan\beta + C)`, which is :math:`Y I` for Scott's
segregated paths, :math:`2\omega\cot\alpha_d\,\sqrt{R^2-b^2}\,I'` for the fixed-path variant
(3.29-3.31), and :math:`Y B (R^2-b^2)^{3/2}/6` without cascade time (Hogg's B, Saeman for B = 1).

Reference: W. J. Scott, *The transport of solids in rotating drums*, PhD thesis, University of
Edinburgh, 1986, chapter 3 (seed 001). Validated range: unflighted drums, below half the
critical speed, fill up to 50 %.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from rotarykiln.errors import (
    InputError,
    OutOfRangeWarning,
    check_nonnegative,
    check_positive,
    check_range,
)
from rotarykiln.geometry import bed_area, fill_from_half_angle
from rotarykiln.transport._common import (
    G,
    check_slope_and_repose,
    critical_speed,
    march,
    warn_speed,
)
from rotarykiln.transport.result import BedProfile
from rotarykiln.transport.weirs import Weir

__all__ = [
    "ScottParameters",
    "bachmann_dynamic_angle",
    "scott_cascade_time",
    "scott_discharge_half_angle",
    "scott_flow_integral",
    "scott_friction_coefficient",
    "scott_limiting_half_angle",
    "scott_profile",
    "scott_surface_slope",
]

SOURCE = "Scott (1986)"
_GL_X, _GL_W = np.polynomial.legendre.leggauss(32)
_U = 0.5 * (_GL_X + 1.0)  # nodes on [0, 1]
_WU = 0.5 * _GL_W


def scott_friction_coefficient(law, alpha_d, alpha_s=None):
    r"""Surface friction coefficient of the cascading layer, :math:`\mu`.

    Laws compared by Scott (eqs. 3.22-3.25): ``"zero"`` (:math:`\mu = 0`), ``"dynamic"``
    (:math:`\tan\alpha_d/3.5`), ``"static"`` (:math:`\tan\alpha_s/3.5`, the adopted law and the
    default) and ``"coulomb"`` (:math:`\tan\alpha_d`, rejected: the particles would never move).
    A float is taken as the value of :math:`\mu` itself. The factor 1/3.5 = 2/7 is the
    slip-to-roll transition of a sphere on an incline.

    Parameters
    ----------
    law : str or float, -
        Name of the law, or the value of :math:`\mu` itself (>= 0).
    alpha_d : float, rad
        Dynamic angle of repose, in (0, pi/2).
    alpha_s : float, rad
        Static angle of repose, in (0, pi/2) (needed for ``"static"``).

    Returns
    -------
    float, -

    Examples
    --------
    >>> round(scott_friction_coefficient("static", 0.5, np.radians(24.5)), 4)
    0.1302

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 3.
    """
    if isinstance(law, int | float) and not isinstance(law, bool):
        check_nonnegative("friction", law)
        return float(law)
    check_range("alpha_d", alpha_d, 0.0, np.pi / 2, unit="rad")
    if law == "zero":
        return 0.0
    if law == "dynamic":
        return float(np.tan(alpha_d) / 3.5)
    if law == "static":
        if alpha_s is None:
            raise InputError("static_angle_of_repose", None, "given for the 'static' law")
        check_range("alpha_s", alpha_s, 0.0, np.pi / 2, unit="rad")
        return float(np.tan(alpha_s) / 3.5)
    if law == "coulomb":
        return float(np.tan(alpha_d))
    raise InputError("friction", law, "one of zero, dynamic, static, coulomb or a number")


def bachmann_dynamic_angle(alpha_s, omega, radius):
    r"""Bachmann's dynamic angle of repose, :math:`\alpha_d = \alpha_s + \omega/\omega_c` (rad).

    Eq. 3.32 of Scott (1986), angles in radians. Reasonable only up to about 5 % of the
    critical speed; it over-predicts beyond (Scott uses it to explain the rise of the filling
    at high speed, Table A4.11).

    Parameters
    ----------
    alpha_s : float or array, rad
        Static angle of repose, in (0, pi/2).
    omega : float or array, rad/s
        Rotation rate, >= 0.
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, rad

    Examples
    --------
    >>> round(float(np.degrees(bachmann_dynamic_angle(np.radians(35), 0.5 * 15.66, 0.04))), 2)
    63.65

    References
    ----------
    Bachmann (1940), as given by Scott, W. J. (1986) The transport of solids in rotating drums, PhD
    thesis, Edinburgh, ch. 3. (eq. 3.32)
    """
    check_range("alpha_s", alpha_s, 0.0, np.pi / 2, unit="rad")
    check_nonnegative("omega", omega, "rad/s")
    check_positive("radius", radius, "m")
    return np.asarray(alpha_s, dtype=float) + np.asarray(omega, dtype=float) / critical_speed(
        radius
    )


def scott_cascade_time(chord, alpha_d, mu):
    r"""Time to slide from rest down a cascade chord, :math:`t_c = \sqrt{2c/(g(\sin\alpha_d -
    \mu\cos\alpha_d))}` (eq. 3.21/3.26), s.

    Parameters
    ----------
    chord : float or array, m
        Transverse cascade length :math:`c`, >= 0.
    alpha_d : float, rad
        Dynamic angle of repose, in (0, pi/2).
    mu : float, -
        Surface friction coefficient, in [0, tan(alpha_d)).

    Returns
    -------
    float or array, s

    Examples
    --------
    >>> round(float(scott_cascade_time(0.05, np.radians(28), 0.1302)), 4)
    0.1696

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 3.
    """
    check_nonnegative("chord", chord, "m")
    _check_angle_and_friction(alpha_d, mu)
    k = np.sin(alpha_d) - mu * np.cos(alpha_d)
    return np.sqrt(2.0 * np.asarray(chord, dtype=float) / (G * k))


def _check_angle_and_friction(alpha_d, mu):
    check_range("alpha_d", alpha_d, 0.0, np.pi / 2, unit="rad")
    check_nonnegative("mu", mu)
    if np.sin(alpha_d) - mu * np.cos(alpha_d) <= 0:
        raise InputError("mu", f"{mu:.6g}", f"< tan(alpha_d) = {np.tan(alpha_d):.6g}")


@dataclass(frozen=True)
class ScottParameters:
    """Operating constants of Scott's model (SI).

    ``path``: ``"segregated"`` (Scott) or ``"fixed"`` (Mu & Perlmutter's half-chord, 3.27-3.31).
    ``cascade``: ``"rest"`` (start from rest, 3.21, Scott), ``"initial_velocity"`` (Mu &
    Perlmutter's impact velocity, 3.11-3.19) or ``"none"`` (no cascade time; with ``hogg_b``
    this is Hogg's B-model, with B = 1 Saeman's kinematics).
    """

    omega: float
    alpha_d: float
    alpha_s: float
    slope: float
    mu: float
    path: str = "segregated"
    cascade: str = "rest"
    hogg_b: float = 1.0

    @property
    def k(self) -> float:
        return float(np.sin(self.alpha_d) - self.mu * np.cos(self.alpha_d))

    @property
    def C(self) -> float:  # noqa: N802 - Scott's symbol
        return float(np.tan(self.slope) / np.cos(self.alpha_d))

    @property
    def cot(self) -> float:
        return float(1.0 / np.tan(self.alpha_d))


def _t_initial_velocity(r, theta_r, chord, p: ScottParameters):
    """Cascade time with Mu & Perlmutter's impact velocity (eqs. 3.11-3.19)."""
    a = p.alpha_d
    gam = np.pi - a - theta_r
    v = p.omega * r
    cg, sg = np.cos(gam), np.sin(gam)
    ta = np.tan(a)
    with np.errstate(divide="ignore", invalid="ignore"):
        t2 = (v / G) * np.sqrt(np.maximum(sg**2 + 4.0 * (cg**2 * ta**2 + ta * sg * cg), 0.0))
        vel = np.sqrt((v * cg) ** 2 + (G * t2) ** 2)
        delta = np.arctan2(2.0 * ta * cg + sg, cg)
    bq = vel * np.cos(delta - a)
    aq = 0.5 * G * p.k
    return (-bq + np.sqrt(bq * bq + 4.0 * aq * chord)) / (2.0 * aq)


def _safe_ratio(num, den):
    """num/den with 0 where den == 0 (the degenerate path r = b has zero weight)."""
    ok = den > 0
    return np.where(ok, num / np.where(ok, den, 1.0), 0.0)


def _capacity(b, r_up, p: ScottParameters):
    r"""Capacity :math:`\Phi(b)` (m3/s) for surface distance ``b`` and outer radius ``r_up``."""
    b = np.asarray(b, dtype=float)
    smax = np.sqrt(np.maximum(r_up * r_up - b * b, 0.0))
    if p.cascade == "none":
        if p.path == "fixed":
            raise InputError("variant", "fixed path without cascade time", "a defined variant")
        return 4.0 * p.omega * p.cot * p.hogg_b * smax**3 / 6.0
    s = smax[..., None] * _U**2  # s = half chord of the path, s = S u^2
    ds = 2.0 * smax[..., None] * _U
    bb = b[..., None]
    theta_r = np.arctan2(s, bb)
    if p.path == "fixed":
        tc = np.sqrt(2.0 * smax / (G * p.k))[..., None]
        integrand = _safe_ratio(theta_r * s, 2.0 * theta_r + p.omega * tc)
        i_fixed = np.sum(integrand * ds * _WU, axis=-1)
        return 2.0 * p.omega * p.cot * smax * i_fixed
    if p.cascade == "initial_velocity":
        r = np.sqrt(s * s + bb * bb)
        tc = _t_initial_velocity(r, theta_r, 2.0 * s, p)
    else:
        tc = np.sqrt(4.0 * s / (G * p.k))
    integrand = _safe_ratio(s * s * theta_r, 2.0 * theta_r + p.omega * tc)
    return 4.0 * p.omega * p.cot * p.hogg_b * np.sum(integrand * ds * _WU, axis=-1)


def scott_flow_integral(b, r_up, omega, alpha_d, mu):
    r"""Scott's flow integral :math:`I = \int_b^{R} r^2\theta_r\sin\theta_r/(2\theta_r +
    \omega t_c(r))\,dr` (eq. 3.5), m3.

    Evaluated with the half-chord :math:`s = \sqrt{r^2-b^2}` as variable
    (:math:`r^2\sin\theta_r\,dr = s^2\,ds`) and 32-point Gauss-Legendre in :math:`u = \sqrt{s/S}`.

    Parameters
    ----------
    b : float or array, m
        Distance from the drum axis to the bed surface, in [-r_up, r_up] (negative beyond half
        fill).
    r_up : float, m
        Outer radius (drum radius, or the opening radius of a constriction, 3.40), > 0.
    omega : float, rad/s
        Rotation rate, > 0.
    alpha_d : float, rad
        Dynamic angle of repose, in (0, pi/2).
    mu : float, -
        Surface friction coefficient, in [0, tan(alpha_d)).

    Returns
    -------
    float or array, m3

    Examples
    --------
    Without cascade time the integral is :math:`(R^2-b^2)^{3/2}/6`; with it, smaller:

    >>> i = scott_flow_integral(0.03, 0.0465, 4.03, np.radians(28), 0.13)
    >>> round(float(i / ((0.0465**2 - 0.03**2) ** 1.5 / 6)), 3)
    0.667

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 3.
    """
    check_positive("r_up", r_up, "m")
    check_range("b", np.asarray(b) / r_up, -1.0, 1.0, closed_low=True, closed_high=True)
    check_positive("omega", omega, "rad/s")
    _check_angle_and_friction(alpha_d, mu)
    p = ScottParameters(omega, alpha_d, alpha_d, 0.0, mu)
    return _capacity(b, r_up, p) / (4.0 * omega / np.tan(alpha_d))


def _tan_beta(phi, q, C):
    """Negative root of q(1+t^2) = phi (t + C), cancellation-free; NaN when none is real."""
    a = phi / (2.0 * q)
    disc = a * a - 1.0 + 2.0 * a * C
    with np.errstate(invalid="ignore", divide="ignore"):
        root = np.sqrt(np.where(disc >= 0, disc, np.nan))
        return (1.0 - 2.0 * a * C) / (a + root)


def scott_surface_slope(theta, q, radius, params: ScottParameters):
    r"""Tangent of the axial slope of the bed surface, :math:`\tan\beta = dh/dx` (eq. 3.9).

    Parameters
    ----------
    theta : float or array, rad
        Filling half-angle, in [0, pi].
    q : float, m3/s
        Volumetric flow, >= 0 (at zero flow the level-bed value :math:`-C` is returned).
    radius : float, m
        Drum inner radius, > 0.
    params : ScottParameters
        Operating constants.

    Returns
    -------
    float or array, -
        :math:`\tan\beta`; NaN where the bed cannot carry ``q`` at any slope (a flag the
        profile integration relies on).

    Examples
    --------
    >>> p = ScottParameters(4.03, np.radians(28), np.radians(24.5), 0.0, 0.1302)
    >>> round(float(scott_surface_slope(np.radians(60), 1.9e-6, 0.0465, p)), 4)
    0.0082

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 3.
    """
    check_range("theta", theta, 0.0, np.pi, closed_low=True, closed_high=True, unit="rad")
    check_nonnegative("q", q, "m3/s")
    check_positive("radius", radius, "m")
    b = radius * np.cos(theta)
    if q == 0:  # q (1 + t^2) = phi (t + C) -> t = -C, the limit of the root below
        return np.full(np.shape(b), -params.C)[()]
    return _tan_beta(_capacity(b, radius, params), q, params.C)


def _solve_b(target, r_up, p: ScottParameters, what: str, q: float):
    """Solve capacity(b; r_up) = target for b in [0, r_up]."""
    phi0 = float(_capacity(0.0, r_up, p))
    if phi0 < target:
        q_max = q * phi0 / target
        raise InputError(
            "feed",
            f"{q:.6g} m3/s",
            f"<= {q_max:.6g} m3/s, the most the {what} (radius {r_up:.6g} m) can pass at this "
            "speed: no steady solution",
        )
    if target <= 0:
        return float(r_up)
    return brentq(
        lambda b: float(_capacity(b, r_up, p)) - target, 0.0, r_up, xtol=1e-15, rtol=1e-13
    )


def scott_discharge_half_angle(q, radius, opening_radius, params: ScottParameters):
    r"""Filling half-angle at a discharge constriction (or internal weir), eq. 3.40-3.41, rad.

    The bed collapses over the lip at the static angle: :math:`\beta = E = \alpha_s - \psi`;
    (3.40) with upper limit :math:`R_c` is solved for :math:`b`, then
    :math:`\theta_x(0) = \arccos(b/R)`. At zero feed the surface is tangent to the opening.

    Parameters
    ----------
    q : float, m3/s
        Volumetric flow, >= 0.
    radius : float, m
        Drum radius, > 0.
    opening_radius : float, m
        Opening radius :math:`R_c`, in (0, radius] (= ``radius`` for an open end).
    params : ScottParameters
        Operating constants.

    Returns
    -------
    float, rad

    Raises
    ------
    InputError
        When the opening cannot pass ``q`` with a bed below its axis (no steady solution).

    Examples
    --------
    Zero feed through a 0.037 m opening of a 0.0465 m drum: 5.37 % filling (Table A4.7):

    >>> p = ScottParameters(4.07, np.radians(24.2), np.radians(24.5), 0.0, 0.1302)
    >>> th = scott_discharge_half_angle(0.0, 0.0465, 0.037, p)
    >>> round(100 * float(fill_from_half_angle(th)), 2)
    5.37

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 3.
    """
    check_nonnegative("q", q, "m3/s")
    check_positive("radius", radius, "m")
    check_range("opening_radius", opening_radius, 0.0, radius, closed_high=True, unit="m")
    e = params.alpha_s - params.slope
    if e <= 0:
        raise InputError(
            "static_angle_of_repose",
            f"{np.degrees(params.alpha_s):.6g} deg",
            f"> the slope ({np.degrees(params.slope):.6g} deg)",
        )
    te = np.tan(e)
    target = q * (1.0 + te * te) / (te + params.C)
    b = _solve_b(target, opening_radius, params, "discharge opening", q)
    return float(np.arccos(np.clip(b / radius, -1.0, 1.0)))


def scott_limiting_half_angle(q, radius, params: ScottParameters):
    r"""Limiting (uniform) filling half-angle of an inclined drum, :math:`I = q/(YC)` (3.42).

    Returns None for a horizontal drum, or when no uniform bed up to a nearly full drum
    can carry ``q``.

    Parameters
    ----------
    q : float, m3/s
        Volumetric flow, >= 0.
    radius : float, m
        Drum inner radius, > 0.
    params : ScottParameters
        Operating constants.

    Returns
    -------
    float or None, rad

    Examples
    --------
    >>> p = ScottParameters(3.61, np.radians(28), np.radians(24.5), np.radians(2), 0.1302)
    >>> round(100 * float(fill_from_half_angle(scott_limiting_half_angle(3e-6, 0.0465, p))), 2)
    6.29

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 3.
    """
    check_nonnegative("q", q, "m3/s")
    check_positive("radius", radius, "m")
    C = params.C
    if C <= 0:
        return None
    target = q / C
    if target <= 0:
        return 0.0
    phi0 = float(_capacity(0.0, radius, params))
    if phi0 >= target:
        b = brentq(
            lambda b: float(_capacity(b, radius, params)) - target,
            0.0,
            radius,
            xtol=1e-15,
            rtol=1e-13,
        )
        return float(np.arccos(b / radius))
    res = minimize_scalar(
        lambda b: -float(_capacity(b, radius, params)),
        bounds=(-0.999 * radius, 0.0),
        method="bounded",
    )
    if -res.fun < target:
        return None
    b = brentq(
        lambda b: float(_capacity(b, radius, params)) - target, res.x, 0.0, xtol=1e-15, rtol=1e-13
    )
    return float(np.arccos(b / radius))


def _section(theta0, x0, x1, q, radius, p: ScottParameters, theta_lim, saturate=False):
    """March one section from x0 (downstream end) to x1; return x, theta, region arrays."""
    length = x1 - x0
    if saturate and theta0 >= np.pi / 2:
        return np.array([x0, x1]), np.full(2, np.pi / 2), np.full(2, 3, dtype=np.int8)
    if saturate and (theta_lim is None or theta_lim > np.pi / 2):
        theta_lim = None
    if theta_lim is not None and theta0 >= theta_lim * (1.0 - 1e-12):
        # pool behind the constriction: horizontal surface, depth falls by tan(psi) per metre
        h0 = radius * (1.0 - np.cos(theta0))
        h_lim = radius * (1.0 - np.cos(theta_lim))
        tp = np.tan(p.slope)
        x_pool = (h0 - h_lim) / tp
        xp = np.linspace(0.0, min(x_pool, length), 129)
        h = h0 - xp * tp
        th = np.arccos(np.clip(1.0 - h / radius, -1.0, 1.0))
        reg = np.full(xp.size, 2, dtype=np.int8)
        if x_pool < length:
            xp = np.append(xp, length)
            th = np.append(th, theta_lim)
            reg = np.append(reg, np.int8(1))
        return x0 + xp, th, reg

    if q == 0.0:  # no flow, horizontal drum: the bed surface is flat at the discharge level
        return np.array([x0, x1]), np.array([theta0, theta0]), np.zeros(2, dtype=np.int8)

    def dxdy(theta):
        tb = _tan_beta(_capacity(radius * np.cos(theta), radius, p), q, p.C)
        return radius * np.sin(theta) / tb

    if theta_lim is not None:
        res = march(dxdy, theta0, length, y_target=theta_lim)
    else:
        res = march(dxdy, theta0, length, y_cap=np.pi / 2 if saturate else np.pi * (1.0 - 1e-9))
    reg = np.zeros(res.x.size, dtype=np.int8)
    x, th = res.x, res.y
    if not res.reached and saturate and theta_lim is None and th[-1] >= np.pi / 2 * (1 - 1e-9):
        x = np.append(x, length)
        th = np.append(th, np.pi / 2)
        reg = np.append(reg, np.int8(3))
        reg[-2] = 3
    elif not res.reached:
        if theta_lim is None:
            raise InputError(
                "feed",
                f"{q:.6g} m3/s",
                "carried by this drum: the bed fills the drum "
                f"{x0 + float(x[-1]):.4g} m from the discharge (no steady solution)",
            )
        x = np.append(x, length)
        th = np.append(th, theta_lim)
        reg = np.append(reg, np.int8(1))
        reg[-2] = 1
    return x0 + x, th, reg


def scott_profile(
    feed,
    *,
    length,
    radius,
    speed,
    slope,
    dynamic_angle,
    static_angle,
    density=None,
    discharge_radius=None,
    weirs=(),
    friction="static",
    path="segregated",
    cascade="rest",
    hogg_b=1.0,
    beyond_half="extend",
    n_points=201,
):
    r"""Axial bed profile, hold-up and residence time by Scott's model (1986, chapter 3).

    Parameters
    ----------
    feed : float, kg/s or m3/s
        Mass flow in kg/s if ``density`` is given, else volumetric flow in m3/s; >= 0.
    length : float, m
        Drum length, > 0.
    radius : float, m
        Drum inner radius :math:`R_d`, > 0.
    speed : float, rad/s
        Angular speed :math:`\omega`, > 0.
    slope : float, rad
        Drum inclination :math:`\psi`, down towards the discharge.
    dynamic_angle, static_angle : float, rad
        :math:`\alpha_d`, :math:`\alpha_s`.
    density : float, kg/m3, optional
        Bulk density.
    discharge_radius : float, m, optional
        Opening radius of the discharge dam :math:`R_c` (None: open end).
    weirs : sequence of :class:`~rotarykiln.transport.weirs.Weir`
        Internal weirs, positions measured from the discharge end.
    friction : str or float
        Surface friction law, see :func:`scott_friction_coefficient` (default ``"static"``).
    path : {"segregated", "fixed"}
        Particle path model.
    cascade : {"rest", "initial_velocity", "none"}
        Cascade-time model.
    hogg_b : float, -
        Hogg's ratio B used with ``cascade="none"``.
    beyond_half : {"extend", "saturate"}
        What happens when the bed reaches half fill. ``"extend"`` (default) continues with the
        surface below the axis (paths with :math:`r < |b|` form a dead core) and warns;
        ``"saturate"`` holds the local fill at 50 %, as Scott's program evidently did (the
        thesis restricts :math:`\theta_x \le \pi/2`; Table A4.16 saturates near 49.9 %).
    n_points : int
        Approximate number of output points along the drum.

    Returns
    -------
    BedProfile

    Raises
    ------
    InputError
        A dam opening outside (0, R] (a dam at or above the drum radius), an angle of repose
        below the slope, friction that stops the cascade, or a feed the drum cannot carry
        (no steady solution).

    Notes
    -----
    Warns (OutOfRangeWarning) above half the critical speed and for fills above 50 %.

    Examples
    --------
    Scott's check value (Table A4.7 upper curve, thesis model 20.50 %):

    >>> prof = scott_profile(0.00337, density=1780, length=0.216, radius=0.0465,
    ...     speed=38.5 * np.pi / 30, slope=0.0, dynamic_angle=np.radians(28),
    ...     static_angle=np.radians(24.5), discharge_radius=0.0262)
    >>> round(100 * prof.mean_fill, 1)
    20.3

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh.
    """
    check_positive("length", length, "m")
    check_positive("radius", radius, "m")
    check_positive("speed", speed, "rad/s")
    check_slope_and_repose(slope, dynamic_angle, "dynamic_angle_of_repose")
    check_slope_and_repose(slope, static_angle, "static_angle_of_repose")
    if density is not None:
        check_positive("density", density, "kg/m3")
        q = float(feed) / float(density)
    else:
        q = float(feed)
    if not np.isfinite(q) or q < 0:
        raise InputError("feed", feed, ">= 0")
    r_c = radius if discharge_radius is None else float(discharge_radius)
    if not (0 < r_c <= radius):
        raise InputError(
            "dam",
            f"opening radius {r_c:.6g} m",
            f"in (0, {radius:.6g}] m: a dam must be lower than the drum radius",
        )
    mu = scott_friction_coefficient(friction, dynamic_angle, static_angle)
    if np.sin(dynamic_angle) - mu * np.cos(dynamic_angle) <= 0:
        raise InputError(
            "friction",
            f"mu = {mu:.6g}",
            f"< tan(dynamic angle) = {np.tan(dynamic_angle):.6g} (the cascade would not move)",
        )
    if path not in ("segregated", "fixed"):
        raise InputError("path", path, "segregated or fixed")
    if beyond_half not in ("extend", "saturate"):
        raise InputError("beyond_half", beyond_half, "extend or saturate")
    if cascade not in ("rest", "initial_velocity", "none"):
        raise InputError("cascade", cascade, "rest, initial_velocity or none")
    weirs = sorted(
        (Weir(float(w.position), float(w.radius)) for w in weirs), key=lambda w: w.position
    )
    for w in weirs:
        if not (0 < w.position < length):
            raise InputError("weir.position", f"{w.position:.6g} m", f"in (0, {length:.6g}) m")
        if not (0 < w.radius <= radius):
            raise InputError("weir.radius", f"{w.radius:.6g} m", f"in (0, {radius:.6g}] m")
    warn_speed(speed, radius, SOURCE)
    p = ScottParameters(
        float(speed),
        float(dynamic_angle),
        float(static_angle),
        float(slope),
        mu,
        path,
        cascade,
        float(hogg_b),
    )
    theta_lim = scott_limiting_half_angle(q, radius, p)
    theta_start = scott_discharge_half_angle(q, radius, r_c, p)
    bounds = [0.0] + [w.position for w in weirs] + [float(length)]
    xs, ths, regs, sections = [], [], [], []
    for k in range(len(bounds) - 1):
        if k > 0:
            th_w = scott_discharge_half_angle(q, radius, weirs[k - 1].radius, p)
            theta_start = max(theta_start, th_w)
        x, th, reg = _section(
            theta_start,
            bounds[k],
            bounds[k + 1],
            q,
            radius,
            p,
            theta_lim,
            beyond_half == "saturate",
        )
        fc = fill_from_half_angle(np.clip(th, 0.0, np.pi))
        sections.append((bounds[k], bounds[k + 1], float(np.trapezoid(fc, x) / (x[-1] - x[0]))))
        xs.append(x)
        ths.append(th)
        regs.append(reg)
        theta_start = float(th[-1])
    profile = _assemble(xs, ths, regs, q, float(length), float(radius), n_points)
    mean_fill = sum((b - a) * f for a, b, f in sections) / float(length)
    if np.max(profile["fill"]) > 0.5:
        warnings.warn(
            f"fill up to {100 * np.max(profile['fill']):.1f} % is above the 50 % validated by "
            f"{SOURCE}",
            OutOfRangeWarning,
            stacklevel=2,
        )
    volume = mean_fill * np.pi * radius**2 * length
    name = "scott"
    if (friction, path, cascade) != ("static", "segregated", "rest"):
        name += f" ({friction} friction, {path} path, cascade {cascade})"
    return BedProfile(
        model=name,
        length=float(length),
        volumetric_flow=q,
        holdup_volume=float(volume),
        mean_fill=float(mean_fill),
        mean_residence_time=float(volume / q) if q > 0 else float("inf"),
        density=None if density is None else float(density),
        discharge_radius=float(r_c),
        weirs=tuple((w.position, w.radius) for w in weirs),
        section_fills=tuple(sections),
        limiting_depth=None if theta_lim is None else float(radius * (1 - np.cos(theta_lim))),
        info={"friction_coefficient": mu, "fraction_of_critical": speed / critical_speed(radius)},
        **profile,
    )


def _assemble(xs, ths, regs, q, length, radius, n_points):
    """Resample section results onto about ``n_points`` points, ordered from the feed end."""
    out_x, out_th, out_reg = [], [], []
    for x, th, reg in zip(xs, ths, regs, strict=True):
        n = max(int(round(n_points * (x[-1] - x[0]) / length)), 3)
        xg = np.linspace(x[0], x[-1], n)
        xu, idx = np.unique(x, return_index=True)
        out_x.append(xg)
        out_th.append(np.interp(xg, xu, th[idx]))
        out_reg.append(reg[idx][np.clip(np.searchsorted(xu, xg, side="left"), 0, xu.size - 1)])
    x = np.concatenate(out_x)[::-1]
    th = np.clip(np.concatenate(out_th)[::-1], 0.0, np.pi)
    reg = np.concatenate(out_reg)[::-1]
    z = length - x
    area = bed_area(th, radius)
    seg = np.diff(z)
    t = (
        np.concatenate([[0.0], np.cumsum(0.5 * (area[1:] + area[:-1]) * seg)]) / q
        if q > 0
        else (np.full(z.size, np.inf))
    )
    return {
        "z": z,
        "depth": radius * (1.0 - np.cos(th)),
        "radius": np.full(z.size, radius),
        "half_angle": th,
        "fill": fill_from_half_angle(th),
        "bed_area": area,
        "residence_time": t,
        "region": reg,
    }
