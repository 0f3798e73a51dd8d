"""Build the :class:`~rotarykiln.kiln.inputs.kiln.Kiln` of a validated case file.

:func:`kiln_from_case` is the one entry point from a :class:`rotarykiln.case.Case` to the
kiln model (the steady solve, the transient, sweeps, the app). The case's sections map onto the
model as follows:

- ``kiln``, ``operation`` (speed, feed, feed temperature, gas direction);
- ``material``: the bed; without ``chemistry`` an inert library ``solid`` (c_p(T) with its
  phases); with ``chemistry`` the feed ``composition`` of bed species, with constant
  properties (``specific_heat``, ``thermal_conductivity``, ``emissivity``; a library solid
  named by ``solid`` or ``name`` fills the gaps);
- ``bed`` (fill or residence time, axial dispersion) or ``transport`` (the Kramers/Scott bed
  profile; with ``chemistry`` the Kramers bed depth is solved with the balances, so the
  profile follows the mass the bed loses, or keeps the fresh feed's volume: ``volume``,
  ``shrinkage``);
- ``gas`` (a hot-gas or sweep-gas inlet) or ``burner`` (fuel and air, burnt by
  :func:`rotarykiln.kiln.combustion.flame.fire`);
- ``wall`` (lining layers, a constant U or a heating jacket; heater zones), ``closures``,
  ``measurements``,
  ``solver`` (cells), ``chemistry`` (reactions).

Studies build thousands of kilns from variants of one case that differ in a few operating
fields (:func:`rotarykiln.case.case_with`): the parts built from sections that do not change
(the lining layers and their materials, the library solid, the closures, the reaction
mechanism, the inlet gas's mass shares) are kept in small bounded caches keyed on the
section's content (the ``repr`` of its values, every float exactly), so a variant's kiln
costs a fraction of a millisecond. The objects kept are frozen dataclasses (their arrays
read-only), shared by the kilns built from equal sections; a kiln built from the cache
equals, bit for bit, one built afresh.
"""

from __future__ import annotations

import dataclasses
import math
from functools import lru_cache

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.kiln.combustion.flame import AirStream, Burner, fire
from rotarykiln.kiln.inputs import (
    SEED004_CLOSURES,
    Bed,
    Chemistry,
    Closures,
    Drum,
    Feed,
    Firing,
    GasInlet,
    Kiln,
    Wall,
)
from rotarykiln.kiln.wall.lining import HeaterZone
from rotarykiln.materials.gas import AIR
from rotarykiln.materials.lining import Layer

__all__ = [
    "burner_from_case",
    "closures_from_case",
    "default_origins",
    "jacket_from_case",
    "kiln_from_case",
    "layers_from_case",
    "mechanism_from_case",
]


def kiln_from_case(case) -> tuple[Kiln, int]:
    """The :class:`~rotarykiln.kiln.inputs.kiln.Kiln` and cell count of a validated case.

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> kiln, cells = kiln_from_case(load_case(builtin_case_path("barr_T4")))
    >>> round(kiln.drum.length, 2), cells, kiln.firing.flame is not None
    (5.5, 100, True)
    """
    if not case.has_kiln_model:
        raise InputError(
            "gas", None, "a gas: or burner: section (the kiln's heat source), or wall.heaters"
        )
    if case.wall is None:
        raise InputError("wall", None, "given (lining: layers, or U: a loss coefficient)")
    feed = case.operation.feed
    if feed is None or feed <= 0:
        raise InputError("operation.feed", feed, "> 0 kg/s for the kiln model")
    gas = _inlet_gas(case)
    if case.chemistry is None:
        kiln = _inert_kiln(case, gas)
    else:
        kiln = _reacting_kiln(case, gas)
    kiln = kiln.replace(bed__dispersion=_bed_dispersion(case, kiln))
    return kiln, int(case.solver.cells)


