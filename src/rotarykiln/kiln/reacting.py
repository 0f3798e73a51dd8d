"""Run the reacting kiln from a case file (``chemistry:`` section) and from sweep dicts.

:func:`reacting_kiln_from_case` builds a :class:`Kiln` from a validated
:class:`rotarykiln.case.Case`; :func:`run_reacting_case` solves it; :func:`reacting_runner` is the
``rotarykiln run`` section runner (profiles CSV, summary JSON, figures, residence-time effects);
:func:`reacting_sweep_model` is the picklable model function for
:func:`rotarykiln.studies.run_sweep` (case dict in, scalars out).
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.chemistry.reaction import builtin_reactions, reaction_from_dict
from rotarykiln.chemistry.species import default_species
from rotarykiln.errors import InputError
from rotarykiln.kiln.model import SEED004_CLOSURES, Closures, Kiln
from rotarykiln.kiln.solution import KilnSolution
from rotarykiln.kiln.solve import solve_kiln
from rotarykiln.kiln.wall import HeaterZone, layers_from_case

__all__ = [
    "mechanism_from_case",
    "reacting_kiln_from_case",
    "run_reacting_case",
    "reacting_runner",
    "reacting_sweep_model",
]


def mechanism_from_case(chem) -> Mechanism:
    """The :class:`Mechanism` of a ``chemistry`` section (built-in names or user mappings).

    Reactions with a sharp onset temperature (``width`` 0) get ``chemistry.onset_width``.
    """
    sp = default_species()
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


def _library_solid(name: str):
    from rotarykiln.materials.solids import load_solid

    try:
        return load_solid(name)
    except InputError:
        return None


def reacting_kiln_from_case(case) -> tuple[Kiln, int]:
    """The :class:`Kiln` and cell count of a case with a ``chemistry`` section."""
    ch = case.chemistry
    if ch is None:
        raise InputError("chemistry", None, "present (the case has no chemistry: section)")
    if ch.gas_gain_per_carbon != "corrected":
        raise InputError(
            "chemistry.gas_gain_per_carbon",
            ch.gas_gain_per_carbon,
            "corrected (seed 004's 30/12 gas gain creates mass and breaks the element balance)",
        )
    feed = case.operation.feed
    if feed is None or feed <= 0:
        raise InputError("operation.feed", feed, "> 0 kg/s for the reacting kiln")
    g = ch.gas
    flame = None
    if ch.burner is not None:
        if g.inlet_flow is not None or g.inlet_temperature is not None or g.composition:
            raise InputError(
                "chemistry.gas.inlet_flow",
                g.inlet_flow,
                "absent with a chemistry.burner (the burner makes the inlet gas)",
            )
        flame, gas_in, t_gas_in = _burner_gas(ch.burner, case.kiln)
    elif g.inlet_flow is None or g.inlet_flow <= 0 or g.inlet_temperature is None:
        raise InputError(
            "chemistry.gas.inlet_flow",
            g.inlet_flow,
            "> 0 kg/s, with chemistry.gas.inlet_temperature",
        )
    if flame is None:
        if g.composition is None:
            raise InputError("chemistry.gas.composition", None, "given (gas mass fractions)")
        gas_in = {n: w * g.inlet_flow for n, w in g.composition.items()}
        t_gas_in = g.inlet_temperature
    lib = _library_solid(case.material.name)
    m = case.material
    rho = m.bulk_density or (lib.bulk_density if lib else None)
    if rho is None:
        raise InputError("material.bulk_density", None, "given (or a library material name)")
    length, radius = case.kiln.length, case.kiln.diameter / 2.0
    bed_depth = None
    if case.transport is not None:
        bed_depth, fill, velocity = _kramers_bed(case, rho)
    elif ch.residence_time is not None:
        velocity = length / ch.residence_time
        fill = feed * ch.residence_time / length / rho / (math.pi * radius**2)
    elif case.bed is not None:
        fill = case.bed.fill
        velocity = feed / (rho * fill * math.pi * radius**2)
    else:
        raise InputError(
            "chemistry.residence_time", None, "given (or a bed: section with the fill)"
        )
    if not 0 < fill <= 0.5:
        raise InputError(
            "chemistry.residence_time", ch.residence_time, f"a fill <= 0.5 (got {fill:.3g})"
        )
    s = ch.solid
    cp = s.specific_heat
    bed_cp = {}
    if cp is not None:
        bed_cp = {n: cp for n in default_species().bed_names if n != "H2O(l)"}
    kb = s.thermal_conductivity or (lib.bed_conductivity if lib else None) or 0.3
    eps_b = s.emissivity if s.emissivity is not None else (lib.emissivity if lib else 0.9)
    dp = m.particle_size or (lib.particle_diameter if lib else 5e-3)
    law = None
    if g.emissivity_a is not None:
        law = (g.emissivity_a, g.emissivity_b_per_K or 0.0, g.emissivity_minimum or 0.0)
    closures = SEED004_CLOSURES if ch.closures is None else Closures.from_case(ch.closures)
    wall = _wall_from_case(ch)
    kiln = Kiln(
        length=length,
        radius=radius,
        omega=case.operation.speed,
        fill=fill,
        bed_velocity=velocity,
        feed={n: w * feed for n, w in ch.feed.composition.items()},
        feed_temperature=ch.feed.temperature,
        bed_cp=bed_cp,
        bulk_density=rho,
        bed_conductivity=kb,
        bed_emissivity=eps_b,
        particle_diameter=dp,
        gas_in=gas_in,
        gas_inlet_temperature=t_gas_in,
        mechanism=mechanism_from_case(ch),
        wall_emissivity=ch.wall_emissivity,
        pressure=g.pressure,
        gas_emissivity_law=law,
        steam_flow=g.steam_flow,
        closures=closures,
        name=case.name,
        counter_current=ch.counter_current,
        heaters=tuple(HeaterZone(z.start, z.end, z.power, z.shell_temperature) for z in ch.heaters),
        bed_depth=bed_depth,
        flame=flame,
        **wall,
    )
    dispersion = _bed_dispersion(ch.axial_dispersion, kiln)
    return dataclasses.replace(kiln, bed_dispersion=dispersion), int(ch.cells)


def _bed_dispersion(choice, kiln) -> float:
    """Axial dispersion coefficient of the bed (m2/s) of ``chemistry.axial_dispersion``:
    ``plug`` (default: seed 004's plug flow, the RTD as post-processing), ``sherritt2003``, or
    a bed Peclet number u L / D."""
    from rotarykiln.rtd.correlations import sherritt_dispersion

    if choice == "plug":
        return 0.0
    if choice == "sherritt2003":
        d = sherritt_dispersion(
            kiln.omega, 2.0 * kiln.radius, kiln.particle_diameter, kiln.mean_fill
        )
        return float(d)
    return kiln.bed_velocity * kiln.length / float(choice)


def _kramers_bed(case, density):
    """The :class:`KramersBed` of a ``transport:`` section, and the fill and solids speed of
    its constant-flow profile (the solve's starting point)."""
    from rotarykiln.kiln.bed_depth import KramersBed
    from rotarykiln.kiln.coupling import bed_profile_from_case

    t = case.transport
    if t.model != "kramers" or t.weirs:
        raise InputError(
            "transport.model",
            t.model if t.model != "kramers" else "kramers with weirs",
            "kramers without weirs (the bed depth solved inside the reacting kiln)",
        )
    if t.dam_height is None:
        raise InputError(
            "transport.dam_height", None, "given (> 0) for the reacting kiln's bed depth"
        )
    if case.material.repose_angle is None:
        raise InputError("material.repose_angle", None, "given with a transport: section")
    bed = KramersBed(
        case.kiln.diameter / 2.0,
        case.operation.speed,
        case.kiln.slope,
        case.material.repose_angle,
        density,
        t.dam_height,
    )
    profile = bed_profile_from_case(case)
    fill = float(np.mean(profile.fill))
    velocity = case.kiln.length / float(profile.mean_residence_time)
    return bed, fill, velocity


def _burner_gas(section, kiln_section):
    """Flame, inlet gas species flows (kg/s) and temperature (K) of a ``chemistry.burner``.

    Instant burn-out: the products of complete combustion at their adiabatic temperature.
    Product species the reacting kiln does not carry (traces of NO, OH ...) are counted
    as N2, by mass (their sum is reported by the flame's products; below 0.1 % for
    natural gas with air).
    """
    from rotarykiln.kiln.flame import fire
    from rotarykiln.kiln.run import burner_from_case
    from rotarykiln.materials.gas import molar_mass

    if section.combustion != "instant":
        raise InputError(
            "chemistry.burner.combustion",
            section.combustion,
            "instant (the reacting kiln takes the burner's products at the burner)",
        )
    flame = fire(burner_from_case(section), kiln_section.diameter, kiln_section.length)
    p = flame.products
    known = set(default_species().gas_names)
    mass = {name: x * molar_mass(f"{name}:1") for name, x in p.composition}
    total = sum(mass.values())
    flows: dict[str, float] = {}
    for name, m in mass.items():
        key = name if name in known else "N2"
        flows[key] = flows.get(key, 0.0) + p.mass_flow * m / total
    return flame, flows, p.adiabatic_temperature


def _wall_from_case(ch) -> dict:
    """Wall inputs of :class:`Kiln` from a ``chemistry`` section.

    ``wall: wall_u`` (the default without a ``lining``): one wall temperature, U and ambient
    from ``wall_loss`` (default 5 W/(m2 K), 298.15 K). ``wall: lining`` (the default with a
    ``lining``): the heat model's lined wall, ambient from ``ambient_temperature`` (or
    ``wall_loss.ambient_temperature``), ``wind_speed``, ``shell_emissivity``.
    """
    wl = ch.wall_loss
    ambient = ch.ambient_temperature
    if wl is not None and ambient is not None and wl.ambient_temperature != ambient:
        raise InputError(
            "chemistry.ambient_temperature",
            ambient,
            f"the same as chemistry.wall_loss.ambient_temperature ({wl.ambient_temperature} K)",
        )
    if ambient is None:
        ambient = wl.ambient_temperature if wl is not None else 298.15
    kind = ch.wall or ("lining" if ch.lining is not None else "wall_u")
    out = {"ambient_temperature": ambient}
    if kind == "wall_u":
        out["wall_loss_u"] = wl.U if wl is not None else 5.0
        return out
    out.update(
        layers=layers_from_case(ch.lining, "chemistry"),
        wind_speed=ch.wind_speed,
        shell_emissivity=ch.shell_emissivity,
    )
    return out


def run_reacting_case(case, n_cells: int | None = None) -> KilnSolution:
    """Solve the reacting kiln of a validated case (with a ``chemistry:`` section).

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> sol = run_reacting_case(load_case(builtin_case_path("limestone_calcination")))
    >>> round(sol.summary()["conversion_CaCO3"], 4)
    1.0
    >>> abs(sol.energy_closure) < 1e-6, max(sol.element_closure.values()) < 1e-8
    (True, True)
    """
    kiln, cells = reacting_kiln_from_case(case)
    return solve_kiln(kiln, n_cells or cells)


def reacting_runner(case, out: Path) -> dict:
    """``rotarykiln run`` runner: solve, write profiles/summary/figures, RTD effects."""
    import matplotlib.pyplot as plt

    from rotarykiln.kiln.residence import residence_time_effects
    from rotarykiln.kiln.run_files import write_solution_files
    from rotarykiln.outputs import save_figure_atomic

    kiln, cells = reacting_kiln_from_case(case)
    sol = solve_kiln(kiln, cells)
    out = Path(out)
    rtd = residence_time_effects(case, kiln, sol)
    summary = write_solution_files(sol, out, "reacting", extra=rtd.summary(), dpi=100)
    ax = rtd.plot()
    save_figure_atomic(out / "reacting_rtd.png", ax.figure, dpi=100)
    plt.close(ax.figure)
    return summary


def reacting_sweep_model(case: dict) -> dict:
    """Model function for :func:`rotarykiln.studies.run_sweep`: case dict -> scalar outputs.

    Returns burn-off and production (% dry basis), the conversion of each reacting bed species,
    outlet temperatures, balances and the Newton iterations.
    """
    from rotarykiln.case import parse_case

    sol = run_reacting_case(parse_case(case))
    s = sol.summary()
    keep = {k: v for k, v in s.items() if k != "name" and isinstance(v, int | float)}
    return {k: v for k, v in keep.items() if not (isinstance(v, float) and math.isnan(v))}
