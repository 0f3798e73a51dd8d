r"""Geometry of the partly filled cross-section of a rotating drum.

The bed occupies a circular segment of a drum of inner radius :math:`R`. Its free surface is a
chord that subtends the central angle :math:`2\theta` (``theta`` is the *half-angle*). With the
bed depth :math:`h` measured at the middle of the chord:

.. math::

    \theta = \arccos\frac{R - h}{R}, \qquad
    f = \frac{2\theta - \sin 2\theta}{2\pi} = \frac{\theta - \sin\theta\cos\theta}{\pi},

    A_{bed} = R^2(\theta - \sin\theta\cos\theta), \qquad L_c = 2R\sin\theta .

Seed 002 (Boateng, ch. 2) prints its eq. 2.3 with the arccos argument inverted,
:math:`\arccos(R/(R-h))`, which is undefined for :math:`0 < h < R`; the correct form above is
used (see docs/geometry.md).

All functions take and return SI floats or numpy arrays (radius and depth in m, angles in rad,
areas in m2) and broadcast over their arguments.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.errors import check_positive, check_range
from rotarykiln.tables import with_units

__all__ = [
    "CrossSection",
    "bed_area",
    "chord_from_half_angle",
    "covered_wall_arc",
    "depth_from_fill",
    "depth_from_half_angle",
    "exposed_bed_width",
    "exposed_wall_arc",
    "fill_from_depth",
    "fill_from_half_angle",
    "freeboard_area",
    "freeboard_hydraulic_diameter",
    "half_angle_from_chord",
    "half_angle_from_depth",
    "half_angle_from_fill",
]


def _x_minus_sin(x: np.ndarray) -> np.ndarray:
    """``x - sin(x)`` without cancellation for small ``x`` (series below 0.1)."""
    x = np.asarray(x, dtype=float)
    x2 = x * x
    series = x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0)))
    return np.where(np.abs(x) < 0.1, series, x - np.sin(x))


def fill_from_half_angle(theta):
    r"""Fractional fill of the cross-section from the half-angle of the bed.

    .. math:: f = \frac{2\theta - \sin 2\theta}{2\pi}

    Parameters
    ----------
    theta : float or array, rad
        Half of the central angle subtended by the bed surface, in [0, pi].

    Returns
    -------
    float or array, -
        Fill fraction in [0, 1].

    Examples
    --------
    >>> round(float(fill_from_half_angle(np.pi / 2)), 12)
    0.5

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    theta = np.asarray(theta, dtype=float)
    check_range("theta", theta, 0.0, np.pi, closed_low=True, closed_high=True, unit="rad")
    return _x_minus_sin(2.0 * theta) / (2.0 * np.pi)


