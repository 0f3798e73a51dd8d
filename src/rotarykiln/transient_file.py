"""The transient file of ``rotarykiln transient``: its schema, its limits and its reader.


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

import math
from typing import Literal

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
from rotarykiln.kiln.transient.events import Event, Transient, check_output_size
from rotarykiln.kiln.transient.holdup import DEFAULT_NODE_SPACING, WallProperties
from rotarykiln.units import gas_flow
from rotarykiln.yaml_limits import check_structure, read_yaml_file, show_value

__all__ = [
    "TransientSpec",
    "read_transient_file",
    "parse_transient",
    "VARIABLES",
    "MAX_EVENTS",
    "MAX_WALL_NODES",
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
        from rotarykiln.materials.gas import molar_mass

        burner = kiln.firing.flame.burner
        if variable == "fuel_flow":
            mm = molar_mass(burner.fuel)
        else:  # an air stream keeps its composition
            mm = getattr(burner, variable).molar_mass
        flow = gas_flow(value, field, allow_zero=variable != "fuel_flow")
        return flow.mass_flow(mm)
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
