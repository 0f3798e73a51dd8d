"""Retort zone of the AOSTRA-Taciuk Processor: shale heated by hot recycled ash (ch. 9).

Builds the two granular materials of a Table 9.2 case (size distributions, densities, initial
temperatures, thermochemistry), the CV grid of the drum, and runs the grid simulation with
heating and pyrolysis.

Reconstructions (see docs/transverse.md): the fill is 30 % (from V_AL = 7.01 m/s of case 2);
the shale:ash ratio is on a mass basis; multi-size feeds are the Table 4.1 distributions with
their class weights tilted exponentially in size until the volume-mean size equals the case's
mean (the thesis's "mixture of the experimental particle sizes" is not reproducible); cases whose
two sizes are equal are taken as single-size feeds.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from rotarykiln.errors import InputError, check_positive, warn_out_of_range
from rotarykiln.transverse.data import load_table
from rotarykiln.transverse.grid import GridMaterial, GridResult, HeatingOptions, simulate_grid
from rotarykiln.transverse.grid_geometry import build_grid
from rotarykiln.transverse.pyrolysis import berkovich_shale, sensible_solid

__all__ = [
    "SIZE_CLASSES",
    "RetortSpec",
    "retort_case",
    "run_retort",
    "tilted_distribution",
]

#: Class mean sizes of Table 4.1 (m), the +6.30 mm fraction (0.1 %) folded into 5.08.
SIZE_CLASSES = np.array([0.30, 0.82, 1.22, 1.70, 2.51, 3.44, 5.08]) * 1e-3


def _table_4_1(material: str) -> np.ndarray:
    t = load_table("particle_size_distribution")
    col = "shale_retained_percent" if material == "shale" else "ash_retained_percent"
    w = t[col].to_numpy()
    # rows: 6.30, 5.08, 3.44, 2.51, 1.70, 1.22, 0.82, 0.30 -> ascending classes of SIZE_CLASSES
    return np.array([w[7], w[6], w[5], w[4], w[3], w[2], w[1] + w[0]])


def tilted_distribution(mean_size: float, material: str = "shale") -> np.ndarray:
    r"""Table 4.1 class fractions tilted by :math:`e^{\lambda d}` to a given mean size.

    Parameters
    ----------
    mean_size : float, m
        Target (mass = volume weighted) mean size, within the class range.
    material : {"shale", "ash"}
        Which Table 4.1 column to start from (shale mean 1.47 mm, ash 2.00 mm).

    Returns
    -------
    array (7,), -
        Fractions over :data:`SIZE_CLASSES`.

    Examples
    --------
    >>> w = tilted_distribution(1.54e-3, "shale")
    >>> round(float(w @ SIZE_CLASSES) * 1e3, 4)
    1.54

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, Table 4.1.
    """
    check_positive("mean_size", mean_size, "m")
    base = _table_4_1(material)
    base = base / base.sum()
    d = SIZE_CLASSES
    if not d[0] < mean_size < d[-1]:
        raise InputError("mean_size", mean_size, f"in ({d[0]:g}, {d[-1]:g}) m for a tilted feed")

    def weights(lam):
        w = base * np.exp(lam * (d - d.mean()))
        return w / w.sum()

    lam = brentq(lambda x: weights(x) @ d - mean_size, -1e4, 1e4, xtol=1e-12)
    return weights(lam)


@dataclass(frozen=True)
class RetortSpec:
    """One retort-zone case (SI units)."""

    name: str = "case 2"
    drum_diameter: float = 6.0
    omega: float = 5 * 2 * np.pi / 60
    fill: float = 0.30
    shale_size: float = 1.54e-3
    ash_size: float = 2.11e-3
    shale_temperature: float = 548.0
    ash_temperature: float = 1048.0
    shale_to_ash: float = 0.32
    duration: float = 220.0
    distribution: str = "auto"  # "auto": single size when both sizes are equal, else tilted
    shale_bulk_density: float = 700.0
    ash_bulk_density: float = 780.0
    voidage: float = 0.5
    shale_cp: float = 1150.0
    ash_cp: float = 1000.0
    emissivity: float = 0.9
    balance: str = "pairwise"
    layers: int = 5
    zones: int = 20
    segregation: bool = True
    snapshot_times: tuple[float, ...] = (5.0, 10.0, 20.0, 40.0, 60.0, 220.0)


def retort_case(number: int, **overrides) -> RetortSpec:
    """The Table 9.2 case ``number`` (1-16) as a :class:`RetortSpec`.

    Examples
    --------
    >>> retort_case(8).ash_temperature
    1198.0
    """
    t = load_table("retort_cases").set_index("case")
    if number not in t.index:
        raise InputError("case", number, "one of 1-16 (Table 9.2)")
    row = t.loc[number]
    spec = dict(
        name=f"case {number}",
        shale_size=row.shale_size_mm * 1e-3,
        ash_size=row.ash_size_mm * 1e-3,
        shale_temperature=float(row.shale_T_K),
        ash_temperature=float(row.ash_T_K),
        shale_to_ash=float(row.shale_to_ash),
        omega=row.speed_rpm * 2 * np.pi / 60,
    )
    spec.update(overrides)
    return RetortSpec(**spec)


def _feed(size: float, material: str, distribution: str, equal: bool):
    if distribution == "single" or (distribution == "auto" and equal):
        return np.array([size]), np.array([1.0])
    if distribution in ("auto", "table4.1"):
        return SIZE_CLASSES, tilted_distribution(size, material)
    raise InputError("distribution", distribution, "one of 'auto', 'single', 'table4.1'")


def run_retort(spec: RetortSpec) -> GridResult:
    """Run one retort-zone case: grid simulation with mixing, segregation, heating, pyrolysis.

    Warns (OutOfRangeWarning) when the drum speed lies outside the rolling regime
    (0.10-0.55 of the critical speed, Henein) or sizes exceed the mixing model's limiting size.

    Parameters
    ----------
    spec : RetortSpec

    Returns
    -------
    GridResult
        Material 0 is the ash, material 1 the shale.

    Examples
    --------
    >>> r = run_retort(retort_case(2, duration=10.0, snapshot_times=()))
    >>> bool(r.mass_error < 1e-12 and r.energy_error < 1e-9)
    True
    """
    check_positive("shale_to_ash", spec.shale_to_ash)
    check_positive("drum_diameter", spec.drum_diameter, "m")
    check_positive("omega", spec.omega, "rad/s")
    radius = 0.5 * spec.drum_diameter
    d_lim = 6.62e-3
    for what, size in (("shale_size", spec.shale_size), ("ash_size", spec.ash_size)):
        check_positive(what, size, "m")
        if size > d_lim:
            warn_out_of_range(
                f"{what} [m] (beyond the limiting size: no mixing)",
                size,
                0,
                d_lim,
                "Van Puyvelde eq 6.8",
            )
    equal = abs(spec.shale_size - spec.ash_size) < 1e-9
    d_sh, w_sh = _feed(spec.shale_size, "shale", spec.distribution, equal)
    d_as, w_as = _feed(spec.ash_size, "ash", spec.distribution, equal)
    sizes = np.union1d(d_sh, d_as)
    f_sh = np.array([w_sh[d_sh == s].sum() for s in sizes])
    f_as = np.array([w_as[d_as == s].sum() for s in sizes])
    v_sh = spec.shale_to_ash / spec.shale_bulk_density
    v_as = 1.0 / spec.ash_bulk_density
    ash = GridMaterial(
        "ash",
        v_as,
        f_as,
        spec.ash_bulk_density,
        spec.ash_bulk_density / (1 - spec.voidage),
        spec.ash_temperature,
        sensible_solid("ash", spec.ash_cp),
    )
    shale = GridMaterial(
        "shale",
        v_sh,
        f_sh,
        spec.shale_bulk_density,
        spec.shale_bulk_density / (1 - spec.voidage),
        spec.shale_temperature,
        berkovich_shale(spec.shale_cp),
    )
    geom = build_grid(radius, spec.omega, spec.fill, layers=spec.layers, zones=spec.zones)
    result = simulate_grid(
        geom,
        sizes,
        (ash, shale),
        duration=spec.duration,
        initial="layer",
        segregation=spec.segregation,
        heating=HeatingOptions(emissivity=spec.emissivity, balance=spec.balance),
        snapshot_times=spec.snapshot_times,
    )
    return dataclasses.replace(result, name=spec.name)