def half_angle_from_fill(fill, *, tol: float = 1e-11, max_iter: int = 60):
    r"""Half-angle of the bed from the fill fraction (inverse of :func:`fill_from_half_angle`).

    Solves :math:`2\theta - \sin 2\theta = 2\pi f` by Newton's method safeguarded by a bracket
    (a bisection step is taken whenever Newton would leave the bracket). The problem is solved
    for :math:`f \le 1/2` and reflected, :math:`\theta(1-f) = \pi - \theta(f)`, which keeps the
    derivative :math:`2\sin^2\theta` away from zero at the far end.

    Parameters
    ----------
    fill : float or array, -
        Fill fraction in [0, 1].
    tol : float, -
        Relative step below which Newton's iteration stops.
    max_iter : int
        Most iterations.

    Returns
    -------
    float or array, rad
        Half-angle in [0, pi]; ``fill_from_half_angle`` of it equals ``fill`` to 1e-12.

    Examples
    --------
    >>> round(float(half_angle_from_fill(0.5)), 12) == round(np.pi / 2, 12)
    True
    >>> round(float(np.degrees(half_angle_from_fill(0.1))), 4)
    46.6031

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    fill = np.asarray(fill, dtype=float)
    check_range("fill", fill, 0.0, 1.0, closed_low=True, closed_high=True)
    f = np.minimum(fill, 1.0 - fill)
    target = 2.0 * np.pi * f
    # starting guess: small-angle series x^3/6 = target, clipped to the bracket
    lo = np.zeros_like(f)
    hi = np.full_like(f, np.pi)  # g is monotone on [0, pi]: the root pi/2 of f = 1/2 stays inside
    x = np.clip(np.cbrt(6.0 * target) / 2.0, 0.0, np.pi / 2)
    for _ in range(max_iter):
        g = _x_minus_sin(2.0 * x) - target
        lo = np.where(g < 0, x, lo)
        hi = np.where(g > 0, x, hi)
        dg = 2.0 * (1.0 - np.cos(2.0 * x))
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(dg > 0, g / dg, np.inf)
        x_new = x - step
        inside = (x_new >= lo) & (x_new <= hi) & np.isfinite(x_new)
        small = np.abs(step) <= tol * np.maximum(1.0, x)
        # outside the bracket: bisect, unless the step is round-off (collapsed bracket)
        x = np.where(inside, x_new, np.where(small, x, 0.5 * (lo + hi)))
        if np.all(small | (g == 0)):
            break
    # Newton converges quadratically: once the step is below ``tol`` one more step reaches
    # machine precision (a tighter stopping test would only chase round-off).
    g = _x_minus_sin(2.0 * x) - target
    dg = 2.0 * (1.0 - np.cos(2.0 * x))
    with np.errstate(divide="ignore", invalid="ignore"):
        polished = x - g / dg
    x = np.where((polished >= lo) & (polished <= hi), polished, x)
    x = np.where(f == 0, 0.0, x)
    return np.where(fill > 0.5, np.pi - x, x)


def half_angle_from_depth(depth, radius):
    r"""Half-angle from the bed depth: :math:`\theta = \arccos(1 - h/R) = 2\arcsin\sqrt{h/2R}`.

    Parameters
    ----------
    depth : float or array, m
        Bed depth at the middle of the chord, in [0, 2R].
    radius : float or array, m
        Drum inner radius.

    Returns
    -------
    float or array, rad

    Examples
    --------
    >>> round(float(half_angle_from_depth(0.2, 0.2)), 12) == round(np.pi / 2, 12)
    True

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    depth = np.asarray(depth, dtype=float)
    radius = np.asarray(radius, dtype=float)
    check_positive("radius", radius, "m")
    ratio = depth / radius
    check_range("depth/radius", ratio, 0.0, 2.0, closed_low=True, closed_high=True)
    return 2.0 * np.arcsin(np.sqrt(ratio / 2.0))


def depth_from_half_angle(theta, radius):
    r"""Bed depth from the half-angle: :math:`h = R(1-\cos\theta) = 2R\sin^2(\theta/2)`, m.

    Parameters
    ----------
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m
        Depth at the middle of the chord, in [0, 2R].

    Examples
    --------
    >>> round(float(depth_from_half_angle(np.pi / 2, 0.3)), 12)
    0.3

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    theta, radius = _check_theta_radius(theta, radius)
    return 2.0 * radius * np.sin(theta / 2.0) ** 2


def fill_from_depth(depth, radius):
    r"""Fill fraction from the bed depth and drum radius.

    .. math:: f = \frac{\theta - \sin\theta\cos\theta}{\pi},\quad \theta = \arccos(1 - h/R)

    Parameters
    ----------
    depth : float or array, m
        Bed depth at the middle of the chord, in [0, 2R].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, -
        Fill fraction in [0, 1].

    Examples
    --------
    >>> round(float(fill_from_depth(1.0, 1.0)), 12)
    0.5
    >>> round(float(fill_from_depth(0.2, 1.0)), 4)
    0.052

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    return fill_from_half_angle(half_angle_from_depth(depth, radius))


def depth_from_fill(fill, radius):
    r"""Bed depth from the fill fraction and drum radius (inverse of :func:`fill_from_depth`).

    .. math:: h = R(1 - \cos\theta(f))

    Parameters
    ----------
    fill : float or array, -
        Fill fraction in [0, 1].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m
        Depth at the middle of the chord, in [0, 2R].

    Examples
    --------
    >>> round(float(depth_from_fill(0.5, 2.0)), 12)
    2.0

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    return depth_from_half_angle(half_angle_from_fill(fill), radius)


def chord_from_half_angle(theta, radius):
    r"""Chord (free-surface width) :math:`L_c = 2R\sin\theta`, m.

    Parameters
    ----------
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m

    Examples
    --------
    >>> round(float(chord_from_half_angle(np.pi / 2, 1.5)), 12)
    3.0

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    theta, radius = _check_theta_radius(theta, radius)
    return 2.0 * radius * np.sin(theta)


