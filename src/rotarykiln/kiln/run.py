"""Run the steady heat model from a validated case file (``heat:`` section).

:func:`heat_kiln_from_case` builds a :class:`HeatKiln` from a :class:`rotarykiln.case.Case`;
:func:`run_heat_case` solves it; :func:`heat_runner` is the ``rotarykiln run`` section runner
(writes ``heat_profiles.csv``, ``heat_summary.json`` and ``heat_profiles.png``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.kiln.coupling import bed_fill_profile
from rotarykiln.kiln.model import Closures, HeatKiln
from rotarykiln.kiln.run_files import write_solution_files
from rotarykiln.kiln.solution import KilnSolution
from rotarykiln.kiln.solve import solve_heat
from rotarykiln.kiln.wall import layers_from_case
from rotarykiln.materials.gas import burn_fuel, gas_table
from rotarykiln.materials.solids import load_solid

__all__ = [
    "FlameProfile",
    "bed_fill_profile",
    "heat_kiln_from_case",
    "run_heat_case",
    "heat_runner",
    "flame_profile",
]


@dataclass(frozen=True)
class FlameProfile:
    """Parabolic heat-release weight :math:`s(\\ell - s)` over the flame (picklable).

    ``start`` and ``flame_length`` (m) are measured from the gas inlet (the burner end).
    """

    length: float
    start: float
    flame_length: float
    counter_current: bool

    def __call__(self, z):
        z = np.asarray(z, dtype=float)
        dist = (self.length - z) if self.counter_current else z
        s = dist - self.start
        return np.where((s > 0) & (s < self.flame_length), s * (self.flame_length - s), 0.0)


def flame_profile(length: float, start: float, flame_length: float, counter_current: bool):
    """Parabolic heat-release profile :math:`s(\\ell - s)` over the flame, s from its start.

    ``start`` and ``flame_length`` are measured from the gas inlet (the burner end), m.

    Examples
    --------
    >>> w = flame_profile(5.0, 0.0, 1.0, True)
    >>> [round(float(v), 3) for v in w(np.array([4.5, 3.0]))]
    [0.25, 0.0]
    """
    return FlameProfile(length, start, flame_length, counter_current)


def heat_kiln_from_case(case) -> tuple[HeatKiln, int]:
    """The :class:`HeatKiln` and cell count of a case with a ``heat`` section."""
    h = case.heat
    if h is None:
        raise InputError("heat", None, "present (the case has no heat: section)")
    if case.operation.feed is None or case.operation.feed <= 0:
        raise InputError("operation.feed", case.operation.feed, "> 0 kg/s for the heat model")
    overrides = {}
    m = case.material
    if m.bulk_density is not None:
        overrides["bulk_density"] = m.bulk_density
    if m.particle_size is not None:
        overrides["particle_diameter"] = m.particle_size
    solid = load_solid(h.solid, **overrides)
    if h.fill is not None:
        fill = np.asarray(h.fill, dtype=float) if isinstance(h.fill, list) else float(h.fill)
    elif case.transport is not None:
        fill = bed_fill_profile(case)
    elif case.bed is not None:
        fill = case.bed.fill
    else:
        raise InputError(
            "heat.fill", None, "given (or a transport: section, or a bed: section with fill)"
        )
    layers = layers_from_case(h.lining, "heat")
    length = case.kiln.length
    kw = {}
    if h.burner is not None:
        b = h.burner
        burnt = burn_fuel(b.fuel, b.fuel_flow, b.air_flow, b.temperature, b.temperature)
        if b.flame_start + b.flame_length > length:
            raise InputError(
                "heat.burner.flame_length", b.flame_length, "inside the kiln (start + length <= L)"
            )
        kw.update(
            gas=burnt.table,
            gas_flow=burnt.mass_flow,
            gas_inlet_temperature=burnt.inlet_temperature,
            heat_release=burnt.heat_release,
            heat_release_profile=flame_profile(
                length, b.flame_start, b.flame_length, h.counter_current
            ),
        )
    else:
        if h.gas.flow is None or h.gas.inlet_temperature is None:
            raise InputError("heat.gas.flow", h.gas.flow, "given with heat.gas.inlet_temperature")
        kw.update(
            gas=gas_table(h.gas.composition),
            gas_flow=h.gas.flow,
            gas_inlet_temperature=h.gas.inlet_temperature,
        )
    c = h.closures
    meas = None
    if h.measurements is not None:
        meas = {k: np.asarray(v, dtype=float) for k, v in h.measurements.model_dump().items()}
        meas["wall_interface"] = int(h.measurements.wall_interface)
    kiln = HeatKiln(
        length=length,
        radius=case.kiln.diameter / 2.0,
        omega=case.operation.speed,
        fill=fill,
        solid=solid,
        solids_flow=case.operation.feed,
        solids_inlet_temperature=h.solid_inlet_temperature,
        layers=layers,
        counter_current=h.counter_current,
        wall_emissivity=h.wall_emissivity,
        shell_emissivity=h.shell_emissivity,
        ambient_temperature=h.ambient_temperature,
        wind_speed=h.wind_speed,
        closures=Closures.from_case(c),
        measurements=meas,
        name=case.name,
        **kw,
    )
    return kiln, int(h.cells)


def run_heat_case(case) -> KilnSolution:
    """Solve the steady heat model of a validated case (with a ``heat:`` section).

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> sol = run_heat_case(load_case(builtin_case_path("heat/tscheng_A16")))
    >>> abs(sol.balance_closure) < 1e-6
    True
    """
    kiln, cells = heat_kiln_from_case(case)
    return solve_heat(kiln, cells)


def heat_runner(case, out: Path) -> dict:
    """``rotarykiln run`` section runner: solve, write profiles/summary/figure, return summary.

    A case that also has a ``chemistry:`` section is solved by the reacting kiln
    (:func:`rotarykiln.kiln.reacting.reacting_runner`) instead: this runner then does nothing.
    """
    if getattr(case, "chemistry", None) is not None:
        return {}
    return write_solution_files(run_heat_case(case), out, "heat", dpi=110)
