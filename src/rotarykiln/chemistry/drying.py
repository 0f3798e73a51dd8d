"""Drying of the bed: moisture H2O(l) -> steam H2O.

Two rate laws, both per unit kiln length:

- :func:`ahmad_critical_moisture_drying_rate`: seed 004 (Ahmad 2006, section 3.2.1, after Kim &
  Srivastava 1988): the vaporisation rate is the heat flow from the gas to the exposed bed
  divided by the latent heat, scaled by the moisture relative to the critical moisture content
  (falling-rate period).
- :func:`heat_limited_drying_rate`: the bed sits at the boiling point while it holds moisture,
  and all net heat it receives evaporates water.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative, check_positive

__all__ = [
    "LATENT_HEAT_AHMAD",
    "ahmad_critical_moisture_drying_rate",
    "heat_limited_drying_rate",
]

#: Latent heat of vaporisation of water used by seed 004 (J/kg), the value at 373 K.
LATENT_HEAT_AHMAD = 2257200.0


def ahmad_critical_moisture_drying_rate(
    conductance,
    T_gas,
    T_bed,
    moisture_flow,
    dry_solid_flow,
    critical_moisture=0.1,
    latent_heat=LATENT_HEAT_AHMAD,
    cap=True,
):
    r"""Drying rate of seed 004 (critical-moisture model), kg water/(s m).

    .. math::
        r_{ev} = \frac{h_t A\,(T_g - T_s)}{H_v}\;
                 \min\!\left(1, \frac{Q_h}{X_c\, Q_{s,dry}}\right)

    with :math:`k_h = h_t A (T_g - T_s)/(H_v X_c Q_s)` as in Ahmad (2006) eq. of section 3.2.1
    (:math:`X_c = 0.1`). The rate is zero when :math:`T_g \le T_s` or there is no moisture.
    The seed has no cap: with ``cap=False`` the moisture ratio is used as printed; the seed's
    cases start at the critical moisture (10 %), where both agree. The seed uses the wet solid
    flow in the denominator; here the dry flow is used (notes 004, section 8.3).

    Parameters
    ----------
    conductance : float or array
        Gas-to-bed heat transfer conductance per length :math:`h_t A`, W/(m K).
    T_gas, T_bed : float or array
        Gas and bed temperatures, K.
    moisture_flow : float or array
        Moisture mass flow :math:`Q_h`, kg/s (or hold-up, kg/m: only the ratio matters).
    dry_solid_flow : float or array
        Dry solid mass flow :math:`Q_{s,dry}`, kg/s (same basis as ``moisture_flow``).
    critical_moisture : float
        Critical moisture content :math:`X_c`, kg water per kg dry solid (seed: 0.1).
    latent_heat : float
        :math:`H_v`, J/kg (seed: 2 257 200).
    cap : bool
        Limit the moisture ratio to 1 (constant-rate period above the critical moisture).

    Returns
    -------
    float or ndarray
        Evaporation rate, kg/(s m).

    Notes
    -----
    Valid in the falling-rate period, bed below the boiling point; the model has no
    temperature limit of its own.

    Examples
    --------
    >>> r = ahmad_critical_moisture_drying_rate(20.0, 750.0, 500.0, 3.33e-4, 3.33e-3)
    >>> round(float(r) * 1e3, 4)   # g/(s m): 20 W/mK * 250 K / 2.2572 MJ/kg
    2.2151

    References
    ----------
    S. Ahmad, Simulation of Rotary Reactor, M.Tech dissertation, IIT Roorkee (2006), 3.2.1.
    Kim & Srivastava, Ind. Eng. Chem. Res. (1988) (trona calciner drying formulation).
    """
    check_nonnegative("drying.conductance", conductance, "W/m/K")
    check_positive("drying.critical_moisture", critical_moisture)
    check_positive("drying.latent_heat", latent_heat, "J/kg")
    dT = np.maximum(np.asarray(T_gas, dtype=float) - np.asarray(T_bed, dtype=float), 0.0)
    qh = np.maximum(np.asarray(moisture_flow, dtype=float), 0.0)
    qs = np.asarray(dry_solid_flow, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(qs > 0, qh / (critical_moisture * np.where(qs > 0, qs, 1.0)), 0.0)
    if cap:
        ratio = np.minimum(ratio, 1.0)
    r = np.asarray(conductance, dtype=float) * dT / latent_heat * ratio
    return r if r.ndim else float(r)


def heat_limited_drying_rate(
    heat_input,
    T_bed,
    moisture_flow,
    latent_heat=LATENT_HEAT_AHMAD,
    T_boil=373.15,
    width=1.0,
):
    r"""Heat-transfer-limited drying rate, kg water/(s m).

    While the bed holds moisture and has reached the boiling point, every watt it receives
    evaporates water and its temperature stays at :math:`T_{boil}`:

    .. math::
        r_{ev} = \frac{\max(q_{bed}, 0)}{H_v}\; s(T_b), \qquad
        s = \mathrm{clip}\!\left(\frac{T_b - T_{boil} + w}{w}, 0, 1\right)

    :math:`s` is a linear ramp of width :math:`w` below :math:`T_{boil}` that keeps the rate
    continuous for an ODE solver (``width`` -> 0 gives the sharp switch). The rate is zero
    when there is no moisture.

    Parameters
    ----------
    heat_input : float or array
        Net heat flow into the bed per length :math:`q_{bed}` (all paths), W/m.
    T_bed : float or array
        Bed temperature, K.
    moisture_flow : float or array
        Moisture mass flow (or hold-up), kg/s; only its sign matters.
    latent_heat : float
        J/kg.
    T_boil : float
        Boiling temperature, K (373.15 K at 1 atm).
    width : float
        Width of the switching ramp, K.

    Returns
    -------
    float or ndarray
        Evaporation rate, kg/(s m). With it the bed energy balance gets
        :math:`q_{bed} - r_{ev} H_v = 0` on the plateau.

    Examples
    --------
    >>> round(heat_limited_drying_rate(2257.2, 373.15, 1e-3) * 1e3, 6)   # g/(s m)
    1.0
    >>> heat_limited_drying_rate(2257.2, 360.0, 1e-3)
    0.0

    References
    ----------
    Standard constant-temperature (boiling) drying model of kiln codes; e.g. the dryer zone of
    SimCem and Mujumdar et al.; the alternative requested by issue 7.
    """
    check_positive("drying.latent_heat", latent_heat, "J/kg")
    check_nonnegative("drying.width", width, "K")
    q = np.maximum(np.asarray(heat_input, dtype=float), 0.0)
    Tb = np.asarray(T_bed, dtype=float)
    if width > 0:
        s = np.clip((Tb - T_boil + width) / width, 0.0, 1.0)
    else:
        s = (Tb >= T_boil).astype(float)
    wet = np.asarray(moisture_flow, dtype=float) > 0
    r = np.where(wet, q / latent_heat * s, 0.0)
    return r if r.ndim else float(r)