def half_angle_from_chord(chord, radius, *, more_than_half: bool = False):
    r"""Half-angle from the chord length. A chord fixes the segment only up to the choice of side:
    ``more_than_half=False`` returns :math:`\theta = \arcsin(L_c/2R) \le \pi/2` (fill <= 0.5),
    ``True`` returns :math:`\pi - \theta`.

    Parameters
    ----------
    chord : float or array, m
        Width of the bed surface, in [0, 2R].
    radius : float or array, m
        Drum inner radius, > 0.
    more_than_half : bool
        Pick the segment larger than half the drum.

    Returns
    -------
    float or array, rad

    Examples
    --------
    >>> round(float(np.degrees(half_angle_from_chord(1.0, 1.0))), 9)
    30.0

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    chord = np.asarray(chord, dtype=float)
    radius = np.asarray(radius, dtype=float)
    check_positive("radius", radius, "m")
    check_range("chord/diameter", chord / (2 * radius), 0.0, 1.0, closed_low=True, closed_high=True)
    theta = np.arcsin(chord / (2.0 * radius))
    return np.pi - theta if more_than_half else theta


def bed_area(theta, radius):
    r"""Bed cross-sectional area :math:`A = R^2(\theta - \sin\theta\cos\theta)`, m2.

    Parameters
    ----------
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m2

    Examples
    --------
    >>> round(float(bed_area(np.pi / 2, 1.0)), 12) == round(np.pi / 2, 12)
    True

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    theta, radius = _check_theta_radius(theta, radius)
    return _bed_area(theta, radius)


def _check_theta_radius(theta, radius):
    """Both as float arrays after the checks theta in [0, pi] rad and radius > 0 m."""
    theta = np.asarray(theta, dtype=float)
    radius = np.asarray(radius, dtype=float)
    check_range("theta", theta, 0.0, np.pi, closed_low=True, closed_high=True, unit="rad")
    check_positive("radius", radius, "m")
    return theta, radius


def _bed_area(theta, radius):
    return radius**2 * _x_minus_sin(2.0 * theta) / 2.0


def covered_wall_arc(theta, radius):
    r"""Wall arc in contact with the bed, :math:`2R\theta`, m.

    Parameters
    ----------
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m

    Examples
    --------
    >>> round(float(covered_wall_arc(np.pi / 2, 1.0)), 6)
    3.141593

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    theta, radius = _check_theta_radius(theta, radius)
    return 2.0 * radius * theta


def exposed_wall_arc(theta, radius):
    r"""Wall arc exposed to the freeboard gas, :math:`2R(\pi - \theta)`, m.

    Parameters
    ----------
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m

    Examples
    --------
    >>> round(float(exposed_wall_arc(np.pi / 3, 1.0)), 6)
    4.18879

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    theta, radius = _check_theta_radius(theta, radius)
    return 2.0 * radius * (np.pi - theta)


def exposed_bed_width(theta, radius):
    r"""Width of the bed surface exposed to the freeboard (the chord), :math:`2R\sin\theta`, m.

    Parameters
    ----------
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m

    Examples
    --------
    >>> round(float(exposed_bed_width(np.pi / 6, 1.0)), 6)
    1.0

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    return chord_from_half_angle(theta, radius)


def freeboard_area(theta, radius):
    r"""Freeboard (gas) cross-sectional area :math:`\pi R^2 - A_{bed}`, m2.

    Parameters
    ----------
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m2

    Examples
    --------
    >>> round(float(freeboard_area(np.pi / 2, 1.0)), 6)
    1.570796

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    theta, radius = _check_theta_radius(theta, radius)
    return np.pi * radius**2 - _bed_area(theta, radius)


def freeboard_hydraulic_diameter(theta, radius):
    r"""Hydraulic diameter of the freeboard, :math:`D_h = 4A_{fb}/(2R(\pi-\theta) + 2R\sin\theta)`, m.

    The wetted perimeter is the exposed wall arc plus the bed surface chord. A full drum
    (:math:`\theta = \pi`) has no freeboard: :math:`D_h \to 0` (the limit, not 0/0).

    Parameters
    ----------
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].
    radius : float or array, m
        Drum inner radius, > 0.

    Returns
    -------
    float or array, m

    Examples
    --------
    >>> round(float(freeboard_hydraulic_diameter(0.0, 0.5)), 12)
    1.0
    >>> float(freeboard_hydraulic_diameter(np.pi, 0.5))
    0.0

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """
    theta, radius = _check_theta_radius(theta, radius)
    perimeter = 2.0 * radius * (np.pi - theta + np.sin(theta))
    area = np.pi * radius**2 - _bed_area(theta, radius)
    with np.errstate(invalid="ignore", divide="ignore"):
        dh = 4.0 * area / perimeter
    return np.where(perimeter > 0, dh, 0.0)