def _common(case, gas: dict) -> dict:
    """The branches of :class:`Kiln` every kind of kiln takes the same way: the wall, the
    burner's firing, the closures, the name and the measurements."""
    meas = None
    if case.measurements is not None:
        m = case.measurements
        dump = m.model_dump(exclude={"thermocouple"})
        meas = {k: np.asarray(v, dtype=float) for k, v in dump.items()}
        meas["wall_interface"] = int(m.wall_interface)
        if m.thermocouple is not None:
            meas["thermocouple"] = m.thermocouple.model_dump()
    return dict(
        wall=_wall(case),
        firing=Firing(
            heat_release=gas.get("heat_release", 0.0),
            profile=gas.get("heat_release_profile"),
            flame=gas.get("flame"),
            soot=gas.get("soot"),
            particles=gas.get("particles"),
            stirred_zone=gas.get("stirred_zone"),
        ),
        closures=closures_from_case(case.closures),
        measurements=meas,
        name=case.name,
    )


def closures_from_case(section) -> Closures:
    """The :class:`~rotarykiln.kiln.inputs.closures.Closures` of a case file's ``closures``
    section: its ``preset`` (``default``: the library's defaults; ``seed004``:
    :data:`~rotarykiln.kiln.inputs.closures.SEED004_CLOSURES`) with the keys it gives.

    Examples
    --------
    >>> from rotarykiln.case import Closures as ClosuresSection
    >>> c = closures_from_case(ClosuresSection(gas_bed="gorog1982"))
    >>> c.gas_bed, c.gas_wall
    ('gorog1982', 'tscheng1979')
    >>> closures_from_case(ClosuresSection(preset="seed004", radiation=False)).gas_wall
    'gorog1982'
    """
    key = _content_key(section)
    if key is None:
        return _closures(section)
    return _cached_closures(_ByContent(key, section))


def _closures(section) -> Closures:
    base = SEED004_CLOSURES if section.preset == "seed004" else Closures()
    given = {f.name: getattr(section, f.name) for f in dataclasses.fields(Closures)}
    return dataclasses.replace(base, **{k: v for k, v in given.items() if v is not None})


@lru_cache(maxsize=32)
def _cached_closures(section: _ByContent) -> Closures:
    return _closures(section.value)


class _ByContent:
    """A section (or any input) passed through an ``lru_cache`` by its content ``key`` alone:
    equal keys are the same entry, whatever object carries them."""

    __slots__ = ("key", "value")

    def __init__(self, key, value):
        self.key = key
        self.value = value

    def __hash__(self) -> int:
        return hash(self.key)

    def __eq__(self, other) -> bool:
        return isinstance(other, _ByContent) and self.key == other.key


def _content_key(section, fields: tuple[str, ...] | None = None) -> str | None:
    """The content of a case-file section (or of its ``fields``) as a cache key: the ``repr``
    of its values (every field; floats written exactly, -0.0 apart from 0.0, NaN apart from
    None, 1 apart from 1.0 and True, text quoted), or None for what is not a section (then
    built afresh)."""
    from pydantic import BaseModel

    if not isinstance(section, BaseModel):
        return None
    memo = (id(section), fields)
    if (hit := _KEYS.get(memo)) is not None and hit[0] is section:
        return hit[1]  # the same (frozen) section: a study's cases share their unchanged ones
    if fields is None:
        key = f"{type(section).__qualname__}:{section!r}"
    else:
        key = f"{type(section).__qualname__}:{tuple(getattr(section, f) for f in fields)!r}"
    if len(_KEYS) >= KEYS_KEPT:
        _KEYS.clear()
    _KEYS[memo] = (section, key)  # the section kept alive: its id is not reused meanwhile
    return key


#: Content keys of the case sections seen last (by identity; case sections are frozen): the
#: repr of a section costs ~0.1 ms, a study's cases share their unchanged sections.
KEYS_KEPT = 512
_KEYS: dict = {}


def _exact(value) -> tuple:
    """A value as a cache key that tells 1 from 1.0 and from True, and 0.0 from -0.0."""
    return (type(value), repr(value))


def _read_only(obj):
    """``obj`` with the numpy arrays among its attributes made read-only (a shared object of
    the caches: a solver writing into one raises instead of changing the next kiln)."""
    for value in getattr(obj, "__dict__", {}).values():
        if isinstance(value, np.ndarray):
            value.setflags(write=False)
    return obj


