"""Accounts of a converged kiln solve: the energy balance sheet and the exhaust.

:func:`energy_sheet` sorts the heat flows of a solve into a sheet engineers read (fuel input,
heat to the solids, shell and exhaust losses, closure, thermal efficiency);
:func:`exhaust_state` gives the gas leaving the kiln after an air ingress at the feed end has
mixed into it (temperature, flow, dry O2).
"""

from __future__ import annotations

import numpy as np

from rotarykiln.kiln.combustion.flame import AIR
from rotarykiln.materials.gas import parse_composition

__all__ = ["energy_sheet", "exhaust_state"]


def exhaust_state(res, flows, temperature: float) -> tuple[dict, float]:
    """The exhaust leaving the kiln, after the air ingress at the feed end mixes into it.

    A counter-current fired kiln draws air in at its feed-end seal; it mixes with the gas
    leaving there, at constant pressure and enthalpy, outside the kiln's gas balance (the
    profiles are not changed by it). Without an ingress the exhaust is the gas outlet.

    Parameters
    ----------
    res : KilnResidual
        The residual of the solve (its kiln, gas species and gas property model).
    flows : array (n_gas,), kg/s
        Gas species flows leaving the kiln.
    temperature : float, K
        Gas outlet temperature.

    Returns
    -------
    (dict, float)
        ``temperature_K``, ``flow_kg_s``, ``O2_dry_mole_fraction`` (of the exhaust after the
        ingress; 0 without O2; None, with the reason in ``O2_dry_note``, when the exhaust holds
        no dry gas: never NaN), ``air_ingress_kg_s``; and the sensible enthalpy
        of the ingress air above 298.15 K, W (an input of the energy sheet).
    """
    flows = np.maximum(np.asarray(flows, dtype=float), 0.0)
    names = list(res.gas_names)
    flame = res.kiln.firing.flame
    air = flame.burner.exhaust_ingress if flame is not None else None
    q_air = np.zeros(len(names))
    h_in = 0.0
    t_mix = float(temperature)
    if air is not None and air.flow > 0:
        # the burner's air (flame.AIR, by mole), by mass
        air_x = dict(parse_composition(AIR))
        x = np.array([air_x.get(n, 0.0) for n in names])
        w = x * np.array([res.species[n].molar_mass for n in names])
        q_air = air.flow * w / w.sum()
        h_air = res.mixture.species_enthalpy(np.array(air.temperature)) @ q_air
        h_gas = res.mixture.species_enthalpy(np.array(t_mix)) @ flows
        h_in = float(h_air)
        total = flows + q_air
        # temperature of the mixture: invert its enthalpy between the two stream temperatures
        lo, hi = sorted((float(air.temperature), t_mix))
        grid = np.linspace(lo, hi, 2001) if hi > lo else np.array([lo, lo + 1.0])
        h_grid = res.mixture.species_enthalpy(grid) @ total
        t_mix = float(np.interp(h_air + h_gas, h_grid, grid))
    total = flows + q_air
    mm = np.array([res.species[n].molar_mass for n in names])
    moles = total / mm
    dry = float(moles.sum() - (moles[names.index("H2O")] if "H2O" in names else 0.0))
    state = {"temperature_K": t_mix, "flow_kg_s": float(total.sum())}
    if dry > 0.0:  # a dry gas without O2 holds none of it: 0, not undefined
        o2 = moles[names.index("O2")] if "O2" in names else 0.0
        state["O2_dry_mole_fraction"] = float(o2 / dry)
    else:  # nothing but water vapour (or no gas): a dry fraction has no meaning
        state["O2_dry_mole_fraction"] = None
        state["O2_dry_note"] = "undefined: the exhaust holds no dry gas"
    state["air_ingress_kg_s"] = float(q_air.sum())
    return state, h_in


def energy_sheet(
    kiln,
    *,
    solids_in,
    to_solids,
    reaction_heat,
    gas_in,
    exhaust,
    shell_loss,
    release,
    heating=0.0,
    ingress=0.0,
) -> dict:
    """Energy balance sheet of a converged solve, W (and the thermal efficiency, -).

    Inputs: the fuel of a burner (its LHV and, for information, its HHV), the sensible
    enthalpy of the gas and solids streams above 298.15 K and the heat of combustion as the
    model releases it (``combustion_heat_W``: for instant burn-out the enthalpy of the
    products entering at their adiabatic temperature less that of the unburnt streams, the
    heat released along the flame otherwise; it differs from the LHV input only by the
    dissociation of the products, the heat capacity of preheated streams and the gas
    property tables, by < 0.2 %).
    An air ingress mixing into the exhaust outside the kiln (``ingress``, its sensible
    enthalpy, W) is an input, and the exhaust is counted after it.
    Outputs: heat to the solids (sensible, and absorbed by the bed's reactions), shell loss,
    exhaust (sensible enthalpy of the flue gas leaving). ``closure_W`` = in - out.
    ``thermal_efficiency`` = heat to the solids (sensible + reaction) / fuel LHV input, or
    over the heat the gas gives up for a kiln without a burner.
    """
    flame = kiln.firing.flame
    if flame is not None:
        lhv, hhv = float(flame.fuel_lhv), float(flame.fuel_hhv)
        if flame.burns_at_inlet:
            # the products enter at the adiabatic temperature: the heat of combustion is their
            # enthalpy (the model's gas tables) less that of the unburnt streams
            gas_sensible = float(flame.sensible_input)
            combustion = float(gas_in) - gas_sensible
        else:
            combustion, gas_sensible = float(release), float(gas_in)
    else:
        lhv = hhv = 0.0
        combustion, gas_sensible = float(release), float(gas_in)
    useful = to_solids + reaction_heat
    supplied = lhv + heating if lhv > 0 else gas_in - exhaust + release + heating
    total_in = solids_in + gas_sensible + combustion + heating + ingress
    total_out = solids_in + useful + shell_loss + exhaust
    return {
        "fuel_lhv_input_W": lhv,
        "fuel_hhv_input_W": hhv,
        "combustion_heat_W": combustion,
        "electric_heating_W": float(heating),
        "sensible_input_gas_W": gas_sensible,
        "sensible_input_solids_W": float(solids_in),
        "sensible_input_air_ingress_W": float(ingress),
        "heat_to_solids_sensible_W": float(to_solids),
        "heat_to_solids_reaction_W": float(reaction_heat),
        "shell_loss_W": float(shell_loss),
        "exhaust_loss_W": float(exhaust),
        "closure_W": total_in - total_out,
        "closure_relative": (total_in - total_out) / max(abs(total_in), 1.0),
        "thermal_efficiency": useful / supplied if supplied else float("nan"),
    }
