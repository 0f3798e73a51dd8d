"""Inputs of the steady reacting kiln: :class:`ReactingKiln` (SI units)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.errors import InputError, check_nonnegative, check_positive, check_range
from rotarykiln.kiln.model import Closures
from rotarykiln.materials.lining import Layer

__all__ = ["ReactingKiln", "SEED004_CLOSURES"]

#: Closures of seed 004 (Gorog et al. 1982 gas-bed and gas-wall, Tscheng & Watkinson 1979
#: covered wall), with the 0.62 exponent of the gas-bed law (notes 004, section 8.4).
SEED004_CLOSURES = Closures(
    gas_wall="gorog1982",
    gas_bed="gorog1982",
    covered_wall="tscheng1979",
    radiation=True,
    gas_emissivity="johansson2011",
    bed_conductivity="given",
)


@dataclass(frozen=True)
class ReactingKiln:
    """Everything the reacting kiln model needs (SI units).

    Geometry and motion: ``length`` (m), ``radius`` (m, inner), ``omega`` (rad/s), ``fill``
    (-, constant), ``bed_velocity`` (m/s, axial solids speed; hold-up per length of species i
    is ``Q_i / bed_velocity``).
    Bed: ``feed`` (bed species -> inlet mass flow, kg/s), ``feed_temperature`` (K),
    ``bed_cp`` (bed species -> constant specific heat, J/(kg K)), ``bulk_density`` (kg/m3,
    for the covered-wall coefficient), ``bed_conductivity`` (W/(m K)), ``bed_emissivity``,
    ``particle_diameter`` (m).
    Gas: ``gas_in`` (gas species -> inlet mass flow, kg/s), ``gas_inlet_temperature`` (K),
    ``pressure`` (Pa), ``gas_emissivity_law`` (a, b, minimum) for
    :math:`\\varepsilon_g = \\max(a + bT, \\min)` or None for the WSGG model of the closures
    with the local CO2 and H2O partial pressures.
    Wall: ``layers`` (inner to outer, :class:`~rotarykiln.materials.lining.Layer`): the lined
    wall of the heat model (k(T) layers, shell loss by convection and radiation to
    ``ambient_temperature`` with ``wind_speed`` m/s, ``shell_emissivity`` default that of the
    last layer); without layers (the default, seed 004): a single inner-wall temperature with
    the loss :math:`U \\pi D (T_w - T_a)`, ``wall_loss_u`` (W/(m2 K), on the inner wall).
    ``ambient_temperature`` (K); ``wall_emissivity`` (inner surface; default that of the first
    layer, or 0.9 without layers).
    Chemistry: ``mechanism`` (:class:`~rotarykiln.chemistry.Mechanism`), ``steam_flow`` (kg/s,
    seed 004's constant Q_a for the Ortiz law; None: the local gas H2O flow).
    ``closures`` (:class:`~rotarykiln.kiln.model.Closures`), ``name``; ``counter_current``
    (gas enters at z = length, against the solids; False: with them, at z = 0);
    ``bed_depth``: a :class:`~rotarykiln.kiln.bed_depth.KramersBed` to solve the bed depth with
    the balances (fill and hold-up then follow it; ``fill`` and ``bed_velocity`` only seed the
    solve), or None for the constant ``fill``.
    """

    length: float
    radius: float
    omega: float
    fill: float
    bed_velocity: float
    feed: dict
    feed_temperature: float
    bed_cp: dict
    bulk_density: float
    bed_conductivity: float
    bed_emissivity: float
    particle_diameter: float
    gas_in: dict
    gas_inlet_temperature: float
    mechanism: Mechanism
    wall_loss_u: float = 5.0
    ambient_temperature: float = 298.15
    wall_emissivity: float | None = None
    layers: tuple[Layer, ...] = ()
    shell_emissivity: float | None = None
    wind_speed: float = 0.0
    pressure: float = 101325.0
    gas_emissivity_law: tuple[float, float, float] | None = None
    steam_flow: float | None = None
    closures: Closures = field(default_factory=lambda: SEED004_CLOSURES)
    name: str = "reacting kiln"
    counter_current: bool = True
    bed_depth: object | None = None

    def __post_init__(self):
        check_positive("kiln.length", self.length, "m")
        check_positive("kiln.radius", self.radius, "m")
        check_positive("operation.speed", self.omega, "rad/s")
        check_range("chemistry.fill", self.fill, 0.0, 0.5, closed_high=True)
        check_positive("chemistry.bed_velocity", self.bed_velocity, "m/s")
        check_positive("chemistry.feed.temperature", self.feed_temperature, "K")
        check_positive("chemistry.gas.inlet_temperature", self.gas_inlet_temperature, "K")
        check_positive("material.bulk_density", self.bulk_density, "kg/m3")
        check_positive("chemistry.solid.thermal_conductivity", self.bed_conductivity, "W/(m K)")
        check_range("chemistry.solid.emissivity", self.bed_emissivity, 0.0, 1.0, closed_high=True)
        for name, eps in (
            ("chemistry.wall_emissivity", self.wall_emissivity),
            ("chemistry.shell_emissivity", self.shell_emissivity),
        ):
            if eps is not None:
                check_range(name, eps, 0.0, 1.0, closed_high=True)
        check_nonnegative("chemistry.wind_speed", self.wind_speed, "m/s")
        if not isinstance(self.closures, Closures):
            raise InputError("chemistry.closures", self.closures, "a Closures object")
        if self.closures.bed_conductivity != "given":
            raise InputError(
                "chemistry.closures.bed_conductivity",
                self.closures.bed_conductivity,
                "given (the reacting kiln uses chemistry.solid.thermal_conductivity)",
            )
        check_positive("material.particle_size", self.particle_diameter, "m")
        check_nonnegative("chemistry.wall_loss.U", self.wall_loss_u, "W/(m2 K)")
        check_positive("chemistry.wall_loss.ambient_temperature", self.ambient_temperature, "K")
        check_positive("chemistry.gas.pressure", self.pressure, "Pa")
        sp = self.mechanism.species
        for label, flows, phase in (
            ("chemistry.feed", self.feed, "bed"),
            ("chemistry.gas", self.gas_in, "gas"),
        ):
            if not flows or sum(flows.values()) <= 0:
                raise InputError(f"{label} mass flow", flows, "> 0 kg/s in total")
            for name, q in flows.items():
                if name not in sp or sp[name].phase != phase:
                    raise InputError(f"{label}.{name}", name, f"a {phase} species")
                check_nonnegative(f"{label}.{name}", q, "kg/s")
        for name, cp in self.bed_cp.items():
            check_positive(f"chemistry.bed_cp.{name}", cp, "J/(kg K)")
        if self.steam_flow is not None:
            check_nonnegative("chemistry.gas.steam_flow", self.steam_flow, "kg/s")
        if self.gas_emissivity_law is not None:
            a, b, lo = self.gas_emissivity_law
            if not (np.isfinite(a) and np.isfinite(b) and 0 <= lo < 1):
                raise InputError(
                    "chemistry.gas.emissivity", self.gas_emissivity_law, "finite a, b; 0 <= min < 1"
                )

    @property
    def eps_wall(self) -> float:
        """Emissivity of the inner wall surface, -."""
        if self.wall_emissivity is not None:
            return self.wall_emissivity
        return self.layers[0].material.emissivity if self.layers else 0.9

    @property
    def eps_shell(self) -> float:
        """Emissivity of the outer shell surface (lined wall), -."""
        if self.shell_emissivity is not None:
            return self.shell_emissivity
        return self.layers[-1].material.emissivity if self.layers else 0.9

    @property
    def feed_flow(self) -> float:
        """Total solids feed, kg/s."""
        return float(sum(self.feed.values()))

    @property
    def gas_flow(self) -> float:
        """Total gas inlet flow, kg/s."""
        return float(sum(self.gas_in.values()))

    @property
    def residence_time(self) -> float:
        """Mean solids residence time L / v, s."""
        return self.length / self.bed_velocity
