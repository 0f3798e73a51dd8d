"""Case files: YAML with units in, validated SI objects out.

A case file gives physical values as strings with units; pydantic models convert each one once to
an SI float. Unknown keys are rejected. Any error becomes one :class:`~rotarykiln.errors.InputError`
line naming the field path, the value and what is accepted, e.g.::

    kiln.diameter: -0.4 m is not > 0
    operation.speed: "3 m" is a length, expected a rotation rate

Example case::

    name: limestone pilot kiln
    kiln:
      length: 5.5 m
      diameter: 0.406 m
      slope: 1.72 deg
    operation:
      speed: 1.5 rpm
      feed: 42 kg/h
    material:
      name: limestone
      bulk_density: 1500 kg/m3
      repose_angle: 35 deg

Sections of the physics packages (``bed``, ``transport``, ``rtd``, ``gas``, ``burner``, ``wall``,
``chemistry`` ...) are optional
fields of :class:`Case`.
"""

from __future__ import annotations

import copy
import difflib
import inspect
import math
import re
import threading
import types
import typing
from collections.abc import Mapping
from functools import lru_cache
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    TypeAdapter,
    ValidationError,
    model_validator,
)
from pydantic_core import PydanticCustomError

from rotarykiln.errors import InputError
from rotarykiln.materials._library import load_library
from rotarykiln.units import to_si
from rotarykiln.yaml_limits import (
    MAX_NUMBER_CHARS,  # noqa: F401 (importable from here, as before)
    MAX_YAML_ALIASES,
    MAX_YAML_BYTES,
    MAX_YAML_DEPTH,
    MAX_YAML_VALUES,
    LimitedLoader,
    YamlLimitError,
    check_structure,
    read_yaml_file,
    short_repr,
)

__all__ = [
    "Angle",
    "Bed",
    "Burner",
    "BurnerAir",
    "Closures",
    "Gas",
    "Jacket",
    "Measurements",
    "Solver",
    "Wall",
    "LiningLayer",
    "Case",
    "Chemistry",
    "Density",
    "Fraction",
    "HeatTransferCoefficient",
    "Instant",
    "Kiln",
    "Length",
    "Mass",
    "MassFlow",
    "Material",
    "Operation",
    "Power",
    "RTD",
    "RTDLifters",
    "Pressure",
    "RotationRate",
    "Section",
    "SpecificHeat",
    "Temperature",
    "ThermalConductivity",
    "Time",
    "Transport",
    "TransportWeir",
    "Velocity",
    "VolumetricFlow",
    "case_with",
    "change_fields",
    "case_file_path",
    "check_quantity",
    "load_case",
    "parse_case",
    "quantity",
    "read_case_data",
    "read_case_yaml",
]


