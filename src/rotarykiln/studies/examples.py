"""Cheap model functions for sweeps: tests, benchmarks and demonstrations (no kiln solver).

Each takes a case dict (quantities as strings with units or SI numbers) and returns a dict of
scalars, the contract of :func:`rotarykiln.studies.runner.run_sweep`.
"""

from __future__ import annotations

import math

from rotarykiln.errors import InputError
from rotarykiln.units import to_si

__all__ = ["first_order_conversion", "ortiz_isothermal_burn_off", "failing_model"]


def first_order_conversion(case: dict) -> dict:
    r"""Plug-flow conversion of a first-order reaction: :math:`X = 1 - e^{-k t}`.

    Case fields: ``reaction.rate_constant`` (frequency), ``operation.residence_time`` (time).

    Examples
    --------
    >>> first_order_conversion({"reaction": {"rate_constant": "0.01 1/s"},
    ...                         "operation": {"residence_time": "100 s"}})["conversion"]
    0.6321205588285577
    """
    k = to_si("reaction.rate_constant", case["reaction"]["rate_constant"], "frequency")
    t = to_si("operation.residence_time", case["operation"]["residence_time"], "time")
    if k < 0 or t < 0:
        raise InputError("reaction.rate_constant", k, ">= 0")
    return {"conversion": 1.0 - math.exp(-k * t), "damkohler": k * t}


def ortiz_isothermal_burn_off(case: dict) -> dict:
    r"""Burn-off of seed 004's charcoal case for an isothermal reaction zone (no heat balance).

    .. math:: \mathrm{BO} = 100\,[1 - \exp(-K_e e^{-8033/T} Q_a\, t_r\, f_r)],\quad
              \mathrm{production} = 100 - \mathrm{BO}

    with :math:`t_r f_r` the time spent in the reaction zone (a fraction ``f_r`` of the residence
    time, seed 004: from 2.5 m to 3.7 m, f_r = 1.2/3.7). Fields (the built-in case's):
    ``chemistry.residence_time``, ``chemistry.gas.steam_flow``; stand-in settings (optional,
    top-level ``standin`` mapping): ``reaction_zone_temperature`` (default 1150 K) and
    ``reaction_zone_fraction``. A stand-in for the kiln model; it shows the directions of seed
    004 Figs. 5.1 and 5.4 only (no heat balance: no effect of gas or solid flow).
    """
    ch = case["chemistry"]
    t = to_si("chemistry.residence_time", ch["residence_time"], "time")
    qa = to_si("chemistry.gas.steam_flow", ch["gas"]["steam_flow"], "mass flow")
    sd = case.get("standin", {})
    T = to_si(
        "standin.reaction_zone_temperature",
        sd.get("reaction_zone_temperature", "1150 K"),
        "temperature",
    )
    f = float(sd.get("reaction_zone_fraction", 1.2 / 3.7))
    k = 6.005 * math.exp(-8033.0 / T) * qa if T >= 1073.0 else 0.0
    bo = 100.0 * (1.0 - math.exp(-k * t * f))
    return {"burn_off": bo, "production": 100.0 - bo}


def failing_model(case: dict) -> dict:
    """Raises for negative ``x``, returns a non-dict for x == 0: exercises error capture."""
    x = float(case["x"])
    if x < 0:
        raise ValueError(f"x = {x} < 0")
    if x == 0:
        return [x]  # type: ignore[return-value]
    return {"y": 2.0 * x, "label": "ok"}
