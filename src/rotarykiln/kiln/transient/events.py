r"""Events of a transient kiln run: a YAML file with units, read once, checked, made a schedule.

A transient file (YAML)::

    start: steady            # or cold: the kiln at ambient, filled with its hold-up of cold feed
    events:                  # in time order; a step, or a ramp with ``over``
      - {at: 1 h, variable: feed, to: 70 kg/h}
      - {at: 2 h, variable: fuel_flow, to: 2.2 NL/s, over: 30 min}
      - {at: 5 h, variable: drum, to: stop}      # solids and feed stop; ``to: run`` restarts
      - {at: 5.5 h, variable: drum, to: run}
    tracer: {at: 0 s, duration: 2 min}           # a non-reacting tracer pulse in the feed
    wall:                    # heat capacity of the lining layers, inner to outer
      layers:
        - {density: 1300 kg/m3, specific_heat: 1000 J/kg/K}
        - {density: 7850 kg/m3, specific_heat: 490 J/kg/K}
    output_every: 5 min

Variables: ``feed`` (solids mass flow, composition kept), ``feed_temperature``, ``speed``
(the solids speed follows the rotation rate, Saeman: u ~ n at a given bed), ``drum``
(``stop``/``run``: a stopped drum carries no solids, so the feed stops with it); with a burner
``fuel_flow``, ``primary_air``, ``secondary_air`` (mass, molar or normal volume flows; the
burner's products are recomputed, :func:`~rotarykiln.kiln.combustion.flame.fire`); without a burner
``gas_flow`` (composition kept) and ``gas_inlet_temperature``.
Refused with one line (:class:`~rotarykiln.errors.InputError`) naming the event: events out of
order, negative times or beyond the end of the run, a ramp into another event of the same
variable, negative flows, an unknown variable, a time without a unit (``at: 3600``), a value
outside the range the case file accepts for it (the quantity types of :mod:`rotarykiln.case`:
a speed of 1e6 rpm, a feed temperature of 1e-6 K), more than :data:`MAX_EVENTS` events, more
than :data:`MAX_OUTPUT_TIMES` output times. The file is read as every YAML file is
(:mod:`rotarykiln.yaml_limits`: size, nesting, aliases and duplicate keys limited).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, ValidationError

from rotarykiln.case import (
    Density,
    Instant,
    Length,
    Mass,
    MassFlow,
    RotationRate,
    SpecificHeat,
    Temperature,
    Time,
    check_quantity,
)
from rotarykiln.errors import InputError
from rotarykiln.kiln.inputs.boundary import BoundaryInputs
from rotarykiln.kiln.transient.holdup import DEFAULT_NODE_SPACING, WallProperties
from rotarykiln.units import gas_flow
from rotarykiln.yaml_limits import check_structure, read_yaml_file, show_value

__all__ = [
    "TransientSpec",
    "Event",
    "Schedule",
    "read_transient_file",
    "parse_transient",
    "VARIABLES",
    "MAX_EVENTS",
    "MAX_OUTPUT_TIMES",
    "MAX_OUTPUT_VALUES",
    "MAX_WALL_NODES",
    "check_output_size",
    "output_times_bound",
]

#: Event variables -> (kind of quantity, what it needs).
VARIABLES = {
    "feed": "mass flow",
    "feed_temperature": "temperature",
    "speed": "rotation rate",
    "drum": "stop or run",
    "fuel_flow": "gas flow",
    "primary_air": "gas flow",
    "secondary_air": "gas flow",
    "gas_flow": "mass flow",
    "gas_inlet_temperature": "temperature",
}
BURNER_VARIABLES = ("fuel_flow", "primary_air", "secondary_air")
GAS_VARIABLES = ("gas_flow", "gas_inlet_temperature")
#: Knots per ramp at which the derived inputs (burner products) are computed.
RAMP_KNOTS = 11
#: Quantity type of the case file (:mod:`rotarykiln.case`) each event variable's value is
#: checked against (the burner's flows are checked as the case's burner flows are).
VARIABLE_RANGES = {
    "feed": MassFlow,
    "feed_temperature": Temperature,
    "speed": RotationRate,
    "gas_flow": MassFlow,
    "gas_inlet_temperature": Temperature,
}
#: Most events in a file (each cuts the run into one more integration segment; 10,000 events
#: ran for minutes).
MAX_EVENTS = 1000
#: Most output times of a run (``until`` / ``output_every``; the default is 201).
MAX_OUTPUT_TIMES = 10_000
#: Most cells x output times of a run (the profiles kept: ~200 floats each, so at most ~1.6 GB
#: in the worst case; the default 201 outputs allow 4,975 cells).
MAX_OUTPUT_VALUES = 1_000_000
#: Most lining nodes across the wall of a cell (``wall.max_node_spacing`` cuts the layers).
MAX_WALL_NODES = 200

_Q = str | float | int


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class EventSpec(_Strict):
    at: _Q
    variable: str
    to: _Q
    over: _Q | None = None


class TracerSpec(_Strict):
    at: _Q = 0.0
    duration: _Q
    mass: _Q | None = None


class WallLayerSpec(_Strict):
    density: _Q
    specific_heat: _Q


class WallSpec(_Strict):
    layers: list[WallLayerSpec] = []
    thickness: _Q | None = None
    density: _Q | None = None
    specific_heat: _Q | None = None
    max_node_spacing: _Q | None = None


class TransientSpec(_Strict):
    """The transient file as read (quantities still strings with units)."""

    start: Literal["steady", "cold"] = "steady"
    events: list[EventSpec] = []
    tracer: TracerSpec | None = None
    wall: WallSpec | None = None
    output_every: _Q | None = None


@dataclass(frozen=True)
class Event:
    """One event in SI: ``time`` (s), ``variable``, ``value`` (SI, or "stop"/"run"),
    ``duration`` (s, 0 for a step), ``label`` (``events[i]`` for messages)."""

    time: float
    variable: str
    value: object
    duration: float = 0.0
    label: str = ""

    @property
    def end(self) -> float:
        return self.time + self.duration


@dataclass(frozen=True)
class Transient:
    """A checked transient file in SI: ``start``, ``events``, ``tracer`` (start s, duration s,
    mass kg or None), ``wall`` (:class:`~rotarykiln.kiln.transient.holdup.WallProperties`),
    ``output_every`` (s or None)."""

    start: str
    events: tuple[Event, ...]
    tracer: tuple[float, float, float | None] | None
    wall: WallProperties
    output_every: float | None


# pydantic's names of union members in an error location (not keys of the file)
_TAGS = {"str", "int", "float", "bool", "none", "list", "dict", "function-before"}
# what a pydantic type check accepts, in the words of "<field>: <value> is not <accepted>"
_SHAPES = {
    "dict_type": "a mapping of keys",
    "model_type": "a mapping of keys",
    "list_type": "a list",
    "string_type": "a text",
    "bool_type": "true or false",
}
_QUANTITY_FIELDS = {
    "at",
    "to",
    "over",
    "duration",
    "mass",
    "density",
    "specific_heat",
    "thickness",
    "max_node_spacing",
    "output_every",
}


def _format_validation(exc: ValidationError, prefix: str = "") -> str:
    e = exc.errors()[0]
    parts = [p for p in e["loc"] if not (isinstance(p, str) and p in _TAGS)]
    loc = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in parts).lstrip(".")
    loc = f"{prefix}{loc}" if loc else prefix.rstrip(".") or "transient file"
    value = show_value(e.get("input"))
    if e["type"] == "extra_forbidden":
        return f"{loc}: unknown key"
    if e["type"] == "missing":
        return f"{loc}: missing (required)"
    if e["type"] == "literal_error":
        return f"{loc}: {value} is not one of {e['ctx']['expected']}"
    last = parts[-1] if parts else ""
    if last in _QUANTITY_FIELDS and e["type"] not in ("dict_type", "model_type", "list_type"):
        return f'{loc}: {value} is not a quantity with a unit (e.g. "1 h", "70 kg/h")'
    return f"{loc}: {value} is not {_SHAPES.get(e['type'], 'accepted')}"


def read_transient_file(path) -> dict:
    """The YAML mapping of a transient file, read within the limits of
    :func:`rotarykiln.yaml_limits.read_yaml_file` (one-line InputError for a missing, large,
    non-UTF-8, malformed or over-limit file, a duplicate key, a file that is not a mapping)."""
    data = read_yaml_file(path, what="events file")
    if data is None:
        data = {}
    if not isinstance(data, dict):
        raise InputError(
            str(path),
            message=f"{path}: not an events file (a YAML mapping of start:, events:, tracer:, "
            "wall:, output_every:)",
        )
    return data


def _time(field, value, kind=Time) -> float:
    """A time of the events file in s: with a unit (a bare number other than 0 is refused),
    in the range of ``kind`` (:data:`rotarykiln.case.Time`, or :data:`~rotarykiln.case.Instant`
    for a moment that may be 0)."""
    if isinstance(value, int | float) and not isinstance(value, bool) and value != 0:
        raise InputError(
            field,
            message=f"{field}: bare number {show_value(value)} needs a unit (e.g. "
            f'"{show_value(value)} s", "1 h")',
        )
    return check_quantity(field, value, kind)


def output_times_bound(transient: Transient, until: float) -> int:
    """At most how many output times a run of ``transient`` to ``until`` (s) keeps: every
    ``output_every`` (default ``until`` / 200) and the start and end of every event."""
    every = transient.output_every or until / 200.0
    return int(until / every) + 2 + 2 * len(transient.events) + 4


def check_output_size(n_cells: int, n_times: int, field: str = "output_every") -> None:
    """Refuse a run whose profiles would exceed :data:`MAX_OUTPUT_TIMES` output times or
    :data:`MAX_OUTPUT_VALUES` cells x output times, before anything is allocated.

    Raises
    ------
    InputError
        One line naming ``field`` and the limit.
    """
    if n_times > MAX_OUTPUT_TIMES:
        raise InputError(
            field,
            message=f"{field}: {n_times} output times is too many (at most {MAX_OUTPUT_TIMES}; "
            "give a longer output_every or a shorter --until)",
        )
    if n_cells * n_times > MAX_OUTPUT_VALUES:
        raise InputError(
            field,
            message=f"{field}: {n_cells} cells x {n_times} output times is too many (at most "
            f"{MAX_OUTPUT_VALUES:,} cell-times; give fewer --cells or a longer output_every)",
        )


def parse_transient(data: dict, kiln, until: float) -> Transient:
    """Check a transient file's mapping against ``kiln`` and the end time ``until`` (s).

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> from rotarykiln.kiln.from_case import kiln_from_case
    >>> kiln, _ = kiln_from_case(load_case(builtin_case_path("tscheng_A16")))
    >>> t = parse_transient({"events": [{"at": "1 h", "variable": "feed", "to": "30 kg/h"}]},
    ...                     kiln, 7200.0)
    >>> t.events[0].time, round(t.events[0].value * 3600, 6)
    (3600.0, 30.0)
    >>> parse_transient({"events": [{"at": "1 h", "variable": "colour", "to": "red"}]},
    ...                 kiln, 7200.0)
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: events[0].variable: "colour" is not one of feed, feed_temperature, speed, drum, gas_flow, gas_inlet_temperature
    """
    if not isinstance(data, dict):
        raise InputError("transient file", message="transient file: expected a mapping")
    check_structure(data, "transient file")
    if isinstance(data.get("events"), list) and len(data["events"]) > MAX_EVENTS:
        raise InputError(
            "events",
            message=f"events: {len(data['events'])} events is too many (at most {MAX_EVENTS})",
        )
    try:
        spec = TransientSpec.model_validate(data)
    except ValidationError as exc:
        raise InputError("transient file", message=_format_validation(exc)) from None
    burner = kiln.firing.flame is not None
    allowed = [v for v in VARIABLES if v not in (GAS_VARIABLES if burner else BURNER_VARIABLES)]
    events = []
    last_end: dict[str, float] = {}
    previous = 0.0
    for i, e in enumerate(spec.events):
        label = f"events[{i}]"
        t = _time(f"{label}.at", e.at, Instant)
        if t > until:
            raise InputError(f"{label}.at", e.at, f"<= the end of the run ({until:g} s)")
        if t < previous:
            raise InputError(
                f"{label}.at", e.at, f"in time order (after the previous event at {previous:g} s)"
            )
        previous = t
        if e.variable not in allowed:
            raise InputError(
                f"{label}.variable",
                message=f"{label}.variable: {show_value(e.variable)} is not one of "
                + ", ".join(allowed),
            )
        duration = 0.0
        if e.over is not None:
            if e.variable == "drum":
                raise InputError(f"{label}.over", e.over, "absent for the drum (a stop is a step)")
            duration = _time(f"{label}.over", e.over)
            if t + duration > until * (1 + 1e-12):
                raise InputError(
                    f"{label}.over",
                    e.over,
                    f"a ramp ending by the end of the run ({until:g} s)",
                )
        if t < last_end.get(e.variable, -1.0):
            raise InputError(
                f"{label}.at",
                e.at,
                f"after the ramp of {e.variable} before it ends ({last_end[e.variable]:g} s)",
            )
        last_end[e.variable] = t + duration
        value = _event_value(label, e.variable, e.to, kiln)
        events.append(Event(t, e.variable, value, duration, label))
    tracer = None
    if spec.tracer is not None:
        s = spec.tracer
        t0 = _time("tracer.at", s.at, Instant)
        dt = _time("tracer.duration", s.duration)
        if t0 + dt > until:
            raise InputError("tracer.duration", s.duration, f"a pulse ending by {until:g} s")
        mass = None
        if s.mass is not None:
            mass = check_quantity("tracer.mass", s.mass, Mass)
        tracer = (t0, dt, mass)
    every = None
    if spec.output_every is not None:
        every = _time("output_every", spec.output_every)
        if not every <= until:
            raise InputError("output_every", spec.output_every, f"in (0, {until:g}] s")
        check_output_size(1, int(until / every) + 1)
    return Transient(spec.start, tuple(events), tracer, _wall(spec.wall, kiln), every)


def _event_value(label, variable, value, kiln):
    field = f"{label}.to"
    if variable == "drum":
        if value not in ("stop", "run"):
            raise InputError(field, message=f"{field}: {show_value(value)} is not stop or run")
        return value
    if variable in BURNER_VARIABLES:
        from rotarykiln.kiln.combustion.flame import AIR
        from rotarykiln.materials.gas import molar_mass

        comp = kiln.firing.flame.burner.fuel if variable == "fuel_flow" else AIR
        flow = gas_flow(value, field, allow_zero=variable != "fuel_flow")
        return flow.mass_flow(molar_mass(comp))
    v = check_quantity(field, value, VARIABLE_RANGES[variable])
    if not v > 0:  # a flow of 0 (the ranges of the case accept a zero feed)
        accepted = "> 0 kg/s"
        if variable == "feed":
            accepted += " (to stop the solids use variable: drum, to: stop)"
        raise InputError(field, message=f"{field}: {show_value(value)} is not {accepted}")
    return v


def _wall(spec: WallSpec | None, kiln) -> WallProperties:
    spec = spec or WallSpec()
    spacing = DEFAULT_NODE_SPACING
    if spec.max_node_spacing is not None:
        spacing = check_quantity("wall.max_node_spacing", spec.max_node_spacing, Length)
    nodes = sum(max(1, math.ceil(layer.thickness / spacing - 1e-9)) for layer in kiln.wall.layers)
    if nodes > MAX_WALL_NODES:
        shown = spec.max_node_spacing if spec.max_node_spacing is not None else f"{spacing} m"
        raise InputError(
            "wall.max_node_spacing",
            message=f"wall.max_node_spacing: {show_value(shown)} cuts the lining into {nodes} "
            f"nodes across the wall (at most {MAX_WALL_NODES}; give a larger spacing)",
        )
    if len(spec.layers) > MAX_WALL_NODES:
        raise InputError("wall.layers", message=f"wall.layers: more than {MAX_WALL_NODES} layers")
    layers = tuple(
        (
            check_quantity(f"wall.layers[{i}].density", w.density, Density),
            check_quantity(f"wall.layers[{i}].specific_heat", w.specific_heat, SpecificHeat),
        )
        for i, w in enumerate(spec.layers)
    )
    if kiln.wall.layers and not layers:
        layers = tuple(_library_heat_capacity(i, layer) for i, layer in enumerate(kiln.wall.layers))
    if kiln.wall.layers and len(layers) != len(kiln.wall.layers):
        raise InputError(
            "wall.layers",
            f"{len(layers)} layers",
            f"one density and specific heat per lining layer ({len(kiln.wall.layers)})",
        )
    lumped = None
    if not kiln.wall.layers:
        given = (spec.thickness, spec.density, spec.specific_heat)
        if any(v is None for v in given):
            raise InputError(
                "wall.thickness",
                None,
                "given with wall.density and wall.specific_heat (a U-value wall has no lining "
                "to give it a heat capacity)",
            )
        lumped = (
            check_quantity("wall.thickness", spec.thickness, Length),
            check_quantity("wall.density", spec.density, Density),
            check_quantity("wall.specific_heat", spec.specific_heat, SpecificHeat),
        )
    return WallProperties(layers, lumped, spacing)


#: Specific heat of lining layers without one given, J/(kg K): steels (Incropera table A.1,
#: plain carbon steel at 300-600 K) and refractories and insulation (fireclay, alumina-silica
#: castables and mineral wools, 0.9-1.1 kJ/(kg K) over 300-1300 K).
STEEL_CP, REFRACTORY_CP = 490.0, 1000.0


def _library_heat_capacity(i, layer):
    """Density (library) and specific heat (typical) of a lining layer's material."""
    from rotarykiln.materials._library import load_library

    lib = load_library("refractories.yaml")
    name = layer.material.name
    if name not in lib or "density" not in lib[name]:
        raise InputError(
            f"wall.layers[{i}]",
            None,
            f"given (density and specific_heat: the lining material {name!r} is not in the "
            "material library)",
        )
    cp = STEEL_CP if "steel" in name else REFRACTORY_CP
    return float(lib[name]["density"]), cp


