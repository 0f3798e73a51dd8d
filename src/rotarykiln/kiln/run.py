"""Run the steady heat model from a validated case file (``heat:`` section).

:func:`heat_kiln_from_case` builds the :class:`~rotarykiln.kiln.model.Kiln` of a bed that
does not react (:meth:`~rotarykiln.kiln.model.Kiln.inert`) from a :class:`rotarykiln.case.Case`;
:func:`run_heat_case` solves it; :func:`heat_runner` is the ``rotarykiln run`` section runner
(writes ``heat_profiles.csv``, ``heat_summary.json`` and ``heat_profiles.png``).
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from rotarykiln.errors import InputError
from rotarykiln.kiln.coupling import bed_fill_profile
from rotarykiln.kiln.flame import AirStream, Burner, fire
from rotarykiln.kiln.model import Closures, Kiln
from rotarykiln.kiln.run_files import write_solution_files
from rotarykiln.kiln.solution import KilnSolution
from rotarykiln.kiln.solve import solve_kiln
from rotarykiln.kiln.wall import HeaterZone, layers_from_case
from rotarykiln.materials.solids import load_solid

__all__ = [
    "bed_fill_profile",
    "burner_from_case",
    "heat_kiln_from_case",
    "run_heat_case",
    "heat_runner",
]


def burner_from_case(section) -> Burner:
    """The :class:`~rotarykiln.kiln.flame.Burner` of a case file's ``burner`` section.

    Examples
    --------
    >>> from rotarykiln.case import Burner as BurnerSection
    >>> b = burner_from_case(BurnerSection(fuel="CH4:1", fuel_flow="2 kg/h",
    ...                                    primary_air={"flow": "40 kg/h"}))
    >>> round(b.fuel_flow * 3600, 6), round(b.air_flow * 3600, 6)
    (2.0, 40.0)
    """
    fuel, primary, secondary = section.mass_flows()
    t_p = section.primary_air.temperature if section.primary_air is not None else 298.15
    t_s = section.secondary_air.temperature if section.secondary_air is not None else 298.15
    return Burner(
        fuel=section.fuel,
        fuel_flow=fuel,
        primary_air=AirStream(primary, t_p),
        secondary_air=AirStream(secondary, t_s),
        fuel_temperature=section.fuel_temperature,
        nozzle_diameter=section.nozzle_diameter,
        combustion=section.combustion,
        flame_length=section.flame_length,
    )


def heat_kiln_from_case(case) -> tuple[Kiln, int]:
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
        if h.burner.flame_length is not None and h.burner.flame_length > length:
            raise InputError(
                "heat.burner.flame_length",
                f"{h.burner.flame_length:.6g} m",
                f"<= the kiln length ({length:.6g} m)",
            )
        flame = fire(burner_from_case(h.burner), case.kiln.diameter, length)
        kw.update(
            gas_composition=flame.products.composition,
            gas_flow=flame.products.mass_flow,
            gas_inlet_temperature=flame.inlet_temperature,
            heat_release=flame.heat_release,
            heat_release_profile=flame.release_profile(length, h.counter_current),
            flame=flame,
        )
    else:
        if h.gas.flow is None or h.gas.inlet_temperature is None:
            raise InputError("heat.gas.flow", h.gas.flow, "given with heat.gas.inlet_temperature")
        kw.update(
            gas_composition=h.gas.composition,
            gas_flow=h.gas.flow,
            gas_inlet_temperature=h.gas.inlet_temperature,
        )
    c = h.closures
    meas = None
    if h.measurements is not None:
        meas = {k: np.asarray(v, dtype=float) for k, v in h.measurements.model_dump().items()}
        meas["wall_interface"] = int(h.measurements.wall_interface)
    kiln = Kiln.inert(
        length=length,
        radius=case.kiln.diameter / 2.0,
        omega=case.operation.speed,
        fill=fill,
        solid=solid,
        solids_flow=case.operation.feed,
        pressure=101325.0,
        solids_inlet_temperature=h.solid_inlet_temperature,
        layers=layers,
        counter_current=h.counter_current,
        wall_emissivity=h.wall_emissivity,
        shell_emissivity=h.shell_emissivity,
        ambient_temperature=h.ambient_temperature,
        wind_speed=h.wind_speed,
        closures=Closures.from_case(c),
        heaters=tuple(HeaterZone(z.start, z.end, z.power, z.shell_temperature) for z in h.heaters),
        measurements=meas,
        name=case.name,
        **kw,
    )
    return dataclasses.replace(kiln, bed_dispersion=_bed_dispersion(case, kiln)), int(h.cells)


def _bed_dispersion(case, kiln) -> float:
    """Axial dispersion coefficient of the bed (m2/s) of ``heat.axial_dispersion``."""
    from rotarykiln.rtd.correlations import sherritt_dispersion

    choice = case.heat.axial_dispersion
    if choice == "plug":
        return 0.0
    if choice == "sherritt2003":
        dp = kiln.particle_diameter
        return float(sherritt_dispersion(kiln.omega, 2.0 * kiln.radius, dp, kiln.mean_fill))
    return kiln.bed_velocity * kiln.length / float(choice)  # a given Peclet number


def run_heat_case(case) -> KilnSolution:
    """Solve the steady heat model of a validated case (with a ``heat:`` section).

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> sol = run_heat_case(load_case(builtin_case_path("tscheng_A16")))
    >>> abs(sol.energy_closure) < 1e-6
    True
    """
    kiln, cells = heat_kiln_from_case(case)
    return solve_kiln(kiln, cells)


def heat_runner(case, out: Path) -> dict:
    """``rotarykiln run`` section runner: solve, write profiles/summary/figure, return summary.

    A case that also has a ``chemistry:`` section is solved by the reacting kiln
    (:func:`rotarykiln.kiln.reacting.reacting_runner`) instead: this runner then does nothing.
    """
    if getattr(case, "chemistry", None) is not None:
        return {}
    return write_solution_files(run_heat_case(case), out, "heat", dpi=110)
