"""Inputs of the steady kiln heat model: :class:`HeatKiln` and :class:`Closures`."""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass, field, fields

import numpy as np

from rotarykiln.errors import InputError, check_nonnegative, check_positive, check_range
from rotarykiln.materials.gas import GasPropertyTable
from rotarykiln.materials.lining import Layer
from rotarykiln.materials.solids import Solid

__all__ = ["Closures", "HeatKiln", "GAS_WALL", "GAS_BED", "COVERED_WALL", "GAS_EMISSIVITY"]

GAS_WALL = ("tscheng1979", "gorog1982")
GAS_BED = ("tscheng1979", "gorog1982")
COVERED_WALL = ("li2005", "tscheng1979", "wachters_kramers1964")
GAS_EMISSIVITY = ("johansson2011", "smith1982")
BED_CONDUCTIVITY = ("given", "maxwell", "zehner_schlunder")


@dataclass(frozen=True)
class Closures:
    """Choice of every closure by name (see docs/heat.md).

    ``gas_wall`` in {tscheng1979, gorog1982}; ``gas_bed`` in {tscheng1979, gorog1982};
    ``covered_wall`` in {li2005, tscheng1979, wachters_kramers1964}; ``radiation`` on/off;
    ``gas_emissivity`` in {johansson2011, smith1982} or a constant in [0, 1);
    ``bed_conductivity`` in {given, maxwell, zehner_schlunder} (``given`` uses the measured
    bulk value of the solid, falling back to zehner_schlunder).
    """

    gas_wall: str = "tscheng1979"
    gas_bed: str = "tscheng1979"
    covered_wall: str = "li2005"
    radiation: bool = True
    gas_emissivity: str | float = "johansson2011"
    bed_conductivity: str = "given"

    def __post_init__(self):
        for name, value, allowed in (
            ("heat.closures.gas_wall", self.gas_wall, GAS_WALL),
            ("heat.closures.gas_bed", self.gas_bed, GAS_BED),
            ("heat.closures.covered_wall", self.covered_wall, COVERED_WALL),
            ("heat.closures.bed_conductivity", self.bed_conductivity, BED_CONDUCTIVITY),
        ):
            if value not in allowed:
                raise InputError(name, value, "one of " + ", ".join(allowed))
        if isinstance(self.gas_emissivity, str):
            if self.gas_emissivity not in GAS_EMISSIVITY:
                raise InputError(
                    "heat.closures.gas_emissivity",
                    self.gas_emissivity,
                    "one of " + ", ".join(GAS_EMISSIVITY) + " or a number in [0, 1)",
                )
        else:
            check_range(
                "heat.closures.gas_emissivity", self.gas_emissivity, 0.0, 1.0, closed_low=True
            )

    @classmethod
    def from_case(cls, section) -> Closures:
        """The closures of a case file's ``closures`` section (:class:`rotarykiln.case.HeatClosures`).

        Examples
        --------
        >>> from rotarykiln.case import HeatClosures
        >>> c = Closures.from_case(HeatClosures(gas_bed="gorog1982"))
        >>> c.gas_bed, c.gas_wall
        ('gorog1982', 'tscheng1979')
        """
        given = {f.name: getattr(section, f.name) for f in fields(cls)}
        return cls(**{k: v for k, v in given.items() if v is not None})


FillLike = float | np.ndarray | Callable[[np.ndarray], np.ndarray] | tuple