@dataclass(frozen=True)
class CrossSection:
    """All the geometry of a partly filled cross-section (SI units), built from any one measure.

    Build it with :meth:`from_fill`, :meth:`from_depth`, :meth:`from_half_angle` or
    :meth:`from_chord` (they check their inputs). Arrays broadcast.

    Parameters
    ----------
    radius : float or array, m
        Drum inner radius, > 0.
    theta : float or array, rad
        Half-angle of the bed, in [0, pi].

    Attributes
    ----------
    fill : -
    depth, chord, covered_wall_arc, exposed_wall_arc, hydraulic_diameter : m
    bed_area, freeboard_area : m2

    Examples
    --------
    >>> cs = CrossSection.from_fill(0.5, radius=1.0)
    >>> round(float(cs.depth), 12)
    1.0

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.3 (arccos argument corrected).
    """

    radius: np.ndarray
    theta: np.ndarray

    @classmethod
    def from_fill(cls, fill, radius) -> CrossSection:
        check_positive("radius", radius, "m")
        return cls(np.asarray(radius, float), half_angle_from_fill(fill))

    @classmethod
    def from_depth(cls, depth, radius) -> CrossSection:
        return cls(np.asarray(radius, float), half_angle_from_depth(depth, radius))

    @classmethod
    def from_half_angle(cls, theta, radius) -> CrossSection:
        check_positive("radius", radius, "m")
        check_range("theta", theta, 0.0, np.pi, closed_low=True, closed_high=True, unit="rad")
        return cls(np.asarray(radius, float), np.asarray(theta, float))

    @classmethod
    def from_chord(cls, chord, radius, *, more_than_half: bool = False) -> CrossSection:
        theta = half_angle_from_chord(chord, radius, more_than_half=more_than_half)
        return cls(np.asarray(radius, float), theta)

    @property
    def fill(self):
        return fill_from_half_angle(self.theta)

    @property
    def depth(self):
        return depth_from_half_angle(self.theta, self.radius)

    @property
    def chord(self):
        return chord_from_half_angle(self.theta, self.radius)

    @property
    def bed_area(self):
        return bed_area(self.theta, self.radius)

    @property
    def covered_wall_arc(self):
        return covered_wall_arc(self.theta, self.radius)

    @property
    def exposed_wall_arc(self):
        return exposed_wall_arc(self.theta, self.radius)

    @property
    def freeboard_area(self):
        return freeboard_area(self.theta, self.radius)

    @property
    def hydraulic_diameter(self):
        return freeboard_hydraulic_diameter(self.theta, self.radius)

    def as_dict(self) -> dict[str, float | np.ndarray]:
        """Every quantity, keyed by name with its SI unit in the key."""
        return {
            "radius_m": self.radius,
            "fill": self.fill,
            "half_angle_rad": self.theta,
            "half_angle_deg": np.degrees(self.theta),
            "depth_m": self.depth,
            "chord_m": self.chord,
            "bed_area_m2": self.bed_area,
            "covered_wall_arc_m": self.covered_wall_arc,
            "exposed_wall_arc_m": self.exposed_wall_arc,
            "exposed_bed_width_m": self.chord,
            "freeboard_area_m2": self.freeboard_area,
            "freeboard_hydraulic_diameter_m": self.hydraulic_diameter,
        }

    def to_frame(self) -> pd.DataFrame:
        """One row per point, one column per quantity."""
        data = {
            k: np.atleast_1d(np.broadcast_to(v, np.broadcast(*self.as_dict().values()).shape))
            for k, v in self.as_dict().items()
        }
        import pandas as pd

        return with_units(pd.DataFrame(data), "geometry.cross_section")

    def plot(self, ax=None):
        """Draw the cross-section (first point if arrays) with the bed shaded."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(4, 4))
        r = float(np.ravel(self.radius)[0])
        th = float(np.ravel(self.theta)[0])
        phi = np.linspace(0, 2 * np.pi, 361)
        ax.plot(r * np.cos(phi), r * np.sin(phi), color="0.2")
        arc = np.linspace(-np.pi / 2 - th, -np.pi / 2 + th, 200)
        ax.fill(
            r * np.cos(arc),
            r * np.sin(arc),
            color="tan",
            label=f"bed, fill {self.fill.flat[0]:.3f}",
        )
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.legend(loc="upper right")
        return ax.figure
