"""Named models for sweeps: ``case dict -> dict of scalars``, picklable for worker processes.

``rotarykiln sweep --model kiln`` looks the name up in :data:`MODELS`; any other model is given as
``module:function``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

__all__ = [
    "MODELS",
    "PROFILE_POINTS",
    "kiln_model",
    "kiln_profile_model",
    "profile_columns",
    "transport_model",
]

#: Positions of the axial profiles of :func:`kiln_profile_model` (evenly spaced, ends included).
PROFILE_POINTS = 41


def _scalars(summary: Mapping) -> dict:
    return {k: v for k, v in summary.items() if isinstance(v, int | float | str | bool)}


def kiln_model(case: dict) -> dict:
    """Steady kiln model of a case (:func:`rotarykiln.commands.kiln_runs.run_kiln_case`): its summary
    as scalars (outlet temperatures, heat flows, shell loss, efficiency, conversions and
    yields of a reacting bed, balances, Newton iterations; NaN values left out)."""
    import math

    from rotarykiln.case import parse_case
    from rotarykiln.commands.kiln_runs import run_kiln_case

    summary = run_kiln_case(parse_case(case)).summary()
    summary.pop("name", None)
    out = _scalars(summary)
    return {k: v for k, v in out.items() if not (isinstance(v, float) and math.isnan(v))}


def kiln_profile_model(case: dict) -> dict:
    """Steady kiln model: the summary of :func:`kiln_model` plus the axial profiles as scalars.

    Profiles at :data:`PROFILE_POINTS` evenly spaced positions z (m, from the solids inlet),
    named ``"<quantity>@<z>"`` with quantities ``bed_temperature``, ``gas_temperature``,
    ``wall_temperature`` (inner wall surface) and ``shell_temperature`` (lined walls), in K:
    e.g. ``"bed_temperature@1.2200"``. Uncertainty bands and calibration read these columns
    (see :func:`profile_columns`).
    """
    import numpy as np

    from rotarykiln.case import parse_case
    from rotarykiln.commands.kiln_runs import run_kiln_case

    sol = run_kiln_case(parse_case(case))
    summary = sol.summary()
    summary.pop("name", None)
    out = _scalars(summary)
    z = np.linspace(float(sol.z_nodes[0]), float(sol.z_nodes[-1]), PROFILE_POINTS)
    profiles = {
        "bed_temperature": sol.bed_temperature_at(z),
        "gas_temperature": sol.gas_temperature_at(z),
        "wall_temperature": sol.wall_temperature_at(z, 0),
    }
    if getattr(sol, "t_lining", None) is not None and len(sol.t_lining) > 1:
        profiles["shell_temperature"] = sol.wall_temperature_at(z, -1)
    for q, values in profiles.items():
        for zi, v in zip(z, values, strict=True):
            out[f"{q}@{zi:.4f}"] = float(v)
    return out


def profile_columns(names) -> dict[str, list[tuple[float, str]]]:
    """Profile columns among output names: quantity -> [(z in m, column name)], z ascending.

    Examples
    --------
    >>> profile_columns(["bed_temperature@0.5000", "fill", "bed_temperature@0.0000"])
    {'bed_temperature': [(0.0, 'bed_temperature@0.0000'), (0.5, 'bed_temperature@0.5000')]}
    """
    out: dict[str, list[tuple[float, str]]] = {}
    for n in names:
        q, sep, z = str(n).rpartition("@")
        if not sep or not q:
            continue
        try:
            out.setdefault(q, []).append((float(z), n))
        except ValueError:
            continue
    return {q: sorted(v) for q, v in out.items()}


def transport_model(case: dict) -> dict:
    """Bed profile of a case with a ``transport:`` section: mean fill, hold-up, residence time."""
    from rotarykiln.case import parse_case
    from rotarykiln.commands.model_runs import bed_profile_from_case

    p = bed_profile_from_case(parse_case(case))
    return {
        "mean_fill": float(p.mean_fill),
        "holdup_kg": float(p.holdup_mass) if p.holdup_mass is not None else float("nan"),
        "mean_residence_time_min": float(p.mean_residence_time) / 60.0,
        "discharge_fill": float(p.discharge_fill),
    }


MODELS: dict[str, Callable[[dict], dict]] = {
    "kiln": kiln_model,
    "kiln_profiles": kiln_profile_model,
    "transport": transport_model,
}
"""Model name -> function, for ``rotarykiln sweep --model NAME``."""
