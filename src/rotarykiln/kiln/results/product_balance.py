r"""Product and fuel balance of a solved lime kiln: what a lime engineer reads off a kiln.

:func:`lime_kiln_balance` takes a solved kiln burning limestone or dolomite
(:class:`~rotarykiln.kiln.results.solution.KilnSolution`) and gives the product at the discharge
(flow, CaO content, residual carbonate, loss on ignition), the CO2 the stone released, the
specific heat consumption (fuel LHV per kg of product) and the temperatures an operator watches
(exhaust, hottest bed, hottest shell). The stone's chemistry (yields, CO2 fractions) is that of
:mod:`rotarykiln.chemistry.lime`.

References
----------
Team source folder reference/cement_lime.md sections 4 (lime: residual CO2 / LOI 0.5-1 % of
rotary lime) and 6.2 (lime kilns: specific heat consumption per tonne of lime).
"""

from __future__ import annotations

import math

import numpy as np

from rotarykiln.chemistry.lime import carbonate_co2_mass_fraction
from rotarykiln.chemistry.ratelaws import MOISTURE

__all__ = ["CARBONATE_SPECIES", "lime_kiln_balance"]

#: Bed species that hold CO2 bound as carbonate -> the carbonate of
#: :func:`~rotarykiln.chemistry.lime.carbonate_co2_mass_fraction`.
CARBONATE_SPECIES = {"CaCO3": "calcite", "MgCO3": "magnesite", "dolomite": "dolomite"}


def lime_kiln_balance(solution) -> dict:
    r"""Lime product, CO2 released and specific heat consumption of a solved lime kiln.

    With :math:`\dot m_i(0)`, :math:`\dot m_i(L)` the bed flows of species :math:`i` at the feed
    end and at the discharge, :math:`w_c` the CO2 mass fraction of carbonate :math:`c`
    (CaCO3 0.4397, MgCO3 0.5220, dolomite 0.4773) and :math:`\dot Q_{LHV}` the fuel's LHV input:

    .. math::
        \dot m_P = \sum_i \dot m_i(L),\qquad
        x_{CO_2} = \frac{\sum_c w_c\,\dot m_c(L)}{\dot m_P},\qquad
        LOI = x_{CO_2} + \frac{\dot m_{H_2O}(L)}{\dot m_P}

    .. math::
        \dot m_{CO_2} = \sum_c w_c\,[\dot m_c(0) - \dot m_c(L)],\qquad
        SHC = \frac{\dot Q_{LHV}}{\dot m_P}

    The loss on ignition is the residual carbonate CO2 plus any water left in the bed (none at
    lime-kiln temperatures); hydrates are not modelled. The CO2 released counts the carbonate
    CO2 the bed lost, so a carbonate made in the kiln (the CaCO3 of half-burnt dolomite) is
    counted where it finally decomposes.

    Parameters
    ----------
    solution : KilnSolution
        A solved kiln (:func:`~rotarykiln.kiln.steady.solve.solve_kiln`), or any object with
        its fields ``bed_flows`` (species -> kg/s at the faces, z = 0 the feed end),
        ``t_bed_nodes``, ``t_gas_nodes`` (K), ``burner`` and ``exhaust`` (dicts), ``t_shell``
        (K per cell, or None) and ``counter_current``.

    Returns
    -------
    dict
        ``product_flow_kg_s`` (kg/s), ``composition`` (species -> mass fraction of the product,
        -), ``CaO_mass_fraction``, ``CaCO3_mass_fraction``, ``residual_CO2_mass_fraction``,
        ``loss_on_ignition`` (-), ``conversion_CaCO3`` (-, NaN without CaCO3 fed),
        ``CO2_released_kg_s`` (kg/s), ``CO2_released_per_feed`` (kg per kg of solids fed),
        ``fuel_lhv_input_W`` (W, NaN without a burner), ``specific_heat_consumption_J_kg``
        (J per kg of product), ``exhaust_temperature_K``, ``bed_outlet_temperature_K``,
        ``bed_max_temperature_K``, ``shell_max_temperature_K`` (K; NaN without a lined wall).

    Examples
    --------
    Hand numbers: 1 kg/s of stone (0.97 CaCO3 + 0.03 inert) leaving with 0.01 kg/s of CaCO3,
    fired with 3.5 MW:

    >>> from types import SimpleNamespace
    >>> sol = SimpleNamespace(
    ...     bed_flows={"CaCO3": np.array([0.97, 0.01]), "CaO": np.array([0.0, 0.537877]),
    ...                "inert": np.array([0.03, 0.03])},
    ...     t_bed_nodes=np.array([298.15, 1400.0]), t_gas_nodes=np.array([1100.0, 600.0]),
    ...     burner={"fuel_lhv_input_W": 3.5e6}, exhaust={},
    ...     t_shell=np.array([450.0, 520.0]), counter_current=True)
    >>> b = lime_kiln_balance(sol)
    >>> round(b["product_flow_kg_s"], 6), round(100 * b["loss_on_ignition"], 3)
    (0.577877, 0.761)
    >>> round(b["CO2_released_kg_s"], 5), round(b["specific_heat_consumption_J_kg"] / 1e6, 3)
    (0.42212, 6.057)

    References
    ----------
    Stoichiometry (IUPAC atomic weights) as in
    :func:`~rotarykiln.chemistry.lime.lime_calcination_mass_balance`; rotary lime LOI 0.5-1 %
    and specific heat consumption per tonne of lime: team source folder
    reference/cement_lime.md sections 4 and 6.2.
    """
    flows = {s: np.asarray(q, dtype=float) for s, q in solution.bed_flows.items()}
    out_flow = {s: float(q[-1]) for s, q in flows.items()}
    product = sum(out_flow.values())
    frac = {s: (v / product if product > 0 else math.nan) for s, v in out_flow.items()}
    w = {s: carbonate_co2_mass_fraction(c) for s, c in CARBONATE_SPECIES.items() if s in flows}
    co2_left = sum(w[s] * out_flow[s] for s in w)
    co2_released = sum(w[s] * (float(flows[s][0]) - out_flow[s]) for s in w)
    residual = co2_left / product if product > 0 else math.nan
    feed = sum(float(q[0]) for q in flows.values())
    caco3 = flows.get("CaCO3")
    lhv = float(solution.burner.get("fuel_lhv_input_W", math.nan))
    t_gas_out = float(solution.t_gas_nodes[0 if solution.counter_current else -1])
    shell = solution.t_shell
    return {
        "product_flow_kg_s": product,
        "composition": frac,
        "CaO_mass_fraction": frac.get("CaO", 0.0),
        "CaCO3_mass_fraction": frac.get("CaCO3", 0.0),
        "residual_CO2_mass_fraction": residual,
        "loss_on_ignition": residual + frac.get(MOISTURE, 0.0),
        "conversion_CaCO3": (
            1.0 - caco3[-1] / caco3[0] if caco3 is not None and caco3[0] > 0 else math.nan
        ),
        "CO2_released_kg_s": co2_released,
        "CO2_released_per_feed": co2_released / feed if feed > 0 else math.nan,
        "fuel_lhv_input_W": lhv,
        "specific_heat_consumption_J_kg": lhv / product if product > 0 else math.nan,
        "exhaust_temperature_K": float(solution.exhaust.get("temperature_K", t_gas_out)),
        "bed_outlet_temperature_K": float(solution.t_bed_nodes[-1]),
        "bed_max_temperature_K": float(np.max(solution.t_bed_nodes)),
        "shell_max_temperature_K": float(np.max(shell)) if shell is not None else math.nan,
    }
