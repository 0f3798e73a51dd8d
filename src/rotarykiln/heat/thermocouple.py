r"""Bare thermocouples in a hot gas: what they read, and the gas temperature behind a reading.

A bare junction in a gas hotter than the surfaces around it reads low: it gains heat by
convection and loses it by radiation. Its steady balance (flames.md section 5) is

.. math:: h\,(T_g - T_{tc}) + \alpha\,q_{abs} =
          \varepsilon_{tc}\,\sigma\,(T_{tc}^4 - T_s^4)

with :math:`h = Nu\,k/d` from Churchill & Bernstein (1977) for a cylinder (the wire or its
sheath, diameter :math:`d`) in cross flow, the gas properties at the film temperature
:math:`(T_g + T_{tc})/2` (the convention of the correlation, Incropera et al. 2007 section 7.4),
:math:`T_s` the temperature of the surfaces the junction sees (their :math:`T^4`-mean) and
:math:`q_{abs}` an optional flux absorbed from a flame, W/m2 of junction surface, already
multiplied by the junction's absorptivity.

It is for comparing a model's gas temperature with bare-thermocouple readings, such as Barr's
gas readings in the UBC pilot kiln: put the model's gas through the thermocouple rather than
the reading through the inverse, and keep the raw gas temperature beside it.

References
----------
S.W. Churchill, M. Bernstein, J. Heat Transfer 99 (1977) 300-306; F.P. Incropera,
D.P. DeWitt, T.L. Bergman, A.S. Lavine, *Fundamentals of Heat and Mass Transfer*, 6th ed.,
Wiley (2007), sections 7.4 and 1.3 (the radiation error of a thermocouple); flames.md
section 5 (the Barr T4 example: 53-82 K for 1.6-6.4 mm junctions of emissivity 0.5-0.8).
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError, check_nonnegative, check_positive, check_range
from rotarykiln.heat.wall import churchill_bernstein_nusselt
from rotarykiln.materials.gas import GasPropertyTable, air_table

__all__ = ["bare_thermocouple_temperature", "gas_temperature_from_thermocouple"]

SIGMA = 5.670374419e-8  # W/(m2 K4)
_ITERATIONS = 50


def _checked(diameter, emissivity, velocity, temperatures):
    check_positive("diameter", diameter, "m")
    check_range("emissivity", emissivity, 0.0, 1.0, closed_high=True)
    check_nonnegative("velocity", velocity, "m/s")
    for name, t in temperatures.items():
        check_positive(name, t, "K")


def _h(gas: GasPropertyTable, t_film, velocity, diameter, pressure):
    """Churchill-Bernstein coefficient of the junction, W/(m2 K), properties at ``t_film``."""
    mu = gas.viscosity(t_film)
    re = gas.density(t_film, pressure) * velocity * diameter / mu
    nu = churchill_bernstein_nusselt(re, gas.prandtl(t_film))
    return nu * gas.conductivity(t_film) / diameter


def bare_thermocouple_temperature(
    t_gas,
    t_surroundings,
    velocity,
    diameter,
    emissivity=0.8,
    *,
    gas: GasPropertyTable | None = None,
    pressure=101325.0,
    absorbed_flux=0.0,
):
    r"""Temperature a bare thermocouple reads in a gas, K (radiation error included).

    .. math:: h(T_f)\,(T_g - T_{tc}) + q_{abs} = \varepsilon\,\sigma\,(T_{tc}^4 - T_s^4),
              \qquad T_f = (T_g + T_{tc})/2

    Solved by Newton's method kept inside its bracket (between :math:`T_s` and :math:`T_g`
    without an absorbed flux), element-wise over broadcast arrays.

    Parameters
    ----------
    t_gas : float or array, K
        Gas temperature.
    t_surroundings : float or array, K
        Radiation temperature of the surfaces the junction sees.
    velocity : float or array, m/s
        Gas velocity across the junction.
    diameter : float or array, m
        Junction (wire or sheath) diameter, > 0.
    emissivity : float or array, -
        Junction emissivity, in (0, 1].
    gas : GasPropertyTable, optional
        Gas properties (default: air, close to a flue gas at high excess air).
    pressure : float, Pa
    absorbed_flux : float or array, W/m2
        Flame radiation absorbed per unit junction surface (>= 0).

    Returns
    -------
    float or array, K
        The reading. Range: Churchill-Bernstein holds for Re Pr > 0.2 (in still gas its
        Nu = 0.3 understates h, natural convection being left out, and so overstates the
        radiation error); the gas table is fitted over 200-3200 K.

    Examples
    --------
    Barr's pilot kiln, trial T4 near the burner (flames.md section 5): gas at 1100 K and
    2.15 m/s, walls at 990 K. A 1.6 mm junction of emissivity 0.5 reads 54 K low, a 6.4 mm one
    of emissivity 0.8 reads 83 K low:

    >>> round(1100.0 - float(bare_thermocouple_temperature(1100.0, 990.0, 2.15, 1.6e-3, 0.5)))
    54
    >>> round(1100.0 - float(bare_thermocouple_temperature(1100.0, 990.0, 2.15, 6.4e-3, 0.8)))
    83

    References
    ----------
    See the module docstring.
    """
    _checked(diameter, emissivity, np.min(velocity), {"t_gas": np.min(t_gas)})
    check_positive("t_surroundings", np.min(t_surroundings), "K")
    check_nonnegative("absorbed_flux", np.min(absorbed_flux), "W/m2")
    gas = gas or air_table()
    tg, ts, u, q = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (t_gas, t_surroundings, velocity, absorbed_flux))
    )
    lo = np.minimum(tg, ts)
    # with an absorbed flux the junction may read above the gas: its radiative equilibrium
    hi = np.maximum(
        np.maximum(tg, ts), (np.maximum(tg, ts) ** 4 + q / (emissivity * SIGMA)) ** 0.25
    )
    t = 0.5 * (lo + hi)
    for _ in range(_ITERATIONS):
        h = _h(gas, 0.5 * (tg + t), u, diameter, pressure)
        f = h * (tg - t) + q - emissivity * SIGMA * (t**4 - ts**4)
        lo = np.where(f > 0, t, lo)  # f falls with t: the root is above t when f > 0
        hi = np.where(f > 0, hi, t)
        newton = t + f / (h + 4.0 * emissivity * SIGMA * t**3)
        t_new = np.where((newton > lo) & (newton < hi), newton, 0.5 * (lo + hi))
        if np.all(np.abs(t_new - t) < 1e-9 * t):
            t = t_new
            break
        t = t_new
    return t if t.ndim else float(t)


def gas_temperature_from_thermocouple(
    t_tc,
    t_surroundings,
    velocity,
    diameter,
    emissivity=0.8,
    *,
    gas: GasPropertyTable | None = None,
    pressure=101325.0,
):
    r"""Gas temperature behind a bare-thermocouple reading, K (the inverse of
    :func:`bare_thermocouple_temperature` without an absorbed flux).

    .. math:: T_g = T_{tc} + \frac{\varepsilon\,\sigma\,(T_{tc}^4 - T_s^4)}{h(T_f)},
              \qquad T_f = (T_g + T_{tc})/2

    by fixed-point iteration on the film temperature (h varies slowly with it, so each step
    contracts the error many times over).

    Parameters
    ----------
    t_tc : float or array, K
        Reading.
    t_surroundings : float or array, K
    velocity : float or array, m/s
    diameter : float or array, m
    emissivity : float or array, -
    gas : GasPropertyTable, optional
    pressure : float, Pa

    Returns
    -------
    float or array, K
        Raises :class:`~rotarykiln.errors.InputError` (field ``t_tc``) for a reading so far
        below hot surroundings that no gas above 0 K gives it.

    Examples
    --------
    >>> t = bare_thermocouple_temperature(1100.0, 990.0, 2.15, 3.2e-3, 0.8)
    >>> round(float(gas_temperature_from_thermocouple(t, 990.0, 2.15, 3.2e-3, 0.8)), 6)
    1100.0

    References
    ----------
    See the module docstring.
    """
    _checked(diameter, emissivity, np.min(velocity), {"t_tc": np.min(t_tc)})
    check_positive("t_surroundings", np.min(t_surroundings), "K")
    gas = gas or air_table()
    tc, ts, u = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (t_tc, t_surroundings, velocity))
    )
    loss = emissivity * SIGMA * (tc**4 - ts**4)
    tg = tc.copy()
    for _ in range(_ITERATIONS):
        tg_new = tc + loss / _h(gas, 0.5 * (tg + tc), u, diameter, pressure)
        if not np.all(tg_new > 0.0):  # hot surroundings, little convection: unreachable
            bad = ~(tg_new > 0.0)
            t_bad, ts_bad = (float(np.broadcast_to(v, bad.shape)[bad].flat[0]) for v in (tc, ts))
            raise InputError(
                "t_tc",
                f"{t_bad:.6g} K",
                f"reachable (surroundings at {ts_bad:.6g} K: no gas above 0 K cools the "
                "junction that far)",
            )
        if np.all(np.abs(tg_new - tg) < 1e-10 * tg):
            tg = tg_new
            break
        tg = tg_new
    return tg if tg.ndim else float(tg)