def _inert_kiln(case, gas: dict) -> Kiln:
    """A bed of a library solid that does not react (:meth:`Kiln.inert`)."""
    from rotarykiln.commands.model_runs import bed_fill_profile

    m = case.material
    name = m.solid or _library_name(m.name)
    if name is None:
        raise InputError(
            "material.solid", None, "a library solid (the bed of a kiln without chemistry:)"
        )
    overrides = {}
    if m.bulk_density is not None:
        overrides["bulk_density"] = m.bulk_density
    if m.particle_size is not None:
        overrides["particle_diameter"] = m.particle_size
    if m.specific_heat is not None:
        overrides["cp_const"] = m.specific_heat
    if m.emissivity is not None:
        overrides["emissivity"] = m.emissivity
    if m.thermal_conductivity is not None:
        overrides["bed_conductivity"] = m.thermal_conductivity
    solid = _solid(name, **overrides)
    bed = case.bed
    if case.transport is not None:
        fill = bed_fill_profile(case)
    elif bed is not None and bed.fill is not None:
        fill = np.asarray(bed.fill, dtype=float) if isinstance(bed.fill, list) else bed.fill
    elif bed is not None and bed.residence_time is not None:
        area = math.pi * (case.kiln.diameter / 2.0) ** 2
        fill = case.operation.feed * bed.residence_time / case.kiln.length / solid.bulk_density
        fill /= area
    else:
        raise InputError("bed.fill", None, "given (or bed.residence_time, or a transport: section)")
    kiln = Kiln.inert(
        fill=fill,
        solid=solid,
        solids_flow=case.operation.feed,
        solids_inlet_temperature=case.operation.feed_temperature,
        gas_composition=gas["gas_in_mole"],
        gas_flow=gas["gas_flow"],
        gas_inlet_temperature=gas["gas_inlet_temperature"],
        length=case.kiln.length,
        radius=case.kiln.diameter / 2.0,
        omega=case.operation.speed,
        counter_current=case.operation.counter_current,
        **_common(case, gas),
    )
    kiln = kiln.replace(gas__pressure=gas["pressure"], gas__emissivity_law=gas.get("law"))
    if gas.get("steam_flow") is not None:
        kiln = kiln.replace(chemistry__steam_flow=gas["steam_flow"])
    if case.gas is not None and case.gas.mass_fractions is not None:  # as given, by mass
        kiln = kiln.replace(gas__flows=gas["gas_in"])
    return kiln


def _reacting_kiln(case, gas: dict) -> Kiln:
    """A bed of reacting species (``chemistry:``, feed ``material.composition``)."""
    ch = case.chemistry
    if ch.gas_gain_per_carbon != "corrected":
        raise InputError(
            "chemistry.gas_gain_per_carbon",
            ch.gas_gain_per_carbon,
            "corrected (seed 004's 30/12 gas gain creates mass and breaks the element balance)",
        )
    m = case.material
    if m.composition is None:
        raise InputError(
            "material.composition", None, "given with chemistry: (bed-species mass fractions)"
        )
    feed = case.operation.feed
    lib = _library_solid(m.solid or m.name)
    rho = m.bulk_density or (lib.bulk_density if lib else None)
    if rho is None:
        raise InputError("material.bulk_density", None, "given (or a library material.solid)")
    length, radius = case.kiln.length, case.kiln.diameter / 2.0
    bed_depth = None
    bed = case.bed
    if case.transport is not None:
        bed_depth, fill, velocity = _kramers_bed(case, rho)
    elif bed is not None and bed.residence_time is not None:
        velocity = length / bed.residence_time
        fill = feed * bed.residence_time / length / rho / (math.pi * radius**2)
    elif bed is not None and bed.fill is not None:
        fill = bed.mean_fill
        velocity = feed / (rho * fill * math.pi * radius**2)
    else:
        raise InputError("bed.residence_time", None, "given (or bed.fill, or a transport: section)")
    if not 0 < fill <= 0.5:
        raise InputError("bed.residence_time", None, f"a fill <= 0.5 (got {fill:.3g})")
    mech = mechanism_from_case(ch)
    bed_cp = {}
    if m.specific_heat is not None:
        bed_cp = {n: m.specific_heat for n in mech.species.bed_names if n != "H2O(l)"}
    kb = m.thermal_conductivity or (lib.bed_conductivity if lib else None) or 0.3
    eps_b = m.emissivity if m.emissivity is not None else (lib.emissivity if lib else 0.9)
    dp = m.particle_size or (lib.particle_diameter if lib else 5e-3)
    return Kiln(
        drum=Drum(length, radius, case.operation.speed),
        bed=Bed(
            fill=fill,
            velocity=velocity,
            bulk_density=rho,
            conductivity=kb,
            emissivity=eps_b,
            particle_diameter=dp,
            cp=bed_cp,
            depth=bed_depth,
        ),
        feed=Feed({n: w * feed for n, w in m.composition.items()}, case.operation.feed_temperature),
        gas=GasInlet(
            gas["gas_in"],
            gas["gas_inlet_temperature"],
            pressure=gas["pressure"],
            counter_current=case.operation.counter_current,
            emissivity_law=gas.get("law"),
        ),
        chemistry=Chemistry(mech, steam_flow=gas.get("steam_flow")),
        **_common(case, gas),
    )


