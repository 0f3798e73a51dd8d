"""Named models for sweeps: ``case dict -> dict of scalars``, picklable for worker processes.

``rotarykiln sweep --model heat`` looks the name up in :data:`MODELS`; any other model is given as
``module:function``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

__all__ = ["MODELS", "heat_model", "transport_model"]


def _scalars(summary: Mapping) -> dict:
    return {k: v for k, v in summary.items() if isinstance(v, int | float | str | bool)}


def heat_model(case: dict) -> dict:
    """Steady heat model of a case with a ``heat:`` section: its summary (outlet temperatures,
    heat flows, shell loss, efficiency, energy closure, Newton iterations)."""
    from rotarykiln.case import parse_case
    from rotarykiln.kiln.run import run_heat_case

    summary = run_heat_case(parse_case(case)).summary()
    summary.pop("name", None)
    return _scalars(summary)


def transport_model(case: dict) -> dict:
    """Bed profile of a case with a ``transport:`` section: mean fill, hold-up, residence time."""
    from rotarykiln.case import parse_case
    from rotarykiln.kiln.coupling import bed_profile_from_case

    p = bed_profile_from_case(parse_case(case))
    return {
        "mean_fill": float(p.mean_fill),
        "holdup_kg": float(p.holdup_mass) if p.holdup_mass is not None else float("nan"),
        "mean_residence_time_min": float(p.mean_residence_time) / 60.0,
        "discharge_fill": float(p.discharge_fill),
    }


MODELS: dict[str, Callable[[dict], dict]] = {
    "heat": heat_model,
    "transport": transport_model,
}
"""Model name -> function, for ``rotarykiln sweep --model NAME``."""
