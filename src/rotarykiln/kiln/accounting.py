"""Accounts of a kiln: the global balance, the energy balance sheet and the exhaust.

:func:`global_balance` integrates the heat flows of a state over the kiln and across its ends
(the one energy balance, used by the steady solve and by the transient's accounting);
:func:`energy_sheet` sorts the heat flows of a solve into a sheet engineers read (fuel input,
heat to the solids, shell and exhaust losses, closure, thermal efficiency);
:func:`exhaust_state` gives the gas leaving the kiln after an air ingress at the feed end has
mixed into it (temperature, flow, dry O2).
"""

from __future__ import annotations

import numpy as np

from rotarykiln.kiln.gas_mixture import temperature_of_enthalpy
from rotarykiln.materials.gas import AIR, parse_composition

__all__ = ["energy_sheet", "exhaust_state", "global_balance"]


def global_balance(
    res,
    fluxes,
    production,
    tb_n,
    tg_n,
    qb,
    qg,
    inputs=None,
    *,
    bed_enthalpy=None,
    gas_enthalpy=None,
    reaction_from_sources=False,
) -> dict:
    r"""The kiln's global energy balance of a state, W (arrays over the leading batch axis).

    .. math:: E_{in} + Q_{release} + Q_{heating} - E_{out} - Q_{loss} - Q_{reaction}
              = \text{accumulation (0 at steady state)}

    with :math:`E` the sensible enthalpy flows (above 298.15 K) of the solids and the gas
    across the ends, :math:`Q_{reaction} = \int (\dot q_r - \sum_i \dot w_i h_i(\bar T_b))
    dz` the heat the reactions absorb (the gases they release priced at the bed temperature),
    the heat released in the gas, the electric (or jacket) heating and the shell loss
    integrated over the cells.

    Parameters
    ----------
    res : KilnResidual
        The residual of the state (grid, species, property tables;
        :class:`~rotarykiln.kiln.residual.KilnResidual`).
    fluxes : dict
        Per-cell fluxes of :meth:`KilnResidual.evaluate` with ``full`` (W/m; ``t_bed_mean``
        K), arrays (..., n).
    production : array (..., n, n_species), kg/(s m)
        Production by the bed reactions.
    tb_n, tg_n : arrays (..., n + 1), K
        Bed and gas face temperatures.
    qb, qg : arrays (..., n + 1, n_bed) and (..., n + 1, n_gas), kg/s
        Bed and gas species flows at the faces.
    inputs : BoundaryInputs, optional
        The feed (kg/s per bed species) and the solids speed factor (-) of a transient state;
        default the flows of ``qb`` at the feed face, speed factor 1.
    bed_enthalpy : array (..., n + 1, n_bed), J/kg, optional
        The bed species' enthalpies at ``tb_n`` when the caller has them.
    gas_enthalpy : array (..., n + 1, n_gas), J/kg, optional
        The gas species' enthalpies at ``tg_n`` when the caller has them (only the ends'
        are used).
    reaction_from_sources : bool
        Take :math:`Q_{reaction}` from the residual's own chemistry sources in ``fluxes``
        (``-(q_bed_chemistry + q_gas_chemistry - q_source_gas)``, the same integral with the
        enthalpies the residual priced them at) instead of pricing ``production`` again: for
        a caller evaluating the balance at every step (the transient's quadrature); the
        steady solve's check prices it independently.

    Returns
    -------
    dict
        Arrays (...) in W: ``energy_in``, ``energy_out``, ``solids_in``, ``solids_out``,
        ``gas_in``, ``gas_out``, ``shell_loss``, ``release``, ``heating``, ``reaction_heat``,
        and ``net`` (in + release + heating - out - loss - reaction; 0 at steady state).

    Examples
    --------
    >>> from rotarykiln.api import load_case
    >>> from rotarykiln.kiln.from_case import kiln_from_case
    >>> from rotarykiln.kiln.residual import KilnResidual
    >>> from rotarykiln.kiln.steady.solve import solve_kiln
    >>> kiln, _ = kiln_from_case(load_case("tscheng_A16"))
    >>> sol = solve_kiln(kiln, 20)
    >>> res = KilnResidual(kiln, 20)
    >>> _, fl, prod, _, faces = res.evaluate(sol.fluxes["x"], full=True)
    >>> bal = global_balance(res, fl, prod, *faces)
    >>> bool(abs(bal["net"]) < 1e-6 * bal["energy_in"])
    True

    References
    ----------
    The conservative finite-volume balances of the kiln: docs/heat.md, "Energy balance".
    """
    dz = res.dz
    s = 1.0 if inputs is None else inputs.speed_factor
    gi, go = (-1, 0) if res.kiln.gas.counter_current else (0, -1)
    hb = res.bed_enthalpy(tb_n) if bed_enthalpy is None else bed_enthalpy
    batch = tb_n.shape[:-1]
    n = res.n
    if inputs is None:
        solids_in = (qb[..., 0, :] * hb[..., 0, :]).sum(-1)
    else:
        solids_in = hb[..., 0, :] @ inputs.feed
    solids_out = s * (qb[..., -1, :] * hb[..., -1, :]).sum(-1)
    if gas_enthalpy is None:
        ends = tg_n[..., [gi, go]]  # only the ends' gas enthalpies are needed
        hg_in, hg_out = np.moveaxis(res.mixture.species_enthalpy(ends), -2, 0)
    else:
        hg_in, hg_out = gas_enthalpy[..., gi, :], gas_enthalpy[..., go, :]
    gas_in = (qg[..., gi, :] * hg_in).sum(-1)
    gas_out = (qg[..., go, :] * hg_out).sum(-1)

    def total(key):
        v = fluxes.get(key)
        if v is None:
            return np.zeros(batch)  # nothing of the kind: 0 W
        if np.shape(v) != batch + (n,):
            v = np.broadcast_to(v, batch + (n,))
        return v.sum(-1) * dz

    if not res.reacting:
        reaction = np.zeros(batch)
    elif reaction_from_sources:
        chemistry = fluxes["q_bed_chemistry"] + fluxes["q_gas_chemistry"]
        if res.kiln.firing.heat_release > 0:  # the release is part of the gas's source
            chemistry = chemistry - fluxes["q_source_gas"]
        reaction = -np.broadcast_to(chemistry, batch + (n,)).sum(-1) * dz
    else:
        tbm = fluxes["t_bed_mean"]
        h_all = np.zeros_like(production)
        h_all[..., res.bed_idx] = res.bed_enthalpy(tbm)
        h_all[..., res.gas_idx] = res.mixture.species_enthalpy(tbm)
        absorbed = np.broadcast_to(fluxes["q_reaction_absorbed"], batch + (n,))
        reaction = (absorbed - (production * h_all).sum(-1)).sum(-1) * dz
    out = {
        "solids_in": solids_in,
        "solids_out": solids_out,
        "gas_in": gas_in,
        "gas_out": gas_out,
        "energy_in": solids_in + gas_in,
        "energy_out": solids_out + gas_out,
        "shell_loss": total("q_shell_loss"),
        "release": total("q_source_gas"),
        "heating": total("q_electric_heating"),
        "reaction_heat": reaction,
    }
    out["net"] = (
        out["energy_in"]
        + out["release"]
        + out["heating"]
        - out["energy_out"]
        - out["shell_loss"]
        - reaction
    )
    return out


