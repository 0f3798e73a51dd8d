"""Drying of the bed: moisture H2O(l) -> steam H2O.

Rate laws, all per unit kiln length:

- :func:`boiling_drying_rate` (the default, law ``boiling_drying``, reaction ``drying``): below
  the boiling point the seed-004 rate; at the boiling point the bed temperature is held and the
  heat reaching the bed evaporates the moisture, so no liquid water survives above it
  (:func:`boiling_evaporation_rate`, the stiff "heat-sink" term, and
  :func:`water_boiling_temperature` for another pressure);
- :func:`ahmad_critical_moisture_drying_rate`: seed 004 (Ahmad 2006, section 3.2.1, after Kim &
  Srivastava 1988): the vaporisation rate is the heat flow from the gas to the exposed bed
  divided by the latent heat, scaled by the moisture relative to the critical moisture content
  (falling-rate period); it has no temperature limit (reaction ``drying_ahmad``, kept for the
  seed-004 validation);
- :func:`heat_limited_drying_rate`: the bed sits at the boiling point while it holds moisture,
  and all net heat it receives evaporates water (no moisture dependence; for ODE paths).
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative, check_positive, warn_out_of_range

__all__ = [
    "LATENT_HEAT_AHMAD",
    "P_ATM",
    "T_BOIL_ATM",
    "ahmad_critical_moisture_drying_rate",
    "boiling_drying_rate",
    "boiling_evaporation_rate",
    "heat_limited_drying_rate",
    "water_boiling_temperature",
]

#: Latent heat of vaporisation of water used by seed 004 (J/kg), the value at 373 K.
LATENT_HEAT_AHMAD = 2257200.0
#: Standard atmosphere, Pa.
P_ATM = 101325.0
#: Normal boiling point of water, K (at :data:`P_ATM`).
T_BOIL_ATM = 373.15
#: Molar mass of water, kg/mol, and the gas constant, J/(mol K).
_M_WATER = 0.01801528
_R = 8.314462618


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


def water_boiling_temperature(pressure, latent_heat=LATENT_HEAT_AHMAD):
    r"""Boiling (saturation) temperature of water at ``pressure``, K.

    Clausius-Clapeyron with a constant latent heat, through the normal boiling point:

    .. math::
        \frac{1}{T_{boil}} = \frac{1}{373.15\ \mathrm{K}}
            - \frac{R}{M_w H_v}\ln\frac{p}{101\,325\ \mathrm{Pa}}

    Parameters
    ----------
    pressure : float or array
        Total pressure over the bed, Pa.
    latent_heat : float
        :math:`H_v`, J/kg (default seed 004's 2 257 200 J/kg, i.e. 40.66 kJ/mol).

    Returns
    -------
    float or ndarray
        Boiling temperature, K.

    Notes
    -----
    Within 1.3 K of the IAPWS saturation line (Cantera's ``Water``) from 20 to 500 kPa
    (333-425 K; tested); outside that range an :class:`~rotarykiln.errors.OutOfRangeWarning`
    is issued (the latent heat falls with temperature, and the error grows).

    Examples
    --------
    >>> round(water_boiling_temperature(101325.0), 2)
    373.15
    >>> round(water_boiling_temperature(2.0e5), 1)   # IAPWS: 393.4 K
    393.6

    References
    ----------
    Clausius-Clapeyron equation, e.g. Smith, Van Ness & Abbott, Introduction to Chemical
    Engineering Thermodynamics, 7th ed. (2005), ch. 6; saturation line of IAPWS-IF97 (checked
    against Cantera's ``Water``).
    """
    check_positive("drying.pressure", pressure, "Pa")
    check_positive("drying.latent_heat", latent_heat, "J/kg")
    p = np.asarray(pressure, dtype=float)
    warn_out_of_range("drying.pressure [Pa]", p, 2.0e4, 5.0e5, "Clausius-Clapeyron, constant H_v")
    inv = 1.0 / T_BOIL_ATM - _R * np.log(p / P_ATM) / (_M_WATER * latent_heat)
    t = 1.0 / inv
    return t if t.ndim else float(t)


def boiling_evaporation_rate(T_bed, moisture_holdup, T_boil=T_BOIL_ATM, k_boil=1.0e3, width=0.25):
    r"""Evaporation at the boiling point as a stiff heat sink, kg water/(s m).

    .. math::
        r_b = k_b\, m'_h\, w \ln\!\left(1 + e^{(T_b - T_{boil})/w}\right)
        \;\xrightarrow{w \to 0}\; k_b\, m'_h\, (T_b - T_{boil})^+

    A bed with moisture cannot be hotter than its boiling point: any excess temperature turns
    into evaporation at the rate :math:`k_b (T_b - T_{boil})` per kg of moisture, fast enough
    that the bed temperature is held near :math:`T_{boil}` while moisture remains and all net
    heat reaching the bed evaporates water (the "thermal" or heat-sink drying model; the
    infinite-rate limit is the boiling law). The softplus of width :math:`w` makes the rate
    smooth for a Newton solver: below the boiling point it decays as
    :math:`e^{(T_b - T_{boil})/w}`, so a drying bed settles a few widths below
    :math:`T_{boil}` (:math:`w \ln(k_b w m'_h H_v / q)`, about 3 K with the defaults).

    Parameters
    ----------
    T_bed : float or array
        Bed temperature, K.
    moisture_holdup : float or array
        Liquid moisture per kiln length :math:`m'_h`, kg/m (negative values count as 0).
    T_boil : float
        Boiling temperature, K (373.15 K at 1 atm; :func:`water_boiling_temperature`).
    k_boil : float
        Rate constant :math:`k_b` per kelvin above the boiling point, 1/(s K).
    width : float
        Smoothing width :math:`w`, K.

    Returns
    -------
    float or ndarray
        Evaporation rate, kg/(s m).

    Notes
    -----
    :math:`k_b` and :math:`w` are numerical, not measured: the defaults (1000 1/(s K),
    0.25 K) leave less than 1e-6 of the feed moisture in a kiln cell of ~50 s residence whose
    bed is 2 K above the boiling point, and keep the banded Newton of the kiln converging
    (docs/reacting.md, "Drying"). The heat of the reaction (latent heat) is charged by the
    mechanism.

    Examples
    --------
    >>> round(boiling_evaporation_rate(375.15, 1.0), 1)   # 2 K above: ~k_b m' (T - T_b)
    2000.1
    >>> boiling_evaporation_rate(363.15, 1.0) < 1e-12     # 10 K below: nothing
    True

    References
    ----------
    Haberle, Skreiberg, Lazar & Haugen, Prog. Energy Combust. Sci. 63 (2017) 204-252 (review
    of drying models: the "thermal" model, evaporation above T_evap as a heat sink, beside the
    equilibrium and kinetic models); Peters & Bruch, J. Anal. Appl. Pyrolysis 70 (2003)
    233-250; the boiling law of ANSYS Fluent's discrete-phase model (Theory Guide, "Droplet
    Boiling"): the droplet stays at its boiling point and the heat reaching it sets the rate.
    """
    check_positive("drying.k_boil", k_boil, "1/(s K)")
    check_positive("drying.width", width, "K")
    check_positive("drying.T_boil", T_boil, "K")
    x = (np.asarray(T_bed, dtype=float) - T_boil) / width
    m = np.maximum(np.asarray(moisture_holdup, dtype=float), 0.0)
    r = k_boil * width * np.logaddexp(0.0, x) * m
    return r if r.ndim else float(r)


def boiling_drying_rate(
    conductance,
    T_gas,
    T_bed,
    moisture_flow,
    dry_solid_flow,
    moisture_holdup,
    critical_moisture=0.1,
    latent_heat=LATENT_HEAT_AHMAD,
    cap=True,
    T_boil=T_BOIL_ATM,
    k_boil=1.0e3,
    width=0.25,
    below_boiling=True,
    T_bed_out=None,
):
    r"""Drying rate with a boiling point (the default drying law), kg water/(s m).

    .. math::
        r_{ev} = \underbrace{\frac{h_t A\,(T_g - T_b)^+}{H_v}
                 \min\!\left(1, \frac{Q_h}{X_c Q_{s,dry}}\right)}_{\text{seed 004, below }T_{boil}}
               + \underbrace{k_b\, m'_h\, w \ln\!\left(1 + e^{(T_b - T_{boil})/w}\right)}_{
                 \text{boiling}}

    Below the boiling point the moisture evaporates at seed 004's critical-moisture rate
    (:func:`ahmad_critical_moisture_drying_rate`: the convective heat from the gas, scaled by
    the moisture content). At the boiling point the second term
    (:func:`boiling_evaporation_rate`) holds the bed temperature and turns all the net heat the
    bed receives (convection, radiation, wall, and the sensible heat of a superheated wet feed)
    into evaporation until the moisture is gone: a bed above its boiling point carries no
    liquid water. The sum is smooth; where one term is active the other is negligible or,
    on the boiling plateau, simply takes less of the heat.

    Parameters
    ----------
    conductance : float or array
        Gas-to-bed heat transfer conductance per length :math:`h_t A`, W/(m K).
    T_gas, T_bed : float or array
        Gas and bed temperatures, K.
    moisture_flow : float or array
        Moisture mass flow :math:`Q_h`, kg/s.
    dry_solid_flow : float or array
        Dry solid mass flow :math:`Q_{s,dry}`, kg/s.
    moisture_holdup : float or array
        Liquid moisture per kiln length :math:`m'_h`, kg/m.
    critical_moisture : float
        Critical moisture content :math:`X_c`, kg water per kg dry solid.
    latent_heat : float
        :math:`H_v`, J/kg.
    cap : bool
        Limit the moisture ratio of the seed-004 term to 1.
    T_boil : float
        Boiling temperature, K (373.15 K at 1 atm).
    k_boil : float
        Boiling rate constant, 1/(s K).
    width : float
        Smoothing width of the boiling term, K.
    below_boiling : bool
        Include the seed-004 term (evaporation below the boiling point).
    T_bed_out : float or array, optional
        Bed temperature at which the boiling term is evaluated, K (default ``T_bed``). A
        discretised kiln passes its cells' outlet-face temperature: with the moisture also
        taken at the outlet, the stiff term is then implicit (backward Euler) and the face
        temperatures plateau without the odd-even oscillation a cell-mean temperature gives.

    Returns
    -------
    float or ndarray
        Evaporation rate, kg/(s m).

    Notes
    -----
    Valid for free (surface and capillary) moisture; bound water and hydrates are not
    modelled. The plateau settles about 3 K below :math:`T_{boil}` with the defaults
    (:func:`boiling_evaporation_rate`).

    Examples
    --------
    >>> r = boiling_drying_rate(20.0, 750.0, 350.0, 3.33e-4, 3.33e-3, 0.3)   # below boiling
    >>> round(r * 1e3, 3)   # g/(s m): seed 004's 20 W/mK * 400 K / 2.2572 MJ/kg
    3.544
    >>> round(boiling_drying_rate(20.0, 750.0, 380.0, 3.33e-4, 3.33e-3, 0.3), 1)  # boiling
    2055.0

    References
    ----------
    Seed-004 term: S. Ahmad, Simulation of Rotary Reactor, M.Tech dissertation, IIT Roorkee
    (2006), 3.2.1, after Kim & Srivastava (1988). Boiling term: see
    :func:`boiling_evaporation_rate` (Haberle et al. 2017; Peters & Bruch 2003).
    """
    t_boiling = T_bed if T_bed_out is None else T_bed_out
    r = boiling_evaporation_rate(t_boiling, moisture_holdup, T_boil, k_boil, width)
    if below_boiling:
        r = r + np.asarray(
            ahmad_critical_moisture_drying_rate(
                conductance,
                T_gas,
                T_bed,
                moisture_flow,
                dry_solid_flow,
                critical_moisture,
                latent_heat,
                cap,
            ),
            dtype=float,
        )
    r = np.asarray(r, dtype=float)
    return r if r.ndim else float(r)
