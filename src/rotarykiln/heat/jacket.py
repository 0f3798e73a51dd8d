r"""Heating jacket: a gas in the annulus around a drum heating the drum wall.

- :func:`gnielinski_annulus_nusselt`: turbulent forced convection at the inner wall of a
  concentric annulus (Gnielinski 2009).
- :func:`shah_london_annulus_nusselt`: fully developed laminar flow, the same boundary
  conditions (Shah & London 1978, as fitted in the VDI Heat Atlas G2).
- :func:`annulus_heat_transfer_coefficient`: the jacket gas to drum coefficient from the gas
  properties: laminar, a linear transition in Re between 2300 and 10^4, turbulent.
- :func:`jacket_radiation_conductance`: radiation of the jacket gas and of the re-radiating
  casing to the drum (VDI Heat Atlas K1).

The kiln's jacket model (:mod:`rotarykiln.kiln.wall.jacket`) combines them with the drum wall's
conduction.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_positive, check_range, warn_out_of_range
from rotarykiln.heat.radiation import STEFAN_BOLTZMANN

__all__ = [
    "gnielinski_annulus_nusselt",
    "shah_london_annulus_nusselt",
    "annulus_heat_transfer_coefficient",
    "jacket_radiation_conductance",
]


def _gnielinski(r, pr, a):
    """Turbulent annulus Nusselt number (unchecked; see :func:`gnielinski_annulus_nusselt`)."""
    la = np.log(a)
    re_star = r * ((1 + a * a) * la + 1 - a * a) / ((1 - a) ** 2 * la)
    f = (1.8 * np.log10(re_star) - 1.5) ** -2
    k1 = 1.07 + 900.0 / r - 0.63 / (1.0 + 10.0 * pr)
    return (
        (f / 8)
        * (r - 1000)
        * pr
        / (k1 + 12.7 * np.sqrt(f / 8) * (pr ** (2 / 3) - 1))
        * (0.75 * a**-0.17)
    )


def _shah_london(a):
    """Laminar annulus Nusselt number (unchecked; see :func:`shah_london_annulus_nusselt`)."""
    return 3.66 + 1.2 * a**-0.8


def gnielinski_annulus_nusselt(reynolds, prandtl, diameter_ratio, *, check=True):
    r"""Turbulent Nusselt number at the heated inner wall of an annulus (Gnielinski 2009).

    Outer wall insulated, fully developed flow, :math:`Nu = h d_h / k` with :math:`d_h = d_o -
    d_i`:

    .. math:: Nu_t = \frac{(f/8)(Re - 1000)Pr}{k_1 + 12.7\sqrt{f/8}(Pr^{2/3} - 1)}
              \,0.75\,a^{-0.17},\quad f = (1.8\log_{10}Re_* - 1.5)^{-2},\quad
              k_1 = 1.07 + 900/Re - 0.63/(1 + 10 Pr)

    with :math:`Re_* = Re\,[(1 + a^2)\ln a + 1 - a^2]/[(1 - a)^2 \ln a]`.

    Parameters
    ----------
    reynolds : float or array, -
        Reynolds number on the hydraulic diameter (validated 10^4 to 10^6).
    prandtl : float or array, -
        Prandtl number of the gas (validated 0.1 to 1000).
    diameter_ratio : float, -
        :math:`a = d_i / d_o`, inner over outer diameter of the annulus, in (0, 1).
    check : bool
        Validate the inputs and warn outside the validated ranges.

    Returns
    -------
    float or array, -
        Nusselt number on the hydraulic diameter.

    Examples
    --------
    >>> round(float(gnielinski_annulus_nusselt(2e4, 0.7, 0.41 / 0.51)), 2)
    42.08

    References
    ----------
    V. Gnielinski, Heat transfer coefficients for turbulent flow in concentric annular ducts,
    Int. J. Heat Mass Transfer 52 (2009) 4447-4456; VDI Heat Atlas, 2nd ed. (2010) G2.
    """
    if check:
        check_positive("reynolds", reynolds)
        check_positive("prandtl", prandtl)
        check_range("diameter_ratio", diameter_ratio, 0.0, 1.0)
        warn_out_of_range("Re", reynolds, 1e4, 1e6, "Gnielinski (2009)")
        warn_out_of_range("Pr", prandtl, 0.1, 1000.0, "Gnielinski (2009)")
    r = np.asarray(reynolds, dtype=float)
    pr = np.asarray(prandtl, dtype=float)
    return _gnielinski(r, pr, float(diameter_ratio))


def shah_london_annulus_nusselt(diameter_ratio, *, check=True):
    r"""Laminar Nusselt number at the heated inner wall of an annulus, fully developed flow.

    Outer wall insulated, :math:`Nu = h d_h / k` with :math:`d_h = d_o - d_i`:

    .. math:: Nu_l = 3.66 + 1.2\,a^{-0.8}

    a fit of Shah & London's solutions (VDI Heat Atlas G2).

    Parameters
    ----------
    diameter_ratio : float or array, -
        :math:`a = d_i / d_o`, inner over outer diameter of the annulus, in (0, 1].
    check : bool
        Validate the input.

    Returns
    -------
    float or array, -
        Nusselt number on the hydraulic diameter.

    Examples
    --------
    >>> round(float(shah_london_annulus_nusselt(0.41 / 0.51)), 3)
    5.089

    References
    ----------
    R.K. Shah, A.L. London, Laminar Flow Forced Convection in Ducts, Academic Press (1978);
    VDI Heat Atlas, 2nd ed. (2010) G2.
    """
    if check:
        check_range("diameter_ratio", diameter_ratio, 0.0, 1.0, closed_high=True)
    return _shah_london(np.asarray(diameter_ratio, dtype=float))


def annulus_heat_transfer_coefficient(
    mass_flow, inner_diameter, gap, temperature, *, gas=None, check=True
):
    r"""Gas to inner wall heat transfer coefficient of a concentric annulus, W/(m2 K).

    Hydraulic diameter :math:`d_h = 2s` (gap s), :math:`a = d_i/d_o`,
    :math:`Re = \dot m d_h/(A\mu)`: laminar :math:`Nu_l` (:func:`shah_london_annulus_nusselt`)
    up to Re 2300, turbulent :math:`Nu_t` (:func:`gnielinski_annulus_nusselt`) from 10^4, and
    between them linear in Re from :math:`Nu_l` to :math:`Nu_t(10^4)` (VDI G2 / Gnielinski
    1995 transition), never below :math:`Nu_l`; :math:`h = Nu\,k/d_h`.

    Parameters
    ----------
    mass_flow : float, kg/s
        Jacket gas flow.
    inner_diameter : float, m
        Outer diameter of the drum (the annulus' inner wall).
    gap : float, m
        Radial width of the annulus (> 0).
    temperature : float or array, K
        Gas temperature (properties).
    gas : GasPropertyTable, optional
        Gas properties (default: flue gas of natural gas with 20 % excess air, approximated by
        air; the difference in k and mu is a few %).
    check : bool
        Validate the inputs and warn outside the validated Prandtl numbers.

    Returns
    -------
    float or array, W/(m2 K)

    Notes
    -----
    Valid for :math:`0.1 \le Pr \le 1000` and :math:`a` 0.05-1 (Gnielinski 2009); developed
    flow (the entrance effect is neglected: conservative); radiation from a radiating flue gas
    or from a hot casing to the drum is not included (:func:`jacket_radiation_conductance`).

    Examples
    --------
    The rotaryPyrolysis flue gas (175 kg/h) around a 0.41 m drum with a 50 mm gap, at 700 K:

    >>> round(float(annulus_heat_transfer_coefficient(175 / 3600, 0.41, 0.05, 700.0)), 2)
    2.63

    References
    ----------
    V. Gnielinski, Int. J. Heat Mass Transfer 52 (2009) 4447-4456; VDI Heat Atlas, 2nd ed.
    (2010) G2; R.K. Shah, A.L. London (1978).
    """
    from rotarykiln.materials.gas import air_table

    if check:
        check_positive("jacket.mass_flow", mass_flow, "kg/s")
        check_positive("jacket.inner_diameter", inner_diameter, "m")
        check_positive("jacket.gap", gap, "m")
    gas = gas or air_table()
    T = np.asarray(temperature, dtype=float)
    k, mu, cp = gas.conductivity(T), gas.viscosity(T), gas.cp(T)
    d_i, d_o = inner_diameter, inner_diameter + 2.0 * gap
    a = d_i / d_o
    dh = 2.0 * gap
    area = np.pi / 4.0 * (d_o**2 - d_i**2)
    re = mass_flow * dh / (area * mu)
    pr = cp * mu / k
    nu_l = _shah_london(a)
    nu_t = _gnielinski(np.maximum(re, 1e4), pr, a)
    g = np.clip((re - 2300.0) / (1e4 - 2300.0), 0.0, 1.0)
    nu = np.where(re >= 1e4, nu_t, nu_l + g * (_gnielinski(1e4, pr, a) - nu_l))
    nu = np.maximum(nu, nu_l)
    if check:
        warn_out_of_range("jacket Prandtl number", pr, 0.1, 1000.0, "Gnielinski (2009)")
    h = nu * k / dh
    return h if np.ndim(h) else float(h)


def jacket_radiation_conductance(
    t_gas, t_drum, drum_diameter, gap, *, eps_drum=0.8, eps_casing=0.8, eps_gas=0.0
):
    r"""Radiative conductance from the jacket gas to the drum, per metre, W/(m K).

    Two parallel paths (VDI Heat Atlas K1; Hottel's re-radiating surface): the gas radiates to
    the drum directly, and the casing, heated by the gas by convection and losing little to the
    outside, re-radiates to the drum. Linearised about the mean temperature
    :math:`\bar T = (T_g + T_d)/2`, with :math:`h_r = 4\sigma\bar T^3`:

    .. math:: G_{gas} = \varepsilon_g h_r P_d,\qquad
              G_{casing} = \frac{h_r}{\frac{1 - \varepsilon_d}{\varepsilon_d P_d} + \frac{1}{P_d}
              + \frac{1 - \varepsilon_c}{\varepsilon_c P_c}}

    :math:`G_{casing}` is in series with the gas-to-casing convection (see
    :class:`rotarykiln.kiln.wall.jacket.JacketWall`).

    Parameters
    ----------
    t_gas, t_drum : float or array, K
        Jacket gas and drum outer surface temperatures.
    drum_diameter : float, m
        Outer diameter of the drum.
    gap : float, m
        Width of the annulus (casing diameter = drum + 2 gap).
    eps_drum, eps_casing : float, -
        Emissivities of the drum's outer surface and the casing's inner surface.
    eps_gas : float or array, -
        Grey emissivity of the jacket gas over the mean beam length :math:`1.8 s` of the gap.

    Returns
    -------
    (G_gas, G_casing) : floats or arrays, W/(m K)

    Examples
    --------
    >>> g, c = jacket_radiation_conductance(800.0, 700.0, 0.41, 0.05)
    >>> round(float(c), 2)   # per metre of kiln
    84.94

    References
    ----------
    VDI Heat Atlas, 2nd ed. (2010) K1; H.C. Hottel, A.F. Sarofim, Radiative Transfer (1967).
    """
    tm = 0.5 * (np.asarray(t_gas, dtype=float) + np.asarray(t_drum, dtype=float))
    hr = 4.0 * STEFAN_BOLTZMANN * tm**3
    p_d = np.pi * drum_diameter
    p_c = np.pi * (drum_diameter + 2.0 * gap)
    r_rad = (
        (1.0 - eps_drum) / (eps_drum * p_d) + 1.0 / p_d + (1.0 - eps_casing) / (eps_casing * p_c)
    )
    return eps_gas * hr * p_d, hr / r_rad
