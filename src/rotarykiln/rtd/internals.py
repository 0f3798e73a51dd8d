r"""Kiln internals that shape the RTD: lifters (flights) and annular exit dams.

Lifter hold-up (seed 003, sec. 4.1, after Debacq et al.): the solids held by one lifter are the
pocket bounded by the lifter, the kiln wall (radius R) and a free surface through the lifter tip
inclined at the angle of repose :math:`\beta` to the horizontal. In the frame of a lifter whose
root is at angular position :math:`\gamma` above the horizontal (3 o'clock = 0, rising side) and
which points radially inward with length :math:`h_1`:

- straight lifter (SL): the tip is at :math:`(R - h_1, 0)`;
- rectangular (L-shaped) lifter (RL): a second arm of length :math:`h_2` at a right angle,
  pointing in the direction of rotation, ends at the tip :math:`(R - h_1, h_2)`.

The pocket is the disc :math:`x^2+y^2 \le R^2` cut by the half-planes :math:`y \ge 0` (the radial
arm), :math:`x \ge R - h_1` (the second arm, RL) and "below the free surface": a line through the
tip at the angle :math:`\beta - \gamma` to the radial arm. Its area :math:`S` is computed by
clipping a fine polygon of the wall (relative error < 1e-8); the hold-up over a kiln of length L
is :math:`V = S L`. At the horizontal position this reproduces seed 003's
:math:`V_{SL} = 75.8` cm3 and :math:`V_{RL} = 242` cm3 for sand (beta = 39 deg, R = 0.05065 m,
h = 10 mm, L = 1.95 m); a straight lifter is empty from :math:`\gamma = \beta` on, consistent with
the observed end of discharge at 20-40 deg.

Loading-lifter area of the Bongo Njeng correlation (eq. 19): :math:`L_s = S(n_{lift} - 1)/2`.

Annular exit dam of height :math:`h_d`: blocked fraction of the outlet area
:math:`1 - ((R - h_d)/R)^2`.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError, check_positive, check_range

__all__ = [
    "exit_dam_blocked_fraction",
    "lifter_cross_section",
    "lifter_holdup",
    "loading_lifter_area",
]

_WALL_NODES = 20001  # nodes on the half wall circle used for clipping


def _clip(poly: np.ndarray, normal: np.ndarray, offset: float) -> np.ndarray:
    """Keep the part of the convex polygon where ``poly @ normal <= offset`` (Sutherland-Hodgman)."""
    if poly.shape[0] == 0:
        return poly
    d = poly @ normal - offset
    nxt = np.roll(poly, -1, axis=0)
    d_nxt = np.roll(d, -1)
    inside = d <= 0
    crosses = (d <= 0) != (d_nxt <= 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.where(crosses, d / np.where(crosses, d - d_nxt, 1.0), 0.0)
    cut = poly + w[:, None] * (nxt - poly)
    pts = np.stack([poly, cut], axis=1)  # for each edge: its start point, then its crossing
    keep = np.stack([inside, crosses], axis=1)
    return pts[keep]


def _polygon_area(poly: np.ndarray) -> float:
    if poly.shape[0] < 3:
        return 0.0
    x, y = poly[:, 0], poly[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def lifter_cross_section(radius, height, repose_angle, *, arm=0.0, position=0.0) -> float:
    r"""Cross-section of the solids held by one lifter (straight, or L-shaped when ``arm`` > 0).

    .. math::

        S = \left|\{x^2 + y^2 \le R^2,\ y \ge 0,\ x \ge R - h_1,\
            (y - h_2)\cos\phi \le (x - R + h_1)\sin\phi\}\right|, \quad \phi = \beta - \gamma

    Parameters
    ----------
    radius : float
        Kiln inner radius R [m].
    height : float
        Radial length of the lifter h_1 [m], < R.
    repose_angle : float
        Angle of repose of the solids beta [rad] (seed 003 uses the static angle).
    arm : float
        Length of the second (tangential) arm h_2 of an L-shaped lifter [m]; 0 for a straight one.
    position : float
        Angular position gamma of the lifter root above the horizontal on the rising side [rad]
        (0 = horizontal, where seed 003 evaluates the hold-up), in [-90, 90] deg.

    Returns
    -------
    float
        S [m2].

    Examples
    --------
    >>> import math
    >>> s = lifter_cross_section(0.05065, 0.010, math.radians(39))
    >>> round(s * 1e6, 2)  # mm2
    38.89

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565.
    """
    check_positive("radius", radius, "m")
    check_range("height", height, 0.0, radius, unit="m")
    check_range("repose_angle", repose_angle, 0.0, np.pi / 2, unit="rad")
    if not np.isfinite(arm) or arm < 0:
        raise InputError("arm", f"{arm} m", ">= 0")
    check_range("position", position, -np.pi / 2, np.pi / 2, closed_low=True, closed_high=True)
    phi = repose_angle - position
    a = np.linspace(-np.pi / 2, np.pi / 2, _WALL_NODES)  # the wall on the lifter's side
    poly = radius * np.column_stack([np.cos(a), np.sin(a)])
    tip = np.array([radius - height, arm])
    poly = _clip(poly, np.array([0.0, -1.0]), 0.0)  # above the radial arm
    poly = _clip(poly, np.array([-1.0, 0.0]), -(radius - height))  # beyond the lifter tip line
    # below the free surface through the tip, inclined at phi: n = (-sin phi, cos phi)
    n = np.array([-np.sin(phi), np.cos(phi)])
    poly = _clip(poly, n, float(n @ tip))
    return _polygon_area(poly)


def lifter_holdup(radius, height, repose_angle, length, *, arm=0.0, position=0.0) -> float:
    r"""Volume of solids held by one lifter running the whole kiln length, :math:`V = S L`.

    Parameters
    ----------
    radius : float
        Kiln inner radius [m].
    height : float
        Radial lifter length [m].
    repose_angle : float
        Angle of repose [rad].
    length : float
        Lifter (kiln) length [m].
    arm : float
        Second arm of an L-shaped (rectangular) lifter [m]; 0 for straight.
    position : float
        Angular position above the horizontal [rad].

    Returns
    -------
    float
        V [m3].

    Examples
    --------
    >>> import math
    >>> r, beta = 0.1013 / 2, math.radians(39)
    >>> round(lifter_holdup(r, 0.01, beta, 1.95) * 1e6, 1)  # straight, cm3
    75.8
    >>> round(lifter_holdup(r, 0.01, beta, 1.95, arm=0.01) * 1e6, 1)  # rectangular, cm3
    242.0

    References
    ----------
    Bongo Njeng et al. (2015) sec. 4.1.
    """
    check_positive("length", length, "m")
    return lifter_cross_section(radius, height, repose_angle, arm=arm, position=position) * length


def loading_lifter_area(n_lifters, lifter_area):
    r"""Area of solids in the loading lifters, seed 003 eq. 19: :math:`L_s = (n - 1) S / 2`.

    Parameters
    ----------
    n_lifters : int
        Number of lifters around the circumference (seed 003: 4).
    lifter_area : float
        Hold-up cross-section of one lifter at the horizontal, S [m2].

    Returns
    -------
    float
        Ls [m2].

    Examples
    --------
    >>> round(loading_lifter_area(4, 3.889e-5) * 1e6, 2)
    58.34

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565, eq. 19.
    """
    if not np.isfinite(n_lifters) or int(n_lifters) != n_lifters or n_lifters < 1:
        raise InputError("n_lifters", n_lifters, "an integer >= 1")
    if not np.isfinite(lifter_area) or lifter_area < 0:
        raise InputError("lifter_area", f"{lifter_area} m2", ">= 0")
    return (n_lifters - 1) / 2.0 * lifter_area


def exit_dam_blocked_fraction(dam_height, radius):
    r"""Fraction of the outlet area blocked by an annular exit dam: :math:`1 - ((R - h)/R)^2`.

    Parameters
    ----------
    dam_height : array_like
        Radial height of the ring h [m], in [0, R].
    radius : float
        Kiln inner radius R [m].

    Returns
    -------
    numpy.ndarray or float
        Blocked fraction [-].

    Examples
    --------
    >>> round(float(exit_dam_blocked_fraction(0.0135, 0.1013 / 2)), 3)  # seed 003: "< 45 %" no effect
    0.462

    References
    ----------
    Bongo Njeng, A. S. et al. (2015) Powder Technol. 269, 554-565.
    """
    check_positive("radius", radius, "m")
    check_range("dam_height", dam_height, 0.0, radius, closed_low=True, closed_high=True, unit="m")
    h = np.asarray(dam_height, dtype=float)
    return (1.0 - ((radius - h) / radius) ** 2)[()]