def _inlet_gas(case) -> dict:
    """Inlet gas of the kiln: the burner's products, or the ``gas:`` section.

    Returns the species mass flows ``gas_in`` (kg/s, species of the chemistry table; others
    such as traces of NO or OH counted as N2), the mole-fraction text ``gas_in_mole`` (for
    :meth:`Kiln.inert`), ``gas_flow``, ``gas_inlet_temperature`` and the burner's
    ``heat_release``, ``heat_release_profile`` and ``flame``, the gas emissivity line,
    ``steam_flow`` and ``pressure``.
    """
    g, b = case.gas, case.burner
    out: dict = {"pressure": g.pressure if g is not None else 101325.0}
    if g is not None:
        if g.emissivity_a is not None:
            law = (g.emissivity_a, g.emissivity_b_per_K or 0.0, g.emissivity_minimum or 0.0)
            out["law"] = law
        if g.steam_flow is not None:
            out["steam_flow"] = g.steam_flow
    length = case.kiln.length
    if b is not None:
        if g is not None and (g.flow is not None or g.temperature is not None):
            raise InputError(
                "gas.flow", g.flow, "absent with a burner: (the burner makes the inlet gas)"
            )
        if b.flame_length is not None and b.flame_length > length:
            raise InputError(
                "burner.flame_length",
                f"{b.flame_length:.6g} m",
                f"<= the kiln length ({length:.6g} m)",
            )
        flame = fire(
            burner_from_case(b, case.operation.counter_current), case.kiln.diameter, length
        )
        p = flame.products
        if b.soot_volume_fraction > 0:
            out["soot"] = _luminous_zone(b, flame, length, case.operation.counter_current)
        if b.particle_radiation and flame.particle_absorption is not None:
            out["particles"] = _particle_cloud(flame, length, case.operation.counter_current)
        out.update(
            gas_in=_products_flows(p),
            gas_in_mole=p.composition,
            gas_flow=p.mass_flow,
            gas_inlet_temperature=flame.inlet_temperature,
            heat_release=flame.heat_release,
            heat_release_profile=flame.release_profile(length, case.operation.counter_current),
            stirred_zone=flame.stirred_zone(length, case.operation.counter_current),
            flame=flame,
        )
        return out
    if g is None or g.flow is None or g.flow <= 0 or g.temperature is None:
        raise InputError(
            "gas.flow",
            None if g is None else g.flow,
            "> 0 kg/s with gas.temperature (or a burner: section)",
        )
    if g.mass_fractions is not None:
        gas_in = {n: w * g.flow for n, w in g.mass_fractions.items()}
        mole = _mole_text(g.mass_fractions)
    else:
        mole = g.composition or AIR
        gas_in = _mass_flows(mole, g.flow)
    out.update(
        gas_in=gas_in, gas_in_mole=mole, gas_flow=g.flow, gas_inlet_temperature=g.temperature
    )
    return out


#: A particle flame's luminous zone: where its fuels release this share of their heat.
LUMINOUS_SHARE = 0.99


