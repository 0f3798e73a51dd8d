r"""Gas-phase (freeboard) reactions: global Arrhenius kinetics per freeboard volume.

Combustibles in the freeboard (CO, CH4, H2 released by the bed, or left by a burner) burn where
oxygen is present, at the rate of a global kinetic step evaluated at the gas temperature and
the local composition:

.. math:: r = A\,T^b \exp\!\left(-\frac{E}{RT_g}\right)\prod_k c_k^{n_k}
          \quad [\mathrm{mol/(m^3\,s)}],\qquad
          c_k = \frac{p_k}{R T_g}\quad [\mathrm{mol/m^3}]

per kiln length :math:`\dot m_b = r\,A_{fb}\,M_b` (kg of basis per second and metre, with
:math:`A_{fb}` the freeboard cross-section). A negative order (Westbrook & Dryer's methane step)
uses :math:`\max(c, c_{floor})^{n}\,c/(c + c_{floor})`, so the rate still vanishes when the
species is used up. The water-gas shift is written as two irreversible steps, forward
(Jones & Lindstedt 1988) and reverse with the equilibrium constant from the standard Gibbs
energies (:func:`shift_equilibrium_constant`), so the pair relaxes to the shift equilibrium.

Rate laws registered here (for reaction YAML, ``phase: gas``):

- ``gas_arrhenius``: the formula above with ``A`` (SI: mol, m3, s), ``b``, ``E`` (J/mol),
  ``orders`` (species -> order) and ``c_floor`` (mol/m3);
- ``wgs_reverse_equilibrium``: :math:`k_f/K(T)\,[CO_2][H_2]` with the forward constant of
  ``gas_arrhenius``' parameters.

The built-in reactions are in ``reactions/gas_phase.yaml`` (Westbrook & Dryer 1981 CO and CH4
oxidation; Jones & Lindstedt 1988 water-gas shift), with their constants converted from the
cm-mol-s units of the sources (factor :math:`10^{6(1-\sum n)}`).

References
----------
C.K. Westbrook, F.L. Dryer, Combust. Sci. Technol. 27 (1981) 31-43; W.P. Jones,
R.P. Lindstedt, Combust. Flame 73 (1988) 233-249; GRI-Mech 3.0 thermochemistry (shift
equilibrium); flames.md section 3 (the constants as read in open kiln/CFD codes).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from rotarykiln.chemistry.ratelaws import register_rate_law
from rotarykiln.errors import InputError

__all__ = ["gas_arrhenius_rate", "shift_equilibrium_constant", "R_GAS"]

R_GAS = 8.314462618  # J/(mol K)


@lru_cache(maxsize=1)
def _shift_table():
    """ln K of the shift on 250-3500 K from the GRI-Mech 3.0 standard Gibbs energies."""
    import cantera as ct

    g = ct.Solution("gri30.yaml")
    T = np.arange(250.0, 3501.0, 10.0)
    nu = {"CO2": 1.0, "H2": 1.0, "CO": -1.0, "H2O": -1.0}
    dg = np.zeros_like(T)
    for name, v in nu.items():
        k = g.species_index(name)
        sp = g.species(k)
        dg += v * np.array([sp.thermo.h(t) - t * sp.thermo.s(t) for t in T])  # J/kmol
    return T, -dg / (ct.gas_constant * T)


def shift_equilibrium_constant(T):
    r"""Equilibrium constant of the water-gas shift CO + H2O = CO2 + H2.

    .. math:: K(T) = \exp\left(-\frac{\Delta G^\circ(T)}{RT}\right)
              = \frac{c_{CO_2}\,c_{H_2}}{c_{CO}\,c_{H_2O}}

    from the standard Gibbs energies of GRI-Mech 3.0 (NASA polynomials), tabulated every
    10 K on 250-3500 K and interpolated in ln K.

    Parameters
    ----------
    T : float or array, K

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(shift_equilibrium_constant(1100.0)), 2)  # K = 1 near 1090 K
    0.99

    References
    ----------
    GRI-Mech 3.0 thermochemistry (Smith et al.), through Cantera; the two-constant fit
    K = exp(4577.8/T - 4.33) of Moe (1962) is within 15-25 % of it.
    """
    tab_T, tab_lnk = _shift_table()
    return np.exp(np.interp(np.asarray(T, dtype=float), tab_T, tab_lnk))


def gas_arrhenius_rate(T, concentrations: dict, A, b, E, orders: dict, c_floor=1e-6):
    r"""Global Arrhenius rate of a gas-phase step, mol/(m3 s).

    .. math:: r = A\,T^b e^{-E/(RT)}\prod_k \tilde c_k^{\,n_k},\qquad
              \tilde c_k = c_k\ (n_k \ge 0),\quad
              \tilde c_k = \max(c_k, c_f)^{n_k}\frac{c_k}{c_k + c_f}\ (n_k < 0)

    Parameters
    ----------
    T : array, K
        Gas temperature.
    concentrations : dict
        Species -> concentration, mol/m3 (arrays like T).
    A : float
        Pre-exponential factor in mol, m3, s units.
    b : float
        Temperature exponent, -.
    E : float
        Activation energy, J/mol.
    orders : dict
        Species -> reaction order, -.
    c_floor : float, mol/m3
        Concentration floor of negative orders.

    Returns
    -------
    array, mol/(m3 s)

    Examples
    --------
    CO oxidation of Westbrook & Dryer at 1000 K, x_CO = 0.01, x_O2 = x_H2O = 0.1, 1 atm:

    >>> c = 101325 / (8.314462618 * 1000.0)
    >>> r = gas_arrhenius_rate(np.array([1000.0]), {"CO": 0.01 * c, "O2": 0.1 * c,
    ...                        "H2O": 0.1 * c}, 3.98e14 * 10**-4.5, 0.0, 40000 * 4.184,
    ...                        {"CO": 1.0, "O2": 0.25, "H2O": 0.5})
    >>> round(float(0.01 * c / r[0]), 3)  # time constant, s (flames.md: 0.04 s)
    0.038

    References
    ----------
    C.K. Westbrook, F.L. Dryer, Combust. Sci. Technol. 27 (1981) 31-43.
    """
    T = np.asarray(T, dtype=float)
    r = A * T**b * np.exp(-E / (R_GAS * T))
    for name, n in orders.items():
        c = np.maximum(np.asarray(concentrations.get(name, 0.0), dtype=float), 0.0)
        if n >= 0:
            r = r * c**n
        else:
            r = r * np.maximum(c, c_floor) ** n * c / (c + c_floor)
    return r


def _concentrations(ctx, orders) -> dict:
    c_tot = 1.0 / (R_GAS * np.maximum(ctx.T_gas, 1.0))
    return {name: ctx.p(name) * c_tot for name in orders}


def _checked_orders(p, law) -> dict:
    orders = p["orders"]
    for k, v in orders.items():
        if not isinstance(v, int | float) or isinstance(v, bool) or not np.isfinite(v):
            raise InputError(f"rate.orders.{k}", v, f"a finite number (rate law {law})")
    return orders


def _per_length(ctx, basis, r):
    area = ctx.input("freeboard_area", "gas-phase rate laws")
    return r * area * ctx.species[basis].molar_mass


_DEFAULTS = {"A": 1.0, "b": 0.0, "E": 0.0, "orders": {}, "c_floor": 1e-6}


@register_rate_law("gas_arrhenius", _DEFAULTS, "global Arrhenius step in the freeboard gas")
def _gas_arrhenius(ctx, basis, p):
    orders = _checked_orders(p, "gas_arrhenius")
    c = _concentrations(ctx, orders)
    r = gas_arrhenius_rate(ctx.T_gas, c, p["A"], p["b"], p["E"], orders, p["c_floor"])
    return _per_length(ctx, basis, r)


@register_rate_law(
    "wgs_reverse_equilibrium", _DEFAULTS, "reverse water-gas shift, K from GRI-Mech 3.0 thermo"
)
def _wgs_reverse(ctx, basis, p):
    orders = {"CO2": 1.0, "H2": 1.0}
    c = _concentrations(ctx, orders)
    k = p["A"] * ctx.T_gas ** p["b"] * np.exp(-p["E"] / (R_GAS * ctx.T_gas))
    r = k / shift_equilibrium_constant(ctx.T_gas) * np.maximum(c["CO2"], 0) * np.maximum(c["H2"], 0)
    return _per_length(ctx, basis, r)
