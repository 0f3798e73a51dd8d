r"""Active layer of a rolling bed: proportion, areas, mean velocities (Van Puyvelde 1999, ch. 5).

In the rolling regime the bed splits into a thin, fast *active layer* under the free surface and
a *stagnant layer* that turns with the wall as a solid body. The thesis measures the active-layer
proportion :math:`X_{AL} = A_{AL}/(A_{AL}+A_{SL})` (eq 5.1) and correlates it with drum speed and
fill (eq 5.2); flux conservation between the layers then gives the mean active-layer velocity
(eq 5.6), the scaling parameter of both the mixing and the segregation models.

Eq 5.6 departs from eq 5.3 by a factor 2: every :math:`V_{AL}` tabulated by the thesis (Tables
6.2, 7.2 and the 7.01 m/s of the retort case) needs :math:`V_{SL} = \omega R` in eq 5.6, while
eq 5.3 derives :math:`V_{SL} = \omega R/2`. ``convention="tables"`` (default) reproduces the
tables and is the convention the mixing constants were fitted in; ``convention="eq5.3"`` gives the
physically derived value (half). See docs/transverse.md.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.errors import InputError, check_positive, check_range
from rotarykiln.geometry import chord_from_half_angle, half_angle_from_fill
from rotarykiln.tables import with_units

__all__ = [
    "ActiveLayer",
    "active_layer",
    "vanpuyvelde_active_layer_proportion",
    "vanpuyvelde_active_layer_velocity",
    "vanpuyvelde_apex_geometry",
    "vanpuyvelde_bed_area",
    "vanpuyvelde_centre_of_rotation",
    "stagnant_layer_velocity",
    "stagnant_residence_time",
    "bed_revolution_period",
    "warn_if_not_rolling",
]

_RPM = 60.0 / (2.0 * np.pi)  # rpm per rad/s

#: Eq 5.2 was fitted on the 570 mm drum over these ranges (N rpm, L %).
SPEED_RANGE_RPM = (2.0, 25.0)
FILL_RANGE = (0.10, 0.40)


def vanpuyvelde_active_layer_proportion(omega, fill):
    r"""Active-layer proportion of the bed cross-section, Van Puyvelde eq 5.2.

    .. math:: X_{AL} = 0.0981 \ln N + 0.00438 \exp\left(0.08744\,(50 - L)\right)

    with :math:`N = 60\omega/2\pi` in rpm and :math:`L = 100 f` in percent of the drum volume
    (the sign of the second term, lost in the OCR, is fixed by Tables 6.2 and 7.2).

    Parameters
    ----------
    omega : float or array, rad/s
        Drum rotation rate.
    fill : float or array, -
        Fractional fill of the drum, in (0, 1).

    Returns
    -------
    float or array, -
        Active-layer area over bed area, clipped to (0, 1).

    Notes
    -----
    Fitted on a 570 mm drum for N = 2-25 rpm, L = 10-40 %, particles 1.70-5.08 mm (average error
    10 %); independent of particle size and of drum diameter (200-570 mm, Table 5.1).

    Examples
    --------
    >>> omega = 9.0 / 60 * 2 * np.pi  # 9 rpm
    >>> round(float(vanpuyvelde_active_layer_proportion(omega, 0.25)), 3)
    0.255

    References
    ----------
    Van Puyvelde, D. R., Industrial Rotating Kiln Simulation, PhD thesis, UTS (1999), eq 5.2.
    """
    omega = np.asarray(omega, dtype=float)
    fill = np.asarray(fill, dtype=float)
    check_positive("omega", omega, "rad/s")
    check_range("fill", fill, 0.0, 1.0, unit="")
    n_rpm = omega * _RPM
    x = 0.0981 * np.log(n_rpm) + 0.00438 * np.exp(0.08744 * (50.0 - 100.0 * fill))
    if np.any((x <= 0.0) | (x >= 1.0)):
        raise InputError(
            "omega",
            f"{float(np.min(n_rpm)):.3g} rpm",
            "giving an active-layer proportion in (0, 1) (eq 5.2 needs N > ~1 rpm)",
        )
    return x


def vanpuyvelde_bed_area(radius, fill):
    r"""Transverse bed area from drum radius and fill, :math:`A_{BED} = f\,\pi R^2`.

    Parameters
    ----------
    radius : float or array, m
        Drum inner radius.
    fill : float or array, -
        Fractional fill, in (0, 1).

    Returns
    -------
    float or array, m2
        Bed cross-section area (per unit drum length, m3/m).

    Examples
    --------
    >>> round(float(vanpuyvelde_bed_area(0.285, 0.25)), 5)
    0.06379

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    check_positive("radius", radius, "m")
    check_range("fill", fill, 0.0, 1.0)
    return np.asarray(fill, dtype=float) * np.pi * np.asarray(radius, dtype=float) ** 2


