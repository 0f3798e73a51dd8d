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

__all__ = [
    "air_ratio",
    "case_summary",
    "denoise",
    "format_duration",
    "format_mass_flow",
    "format_power",
    "format_quantity",
    "format_table",
    "format_temperature",
    "regime_summary",
    "significant",
]

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


# --- numbers as an engineer reads them ---------------------------------------------------------

ZERO_C = 273.15
"""0 degC in K."""


def significant(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures, in plain notation where it is readable.

    Plain notation from 1e-3 to 1e6 (``70538.07`` -> ``"70540"``, ``0.072574`` -> ``"0.07257"``),
    scientific outside it (``1.6374e-09`` -> ``"1.637e-09"``); no trailing zeros; ``"0"`` for 0.

    Parameters
    ----------
    value : float
        The number.
    digits : int
        Significant figures.

    Returns
    -------
    str

    Examples
    --------
    >>> significant(70538.07), significant(0.072574), significant(1.6374e-09), significant(-2.0)
    ('70540', '0.07257', '1.637e-09', '-2')
    """
    value = float(value)
    if value == 0 or not np.isfinite(value):
        return "0" if value == 0 else str(value)
    magnitude = int(np.floor(np.log10(abs(value))))
    if not -3 <= magnitude < 6:
        return f"{value:.{digits - 1}e}".replace(".000e", "e").rstrip()
    decimals = digits - 1 - magnitude  # negative: rounds to tens, hundreds...
    text = f"{round(value, decimals):.{max(decimals, 0)}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def denoise(value: float, scale: float, rtol: float) -> float:
    """``value``, or 0 when it is below ``rtol`` times ``scale`` (round-off, not a result).

    Parameters
    ----------
    value : float
        The number (an energy term, a closure).
    scale : float
        What it is small against (the total energy input; 1 for a relative closure).
    rtol : float
        The tolerance the solver closes the balance to.

    Returns
    -------
    float

    Examples
    --------
    >>> denoise(1.6374e-09, 70538.0, 1e-6), denoise(14139.0, 70538.0, 1e-6)
    (0.0, 14139.0)
    """
    return 0.0 if abs(value) < rtol * abs(scale) else float(value)


def format_power(watts: float, digits: int = 4) -> str:
    """A heat flow in W, kW or MW (``119740`` -> ``"119.7 kW"``).

    Examples
    --------
    >>> format_power(119740.3), format_power(2.5e6), format_power(35.0), format_power(0.0)
    ('119.7 kW', '2.5 MW', '35 W', '0 W')
    """
    return _in_units(float(watts), ((1e6, 1e6, "MW"), (1e3, 1e3, "kW")), "W", digits)


def _in_units(value: float, larger: tuple, unit: str, digits: int) -> str:
    """``value`` (in ``unit``) in the first of the ``larger`` units (from, factor, unit) whose
    ``from`` its magnitude reaches, else in ``unit``, to ``digits`` significant figures."""
    for start, factor, name in larger:
        if abs(value) >= start:
            return f"{significant(value / factor, digits)} {name}"
    return f"{significant(value, digits)} {unit}"


def format_temperature(kelvin: float) -> str:
    """A temperature in K with degrees Celsius beside it, to 0.1 K.

    Examples
    --------
    >>> format_temperature(1011.83)
    '1011.8 K (738.7 °C)'
    """
    kelvin = float(kelvin)
    return f"{kelvin:.1f} K ({kelvin - ZERO_C:.1f} °C)"


def format_mass_flow(kg_s: float, digits: int = 4) -> str:
    """A mass flow in kg/h, or t/h from 1 t/h (``0.017222`` -> ``"62 kg/h"``).

    Examples
    --------
    >>> format_mass_flow(0.0172222), format_mass_flow(12.5), format_mass_flow(0.079155)
    ('62 kg/h', '45 t/h', '285 kg/h')
    """
    return _in_units(float(kg_s) * 3600.0, ((1000.0, 1000.0, "t/h"),), "kg/h", digits)


def format_duration(seconds: float, digits: int = 4) -> str:
    """A duration in s, min or h, whichever reads best (``7423`` -> ``"123.7 min"``).

    Examples
    --------
    >>> format_duration(7423.0), format_duration(45.0), format_duration(36000.0)
    ('123.7 min', '45 s', '10 h')
    """
    steps = ((5 * 3600, 3600.0, "h"), (120, 60.0, "min"))
    return _in_units(float(seconds), steps, "s", digits)


def air_ratio(excess_air: float) -> str:
    """The air ratio lambda (air over stoichiometric air) beside the excess air in %.

    Parameters
    ----------
    excess_air : float
        Air over stoichiometric air, less 1 (``-0.072574``: 7.3 % short of stoichiometric).

    Returns
    -------
    str

    Examples
    --------
    >>> air_ratio(-0.072574), air_ratio(0.39653)
    ('λ = 0.93 (-7.3 % excess air)', 'λ = 1.40 (+39.7 % excess air)')
    """
    lam = 1.0 + float(excess_air)
    return f"λ = {lam:.2f} ({100.0 * excess_air:+.1f} % excess air)"


def format_quantity(value: Any, unit: str, digits: int = 4) -> str:
    """A summary value with its unit, in the unit people read (kW, K with degC, kg/h, min).

    Parameters
    ----------
    value : float, int, str or bool
        The value, SI as in the summary.
    unit : str
        Its unit as :func:`rotarykiln.tables.split_unit` gives it (``"W"``, ``"K"``,
        ``"kg/s"``, ``"s"``, ``""`` for a dimensionless number...).
    digits : int
        Significant figures.

    Returns
    -------
    str

    Examples
    --------
    >>> format_quantity(1.1974e5, "W"), format_quantity(0.0172222, "kg/s")
    ('119.7 kW', '62 kg/h')
    >>> format_quantity(100, ""), format_quantity("rolling", ""), format_quantity(0.12, "")
    ('100', 'rolling', '0.12')
    """
    if isinstance(value, bool) or not isinstance(value, int | float | np.floating | np.integer):
        return str(value)
    if isinstance(value, int | np.integer):
        return f"{value} {unit}".rstrip()
    special = {
        "W": format_power,
        "K": lambda v, d: format_temperature(v),
        "kg/s": format_mass_flow,
        "s": format_duration,
    }.get(unit)
    if special is not None:
        return special(value, digits)
    return f"{significant(value, digits)} {unit}".rstrip()
