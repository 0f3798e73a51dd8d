r"""Saeman's kinematics of axial transport and McTait's dimensionless forms (seed 002, Boateng
ch. 2, eqs. 2.4-2.17, with the printed errors corrected).

Corrections (see docs/validation.md): the denominators :math:`\sin\theta` of eqs. 2.6,
2.8, 2.12, 2.13 are :math:`\sin\xi`; eq. 2.13 integrates to :math:`R`, not :math:`r`; the second
form of eq. 2.10 is :math:`\bar\tau = 2L\theta\sin\xi/(\omega L_c\tan\phi)`; eq. 2.16 misses
:math:`y/R` in its first bracket; the exponent of eq. 2.17 is 3/2. Symbols: :math:`\xi` dynamic
angle of repose, :math:`\phi` kiln slope, :math:`\psi` axial inclination of the bed surface,
:math:`n = \omega/2\pi`.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError, check_nonnegative, check_positive, check_range

__all__ = [
    "mctait_flow_dimensionless",
    "mctait_residence_time",
    "mctait_residence_time_dimensionless",
    "mctait_uniform_flow_dimensionless",
    "saeman_axial_advance",
    "saeman_axial_velocity",
    "saeman_cascades_per_revolution",
    "saeman_flow",
    "saeman_residence_time",
]


def _check_angles(slope, bed_slope, repose, *, positive_slope=False):
    if positive_slope:
        check_positive("slope", slope, "rad")
    else:
        check_nonnegative("slope", slope, "rad")
    if bed_slope is not None:
        check_range("bed_slope", bed_slope, -np.pi / 2, np.pi / 2, unit="rad")
    check_range("repose", repose, 0.0, np.pi / 2, unit="rad")


def saeman_axial_advance(chord, slope, bed_slope, repose):
    r"""Axial advance per cascade, :math:`z_o = L_c(\phi + \psi\cos\xi)/\sin\xi` (eq. 2.4), m.

    Parameters
    ----------
    chord : float or array, m
        Surface chord of the path, :math:`L_c`.
    slope : float or array, rad
        Kiln slope :math:`\phi`.
    bed_slope : float or array, rad
        Axial inclination of the bed surface :math:`\psi`.
    repose : float or array, rad
        Dynamic angle of repose :math:`\xi`.

    Returns
    -------
    float or array, m

    Examples
    --------
    >>> round(float(saeman_axial_advance(1.0, np.radians(3), 0.0, np.radians(40))), 4)
    0.0815

    References
    ----------
    Saeman, W. C. (1951) Chem. Eng. Prog. 47, 508; Boateng, A. A., Rotary Kilns,
    ch. 2, eqs. 2.4-2.13 (printed errors corrected, see the module docstring).
    """
    check_nonnegative("chord", chord, "m")
    _check_angles(slope, bed_slope, repose)
    return (
        np.asarray(chord)
        * (np.asarray(slope) + np.asarray(bed_slope) * np.cos(repose))
        / (np.sin(repose))
    )


def saeman_cascades_per_revolution(chord, r):
    r"""Number of cascades per revolution of a path of radius r, :math:`\pi/\arcsin(L_c/2r)`
    (eq. 2.5), -.

    Parameters
    ----------
    chord : float or array, m
        Surface chord of the path, in (0, 2r].
    r : float or array, m
        Radius of the particle path, > 0.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(saeman_cascades_per_revolution(1.0, 1.0)), 3)
    6.0

    References
    ----------
    Saeman, W. C. (1951) Chem. Eng. Prog. 47, 508; Boateng, A. A., Rotary Kilns,
    ch. 2, eqs. 2.4-2.13 (printed errors corrected, see the module docstring).
    """
    check_positive("r", r, "m")
    check_positive("chord", chord, "m")
    ratio = np.asarray(chord, dtype=float) / (2.0 * np.asarray(r, dtype=float))
    check_range("chord/(2 r)", ratio, 0.0, 1.0, closed_high=True)
    return np.pi / np.arcsin(ratio)


def saeman_axial_velocity(r, surface_distance, speed, slope, bed_slope, repose, *, exact=True):
    r"""Mean axial velocity of the path of radius r, :math:`u = n z_o N_c` (eqs. 2.6-2.8), m/s.

    ``exact=False`` uses the lightly-loaded form (2.7-2.8),
    :math:`u = 2\pi r n(\phi + \psi\cos\xi)/\sin\xi` (valid to about 10-12 % fill).

    The path at the bed surface (zero chord) has the limit :math:`2\pi r n(\phi +
    \psi\cos\xi)/\sin\xi`.

    Parameters
    ----------
    r : float or array, m
        Radius of the particle path, > 0, at or below the bed surface (r >= |r_o|).
    surface_distance : float or array, m
        Distance from the axis to the bed surface, :math:`r_o = R - H`.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Kiln slope :math:`\phi`, >= 0.
    bed_slope : float or array, rad
        Axial inclination of the bed surface :math:`\psi`.
    repose : float or array, rad
        Dynamic angle of repose :math:`\xi`, in (0, pi/2).
    exact : bool
        False: the lightly-loaded form.

    Returns
    -------
    float or array, m/s

    Examples
    --------
    >>> round(float(saeman_axial_velocity(1.0, 0.9, 0.1, np.radians(3), 0.0, np.radians(40))), 6)
    0.007872

    References
    ----------
    Saeman, W. C. (1951) Chem. Eng. Prog. 47, 508; Boateng, A. A., Rotary Kilns,
    ch. 2, eqs. 2.4-2.13 (printed errors corrected, see the module docstring).
    """
    check_positive("r", r, "m")
    check_positive("speed", speed, "rad/s")
    check_range("surface_distance", surface_distance, -np.inf, np.inf, unit="m")
    _check_angles(slope, bed_slope, repose)
    n = np.asarray(speed) / (2.0 * np.pi)
    r = np.asarray(r, dtype=float)
    k = (np.asarray(slope) + np.asarray(bed_slope) * np.cos(repose)) / np.sin(repose)
    if not exact:
        return 2.0 * np.pi * r * n * k
    s2 = r**2 - np.asarray(surface_distance) ** 2
    if np.any(s2 < -1e-9 * r**2):
        raise InputError("r", float(np.min(r)), ">= |surface_distance| (the path lies in the bed)")
    chord = 2.0 * np.sqrt(np.maximum(s2, 0.0))
    with np.errstate(invalid="ignore", divide="ignore"):
        per_cascade = chord / np.arcsin(chord / (2.0 * r))
    per_cascade = np.where(chord > 0, per_cascade, 2.0 * r)  # limit at the surface path
    return n * k * np.pi * per_cascade


def saeman_residence_time(length, r, speed, slope, repose):
    r"""Residence time on the path r of a uniform, lightly loaded bed,
    :math:`\bar\tau = L\sin\xi/(2\pi r n\phi)` (eqs. 2.9-2.10), s.

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    r : float or array, m
        Radius of the particle path, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Kiln slope :math:`\phi`, > 0.
    repose : float or array, rad
        Dynamic angle of repose :math:`\xi`, in (0, pi/2).

    Returns
    -------
    float or array, s

    Examples
    --------
    Boateng's design kiln (D 3.66 m, L/D 10, 3 deg, 40 deg, 1 rpm), outermost path: 39.1 min

    >>> t = saeman_residence_time(36.6, 1.83, np.pi / 30, np.radians(3), np.radians(40))
    >>> round(float(t / 60), 1)
    39.1

    References
    ----------
    Saeman, W. C. (1951) Chem. Eng. Prog. 47, 508; Boateng, A. A., Rotary Kilns,
    ch. 2, eqs. 2.4-2.13 (printed errors corrected, see the module docstring).
    """
    check_positive("length", length, "m")
    check_positive("r", r, "m")
    check_positive("speed", speed, "rad/s")
    _check_angles(slope, None, repose, positive_slope=True)
    n = np.asarray(speed) / (2.0 * np.pi)
    return np.asarray(length) * np.sin(repose) / (2.0 * np.pi * np.asarray(r) * n * slope)


def saeman_flow(radius, surface_distance, speed, slope, bed_slope, repose):
    r"""Volumetric transport rate (eq. 2.13 corrected),
    :math:`q = \frac{4\pi n}{3}\frac{\phi + \psi\cos\xi}{\sin\xi}(R^2 - r_o^2)^{3/2}`, m3/s.

    Parameters
    ----------
    radius : float or array, m
        Drum inner radius, > 0.
    surface_distance : float or array, m
        Distance from the axis to the bed surface, :math:`r_o = R - H`.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Kiln slope :math:`\phi`, >= 0.
    bed_slope : float or array, rad
        Axial inclination of the bed surface :math:`\psi`.
    repose : float or array, rad
        Dynamic angle of repose :math:`\xi`, in (0, pi/2).

    Returns
    -------
    float or array, m3/s

    Examples
    --------
    >>> round(float(saeman_flow(1.0, 0.0, 2 * np.pi, np.radians(3), 0.0, np.radians(40))), 4)
    0.3412

    References
    ----------
    Saeman, W. C. (1951) Chem. Eng. Prog. 47, 508; Boateng, A. A., Rotary Kilns,
    ch. 2, eqs. 2.4-2.13 (printed errors corrected, see the module docstring).
    """
    check_positive("radius", radius, "m")
    check_nonnegative("speed", speed, "rad/s")
    check_range("surface_distance", surface_distance, -np.inf, np.inf, unit="m")
    _check_angles(slope, bed_slope, repose)
    n = np.asarray(speed) / (2.0 * np.pi)
    k = (np.asarray(slope) + np.asarray(bed_slope) * np.cos(repose)) / np.sin(repose)
    s2 = np.asarray(radius) ** 2 - np.asarray(surface_distance) ** 2
    return 4.0 * np.pi * n / 3.0 * k * np.maximum(s2, 0.0) ** 1.5


def _theta(y_over_r):
    y = np.asarray(y_over_r, dtype=float)
    check_range("y/R", y, 0.0, 1.0, closed_high=True)
    return np.arcsin(np.sqrt((2.0 - y) * y))


def mctait_residence_time_dimensionless(y_over_r):
    r"""McTait's dimensionless residence time (eq. 2.15),
    :math:`\bar\tau_d = \bar\tau nD\tan\phi/(L\sin\xi) = \theta/(\pi\sin\theta)`.

    Parameters
    ----------
    y_over_r : float or array, -
        Bed depth over radius, in (0, 1].

    Returns
    -------
    float or array, -  (1/pi at zero depth, 1/2 at half fill)

    Examples
    --------
    >>> round(float(mctait_residence_time_dimensionless(0.2)), 4)
    0.3414

    References
    ----------
    McTait et al. (1995), as given by Boateng, A. A., Rotary Kilns, ch. 2,
    eqs. 2.15-2.17 (corrected, see the module docstring).
    """
    th = _theta(y_over_r)
    return th / (np.pi * np.sin(th))


def mctait_flow_dimensionless(y_over_r):
    r"""McTait's dimensionless flow (eq. 2.16 corrected),

    .. math:: q_d = \frac{q\sin\xi}{nD^3\tan\phi}
        = \frac{\pi}{4}\sin\theta\left(1 - \frac{\sin\theta\cos\theta}{\theta}\right)

    Parameters
    ----------
    y_over_r : float or array, -
        Bed depth over radius, in (0, 1].

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(mctait_flow_dimensionless(0.2)), 5)
    0.11973

    References
    ----------
    McTait et al. (1995), as given by Boateng, A. A., Rotary Kilns, ch. 2,
    eqs. 2.15-2.17 (corrected, see the module docstring).
    """
    th = _theta(y_over_r)
    return np.pi / 4.0 * np.sin(th) * (1.0 - np.sin(th) * np.cos(th) / th)


def mctait_uniform_flow_dimensionless(y_over_r):
    r"""Dimensionless flow of a uniform bed (eq. 2.17, exponent corrected to 3/2),
    :math:`q_d = \frac{\pi}{6}\sin^3\theta`.

    Parameters
    ----------
    y_over_r : float or array, -
        Bed depth over radius, in (0, 1].

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(mctait_uniform_flow_dimensionless(0.2)), 5)
    0.1131

    References
    ----------
    McTait et al. (1995), as given by Boateng, A. A., Rotary Kilns, ch. 2,
    eqs. 2.15-2.17 (corrected, see the module docstring).
    """
    return np.pi / 6.0 * np.sin(_theta(y_over_r)) ** 3


def mctait_residence_time(length, diameter, speed, slope, repose, y_over_r):
    r"""Mean residence time from eq. 2.15, :math:`\bar\tau = \bar\tau_d L\sin\xi/(nD\tan\phi)`, s.

    Parameters
    ----------
    length : float or array, m
        Drum length, > 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    speed : float or array, rad/s
        Rotation rate, > 0.
    slope : float or array, rad
        Kiln slope :math:`\phi`, > 0.
    repose : float or array, rad
        Dynamic angle of repose :math:`\xi`, in (0, pi/2).
    y_over_r : float or array, -
        Bed depth over radius, in (0, 1].

    Returns
    -------
    float or array, s

    Examples
    --------
    Boateng's Fig. 2.7 kiln at y/R = 0.2 (regenerated table of notes 002: 41.87 min):

    >>> t = mctait_residence_time(36.6, 3.66, np.pi / 30, np.radians(3), np.radians(40), 0.2)
    >>> round(float(t / 60), 2)
    41.87

    References
    ----------
    McTait et al. (1995), as given by Boateng, A. A., Rotary Kilns, ch. 2,
    eqs. 2.15-2.17 (corrected, see the module docstring).
    """
    check_positive("length", length, "m")
    check_positive("diameter", diameter, "m")
    check_positive("speed", speed, "rad/s")
    _check_angles(slope, None, repose, positive_slope=True)
    n = np.asarray(speed) / (2.0 * np.pi)
    scale = np.asarray(length) * np.sin(repose) / (n * np.asarray(diameter) * np.tan(slope))
    return mctait_residence_time_dimensionless(y_over_r) * scale