def exhaust_state(res, flows, temperature: float) -> tuple[dict, float]:
    """The exhaust leaving the kiln, after the air ingress at the feed end mixes into it.

    A counter-current fired kiln draws air in at its feed-end seal; it mixes with the gas
    leaving there, at constant pressure and enthalpy, outside the kiln's gas balance (the
    profiles are not changed by it). Without an ingress the exhaust is the gas outlet.

    Parameters
    ----------
    res : KilnResidual
        The residual of the solve (its kiln, gas species and gas property model;
        :class:`~rotarykiln.kiln.residual.KilnResidual`).
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

    Examples
    --------
    >>> from rotarykiln.api import load_case
    >>> from rotarykiln.kiln.from_case import kiln_from_case
    >>> from rotarykiln.kiln.residual import KilnResidual
    >>> kiln, _ = kiln_from_case(load_case("tscheng_A16"))
    >>> res = KilnResidual(kiln, 10)
    >>> state, h_in = exhaust_state(res, res.gas_inlet, 400.0)
    >>> state["temperature_K"], round(state["O2_dry_mole_fraction"], 4), h_in
    (400.0, 0.2095, 0.0)

    References
    ----------
    Mixing at constant pressure and enthalpy; dry-basis O2 as flue-gas analysers report it
    (e.g. VDI 2066 / EN 14789).
    """
    flows = np.maximum(np.asarray(flows, dtype=float), 0.0)
    names = list(res.gas_names)
    flame = res.kiln.firing.flame
    air = flame.burner.exhaust_ingress if flame is not None else None
    q_air = np.zeros(len(names))
    h_in = 0.0
    t_mix = float(temperature)
    if air is not None and air.flow > 0:
        # the burner's air (materials.gas.AIR, by mole), by mass
        air_x = dict(parse_composition(AIR))
        x = np.array([air_x.get(n, 0.0) for n in names])
        w = x * np.array([res.species[n].molar_mass for n in names])
        q_air = air.flow * w / w.sum()
        h_air = res.mixture.species_enthalpy(np.array(air.temperature)) @ q_air
        h_gas = res.mixture.species_enthalpy(np.array(t_mix)) @ flows
        h_in = float(h_air)
        total = flows + q_air
        # temperature of the mixture: its enthalpy inverted between the two stream temperatures
        lo, hi = sorted((float(air.temperature), t_mix))
        t_mix = temperature_of_enthalpy(res.mixture, total, h_air + h_gas, lo, hi, 2001)
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
    An air ingress mixing into the exhaust outside the kiln is an input, and the exhaust is
    counted after it. Outputs: heat to the solids (sensible, and absorbed by the bed's
    reactions), shell loss, exhaust (sensible enthalpy of the flue gas leaving).
    ``closure_W`` = in - out. ``thermal_efficiency`` = heat to the solids (sensible +
    reaction) / fuel LHV input, or over the heat the gas gives up for a kiln without a burner.

    Parameters
    ----------
    kiln : Kiln
        The kiln solved (its burner's flame, if any).
    solids_in : float, W
        Sensible enthalpy of the feed.
    to_solids : float, W
        Sensible heat gained by the solids.
    reaction_heat : float, W
        Heat absorbed by the bed's reactions.
    gas_in : float, W
        Sensible enthalpy of the inlet gas (the burner's products).
    exhaust : float, W
        Sensible enthalpy of the exhaust (after an ingress).
    shell_loss : float, W
        Heat lost through the shell.
    release : float, W
        Heat released in the gas along the kiln.
    heating : float, W
        Electric or jacket heating.
    ingress : float, W
        Sensible enthalpy of the air ingress.

    Returns
    -------
    dict
        The sheet's terms in W (``*_W``), ``closure_relative`` and ``thermal_efficiency`` (-).

    Examples
    --------
    >>> from rotarykiln.api import load_case
    >>> from rotarykiln.kiln.from_case import kiln_from_case
    >>> kiln, _ = kiln_from_case(load_case("tscheng_A16"))
    >>> s = energy_sheet(kiln, solids_in=0.0, to_solids=400.0, reaction_heat=0.0,
    ...     gas_in=1000.0, exhaust=500.0, shell_loss=100.0, release=0.0)
    >>> s["closure_W"], s["thermal_efficiency"]
    (0.0, 0.8)

    References
    ----------
    The kiln energy balance as plant audits draw it: K.E. Peray, The Rotary Cement Kiln, 2nd
    ed. (1986), ch. 11 (heat balance); docs/heat.md.
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
