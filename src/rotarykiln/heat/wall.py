r"""Kiln wall: conduction through lining layers and the shell loss to ambient.

- :func:`cylinder_layer_heat_flow`: exact steady radial conduction with :math:`k(T)` through
  the Kirchhoff potential :math:`K(T) = \int k\,dT`:
  :math:`q' = 2\pi [K(T_i) - K(T_o)]/\ln(r_o/r_i)`.
- :func:`churchill_chu_nusselt`: natural convection from a horizontal cylinder.
- :func:`churchill_bernstein_nusselt`: forced cross-flow (wind).
- :func:`shell_heat_loss`: convection (natural, or mixed with wind by
  :math:`Nu^3 = Nu_F^3 + Nu_N^3`) plus radiation :math:`\varepsilon\sigma(T_{sh}^4-T_\infty^4)`.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative, check_positive, check_range
from rotarykiln.heat.radiation import STEFAN_BOLTZMANN

__all__ = [
    "cylinder_layer_heat_flow",
    "churchill_chu_nusselt",
    "churchill_bernstein_nusselt",
    "shell_heat_loss",
]

G = 9.80665


def cylinder_layer_heat_flow(k_integral_inner, k_integral_outer, r_inner, r_outer, *, check=True):
    r"""Heat flow per unit length through a cylindrical layer with :math:`k(T)`.

    .. math:: q' = \frac{2\pi\,[K(T_i) - K(T_o)]}{\ln(r_o/r_i)}

    Parameters
    ----------
    k_integral_inner, k_integral_outer : float or array, W/m
        Kirchhoff potential :math:`K(T) = \int k\,dT` at the inner and outer faces (see
        :meth:`rotarykiln.materials.lining.LiningMaterial.conductivity_integral`). For constant
        k this is :math:`kT`.
    r_inner : float or array, m
        Inner radius of the layer, > 0.
    r_outer : float or array, m
        Outer radius of the layer, > r_inner.
    check : bool
        Validate the inputs (the kiln's inner loop may pass False).

    Returns
    -------
    float or array, W/m (positive outwards)

    Examples
    --------
    >>> round(float(cylinder_layer_heat_flow(1.0 * 500, 1.0 * 400, 0.5, 0.6)), 1)
    3446.2

    References
    ----------
    Steady radial conduction with the Kirchhoff transform, e.g. Incropera & DeWitt, Fundamentals of
    Heat and Mass Transfer, ch. 3.
    """
    if check:
        check_range("k_integral_inner", k_integral_inner, -np.inf, np.inf, unit="W/m")
        check_range("k_integral_outer", k_integral_outer, -np.inf, np.inf, unit="W/m")
        check_positive("r_inner", r_inner, "m")
        check_positive("r_outer - r_inner", np.asarray(r_outer) - np.asarray(r_inner), "m")
    return (
        2.0
        * np.pi
        * (np.asarray(k_integral_inner) - np.asarray(k_integral_outer))
        / np.log(np.asarray(r_outer) / np.asarray(r_inner))
    )


def churchill_chu_nusselt(rayleigh, prandtl, *, check=True):
    r"""Natural convection from a horizontal isothermal cylinder (Churchill & Chu 1975).

    .. math:: Nu_D = \left[0.60 + \frac{0.387\,Ra_D^{1/6}}
              {[1 + (0.559/Pr)^{9/16}]^{8/27}}\right]^2

    Parameters
    ----------
    rayleigh : float or array, -
        :math:`Ra_D = g\beta\Delta T D^3/(\nu\alpha)`, valid 1e-5 to 1e12.
    prandtl : float or array, -
    check : bool
        Validate the inputs (False: a caller that computed them from validated ones).

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(churchill_chu_nusselt(2.63e9 * 0.69, 0.69)), 2)
    139.13

    References
    ----------
    S.W. Churchill, H.H.S. Chu, Int. J. Heat Mass Transfer 18 (1975) 1049-1053; as in
    CalebBell/ht conv_free_immersed.py.
    """
    if check:
        check_nonnegative("rayleigh", rayleigh)
        check_positive("prandtl", prandtl)
    ra = np.asarray(rayleigh, dtype=float)
    pr = np.asarray(prandtl, dtype=float)
    return (0.60 + 0.387 * ra ** (1 / 6) / (1 + (0.559 / pr) ** (9 / 16)) ** (8 / 27)) ** 2


def churchill_bernstein_nusselt(reynolds, prandtl):
    r"""Forced cross-flow over a cylinder (Churchill & Bernstein 1977).

    .. math:: Nu_D = 0.3 + \frac{0.62 Re^{1/2} Pr^{1/3}}{[1 + (0.4/Pr)^{2/3}]^{1/4}}
              \left[1 + \left(\frac{Re}{282000}\right)^{5/8}\right]^{4/5}

    Parameters
    ----------
    reynolds, prandtl : float or array, -
        Valid for Re Pr > 0.2.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(churchill_bernstein_nusselt(6071.0, 0.7)), 2)
    40.64

    References
    ----------
    S.W. Churchill, M. Bernstein, J. Heat Transfer 99 (1977) 300-306.
    """
    check_nonnegative("reynolds", reynolds)
    check_positive("prandtl", prandtl)
    re = np.asarray(reynolds, dtype=float)
    pr = np.asarray(prandtl, dtype=float)
    return 0.3 + 0.62 * re**0.5 * pr ** (1 / 3) / (1 + (0.4 / pr) ** (2 / 3)) ** 0.25 * (
        1 + (re / 282000.0) ** (5 / 8)
    ) ** (4 / 5)


def shell_heat_loss(
    t_shell, t_ambient, outer_diameter, emissivity, air, wind_speed=0.0, *, check=True
):
    r"""Heat lost by the kiln shell per unit length, convection plus radiation, W/m.

    .. math:: q' = \pi D_o\left[\frac{Nu\,k}{D_o}(T_{sh} - T_\infty)
              + \varepsilon\sigma(T_{sh}^4 - T_\infty^4)\right]

    Convection: Churchill-Chu natural convection, combined with Churchill-Bernstein forced
    convection as :math:`Nu^3 = Nu_N^3 + Nu_F^3` when ``wind_speed`` > 0. Air properties at the
    film temperature, :math:`\beta = 1/T_{film}`.

    Parameters
    ----------
    t_shell, t_ambient : float or array, K
        Shell and ambient temperatures, > 0.
    outer_diameter : float or array, m
        Shell outer diameter, > 0.
    emissivity : float or array, -
        Shell surface emissivity in (0, 1].
    air : GasPropertyTable
        Air properties (:func:`rotarykiln.materials.gas.air_table`).
    wind_speed : float, m/s
        Cross-wind speed, >= 0.
    check : bool
        Validate the inputs (the kiln's inner loop, whose wall was validated when it was
        built and whose temperatures are floored, may pass False).

    Returns
    -------
    float or array, W/m

    Examples
    --------
    >>> from rotarykiln.materials.gas import air_table
    >>> round(float(shell_heat_loss(400.0, 300.0, 0.5, 0.9, air_table())), -1)
    2310.0

    References
    ----------
    S.W. Churchill, H.H.S. Chu, Int. J. Heat Mass Transfer 18 (1975) 1049-1053; S.W. Churchill,
    M. Bernstein, J. Heat Transfer 99 (1977) 300-306; closures.md (shell loss).
    """
    if check:
        check_range("shell.emissivity", emissivity, 0.0, 1.0, closed_high=True)
        check_nonnegative("shell.wind_speed", wind_speed, "m/s")
        check_positive("shell.outer_diameter", outer_diameter, "m")
        check_positive("t_shell", t_shell, "K")
        check_positive("t_ambient", t_ambient, "K")
    ts = np.asarray(t_shell, dtype=float)
    ta = np.asarray(t_ambient, dtype=float)
    tf = 0.5 * (ts + ta)
    cp, k, mu = air.cp_conductivity_viscosity(tf)
    rho = air.density(tf)
    nu = mu / rho
    alpha = k / (rho * cp)
    pr = nu / alpha
    d = np.asarray(outer_diameter, dtype=float)
    # |dT| with a tiny floor keeps Ra > 0 and the derivative smooth near dT = 0
    dt = np.sqrt((ts - ta) ** 2 + 1e-6)
    ra = G * dt / tf * d**3 / (nu * alpha)
    nusselt = churchill_chu_nusselt(ra, pr, check=check)
    if (np.asarray(wind_speed) > 0).any():
        nf = churchill_bernstein_nusselt(rho * wind_speed * d / mu, pr)
        nusselt = np.cbrt(nusselt**3 + nf**3)
    h = nusselt * k / d
    return np.pi * d * (h * (ts - ta) + emissivity * STEFAN_BOLTZMANN * (ts**4 - ta**4))