# --- the schedule: inputs against time ----------------------------------------------------------


@lru_cache(maxsize=256)
def _flame_gas(burner, diameter, length, gas_names, dissociation=None):
    """Gas inlet flows (per ``gas_names``), temperature and heat release of ``burner``.

    ``dissociation``: the dissociation heat the transient's gas tables carry (that of the
    burner it started with, or None). The products of another burner state enter at the
    temperature at which those tables hold their enthalpy (the frozen products at their frozen
    adiabatic temperature), so the energy fed is the new flame's even though the tables'
    dissociation heat is the old products'.
    """
    from rotarykiln.kiln.combustion.flame import fire
    from rotarykiln.materials.gas import molar_mass

    flame = fire(burner, diameter, length)
    p = flame.products
    mass = {}
    for name, x in p.composition:
        key = name if name in gas_names else "N2"
        mass[key] = mass.get(key, 0.0) + x * molar_mass(f"{name}:1")
    total = sum(mass.values())
    flows = np.array([p.mass_flow * mass.get(s, 0.0) / total for s in gas_names])
    t_in = float(flame.inlet_temperature)
    if dissociation is not None and flame.burns_at_inlet and flame.dissociation is not dissociation:
        t_in = _inlet_temperature(flows, gas_names, p.adiabatic_temperature, dissociation)
    return flows, t_in, float(flame.heat_release)


