"""The ``transverse:`` section of a case file (retort-zone grid simulation).

Plain pydantic with unit conversion by :func:`rotarykiln.units.to_si`; it does not import
``rotarykiln.case`` (which imports it for the optional ``Case.transverse`` field), so there is no
import cycle. The drum (``kiln.diameter``), the speed (``operation.speed``) and the fill
(``bed.fill``) come from the usual sections of the case; this section holds the two feeds and
the simulation settings::

    transverse:
      duration: 220 s
      shale_to_ash: 0.32          # mass ratio
      shale: {mean_size: 1.54 mm, temperature: 548 K}
      ash: {mean_size: 2.11 mm, temperature: 1048 K}
      grid: {layers: 5, zones: 20}
      snapshot_times: [5 s, 10 s, 20 s, 40 s, 60 s, 220 s]
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field
from pydantic_core import PydanticCustomError

from rotarykiln.errors import InputError
from rotarykiln.units import to_si

__all__ = ["FeedSection", "GridSection", "TransverseSection", "retort_spec_from_case"]


def _quantity(kind: str, *, gt: float | None = None, le: float | None = None, shown: str = ""):
    def convert(value: Any) -> float:
        try:
            si = to_si("", value, kind)
        except InputError as exc:
            raise PydanticCustomError("quantity", str(exc).removeprefix(": ")) from None
        if not math.isfinite(si) or (gt is not None and si <= gt) or (le is not None and si > le):
            raise PydanticCustomError(
                "quantity_range", "{value} is not {bound}", {"value": value, "bound": shown}
            )
        return si

    return Annotated[float, BeforeValidator(convert)]


_Length = _quantity("length", gt=0, shown="> 0")
_Temperature = _quantity("temperature", gt=0, shown="> 0 K")
_Density = _quantity("density", gt=0, shown="> 0")
_SpecificHeat = _quantity("specific heat", gt=0, shown="> 0")
_Time = _quantity("time", gt=0, shown="> 0 s")
_Fraction = _quantity("fraction", gt=0, le=1, shown="in (0, 1]")


def _positive(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0:
        raise PydanticCustomError(
            "number", "{value} is not > 0 (a mass ratio of shale to ash)", {"value": value}
        )
    return float(value)


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class FeedSection(_Section):
    """One feed (shale or ash): mean size, initial temperature, properties."""

    mean_size: _Length
    temperature: _Temperature
    bulk_density: _Density | None = None
    heat_capacity: _SpecificHeat | None = None


class GridSection(_Section):
    """Grid size: stagnant layers (the active layer gets 2 zones per layer) and zones."""

    layers: int = Field(5, ge=2)
    zones: int = Field(20, ge=4)


class TransverseSection(_Section):
    """Settings of the transverse grid simulation with heating (retort zone, ch 9)."""

    duration: _Time = 220.0
    shale_to_ash: Annotated[float, BeforeValidator(_positive)] = 0.32
    shale: FeedSection = FeedSection(mean_size=1.54e-3, temperature=548.0)
    ash: FeedSection = FeedSection(mean_size=2.11e-3, temperature=1048.0)
    distribution: Literal["auto", "single", "table4.1"] = "auto"
    voidage: _Fraction = 0.5
    emissivity: _Fraction = 0.9
    balance: Literal["pairwise", "smaller"] = "pairwise"
    segregation: bool = True
    grid: GridSection = GridSection()
    snapshot_times: list[_Time] = [5.0, 10.0, 20.0, 40.0, 60.0, 220.0]


def retort_spec_from_case(case) -> Any:
    """Build a :class:`~rotarykiln.transverse.retort.RetortSpec` from a validated Case.

    Raises
    ------
    InputError
        When the case has no ``transverse`` section or no ``bed.fill``.
    """
    from rotarykiln.transverse.retort import RetortSpec

    sec = getattr(case, "transverse", None)
    if sec is None:
        raise InputError("transverse", message="transverse: missing (required section)")
    if case.bed is None or case.bed.mean_fill is None:
        raise InputError("bed.fill", message="bed.fill: missing (required for transverse)")
    kw = dict(
        name=case.name,
        drum_diameter=case.kiln.diameter,
        omega=case.operation.speed,
        fill=case.bed.mean_fill,
        shale_size=sec.shale.mean_size,
        ash_size=sec.ash.mean_size,
        shale_temperature=sec.shale.temperature,
        ash_temperature=sec.ash.temperature,
        shale_to_ash=sec.shale_to_ash,
        duration=sec.duration,
        distribution=sec.distribution,
        voidage=sec.voidage,
        emissivity=sec.emissivity,
        balance=sec.balance,
        layers=sec.grid.layers,
        zones=sec.grid.zones,
        segregation=sec.segregation,
        snapshot_times=tuple(sec.snapshot_times),
    )
    for feed, prefix in ((sec.shale, "shale"), (sec.ash, "ash")):
        if feed.bulk_density is not None:
            kw[f"{prefix}_bulk_density"] = feed.bulk_density
        if feed.heat_capacity is not None:
            kw[f"{prefix}_cp"] = feed.heat_capacity
    return RetortSpec(**kw)