@dataclass(frozen=True)
class HeatKiln:
    """Everything the steady heat model needs, in SI units.

    Geometry: ``length`` (m), ``radius`` (m, inner), ``omega`` (rad/s).
    Bed: ``fill`` (-) as a number, an array of values at evenly spaced positions from the
    solids inlet (z = 0) to the discharge (z = length), a pair ``(z, fill)`` of arrays, or a
    callable ``fill(z)``; ``solid`` (:class:`Solid`), ``solids_flow`` (kg/s),
    ``solids_inlet_temperature`` (K).
    Gas: ``gas`` (:class:`GasPropertyTable`), ``gas_flow`` (kg/s), ``gas_inlet_temperature``
    (K), ``counter_current`` (gas enters at z = length), ``heat_release`` (W, released in the
    gas by a flame inside the kiln) with ``heat_release_profile`` (callable of z, normalised
    by the solver) or None for uniform; ``pressure`` (Pa).
    Wall: ``layers`` (inner to outer, :class:`Layer`), ``wall_emissivity`` (inner surface,
    default that of the first layer material), ``shell_emissivity`` (default that of the last
    layer), ``ambient_temperature`` (K), ``wind_speed`` (m/s).
    ``flame``: the :class:`~rotarykiln.kiln.flame.Flame` of a burner (its heating values and
    jet numbers enter the energy balance sheet and the summary), or None.
    ``closures``: :class:`Closures`. ``measurements``: optional dict of arrays
    (``z_gas``, ``t_gas``, ``z_bed``, ``t_bed``, ``z_wall``, ``t_wall``) overlaid on plots.
    """

    length: float
    radius: float
    omega: float
    fill: FillLike
    solid: Solid
    solids_flow: float
    solids_inlet_temperature: float
    gas: GasPropertyTable
    gas_flow: float
    gas_inlet_temperature: float
    layers: tuple[Layer, ...]
    counter_current: bool = True
    heat_release: float = 0.0
    heat_release_profile: Callable[[np.ndarray], np.ndarray] | None = None
    pressure: float = 101325.0
    wall_emissivity: float | None = None
    shell_emissivity: float | None = None
    ambient_temperature: float = 298.15
    wind_speed: float = 0.0
    closures: Closures = field(default_factory=Closures)
    measurements: dict | None = None
    name: str = "kiln"
    flame: object | None = None

    def __post_init__(self):
        check_positive("kiln.length", self.length, "m")
        check_positive("kiln.radius", self.radius, "m")
        check_positive("operation.rotation_rate", self.omega, "rad/s")
        check_positive("heat.solids_flow", self.solids_flow, "kg/s")
        check_positive("heat.gas_flow", self.gas_flow, "kg/s")
        check_positive("heat.solids_inlet_temperature", self.solids_inlet_temperature, "K")
        check_positive("heat.gas_inlet_temperature", self.gas_inlet_temperature, "K")
        check_positive("heat.ambient_temperature", self.ambient_temperature, "K")
        check_positive("heat.pressure", self.pressure, "Pa")
        check_nonnegative("heat.heat_release", self.heat_release, "W")
        check_nonnegative("heat.wind_speed", self.wind_speed, "m/s")
        if not self.layers:
            raise InputError("heat.lining", "[]", "a list of at least one layer")
        for name, eps in (
            ("heat.wall_emissivity", self.wall_emissivity),
            ("heat.shell_emissivity", self.shell_emissivity),
        ):
            if eps is not None:
                check_range(name, eps, 0.0, 1.0, closed_high=True)
        if not isinstance(self.closures, Closures):
            raise InputError("heat.closures", self.closures, "a Closures object")
        if self.heat_release == 0.0 and self.gas_inlet_temperature < self.solids_inlet_temperature:
            warnings.warn(
                f"heat.gas_inlet_temperature: {self.gas_inlet_temperature:.6g} K is colder than "
                f"the solids feed ({self.solids_inlet_temperature:.6g} K): the gas cools the bed",
                UserWarning,
                stacklevel=3,
            )

    @property
    def eps_wall(self) -> float:
        """Emissivity of the inner wall surface, -."""
        if self.wall_emissivity is not None:
            return self.wall_emissivity
        return self.layers[0].material.emissivity

    @property
    def eps_shell(self) -> float:
        """Emissivity of the outer shell surface, -."""
        if self.shell_emissivity is not None:
            return self.shell_emissivity
        return self.layers[-1].material.emissivity

    def fill_at(self, z: np.ndarray) -> np.ndarray:
        """Fill fraction at positions ``z`` (m), from whichever form ``fill`` was given in."""
        z = np.asarray(z, dtype=float)
        f = self.fill
        if callable(f):
            out = np.asarray(f(z), dtype=float) * np.ones_like(z)
        elif isinstance(f, tuple):
            zf, vf = (np.asarray(a, dtype=float) for a in f)
            out = np.interp(z, zf, vf)
        else:
            arr = np.asarray(f, dtype=float)
            if arr.ndim == 0:
                out = np.full_like(z, float(arr))
            else:
                out = np.interp(z, np.linspace(0.0, self.length, arr.size), arr)
        check_range("heat.fill", out, 0.0, 0.5, closed_high=True)
        return out