def stagnant_layer_velocity(omega, radius):
    r"""Mean stagnant-layer velocity for a linear no-slip profile, Van Puyvelde eq 5.3.

    .. math:: V_{SL} = \omega \int_0^R r\,dr \Big/ \int_0^R dr = \omega R / 2

    Parameters
    ----------
    omega : float or array, rad/s
        Drum rotation rate.
    radius : float or array, m
        Drum inner radius.

    Returns
    -------
    float or array, m/s

    Examples
    --------
    >>> round(float(stagnant_layer_velocity(1.0, 0.3)), 3)
    0.15

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eq 5.3.
    """
    check_positive("omega", omega, "rad/s")
    check_positive("radius", radius, "m")
    return 0.5 * np.asarray(omega, dtype=float) * np.asarray(radius, dtype=float)


def vanpuyvelde_active_layer_velocity(omega, radius, x_al, *, convention: str = "tables"):
    r"""Mean active-layer velocity from flux conservation, Van Puyvelde eq 5.6.

    .. math:: V_{AL} = V_{SL}\,\frac{A_{SL}}{A_{AL}} = c\,\omega R\,\frac{1 - X_{AL}}{X_{AL}}

    with :math:`c = 1` for ``convention="tables"`` (the form that reproduces every tabulated
    V_AL of the thesis, :math:`\pi N D/60 \cdot (1-X)/X`) and :math:`c = 1/2` for
    ``convention="eq5.3"`` (V_SL = ωR/2 as derived in eq 5.3).

    Parameters
    ----------
    omega : float or array, rad/s
        Drum rotation rate.
    radius : float or array, m
        Drum inner radius.
    x_al : float or array, -
        Active-layer proportion, in (0, 1).
    convention : {"tables", "eq5.3"}
        Which form of the stagnant-layer velocity to use (see module docstring).

    Returns
    -------
    float or array, m/s
        Mean active-layer velocity.

    Examples
    --------
    Retort-zone base case (6 m drum, 5 rpm, 30 % fill):

    >>> w = 5 / 60 * 2 * np.pi
    >>> x = vanpuyvelde_active_layer_proportion(w, 0.30)
    >>> round(float(vanpuyvelde_active_layer_velocity(w, 3.0, x)), 2)
    7.01

    References
    ----------
    Van Puyvelde (1999), eqs 5.3-5.6, Tables 6.2 and 7.2.
    """
    check_positive("omega", omega, "rad/s")
    check_positive("radius", radius, "m")
    check_range("x_al", x_al, 0.0, 1.0)
    if convention == "tables":
        c = 1.0
    elif convention == "eq5.3":
        c = 0.5
    else:
        raise InputError("convention", convention, "one of 'tables', 'eq5.3'")
    x_al = np.asarray(x_al, dtype=float)
    return c * np.asarray(omega, dtype=float) * np.asarray(radius, dtype=float) * (1 - x_al) / x_al


def stagnant_residence_time(omega, fill):
    r"""Time a wall particle spends in the stagnant layer per revolution, :math:`2\theta/\omega`.

    Solid-body rotation through the angle :math:`2\theta` the bed subtends at the drum axis
    (the ≈2 s steps of the mixing curve of exp 3 in the thesis, Fig 6.4).

    Parameters
    ----------
    omega : float or array, rad/s
        Drum rotation rate.
    fill : float or array, -
        Fractional fill, in (0, 1).

    Returns
    -------
    float or array, s

    Examples
    --------
    >>> round(float(stagnant_residence_time(9 / 60 * 2 * np.pi, 0.25)), 2)
    2.45

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    check_positive("omega", omega, "rad/s")
    theta = half_angle_from_fill(fill)
    return 2.0 * theta / np.asarray(omega, dtype=float)


def bed_revolution_period(omega, radius, fill, *, convention: str = "tables"):
    r"""Time for one circulation of a wall particle: stagnant traverse plus active-layer transit.

    .. math:: t_{rev} = \frac{2\theta}{\omega} + \frac{L_c}{V_{AL}}

    Parameters
    ----------
    omega : float or array, rad/s
        Drum rotation rate.
    radius : float or array, m
        Drum inner radius.
    fill : float or array, -
        Fractional fill, in (0, 1).
    convention : {"tables", "eq5.3"}
        Convention of :func:`vanpuyvelde_active_layer_velocity`.

    Returns
    -------
    float or array, s

    Examples
    --------
    >>> round(float(bed_revolution_period(5 / 60 * 2 * np.pi, 3.0, 0.30)), 2)
    5.57

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    theta = half_angle_from_fill(fill)
    x = vanpuyvelde_active_layer_proportion(omega, fill)
    v = vanpuyvelde_active_layer_velocity(omega, radius, x, convention=convention)
    return 2.0 * theta / np.asarray(omega, dtype=float) + chord_from_half_angle(theta, radius) / v


