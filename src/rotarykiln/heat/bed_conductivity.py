r"""Effective (stagnant) conductivity of a packed bed of particles in a gas.

- :func:`maxwell_bed_conductivity` (closures.md 4a): :math:`\phi_s` is the **solids** fraction
  (SimCem passes the void fraction by mistake).
- :func:`zehner_schlunder_bed_conductivity` (closures.md 4b), without radiation.
- :func:`radiative_bed_conductivity`: the radiation between particles, added to either.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_positive, check_range

__all__ = [
    "maxwell_bed_conductivity",
    "zehner_schlunder_bed_conductivity",
    "radiative_bed_conductivity",
]

SIGMA = 5.670374419e-8  # W/(m2 K4)


def maxwell_bed_conductivity(gas_conductivity, solid_conductivity, solid_fraction):
    r"""Maxwell (Eucken) bound for dispersed solid spheres in a continuous gas.

    .. math:: k_b = k_g\,\frac{2k_g + k_s + 2\phi_s(k_s - k_g)}{2k_g + k_s - \phi_s(k_s - k_g)}

    Parameters
    ----------
    gas_conductivity : float or array, W/(m K)
    solid_conductivity : float or array, W/(m K)
    solid_fraction : float or array, -
        Solids volume fraction :math:`1 - \varepsilon`, in [0, 1).

    Returns
    -------
    float or array, W/(m K)

    Examples
    --------
    >>> round(float(maxwell_bed_conductivity(1.0, 50.0, 0.6)), 2)
    4.9

    References
    ----------
    J.C. Maxwell, A Treatise on Electricity and Magnetism (1873); SimCem kiln.hpp (maxwell).
    """
    check_positive("gas_conductivity", gas_conductivity, "W/(m K)")
    check_positive("solid_conductivity", solid_conductivity, "W/(m K)")
    check_range("solid_fraction", solid_fraction, 0.0, 1.0, closed_low=True)
    kg = np.asarray(gas_conductivity, dtype=float)
    ks = np.asarray(solid_conductivity, dtype=float)
    phi = np.asarray(solid_fraction, dtype=float)
    return kg * (2 * kg + ks + 2 * phi * (ks - kg)) / (2 * kg + ks - phi * (ks - kg))


def zehner_schlunder_bed_conductivity(
    gas_conductivity, solid_conductivity, void_fraction, *, shape_factor=1.25
):
    r"""Zehner-Schlunder (1970) stagnant conductivity of a packed bed (no radiation).

    .. math::
        \frac{k_b}{k_g} = 1 - \sqrt{1-\varepsilon} + \sqrt{1-\varepsilon}\,k_c, \quad
        k_c = \frac{2}{N}\left[\frac{B(\kappa-1)}{N^2\kappa}\ln\frac{\kappa}{B}
              - \frac{B+1}{2} - \frac{B-1}{N}\right],

    with :math:`N = 1 - B/\kappa`, :math:`\kappa = k_s/k_g`,
    :math:`B = C((1-\varepsilon)/\varepsilon)^{10/9}`.

    Parameters
    ----------
    gas_conductivity, solid_conductivity : float or array, W/(m K)
    void_fraction : float or array, -
        Bed porosity :math:`\varepsilon` in (0, 1).
    shape_factor : float
        C = 1.25 spheres (1.4 crushed, 2.5 cylinders [memory]).

    Returns
    -------
    float or array, W/(m K)

    Examples
    --------
    >>> round(float(zehner_schlunder_bed_conductivity(1.0, 50.0, 0.4)), 2)
    7.1

    References
    ----------
    P. Zehner, E.U. Schlunder, Chem. Ing. Tech. 42 (1970) 933-941.
    """
    check_positive("gas_conductivity", gas_conductivity, "W/(m K)")
    check_positive("solid_conductivity", solid_conductivity, "W/(m K)")
    check_range("void_fraction", void_fraction, 0.0, 1.0)
    kg = np.asarray(gas_conductivity, dtype=float)
    kappa = np.asarray(solid_conductivity, dtype=float) / kg
    eps = np.asarray(void_fraction, dtype=float)
    B = shape_factor * ((1 - eps) / eps) ** (10.0 / 9.0)
    N = 1 - B / kappa
    kc = (2 / N) * (
        B * (kappa - 1) / (N**2 * kappa) * np.log(kappa / B) - (B + 1) / 2 - (B - 1) / N
    )
    s = np.sqrt(1 - eps)
    return kg * (1 - s + s * kc)


def radiative_bed_conductivity(particle_diameter, temperature, emissivity):
    r"""Conductivity of the radiation across the voids of a packed bed (Damkohler form).

    .. math:: k_r = \frac{4\sigma}{2/\varepsilon - 1}\,d_p\,T^3

    the radiative term of the Zehner-Bauer-Schlunder model without its solid-conduction
    correction (good when :math:`k_s/(4\sigma d_p T^3)` is large): it grows with the particle
    size, so a coarse sand conducts better than a fine one when hot.

    Parameters
    ----------
    particle_diameter : float or array, m
    temperature : float or array, K
    emissivity : float or array, -
        Particle surface emissivity in (0, 1].

    Returns
    -------
    float or array, W/(m K)

    Examples
    --------
    >>> round(float(radiative_bed_conductivity(2.5e-3, 1000.0, 0.9)), 3)
    0.464

    References
    ----------
    G. Damkohler, in Eucken-Jakob, Der Chemie-Ingenieur 3 (1937) 441; P. Zehner,
    E.U. Schlunder, Chem. Ing. Tech. 45 (1973) 272 (the radiation term of the ZBS model; VDI
    Heat Atlas D6.3) [MEMORY: the form 4 sigma/(2/eps - 1) d_p T^3, not in closures.md].
    """
    check_positive("particle_diameter", particle_diameter, "m")
    check_range("emissivity", emissivity, 0.0, 1.0, closed_high=True)
    eps = np.asarray(emissivity, dtype=float)
    t = np.asarray(temperature, dtype=float)
    return 4.0 * SIGMA / (2.0 / eps - 1.0) * particle_diameter * t**3
