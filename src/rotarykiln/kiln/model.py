"""Inputs of the steady kiln model: :class:`Kiln` (SI units) and the choice of closures."""

from __future__ import annotations

import dataclasses
import warnings
from dataclasses import dataclass, field, fields

import numpy as np

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.errors import InputError, check_nonnegative, check_positive, check_range
from rotarykiln.materials.lining import Layer

__all__ = [
    "Closures",
    "Kiln",
    "SEED004_CLOSURES",
    "GAS_WALL",
    "GAS_BED",
    "COVERED_WALL",
    "GAS_EMISSIVITY",
    "RADIATION_MODELS",
]

GAS_WALL = ("tscheng1979", "gorog1982")
GAS_BED = ("tscheng1979", "gorog1982")
COVERED_WALL = ("li2005", "tscheng1979", "wachters_kramers1964")
GAS_EMISSIVITY = ("johansson2011", "smith1982")
BED_CONDUCTIVITY = ("given", "maxwell", "zehner_schlunder")
RADIATION_MODELS = ("grey", "banded")


@dataclass(frozen=True)
class Closures:
    """Choice of every closure by name (see docs/heat.md).

    ``gas_wall`` in {tscheng1979, gorog1982}; ``gas_bed`` in {tscheng1979, gorog1982};
    ``covered_wall`` in {li2005, tscheng1979, wachters_kramers1964}; ``radiation`` on/off;
    ``gas_emissivity`` in {johansson2011, smith1982} or a constant in [0, 1);
    ``bed_conductivity`` in {given, maxwell, zehner_schlunder} (``given`` uses the measured
    bulk value of the solid, falling back to zehner_schlunder); ``convection_factor`` (-, > 0,
    default 1: the correlations as published) multiplies the gas-wall and gas-bed convection
    coefficients, a handle for calibration to plant data, not a default to change;
    ``near_bed_mixing`` (W/(m2 K), None: off): a layered freeboard, the bed exchanging (by
    convection and gas radiation) with a near-bed gas layer fed from the core gas through this
    mixing coefficient in series (the layer's temperature lies between bed and core);
    ``bed_radiation``: the bed conductivity gains the radiation between particles,
    :func:`rotarykiln.heat.bed_conductivity.radiative_bed_conductivity` (Damkohler /
    Zehner-Bauer-Schlunder, growing as d_p T^3); ``exposed_bed_penetration``: the heat
    reaching the exposed bed surface penetrates the bed through a penetration-theory
    resistance (Wachters & Kramers over the bed's circulation time) in series;
    ``radiation_model`` in {grey, banded}: the freeboard exchange with one grey gas
    (absorptivity equal to the emissivity at the gas temperature) or with every grey gas of the
    WSGG ``gas_emissivity`` model in the network, the surfaces' radiation weighted at their own
    temperature (:func:`rotarykiln.heat.radiation.freeboard_radiation_bands`; a constant or a
    line emissivity stays grey).
    """

    gas_wall: str = "tscheng1979"
    gas_bed: str = "tscheng1979"
    covered_wall: str = "li2005"
    radiation: bool = True
    gas_emissivity: str | float = "johansson2011"
    bed_conductivity: str = "given"
    convection_factor: float = 1.0
    radiation_model: str = "grey"
    near_bed_mixing: float | None = None
    bed_radiation: bool = False
    exposed_bed_penetration: bool = False

    def __post_init__(self):
        for name, value, allowed in (
            ("closures.gas_wall", self.gas_wall, GAS_WALL),
            ("closures.gas_bed", self.gas_bed, GAS_BED),
            ("closures.covered_wall", self.covered_wall, COVERED_WALL),
            ("closures.bed_conductivity", self.bed_conductivity, BED_CONDUCTIVITY),
            ("closures.radiation_model", self.radiation_model, RADIATION_MODELS),
        ):
            if value not in allowed:
                raise InputError(name, value, "one of " + ", ".join(allowed))
        if isinstance(self.gas_emissivity, str):
            if self.gas_emissivity not in GAS_EMISSIVITY:
                raise InputError(
                    "closures.gas_emissivity",
                    self.gas_emissivity,
                    "one of " + ", ".join(GAS_EMISSIVITY) + " or a number in [0, 1)",
                )
        else:
            check_range("closures.gas_emissivity", self.gas_emissivity, 0.0, 1.0, closed_low=True)
        check_range("closures.convection_factor", self.convection_factor, 0.0, 100.0)
        if self.near_bed_mixing is not None:
            check_range(
                "closures.near_bed_mixing", self.near_bed_mixing, 0.0, 1e4, closed_high=True
            )

    @classmethod
    def from_case(cls, section) -> Closures:
        """The closures of a case file's ``closures`` section (:class:`rotarykiln.case.Closures`):
        its ``preset`` (``default``: these defaults; ``seed004``: :data:`SEED004_CLOSURES`)
        with the keys it gives.

        Examples
        --------
        >>> from rotarykiln.case import Closures as ClosuresSection
        >>> c = Closures.from_case(ClosuresSection(gas_bed="gorog1982"))
        >>> c.gas_bed, c.gas_wall
        ('gorog1982', 'tscheng1979')
        >>> Closures.from_case(ClosuresSection(preset="seed004", radiation=False)).gas_wall
        'gorog1982'
        """
        base = SEED004_CLOSURES if getattr(section, "preset", "default") == "seed004" else cls()
        given = {f.name: getattr(section, f.name) for f in fields(cls)}
        return dataclasses.replace(base, **{k: v for k, v in given.items() if v is not None})


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
class Kiln:
    """Everything the kiln model needs, inert or reacting (SI units).

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
    Wall: ``layers`` (inner to outer, :class:`~rotarykiln.materials.lining.Layer`): a lined
    wall (:class:`~rotarykiln.kiln.wall.LinedWall`: k(T) layers, shell loss by convection and radiation to
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
    ``fill`` may also vary along the kiln (an array at evenly spaced positions from z = 0 to
    L, a pair ``(z, fill)`` of arrays, or a callable of z; e.g. a transport model's profile
    for a bed that does not react).
    ``bed_solids``: bed species -> :class:`~rotarykiln.materials.solids.Solid` whose
    temperature-dependent enthalpy (phases included) replaces the constant ``bed_cp``;
    ``bed_material``: a Solid whose properties (cp(T), conductivity and its closures,
    particle size, emissivity, bulk density) the cross-section exchange uses instead of the
    constant ones above.
    ``heat_release`` (W) released in the gas along ``heat_release_profile`` (callable of the
    cell centres, normalised; None: uniform), e.g. a burner's burn-out;
    ``flame``: the :class:`~rotarykiln.kiln.flame.Flame` of a burner (heating values and jet
    numbers for the energy sheet and the summary); ``measurements``: measured profiles
    (``z_gas``, ``t_gas``, ``z_bed``, ...) overlaid on the plots.
    ``soot``: (f_v, z_start, z_end), a luminous zone (a sooting flame) of soot volume
    fraction f_v between z_start and z_end (m), whose grey soot emissivity adds to the gas's
    (:func:`rotarykiln.heat.gas_radiation.soot_emissivity`); None: a non-luminous gas.
    ``stirred_zone``: (z_start, z_end, K), the burner's recirculation zone, a well-stirred
    gas: its gas nodes exchange heat by an axial conductance K (W m/K, strong enough for a zone
    Peclet number of 0.1), conserving energy; None: plug-flow gas throughout.
    ``bed_dispersion`` (m2/s): axial dispersion coefficient of the bed inside the balances
    (:mod:`rotarykiln.kiln.dispersion`; 0: plug flow; e.g. :math:`u L / Pe` with Pe from
    :mod:`rotarykiln.rtd.correlations`).
    ``heaters``: electric heater zones on the shell
    (:class:`~rotarykiln.kiln.wall.HeaterZone`: a power or a shell set-point; a lined wall only).
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
    bed_solids: dict = field(default_factory=dict)
    bed_material: object | None = None
    heat_release: float = 0.0
    heat_release_profile: object | None = None
    flame: object | None = None
    measurements: dict | None = None
    bed_dispersion: float = 0.0
    heaters: tuple = ()
    soot: tuple[float, float, float] | None = None
    stirred_zone: tuple[float, float, float] | None = None

    def __post_init__(self):
        check_positive("kiln.length", self.length, "m")
        check_positive("kiln.radius", self.radius, "m")
        check_positive("operation.speed", self.omega, "rad/s")
        if isinstance(self.fill, int | float):
            check_range("bed.fill", self.fill, 0.0, 0.5, closed_high=True)
        check_nonnegative("burner.heat_release", self.heat_release, "W")
        check_positive("bed.residence_time (solids speed)", self.bed_velocity, "m/s")
        check_positive("operation.feed_temperature", self.feed_temperature, "K")
        check_positive("gas.temperature", self.gas_inlet_temperature, "K")
        check_positive("material.bulk_density", self.bulk_density, "kg/m3")
        check_positive("material.thermal_conductivity", self.bed_conductivity, "W/(m K)")
        check_range("material.emissivity", self.bed_emissivity, 0.0, 1.0, closed_high=True)
        for name, eps in (
            ("wall.emissivity", self.wall_emissivity),
            ("wall.shell_emissivity", self.shell_emissivity),
        ):
            if eps is not None:
                check_range(name, eps, 0.0, 1.0, closed_high=True)
        check_nonnegative("wall.wind_speed", self.wind_speed, "m/s")
        if not isinstance(self.closures, Closures):
            raise InputError("closures", self.closures, "a Closures object")
        if self.closures.bed_conductivity != "given" and self.bed_material is None:
            raise InputError(
                "closures.bed_conductivity",
                self.closures.bed_conductivity,
                "given (a bed without a library solid uses material.thermal_conductivity)",
            )
        check_positive("material.particle_size", self.particle_diameter, "m")
        check_nonnegative("wall.U", self.wall_loss_u, "W/(m2 K)")
        check_positive("wall.ambient_temperature", self.ambient_temperature, "K")
        check_positive("gas.pressure", self.pressure, "Pa")
        check_nonnegative("bed.axial_dispersion", self.bed_dispersion, "m2/s")
        if self.soot is not None:
            f_v, z0, z1 = self.soot
            check_range("burner.soot_volume_fraction", f_v, 0.0, 1e-4, closed_high=True)
            if not 0.0 <= z0 < z1 <= self.length + 1e-9:
                raise InputError(
                    "burner.soot_volume_fraction", (z0, z1), "a luminous zone inside the kiln"
                )
        if self.heaters and not self.layers:
            raise InputError(
                "wall.heaters", "given", "with a lining (the heaters sit on the shell)"
            )
        for zone in self.heaters:
            if zone.end > self.length + 1e-9:
                raise InputError(
                    "wall.heaters",
                    f"{zone.end:.6g} m",
                    f"<= the kiln length ({self.length:.6g} m)",
                )
        zones = sorted(self.heaters, key=lambda z: z.start)
        for a, b in zip(zones, zones[1:], strict=False):
            if b.start < a.end - 1e-9:
                raise InputError(
                    "wall.heaters",
                    f"[{a.start:.6g} m, {a.end:.6g} m] and [{b.start:.6g} m, {b.end:.6g} m]",
                    "zones that do not overlap (one may end where the next starts)",
                )
        if (
            self.heat_release == 0.0
            and not self.mechanism.reactions
            and self.gas_inlet_temperature < self.feed_temperature
        ):
            warnings.warn(
                f"gas inlet temperature {self.gas_inlet_temperature:.6g} K is colder than "
                f"the solids feed ({self.feed_temperature:.6g} K): the gas cools the bed",
                UserWarning,
                stacklevel=3,
            )
        sp = self.mechanism.species
        for label, flows, phase in (
            ("material.composition", self.feed, "bed"),
            ("gas", self.gas_in, "gas"),
        ):
            if not flows or sum(flows.values()) <= 0:
                raise InputError(f"{label} mass flow", flows, "> 0 kg/s in total")
            for name, q in flows.items():
                if name not in sp or sp[name].phase != phase:
                    raise InputError(f"{label}.{name}", name, f"a {phase} species")
                check_nonnegative(f"{label}.{name}", q, "kg/s")
        for name, cp in self.bed_cp.items():
            check_positive(f"material.specific_heat ({name})", cp, "J/(kg K)")
        if self.steam_flow is not None:
            check_nonnegative("gas.steam_flow", self.steam_flow, "kg/s")
        if self.gas_emissivity_law is not None:
            a, b, lo = self.gas_emissivity_law
            if not (np.isfinite(a) and np.isfinite(b) and 0 <= lo < 1):
                raise InputError(
                    "gas.emissivity_a", self.gas_emissivity_law, "finite a, b; 0 <= min < 1"
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

    @classmethod
    def inert(
        cls,
        *,
        solid,
        solids_flow: float,
        solids_inlet_temperature: float,
        gas_composition,
        gas_flow: float,
        gas_inlet_temperature: float,
        closures: Closures | None = None,
        **kw,
    ) -> Kiln:
        """A kiln whose bed does not react: a library solid heated (or cooled) by a gas.

        ``solid`` (:class:`~rotarykiln.materials.solids.Solid`) fed at ``solids_flow`` (kg/s)
        and ``solids_inlet_temperature`` (K) as the bed species ``inert`` with the solid's
        h(T); the gas of ``gas_composition`` (mole fractions, e.g. ``"O2:0.21, N2:0.79"``;
        species outside the chemistry table, such as traces of NO or OH in burnt gas, are
        counted as N2 by mass) at ``gas_flow`` (kg/s) and ``gas_inlet_temperature`` (K); no
        reaction. ``closures`` default to :class:`Closures` (Tscheng & Watkinson, Li 2005);
        ``kw``: the other fields (``length``, ``radius``, ``omega``, ``fill``, ``layers``,
        ``counter_current``, ``heat_release``, ...).

        Examples
        --------
        >>> from rotarykiln.materials.solids import load_solid
        >>> k = Kiln.inert(solid=load_solid("sand"), solids_flow=0.004,
        ...     solids_inlet_temperature=298.15, gas_composition="O2:0.21, N2:0.79",
        ...     gas_flow=0.007, gas_inlet_temperature=535.0, length=2.44, radius=0.094,
        ...     omega=0.157, fill=0.17)
        >>> sorted(k.gas_in), round(k.residence_time)
        (['N2', 'O2'], 4750)
        """
        from rotarykiln.materials.gas import parse_composition

        check_positive("operation.feed", solids_flow, "kg/s")
        check_positive("gas.flow", gas_flow, "kg/s")
        mech = Mechanism(())
        sp = mech.species
        mass = {}
        for name, x in parse_composition(gas_composition):
            key = name if name in sp.gas_names else None
            if key is None:
                from rotarykiln.materials.gas import molar_mass

                mm = molar_mass(f"{name}:1")
                key = "N2"
            else:
                mm = sp[key].molar_mass
            mass[key] = mass.get(key, 0.0) + x * mm
        total = sum(mass.values())
        gas_in = {k: gas_flow * m / total for k, m in mass.items()}
        fill = kw.pop("fill")
        probe = cls(
            feed={"inert": solids_flow},
            feed_temperature=solids_inlet_temperature,
            bed_cp={},
            bulk_density=solid.bulk_density,
            bed_conductivity=solid.bed_conductivity or solid.solid_conductivity,
            bed_emissivity=solid.emissivity,
            particle_diameter=solid.particle_diameter,
            gas_in=gas_in,
            gas_inlet_temperature=gas_inlet_temperature,
            mechanism=mech,
            bed_solids={"inert": solid},
            bed_material=solid,
            closures=closures or Closures(),
            fill=fill,
            bed_velocity=1.0,
            **kw,
        )
        area = np.pi * probe.radius**2
        velocity = solids_flow / (solid.bulk_density * probe.mean_fill * area)
        return dataclasses.replace(probe, bed_velocity=velocity)

    def fill_at(self, z) -> np.ndarray:
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
        check_range("fill", out, 0.0, 0.5, closed_high=True)
        return out

    @property
    def mean_fill(self) -> float:
        """Fill averaged along the kiln, -."""
        return float(np.mean(self.fill_at(np.linspace(0.0, self.length, 201))))

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