def vanpuyvelde_apex_geometry(omega, fill):
    r"""Apex distances and angle of the 570 mm drum images, Van Puyvelde eqs 5.7-5.9.

    .. math::

        R_A = 168.82 + 2.211 N + 2.808 L \;[mm],\quad
        R_B = 193.61 + 4.606 N + 2.403 L \;[mm],\quad
        \theta_A = 2.56 + 0.813 N + 0.126 L \;[deg]

    The signs are lost in the OCR; "+" is taken (see docs/validation.md). Valid for
    the 570 mm drum only; used to locate the centre of rotation in images.

    Parameters
    ----------
    omega : float or array, rad/s
        Drum rotation rate.
    fill : float or array, -
        Fractional fill.

    Returns
    -------
    tuple of (float or array)
        R_A [m], R_B [m], theta_A [rad].

    Examples
    --------
    >>> ra, rb, ta = vanpuyvelde_apex_geometry(10 / 60 * 2 * np.pi, 0.25)
    >>> round(float(ra), 4), round(float(rb), 4), round(float(np.degrees(ta)), 2)
    (0.2611, 0.2997, 13.84)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eqs 5.7-5.9.
    """
    check_positive("omega", omega, "rad/s")
    check_range("fill", fill, 0.0, 1.0)
    n = np.asarray(omega, dtype=float) * _RPM
    pct = 100.0 * np.asarray(fill, dtype=float)
    r_a = (168.82 + 2.211 * n + 2.808 * pct) * 1e-3
    r_b = (193.61 + 4.606 * n + 2.403 * pct) * 1e-3
    th_a = np.radians(2.56 + 0.813 * n + 0.126 * pct)
    return r_a, r_b, th_a


def vanpuyvelde_centre_of_rotation(apex_a, apex_b, r_a, theta_a):
    r"""Centre of rotation of the bed from apex A, Van Puyvelde eq 5.10 (sign reconstructed).

    .. math::

        X_O = X_A + R_A\cos(\theta_{AB} - \theta_A), \quad
        Y_O = Y_A + R_A\sin(\theta_{AB} - \theta_A)

    with :math:`\theta_{AB} = \operatorname{atan2}(Y_B - Y_A, X_B - X_A)`; the angle is turned
    from the line A-B towards the bed (y up, bed below the line A-B when A is to the left).

    Parameters
    ----------
    apex_a, apex_b : (float, float), m
        Image coordinates of the two apexes (y up).
    r_a : float, m
        Distance from apex A to the centre of rotation (eq 5.7).
    theta_a : float, rad
        Angle between A-B and the line from A to the centre (eq 5.9).

    Returns
    -------
    (float, float), m
        Coordinates of the centre of rotation.

    Examples
    --------
    >>> xo, yo = vanpuyvelde_centre_of_rotation((0.0, 0.0), (0.5, 0.0), 0.25, np.radians(10))
    >>> round(xo, 4), round(yo, 4)
    (0.2462, -0.0434)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eq 5.10.
    """
    (xa, ya), (xb, yb) = apex_a, apex_b
    check_range("apex_a", (xa, ya), -np.inf, np.inf, unit="m")
    check_range("apex_b", (xb, yb), -np.inf, np.inf, unit="m")
    check_positive("r_a", r_a, "m")
    check_range("theta_a", theta_a, -np.pi, np.pi, closed_low=True, closed_high=True, unit="rad")
    th_ab = np.arctan2(yb - ya, xb - xa)
    ang = th_ab - theta_a
    return float(xa + r_a * np.cos(ang)), float(ya + r_a * np.sin(ang))