def _products_flows(products) -> dict[str, float]:
    """Species mass flows (kg/s) of a burner's products: by their mass fractions when the
    products were made by elements (solid and liquid fuels: exact), else by their mole
    fractions (:func:`_mass_flows`)."""
    table = products.table
    if hasattr(table, "mass_fractions"):
        pairs = zip(table.names, table.mass_fractions, strict=True)
        return {n: w * products.mass_flow for n, w in pairs}
    return _mass_flows(products.composition, products.mass_flow)


def _luminous_zone(section, flame, length: float, counter_current: bool):
    """(f_v, z_start, z_end) of a sooting flame: the flame length from the burner end; for the
    ``particles`` model without a flame length, the length within which its fuels release
    99 % of their heat (:meth:`~rotarykiln.kiln.combustion.flame.Flame.release_distance`)."""
    lf = flame.flame_length
    if lf is None:
        lf = flame.release_distance(LUMINOUS_SHARE)
    if lf is None:
        raise InputError(
            "burner.soot_volume_fraction",
            section.soot_volume_fraction,
            "0 without burner.flame_length or burner.nozzle_diameter (the luminous zone is "
            "the flame), or with combustion: particles",
        )
    lf = min(float(lf), length)
    zone = (length - lf, length) if counter_current else (0.0, lf)
    return (float(section.soot_volume_fraction), *zone)


def _particle_cloud(flame, length: float, counter_current: bool):
    """(z, kappa): the burning particles' absorption coefficient (1/m) at kiln positions z
    (m, increasing) from the flame's table against the distance from the burner."""
    x = np.asarray(flame.release_table[0], dtype=float)
    kappa = np.asarray(flame.particle_absorption, dtype=float)
    if counter_current:  # the burner at z = length
        x, kappa = length - x[::-1], kappa[::-1]
    return tuple(float(v) for v in x), tuple(float(v) for v in kappa)


def _mass_flows(composition, flow: float) -> dict[str, float]:
    """Species mass flows (kg/s) of ``flow`` kg/s of a gas of mole fractions ``composition``
    (text or pairs); species outside the chemistry table are counted as N2, by mass."""
    if type(composition) is str:
        key = composition
    elif isinstance(composition, tuple | list) and all(
        isinstance(p, tuple) and len(p) == 2 and type(p[0]) is str and type(p[1]) is float
        for p in composition
    ):  # (species, mole fraction) pairs, a flame's products
        key = tuple((n, repr(x)) for n, x in composition)
    else:
        key = None
    if key is None:
        mass, total = _shares(composition)
    else:
        mass, total = _mass_shares(_ByContent(key, composition))
    return {k: flow * v / total for k, v in mass}


@lru_cache(maxsize=64)
def _mass_shares(composition: _ByContent) -> tuple[tuple[tuple[str, float], ...], float]:
    return _shares(composition.value)


def _shares(composition) -> tuple[tuple[tuple[str, float], ...], float]:
    """Species -> x M (kg/mol, species outside the chemistry table counted as N2) of a gas of
    mole fractions ``composition`` (text or pairs), and their sum."""
    from rotarykiln.chemistry.species import default_species
    from rotarykiln.materials.gas import parse_composition

    pairs = parse_composition(composition) if isinstance(composition, str) else composition
    known = set(default_species().gas_names)
    mass: dict[str, float] = {}
    for name, x in pairs:
        key = name if name in known else "N2"
        mass[key] = mass.get(key, 0.0) + x * gas_molar_mass(name)
    total = sum(mass.values())
    return tuple(mass.items()), total


@lru_cache(maxsize=128)
def gas_molar_mass(name: str) -> float:
    """Molar mass of a gas species, kg/mol: GRI-Mech 3.0's (Cantera), or the chemistry
    table's for a species outside it (SO2 of a fuel's sulphur)."""
    from rotarykiln.chemistry.species import default_species
    from rotarykiln.materials.gas import molar_mass

    sp = default_species()
    if name in sp.gas_names and sp[name].thermo is not None:
        return float(sp[name].molar_mass)
    return molar_mass(f"{name}:1")


def _mole_text(mass_fractions: dict[str, float]) -> str:
    """Mole fractions (Cantera text) of a gas given by mass fractions."""
    from rotarykiln.materials.gas import molar_mass

    moles = {n: w / molar_mass(f"{n}:1") for n, w in mass_fractions.items() if w > 0}
    total = sum(moles.values())
    return ", ".join(f"{n}:{v / total:.12g}" for n, v in moles.items())