def _inlet_temperature(flows, gas_names, t_frozen: float, dissociation) -> float:
    """Temperature (K) at which gas tables carrying ``dissociation`` hold the enthalpy of the
    frozen products ``flows`` (kg/s per ``gas_names``) at ``t_frozen``."""
    from rotarykiln.kiln.gas_mixture import GasMixture

    present = [i for i, q in enumerate(flows) if q > 0]
    names = tuple(gas_names[i] for i in present)
    q = np.asarray(flows, dtype=float)[present]
    target = float(GasMixture.of(names).species_enthalpy(np.array(t_frozen)) @ q)
    grid = np.linspace(200.0, t_frozen, 4001)
    h = GasMixture.of(names, None, dissociation).species_enthalpy(grid) @ q
    return float(np.interp(target, h, grid))


class Schedule:
    """Inputs of ``kiln`` against time for ``events`` (and a tracer pulse), over [0, until].

    :meth:`segments` are the intervals between the discontinuities (steps, ramp ends, tracer
    pulse); inside a segment :meth:`inputs` is linear between knots (ramps of the burner are
    computed at :data:`RAMP_KNOTS` points, the products of a flame being nonlinear in its flows).
    """

    def __init__(self, kiln, bed_names, gas_names, events=(), until=0.0, tracer=None):
        self.kiln = kiln
        self.bed_names, self.gas_names = tuple(bed_names), tuple(gas_names)
        self.events = tuple(events)
        self.until = float(until)
        feed = np.array([kiln.feed.flows.get(s, 0.0) for s in self.bed_names])
        self.feed_fractions = feed / feed.sum()
        self.base = {"feed": float(feed.sum()), "feed_temperature": kiln.feed.temperature}
        self.base.update(speed=kiln.drum.omega, drum="run")
        if kiln.firing.flame is not None:
            b = kiln.firing.flame.burner
            self.base.update(
                fuel_flow=b.fuel_flow,
                primary_air=b.primary_air.flow,
                secondary_air=b.secondary_air.flow,
            )
        gas = np.array([kiln.gas.flows.get(s, 0.0) for s in self.gas_names])
        self.gas_fractions = gas / gas.sum()
        self.base.update(gas_flow=float(gas.sum()), gas_inlet_temperature=kiln.gas.temperature)
        self.tracer = tracer
        cuts = {0.0, self.until}
        for e in self.events:
            cuts.update((e.time, e.end))
        if tracer is not None:
            cuts.update((tracer[0], tracer[0] + tracer[1]))
        cuts = sorted(c for c in cuts if 0.0 <= c <= self.until)
        self._segments = list(zip(cuts[:-1], cuts[1:], strict=True))
        self._knots = {}

    def segments(self):
        """Intervals (s) between discontinuities of the inputs."""
        return list(self._segments)

    def value(self, variable, t, right=True):
        """The raw value of ``variable`` at ``t`` (s): right or left limit at a step."""
        v = self.base[variable]
        for e in self.events:
            if e.variable != variable:
                continue
            if e.time > t or (e.time == t and not right and e.duration == 0):
                break
            if e.duration == 0 or t >= e.end:
                v = e.value
            else:
                v = v + (e.value - v) * (t - e.time) / e.duration
        return v

    def _derived(self, t, right):
        k = self.kiln
        running = self.value("drum", t, right) == "run"
        feed = self.value("feed", t, right) * running
        omega = self.value("speed", t, right)
        s = omega / k.drum.omega * running
        if k.firing.flame is not None:
            b = k.firing.flame.burner
            burner = dataclasses.replace(
                b,
                fuel_flow=self.value("fuel_flow", t, right),
                primary_air=dataclasses.replace(
                    b.primary_air, flow=self.value("primary_air", t, right)
                ),
                secondary_air=dataclasses.replace(
                    b.secondary_air, flow=self.value("secondary_air", t, right)
                ),
            )
            if burner == b:
                gas = np.array([k.gas.flows.get(n, 0.0) for n in self.gas_names])
                t_gas, release = k.gas.temperature, k.firing.heat_release
            else:
                if burner.air_flow <= 0:
                    raise InputError(
                        "events",
                        message="events: the burner's air flows reach 0 (a flame needs air)",
                    )
                gas, t_gas, release = _flame_gas(
                    burner,
                    2.0 * k.drum.radius,
                    k.drum.length,
                    self.gas_names,
                    k.firing.flame.dissociation,
                )
        else:
            gas = self.value("gas_flow", t, right) * self.gas_fractions
            t_gas, release = self.value("gas_inlet_temperature", t, right), k.firing.heat_release
        tracer = 0.0
        if self.tracer is not None:
            t0, dt, mass = self.tracer
            inside = (t0 <= t < t0 + dt) if right else (t0 < t <= t0 + dt)
            if inside:
                m = mass if mass is not None else 0.01 * self.base["feed"] * dt
                tracer = m / dt
        return BoundaryInputs(
            feed * self.feed_fractions,
            self.value("feed_temperature", t, right),
            np.asarray(gas, dtype=float),
            float(t_gas),
            float(release),
            omega,
            s,
            tracer,
        )

    def _segment_knots(self, i):
        if i not in self._knots:
            a, b = self._segments[i]
            ts = [a, b]
            for e in self.events:
                if e.duration > 0 and e.time < b and e.end > a:
                    ts += list(np.linspace(e.time, e.end, RAMP_KNOTS))
            ts = np.array(sorted({t for t in ts if a <= t <= b}))
            vals = [self._derived(t, right=True) for t in ts[:-1]]
            vals.append(self._derived(ts[-1], right=False))
            self._knots[i] = (ts, vals, np.array([v.vector() for v in vals]))
        return self._knots[i]

    def inputs(self, t, segment: int) -> BoundaryInputs:
        """The inputs at ``t`` (s) inside segment number ``segment``."""
        ts, vals, mat = self._segment_knots(segment)
        if len(ts) == 2 and np.array_equal(mat[0], mat[1]):
            return vals[0]
        v = np.array([np.interp(t, ts, mat[:, c]) for c in range(mat.shape[1])])
        nb, ng = len(self.bed_names), len(self.gas_names)
        return BoundaryInputs(v[:nb], v[nb], v[nb + 1 : nb + 1 + ng], *v[nb + 1 + ng :])


def kiln_at(kiln, u: BoundaryInputs, bed_names, gas_names):
    """A copy of ``kiln`` with the inputs ``u`` (for the steady solve of the new inputs).

    Raises InputError when the inputs are not a steady kiln (a stopped drum).
    """
    if u.speed_factor <= 0:
        raise InputError("drum", "stop", "running for a steady kiln")
    feed = {s: float(q) for s, q in zip(bed_names, u.feed, strict=True) if q > 0}
    gas = {s: float(q) for s, q in zip(gas_names, u.gas, strict=True) if q > 0}
    return kiln.replace(
        feed__flows=feed,
        feed__temperature=u.feed_temperature,
        gas__flows=gas,
        gas__temperature=u.gas_temperature,
        firing__heat_release=u.heat_release,
        drum__omega=u.omega,
        bed__velocity=kiln.bed.velocity * u.speed_factor,
    )
