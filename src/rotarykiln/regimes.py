r"""Transverse bed motion: Froude number, critical speed and the bed regime.

.. math::

    Fr = \frac{\omega^2 R}{g}, \qquad \omega_c = \sqrt{g/R}, \qquad
    N_c = \frac{60}{2\pi}\sqrt{g/R}\ \text{rpm} \approx \frac{42.3}{\sqrt{D}}, \qquad
    \frac{\omega}{\omega_c} = \sqrt{Fr}

Two regime criteria are offered, because the sources disagree:

``"mellmann"`` (default)
    Froude-number bands with the fill degree, Mellmann (2001), *Powder Technol.* 118, 251-270,
    Table 1 (transcribed in seed 004, Ahmad, Table 1): slipping Fr < 1e-4 (low wall friction),
    slumping 1e-5 < Fr < 1e-3 (f < 0.1), rolling 1e-4 < Fr < 1e-2 (f > 0.1), cascading
    1e-3 < Fr < 1e-1, cataracting 0.1 < Fr < 1, centrifuging Fr >= 1. The bands overlap; the
    default boundaries resolve the overlaps as :class:`MellmannBands` documents. When the wall
    friction coefficient is given, Mellmann's eq. (critical wall friction, seed 004 eq. 2.14)
    :math:`\mu_{W,c} = 2\sin^3\varepsilon\,\sin\xi / (3\pi f (1+Fr))` decides slipping.
``"henein"``
    Fraction of critical speed: rolling for 0.10 < omega/omega_c < 0.55 (Henein, Brimacombe &
    Watkinson 1983, as used by seed 000, section 3.2), cataracting from 0.55-0.60 omega_c (Rutgers
    1965, seed 000), centrifuging at and above omega_c. Below 0.10 the bed slumps (or slips with
    low wall friction, which this criterion does not resolve).

Example: a 6 m drum at 5 rpm, 30 % fill has Fr = 0.084 and runs at 0.29 of critical speed: the
Mellmann bands call it cascading, Henein's band calls it rolling (seed 000 models it as rolling).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.errors import InputError, check_nonnegative, check_positive, check_range
from rotarykiln.tables import with_units

__all__ = [
    "G",
    "REGIMES",
    "HeneinBands",
    "MellmannBands",
    "RegimeResult",
    "classify_regime",
    "critical_speed",
    "critical_speed_rpm",
    "critical_wall_friction_mellmann",
    "fraction_of_critical",
    "froude_number",
    "plot_regime_map",
]

G = 9.80665
"""Standard gravity, m/s2."""

REGIMES = ("slipping", "slumping", "rolling", "cascading", "cataracting", "centrifuging")
RPM = 2.0 * np.pi / 60.0  # rad/s per rpm


def froude_number(speed, radius, g: float = G):
    r"""Rotational Froude number :math:`Fr = \omega^2 R / g`.

    Parameters
    ----------
    speed : float or array, rad/s
        Drum angular speed (>= 0).
    radius : float or array, m
        Drum inner radius (> 0).
    g : float, m/s2
        Gravitational acceleration.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(froude_number(5 * 2 * np.pi / 60, 3.0)), 4)
    0.0839

    References
    ----------
    Boateng, Rotary Kilns, ch. 2, eq. 2.2.
    """
    check_nonnegative("speed", speed, "rad/s")
    check_positive("radius", radius, "m")
    return np.asarray(speed, float) ** 2 * np.asarray(radius, float) / g


def critical_speed(radius, g: float = G):
    r"""Critical (centrifuging) speed :math:`\omega_c = \sqrt{g/R}`, rad/s (Fr = 1).

    Parameters
    ----------
    radius : float or array, m
        Drum inner radius (> 0).
    g : float, m/s2
        Gravitational acceleration.

    Returns
    -------
    float or array, rad/s

    Examples
    --------
    >>> round(float(critical_speed(1.0)), 4)
    3.1316

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.2.
    """
    check_positive("radius", radius, "m")
    return np.sqrt(g / np.asarray(radius, float))


def critical_speed_rpm(radius, g: float = G):
    r"""Critical speed in rpm, :math:`N_c = (60/2\pi)\sqrt{g/R} \approx 42.3/\sqrt{D}`.

    For display only: every other function takes rad/s.

    Parameters
    ----------
    radius : float or array, m
        Drum inner radius (> 0).
    g : float, m/s2
        Gravitational acceleration.

    Returns
    -------
    float or array, rpm

    Examples
    --------
    >>> [round(float(critical_speed_rpm(d / 2)), 1) for d in (0.2, 0.4, 0.57, 6.0)]
    [94.6, 66.9, 56.0, 17.3]

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.2.
    """
    return critical_speed(radius, g) / RPM


def fraction_of_critical(speed, radius, g: float = G):
    r"""Fraction of critical speed :math:`\omega/\omega_c = \sqrt{Fr}`.

    Parameters
    ----------
    speed : float or array, rad/s
        Drum angular speed (>= 0).
    radius : float or array, m
        Drum inner radius (> 0).
    g : float, m/s2
        Gravitational acceleration.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(fraction_of_critical(5 * RPM, 3.0)), 3)
    0.29

    References
    ----------
    Boateng, A. A., Rotary Kilns, ch. 2, eq. 2.2.
    """
    check_nonnegative("speed", speed, "rad/s")
    return np.asarray(speed, float) / critical_speed(radius, g)


def critical_wall_friction_mellmann(fill, repose_angle, froude):
    r"""Critical wall friction coefficient below which the bed slips (Mellmann 2001).

    .. math:: \mu_{W,c} = \frac{2\sin^3\varepsilon\,\sin\xi}{3\pi f\,(1 + Fr)}

    with :math:`\varepsilon` the half bed angle (the half-angle of :mod:`rotarykiln.geometry`),
    :math:`\xi` the dynamic angle of repose and :math:`f` the fill.

    Validity: rolling and slumping beds (Fr < 0.1), fill in (0, 1).

    Parameters
    ----------
    fill : float or array, -
        Fill fraction in (0, 1).
    repose_angle : float or array, rad
        Dynamic angle of repose, in (0, pi/2).
    froude : float or array, -
        Rotational Froude number, >= 0.

    Returns
    -------
    float or array, -
        Critical wall friction coefficient.

    Examples
    --------
    >>> round(float(critical_wall_friction_mellmann(0.1, np.radians(35), 1e-3)), 3)
    0.466

    References
    ----------
    Mellmann, Powder Technol. 118 (2001) 251; as printed in seed 004 (Ahmad), eq. 2.14.
    """
    from rotarykiln.geometry import half_angle_from_fill

    check_range("fill", fill, 0.0, 1.0)
    check_range("repose_angle", repose_angle, 0.0, np.pi / 2, unit="rad")
    check_nonnegative("froude", froude)
    eps = half_angle_from_fill(fill)
    f = np.asarray(fill, float)
    return 2 * np.sin(eps) ** 3 * np.sin(repose_angle) / (3 * np.pi * f * (1 + np.asarray(froude)))


@dataclass(frozen=True)
class MellmannBands:
    """Froude-number boundaries of the ``"mellmann"`` criterion (defaults from Mellmann 2001).

    Mellmann's bands overlap; the defaults take, in order of rising Fr:
    slipping below ``slumping_min`` (1e-5, the lower end of his slumping band); slumping up to
    ``rolling_min`` (1e-4) or, for fills below ``low_fill`` (0.1), up to ``rolling_min_low_fill``
    (1e-3, the top of his slumping band); rolling up to ``cascading_min`` (1e-2, the top of his
    rolling band); cascading up to ``cataracting_min`` (0.1); cataracting up to ``centrifuging_min``
    (1.0).
    """

    slumping_min: float = 1e-5
    rolling_min: float = 1e-4
    rolling_min_low_fill: float = 1e-3
    low_fill: float = 0.1
    cascading_min: float = 1e-2
    cataracting_min: float = 0.1
    centrifuging_min: float = 1.0
    source: str = "Mellmann (2001), Powder Technol. 118:251, Table 1"


@dataclass(frozen=True)
class HeneinBands:
    """Fraction-of-critical-speed boundaries of the ``"henein"`` criterion.

    rolling from ``rolling_min`` = 0.10 to ``rolling_max`` = 0.55 (Henein et al. 1983, as used in
    seed 000); cascading between 0.55 and ``cataracting_min`` = 0.60, cataracting above it
    (Rutgers 1965: cataracting sets in at 0.55-0.60 of critical); centrifuging at 1.
    """

    rolling_min: float = 0.10
    rolling_max: float = 0.55
    cataracting_min: float = 0.60
    centrifuging_min: float = 1.0
    source: str = "Henein, Brimacombe & Watkinson (1983); Rutgers (1965)"


@dataclass(frozen=True)
class RegimeResult:
    """The bed regime at one or many operating points.

    Attributes
    ----------
    name : str or array of str
        One of :data:`REGIMES`.
    criterion : str
        ``"mellmann"`` or ``"henein"``.
    froude, fraction_of_critical, fill : float or array
    source : str
        The source of the boundaries used.
    """

    name: np.ndarray
    criterion: str
    froude: np.ndarray
    fraction_of_critical: np.ndarray
    fill: np.ndarray
    source: str
    bands: MellmannBands | HeneinBands = field(repr=False, default_factory=MellmannBands)

    def to_frame(self) -> pd.DataFrame:
        shape = np.broadcast(self.name, self.froude, self.fill).shape
        import pandas as pd

        frame = pd.DataFrame(
            {
                "regime": np.broadcast_to(self.name, shape).ravel(),
                "froude": np.broadcast_to(self.froude, shape).ravel(),
                "fraction_of_critical": np.broadcast_to(self.fraction_of_critical, shape).ravel(),
                "fill": np.broadcast_to(self.fill, shape).ravel(),
                "criterion": self.criterion,
            }
        )
        return with_units(frame, "regimes")

    def plot(self, ax=None):
        """The regime map with these operating points marked."""
        return plot_regime_map(self.fill, self.froude, ax=ax)


def classify_regime(
    froude,
    fill,
    *,
    criterion: str = "mellmann",
    bands: MellmannBands | HeneinBands | None = None,
    wall_friction=None,
    repose_angle=None,
) -> RegimeResult:
    """Classify the transverse bed regime.

    Parameters
    ----------
    froude : float or array, -
        Rotational Froude number (see :func:`froude_number`).
    fill : float or array, -
        Fill fraction in (0, 1).
    criterion : {"mellmann", "henein"}
        Froude-number bands with fill (Mellmann 2001), or fraction of critical speed (Henein 1983).
    bands : MellmannBands or HeneinBands, optional
        Boundaries; the literature defaults when omitted.
    wall_friction : float, optional, -
        Wall friction coefficient; with ``repose_angle`` (rad) it lets the Mellmann criterion
        decide slipping by the critical wall friction.
    repose_angle : float or array, optional, rad
        Dynamic angle of repose, needed with ``wall_friction``.

    Returns
    -------
    RegimeResult
        ``name`` of the regime at each point, with ``froude`` (-) and ``fill`` (-).

    Examples
    --------
    >>> fr = froude_number(5 * RPM, 3.0)
    >>> str(classify_regime(fr, 0.3).name), str(classify_regime(fr, 0.3, criterion="henein").name)
    ('cascading', 'rolling')

    References
    ----------
    Mellmann, J. (2001) Powder Technol. 118, 251-270, Table 1; Henein, H., Brimacombe, J. K.,
    Watkinson, A. P. (1983) Metall. Trans. B 14, 191-205.
    """
    fr = np.asarray(froude, float)
    f = np.asarray(fill, float)
    check_nonnegative("froude", fr)
    check_range("fill", f, 0.0, 1.0)
    n = np.sqrt(fr)
    if criterion == "mellmann":
        b = bands if isinstance(bands, MellmannBands) else MellmannBands()
        rolling_min = np.where(f < b.low_fill, b.rolling_min_low_fill, b.rolling_min)
        name = np.select(
            [
                fr >= b.centrifuging_min,
                fr >= b.cataracting_min,
                fr >= b.cascading_min,
                fr >= rolling_min,
                fr >= b.slumping_min,
            ],
            ["centrifuging", "cataracting", "cascading", "rolling", "slumping"],
            default="slipping",
        )
        if wall_friction is not None:
            if repose_angle is None:
                raise InputError("repose_angle", None, "given when wall_friction is given")
            check_nonnegative("wall_friction", wall_friction)
            mu_c = critical_wall_friction_mellmann(f, repose_angle, fr)
            slip = (np.asarray(wall_friction) < mu_c) & (fr < b.cataracting_min)
            name = np.where(slip, "slipping", name)
    elif criterion == "henein":
        b = bands if isinstance(bands, HeneinBands) else HeneinBands()
        name = np.select(
            [
                n >= b.centrifuging_min,
                n >= b.cataracting_min,
                n >= b.rolling_max,
                n >= b.rolling_min,
            ],
            ["centrifuging", "cataracting", "cascading", "rolling"],
            default="slumping",
        )
    else:
        raise InputError("criterion", repr(criterion), "one of 'mellmann', 'henein'")
    if name.ndim == 0:
        name = name.item()
    return RegimeResult(name, criterion, fr, n, f, b.source, b)


def plot_regime_map(fill=None, froude=None, *, bands: MellmannBands | None = None, ax=None):
    """Regime map (Mellmann bands): Froude number (log) against fill, operating point(s) marked.

    Returns the matplotlib Figure.
    """
    import matplotlib.pyplot as plt

    b = bands or MellmannBands()
    if ax is None:
        _, ax = plt.subplots(figsize=(6.5, 4.5))
    fills = np.linspace(0.0, 0.6, 301)
    fr_min, fr_max = 1e-6, 3.0
    colors = {
        "slipping": "#d9d9d9",
        "slumping": "#c6dbef",
        "rolling": "#a1d99b",
        "cascading": "#fdd0a2",
        "cataracting": "#fc9272",
        "centrifuging": "#bcbddc",
    }
    rolling_min = np.where(fills < b.low_fill, b.rolling_min_low_fill, b.rolling_min)
    layers = [
        ("slipping", np.full_like(fills, fr_min), np.full_like(fills, b.slumping_min)),
        ("slumping", np.full_like(fills, b.slumping_min), rolling_min),
        ("rolling", rolling_min, np.full_like(fills, b.cascading_min)),
        ("cascading", np.full_like(fills, b.cascading_min), np.full_like(fills, b.cataracting_min)),
        (
            "cataracting",
            np.full_like(fills, b.cataracting_min),
            np.full_like(fills, b.centrifuging_min),
        ),
        ("centrifuging", np.full_like(fills, b.centrifuging_min), np.full_like(fills, fr_max)),
    ]
    for name, lo, hi in layers:
        ax.fill_between(fills, lo, hi, color=colors[name], step="mid", label=name, lw=0)
    if fill is not None and froude is not None:
        ax.plot(np.ravel(fill), np.ravel(froude), "k*", ms=14, label="operating point")
    ax.set_yscale("log")
    ax.set_ylim(fr_min, fr_max)
    ax.set_xlim(fills[0], fills[-1])
    ax.set_xlabel("fill fraction f (-)")
    ax.set_ylabel(r"Froude number $Fr = \omega^2 R/g$ (-)")
    ax.set_title("Transverse bed regimes (Mellmann 2001 bands)")
    ax.legend(
        loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8, frameon=False
    )  # hides no point
    return ax.figure
