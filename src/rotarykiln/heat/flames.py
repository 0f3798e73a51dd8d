r"""Turbulent jet diffusion flames: their length and where along them the fuel burns.

- :func:`hawthorne_flame_length`: the length of a turbulent jet diffusion flame (Hawthorne,
  Weddell & Hottel 1949).
- :func:`burnout_fraction`: the burnt fraction of the fuel along the flame, from self-similar
  velocity and mixture-fraction profiles (flames.md section 2).

The kiln's burner (:mod:`rotarykiln.kiln.combustion.flame`) uses them for the ``burnout``
combustion model.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError, check_positive

__all__ = ["BURNOUT_EXPONENT", "burnout_fraction", "hawthorne_flame_length"]

#: Width ratio squared of the mixture-fraction and velocity profiles of a round jet.
BURNOUT_EXPONENT = 1.4


def burnout_fraction(xi, m: float = BURNOUT_EXPONENT):
    r"""Burnt fraction of the fuel along a turbulent jet flame, self-similar profiles.

    .. math:: X_b(\xi) = \xi^{1+m} + \xi\frac{1+m}{m}(1 - \xi^m),\quad 0 \le \xi \le 1;
              \qquad X_b = 1 \text{ for } \xi > 1

    Parameters
    ----------
    xi : float or array, -
        Distance from the burner over the flame length (clipped to [0, 1]).
    m : float, -
        Ratio of the mixture-fraction to the velocity profile widths, squared (1.4).

    Returns
    -------
    float or array, -
        Burnt fraction.

    Examples
    --------
    >>> [round(float(burnout_fraction(v)), 2) for v in (0.25, 0.5, 1.0)]
    [0.4, 0.72, 1.0]

    References
    ----------
    flames.md section 2 (recommended burn-out profile: Gaussian self-similar velocity and
    mixture-fraction profiles, fast chemistry at the stoichiometric mixture fraction).
    """
    xi = np.clip(np.asarray(xi, dtype=float), 0.0, 1.0)
    return xi ** (1.0 + m) + xi * (1.0 + m) / m * (1.0 - xi**m)


def hawthorne_flame_length(
    nozzle_diameter, c_t, t_flame, t_nozzle, m_surroundings, m_nozzle, alpha_t=1.0
):
    r"""Length of a turbulent jet diffusion flame (Hawthorne, Weddell & Hottel 1949).

    .. math:: \frac{L_f}{d} = \frac{5.3}{C_T}\sqrt{\frac{T_F}{\alpha_T T_N}
              \left[C_T + (1 - C_T)\frac{M_s}{M_N}\right]}

    Parameters
    ----------
    nozzle_diameter : float, m
        Diameter of the nozzle.
    c_t : float, -
        Mole fraction of nozzle fluid in its stoichiometric mixture with the surroundings.
    t_flame, t_nozzle : float, K
        Adiabatic flame temperature of that mixture; temperature of the nozzle fluid.
    m_surroundings, m_nozzle : float, kg/mol
        Molar masses of the surrounding fluid and of the nozzle fluid.
    alpha_t : float, -
        Moles of reactants per mole of products (about 1 for methane and air).

    Returns
    -------
    float, m

    Examples
    --------
    Pure methane into air (C_T = 0.095, T_F = 2225 K): about 200 nozzle diameters.

    >>> round(hawthorne_flame_length(1.0, 0.095, 2225.0, 298.15, 0.02885, 0.016043))
    200

    References
    ----------
    W.R. Hawthorne, D.S. Weddell, H.C. Hottel, 3rd Symp. Combust. (1949) 266-288; flames.md
    section 2.
    """
    check_positive("nozzle_diameter", nozzle_diameter, "m")
    if not 0 < c_t <= 1:
        raise InputError("c_t", c_t, "in (0, 1]")
    ratio = (t_flame / (alpha_t * t_nozzle)) * (c_t + (1.0 - c_t) * m_surroundings / m_nozzle)
    return float(nozzle_diameter * 5.3 / c_t * np.sqrt(ratio))
