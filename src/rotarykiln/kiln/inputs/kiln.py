r"""Inputs of the kiln model as a tree of frozen dataclasses (SI units), validated once.

:class:`Kiln` is the root; each branch holds one part of the kiln and each choice of model is a
field of a branch, not a subclass:

=================  ===========================================================================
branch             holds
=================  ===========================================================================
``drum``           :class:`Drum`: length, inner radius, rotation rate
``bed``            :class:`Bed`: fill (constant, profile or callable), solids speed, bulk and
                   particle properties, the bed's enthalpy (constant c_p or library solids),
                   the bed-depth law (``depth``: None for the given fill, or a
                   :class:`~rotarykiln.kiln.bed.depth.KramersBed` solved with the balances,
                   with its volume law) and the axial dispersion
``feed``           :class:`Feed`: the solids feed, mass flow per bed species, temperature
``gas``            :class:`GasInlet`: the gas entering the kiln, its direction and pressure
``firing``         :class:`Firing`: heat released in the gas by a burner, its flame, soot, the
                   stirred zone (all off for a kiln without a burner)
``wall``           :class:`Wall`: lining layers or a constant U, shell, heater zones, or a
                   heating :class:`~rotarykiln.kiln.wall.jacket.Jacket`
``chemistry``      :class:`Chemistry`: the mechanism (empty for an inert bed)
``closures``       :class:`~rotarykiln.kiln.inputs.closures.Closures`: every closure by name
=================  ===========================================================================

A case file becomes a :class:`Kiln` in one place, :func:`rotarykiln.kiln.from_case.kiln_from_case`.
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.errors import InputError, check_nonnegative, check_positive, check_range
from rotarykiln.kiln.inputs.closures import SEED004_CLOSURES, Closures
from rotarykiln.materials.lining import Layer

__all__ = ["Drum", "Bed", "Feed", "GasInlet", "Firing", "Wall", "Chemistry", "Kiln"]


@dataclass(frozen=True)
class Drum:
    """The rotating drum: ``length`` (m), ``radius`` (m, inner), ``omega`` (rad/s)."""

    length: float
    radius: float
    omega: float

    def __post_init__(self):
        check_positive("kiln.length", self.length, "m")
        check_positive("kiln.radius", self.radius, "m")
        check_positive("operation.speed", self.omega, "rad/s")


@dataclass(frozen=True)
class Bed:
    """The solids bed.

    ``fill`` (-): a constant, an array at evenly spaced positions from z = 0 to L, a pair
    ``(z, fill)`` of arrays, or a callable of z (e.g. a transport model's profile);
    ``velocity`` (m/s): axial solids speed (hold-up per length of species i is
    ``Q_i / velocity``); ``bulk_density`` (kg/m3); ``conductivity`` (W/(m K));
    ``emissivity`` (-); ``particle_diameter`` (m); ``cp``: bed species -> constant specific
    heat (J/(kg K)); ``solids``: bed species -> :class:`~rotarykiln.materials.solids.Solid`
    whose h(T) (phases included) replaces the constant c_p; ``material``: a Solid whose
    properties the cross-section exchange uses instead of the constants above; ``depth``:
    None (the given ``fill``) or a :class:`~rotarykiln.kiln.bed.depth.KramersBed` solved with
    the balances (fill and hold-up then follow it; ``fill`` and ``velocity`` only seed the
    solve); ``dispersion`` (m2/s): axial dispersion coefficient inside the balances (0: plug
    flow).
    """

    fill: float | np.ndarray | tuple | Callable
    velocity: float
    bulk_density: float
    conductivity: float
    emissivity: float
    particle_diameter: float
    cp: dict = field(default_factory=dict)
    solids: dict = field(default_factory=dict)
    material: object | None = None
    depth: object | None = None
    dispersion: float = 0.0

    def __post_init__(self):
        if isinstance(self.fill, int | float):
            check_range("bed.fill", self.fill, 0.0, 0.5, closed_high=True)
        check_positive("bed.residence_time (solids speed)", self.velocity, "m/s")
        check_positive("material.bulk_density", self.bulk_density, "kg/m3")
        check_positive("material.thermal_conductivity", self.conductivity, "W/(m K)")
        check_range("material.emissivity", self.emissivity, 0.0, 1.0, closed_high=True)
        check_positive("material.particle_size", self.particle_diameter, "m")
        check_nonnegative("bed.axial_dispersion", self.dispersion, "m2/s")
        for name, cp in self.cp.items():
            check_positive(f"material.specific_heat ({name})", cp, "J/(kg K)")
        if self.depth is not None and self.depth.density != self.bulk_density:
            raise InputError(
                "material.bulk_density",
                self.bulk_density,
                f"the bed-depth law's density ({self.depth.density:.6g} kg/m3): one bulk density",
            )


@dataclass(frozen=True)
class Feed:
    """The solids feed: ``flows`` (bed species -> mass flow, kg/s), ``temperature`` (K)."""

    flows: dict
    temperature: float

    def __post_init__(self):
        check_positive("operation.feed_temperature", self.temperature, "K")

    @property
    def total(self) -> float:
        """Total solids feed, kg/s."""
        return float(sum(self.flows.values()))


@dataclass(frozen=True)
class GasInlet:
    r"""The gas entering the kiln.

    ``flows`` (gas species -> mass flow, kg/s), ``temperature`` (K), ``pressure`` (Pa),
    ``counter_current`` (True: the gas enters at z = L, against the solids; False: at z = 0,
    with them), ``emissivity_law`` (a, b, minimum) for
    :math:`\varepsilon_g = \max(a + bT, \min)`, or None for the WSGG model of the closures
    with the local CO2 and H2O partial pressures.
    """

    flows: dict
    temperature: float
    pressure: float = 101325.0
    counter_current: bool = True
    emissivity_law: tuple[float, float, float] | None = None

    def __post_init__(self):
        check_positive("gas.temperature", self.temperature, "K")
        check_positive("gas.pressure", self.pressure, "Pa")
        if self.emissivity_law is not None:
            a, b, lo = self.emissivity_law
            if not (np.isfinite(a) and np.isfinite(b) and 0 <= lo < 1):
                raise InputError(
                    "gas.emissivity_a", self.emissivity_law, "finite a, b; 0 <= min < 1"
                )

    @property
    def total(self) -> float:
        """Total gas inlet flow, kg/s."""
        return float(sum(self.flows.values()))


@dataclass(frozen=True)
class Firing:
    """Heat released in the gas by a burner (all off without one).

    ``heat_release`` (W) released along ``profile`` (callable of the cell centres, normalised;
    None: uniform); ``flame``: the :class:`~rotarykiln.kiln.combustion.flame.Flame` of the
    burner (heating values and jet numbers for the energy sheet and the summary); ``soot``:
    (f_v, z_start, z_end), a luminous zone of soot volume fraction f_v between z_start and
    z_end (m), whose grey soot emissivity adds to the gas's; ``particles``: (z, kappa), the
    absorption coefficient of a solid fuel's burning particles (1/m) at the kiln positions z
    (m, increasing), a grey absorber added to the gas's like soot; ``stirred_zone``: (z_start, z_end,
    K), the burner's recirculation zone, a well-stirred gas whose nodes exchange heat by an
    axial conductance K (W m/K).
    """

    heat_release: float = 0.0
    profile: Callable | None = None
    flame: object | None = None
    soot: tuple[float, float, float] | None = None
    particles: tuple[tuple, tuple] | None = None
    stirred_zone: tuple[float, float, float] | None = None

    def __post_init__(self):
        check_nonnegative("burner.heat_release", self.heat_release, "W")
        if self.particles is not None:
            z, kappa = (np.asarray(v, dtype=float) for v in self.particles)
            if z.shape != kappa.shape or z.size < 2 or np.any(np.diff(z) <= 0):
                raise InputError("burner.particles", z.size, "increasing positions, one kappa each")
            check_nonnegative("burner.particles kappa", float(np.min(kappa)), "1/m")
        if self.soot is not None:
            check_range("burner.soot_volume_fraction", self.soot[0], 0.0, 1e-4, closed_high=True)


@dataclass(frozen=True)
class Wall:
    """The kiln wall and what heats it from outside.

    ``layers`` (inner to outer, :class:`~rotarykiln.materials.lining.Layer`): a lined wall
    (:class:`~rotarykiln.kiln.wall.lining.LinedWall`: k(T) layers, shell loss by convection and
    radiation to ``ambient_temperature`` with ``wind_speed`` m/s, ``shell_emissivity``
    default that of the last layer); without layers: one inner-wall temperature with the loss
    :math:`U \\pi D (T_w - T_a)`, ``loss_u`` (W/(m2 K), on the inner wall). ``emissivity``:
    the inner surface's (default that of the first layer, or 0.9 without layers).
    ``heaters``: electric heater zones on the shell
    (:class:`~rotarykiln.kiln.wall.lining.HeaterZone`; a lined wall only); ``jacket``: a
    heating :class:`~rotarykiln.kiln.wall.jacket.Jacket` (the wall model then; no lining, no
    heaters).
    """

    layers: tuple[Layer, ...] = ()
    loss_u: float = 5.0
    ambient_temperature: float = 298.15
    emissivity: float | None = None
    shell_emissivity: float | None = None
    wind_speed: float = 0.0
    heaters: tuple = ()
    jacket: object | None = None

    def __post_init__(self):
        for name, eps in (
            ("wall.emissivity", self.emissivity),
            ("wall.shell_emissivity", self.shell_emissivity),
        ):
            if eps is not None:
                check_range(name, eps, 0.0, 1.0, closed_high=True)
        check_nonnegative("wall.wind_speed", self.wind_speed, "m/s")
        check_nonnegative("wall.U", self.loss_u, "W/(m2 K)")
        check_positive("wall.ambient_temperature", self.ambient_temperature, "K")
        if self.heaters and not self.layers:
            raise InputError(
                "wall.heaters", "given", "with a lining (the heaters sit on the shell)"
            )
        if self.jacket is not None and (self.heaters or self.layers):
            raise InputError(
                "jacket", "given with heaters or a lining", "a jacket alone (the wall model)"
            )
        zones = sorted(self.heaters, key=lambda z: z.start)
        for a, b in zip(zones, zones[1:], strict=False):
            if b.start < a.end - 1e-9:
                raise InputError(
                    "wall.heaters",
                    f"[{a.start:.6g} m, {a.end:.6g} m] and [{b.start:.6g} m, {b.end:.6g} m]",
                    "zones that do not overlap (one may end where the next starts)",
                )

    @property
    def inner_emissivity(self) -> float:
        """Emissivity of the inner wall surface, -."""
        if self.emissivity is not None:
            return self.emissivity
        return self.layers[0].material.emissivity if self.layers else 0.9

    @property
    def outer_emissivity(self) -> float:
        """Emissivity of the outer shell surface (lined wall), -."""
        if self.shell_emissivity is not None:
            return self.shell_emissivity
        return self.layers[-1].material.emissivity if self.layers else 0.9


@dataclass(frozen=True)
class Chemistry:
    """The bed and gas chemistry: ``mechanism`` (:class:`~rotarykiln.chemistry.Mechanism`,
    empty for an inert bed), ``steam_flow`` (kg/s, seed 004's constant Q_a for the Ortiz law;
    None: the local gas H2O flow)."""

    mechanism: Mechanism
    steam_flow: float | None = None

    def __post_init__(self):
        if self.steam_flow is not None:
            check_nonnegative("gas.steam_flow", self.steam_flow, "kg/s")


@dataclass(frozen=True)
class Kiln:
    """Everything the kiln model needs, inert or reacting, heated by any source (SI units).

    The branches are described in :mod:`rotarykiln.kiln.inputs.kiln`; ``name`` names the kiln
    in results and plots; ``measurements``: measured profiles (``z_gas``, ``t_gas``,
    ``z_bed``, ...) overlaid on the plots.

    Examples
    --------
    >>> from rotarykiln.materials.solids import load_solid
    >>> k = Kiln.inert(solid=load_solid("sand"), solids_flow=0.004,
    ...     solids_inlet_temperature=298.15, gas_composition="O2:0.21, N2:0.79",
    ...     gas_flow=0.007, gas_inlet_temperature=535.0, length=2.44, radius=0.094,
    ...     omega=0.157, fill=0.17)
    >>> k.drum.length, sorted(k.gas.flows), round(k.residence_time)
    (2.44, ['N2', 'O2'], 4750)
    """

    drum: Drum
    bed: Bed
    feed: Feed
    gas: GasInlet
    chemistry: Chemistry
    wall: Wall = field(default_factory=Wall)
    firing: Firing = field(default_factory=Firing)
    closures: Closures = field(default_factory=lambda: SEED004_CLOSURES)
    name: str = "reacting kiln"
    measurements: dict | None = None

    def __post_init__(self):
        for name, branch, kind in (
            ("kiln", self.drum, Drum),
            ("bed", self.bed, Bed),
            ("feed", self.feed, Feed),
            ("gas", self.gas, GasInlet),
            ("chemistry", self.chemistry, Chemistry),
            ("wall", self.wall, Wall),
            ("burner", self.firing, Firing),
            ("closures", self.closures, Closures),
        ):
            if not isinstance(branch, kind):
                raise InputError(name, type(branch).__name__, f"a {kind.__name__} object")
        if self.closures.bed_conductivity != "given" and self.bed.material is None:
            raise InputError(
                "closures.bed_conductivity",
                self.closures.bed_conductivity,
                "given (a bed without a library solid uses material.thermal_conductivity)",
            )
        length = self.drum.length
        if self.firing.soot is not None:
            _, z0, z1 = self.firing.soot
            if not 0.0 <= z0 < z1 <= length + 1e-9:
                raise InputError(
                    "burner.soot_volume_fraction", (z0, z1), "a luminous zone inside the kiln"
                )
        for zone in self.wall.heaters:
            if zone.end > length + 1e-9:
                raise InputError(
                    "wall.heaters", f"{zone.end:.6g} m", f"<= the kiln length ({length:.6g} m)"
                )
        if (
            self.firing.heat_release == 0.0
            and not self.chemistry.mechanism.reactions
            and self.gas.temperature < self.feed.temperature
        ):
            warnings.warn(
                f"gas inlet temperature {self.gas.temperature:.6g} K is colder than "
                f"the solids feed ({self.feed.temperature:.6g} K): the gas cools the bed",
                UserWarning,
                stacklevel=3,
            )
        sp = self.chemistry.mechanism.species
        for label, flows, phase in (
            ("material.composition", self.feed.flows, "bed"),
            ("gas", self.gas.flows, "gas"),
        ):
            if not flows or sum(flows.values()) <= 0:
                raise InputError(f"{label} mass flow", flows, "> 0 kg/s in total")
            for name, q in flows.items():
                if name not in sp or sp[name].phase != phase:
                    raise InputError(f"{label}.{name}", name, f"a {phase} species")
                check_nonnegative(f"{label}.{name}", q, "kg/s")

    def replace(self, **branches) -> Kiln:
        """A copy with whole branches replaced, or single fields by ``branch__field``.

        Examples
        --------
        >>> from rotarykiln.materials.solids import load_solid
        >>> k = Kiln.inert(solid=load_solid("sand"), solids_flow=0.004,
        ...     solids_inlet_temperature=298.15, gas_composition="O2:0.21, N2:0.79",
        ...     gas_flow=0.007, gas_inlet_temperature=535.0, length=2.44, radius=0.094,
        ...     omega=0.157, fill=0.17)
        >>> k.replace(bed__dispersion=1e-5, closures__radiation=False).bed.dispersion
        1e-05
        >>> k.replace(bed__dispersoin=1e-5)  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        rotarykiln.errors.InputError: Kiln.replace: ...bed__dispersoin... a field of bed: fill, ...
        """
        names = [f.name for f in dataclasses.fields(self)]
        nested: dict[str, dict] = {}
        whole = {}
        for key, value in branches.items():
            branch, sep, name = key.partition("__")
            if branch not in names:
                raise InputError("Kiln.replace", key, "a branch of " + ", ".join(names))
            if sep:
                nested.setdefault(branch, {})[name] = value
            else:
                whole[branch] = value
        for branch, changes in nested.items():
            base = whole.get(branch, getattr(self, branch))
            fields = (
                [f.name for f in dataclasses.fields(base)] if dataclasses.is_dataclass(base) else []
            )
            for name in changes:
                if name not in fields:
                    raise InputError(
                        "Kiln.replace",
                        f"{branch}__{name}",
                        f"a field of {branch}: " + ", ".join(fields),
                    )
            whole[branch] = dataclasses.replace(base, **changes)
        return dataclasses.replace(self, **whole)

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
        length: float,
        radius: float,
        omega: float,
        fill,
        closures: Closures | None = None,
        counter_current: bool = True,
        wall: Wall | None = None,
        firing: Firing | None = None,
        bed_dispersion: float = 0.0,
        name: str = "reacting kiln",
        measurements: dict | None = None,
    ) -> Kiln:
        """A kiln whose bed does not react: a library solid heated (or cooled) by a gas.

        ``solid`` (:class:`~rotarykiln.materials.solids.Solid`) fed at ``solids_flow`` (kg/s)
        and ``solids_inlet_temperature`` (K) as the bed species ``inert`` with the solid's
        h(T); the gas of ``gas_composition`` (mole fractions, e.g. ``"O2:0.21, N2:0.79"``;
        species outside the chemistry table, such as traces of NO or OH in burnt gas, are
        counted as N2 by mass) at ``gas_flow`` (kg/s) and ``gas_inlet_temperature`` (K); no
        reaction. The drum (``length``, ``radius`` m, ``omega`` rad/s), the ``fill`` (any
        form :class:`Bed` takes; the solids speed follows from it and the feed), the
        ``wall`` and ``firing`` branches; ``closures`` default to :class:`Closures` (Tscheng &
        Watkinson, Li 2005).
        """
        from rotarykiln.materials.gas import molar_mass, parse_composition

        check_positive("operation.feed", solids_flow, "kg/s")
        check_positive("gas.flow", gas_flow, "kg/s")
        mech = Mechanism(())
        sp = mech.species
        mass = {}
        for species, x in parse_composition(gas_composition):
            if species in sp.gas_names:
                key, mm = species, sp[species].molar_mass
            else:
                key, mm = "N2", molar_mass(f"{species}:1")
            mass[key] = mass.get(key, 0.0) + x * mm
        total = sum(mass.values())
        drum = Drum(length, radius, omega)
        bed = Bed(
            fill=fill,
            velocity=1.0,
            bulk_density=solid.bulk_density,
            conductivity=solid.bed_conductivity or solid.solid_conductivity,
            emissivity=solid.emissivity,
            particle_diameter=solid.particle_diameter,
            solids={"inert": solid},
            material=solid,
            dispersion=bed_dispersion,
        )
        mean_fill = _mean_fill(bed.fill, length)
        velocity = solids_flow / (solid.bulk_density * mean_fill * np.pi * radius**2)
        return cls(
            drum=drum,
            bed=dataclasses.replace(bed, velocity=velocity),
            feed=Feed({"inert": solids_flow}, solids_inlet_temperature),
            gas=GasInlet(
                {k: gas_flow * m / total for k, m in mass.items()},
                gas_inlet_temperature,
                counter_current=counter_current,
            ),
            chemistry=Chemistry(mech),
            wall=wall or Wall(),
            firing=firing or Firing(),
            closures=closures or Closures(),
            name=name,
            measurements=measurements,
        )

    def fill_at(self, z) -> np.ndarray:
        """Fill fraction at positions ``z`` (m), from whichever form the bed's fill was given in."""
        return _fill_at(self.bed.fill, self.drum.length, z)

    @property
    def mean_fill(self) -> float:
        """Fill averaged along the kiln, -."""
        return _mean_fill(self.bed.fill, self.drum.length)

    @property
    def feed_flow(self) -> float:
        """Total solids feed, kg/s."""
        return self.feed.total

    @property
    def gas_flow(self) -> float:
        """Total gas inlet flow, kg/s."""
        return self.gas.total

    @property
    def residence_time(self) -> float:
        """Mean solids residence time of the given fill, L / v, s (with a solved bed depth,
        the solution's :attr:`~rotarykiln.kiln.results.solution.KilnSolution.residence_time`)."""
        return self.drum.length / self.bed.velocity


def _fill_at(fill, length: float, z) -> np.ndarray:
    """Fill fraction at ``z`` (m) of a fill given as a constant, samples, (z, fill) or callable."""
    z = np.asarray(z, dtype=float)
    if callable(fill):
        out = np.asarray(fill(z), dtype=float) * np.ones_like(z)
    elif isinstance(fill, tuple):
        zf, vf = (np.asarray(a, dtype=float) for a in fill)
        out = np.interp(z, zf, vf)
    else:
        arr = np.asarray(fill, dtype=float)
        if arr.ndim == 0:
            out = np.full_like(z, float(arr))
        else:
            out = np.interp(z, np.linspace(0.0, length, arr.size), arr)
    check_range("fill", out, 0.0, 0.5, closed_high=True)
    return out


def _mean_fill(fill, length: float) -> float:
    return float(np.mean(_fill_at(fill, length, np.linspace(0.0, length, 201))))
