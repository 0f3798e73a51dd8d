"""Gaseous fuels: their heating values.

The thermochemistry (molar mass, O2 demand, LHV and HHV, GRI-Mech 3.0 through Cantera, cached
per fuel) is :func:`rotarykiln.materials.gas.fuel_data`; :func:`heating_values` gives the two
heating values of a composition. Solid fuels: :mod:`rotarykiln.chemistry.solid_fuels`.
"""

from __future__ import annotations

from rotarykiln.materials.gas import fuel_data, parse_composition

__all__ = ["heating_values"]


def heating_values(fuel) -> tuple[float, float]:
    """Lower and higher heating values of a gaseous fuel at 298.15 K, J/kg.

    Complete combustion to CO2 and H2O (vapour for the LHV, liquid for the HHV, with the
    enthalpy of vaporisation of water at 298.15 K, 44.0 kJ/mol); Cantera GRI-Mech 3.0
    thermochemistry (:func:`rotarykiln.materials.gas.fuel_data`).

    Parameters
    ----------
    fuel : str or mapping
        Composition by mole, e.g. ``"CH4:1"``.

    Returns
    -------
    lhv, hhv : float, J/kg
        Per kg of fuel.

    Examples
    --------
    >>> lhv, hhv = heating_values("CH4:1")
    >>> round(lhv / 1e6, 2), round(hhv / 1e6, 2)
    (50.03, 55.51)

    References
    ----------
    Cantera GRI-Mech 3.0 thermo; flames.md section 1 (CH4 LHV 50.03 MJ/kg).
    """
    _, _, lhv, hhv = fuel_data(parse_composition(fuel))
    return lhv, hhv