def _wall(case) -> Wall:
    """The :class:`Wall` branch: lining layers with the shell loss and heater zones, a
    constant U, or a heating jacket."""
    w = case.wall
    common = dict(ambient_temperature=w.ambient_temperature, emissivity=w.emissivity)
    if w.jacket is not None:  # the jacket is the wall model (kiln/wall/jacket.py)
        return Wall(jacket=jacket_from_case(w.jacket), **common)
    heaters = tuple(HeaterZone(z.start, z.end, z.power, z.shell_temperature) for z in w.heaters)
    if w.lining is None:
        return Wall(loss_u=w.U, heaters=heaters, **common)
    return Wall(
        layers=layers_from_case(w.lining, "wall"),
        wind_speed=w.wind_speed,
        shell_emissivity=w.shell_emissivity,
        heaters=heaters,
        **common,
    )


def jacket_from_case(section):
    """The :class:`~rotarykiln.kiln.wall.jacket.Jacket` of a case file's ``wall.jacket`` section.

    Examples
    --------
    >>> from rotarykiln.case import Jacket as JacketSection
    >>> j = jacket_from_case(JacketSection(flow="175 kg/h", temperature="560 degC",
    ...                                    specific_heat="1226.9 J/kg/K"))
    >>> round(j.mass_flow * 3600, 6), j.htc, j.counter_current
    (175.0, 'annulus', False)
    """
    from rotarykiln.kiln.wall.jacket import Jacket

    return Jacket(
        section.flow,
        section.temperature,
        cp=section.specific_heat,
        composition=section.composition,
        counter_current=section.counter_current,
        htc=section.heat_transfer,
        gap=section.gap,
        wall_thickness=section.wall_thickness,
        wall_conductivity=section.wall_conductivity,
        casing_u=section.casing_u,
        casing_perimeter=section.casing_perimeter,
        radiation=section.radiation,
        eps_drum=section.drum_emissivity,
        eps_casing=section.casing_emissivity,
    )


def burner_from_case(section, counter_current: bool = True) -> Burner:
    """The :class:`~rotarykiln.kiln.combustion.flame.Burner` of a case file's ``burner`` section.

    ``counter_current``: the gas direction; an air ingress at the feed end joins the burner's
    air in a co-current kiln (the burner is at the feed end) and the exhaust otherwise.

    Examples
    --------
    >>> from rotarykiln.case import Burner as BurnerSection
    >>> b = burner_from_case(BurnerSection(fuel="CH4:1", fuel_flow="2 kg/h",
    ...                                    primary_air={"flow": "40 kg/h"}))
    >>> round(b.fuel_flow * 3600, 6), round(b.air_flow * 3600, 6)
    (2.0, 40.0)
    """
    fuel, primary, secondary = section.mass_flows()
    p, s = section.primary_air, section.secondary_air
    return Burner(
        fuel=section.fuel,
        fuel_flow=fuel,
        primary_air=AirStream(primary, *((p.temperature, p.gas) if p else ())),
        secondary_air=AirStream(secondary, *((s.temperature, s.gas) if s else ())),
        fuel_temperature=section.fuel_temperature,
        nozzle_diameter=section.nozzle_diameter,
        combustion=section.combustion,
        flame_length=section.flame_length,
        ingress_air=AirStream(
            section.ingress_flow(),
            section.air_ingress.temperature if section.air_ingress is not None else 298.15,
        ),
        ingress_at_burner=not counter_current,
        products=section.products,
        recirculation_length=section.recirculation_length,
        fired=fired_fuels_from_case(section),
    )


def fired_fuels_from_case(section) -> tuple:
    """The :class:`~rotarykiln.kiln.combustion.fired_fuels.FiredFuel` of a burner section's
    ``solid_fuels`` and ``liquid_fuels`` (labels ``solid_fuels[i]``, ``liquid_fuels[i]``)."""
    from rotarykiln.kiln.combustion.fired_fuels import FiredFuel

    out = []
    for state, items in (("solid", section.solid_fuels), ("liquid", section.liquid_fuels)):
        for i, f in enumerate(items):
            out.append(
                FiredFuel(
                    f.solid_fuel(),
                    f.flow,
                    state,
                    None if f.fineness is None else f.fineness.distribution(),
                    f.specific_heat,
                    label=f"{state}_fuels[{i}]" if f.name is None else f.name,
                )
            )
    return tuple(out)


