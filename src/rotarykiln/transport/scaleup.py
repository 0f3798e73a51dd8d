r"""Dimensionless scale-up groups for rotating drums (Scott 1986, section 5.6; eqs. 2.40-2.46).

All functions take SI inputs. Where the source defines a group with mixed units (q in m3/min
and N in rpm), the group is the same number when q is in m3/s and the speed in rev/s, because
both carry one time unit; the functions use rev/s = omega/(2 pi).
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative, check_positive, check_range

__all__ = [
    "abouzeid_psi",
    "gilbert_flow_number",
    "karra_feed_number",
    "scott_psi",
]


def _check(q, diameter, length=None, speed=None, repose=None):
    check_nonnegative("q", q, "m3/s")
    check_positive("diameter", diameter, "m")
    if length is not None:
        check_positive("length", length, "m")
    if speed is not None:
        check_positive("speed", speed, "rad/s")
    if repose is not None:
        check_range("repose", repose, 0.0, np.pi / 2, unit="rad")


def _rev_per_s(omega):
    return np.asarray(omega, dtype=float) / (2.0 * np.pi)


def abouzeid_psi(q, length, diameter, speed, repose):
    r"""Abouzeid & Fuerstenau's scale-up parameter with :math:`B = \cot\alpha_d` (eq. 2.46).

    .. math:: \Psi = \frac{q L}{\cot\alpha_d\, N D^4}

    with :math:`N` in revolutions per unit time of :math:`q`.

    Parameters
    ----------
    q : float or array, m3/s
    length, diameter : float or array, m
    speed : float or array, rad/s
    repose : float or array, rad
        Dynamic angle of repose.

    Returns
    -------
    float or array, -

    Examples
    --------
    A&F's drum (Table A4.15): F = 1 g/s, rho 1400, L 0.24 m, D 0.08 m, 42 rpm, 39 deg:

    >>> round(float(abouzeid_psi(0.001 / 1400, 0.24, 0.08, 42 * np.pi / 30, np.radians(39))), 5)
    0.00484

    References
    ----------
    Abouzeid, A.-Z. M. A., Fuerstenau, D. W. (1980) Ind. Eng. Chem. Proc. Des. Dev. 19, 201;
    Scott (1986) eq. 2.46, Fig. 5.14.
    """
    _check(q, diameter, length, speed, repose)
    return (
        np.asarray(q, dtype=float)
        * np.asarray(length, dtype=float)
        * np.tan(repose)
        / (_rev_per_s(speed) * np.asarray(diameter, dtype=float) ** 4)
    )


def scott_psi(q, length, diameter, speed, repose):
    r"""Scott's improved scale-up parameter (section 5.6, Fig. 5.17).

    .. math:: \Psi_S = \frac{q}{\cot\alpha_d\, N D^3}\left(\frac{L}{D}\right)^{0.75}

    Parameters
    ----------
    q : float or array, m3/s
    length, diameter : float or array, m
    speed : float or array, rad/s
    repose : float or array, rad

    Returns
    -------
    float or array, -

    Examples
    --------
    Table A4.16 group 1: F 0.005 kg/s, rho 1780, L 0.25, D 0.1, 33.4 rpm, 28 deg (printed
    5.34e-3):

    >>> round(1000 * float(scott_psi(0.005 / 1780, 0.25, 0.1, 33.4 * np.pi / 30,
    ...                              np.radians(28))), 2)
    5.33

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh,
    section 5.6 and eqs. 2.40-2.46.
    """
    _check(q, diameter, length, speed, repose)
    d = np.asarray(diameter, dtype=float)
    return (
        np.asarray(q, dtype=float)
        * np.tan(repose)
        / (_rev_per_s(speed) * d**3)
        * (np.asarray(length, dtype=float) / d) ** 0.75
    )


def gilbert_flow_number(q, diameter, speed):
    r"""Gilbert's (1932) dimensionless flow :math:`q/(N D^3)` (first dimensionless comparison).

    Parameters
    ----------
    q : float or array, m3/s
    diameter : float or array, m
    speed : float or array, rad/s

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(gilbert_flow_number(1e-5, 0.1, 2 * np.pi)), 4)
    0.01

    References
    ----------
    Gilbert (1932) [G1 of Scott], reviewed in Scott, W. J. (1986) The transport of solids in
    rotating drums, PhD thesis, Edinburgh,
    section 5.6 and eqs. 2.40-2.46.
    """
    _check(q, diameter, speed=speed)
    return np.asarray(q, dtype=float) / (_rev_per_s(speed) * np.asarray(diameter, float) ** 3)


def karra_feed_number(q, diameter, g=9.81):
    r"""Dimensionless feed :math:`F^* = q/(\omega_c D^3)`, :math:`\omega_c = \sqrt{g/R}` (2.40).

    Parameters
    ----------
    q : float or array, m3/s
        Volumetric flow, >= 0.
    diameter : float or array, m
        Drum inner diameter, > 0.
    g : float, m/s2
        Gravitational acceleration.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(karra_feed_number(1e-6, 0.08)), 6)
    0.000125

    References
    ----------
    Karra & Fuerstenau (1978) [K2 of Scott], reviewed in Scott, W. J. (1986) The transport of
    solids in rotating drums, PhD thesis, Edinburgh,
    section 5.6 and eqs. 2.40-2.46.
    """
    _check(q, diameter)
    check_positive("g", g, "m/s2")
    d = np.asarray(diameter, dtype=float)
    return np.asarray(q, dtype=float) / (np.sqrt(g / (d / 2.0)) * d**3)