class Section(BaseModel):
    """Base of every case-file section: unknown keys are rejected, models are frozen."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    def model_copy(self, *, update: Any = None, deep: bool = False):
        """A copy; with ``update``, refused: pydantic would not check the new values (a case
        changes through :meth:`Case.replace`, which validates them)."""
        if update:
            raise InputError(
                "update",
                message=f"update: {type(self).__name__}.model_copy(update=...) does not check "
                "values; change a case with case.replace({'operation.speed': '2.5 rpm'}) "
                "(dotted fields of the case, validated as a case file)",
            )
        return super().model_copy(deep=deep)


def _bound_text(gt, ge, lt, le) -> str:
    parts = []
    if gt is not None:
        parts.append(f"> {gt:g}")
    if ge is not None:
        parts.append(f">= {ge:g}")
    if lt is not None:
        parts.append(f"< {lt:g}")
    if le is not None:
        parts.append(f"<= {le:g}")
    return " and ".join(parts)


def quantity(
    kind: str,
    *,
    gt: float | None = None,
    ge: float | None = None,
    lt: float | None = None,
    le: float | None = None,
    shown: str | None = None,
):
    """An annotated float field that accepts ``"1.5 rpm"``-style strings and stores SI.

    Bounds apply to the SI value; ``shown`` (e.g. ``"< 90 deg"``) replaces the bound text in
    messages when the SI bound would read oddly.
    """

    def convert(value: Any) -> float:
        try:
            si = to_si("", value, kind)
        except InputError as exc:
            raise PydanticCustomError("quantity", str(exc).removeprefix(": ")) from None
        ok = (
            (gt is None or si > gt)
            and (ge is None or si >= ge)
            and (lt is None or si < lt)
            and (le is None or si <= le)
            and math.isfinite(si)
        )
        if not ok:
            raise PydanticCustomError(
                "quantity_range",
                "{value} is not {bound}",
                {"value": value, "bound": shown or _bound_text(gt, ge, lt, le)},
            )
        return si

    return Annotated[float, BeforeValidator(convert)]


# Physical ranges (issue 15): wide enough for any real kiln or lab drum, narrow enough that no
# 1e-308 or 1e300 reaches a solver. The message shows the range in the unit most people type.
Length = quantity("length", ge=1e-6, le=1e4, shown="in [1 um, 10 km]")
Position = quantity("length", ge=0, le=1e4, shown="in [0, 10 km]")
#: A lining layer's local thickness (0: the layer is absent there).
LayerThickness = quantity("length", ge=0, le=10.0, shown="in [0, 10 m]")
Angle = quantity("angle", ge=-math.pi / 2, le=math.pi / 2, shown="in [-90, 90] deg")
RotationRate = quantity(
    "rotation rate", ge=1e-6, le=100.0, shown="in [1e-5 rpm, 955 rpm] (1e-6 to 100 rad/s)"
)
MassFlow = quantity("mass flow", ge=0, le=1e5, shown="in [0, 1e5 kg/s]")
VolumetricFlow = quantity("volumetric flow", ge=0, le=1e4, shown="in [0, 1e4 m3/s]")
Temperature = quantity("temperature", ge=150.0, le=1e4, shown="in [150 K, 10000 K]")
"""A temperature of a kiln case: no stream, wall or ambient of a kiln is colder than 150 K (the
floor the solver evaluates properties at), none hotter than 10000 K."""
Density = quantity("density", ge=1e-3, le=1e5, shown="in [0.001, 1e5] kg/m3")
Time = quantity("time", ge=1e-6, le=1e10, shown="in [1 us, 1e10 s]")
Instant = quantity("time", ge=0, le=1e10, shown="in [0, 1e10 s]")
"""A moment of a run from its start (a transient event's ``at``): a :data:`Time` or zero."""
Mass = quantity("mass", gt=0, le=1e6, shown="in (0, 1e6 kg]")
"""A mass fed at once (a tracer pulse), up to a thousand tonnes."""
Velocity = quantity("velocity", ge=0, le=1e3, shown="in [0, 1000] m/s")
Fraction = quantity("fraction", ge=0, le=1)
Power = quantity("power", ge=-1e10, le=1e10, shown="in [-1e10, 1e10] W")
Pressure = quantity("pressure", ge=1.0, le=1e8, shown="in [1 Pa, 1000 bar]")
ThermalConductivity = quantity(
    "thermal conductivity", ge=1e-5, le=1e4, shown="in [1e-5, 1e4] W/(m K)"
)
SpecificHeat = quantity("specific heat", ge=1.0, le=1e6, shown="in [1, 1e6] J/(kg K)")
HeatTransferCoefficient = quantity(
    "heat transfer coefficient", ge=0, le=1e6, shown="in [0, 1e6] W/(m2 K)"
)

SootFraction = quantity("fraction", ge=0, le=1e-4, shown="in [0, 1e-4]")
Slope = quantity("angle", ge=0, lt=math.radians(45), shown="in [0, 45) deg")
ReposeAngle = quantity("angle", gt=0, lt=math.radians(90), shown="in (0, 90) deg")
Shrinkage = quantity("fraction", ge=0, lt=1, shown="in [0, 1)")
"""The share of a bed's volume lost at full conversion (``transport.shrinkage``): 1 would be a
bed that vanishes."""
FillFraction = quantity("fraction", ge=1e-3, lt=1, shown="in [0.001, 1)")
"""A bed fill: below 0.1 % no kiln model has a bed to work on (a fill of 1e-308 is refused at
load rather than failing in the solver)."""


class Kiln(Section):
    """The drum: inner length and diameter, slope of its axis."""

    length: Length
    diameter: Length
    slope: Slope = 0.0


class Operation(Section):
    """Operating point: rotation speed, solids feed (mass flow) and its temperature, and the
    gas direction (``counter_current``: the gas flows against the solids, the usual kiln;
    false: with them, as in co-current dryers and pyrolysis kilns)."""

    speed: RotationRate
    feed: MassFlow | None = None
    feed_temperature: Temperature = 298.15
    counter_current: bool = True


def _int_in(low: int, high: int):
    """An integer field in [low, high] (an integral float such as ``1e3`` is accepted)."""

    def check(v: Any) -> int:
        if (
            isinstance(v, bool)
            or not isinstance(v, int | float)
            or (isinstance(v, float) and not (math.isfinite(v) and v.is_integer()))
            or not low <= v <= high
        ):
            raise PydanticCustomError(
                "number",
                "{value} is not an integer in [{low}, {high}]",
                {"value": v, "low": low, "high": high},
            )
        return int(v)

    return Annotated[int, BeforeValidator(check)]


Cells = _int_in(4, 20_000)
"""Cells along the kiln (the kiln model): at least 4; 20,000 is 1 mm in a 20 m kiln."""


def _positive_number(v: Any) -> float:
    if isinstance(v, bool) or not isinstance(v, int | float) or not v > 0:
        raise PydanticCustomError("number", "{value} is not a number > 0", {"value": v})
    return float(v)


#: Peclet numbers (u L / D) the kiln and RTD models accept: the RTD models' own range
#: (:data:`rotarykiln.rtd.dispersion.SHAPE_RANGE`); beyond it the bed is plug flow or well mixed.
PECLET_RANGE = (1e-6, 1e10)


def _peclet(v: Any) -> float:
    x = _positive_number(v)
    if not PECLET_RANGE[0] <= x <= PECLET_RANGE[1]:
        raise PydanticCustomError(
            "number",
            "{value} is not in [1e-06, 1e+10] (a Peclet number u L / D)",
            {"value": v},
        )
    return x


def _library_name(filename: str):
    """A validator: the value must be an entry of the material library ``filename``."""

    def check(v: Any) -> str:
        names = sorted(load_library(filename))
        if v not in names:
            shown = "None" if v is None else _show(v)  # None: "empty, expected one of ..."
            raise PydanticCustomError(
                "choice",
                "{value} is not one of {names}",
                {"value": shown, "names": ", ".join(names)},
            )
        return v

    return check


SolidName = Annotated[str, BeforeValidator(_library_name("solids.yaml"))]
LiningMaterialName = Annotated[str, BeforeValidator(_library_name("refractories.yaml"))]


class LiningMaterialSpec(Section):
    """A lining material given in the case file: conductivity k(T) = k0 + k1 T + k2 T^2
    (``k``: [k0 W/(m K), k1 W/(m K2), k2 W/(m K3)], T in K), surface emissivity and service
    limit."""

    name: str
    k: Annotated[list[float], BeforeValidator(lambda v: _k_coefficients(v))]
    emissivity: Fraction = 0.85
    t_max: Temperature = 1700.0


def _k_coefficients(v: Any) -> list[float]:
    if (
        not isinstance(v, list)
        or not 1 <= len(v) <= 3
        or not all(isinstance(x, int | float) and not isinstance(x, bool) for x in v)
        or not all(math.isfinite(x) for x in v)
    ):
        raise PydanticCustomError(
            "number",
            "{value} is not a list [k0, k1, k2] of finite numbers (k = k0 + k1 T + k2 T^2, "
            "W/(m K), T in K)",
            {"value": v},
        )
    return [float(x) for x in v] + [0.0] * (3 - len(v))


class LiningLayer(Section):
    """One lining layer (``wall.lining``): a library material (or one given inline), a
    thickness and the stretches (from z, to z) where it is absent; or, for a layer whose
    thickness varies along the kiln (a coating built up in the burning zone, a worn brick),
    ``thickness_profile``: ``[z, thickness]`` pairs, linear between them, constant beyond,
    the layer absent where its thickness is 0."""

    material: LiningMaterialName | LiningMaterialSpec
    thickness: Length | None = None
    absent: list[tuple[Position, Position]] = []
    thickness_profile: list[tuple[Position, LayerThickness]] | None = None

    @model_validator(mode="after")
    def _one_thickness(self):
        if (self.thickness is None) == (self.thickness_profile is None):
            raise PydanticCustomError(
                "number", "give thickness or thickness_profile, one of them", {}
            )
        if self.thickness_profile is not None:
            z = [p for p, _ in self.thickness_profile]
            if not all(b > a for a, b in zip(z, z[1:], strict=False)):
                raise PydanticCustomError(
                    "number", "thickness_profile positions must increase along the kiln", {}
                )
            if not max(t for _, t in self.thickness_profile) > 0:
                raise PydanticCustomError("number", "thickness_profile is 0 everywhere", {})
        return self


def _gas_flow_text(v: Any) -> Any:
    """A burner flow as given: a string with its unit (converted by :class:`Burner`)."""
    if isinstance(v, bool) or not isinstance(v, str | int | float):
        raise PydanticCustomError(
            "number", '{value} is not a gas flow with a unit ("2.2 kg/h", "12 Nm3/h")', {"value": v}
        )
    return v


def _fuel_composition(v: Any) -> str:
    from rotarykiln.materials.gas import check_composition

    try:
        pairs = check_composition(v, "")
    except InputError as exc:
        raise PydanticCustomError("number", "{msg}", {"msg": str(exc).removeprefix(": ")}) from None
    return ", ".join(f"{k}:{x:.12g}" for k, x in pairs)


GasFlowText = Annotated[Any, BeforeValidator(_gas_flow_text)]


def _oxidiser_composition(v: Any) -> str:
    """An oxidiser stream's composition by mole: known gases, with O2 in it."""
    text = _fuel_composition(v)
    from rotarykiln.materials.gas import parse_composition

    x = dict(parse_composition(text))
    if not x.get("O2", 0.0) > 0:
        raise PydanticCustomError(
            "number",
            "{value} holds no O2: an oxidiser stream needs O2 (air is O2:0.2095, N2:0.7808, "
            "AR:0.0097)",
            {"value": text},
        )
    return text


class BurnerAir(Section):
    """An air stream of the burner: its flow (mass, molar or normal volume), temperature and
    composition by mole (default dry air; O2-enriched air ``"O2:0.3, N2:0.7"``, pure oxygen
    ``"O2:1"``, recirculated flue gas with its O2)."""

    flow: GasFlowText
    temperature: Temperature = 298.15
    composition: Annotated[str, BeforeValidator(_oxidiser_composition)] | None = None

    @property
    def gas(self) -> str:
        """The stream's composition (Cantera text): the given one or dry air."""
        from rotarykiln.materials.gas import AIR

        return self.composition or AIR


SpecificEnergy = quantity("specific energy", gt=0, le=2e8, shown="in (0, 200 MJ/kg]")
Size = quantity("length", gt=0, le=0.1, shown="in (0, 100 mm]")
AnalysisFraction = quantity("fraction", ge=0, le=1, shown="in [0, 100 %]")


class Fineness(Section):
    """A pulverised fuel's size distribution: Rosin-Rammler by its residue on a sieve
    (``residue`` on ``sieve``, e.g. R90 = 12 % on 90 um) or its size parameter ``x_prime``,
    with the spread ``n`` (about 1 to 1.2 for kiln coal); ``classes`` size classes."""

    n: Annotated[float, BeforeValidator(lambda v: _positive_number(v))] = 1.1
    x_prime: Size | None = None
    residue: Fraction | None = None
    sieve: Size | None = None
    classes: int = Field(default=8, ge=1, le=40)

    @model_validator(mode="after")
    def _one_size(self):
        if (self.x_prime is None) == (self.residue is None):
            raise PydanticCustomError(
                "fineness", "give x_prime, or residue with sieve (e.g. 12 % on 90 um)", {}
            )
        if self.residue is not None and (self.sieve is None or not 0 < self.residue < 1):
            raise PydanticCustomError(
                "fineness", "residue in (0, 100 %) with its sieve size (e.g. sieve: 90 um)", {}
            )
        return self

    def distribution(self):
        """The :class:`~rotarykiln.chemistry.fuel_burnout.ParticleSizeDistribution`."""
        from rotarykiln.chemistry.fuel_burnout import (
            ParticleSizeDistribution,
            rosin_rammler_x_prime,
        )

        x = self.x_prime
        if x is None:
            x = rosin_rammler_x_prime(self.sieve, self.residue, self.n)
        return ParticleSizeDistribution.rosin_rammler(x, self.n, self.classes)


class FiredFuelSection(Section):
    """A solid or liquid fuel of the burner: a fuel of the library (``library``: a name of
    data/fuels/kiln_fuels.yaml, e.g. ``pittsburgh_8``) or its analyses: ``ultimate`` (C, H, N,
    S, Cl, O (by difference when absent), ash; mass fractions or %) on ``ultimate_basis``
    (``ar`` as received, ``ad`` air dried, ``d`` dry, ``daf``), ``proximate`` (moisture,
    volatiles, fixed_carbon, ash) on ``proximate_basis``, ``moisture`` as received when no
    proximate analysis gives it, ``heating_value`` (HHV on ``heating_value_basis``; default
    Channiwala-Parikh from the ultimate analysis); its as-fired ``flow``; ``fineness`` (a solid
    fuel's grind, for the ``particles`` combustion model); ``specific_heat`` of the fuel fed
    hot (default 1.25 kJ/(kg K) solid, 2.0 liquid)."""

    name: str | None = None
    library: str | None = None
    ultimate: dict[str, AnalysisFraction] | None = None
    ultimate_basis: Literal["ar", "ad", "d", "daf"] = "d"
    proximate: dict[str, AnalysisFraction] | None = None
    proximate_basis: Literal["ar", "ad", "d", "daf"] = "ar"
    moisture: AnalysisFraction | None = None
    heating_value: SpecificEnergy | None = None
    heating_value_basis: Literal["ar", "ad", "d", "daf"] = "ar"
    flow: MassFlow
    fineness: Fineness | None = None
    specific_heat: SpecificHeat | None = None

    @model_validator(mode="after")
    def _one_fuel(self):
        if (self.library is None) == (self.ultimate is None):
            raise PydanticCustomError(
                "fuel", "give library (a fuel of the library) or ultimate (its analysis)", {}
            )
        if self.flow <= 0:
            raise PydanticCustomError("number", "flow > 0 kg/s (a fuel fired)", {})
        self.solid_fuel()
        return self

    def solid_fuel(self):
        """The :class:`~rotarykiln.chemistry.solid_fuels.SolidFuel` (analyses checked)."""
        from rotarykiln.chemistry.solid_fuels import SolidFuel, load_kiln_fuel

        try:
            if self.library is not None:
                return load_kiln_fuel(self.library)
            return SolidFuel.from_analyses(
                ultimate=dict(self.ultimate),
                ultimate_basis=self.ultimate_basis,
                proximate=None if self.proximate is None else dict(self.proximate),
                proximate_basis=self.proximate_basis,
                moisture_ar=self.moisture,
                hhv=self.heating_value,
                hhv_basis=self.heating_value_basis,
                name=self.name or "fuel",
            )
        except InputError as exc:
            raise PydanticCustomError("fuel", "{msg}", {"msg": str(exc)}) from None


class Burner(Section):
    """A burner at the gas inlet end (see docs/heat.md, "Burner and flame").

    ``fuel``: composition by mole; ``fuel_flow`` and the air flows as mass flows ("2.2 kg/h"),
    molar flows ("0.1 mol/s") or normal volume flows ("12 Nm3/h", "0.83 NL/s" at 0 degC and
    1 atm; "Sm3/h" at 15 degC); a plain volume flow ("1.42 L/s") needs
    ``reference_temperature`` (and ``reference_pressure``, default 1 atm).
    ``combustion``: ``instant`` (burn-out at the burner), ``burnout`` (mixing-limited along
    the flame, which needs ``flame_length`` or ``nozzle_diameter``) or ``stirred`` (burn-out in
    a well-stirred recirculation zone, which needs ``recirculation_length`` or
    ``nozzle_diameter``).
    ``soot_volume_fraction``: a luminous flame (soot volume fraction f_v over the flame length,
    e.g. 5e-8 for natural gas; default 0, a non-luminous flame), which needs the flame length
    (or ``combustion: particles``: over the length within which the fuels release 99 % of their
    heat).
    ``products``: ``equilibrium`` (default: the products dissociate at equilibrium, which
    lowers a hot flame's adiabatic temperature and returns the heat where the gas cools) or
    ``complete`` (frozen complete-combustion products).
    ``air_ingress``: air leaking in at the feed end (the kiln inlet seal), a flow and a
    temperature: in a counter-current kiln it dilutes the exhaust leaving there (the exhaust
    temperature and O2 reported after it), in a co-current kiln it joins the burner's air.
    ``solid_fuels``, ``liquid_fuels``: coal, petroleum coke, alternative fuels, fuel oil
    (:class:`FiredFuelSection` each), fired alone (``fuel_flow`` absent) or with the gaseous
    fuel; their ash falls into the bed. ``combustion: particles`` burns the solid fuels by
    their particles' burn-out along the kiln (docs/cement_lime.md); ``particle_radiation``
    (default true) then adds the burning particles' grey emissivity to the gas's.
    """

    fuel: Annotated[str, BeforeValidator(_fuel_composition)] = (
        "CH4:0.95, C2H6:0.03, N2:0.01, CO2:0.01"
    )
    fuel_flow: GasFlowText = None
    fuel_temperature: Temperature = 298.15
    primary_air: BurnerAir | None = None
    secondary_air: BurnerAir | None = None
    reference_temperature: Temperature | None = None
    reference_pressure: Pressure | None = None
    nozzle_diameter: Length | None = None
    combustion: Literal["instant", "burnout", "stirred", "particles"] = "instant"
    products: Literal["equilibrium", "complete"] = "equilibrium"
    flame_length: Length | None = None
    recirculation_length: Length | None = None
    soot_volume_fraction: SootFraction = 0.0
    particle_radiation: bool = True
    air_ingress: BurnerAir | None = None
    solid_fuels: list[FiredFuelSection] = Field(default_factory=list)
    liquid_fuels: list[FiredFuelSection] = Field(default_factory=list)

    @model_validator(mode="after")
    def _flows(self):
        if self.fuel_flow is None and not (self.solid_fuels or self.liquid_fuels):
            raise PydanticCustomError(
                "number", "fuel_flow: missing (required, or solid_fuels / liquid_fuels)", {}
            )
        self.mass_flows()
        self.ingress_flow()
        return self

    def ingress_flow(self) -> float:
        """Mass flow of the air ingress at the feed end, kg/s (0 without one)."""
        from rotarykiln.materials.gas import AIR_MOLAR_MASS
        from rotarykiln.units import gas_flow

        if self.air_ingress is None:
            return 0.0
        try:
            f = gas_flow(
                self.air_ingress.flow,
                "air_ingress.flow",
                reference_temperature=self.reference_temperature,
                reference_pressure=self.reference_pressure,
                allow_zero=True,
            )
        except InputError as exc:
            raise PydanticCustomError("number", "{msg}", {"msg": str(exc)}) from None
        return f.mass_flow(AIR_MOLAR_MASS)

    def mass_flows(self) -> tuple[float, float, float]:
        """Fuel, primary air and secondary air mass flows, kg/s (refused: no air, bad flows)."""
        from rotarykiln.materials.gas import (
            AIR_MOLAR_MASS,
            AIR_O2,
            fuel_data,
            molar_mass,
            parse_composition,
        )
        from rotarykiln.units import gas_flow

        def convert(name, value, mm, allow_zero=False):
            try:
                f = gas_flow(
                    value,
                    name,
                    reference_temperature=self.reference_temperature,
                    reference_pressure=self.reference_pressure,
                    allow_zero=allow_zero,
                )
            except InputError as exc:
                raise PydanticCustomError("number", "{msg}", {"msg": str(exc)}) from None
            return f.mass_flow(mm)

        if self.primary_air is None and self.secondary_air is None:
            raise PydanticCustomError(
                "number",
                "fuel without air: give primary_air (and secondary_air) with their flows",
                {},
            )

        def mm(stream):
            return AIR_MOLAR_MASS if stream.composition is None else molar_mass(stream.gas)

        def o2(stream):
            if stream.composition is None:
                return AIR_O2
            x = dict(parse_composition(stream.gas))
            return x["O2"] / sum(x.values())

        fired = bool(self.solid_fuels or self.liquid_fuels)
        if self.fuel_flow is None:
            fuel = 0.0
        else:
            fuel = convert("fuel_flow", self.fuel_flow, molar_mass(self.fuel), fired)
        prim = sec = 0.0
        o2_supplied = 0.0  # mol/s
        if self.primary_air is not None:
            a = self.primary_air
            prim = convert("primary_air.flow", a.flow, mm(a), True)
            o2_supplied += prim / mm(a) * o2(a)
        if self.secondary_air is not None:
            a = self.secondary_air
            sec = convert("secondary_air.flow", a.flow, mm(a), True)
            o2_supplied += sec / mm(a) * o2(a)
        if prim + sec <= 0:
            raise PydanticCustomError(
                "number", "fuel without air: the air flows sum to 0 (a flame needs air)", {}
            )
        if fired:  # the air ratio of solid and liquid fuels: checked when they are burnt
            return fuel, prim, sec
        o2_demand = fuel_data(parse_composition(self.fuel))[1]  # mol O2 per mol of fuel
        ratio = o2_supplied / (fuel / molar_mass(self.fuel) * o2_demand)  # the air ratio
        stoichiometric = (prim + sec) / ratio  # kg/s of these streams that burn the fuel
        if prim + sec < stoichiometric * (1.0 - 1e-9):
            raise PydanticCustomError(
                "number",
                "the air streams cannot burn the fuel: primary + secondary air {air} kg/h "
                "against {need} kg/h for complete combustion (an air ratio of {ratio}); "
                "accepted: an air ratio of at least 1 (more air, or less fuel)",
                {
                    "air": f"{(prim + sec) * 3600:.4g}",
                    "need": f"{stoichiometric * 3600:.4g}",
                    "ratio": f"{(prim + sec) / stoichiometric:.3g}",
                },
            )
        return fuel, prim, sec


class Closures(Section):
    """Closure names of the kiln model (see docs/heat.md). ``preset``: ``default``
    (:class:`rotarykiln.kiln.inputs.closures.Closures`: Tscheng & Watkinson convection, Li 2005 covered
    wall, radiation on, Johansson 2011 gas emissivity, the solid's given conductivity) or
    ``seed004`` (Gorog 1982 gas-bed and gas-wall, Tscheng & Watkinson covered wall: the
    closures of Ahmad's (2006) reacting kilns); a key given overrides the preset's choice.
    ``radiation_model``: ``grey`` (one grey gas) or ``banded`` (every WSGG grey gas in the
    freeboard exchange); ``near_bed_mixing`` (W/(m2 K)): a layered freeboard, the bed seeing a
    near-bed gas fed from the core through this coefficient; ``bed_radiation``: radiation
    between particles in the bed conductivity; ``exposed_bed_penetration``: a penetration
    resistance at the exposed bed surface (see docs/validation.md, Barr, for what each does on
    the fired pilot kiln)."""

    preset: Literal["default", "seed004"] = "default"
    gas_wall: str | None = None
    gas_bed: str | None = None
    covered_wall: str | None = None
    radiation: bool | None = None
    gas_emissivity: str | float | None = None
    bed_conductivity: str | None = None
    convection_factor: Annotated[float, BeforeValidator(lambda v: _positive_number(v))] | None = (
        None
    )
    radiation_model: Literal["grey", "banded"] | None = None
    near_bed_mixing: HeatTransferCoefficient | None = None
    bed_radiation: bool | None = None
    exposed_bed_penetration: bool | None = None


class Thermocouple(Section):
    """The bare thermocouple of the gas readings (:mod:`rotarykiln.heat.thermocouple`):
    junction ``diameter``, ``emissivity`` (default 0.8) and ``bed_view`` (the share of its view
    taken by the bed surface, the rest by the wall: 0.5 just above the bed)."""

    diameter: Length
    emissivity: Annotated[float, BeforeValidator(lambda v: _emissivity(v))] = 0.8
    bed_view: Fraction = 0.5


def _emissivity(v: Any) -> float:
    x = _positive_number(v)
    if x > 1.0:
        raise PydanticCustomError("number", "{value} is not in (0, 1]", {"value": v})
    return x


class Measurements(Section):
    """Measured profiles to overlay on the figure and score the solution against.

    ``thermocouple``: the gas readings are bare-thermocouple readings; the solution then also
    gives the gas temperature such a thermocouple would read (``T_gas_thermocouple_K``) and
    scores the gas readings against it as well as against the raw gas temperature.
    """

    z_gas: list[Position] = []
    t_gas: list[Temperature] = []
    z_bed: list[Position] = []
    t_bed: list[Temperature] = []
    z_wall: list[Position] = []
    t_wall: list[Temperature] = []
    z_gas_wall: list[Position] = []
    t_gas_wall: list[Temperature] = []
    wall_interface: int = 0
    thermocouple: Thermocouple | None = None

    @model_validator(mode="after")
    def _pairs(self):
        for key in ("gas", "bed", "wall", "gas_wall"):
            z, t = getattr(self, f"z_{key}"), getattr(self, f"t_{key}")
            if len(z) != len(t):
                raise PydanticCustomError(
                    "number",
                    "z_{key} has {nz} positions but t_{key} {nt} temperatures: give one "
                    "temperature per position",
                    {"key": key, "nz": len(z), "nt": len(t)},
                )
        return self


class HeaterZoneSection(Section):
    """An electric heater zone on the shell: from ``start`` to ``end`` (m from the solids inlet)
    with a ``power`` ("5 kW" over the zone) or a ``shell_temperature`` set-point (the power
    is then an output)."""

    start: Position
    end: Position
    power: Power | None = None
    shell_temperature: Temperature | None = None


class TransportWeir(Section):
    """An internal weir: distance from the discharge end and height above the wall."""

    position: Length
    height: Length


class Transport(Section):
    """Axial solids transport (rotarykiln.transport): model choice, friction law, dams, weirs.

    ``model``: ``kramers`` (Kramers-Croockewit/Saeman ODE) or ``scott`` (Scott 1986);
    ``friction`` (Scott): ``zero``, ``dynamic``, ``static`` or a number; ``dam_height``:
    discharge dam above the wall (open end if absent); ``weirs`` (Scott only).

    In a reacting kiln (``chemistry:``) the Kramers bed depth is solved with the balances, at
    the bed's volume flow by ``volume``: ``bulk`` (default: the mass flow over
    ``material.bulk_density``; a bed that loses mass compacts) or ``fresh_feed`` (the fresh
    feed's volume flow, its mass over ``material.bulk_density``, all along: particles that keep
    their size as they lose mass, as the wood chips of the rotaryPyrolysis script; the bulk
    density then falls). ``shrinkage`` (with ``fresh_feed``): the fraction of that volume lost
    at full conversion of the fed species, in [0, 1) (e.g. ``30 %`` for wood chips that lose
    about a third of their volume when charred); default 0.
    """

    model: Literal["kramers", "scott"] = "kramers"
    friction: Annotated[str | float, BeforeValidator(lambda v: _friction(v))] = "static"
    dam_height: Length | None = None
    weirs: list[TransportWeir] = []
    n_points: _int_in(2, 100_000) = 201
    volume: Literal["bulk", "fresh_feed"] = "bulk"
    shrinkage: Shrinkage = 0.0

    @model_validator(mode="after")
    def _weirs_need_scott(self):
        if self.weirs and self.model != "scott":
            raise PydanticCustomError(
                "number", "weirs are given with the kramers model: weirs need model: scott", {}
            )
        if self.shrinkage > 0 and self.volume != "fresh_feed":
            raise PydanticCustomError(
                "number",
                "shrinkage: {value} is not 0 with volume: {volume} (a shrinkage is a share of "
                "the fresh feed's volume: volume: fresh_feed)",
                {"value": f"{self.shrinkage:g}", "volume": self.volume},
            )
        return self


def _friction(v: Any) -> str | float:
    """Scott's friction: a name or a number >= 0."""
    if v in ("zero", "dynamic", "static"):
        return v
    if isinstance(v, bool) or not isinstance(v, int | float) or not v >= 0:
        raise PydanticCustomError(
            "number", "{value} is not zero, dynamic, static or a number >= 0", {"value": v}
        )
    return float(v)


def _nonnegative_number(v: Any) -> float:
    if isinstance(v, bool) or not isinstance(v, int | float) or not v >= 0:
        raise PydanticCustomError("number", "{value} is not a number >= 0", {"value": v})
    return float(v)


def _reworded(exc: InputError) -> str:
    """An InputError of a lower layer in the case's words: text values quoted, None empty."""
    value, accepted = exc.value, exc.accepted
    if not accepted:
        return str(exc)
    if isinstance(value, str) and value.startswith("fractions summing to "):
        total, expected = value.removeprefix("fractions summing to "), accepted
        return f"{exc.field}: the fractions sum to {total}, expected {expected.split(' ', 2)[-1]}"
    if value is None:
        return f"{exc.field}: empty, expected {accepted}"
    return f"{exc.field}: {_show(value) if isinstance(value, str) else _short(value)} is not {accepted}"


def _user_species(info):
    """The species table of the case's ``chemistry.species`` (set by :func:`parse_case` in the
    validation context), or None for the built-in table."""
    context = getattr(info, "context", None)
    return context.get("species") if isinstance(context, dict) else None


def _composition(phase: str):
    def check(v: Any, info) -> dict[str, float]:
        from rotarykiln.chemistry.species import check_mass_fractions

        try:
            return check_mass_fractions("composition", v, _user_species(info), phase=phase)
        except InputError as exc:
            raise PydanticCustomError("number", "{msg}", {"msg": _reworded(exc)}) from None

    return Annotated[dict[str, float], BeforeValidator(check)]


def _reaction_names(v: Any, info) -> list:
    """Built-in reaction names or user reactions (mappings, validated as reaction YAML, on the
    case's own species when it has ``chemistry.species``)."""
    from rotarykiln.chemistry.reaction import builtin_reactions, reaction_from_dict

    if not isinstance(v, list) or not v or not all(isinstance(x, str | dict) for x in v):
        raise PydanticCustomError(
            "number", "{value} is not a list of reaction names or reactions", {"value": v}
        )
    species = _user_species(info)
    known = _builtin_reaction_names() if species is None else builtin_reactions(species)
    seen = set()
    for i, item in enumerate(v):
        if isinstance(item, dict):
            try:
                name = reaction_from_dict(item, species, where=f"[{i}]").name
            except InputError as exc:
                raise PydanticCustomError("number", "{msg}", {"msg": str(exc)}) from None
        else:
            name = item
            if name not in known:
                raise PydanticCustomError(
                    "number",
                    "{name} is not a built-in reaction ({known})",
                    {"name": _show(name), "known": ", ".join(sorted(known))},
                )
        if name in seen:
            raise PydanticCustomError("number", "{name} is listed twice", {"name": _show(name)})
        seen.add(name)
    return v


@lru_cache(maxsize=1)
def _builtin_reaction_names() -> frozenset[str]:
    """The names of the built-in reactions on the built-in species (read once: their files
    are part of the package)."""
    from rotarykiln.chemistry.reaction import builtin_reactions

    return frozenset(builtin_reactions())


class Gas(Section):
    """Gas entering at the gas inlet end without a burner (a hot-air or flue-gas kiln, a sweep
    gas): mass ``flow``, inlet ``temperature``, and its composition as mole fractions
    (``composition``, default air) or as mass fractions (``mass_fractions``).
    ``steam_flow``: a constant steam flow seen by steam reactions (seed 004); ``emissivity_a``,
    ``emissivity_b_per_K``, ``emissivity_minimum``: a gas emissivity line
    max(a + b T, minimum) instead of the closures' gas emissivity model."""

    flow: MassFlow | None = None
    temperature: Temperature | None = None
    composition: Annotated[str, BeforeValidator(_fuel_composition)] | None = None
    mass_fractions: _composition("gas") | None = None
    steam_flow: MassFlow | None = None
    emissivity_a: Fraction | None = None
    emissivity_b_per_K: float | None = None
    emissivity_minimum: Fraction | None = None
    pressure: Pressure = 101325.0

    @model_validator(mode="after")
    def _one_composition(self):
        if self.composition is not None and self.mass_fractions is not None:
            raise PydanticCustomError(
                "number", "give composition (mole fractions) or mass_fractions, not both", {}
            )
        return self


class Jacket(Section):
    """A heating jacket around the drum (indirectly heated kilns, kiln/wall/jacket.py): a gas of
    mass ``flow`` entering at ``temperature``, flowing with the solids (``counter_current:
    false``, entering at the feed end) or against them; its ``specific_heat`` (constant) or
    ``composition`` (mole fractions, enthalpy from the gas tables). ``heat_transfer``: the
    jacket gas to drum coefficient (a value, W/(m2 K)), ``annulus`` (forced convection in the
    annular ``gap`` with gas and casing radiation, Gnielinski / Shah-London, through a drum wall
    of ``wall_thickness`` and ``wall_conductivity``) or ``wall_at_gas`` (no resistance: the
    rotaryPyrolysis assumption). ``casing_u``: loss of the jacket casing to ambient, W/(m2 K)
    on ``casing_perimeter`` (default the drum's)."""

    flow: MassFlow
    temperature: Temperature
    specific_heat: SpecificHeat | None = None
    composition: Annotated[str, BeforeValidator(_fuel_composition)] | None = None
    counter_current: bool = False
    heat_transfer: Literal["annulus", "wall_at_gas"] | HeatTransferCoefficient = "annulus"
    gap: Length = 0.05
    wall_thickness: Position = 0.005
    wall_conductivity: ThermalConductivity = 45.0
    casing_u: HeatTransferCoefficient = 0.0
    casing_perimeter: Length | None = None
    radiation: bool = True
    drum_emissivity: Fraction = 0.8
    casing_emissivity: Fraction = 0.8

    @model_validator(mode="after")
    def _one_property(self):
        if (self.specific_heat is None) == (self.composition is None):
            raise PydanticCustomError(
                "number", "give specific_heat or composition (the jacket gas), one of them", {}
            )
        return self


class Wall(Section):
    """The kiln wall: ``lining`` layers (inner to outer, the shell included) with the shell's
    loss by convection (``wind_speed``) and radiation to ``ambient_temperature``, a constant
    loss coefficient ``U`` (W/(m2 K), referred to the inner wall: q = U pi D (T_wall - T_amb)),
    or a heating ``jacket`` (its own gas stream and energy balance). ``emissivity``: inner wall
    surface (default: the first layer's); ``shell_emissivity``; ``heaters``: electric heater
    zones on the shell (with a lining)."""

    lining: list[LiningLayer] | None = None
    U: HeatTransferCoefficient | None = None
    jacket: Jacket | None = None
    ambient_temperature: Temperature = 298.15
    wind_speed: Velocity = 0.0
    emissivity: Fraction | None = None
    shell_emissivity: Fraction | None = None
    heaters: list[HeaterZoneSection] = []

    @model_validator(mode="after")
    def _lining_or_u(self):
        if sum(x is not None for x in (self.lining, self.U, self.jacket)) != 1:
            raise PydanticCustomError(
                "number",
                "give lining (layers), U (a constant loss coefficient, W/(m2 K)) or jacket, "
                "one of them",
                {},
            )
        if self.jacket is not None and self.heaters:
            raise PydanticCustomError(
                "number", "heaters need a lining; a jacketed wall takes none", {}
            )
        return self


class Solver(Section):
    """Discretisation of the kiln model: ``cells`` along the kiln."""

    cells: Cells = 100


class Chemistry(Section):
    """Reactions of the bed and the freeboard (rotarykiln.chemistry): built-in names
    (chemistry/reactions/*.yaml) or reactions given inline; the feed composition is
    ``material.composition``.

    ``onset_width`` (K): a linear onset ramp for reactions with a sharp onset temperature;
    ``kirchhoff``: heats of reaction follow Kirchhoff's law with the species' c_p;
    ``peclet``: the bed Peclet number of the residence-time effects (default: the ``rtd:``
    section or the Sherritt correlation); ``expected``: the source's printed results (shown
    beside the solution, never used by the solve); ``species``: user species added to the
    built-in ones (:func:`rotarykiln.chemistry.species.load_species`), a YAML file beside the
    case file (a relative path inside its folder; read once when the case is loaded, and kept
    inline) or the same mapping inline (``bed:``, ``gas:``). A case given as data (an app
    upload, a Python mapping) names no file."""

    species: str | dict[str, Any] | None = None
    reactions: Annotated[list, BeforeValidator(_reaction_names)]
    kirchhoff: bool = False
    onset_width: Annotated[float, BeforeValidator(lambda v: _nonnegative_number(v))] = 0.0
    gas_gain_per_carbon: Literal["corrected", "faithful"] = "corrected"
    peclet: Annotated[float, BeforeValidator(lambda v: _peclet(v))] | None = None
    expected: dict[str, Any] = {}


class Material(Section):
    """The bulk solid: its name, bulk properties for the transport models, and for the kiln
    model the library ``solid`` whose properties (c_p(T) with its phases, conductivity,
    emissivity) the bed takes, constant overrides (``specific_heat``, ``thermal_conductivity``,
    ``emissivity``), and the feed ``composition`` (mass fractions of the bed species of
    ``chemistry``; needed with a ``chemistry:`` section)."""

    name: str = "solid"
    solid: SolidName | None = None
    bulk_density: Density | None = None
    repose_angle: ReposeAngle | None = None
    static_repose_angle: ReposeAngle | None = None
    particle_size: Length | None = None
    wall_friction: Annotated[float, BeforeValidator(lambda v: _positive_number(v))] | None = None
    specific_heat: SpecificHeat | None = None
    thermal_conductivity: ThermalConductivity | None = None
    emissivity: Fraction | None = None
    composition: _composition("bed") | None = None


class Bed(Section):
    """How the bed fills the kiln when no ``transport:`` section computes it: a ``fill``
    fraction (a number, or a list of values evenly spaced from the solids inlet to the
    discharge) or a solids ``residence_time`` (the fill then follows from the feed).
    ``axial_dispersion``: the bed's axial dispersion in the kiln model's balances, from the
    correlation of Sherritt et al. (2003) (``sherritt2003``, default), ``plug`` flow, or a bed
    Peclet number u L / D (a number)."""

    fill: FillFraction | list[FillFraction] | None = None
    residence_time: Time | None = None
    axial_dispersion: (
        Literal["sherritt2003", "plug"] | Annotated[float, BeforeValidator(lambda v: _peclet(v))]
    ) = "sherritt2003"

    @model_validator(mode="after")
    def _fill_or_time(self):
        if isinstance(self.fill, list) and not self.fill:
            raise PydanticCustomError("number", "fill: [] is not a fill (a number or a list)", {})
        if self.fill is not None and self.residence_time is not None:
            raise PydanticCustomError(
                "number", "give fill or residence_time, not both (one sets the other)", {}
            )
        return self

    @property
    def mean_fill(self) -> float | None:
        """The fill as one number (the mean of a list), or None when not given."""
        if self.fill is None:
            return None
        return float(sum(self.fill) / len(self.fill)) if isinstance(self.fill, list) else self.fill


class RTDLifters(Section):
    """Lifters for the RTD correlations: type, number around the circumference, dimensions."""

    type: Literal["none", "straight", "rectangular"] = "none"
    count: Annotated[int, BeforeValidator(lambda v: _positive_int(v))] = 4
    height: Length = 0.01
    arm: Length | None = None  # second arm of a rectangular lifter (default: = height)


class RTD(Section):
    """Residence time distribution: a given mean residence time (or the transport model's) and a
    Peclet number (given, or from a dispersion correlation)."""

    mean_residence_time: Time | None = None
    correlation: Literal["bongo_njeng2015", "sherritt2003", "sai1990"] = "bongo_njeng2015"
    peclet: Annotated[float, BeforeValidator(lambda v: _peclet(v))] | None = None
    model: Literal["open-open", "closed-closed", "open-closed", "gaussian"] = "open-open"
    lifters: RTDLifters = RTDLifters()
    holdup_fraction: Fraction | None = None  # Sherritt; default: feed x MRT / (rho_b V)
    tracer_repose_angle: ReposeAngle | None = None  # Sai; default: the material's
    tracer_density: Density | None = None  # Sai; default: the material's bulk density


def _positive_int(v: Any) -> int:
    if isinstance(v, bool) or not isinstance(v, int) or v < 1:
        raise PydanticCustomError("number", "{value} is not an integer >= 1", {"value": v})
    return v


# --- transverse: the retort zone of the transverse grid model (seed 000 ch 9) -----------------

_TLength = quantity("length", gt=0, shown="> 0")
_TTemperature = quantity("temperature", gt=0, shown="> 0 K")
_TDensity = quantity("density", gt=0, shown="> 0")
_TSpecificHeat = quantity("specific heat", gt=0, shown="> 0")
_TTime = quantity("time", gt=0, shown="> 0 s")
_TFraction = quantity("fraction", gt=0, le=1, shown="in (0, 1]")


def _shale_to_ash(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0:
        raise PydanticCustomError(
            "number", "{value} is not > 0 (a mass ratio of shale to ash)", {"value": value}
        )
    return float(value)


class _TransverseSection(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class FeedSection(_TransverseSection):
    """One feed (shale or ash): mean size, initial temperature, properties."""

    mean_size: _TLength
    temperature: _TTemperature
    bulk_density: _TDensity | None = None
    heat_capacity: _TSpecificHeat | None = None


class GridSection(_TransverseSection):
    """Grid size: stagnant layers (the active layer gets 2 zones per layer) and zones."""

    layers: int = Field(5, ge=2)
    zones: int = Field(20, ge=4)


class TransverseSection(_TransverseSection):
    """Settings of the transverse grid simulation with heating (retort zone, ch 9)."""

    duration: _TTime = 220.0
    shale_to_ash: Annotated[float, BeforeValidator(_shale_to_ash)] = 0.32
    shale: FeedSection = FeedSection(mean_size=1.54e-3, temperature=548.0)
    ash: FeedSection = FeedSection(mean_size=2.11e-3, temperature=1048.0)
    distribution: Literal["auto", "single", "table4.1"] = "auto"
    voidage: _TFraction = 0.5
    emissivity: _TFraction = 0.9
    balance: Literal["pairwise", "smaller"] = "pairwise"
    segregation: bool = True
    grid: GridSection = GridSection()
    snapshot_times: list[_TTime] = [5.0, 10.0, 20.0, 40.0, 60.0, 220.0]


class Case(Section):
    """A complete case file."""

    name: str = "case"
    description: str = ""
    kiln: Kiln
    operation: Operation
    material: Material = Material()
    bed: Bed | None = None
    transport: Transport | None = None
    gas: Gas | None = None
    burner: Burner | None = None
    wall: Wall | None = None
    chemistry: Chemistry | None = None
    closures: Closures = Closures()
    measurements: Measurements | None = None
    solver: Solver = Solver()
    transverse: TransverseSection | None = None
    rtd: RTD | None = None

    @property
    def has_kiln_model(self) -> bool:
        """Whether the case asks for the kiln model: a heat source (``gas``, ``burner``, heater
        zones or a jacket on the ``wall``) or a ``chemistry`` section."""
        heated = self.wall is not None and (bool(self.wall.heaters) or self.wall.jacket is not None)
        return heated or any(s is not None for s in (self.gas, self.burner, self.chemistry))

    def replace(self, changes: Any = None, /, **sections: Any) -> Case:
        """A new case with some fields changed, validated as a case file (a case is frozen).

        The case equals the one :func:`parse_case` makes of the case file with the fields
        changed (:func:`change_fields`), and is made as :func:`case_with` makes it: only the
        changed fields are validated; a bad value raises the one-line
        :class:`~rotarykiln.errors.InputError` of a case file, naming the field.

        Parameters
        ----------
        changes : mapping, optional
            Dotted field -> value: ``{"operation.speed": "2.5 rpm", "bed.fill": 0.1,
            "wall.lining[0].thickness": "80 mm"}``; values as a case file gives them (text with
            units, numbers, mappings, a section of a case); None removes the field (its default
            applies).
        **sections
            Whole sections: ``replace(transport={"model": "kramers"}, bed=None)``; applied
            before ``changes``.

        Returns
        -------
        Case

        Examples
        --------
        >>> from rotarykiln.cases import builtin_case_path
        >>> case = load_case(builtin_case_path("barr_T4"))
        >>> faster = case.replace({"operation.speed": "3 rpm"})
        >>> round(faster.operation.speed, 4), round(case.operation.speed, 4)
        (0.3142, 0.1571)
        >>> case.replace({"operation.speed": "3 m"})  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        rotarykiln.errors.InputError: operation.speed: "3 m" is ...
        """
        return case_with(self, {**sections, **dict(changes or {})})

    def model_copy(self, *, update: Any = None, deep: bool = False) -> Case:
        """A copy; with ``update`` (dotted fields or sections -> values), :meth:`replace`,
        which validates the new values."""
        if update:
            return self.replace(update)
        return super().model_copy(deep=deep)


def _model_at(model: type[BaseModel], loc: tuple) -> type[BaseModel] | None:
    """The pydantic model class that owns the field at ``loc`` (without its last element)."""
    current: Any = model
    for part in loc[:-1]:
        if isinstance(part, int):  # an index into a list: the list's item model owns the rest
            continue
        if not (isinstance(current, type) and issubclass(current, BaseModel)):
            return None
        info = current.model_fields.get(part)
        if info is None:
            return None
        current = _unwrap(info.annotation)
    return current if isinstance(current, type) and issubclass(current, BaseModel) else None


def _unwrap(annotation: Any) -> Any:
    """The model class inside ``X | None``, ``list[X]``, ``list[X] | None`` (else ``annotation``)."""
    for a in getattr(annotation, "__args__", None) or ():
        if isinstance(a, type) and issubclass(a, BaseModel):
            return a
        inner = _unwrap(a)
        if isinstance(inner, type) and issubclass(inner, BaseModel):
            return inner
    return annotation


_DOTTED = re.compile(r"^[^.\[\]\s]+(?:\.[^.\[\]\s]+|\[\d+\])*$")


def change_fields(data: Any, changes: Any, model: type[BaseModel] | None = None) -> Any:
    """A case mapping (as read from YAML) with ``changes`` made: dotted field -> value.

    The fields are checked against the case model (``model``, default :class:`Case`): a name
    that is no field raises :class:`InputError` naming the dotted field and the accepted ones.
    Missing sections are created; None removes a field; a section model given as a value is
    written back with units. ``data`` itself is not changed; the values are checked later, by
    :func:`parse_case`.

    Examples
    --------
    >>> change_fields({"operation": {"speed": "1 rpm"}}, {"operation.speed": "2.5 rpm"})
    {'operation': {'speed': '2.5 rpm'}}
    >>> change_fields({}, {"operation.sped": "2 rpm"})  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: operation.sped: not a field of the case, did you mean "speed"? ...
    """
    if not changes or not isinstance(data, dict):  # not a mapping: parse_case says so
        return data
    import copy

    data = copy.deepcopy(data)
    for path, value in dict(changes).items():
        _change_field(data, path, value, model or Case)
    return data


def _change_field(data: dict, path: Any, value: Any, model: type[BaseModel]) -> None:
    """Set (or, for None, remove) the dotted field ``path`` of ``data`` (see change_fields)."""
    if not isinstance(path, str) or not _DOTTED.match(path):
        raise InputError(
            str(path),
            message=f"{_show(path)}: not a dotted field of the case "
            '(e.g. "operation.speed", "wall.lining[0].thickness")',
        )
    if isinstance(value, BaseModel):
        from rotarykiln.case_io import dump_case

        value = dump_case(value)
    parts = [
        int(index or name) if (index or name).isdigit() else name
        for index, name in re.findall(r"\[(\d+)\]|([^.\[\]]+)", path)
    ]
    node: Any = data
    owner: Any = model  # the section model that owns the next part (None: a free mapping)
    shown = ""
    for k, part in enumerate(parts):
        parent, shown = shown, f"{shown}.{part}" if shown else str(part)
        if isinstance(part, int):
            if not isinstance(node, list):
                raise InputError(shown, message=f"{shown}: {parent} is not a list")
            if not 0 <= part < len(node):
                raise InputError(shown, message=f"{shown}: no such item ({parent} has {len(node)})")
        elif not isinstance(node, dict):
            raise InputError(shown, message=f"{shown}: {parent} is a list (give an index)")
        elif isinstance(owner, type) and issubclass(owner, BaseModel):
            names = list(owner.model_fields)
            if part not in names:
                close = difflib.get_close_matches(part, names, n=1)
                if not close and k == 0:  # a field of a section given alone: "speed"
                    close = [
                        f"{name}.{part}"
                        for name, info in owner.model_fields.items()
                        if part in getattr(_unwrap(info.annotation), "model_fields", {})
                    ][:1]
                hint = f', did you mean "{close[0]}"?' if close else ""
                raise InputError(
                    shown,
                    message=f"{shown}: not a field of the case{hint} (accepted: {', '.join(names)})",
                )
            annotation = owner.model_fields[part].annotation
            owner = None if getattr(annotation, "__origin__", None) is dict else _unwrap(annotation)
        else:
            owner = None
        if k == len(parts) - 1:
            if value is not None:
                node[part] = value
            elif isinstance(node, list):
                del node[part]
            else:
                node.pop(part, None)
            return
        child = node[part] if isinstance(node, list) else node.get(part)
        if child is None:
            if isinstance(parts[k + 1], int):
                raise InputError(shown, message=f"{shown}: not given (no list to index)")
            child = node[part] = {}
        elif not isinstance(child, dict | list):
            raise InputError(
                shown, message=f"{shown}: {_show(child)} is a value, not a section of fields"
            )
        node = child


def case_with(base: Case, changes: Mapping[str, object]) -> Case:
    """The case ``base`` with the dotted fields of ``changes`` replaced, validated as a case file.

    The result equals ``parse_case(change_fields(data, changes))``, ``data`` being the case
    file ``base`` was read from: the same values (SI floats), the same fields given, the same
    rules, limits and messages. Only the changed fields are validated, with the checks of the
    sections that hold them (a burner's air against its fuel, a bed's fill or residence time,
    a lining layer's thickness ...); the rest of ``base`` is taken as it is. A change that the
    fast path cannot decide alone (a bad value, a list item removed, an index into a list of
    numbers, the case's own species, a path inside a value given by another change) is made
    the slow way: the case written back with units, changed and parsed again, which gives the
    same case or the same error. Built for studies, where a sweep, a Sobol design or a
    calibration solves thousands of variants of one base case: a variant costs ~0.02 ms here,
    plus ~0.1 ms for pint to read each text it has not read before (a parse of the whole case
    takes ~0.3 ms with its texts read before, ~4 ms without; the slow way ~5 ms).

    Parameters
    ----------
    base : Case
        A validated case (:func:`load_case`, :func:`parse_case`).
    changes : mapping
        Dotted field -> value, as a case file gives them: ``{"operation.speed": "1.5 rpm",
        "gas.flow": "24.6 kg/h", "burner.primary_air.flow": "17 L/s", "bed.fill": [0.1, 0.2],
        "wall.lining[0].thickness": "80 mm"}`` (``wall.lining.0.thickness`` also names the
        first layer); text with units, or numbers in SI where a case file accepts them (a
        rotation rate or a flow needs its unit, 0 excepted); a mapping or a section model for
        a whole section; None removes the field (its default applies). Applied in order.

    Returns
    -------
    Case
        A new case (``base`` itself when ``changes`` is empty); the sections not changed are
        those of ``base`` (a case is frozen).

    Raises
    ------
    InputError
        As :func:`parse_case` of the changed case file: one line naming the field, the value
        and what is accepted; or, for a name that is no field, as :func:`change_fields`.

    Examples
    --------
    >>> from rotarykiln.cases import builtin_case_path
    >>> base = load_case(builtin_case_path("tscheng_A16"))
    >>> case = case_with(base, {"operation.speed": "3 rpm", "gas.flow": "30 kg/h"})
    >>> round(case.operation.speed, 5), round(case.gas.flow * 3600, 6)  # rad/s, kg/h
    (0.31416, 30.0)
    >>> case.wall is base.wall  # unchanged sections are shared
    True
    >>> case_with(base, {"operation.speed": "3 m"})
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: operation.speed: "3 m" is a length, expected a rotation rate (rpm, rad/s)
    """
    if not isinstance(base, BaseModel):
        raise TypeError(f"case_with: base is a {type(base).__name__}, not a validated case")
    if not isinstance(changes, Mapping):
        raise TypeError(f"case_with: changes is a {type(changes).__name__}, not a mapping")
    if not changes:
        return base
    try:
        return _case_with_fast(base, changes)
    except _SlowPath:
        from rotarykiln.case_io import dump_case

        data = change_fields(dump_case(base), changes, type(base))
        return parse_case(data, source="case", model=type(base))


class _SlowPath(Exception):
    """:func:`case_with` cannot decide a change alone: the whole case is parsed."""


class _Given:
    """A value a change gives to a field (a leaf of :func:`_change_tree`)."""

    __slots__ = ("value",)

    def __init__(self, value: Any):
        self.value = value


def _change_tree(changes: Mapping) -> dict:
    """The changes as a tree: field name (or list index) -> subtree, or :class:`_Given` for a
    field given a value (:class:`_SlowPath` for a change inside a value given before, or one
    that replaces fields changed before: made one after the other, as in a file)."""
    tree: dict = {}
    for path, value in changes.items():
        if not isinstance(path, str) or not _DOTTED.match(path):
            raise _SlowPath
        parts = [
            int(index or name) if (index or name).isdigit() else name
            for index, name in re.findall(r"\[(\d+)\]|([^.\[\]]+)", path)
        ]
        node = tree
        for part in parts[:-1]:
            child = node.get(part)
            if child is None:
                child = node[part] = {}
            elif isinstance(child, _Given):  # inside a value another change gave: as a file
                raise _SlowPath
            node = child
        if isinstance(node.get(parts[-1]), dict):  # replaces fields changed before: as a file
            raise _SlowPath  # (those changes are still checked, and may be refused)
        if isinstance(value, BaseModel):  # a section model: written back with units
            from rotarykiln.case_io import dump_case

            value = dump_case(value)
        node[parts[-1]] = _Given(value)
    return tree


def _as_data(tree: dict) -> dict:
    """A subtree of changes as the case-file mapping it makes in an absent section."""
    out = {}
    for part, node in tree.items():
        if not isinstance(part, str):  # an index into a list the case does not give
            raise _SlowPath
        if isinstance(node, _Given):
            if node.value is not None:
                out[part] = node.value
        else:
            out[part] = _as_data(node)
    return out


def _count_values(node: Any) -> int:
    """Values of a case (or a part of one) as :func:`check_structure` counts them."""
    if isinstance(node, BaseModel):
        return 1 + sum(_count_values(getattr(node, k)) for k in node.model_fields_set)
    if isinstance(node, _Given):
        return _count_values(node.value)
    if isinstance(node, dict):
        return 1 + sum(_count_values(v) for v in node.values())
    if isinstance(node, list | tuple):
        return 1 + sum(_count_values(v) for v in node)
    return 1


class _BaseFacts:
    """What :func:`case_with` needs of a base case beyond its fields: its number of values
    (the limit of :func:`check_structure`) and its own species table (the validation context
    of compositions and reactions), worked out once per base."""

    __slots__ = ("base", "count", "species")

    def __init__(self, base: BaseModel):
        self.base = base  # kept alive: its id stays its own
        self.count = _count_values(base)
        self.species = None
        chem = getattr(base, "chemistry", None)
        if chem is not None and getattr(chem, "species", None) is not None:
            from rotarykiln.chemistry.species import load_species

            self.species = load_species(chem.species)


_BASES: dict[int, _BaseFacts] = {}  # id of the base -> its facts, the last few bases
_BASES_LOCK = threading.Lock()


def _base_facts(base: BaseModel) -> _BaseFacts:
    """The :class:`_BaseFacts` of ``base``, kept for the last 8 bases (a study's base is
    worked out once)."""
    with _BASES_LOCK:
        hit = _BASES.get(id(base))
    if hit is not None and hit.base is base:
        return hit
    facts = _BaseFacts(base)
    with _BASES_LOCK:
        if len(_BASES) >= 8:
            _BASES.pop(next(iter(_BASES)))
        _BASES[id(base)] = facts
    return facts


def _check_changes_structure(facts: _BaseFacts, tree: dict) -> None:
    """The limits :func:`parse_case` puts on the whole case (:func:`check_structure`), on the
    changes: their depth and integers exactly, their count with the base's (values of the base
    that a change replaces are counted too, with a wide margin for values the validation
    merged, such as a composition mapping made one text)."""

    def data(node):
        if isinstance(node, _Given):
            return node.value
        return {str(k): data(v) for k, v in node.items()}

    try:
        _check_structure(data(tree), "case")
    except InputError:
        raise _SlowPath from None
    if _count_values(tree) + facts.count > MAX_YAML_VALUES // 2:
        raise _SlowPath


def _case_with_fast(base: BaseModel, changes: Mapping) -> BaseModel:
    tree = _change_tree(changes)
    chem = tree.get("chemistry")
    if isinstance(chem, _Given) or (isinstance(chem, dict) and "species" in chem):
        raise _SlowPath  # the species every composition and reaction is checked against
    facts = _base_facts(base)
    _check_changes_structure(facts, tree)
    return _patched(base, tree, {"species": facts.species})


def _patched(section: BaseModel, tree: dict, context: dict) -> BaseModel:
    """A copy of ``section`` with the changes of ``tree`` validated, then the section's own
    checks (its ``after`` model validators) run on it; :class:`_SlowPath` when in doubt."""
    cls = type(section)
    checks = _section_checks(cls)
    if checks is None:
        raise _SlowPath
    new = copy.copy(section)  # its own __dict__ and set of fields given
    values, given = new.__dict__, new.__pydantic_fields_set__
    for name, node in tree.items():
        info = cls.model_fields.get(name) if isinstance(name, str) else None
        if info is None:
            raise _SlowPath  # no such field: change_fields names it
        if isinstance(node, _Given):
            if node.value is None:  # removed: the default applies
                if info.is_required():
                    raise _SlowPath
                values[name] = info.get_default(call_default_factory=True)
                given.discard(name)
                continue
            values[name] = _validated(cls, name, node.value, context)
            given.add(name)
            continue
        current = values[name]
        if name not in given or current is None:  # a section the case does not give
            values[name] = _validated(cls, name, _as_data(node), context)
            given.add(name)
        elif isinstance(current, BaseModel):
            values[name] = _patched(current, node, context)
        elif isinstance(current, list) and _is_list_of_sections(cls, name):
            items = list(current)
            for index, sub in node.items():
                if not (isinstance(index, int) and 0 <= index < len(items)):
                    raise _SlowPath
                if isinstance(sub, _Given):
                    if sub.value is None:  # an item removed
                        raise _SlowPath
                    items[index] = sub.value  # validated with the list below
                elif isinstance(items[index], BaseModel):
                    items[index] = _patched(items[index], sub, context)
                else:
                    raise _SlowPath
            values[name] = _validated(cls, name, items, context)
        else:
            raise _SlowPath  # inside a value (a number, a list of numbers, a mapping)
    for check in checks:
        try:
            result = check(new)
        except Exception:  # refused: the parse of the whole case says how
            raise _SlowPath from None
        if result is not new:
            raise _SlowPath
    return new


@lru_cache(maxsize=256)
def _section_checks(cls: type[BaseModel]) -> tuple | None:
    """The ``after`` model validators of a section class (functions of the instance), or None
    when the class has checks :func:`case_with` cannot run on a changed copy (``before`` or
    ``wrap`` validators, validators of the whole field set, ``model_post_init``)."""
    decorators = cls.__pydantic_decorators__
    if cls.__pydantic_post_init__ is not None:
        return None
    checks = []
    for dec in decorators.model_validators.values():
        func = dec.func
        if dec.info.mode != "after" or not inspect.isfunction(func):
            return None
        if len(inspect.signature(func).parameters) != 1:  # (self, info): not run here
            return None
        checks.append(func)
    return tuple(checks)


@lru_cache(maxsize=1024)
def _field_adapter(cls: type[BaseModel], name: str) -> TypeAdapter | None:
    """A validator of the field ``name`` of ``cls`` alone: its annotation with its metadata
    (units, bounds, library names), as the model validates it; None when the class has field
    validators of its own."""
    decorators = cls.__pydantic_decorators__
    for dec in decorators.field_validators.values():
        if name in dec.info.fields or "*" in dec.info.fields:
            return None
    info = cls.model_fields[name]
    annotation = info.annotation
    if info.metadata:
        annotation = Annotated[(annotation, *info.metadata)]
    return TypeAdapter(annotation)


def _validated(cls: type[BaseModel], name: str, value: Any, context: dict) -> Any:
    """``value`` validated as the field ``name`` of ``cls``; :class:`_SlowPath` if refused."""
    adapter = _field_adapter(cls, name)
    if adapter is None:
        raise _SlowPath
    try:
        return adapter.validate_python(value, context=context)
    except ValidationError:
        raise _SlowPath from None


@lru_cache(maxsize=256)
def _is_list_of_sections(cls: type[BaseModel], name: str) -> bool:
    """Whether the field is a plain list of section models (``list[X]`` or ``list[X] | None``),
    whose items a change may index."""
    info = cls.model_fields[name]
    if info.metadata:
        return False
    annotation = info.annotation
    if typing.get_origin(annotation) in (typing.Union, types.UnionType):
        arms = [a for a in typing.get_args(annotation) if a is not type(None)]
        if len(arms) != 1:
            return False
        annotation = arms[0]
    if typing.get_origin(annotation) is not list:
        return False
    (item,) = typing.get_args(annotation)
    return isinstance(item, type) and issubclass(item, BaseModel)


# What a built-in pydantic check accepts, in the words of "<field>: <value> is not <accepted>".
_ACCEPTED = {
    "string_type": "a text (in quotes if it looks like a number)",
    "list_type": "a list",
    "tuple_type": "a list",
    "set_type": "a list",
    "dict_type": "a mapping of keys",
    "model_type": "a mapping of keys",
    "model_attributes_type": "a mapping of keys",
    "int_type": "an integer",
    "int_parsing": "an integer",
    "int_from_float": "an integer",
    "int_parsing_size": "an integer of a sensible size",
    "float_type": "a number",
    "float_parsing": "a number",
    "finite_number": "a finite number",
    "bool_type": "true or false",
    "bool_parsing": "true or false",
    "literal_error": "one of {expected}",
    "enum": "one of {expected}",
    "greater_than": "> {gt}",
    "greater_than_equal": ">= {ge}",
    "less_than": "< {lt}",
    "less_than_equal": "<= {le}",
    "too_short": "a list of at least {min_length} items",
    "too_long": "a list of at most {max_length} items",
    "string_too_long": "a text of at most {max_length} characters",
}
# pydantic's names of union members and validators in an error location (not keys of the case)
_LOC_TAG = re.compile(
    r"^(?:str|int|float|bool|none|(?:function|literal|list|tuple|dict|set|lax-or-strict|"
    r"json-or-python|nullable|union|tagged-union|chain)\b.*|[A-Z][A-Za-z0-9]+)$"
)
# a message of a nested validator that starts with its own field: "composition.N2: ..."
_INNER_FIELD = re.compile(r"^((?:\[\d+\]|[A-Za-z_][\w()]*)(?:\.[\w()]+|\[\d+\])*): (.*)$")


def _show(value: Any) -> str:
    """A value as a message shows it: text in double quotes, the rest as Python writes it."""
    if isinstance(value, str):
        return '"' + (value if len(value) <= 50 else value[:47] + "...") + '"'
    return _short(value)


def _error_loc(err: dict) -> tuple:
    """The error's location as keys and indices of the case (pydantic's tags removed)."""
    return tuple(p for p in err["loc"] if not (isinstance(p, str) and _LOC_TAG.match(p)))


def _accepted(err: dict) -> str | None:
    """What a built-in pydantic check accepts, or None for other (custom) errors."""
    template = _ACCEPTED.get(err["type"])
    if template is None:
        return None
    ctx = dict(err.get("ctx") or {})
    if "expected" in ctx:  # "'instant' or 'burnout'" -> "instant, burnout"
        ctx["expected"] = (
            ", ".join(re.findall(r"'([^']*)'", str(ctx["expected"]))) or ctx["expected"]
        )
    try:
        return template.format(**ctx)
    except (KeyError, IndexError):
        return template.split(" {", 1)[0]


def _format_error(model: type[BaseModel], err: dict, siblings: list[dict] = ()) -> str:
    """One line "<field>: <value> is not <accepted>" (or "<field>: missing (required)") for a
    pydantic error; ``siblings``, the other errors at the same location (union members), add
    what they accept."""
    loc = _error_loc(err)
    path = ".".join(str(p) for p in loc) or "(top level)"
    kind = err["type"]
    value = err.get("input")
    if kind == "extra_forbidden":
        owner = _model_at(model, loc)
        names = list(owner.model_fields) if owner else []
        close = difflib.get_close_matches(str(loc[-1]), names, n=1) if loc else []
        hint = f', did you mean "{close[0]}"?' if close else ""
        return f"{path}: unknown key{hint} (accepted keys: {', '.join(names)})"
    if kind == "missing":
        return f"{path}: missing (required)"
    accepted = _accepted(err)
    if accepted is not None:
        others = [a for e in siblings if (a := _accepted(e)) and a != accepted]
        accepted = " or ".join(dict.fromkeys([accepted, *others]))
        if value is None:
            return f"{path}: empty, expected {accepted}"
        return f"{path}: {_show(value)} is not {accepted}"
    msg = re.sub(r"^Value error, ", "", err["msg"])
    ctx = err.get("ctx") or {}
    if kind == "number" and "value" in ctx and msg.startswith(str(ctx["value"])):
        # custom checks write {value} with str(): quote text, shorten the rest
        shown = "None" if ctx["value"] is None else _show(ctx["value"])
        msg = shown + msg[len(str(ctx["value"])) :]
    inner = _INNER_FIELD.match(msg)
    if inner and kind in ("quantity", "number", "choice"):  # "composition.N2: ..." of a field
        field, msg = inner.groups()
        last = str(loc[-1]) if loc else ""
        if field == last or field.startswith((f"{last}.", f"{last}[")):
            field = field[len(last) :]
        path += field if field.startswith(("[", ".")) or not field else f".{field}"
    msg = re.sub(r"(^|: )None is not (?=\S)", r"\1empty, expected ", msg)
    return f"{path}: {msg}"


_short = short_repr  # ``repr(value)`` in at most about 80 characters, however large the value


def _check_structure(data: Any, source: str) -> None:
    """Refuse data nested too deeply, too large or with huge integers
    (:func:`rotarykiln.yaml_limits.check_structure`)."""
    check_structure(data, source)


def _error_rank(err: dict) -> int:
    """Unknown keys first (they explain "missing" ones), a union's model member before its
    name-list member when a mapping was given, pydantic's type checks last."""
    if err["type"] == "extra_forbidden":
        return 0
    if err["type"] == "choice" and not isinstance(err.get("input"), str):
        return 3
    return 2 if err["type"] in _ACCEPTED else 1


SPECIES_ACCEPTED = "a species file beside the case file, or a mapping of species (bed:, gas:)"
"""What ``chemistry.species`` accepts, in its messages."""


def case_file_path(field: str, spec: Any, base_dir: str | Path | None, accepted: str) -> Path:
    """The file a case names at ``field``: ``spec`` resolved inside the case file's folder.

    A case may only name a file beside it: a relative path that stays inside ``base_dir`` once
    resolved (no absolute path, no ``..``, no symbolic link leading out), naming a regular file.
    A case given as data (``base_dir`` None: a Python mapping, an app upload) names no file.

    Parameters
    ----------
    field : str
        The field of the case (``"chemistry.species"``), named in messages.
    spec : str
        The path as the user typed it.
    base_dir : str, Path or None
        The case file's folder; None: no file is accepted.
    accepted : str
        What the field accepts, for the messages.

    Returns
    -------
    Path
        The resolved path of the file.

    Raises
    ------
    InputError
        One line naming the field and the path as typed (never the file's content).
    """
    refused = InputError(field, message=f"{field}: {_show(spec)} is not accepted ({accepted})")
    if base_dir is None:
        raise InputError(
            field,
            message=f"{field}: {_show(spec)} is not accepted ({accepted}; a case given as data "
            "names no file)",
        )
    if not isinstance(spec, str) or not spec.strip() or "\0" in spec or len(spec) > 255:
        raise refused
    typed = Path(spec)
    if typed.is_absolute() or ".." in typed.parts:
        raise refused
    try:
        base = Path(base_dir).resolve()
        target = (base / typed).resolve()
    except (OSError, RuntimeError, ValueError):  # a loop of symbolic links
        raise refused from None
    if not target.is_relative_to(base) or target == base:
        raise refused
    if not target.is_file():
        raise InputError(
            field,
            message=f"{field}: {_show(spec)} is not a file beside the case file ({accepted})",
        )
    return target


def _species_file(spec: str, base_dir) -> dict:
    """The mapping of the species file ``spec`` (beside the case); messages show no content."""
    field = "chemistry.species"
    path = case_file_path(field, spec, base_dir, SPECIES_ACCEPTED)
    raw = read_yaml_file(path, what="species file", label=f"{field}: {_show(spec)}", content=False)
    if isinstance(raw, dict) and "species" in raw and not ({"bed", "gas"} & set(raw)):
        raw = raw["species"]  # a file may hold its species under a top-level species: key
    if (
        not isinstance(raw, dict)
        or not raw
        or not all(isinstance(k, str) and k in ("bed", "gas", "elements") for k in raw)
    ):
        raise InputError(
            field,
            message=f"{field}: {_show(spec)} is not a species file (a YAML mapping with bed:, "
            "gas: and elements: sections)",
        )
    return raw


def _load_user_species(data: dict, source: str, base_dir: str | Path | None = None):
    """The case's user species (``chemistry.species``: a file beside the case file, or a
    mapping), loaded once: the data with the species inline (a file's mapping in place of its
    name), and the species table (None without user species). A bad species:
    :class:`InputError` naming ``chemistry.species``; the values of a file are never shown."""
    chem = data.get("chemistry")
    if not isinstance(chem, dict) or chem.get("species") is None:
        return data, None
    from rotarykiln.chemistry.species import load_species

    spec = chem["species"]
    if isinstance(spec, str):
        mapping = _species_file(spec, base_dir)
        try:
            species = load_species(mapping)
        except InputError as exc:
            where = f"chemistry.species: {_show(spec)}: {str(exc.field)[:80]}"
            if exc.value is None or exc.value == "missing" or not exc.accepted:
                shown = str(exc).split(": ", 1)[-1] if exc.value is None else "not accepted"
                raise InputError("chemistry.species", message=f"{where}: {shown}") from None
            raise InputError(
                "chemistry.species",
                message=f"{where}: the value given is not {exc.accepted}",
            ) from None
        return {**data, "chemistry": {**chem, "species": mapping}}, species
    if not isinstance(spec, dict):
        raise InputError(
            "chemistry.species",
            message=f"chemistry.species: {_short(spec)} is not accepted ({SPECIES_ACCEPTED})",
        )
    try:
        species = load_species(spec)
    except InputError as exc:
        raise InputError("chemistry.species", message=f"chemistry.{exc}") from None
    return data, species


def parse_case(
    data: Any,
    *,
    source: str = "case",
    model: type[BaseModel] = Case,
    base_dir: str | Path | None = None,
) -> Case:
    """Validate a mapping (parsed YAML) into a :class:`Case`.

    Parameters
    ----------
    data : mapping
        The case file's content (parsed YAML, or a Python mapping).
    source : str
        How messages name the case (a file name).
    model : type
        The pydantic model to validate against (default :class:`Case`).
    base_dir : str, Path or None
        The folder of the case file, in which the files a case names (``chemistry.species``)
        are looked up (:func:`case_file_path`: only files inside it). None (default): a case
        given as data, which names no file: only inline mappings and built-in names are
        accepted (the app's uploads, sweeps, Python callers).

    Raises
    ------
    InputError
        One line: the first problem found, with a count of the others.
    """
    if data is None:
        raise InputError(
            source, message=f"{source}: the case is empty (it needs kiln: and operation: sections)"
        )
    if not isinstance(data, dict):
        raise InputError(
            source, message=f"{source}: expected a mapping of sections, got {_short(data)}"
        )
    _check_structure(data, source)
    data, species = _load_user_species(data, source, base_dir)
    try:
        return model.model_validate(data, context={"species": species})
    except ValidationError as exc:
        # a misspelt key also makes the real key "missing": report the misspelling first; a
        # union's members each report an error at one place: count the place once
        errors = sorted(exc.errors(), key=_error_rank)
        places = list(dict.fromkeys(_error_loc(e) for e in errors))
        siblings = [e for e in errors[1:] if _error_loc(e) == places[0]]
        first = _format_error(model, errors[0], siblings)
        n = len(places) - 1
        message = first + (f" (and {n} more problem{'s' if n > 1 else ''})" if n else "")
        path = first.split(":", 1)[0]
        raise InputError(path, message=message) from None


def check_quantity(field: str, value: Any, kind: Any) -> float:
    """``value`` converted to SI and checked against a quantity type of the case file.

    The same units and ranges as a case file's field of that type, for inputs that are not
    case files (transient events files): ``check_quantity("events[0].to", "1e6 rpm",
    RotationRate)`` is refused as ``operation.speed: "1e6 rpm"`` is.

    Parameters
    ----------
    field : str
        The field's name in messages (``"events[0].to"``).
    value : str or number
        The value as given (``"1.5 rpm"``).
    kind : type
        A quantity type of this module (:data:`RotationRate`, :data:`Temperature`...).

    Returns
    -------
    float
        The SI value.

    Raises
    ------
    InputError
        One line: ``<field>: <value> is not <range>`` or the unit's message.

    Examples
    --------
    >>> check_quantity("events[0].to", "1e6 rpm", RotationRate)
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: events[0].to: 1e6 rpm is not in [1e-5 rpm, 955 rpm] (1e-6 to 100 rad/s)
    """
    convert = next(m.func for m in kind.__metadata__ if isinstance(m, BeforeValidator))
    try:
        return convert(value)
    except PydanticCustomError as exc:
        raise InputError(field, message=f"{field}: {exc.message()}") from None


MAX_CASE_BYTES = MAX_YAML_BYTES
"""Largest case file read, bytes (:data:`rotarykiln.yaml_limits.MAX_YAML_BYTES`)."""
MAX_CASE_DEPTH = MAX_YAML_DEPTH
"""Deepest nesting of mappings and lists in a case (:data:`~rotarykiln.yaml_limits.MAX_YAML_DEPTH`)."""
MAX_CASE_ALIASES = MAX_YAML_ALIASES
"""Most YAML aliases (``*name``) in a case file."""
MAX_CASE_VALUES = MAX_YAML_VALUES
"""Most values (keys, scalars, lists and mappings, aliases expanded) in a case."""
_LimitError = YamlLimitError  # the names of the limited loader before rotarykiln.yaml_limits
_CaseLoader = LimitedLoader


def read_case_yaml(path: str | Path) -> Any:
    """Read a YAML case file into Python objects, within the limits of
    :mod:`rotarykiln.yaml_limits` (not validated; the files it names are not read).

    Raises
    ------
    InputError
        One line naming the file: missing, unreadable, larger than :data:`MAX_CASE_BYTES`, not
        UTF-8, malformed YAML, over a limit of the loader, a duplicate key.
    """
    return read_yaml_file(path, what="case file")


def _case_folder(path: str | Path) -> Path:
    """The folder of a case file (as given: a case reached through a link names files beside
    the link)."""
    return Path(path).absolute().parent


def read_case_data(path: str | Path) -> Any:
    """A case file's mapping with the files it names read in (``chemistry.species``: the
    species file beside it, as a mapping): data that :func:`parse_case` validates without a
    folder (sweeps, studies, worker processes), refused as :func:`load_case` refuses it.

    Raises
    ------
    InputError
        One line: as :func:`read_case_yaml`, or a file the case names that is refused.
    """
    data = read_case_yaml(path)
    if isinstance(data, dict):
        _check_structure(data, str(path))
        data, _ = _load_user_species(data, str(path), _case_folder(path))
    return data


def load_case(path: str | Path) -> Case:
    """Read and validate a YAML case file (within the limits of :func:`read_case_yaml`); the
    files it names are looked up beside it (see :func:`parse_case`).

    Examples
    --------
    >>> from rotarykiln.cases import builtin_case_path
    >>> case = load_case(builtin_case_path("tscheng_A16"))
    >>> round(case.operation.speed, 4)
    0.1571
    """
    return parse_case(read_case_yaml(path), source=str(path), base_dir=_case_folder(path))


def case_json_schema() -> dict:
    """The JSON Schema (draft 2020-12) of a case file (:func:`rotarykiln.case_io.json_schema_of`
    of :class:`Case`): what an editor can check while typing; the loader checks more (units,
    ranges, library names)."""
    from rotarykiln.case_io import json_schema_of

    return json_schema_of(Case)
