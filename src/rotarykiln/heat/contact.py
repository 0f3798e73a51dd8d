r"""Covered wall to bed heat transfer (the wall under the bed).

- :func:`li_covered_wall_h`: penetration theory plus a gas film (Li et al. 2005),
  :math:`1/h = \chi d_p/k_g + \tfrac12\sqrt{\pi t_c/(k_b\rho_b c_b)}`, :math:`t_c = \Theta/\omega`
  with :math:`\Theta` the **full** bed central angle.
- :func:`tscheng_covered_wall_h`: the empirical fit of Tscheng & Watkinson (1979).
- :func:`wachters_kramers_covered_wall_h`: pure penetration (Li with :math:`\chi = 0`).

Pitfalls (closures.md 2a): published codes use rpm or the half angle (h too high by 3.5-11x).
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative, check_positive, warn_out_of_range

__all__ = [
    "li_film_thickness",
    "li_covered_wall_h",
    "tscheng_covered_wall_h",
    "wachters_kramers_covered_wall_h",
]


def li_film_thickness(particle_diameter, *, check=True):
    r"""Dimensionless gas-film thickness :math:`\chi` of Li et al. (2005), fit to their Fig. 4.

    .. math:: \chi = 0.095 + 0.205\,\exp(-0.0045\,d_p[\mu m])

    Parameters
    ----------
    particle_diameter : float or array, m
    check : bool
        Warn outside 157.5-1038 micrometres.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(li_film_thickness(1038e-6)), 3)
    0.097

    References
    ----------
    Fit given in wallytutor/plug-flow-kiln docs/theory.tex (closures.md 2a).
    """
    dp_um = np.asarray(particle_diameter, dtype=float) * 1e6
    if check:
        check_positive("particle_diameter", particle_diameter, "m")
        warn_out_of_range(
            "d_p [um]",
            dp_um,
            157.5,
            1038.0,
            "Li et al. (2005) chi fit",
            closure="covered_wall.li2005",
        )
    return 0.095 + 0.205 * np.exp(-0.0045 * dp_um)


def wachters_kramers_covered_wall_h(bed_conductivity, rho_c, omega, full_angle, *, check=True):
    r"""Pure penetration (surface renewal) coefficient of the covered wall.

    .. math:: h = 2\sqrt{\frac{k_b \rho_b c_b\,\omega}{\pi\,\Theta}}

    Parameters
    ----------
    bed_conductivity : float or array, W/(m K)
    rho_c : float or array, J/(m3 K)
        Bulk density times specific heat of the bed.
    omega : float or array, rad/s
    full_angle : float or array, rad
        Full central angle :math:`\Theta` subtended by the bed (twice the half-angle).
    check : bool

    Returns
    -------
    float or array, W/(m2 K)

    Examples
    --------
    >>> round(float(wachters_kramers_covered_wall_h(0.3, 1.6e6, 0.2094, 2.0)), 0)
    253.0

    References
    ----------
    Wachters & Kramers (1964), derived as the chi = 0 limit of Li et al. (2005).
    """
    if check:
        for name, v in (("bed_conductivity", bed_conductivity), ("rho_c", rho_c)):
            check_positive(name, v)
        check_positive("omega", omega, "rad/s")
        check_positive("full_angle", full_angle, "rad")
    return 2.0 * np.sqrt(
        np.asarray(bed_conductivity) * np.asarray(rho_c) * omega / (np.pi * np.asarray(full_angle))
    )


def li_covered_wall_h(
    gas_conductivity,
    particle_diameter,
    bed_conductivity,
    rho_c,
    omega,
    full_angle,
    *,
    chi=None,
    check=True,
):
    r"""Covered wall to bed coefficient: penetration theory with a gas film (Li et al. 2005).

    .. math::
        \frac{1}{h_{cwb}} = \frac{\chi d_p}{k_g}
            + \frac{1}{2}\sqrt{\frac{\pi\,\Theta/\omega}{k_b \rho_b c_b}}

    Parameters
    ----------
    gas_conductivity : float or array, W/(m K)
        Conductivity of the gas in the film (at the wall/bed temperature).
    particle_diameter : float or array, m
        Mean particle size, > 0.
    bed_conductivity : float or array, W/(m K)
        Effective bed conductivity.
    rho_c : float or array, J/(m3 K)
        Bulk density times specific heat.
    omega : float or array, rad/s
        Rotation rate.
    full_angle : float or array, rad
        Full bed central angle :math:`\Theta` (twice the geometry half-angle).
    chi : float or array, optional, -
        Film thickness; default :func:`li_film_thickness` of ``particle_diameter``.
    check : bool
        Validate the inputs.

    Returns
    -------
    float or array, W/(m2 K)

    Notes
    -----
    :math:`\chi` ranges 0.096-0.198 in the source.

    Examples
    --------
    >>> round(float(li_covered_wall_h(0.06, 1e-3, 0.3, 1.6e6, 0.2094, 2.0, chi=0.1)), 0)
    178.0

    References
    ----------
    S.-Q. Li, L.-B. Ma, W. Wan, Q. Yao, Chem. Eng. Technol. 28 (2005) 1480-1489 [attribution
    by memory, closures.md 1c]; as implemented in SimCem (h_bed_wall_Li_etal_2005).
    """
    if chi is None:
        chi = li_film_thickness(particle_diameter, check=check)
    if check:
        check_positive("gas_conductivity", gas_conductivity, "W/(m K)")
        check_positive("particle_diameter", particle_diameter, "m")
        check_nonnegative("chi", chi)
    h_pen = wachters_kramers_covered_wall_h(bed_conductivity, rho_c, omega, full_angle, check=check)
    return 1.0 / (np.asarray(chi) * particle_diameter / np.asarray(gas_conductivity) + 1.0 / h_pen)


def tscheng_covered_wall_h(bed_conductivity, rho_c, omega, radius, full_angle, *, check=True):
    r"""Covered wall to bed coefficient of Tscheng & Watkinson (1979), empirical.

    .. math::
        h_{cwb} = 11.6\,\frac{k_b}{R\Theta}
            \left(\frac{\omega R^2 \Theta}{\alpha_b}\right)^{0.3},
        \quad \alpha_b = \frac{k_b}{\rho_b c_b}

    Parameters
    ----------
    bed_conductivity : float or array, W/(m K)
    rho_c : float or array, J/(m3 K)
    omega : float or array, rad/s
    radius : float or array, m
        Kiln inner radius.
    full_angle : float or array, rad
        Full bed central angle.
    check : bool

    Returns
    -------
    float or array, W/(m2 K)

    Notes
    -----
    Fitted at low temperature; no particle-size or gas-film effect.

    Examples
    --------
    >>> round(float(tscheng_covered_wall_h(0.3, 1.6e6, 0.2094, 0.5, 2.0)), 0)
    184.0

    References
    ----------
    S.H. Tscheng, A.P. Watkinson, Can. J. Chem. Eng. 57 (1979) 433-443.
    """
    if check:
        check_positive("bed_conductivity", bed_conductivity, "W/(m K)")
        check_positive("omega", omega, "rad/s")
        check_positive("full_angle", full_angle, "rad")
        check_positive("rho_c", rho_c, "J/(m3 K)")
        check_positive("radius", radius, "m")
    kb = np.asarray(bed_conductivity)
    alpha = kb / np.asarray(rho_c)
    arc = np.asarray(radius) * np.asarray(full_angle)
    return 11.6 * kb / arc * (omega * np.asarray(radius) * arc / alpha) ** 0.3
