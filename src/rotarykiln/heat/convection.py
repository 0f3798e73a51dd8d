r"""Freeboard gas convection to the exposed wall and to the exposed bed surface.

Two families:

- Tscheng & Watkinson (1979): :math:`Nu = h D_e/k_g = a_0 Re^{a_1} Re_\omega^{a_2} f^{a_3}`,
  fitted on Tscheng's pilot kiln (air, sand), with
  :math:`Re = \rho_g u_g D_e/\mu_g` and :math:`Re_\omega = \rho_g \omega D_e^2/\mu_g`
  (:math:`\omega` in rad/s, never rev/s), properties at the bulk gas temperature.
- Gorog, Adams & Brimacombe (1982) as printed in seed 004: an entrance-region pipe-flow form
  for the wall and a dimensional mass-flux form for the bed.

Coefficients and pitfalls: team source folder reference/closures.md sections 1a-1c.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative, check_positive, check_range, warn_out_of_range

__all__ = [
    "tscheng_watkinson_gas_wall_nusselt",
    "tscheng_watkinson_gas_bed_nusselt",
    "gorog_gas_wall_h",
    "gorog_gas_bed_h",
    "gas_reynolds",
    "rotational_reynolds",
]

_TW_SOURCE = "Tscheng & Watkinson (1979)"


def gas_reynolds(mass_flux, hydraulic_diameter, viscosity, *, check=True):
    r"""Axial gas Reynolds number :math:`Re = G D_e/\mu_g`.

    Parameters
    ----------
    mass_flux : float or array, kg/(m2 s)
        Gas mass flow divided by the freeboard area, >= 0.
    hydraulic_diameter : float or array, m
        Freeboard hydraulic diameter :math:`D_e`, > 0.
    viscosity : float or array, Pa s
        Gas dynamic viscosity, > 0.
    check : bool
        Validate the inputs (the kiln's inner loop may pass False).

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(gas_reynolds(0.3, 0.15, 2.7e-5)), 0)
    1667.0

    References
    ----------
    Definition; used with the closures of Tscheng & Watkinson (1979) and Gorog et al. (1982).
    """
    if check:
        check_nonnegative("mass_flux", mass_flux, "kg/(m2 s)")
        check_positive("hydraulic_diameter", hydraulic_diameter, "m")
        check_positive("viscosity", viscosity, "Pa s")
    return np.asarray(mass_flux) * np.asarray(hydraulic_diameter) / np.asarray(viscosity)


def rotational_reynolds(density, omega, hydraulic_diameter, viscosity, *, check=True):
    r"""Rotational Reynolds number :math:`Re_\omega = \rho_g \omega D_e^2/\mu_g`.

    Parameters
    ----------
    density : float or array, kg/m3
        Gas density, > 0.
    omega : float or array, rad/s
        Kiln rotation rate, >= 0 (rad/s: rev/s would be 2 pi too small).
    hydraulic_diameter : float or array, m
        Freeboard hydraulic diameter, > 0.
    viscosity : float or array, Pa s
        Gas dynamic viscosity, > 0.
    check : bool
        Validate the inputs (the kiln's inner loop may pass False).

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(rotational_reynolds(0.7, 0.314, 0.15, 2.7e-5)), 0)
    183.0

    References
    ----------
    S.H. Tscheng, A.P. Watkinson, Can. J. Chem. Eng. 57 (1979) 433-443 (definition).
    """
    if check:
        check_positive("density", density, "kg/m3")
        check_nonnegative("omega", omega, "rad/s")
        check_positive("hydraulic_diameter", hydraulic_diameter, "m")
        check_positive("viscosity", viscosity, "Pa s")
    return (
        np.asarray(density)
        * np.asarray(omega)
        * np.asarray(hydraulic_diameter) ** 2
        / np.asarray(viscosity)
    )


def _check_tw(reynolds, rot_reynolds, check, closure):
    if check:
        check_positive("reynolds", reynolds)
        check_positive("rotational_reynolds", rot_reynolds)
        warn_out_of_range("Re", reynolds, 1600.0, 7800.0, _TW_SOURCE, closure=closure)
        warn_out_of_range("Re_omega", rot_reynolds, 20.0, 800.0, _TW_SOURCE, closure=closure)


def tscheng_watkinson_gas_wall_nusselt(reynolds, rot_reynolds, *, check=True):
    r"""Gas to exposed wall Nusselt number of Tscheng & Watkinson (1979).

    .. math:: Nu_{gw} = \frac{h_{gw} D_e}{k_g} = 1.54\, Re^{0.575}\, Re_\omega^{-0.292}

    Parameters
    ----------
    reynolds : float or array, -
        Axial gas Reynolds number on the freeboard hydraulic diameter.
    rot_reynolds : float or array, -
        Rotational Reynolds number :math:`\rho_g\omega D_e^2/\mu_g`, :math:`\omega` in rad/s.
    check : bool
        Validate inputs and warn (:class:`OutOfRangeWarning`) outside the fitted range.

    Returns
    -------
    float or array, -

    Notes
    -----
    Validity: 1600 < Re < 7800, 20 < Re_omega < 800 (air, sand, pilot kiln 0.19 m ID).

    Examples
    --------
    >>> round(float(tscheng_watkinson_gas_wall_nusselt(3000.0, 200.0)), 2)
    32.73

    References
    ----------
    S.H. Tscheng, A.P. Watkinson, Can. J. Chem. Eng. 57 (1979) 433-443; re-quoted as eqs. 8-9
    of Li et al. (2005) and implemented in SimCem (kiln.hpp).
    """
    _check_tw(reynolds, rot_reynolds, check, "gas_wall.tscheng1979")
    return 1.54 * np.asarray(reynolds) ** 0.575 * np.asarray(rot_reynolds) ** -0.292


def tscheng_watkinson_gas_bed_nusselt(reynolds, rot_reynolds, fill, *, check=True):
    r"""Gas to exposed bed Nusselt number of Tscheng & Watkinson (1979).

    .. math:: Nu_{gb} = \frac{h_{gb} D_e}{k_g} = 0.46\, Re^{0.535}\, Re_\omega^{0.104}\, f^{-0.341}

    Parameters
    ----------
    reynolds, rot_reynolds : float or array, -
        As in :func:`tscheng_watkinson_gas_wall_nusselt`.
    fill : float or array, -
        Fractional fill of the cross-section, in (0, 1).
    check : bool

    Returns
    -------
    float or array, -

    Notes
    -----
    Validity as for the wall form; the fill range of the experiments was about 0.06-0.17.

    Examples
    --------
    >>> round(float(tscheng_watkinson_gas_bed_nusselt(3000.0, 200.0, 0.11)), 2)
    122.8

    References
    ----------
    S.H. Tscheng, A.P. Watkinson, Can. J. Chem. Eng. 57 (1979) 433-443.
    """
    _check_tw(reynolds, rot_reynolds, check, "gas_bed.tscheng1979")
    if check:
        check_range("fill", fill, 0.0, 1.0)
    return (
        0.46
        * np.asarray(reynolds) ** 0.535
        * np.asarray(rot_reynolds) ** 0.104
        * np.asarray(fill) ** -0.341
    )


def gorog_gas_wall_h(conductivity, hydraulic_diameter, reynolds, prandtl, length, *, check=True):
    r"""Gas to wall coefficient, entrance-region pipe flow (Gorog et al. 1982, seed 004).

    .. math:: h_{gw} = 0.036\,\frac{k_g}{D_e}\,Re^{0.8}\,Pr^{0.33}\left(\frac{D_e}{L}\right)^{0.055}

    Parameters
    ----------
    conductivity : float or array, W/(m K)
        Gas conductivity.
    hydraulic_diameter : float or array, m
    reynolds : float or array, -
    prandtl : float or array, -
    length : float, m
        Kiln length.
    check : bool

    Returns
    -------
    float or array, W/(m2 K)

    Notes
    -----
    Turbulent pipe flow, Re > 1e4 (warned below). The exponent 0.055 is the one printed in the
    limestone section of seed 004 (its charcoal section prints 0.035).

    Examples
    --------
    >>> round(float(gorog_gas_wall_h(0.07, 0.3, 2.0e4, 0.7, 5.5)), 2)
    17.56

    References
    ----------
    G.J.P. Gorog, T.N. Adams, J.K. Brimacombe, Metall. Trans. B 13B (1982) 153-163, as printed
    by S. Ahmad, M.Tech thesis, IIT Roorkee (2006), section 4.4.1.
    """
    if check:
        check_positive("length", length, "m")
        check_positive("conductivity", conductivity, "W/(m K)")
        check_positive("hydraulic_diameter", hydraulic_diameter, "m")
        check_positive("reynolds", reynolds)
        check_positive("prandtl", prandtl)
        warn_out_of_range(
            "Re",
            reynolds,
            1.0e4,
            1.0e6,
            "Gorog et al. (1982) pipe-flow form",
            closure="gas_wall.gorog1982",
        )
    return (
        0.036
        * np.asarray(conductivity)
        / np.asarray(hydraulic_diameter)
        * np.asarray(reynolds) ** 0.8
        * np.asarray(prandtl) ** 0.33
        * (np.asarray(hydraulic_diameter) / length) ** 0.055
    )


def gorog_gas_bed_h(mass_flux, *, exponent=0.62, check=True):
    r"""Gas to exposed bed coefficient of the Brimacombe group (dimensional).

    .. math:: h_{gb} = 0.4\,G^{0.62}, \quad G \text{ in } kg/(m^2 h)

    Parameters
    ----------
    mass_flux : float or array, kg/(m2 s)
        Gas mass flux (converted to kg/(m2 h) inside), > 0.
    exponent : float, -
        0.62 (default, the form usually quoted) or 0.8 (as printed in seed 004).
    check : bool
        Validate the inputs.

    Returns
    -------
    float or array, W/(m2 K)

    Examples
    --------
    >>> round(float(gorog_gas_bed_h(1100.0 / 3600.0)), 1)
    30.7

    References
    ----------
    Gorog, Adams & Brimacombe (1982) as quoted by Ahmad (2006); exponent open (closures.md 1b).
    """
    if check:
        check_positive("mass_flux", mass_flux, "kg/(m2 s)")
    return 0.4 * (np.asarray(mass_flux) * 3600.0) ** exponent
