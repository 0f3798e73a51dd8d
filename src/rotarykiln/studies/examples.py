"""Cheap model functions for sweeps: tests, benchmarks and demonstrations (no kiln solver).

Each takes a case dict (quantities as strings with units or SI numbers) and returns a dict of
scalars, the contract of :func:`rotarykiln.studies.runner.run_sweep`.
"""

from __future__ import annotations

import math
import os
import time
from pathlib import Path

from rotarykiln.errors import InputError
from rotarykiln.units import to_si

__all__ = [
    "first_order_conversion",
    "ortiz_isothermal_burn_off",
    "failing_model",
    "ishigami",
    "sleepy_square",
    "crash_once",
    "trivial_model",
    "exponential_heating",
    "EXPONENTIAL_CASE",
]

#: Base case of :func:`exponential_heating` (a bed heated by gas at a fixed temperature).
EXPONENTIAL_CASE = {
    "kiln": {"length": "2 m"},
    "heat": {"gas_temperature": "700 K", "inlet_temperature": "300 K", "exchange": "0.6 1/m"},
}


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
    r"""Burn-off of Ahmad's (2006) charcoal case for an isothermal reaction zone (no heat balance).

    .. math:: \mathrm{BO} = 100\,[1 - \exp(-K_e e^{-8033/T} Q_a\, t_r\, f_r)],\quad
              \mathrm{production} = 100 - \mathrm{BO}

    with :math:`t_r f_r` the time spent in the reaction zone (a fraction ``f_r`` of the residence
    time, Ahmad 2006: from 2.5 m to 3.7 m, f_r = 1.2/3.7). Fields (the built-in case's):
    ``bed.residence_time``, ``gas.steam_flow``; stand-in settings (optional,
    top-level ``standin`` mapping): ``reaction_zone_temperature`` (default 1150 K) and
    ``reaction_zone_fraction``. A stand-in for the kiln model; it shows the directions of Ahmad's
    (2006) Figs. 5.1 and 5.4 only (no heat balance: no effect of gas or solid flow).
    """
    t = to_si("bed.residence_time", case["bed"]["residence_time"], "time")
    qa = to_si("gas.steam_flow", case["gas"]["steam_flow"], "mass flow")
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


def ishigami(case: dict) -> dict:
    r"""Ishigami function, the standard test of sensitivity indices.

    .. math:: y = \sin x_1 + a \sin^2 x_2 + b x_3^4 \sin x_1,\quad a = 7,\ b = 0.1

    with :math:`x_i` uniform on :math:`[-\pi, \pi]`. Analytic indices: S1 = 0.3139, 0.4424,
    0; ST = 0.5576, 0.4424, 0.2437.

    Parameters
    ----------
    case : dict
        Fields ``x1``, ``x2``, ``x3`` (plain numbers, -).

    Returns
    -------
    dict
        ``{"y": value}`` (-).

    Examples
    --------
    >>> round(ishigami({"x1": 1.0, "x2": 0.5, "x3": 2.0})["y"], 4)
    3.7968

    References
    ----------
    Ishigami & Homma (1990), Proc. ISUMA '90, 398-403; Sobol' & Levitan (1999), Comput. Phys.
    Commun. 117, 52-61 (analytic indices).
    """
    x1, x2, x3 = (float(case[k]) for k in ("x1", "x2", "x3"))
    y = math.sin(x1) + 7.0 * math.sin(x2) ** 2 + 0.1 * x3**4 * math.sin(x1)
    return {"y": y}


def sleepy_square(case: dict) -> dict:
    """``y = x**2`` after sleeping ``sleep_s`` seconds (a stand-in for a slow model in tests)."""
    time.sleep(float(case.get("sleep_s", 0.0)))
    x = float(case["x"])
    return {"y": x * x}


def crash_once(case: dict) -> dict:
    """Kills its worker process once (for ``x == crash_at``, if file ``marker`` does not exist
    yet: it is created first; every time if ``always`` is true), else returns ``y = 2 x``.
    Tests the runner's recovery."""
    x = float(case["x"])
    marker = Path(case["marker"])
    if x == float(case["crash_at"]) and (case.get("always") or not marker.exists()):
        marker.write_text("crashed")
        os._exit(1)
    return {"y": 2.0 * x}


def trivial_model(case: dict) -> dict:
    """Returns ``{"y": x}`` at once: measures the runner's own overhead per case."""
    return {"y": case["x"]}


def exponential_heating(case: dict) -> dict:
    r"""Bed heated by gas at a fixed temperature: :math:`T(z) = T_g - (T_g - T_0) e^{-k z}`.

    A cheap stand-in for a kiln profile model in calibration tests. Fields: ``kiln.length``,
    ``heat.gas_temperature``, ``heat.inlet_temperature``, ``heat.exchange`` (k, 1/m).
    Returns ``bed_temperature@<z>`` at 21 positions (K) and ``bed_outlet_temperature_K``.

    Examples
    --------
    >>> round(exponential_heating(EXPONENTIAL_CASE)["bed_outlet_temperature_K"], 1)
    579.5
    """
    import numpy as np

    L = to_si("kiln.length", case["kiln"]["length"], "length")
    h = case["heat"]
    tg = to_si("heat.gas_temperature", h["gas_temperature"], "temperature")
    t0 = to_si("heat.inlet_temperature", h["inlet_temperature"], "temperature")
    k = h["exchange"]
    if isinstance(k, str):
        from rotarykiln.units import ureg

        k = ureg.Quantity(k).to("1/m").magnitude
    k = float(k)
    z = np.linspace(0.0, L, 21)
    t = tg - (tg - t0) * np.exp(-k * z)
    out = {f"bed_temperature@{zi:.4f}": float(ti) for zi, ti in zip(z, t, strict=True)}
    out["bed_outlet_temperature_K"] = float(t[-1])
    return out
