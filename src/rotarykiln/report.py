"""Summaries of cases and results for people: dictionaries of named values and plain-text tables."""

from __future__ import annotations

from typing import Any

import numpy as np

from rotarykiln.geometry import CrossSection
from rotarykiln.regimes import (
    classify_regime,
    critical_speed,
    critical_speed_rpm,
    fraction_of_critical,
    froude_number,
)

__all__ = ["case_summary", "format_table", "regime_summary"]

RPM = 2 * np.pi / 60


def regime_summary(
    radius: float,
    speed: float,
    fill: float,
    *,
    criterion: str = "mellmann",
    wall_friction: float | None = None,
    repose_angle: float | None = None,
) -> dict[str, Any]:
    """Froude number, critical speed and the regime by the chosen criterion and by the other one.

    Parameters: radius (m), speed (rad/s), fill (-). Returns a flat dict for printing or JSON.
    """
    fr = float(froude_number(speed, radius))
    other = "henein" if criterion == "mellmann" else "mellmann"
    main = classify_regime(
        fr,
        fill,
        criterion=criterion,
        wall_friction=wall_friction if criterion == "mellmann" else None,
        repose_angle=repose_angle,
    )
    alt = classify_regime(fr, fill, criterion=other)
    note = (
        "both criteria agree"
        if str(main.name) == str(alt.name)
        else f"the criteria disagree: {criterion}'s applies ({_WHY[criterion]}); "
        f"{other}'s gives {alt.name} ({_WHY[other]})"
    )
    return {
        "radius_m": radius,
        "speed_rpm": speed / RPM,
        "fill": fill,
        "froude": fr,
        "critical_speed_rad_s": float(critical_speed(radius)),
        "critical_speed_rpm": float(critical_speed_rpm(radius)),
        "fraction_of_critical": float(fraction_of_critical(speed, radius)),
        "regime": str(main.name),
        "criterion": f"{criterion}: {main.source}",
        "regime_by_" + other: str(alt.name),
        "criterion_" + other: alt.source,
        "regime_note": note,
    }


# why each regime criterion applies, as the note beside a disagreement says it
_WHY = {
    "mellmann": "Mellmann 2001: Froude number, fill and wall friction bands for any free-flowing "
    "material, the one this model uses",
    "henein": "Henein et al. 1983: a bed-behaviour diagram measured for sand and limestone in "
    "pilot drums, shown for comparison",
}


def case_summary(case) -> dict[str, Any]:
    """The foundation summary of a validated case: geometry, speeds and regime."""
    radius = case.kiln.diameter / 2
    out: dict[str, Any] = {
        "name": case.name,
        "length_m": case.kiln.length,
        "diameter_m": case.kiln.diameter,
        "slope_deg": float(np.degrees(case.kiln.slope)),
        "speed_rpm": case.operation.speed / RPM,
        "critical_speed_rpm": float(critical_speed_rpm(radius)),
        "froude": float(froude_number(case.operation.speed, radius)),
        "fraction_of_critical": float(fraction_of_critical(case.operation.speed, radius)),
    }
    if case.operation.feed is not None:
        out["feed_kg_h"] = case.operation.feed * 3600
    fill = case.bed.mean_fill if case.bed is not None else None
    if fill is not None:
        cs = CrossSection.from_fill(fill, radius)
        out.update({k: float(v) for k, v in cs.as_dict().items() if k != "radius_m"})
        reg = regime_summary(radius, case.operation.speed, fill)
        out.update({k: reg[k] for k in ("regime", "criterion", "regime_by_henein", "regime_note")})
    return out


def format_table(data: dict[str, Any]) -> str:
    """A two-column plain-text table of a flat dict; floats with 5 significant digits."""
    width = max(len(k) for k in data)
    lines = []
    for key, value in data.items():
        text = f"{value:.5g}" if isinstance(value, float) else str(value)
        lines.append(f"{key:<{width}}  {text}")
    return "\n".join(lines)
