"""Charcoal activation by steam: C + H2O -> CO + H2."""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative, check_positive

__all__ = ["ortiz_activation_rate", "onset_window"]


def onset_window(T, T_on, T_off=None, width=0.0):
    r"""Switch between 0 and 1 for a reaction active only in :math:`[T_{on}, T_{off}]`.

    With ``width`` = 0 it is the sharp step of seed 004; with ``width`` > 0 a linear ramp of that
    width (K) ending at :math:`T_{on}` (and starting at :math:`T_{off}`) keeps rates continuous
    for an ODE solver.

    Parameters
    ----------
    T : float or array
        Temperature, K.
    T_on : float
        Onset temperature, K.
    T_off : float or None
        Upper limit, K (None: no upper limit).
    width : float
        Ramp width, K.

    Returns
    -------
    ndarray
        Factor in [0, 1].

    Examples
    --------
    >>> onset_window([1000.0, 1073.0, 1100.0], 1073.0).tolist()
    [0.0, 1.0, 1.0]
    >>> onset_window(1068.0, 1073.0, width=10.0).tolist()
    0.5
    """
    T = np.asarray(T, dtype=float)
    if width > 0:
        s = np.clip((T - T_on + width) / width, 0.0, 1.0)
        if T_off is not None:
            s = s * np.clip((T_off + width - T) / width, 0.0, 1.0)
    else:
        s = (T >= T_on).astype(float)
        if T_off is not None:
            s = s * (T <= T_off)
    return s


def ortiz_activation_rate(
    T_solid,
    steam_flow,
    carbon_holdup,
    K_e=6.005,
    T_act=8033.0,
    T_on=1073.0,
    T_off=None,
    width=0.0,
):
    r"""Steam activation (gasification) rate of charcoal, Ortiz et al. (2003a), kg C/(s m).

    .. math::
        \gamma_s = -\frac{dQ_s}{dz} = K_e\, \exp\!\left(-\frac{T_A}{T_s}\right)
        \frac{Q_a\, Q_s}{V_s} = K_e\, e^{-T_A/T_s}\, Q_a\, m'_s,
        \qquad T_s \ge T_{on}

    with :math:`K_e = 6.005\ \mathrm{kg^{-1}}`, :math:`T_A = E/R = 8033` K
    (:math:`E \approx 66.8` kJ/mol), :math:`Q_a` the steam mass flow and
    :math:`m'_s = Q_s/V_s` the reacting solid hold-up per length. Seed 004 switches the
    reaction on at 1073 K ("primary reaction is occurring at 1073 K") and names 1273 K "the
    other extreme limit of reaction".

    Parameters
    ----------
    T_solid : float or array
        Solid temperature, K.
    steam_flow : float or array
        Steam mass flow :math:`Q_a`, kg/s (seed: 0.005 kg/s, taken constant).
    carbon_holdup : float or array
        Mass of reacting solid per kiln length :math:`m'_s = Q_s/V_s`, kg/m.
    K_e : float, 1/kg
        Rate constant.
    T_act : float
        Activation temperature E/R, K.
    T_on, T_off : float
        Active window, K (T_off None: no upper limit).
    width : float
        Width of the onset ramp, K (0: sharp switch as in the seed).

    Returns
    -------
    float or ndarray
        Carbon gasification rate, kg/(s m).

    Notes
    -----
    Reactor-lumped law regressed by Ortiz et al. on their pilot kiln; valid only around its
    conditions (1073-1273 K; 1373 K in a later paper). At 1100 K and Q_a = 0.005 kg/s the
    specific rate is 2.0e-5 1/s (notes 004, section 8.4).

    Examples
    --------
    >>> round(ortiz_activation_rate(1100.0, 0.005, 1.0) * 1e5, 3)   # 1e-5 kg/(s m) per kg/m
    2.023
    >>> ortiz_activation_rate(1000.0, 0.005, 1.0)
    0.0

    References
    ----------
    O.A. Ortiz, N.D. Martinez, S.E. Noriega, Steady state simulation of rotary kiln for
    charcoal activation, Latin Am. Appl. Res. 33 (2003) 51-57, as used by S. Ahmad (2006)
    eq. (3.11).
    """
    check_nonnegative("activation.steam_flow", steam_flow, "kg/s")
    check_positive("activation.T_solid", T_solid, "K")
    T = np.asarray(T_solid, dtype=float)
    m = np.maximum(np.asarray(carbon_holdup, dtype=float), 0.0)
    r = K_e * np.exp(-T_act / T) * np.asarray(steam_flow, dtype=float) * m
    r = r * onset_window(T, T_on, T_off, width)
    return r if r.ndim else float(r)