def warn_if_not_rolling(omega, radius, fill) -> bool:
    """Warn (OutOfRangeWarning) when the drum is not in the rolling regime.

    Uses the Henein (1983) bands of :func:`rotarykiln.regimes.classify_regime` (rolling between
    0.10 and 0.55 of the critical speed), the regime for which every transverse model of
    Van Puyvelde (1999) was developed. Returns True when a warning was issued.

    Examples
    --------
    >>> warn_if_not_rolling(5 / 60 * 2 * np.pi, 3.0, 0.3)
    False
    """
    import warnings

    from rotarykiln.errors import OutOfRangeWarning
    from rotarykiln.regimes import classify_regime, froude_number

    res = classify_regime(froude_number(omega, radius), fill, criterion="henein")
    if res.name == "rolling":
        return False
    warnings.warn(
        f"drum speed is {float(np.sqrt(res.froude)):.3f} of the critical speed: {res.name} "
        "regime, outside the rolling regime (0.10-0.55 of critical, Henein 1983) for which the "
        "transverse mixing and segregation models were developed",
        OutOfRangeWarning,
        stacklevel=3,
    )
    return True


@dataclass(frozen=True)
class ActiveLayer:
    """Active-layer state of a drum cross-section (all SI)."""

    radius: np.ndarray
    omega: np.ndarray
    fill: np.ndarray
    x_al: np.ndarray
    bed_area: np.ndarray
    active_area: np.ndarray
    stagnant_area: np.ndarray
    stagnant_velocity: np.ndarray
    active_velocity: np.ndarray
    stagnant_time: np.ndarray
    revolution_period: np.ndarray
    convention: str = "tables"

    def to_frame(self) -> pd.DataFrame:
        """One row per operating point."""
        import pandas as pd

        cols = {
            "radius": "radius_m",
            "omega": "omega_rad_s",
            "fill": "fill",
            "x_al": "x_al",
            "bed_area": "bed_area_m2",
            "active_area": "active_area_m2",
            "stagnant_area": "stagnant_area_m2",
            "stagnant_velocity": "stagnant_velocity_m_s",
            "active_velocity": "active_velocity_m_s",
            "stagnant_time": "stagnant_time_s",
            "revolution_period": "revolution_period_s",
        }
        data = {
            c: np.atleast_1d(np.asarray(getattr(self, a), dtype=float)) for a, c in cols.items()
        }
        n = max(len(v) for v in data.values())
        frame = pd.DataFrame({c: np.broadcast_to(v, (n,)) for c, v in data.items()})
        return with_units(frame, "transverse.active_layer")

    def plot(self, ax=None):
        """Bar chart of active and stagnant areas per operating point; returns the Figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        df = self.to_frame()
        idx = np.arange(len(df))
        ax.bar(idx, df["stagnant_area_m2"], label="stagnant layer")
        ax.bar(idx, df["active_area_m2"], bottom=df["stagnant_area_m2"], label="active layer")
        ax.set_xlabel("operating point")
        ax.set_ylabel("area (m$^2$)")
        ax.legend()
        return ax.figure


def active_layer(radius, omega, fill, *, convention: str = "tables") -> ActiveLayer:
    """Active-layer proportion, areas, velocities and times for a drum (eqs 5.1-5.6).

    Parameters
    ----------
    radius : float or array, m
        Drum inner radius.
    omega : float or array, rad/s
        Drum rotation rate.
    fill : float or array, -
        Fractional fill, in (0, 1).
    convention : {"tables", "eq5.3"}
        Velocity convention of eq 5.6 (see :func:`vanpuyvelde_active_layer_velocity`).

    Returns
    -------
    ActiveLayer

    Examples
    --------
    >>> al = active_layer(3.0, 5 / 60 * 2 * np.pi, 0.30)
    >>> round(float(al.x_al), 3), round(float(al.active_velocity), 2)
    (0.183, 7.01)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eqs 5.1-5.6.
    """
    x = vanpuyvelde_active_layer_proportion(omega, fill)
    a_bed = vanpuyvelde_bed_area(radius, fill)
    v_al = vanpuyvelde_active_layer_velocity(omega, radius, x, convention=convention)
    c = 1.0 if convention == "tables" else 0.5
    return ActiveLayer(
        radius=np.asarray(radius, dtype=float),
        omega=np.asarray(omega, dtype=float),
        fill=np.asarray(fill, dtype=float),
        x_al=x,
        bed_area=a_bed,
        active_area=x * a_bed,
        stagnant_area=(1 - x) * a_bed,
        stagnant_velocity=c * np.asarray(omega, dtype=float) * np.asarray(radius, dtype=float),
        active_velocity=v_al,
        stagnant_time=stagnant_residence_time(omega, fill),
        revolution_period=bed_revolution_period(omega, radius, fill, convention=convention),
        convention=convention,
    )
