"""Events of a transient kiln run: the inputs against time, made a schedule.

:class:`Event` (a step or a ramp of one input) and :class:`Transient` (the events, the start, the
tracer pulse, the wall's heat capacity, the outputs) are what the transient kiln
(:func:`~rotarykiln.kiln.transient.integrate.simulate`) runs; a transient file becomes them in
:mod:`rotarykiln.transient_file`. :class:`Schedule` gives the
:class:`~rotarykiln.kiln.inputs.boundary.BoundaryInputs` at any time (a burner's products
recomputed, :func:`~rotarykiln.kiln.combustion.flame.fire`); :func:`kiln_at` the steady kiln of
the inputs at one time.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.kiln.inputs.boundary import BoundaryInputs
from rotarykiln.kiln.transient.holdup import WallProperties

__all__ = [
    "Event",
    "Transient",
    "Schedule",
    "kiln_at",
    "MAX_OUTPUT_TIMES",
    "MAX_OUTPUT_VALUES",
    "check_output_size",
    "output_times_bound",
]

#: Knots per ramp at which the derived inputs (burner products) are computed.
RAMP_KNOTS = 11
#: Most output times of a run (``until`` / ``output_every``; the default is 201).
MAX_OUTPUT_TIMES = 10_000
#: Most cells x output times of a run (the profiles kept: ~200 floats each, so at most ~1.6 GB
#: in the worst case; the default 201 outputs allow 4,975 cells).
MAX_OUTPUT_VALUES = 1_000_000


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
    from rotarykiln.kiln.from_case import gas_molar_mass

    flame = fire(burner, diameter, length)
    p = flame.products
    if hasattr(p.table, "mass_fractions"):  # products made by elements (solid fuels): exact
        given = dict(zip(p.table.names, p.table.mass_fractions, strict=True))
        flows = np.array([p.mass_flow * given.get(s, 0.0) for s in gas_names])
        return flows, float(flame.inlet_temperature), float(flame.heat_release)
    mass = {}
    for name, x in p.composition:
        key = name if name in gas_names else "N2"
        mass[key] = mass.get(key, 0.0) + x * gas_molar_mass(name)
    total = sum(mass.values())
    flows = np.array([p.mass_flow * mass.get(s, 0.0) / total for s in gas_names])
    t_in = float(flame.inlet_temperature)
    if dissociation is not None and flame.burns_at_inlet and flame.dissociation is not dissociation:
        t_in = _inlet_temperature(flows, gas_names, p.adiabatic_temperature, dissociation)
    return flows, t_in, float(flame.heat_release)


def _inlet_temperature(flows, gas_names, t_frozen: float, dissociation) -> float:
    """Temperature (K) at which gas tables carrying ``dissociation`` hold the enthalpy of the
    frozen products ``flows`` (kg/s per ``gas_names``) at ``t_frozen``."""
    from rotarykiln.kiln.gas_mixture import GasMixture, temperature_of_enthalpy

    present = [i for i, q in enumerate(flows) if q > 0]
    names = tuple(gas_names[i] for i in present)
    q = np.asarray(flows, dtype=float)[present]
    target = float(GasMixture.of(names).species_enthalpy(np.array(t_frozen)) @ q)
    tables = GasMixture.of(names, None, dissociation)
    return temperature_of_enthalpy(tables, q, target, 200.0, t_frozen, 4001)


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
        self._last = None  # the last inputs evaluated: (segment, t, inputs)

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
        """The inputs at ``t`` (s) inside segment number ``segment`` (the last ones kept: an
        implicit step evaluates the right-hand side at one time several times)."""
        last = self._last
        if last is not None and last[0] == segment and last[1] == t:
            return last[2]
        ts, vals, mat = self._segment_knots(segment)
        if len(ts) == 2 and np.array_equal(mat[0], mat[1]):
            u = vals[0]
        else:
            v = np.array([np.interp(t, ts, mat[:, c]) for c in range(mat.shape[1])])
            nb, ng = len(self.bed_names), len(self.gas_names)
            u = BoundaryInputs(v[:nb], v[nb], v[nb + 1 : nb + 1 + ng], *v[nb + 1 + ng :])
        self._last = (segment, t, u)
        return u


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