def mechanism_from_case(chem):
    """The :class:`~rotarykiln.chemistry.Mechanism` of a ``chemistry`` section (built-in
    names or user mappings, on the built-in species and the section's own ``species``);
    reactions with a sharp onset temperature (``width`` 0) get ``chemistry.onset_width``."""
    key = _content_key(chem, ("species", "reactions", "onset_width", "kirchhoff"))
    if key is None:
        return _mechanism(chem)
    return _cached_mechanism(_ByContent(key, chem))


@lru_cache(maxsize=16)
def _cached_mechanism(chem: _ByContent):
    mech = _read_only(_mechanism(chem.value))
    for r in mech.reactions:
        _read_only(r)
    return mech


def _mechanism(chem):
    from rotarykiln.chemistry.mechanism import Mechanism
    from rotarykiln.chemistry.reaction import builtin_reactions, reaction_from_dict
    from rotarykiln.chemistry.species import default_species, load_species

    # the built-in species, with the case's own (chemistry.species) when it has some
    sp = default_species() if chem.species is None else load_species(chem.species)
    known = builtin_reactions(sp)
    chosen = []
    for i, item in enumerate(chem.reactions):
        if isinstance(item, str):
            r = known[item]
        else:
            r = reaction_from_dict(item, sp, where=f"chemistry.reactions[{i}]")
        if chem.onset_width > 0 and r.params.get("width", None) == 0.0:
            r = dataclasses.replace(r, params={**r.params, "width": float(chem.onset_width)})
        chosen.append(r)
    return Mechanism(tuple(chosen), sp, kirchhoff=chem.kirchhoff)


def _library_name(name: str | None) -> str | None:
    from rotarykiln.materials._library import load_library

    return name if name in load_library("solids.yaml") else None


def _library_solid(name: str | None):
    name = _library_name(name)
    return _solid(name) if name is not None else None


def _solid(name: str, **overrides):
    """:func:`~rotarykiln.materials.solids.load_solid` of the library solid ``name`` with its
    overrides, kept for the last few (name, overrides) built (a frozen
    :class:`~rotarykiln.materials.solids.Solid`)."""
    from rotarykiln.materials.solids import load_solid

    if not all(isinstance(v, float | int | str | bool | None) for v in overrides.values()):
        return load_solid(name, **overrides)
    key = (name, tuple((k, *_exact(v)) for k, v in sorted(overrides.items())))
    return _cached_solid(_ByContent(key, (name, overrides)))


@lru_cache(maxsize=32)
def _cached_solid(given: _ByContent):
    from rotarykiln.materials.solids import load_solid

    name, overrides = given.value
    return load_solid(name, **overrides)


def _bed_dispersion(case, kiln: Kiln) -> float:
    """Axial dispersion coefficient of the bed (m2/s) of ``bed.axial_dispersion``: the
    Sherritt et al. (2003) correlation (default), ``plug`` flow, or a given Peclet u L / D."""
    from rotarykiln.rtd.correlations import sherritt_dispersion

    choice = case.bed.axial_dispersion if case.bed is not None else "sherritt2003"
    if choice == "plug":
        return 0.0
    if choice == "sherritt2003":
        d = sherritt_dispersion(
            kiln.drum.omega, 2.0 * kiln.drum.radius, kiln.bed.particle_diameter, kiln.mean_fill
        )
        return float(d)
    return kiln.bed.velocity * kiln.drum.length / float(choice)


