r"""Lime and dolomite burning: carbonate equilibria from thermodynamic data, yields, heats.

The equilibrium CO2 pressure of a carbonate decomposition follows from the standard reaction
Gibbs energy of the SimCem database (Holland & Powell 2011 data, one consistent source):

.. math:: p_{eq} = p^\circ \exp\!\left(-\frac{\Delta G^\circ(T)}{\nu_{CO_2} R T}\right),
    \qquad p^\circ = 1\ \mathrm{bar}

for calcite (CaCO3 -> CaO + CO2), magnesite (MgCO3 -> MgO + CO2) and dolomite in its two steps
(half-calcination CaMg(CO3)2 -> CaCO3 + MgO + CO2, and the full CaMg(CO3)2 -> CaO + MgO + 2 CO2).

How this relates to :mod:`rotarykiln.chemistry.calcination`: that module has the empirical
calcite equilibrium of Baker (1962) (and Garcia-Labiano 2002) and the rate laws the kiln uses;
Baker's line is 13 K above the thermodynamic one at 1 atm (1173.6 against 1160 K). This module
adds what Baker does not cover (magnesite, dolomite), the thermodynamic calcite line to compare
with, the product mass balance (yield, residual CO2) and the theoretical heat of burning. Any of
the equilibrium pressures can feed the driving force :math:`1 - p_{CO_2}/p_{eq}` of the rate laws.

Reference note: team source folder reference/cement_lime.md section 4.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from rotarykiln.chemistry.clinker import (
    R_GAS,
    molar_mass,
    simcem_reaction_enthalpy,
    simcem_reaction_gibbs,
)
from rotarykiln.errors import InputError, check_positive, check_range

__all__ = [
    "CARBONATES",
    "P_STANDARD",
    "carbonate_co2_mass_fraction",
    "holland_powell_co2_equilibrium_pressure",
    "holland_powell_equilibrium_temperature",
    "lime_calcination_mass_balance",
    "theoretical_heat_of_lime_burning",
]

#: Standard pressure of the thermodynamic data, Pa.
P_STANDARD = 1.0e5

#: Decompositions: database reaction and moles of CO2 released per mole of reaction.
CARBONATES = {
    "calcite": ("calcination_HP2011", 1),
    "magnesite": ("magnesite_HP2011", 1),
    "dolomite_half": ("dolomite_half_HP2011", 1),
    "dolomite_full": ("dolomite_full_HP2011", 2),
}


def _reaction(carbonate):
    if carbonate not in CARBONATES:
        raise InputError("carbonate", carbonate, "one of " + ", ".join(CARBONATES))
    return CARBONATES[carbonate]


def holland_powell_co2_equilibrium_pressure(T, carbonate="calcite"):
    r"""Equilibrium CO2 pressure of a carbonate decomposition, Holland & Powell (2011) data, Pa.

    .. math:: p_{eq} = p^\circ \exp\!\left(-\frac{\Delta G^\circ(T)}{\nu_{CO_2} R T}\right)

    with :math:`\Delta G^\circ = \sum \nu_i G_i(T)` of the SimCem database (HP2011 entries of
    CaCO3, CaO, MgCO3, MgO, dolomite and CO2) and :math:`p^\circ = 1` bar.

    Parameters
    ----------
    T : float or array, K
        Temperature (the data are fitted over 273-2000 K).
    carbonate : str
        ``calcite``, ``magnesite``, ``dolomite_half`` (-> CaCO3 + MgO + CO2) or
        ``dolomite_full`` (-> CaO + MgO + 2 CO2).

    Returns
    -------
    float or ndarray, Pa

    Notes
    -----
    Calcite: 1 atm at 1160 K, 13 K below Baker (1962). Dolomite half-calcines at equilibrium near
    707 K under 1 atm CO2, far below the 700-750 degC observed: kinetics, not equilibrium, set
    the observed temperature.

    Examples
    --------
    >>> round(holland_powell_co2_equilibrium_pressure(1173.0) / 1e5, 2)
    1.23

    References
    ----------
    T.J.B. Holland, R. Powell, J. Metamorph. Geol. 29 (2011) 333-383, as the HP2011 entries of
    the SimCem 1.0.0 database; team source folder reference/cement_lime.md sections 0.2 and 4.
    """
    name, nu = _reaction(carbonate)
    T = np.asarray(T, dtype=float)
    check_positive("T", T, "K")
    dG = np.asarray(simcem_reaction_gibbs(name, T), dtype=float)
    p = P_STANDARD * np.exp(-dG / (nu * R_GAS * T))
    return p if p.ndim else float(p)


def holland_powell_equilibrium_temperature(p_co2, carbonate="calcite"):
    r"""Temperature at which a carbonate decomposes under a CO2 partial pressure, HP2011, K.

    The root of :math:`p_{eq}(T) = p_{CO_2}` (:func:`holland_powell_co2_equilibrium_pressure`).

    Parameters
    ----------
    p_co2 : float, Pa
        CO2 partial pressure, between 1e-3 and 1e7 Pa.
    carbonate : str
        As in :func:`holland_powell_co2_equilibrium_pressure`.

    Returns
    -------
    float, K

    Examples
    --------
    >>> round(holland_powell_equilibrium_temperature(101325.0))
    1160

    References
    ----------
    Holland & Powell (2011); team source folder reference/cement_lime.md section 4.
    """
    _reaction(carbonate)
    check_range("p_co2", p_co2, 1e-3, 1e7, closed_low=True, closed_high=True, unit="Pa")
    lnp = math.log(float(p_co2))

    def f(T):
        return math.log(holland_powell_co2_equilibrium_pressure(T, carbonate)) - lnp

    return float(brentq(f, 300.0, 2000.0, xtol=1e-9))


def carbonate_co2_mass_fraction(carbonate="calcite"):
    r"""Mass fraction of CO2 in a carbonate, kg CO2 per kg carbonate.

    .. math:: w_{CO_2} = \frac{n\,M_{CO_2}}{M_{carbonate}}

    Parameters
    ----------
    carbonate : str
        ``calcite`` (CaCO3), ``magnesite`` (MgCO3) or ``dolomite`` (CaMg(CO3)2).

    Returns
    -------
    float, -
        0.4397 (calcite), 0.5220 (magnesite), 0.4773 (dolomite); the yield of oxide is
        ``1 - w``.

    Examples
    --------
    >>> round(carbonate_co2_mass_fraction("calcite"), 4)
    0.4397

    References
    ----------
    Stoichiometry with IUPAC atomic weights; team source folder reference/cement_lime.md 4.
    """
    phases = {"calcite": ("CaCO3", 1), "magnesite": ("MgCO3", 1), "dolomite": ("dolomite", 2)}
    if carbonate not in phases:
        raise InputError("carbonate", carbonate, "one of calcite, magnesite, dolomite")
    ph, n = phases[carbonate]
    return n * molar_mass("CO2") / molar_mass(ph)


def lime_calcination_mass_balance(
    CaCO3, MgCO3=0.0, inert=0.0, conversion_ca=1.0, conversion_mg=1.0
):
    r"""Product of burning a limestone or dolomite stone: composition, yield and residual CO2.

    Per kg of dry stone with mass fractions :math:`w_{CaCO_3}, w_{MgCO_3}` (dolomite counted as
    its CaCO3 and MgCO3) and inert :math:`w_i`, converted to the fractions :math:`X_{Ca}, X_{Mg}`:

    .. math::
        m_{CaO} = X_{Ca} w_{CaCO_3} \frac{M_{CaO}}{M_{CaCO_3}},\quad
        m_{CaCO_3} = (1 - X_{Ca}) w_{CaCO_3},\ \ldots,\quad
        \text{yield} = \sum m,\quad CO_2^{res} = \frac{\sum (1-X) w\,w_{CO_2}}{\text{yield}}

    The residual CO2 is the product's loss on ignition from the carbonates (rotary lime LOI
    0.5-1 %; soft-burnt specs often <= 2 % CO2).

    Parameters
    ----------
    CaCO3, MgCO3, inert : float, -
        Mass fractions of the dry stone (sum 1 +- 0.005).
    conversion_ca, conversion_mg : float, -
        Fractions of CaCO3 and MgCO3 decomposed, in [0, 1].

    Returns
    -------
    dict of float
        ``CaO``, ``MgO``, ``CaCO3``, ``MgCO3``, ``inert`` (mass fractions of the product, -),
        ``residual_CO2`` (-), ``yield`` (kg product per kg stone), ``CO2_released`` (kg per kg
        stone).

    Examples
    --------
    >>> b = lime_calcination_mass_balance(0.97, 0.01, 0.02, conversion_ca=0.98)
    >>> round(b["residual_CO2"] * 100, 2), round(b["yield"], 3)
    (1.48, 0.577)

    References
    ----------
    Stoichiometry; typical residual CO2 from the team source folder reference/cement_lime.md 4.
    """
    for name, v in (("CaCO3", CaCO3), ("MgCO3", MgCO3), ("inert", inert)):
        check_range(name, v, 0.0, 1.0, closed_low=True, closed_high=True)
    for name, v in (("conversion_ca", conversion_ca), ("conversion_mg", conversion_mg)):
        check_range(name, v, 0.0, 1.0, closed_low=True, closed_high=True)
    total = CaCO3 + MgCO3 + inert
    if abs(total - 1.0) > 0.005:
        raise InputError(
            "stone (dry basis: CaCO3 + MgCO3 + inert)", f"sum {total:.6g}", "1 +- 0.005"
        )
    wca = carbonate_co2_mass_fraction("calcite")
    wmg = carbonate_co2_mass_fraction("magnesite")
    m = {
        "CaO": conversion_ca * CaCO3 * (1.0 - wca),
        "MgO": conversion_mg * MgCO3 * (1.0 - wmg),
        "CaCO3": (1.0 - conversion_ca) * CaCO3,
        "MgCO3": (1.0 - conversion_mg) * MgCO3,
        "inert": inert,
    }
    y = sum(m.values())
    out = {k: v / y for k, v in m.items()}
    out["residual_CO2"] = (m["CaCO3"] * wca + m["MgCO3"] * wmg) / y
    out["yield"] = y
    out["CO2_released"] = conversion_ca * CaCO3 * wca + conversion_mg * MgCO3 * wmg
    return out


def theoretical_heat_of_lime_burning(CaCO3=1.0, MgCO3=0.0, T=298.15):
    r"""Decomposition enthalpy of a stone per kg of oxide product (HP2011 data), J/kg.

    .. math:: Q = \frac{n_{CaCO_3} \Delta H_{cc}(T) + n_{MgCO_3} \Delta H_{mg}(T)}
        {n_{CaCO_3} M_{CaO} + n_{MgCO_3} M_{MgO}}

    Reaction heat only (reactants and products at :math:`T`), no sensible heat, no losses;
    inert matter is not counted in the product mass.

    Parameters
    ----------
    CaCO3, MgCO3 : float, -
        Mass fractions of the stone (only their ratio matters).
    T : float, K
        Temperature of the reaction.

    Returns
    -------
    float, J/kg
        Per kg of CaO + MgO formed.

    Examples
    --------
    >>> round(theoretical_heat_of_lime_burning() / 1e6, 3)
    3.205

    References
    ----------
    Holland & Powell (2011) via the SimCem database; 3.17 GJ per tonne of lime theoretical
    (sciencelearn.org.nz), team source folder reference/cement_lime.md 0.2 and 6.2.
    """
    check_range("CaCO3", CaCO3, 0.0, 1.0, closed_low=True, closed_high=True)
    check_range("MgCO3", MgCO3, 0.0, 1.0, closed_low=True, closed_high=True)
    if CaCO3 + MgCO3 <= 0.0:
        raise InputError("CaCO3 + MgCO3", CaCO3 + MgCO3, "> 0")
    n_ca = CaCO3 / molar_mass("CaCO3")
    n_mg = MgCO3 / molar_mass("MgCO3")
    q = n_ca * simcem_reaction_enthalpy("calcination_HP2011", T)
    q += n_mg * simcem_reaction_enthalpy("magnesite_HP2011", T)
    return float(q / (n_ca * molar_mass("CaO") + n_mg * molar_mass("MgO")))