def _kramers_bed(case, density):
    """The :class:`KramersBed` of a ``transport:`` section, and the fill and solids speed of
    its constant-flow profile (the solve's starting point: the Saeman profile of the fresh
    feed's volume flow, the feed over the bulk density, whatever the volume law)."""
    from rotarykiln.commands.model_runs import bed_profile_from_case
    from rotarykiln.kiln.bed.depth import KramersBed

    t = case.transport
    if t.model != "kramers" or t.weirs:
        raise InputError(
            "transport.model",
            t.model if t.model != "kramers" else "kramers with weirs",
            "kramers without weirs (the bed depth solved inside a reacting kiln)",
        )
    if t.dam_height is None:
        raise InputError("transport.dam_height", None, "given (> 0) for a reacting kiln's bed")
    if case.material.repose_angle is None:
        raise InputError("material.repose_angle", None, "given with a transport: section")
    bed = KramersBed(
        case.kiln.diameter / 2.0,
        case.operation.speed,
        case.kiln.slope,
        case.material.repose_angle,
        density,
        t.dam_height,
        **_volume_law(case, density),
    )
    profile = bed_profile_from_case(case)
    fill = float(np.mean(profile.fill))
    velocity = case.kiln.length / float(profile.mean_residence_time)
    return bed, fill, velocity


def _volume_law(case, density) -> dict:
    r"""The volume law of the solved bed depth (``transport.volume``, ``transport.shrinkage``;
    :class:`~rotarykiln.kiln.bed.depth.KramersBed`): nothing for ``bulk`` (the flow over the
    bulk density, the law's default); for ``fresh_feed`` the fresh feed's volumetric flow
    :math:`\dot V_0 = \dot m_0/\rho_b` (m3/s), its species flows (kg/s) and the shrinkage.

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> law = _volume_law(load_case(builtin_case_path("rotary_pyrolysis")), 279.5)
    >>> law["volume_law"], round(law["volume_flow0"] * 3600, 5), law["shrinkage"]
    ('fresh_feed', 0.10733, 0.0)
    """
    t = case.transport
    if t.volume == "bulk":
        return {}
    feed = case.operation.feed
    return dict(
        volume_law=t.volume,
        volume_flow0=feed / density,
        feed=tuple((n, w * feed) for n, w in case.material.composition.items()),
        shrinkage=t.shrinkage,
    )


def layers_from_case(lining, section: str = "wall") -> tuple[Layer, ...]:
    """Lining layers of a case file's ``lining`` list (:class:`rotarykiln.case.LiningLayer`).

    Raises :class:`~rotarykiln.errors.InputError` (``<section>.lining``) for an empty list.

    Examples
    --------
    >>> from rotarykiln.case import LiningLayer
    >>> (layer,) = layers_from_case([LiningLayer(material="fireclay_brick", thickness="0.1 m")])
    >>> layer.material.name, layer.thickness
    ('fireclay_brick', 0.1)
    """
    keys = [_content_key(spec) for spec in lining or ()]
    if keys and None not in keys:
        return _cached_layers(_ByContent((section, *keys), (tuple(lining), section)))
    return _layers(lining, section)


@lru_cache(maxsize=32)
def _cached_layers(lining: _ByContent) -> tuple[Layer, ...]:
    return _layers(*lining.value)


def _layers(lining, section: str) -> tuple[Layer, ...]:
    from rotarykiln.materials.lining import LiningMaterial, load_lining_material

    def material(spec):
        if isinstance(spec, str):
            return load_lining_material(spec)
        return LiningMaterial(spec.name, tuple(spec.k), spec.emissivity, spec.t_max)

    def layer_of(spec):
        profile = None
        thickness = spec.thickness
        if spec.thickness_profile is not None:
            z, t = zip(*spec.thickness_profile, strict=True)
            profile = (tuple(z), tuple(t))
            thickness = max(t)
        absent = tuple(tuple(a) for a in spec.absent)
        return Layer(material(spec.material), thickness, absent=absent, profile=profile)

    layers = tuple(layer_of(spec) for spec in lining or ())
    if not layers:
        raise InputError(f"{section}.lining", "[]", "a list of at least one layer")
    return layers


def default_origins(case) -> dict[str, str]:
    """Case-file field -> where the model's value comes from, for the inputs the case leaves
    to a default (what the warnings of a run say of a value the case did not give).

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> default_origins(load_case(builtin_case_path("tscheng_A16")))
    {}
    """
    m = case.material
    if m.particle_size is not None:
        return {}
    field = "material.particle_size"
    name = _library_name(m.solid or m.name)
    if name is None:
        return {field: f"the model's default particle size: give {field}"}
    return {field: f"the library default for {name}: give {field}"}
