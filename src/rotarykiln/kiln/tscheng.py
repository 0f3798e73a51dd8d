"""Tscheng's (1978) hot-air pilot kiln, runs A11-A54: set-up from measured inputs and scoring.

Every run is built from its measured inputs only: air flow, speed, fill, solids feed, and the
inlet air temperature taken as the gas reading at 2.32 m (the data README). Kiln and sand data
are those of the README. The wall is not tabulated in the data; it is modelled as (inner to
outer) refractory cement 12.7 mm, carbon steel 6.35 mm [both assumed] and mineral-wool
insulation, absent on 1.02-1.22 m. The insulation thickness is the one that reproduces the
wall loss of the thesis sample calculation (run A16, z = 1.25 m: 154.4 W/m at T_w = 369.2 K,
measured between cement and shell) with ambient 298.15 K: it is derived from a published
number, not fitted to the 44 runs. See docs/validation.md.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd
from scipy.optimize import brentq

from rotarykiln.heat.wall import cylinder_layer_heat_flow, shell_heat_loss
from rotarykiln.kiln.inputs import Closures, Kiln, Wall
from rotarykiln.materials.gas import air_table
from rotarykiln.materials.lining import Layer, load_lining_material
from rotarykiln.materials.solids import load_solid
from rotarykiln.rtd.correlations import sherritt_dispersion

#: Dry air by mole, the gas of Tscheng's kiln.
AIR = "O2:0.2095, N2:0.7808, AR:0.0097"

__all__ = [
    "TSCHENG_LENGTH",
    "TSCHENG_RADIUS",
    "Z_GAS_BED",
    "Z_WALL",
    "WINDOW",
    "load_tscheng_runs",
    "tscheng_kiln",
    "insulation_thickness",
    "score_run",
    "validate_all",
]

TSCHENG_LENGTH = 2.44  # m
TSCHENG_RADIUS = 0.09425  # m
Z_GAS_BED = np.array([0.21, 0.72, 1.25, 1.78, 2.32])
Z_WALL = np.array([0.31, 0.91, 1.52, 2.13])
WINDOW = (1.25, 1.78)
AMBIENT = 298.15
CEMENT_THICKNESS = 0.0127  # m [assumed]
STEEL_THICKNESS = 0.00635  # m [assumed]
UNINSULATED = ((1.02, 1.22),)
SAMPLE_LOSS = 154.4  # W/m, thesis sample calculation A16 at 1.25 m
SAMPLE_T_WALL = 369.2  # K


def load_tscheng_runs() -> pd.DataFrame:
    """The 44 runs as a DataFrame indexed by run id (columns as in the CSV)."""
    import pandas as pd

    path = resources.files("rotarykiln") / "data" / "tscheng1978" / "tscheng_pilot_kiln_A11-A54.csv"
    with path.open("r", encoding="utf-8") as fh:
        df = pd.read_csv(fh)
    return df.set_index("Experiment ID")


@lru_cache(maxsize=1)
def insulation_thickness() -> float:
    """Mineral-wool thickness (m) giving the thesis sample-calculation loss at z = 1.25 m.

    Examples
    --------
    >>> round(insulation_thickness() * 1000, 1)  # mm
    13.8
    """
    steel = load_lining_material("carbon_steel")
    wool = load_lining_material("mineral_wool")
    air = air_table()
    r1 = TSCHENG_RADIUS + CEMENT_THICKNESS
    r2 = r1 + STEEL_THICKNESS

    def loss_error(t_ins):
        r3 = r2 + t_ins

        def shell_balance(ts):
            # temperature at the steel/wool interface from the steel layer with q = SAMPLE_LOSS
            ti = brentq(
                lambda t: float(
                    cylinder_layer_heat_flow(
                        wool.conductivity_integral(t), wool.conductivity_integral(ts), r2, r3
                    )
                    - shell_heat_loss(ts, AMBIENT, 2 * r3, wool.emissivity, air)
                ),
                ts,
                2000.0,
            )
            return ti

        # find the shell temperature for which the steel inner face sits at SAMPLE_T_WALL
        def steel_inner(ts):
            ti = shell_balance(ts)
            q = float(shell_heat_loss(ts, AMBIENT, 2 * r3, wool.emissivity, air))
            k_avg = float(steel.conductivity(ti))
            return ti + q * np.log(r2 / r1) / (2 * np.pi * k_avg) - SAMPLE_T_WALL

        ts = brentq(steel_inner, AMBIENT + 1e-6, SAMPLE_T_WALL)
        return float(shell_heat_loss(ts, AMBIENT, 2 * r3, wool.emissivity, air)) - SAMPLE_LOSS

    return float(brentq(loss_error, 1e-4, 0.2))


def _layers() -> tuple[Layer, ...]:
    return (
        Layer(load_lining_material("refractory_cement"), CEMENT_THICKNESS),
        Layer(load_lining_material("carbon_steel"), STEEL_THICKNESS),
        Layer(load_lining_material("mineral_wool"), insulation_thickness(), absent=UNINSULATED),
    )


def tscheng_kiln(run: str, closures: Closures | None = None, **overrides) -> Kiln:
    """The :class:`~rotarykiln.kiln.inputs.kiln.Kiln` of Tscheng's run ``run`` (e.g. ``"A16"``) from its measured inputs.

    Examples
    --------
    >>> k = tscheng_kiln("A16")
    >>> round(k.gas.temperature, 1), round(k.feed_flow * 3600, 1)
    (535.0, 14.2)
    """
    from rotarykiln.errors import InputError

    runs = load_tscheng_runs()
    if run not in runs.index:
        raise InputError("tscheng.run", run, "one of A11 ... A54")
    r = runs.loc[run]
    t_gas = r[[f"T-g-{i}" for i in range(1, 6)]].to_numpy(dtype=float)
    t_bed = r[[f"T-s-{i}" for i in range(1, 6)]].to_numpy(dtype=float)
    t_wall = r[[f"T-w-{i}" for i in range(1, 5)]].to_numpy(dtype=float)
    kw = dict(
        length=TSCHENG_LENGTH,
        radius=TSCHENG_RADIUS,
        omega=float(r["RPM"]) * 2 * np.pi / 60.0,
        fill=float(r["Solid loading (%)"]) / 100.0,
        solid=load_solid("sand"),
        solids_flow=float(r["Solid flow (kg/hr)"]) / 3600.0,
        solids_inlet_temperature=AMBIENT,
        gas_composition=AIR,
        gas_flow=float(r["Air flow (kg/hr)"]) / 3600.0,
        gas_inlet_temperature=float(t_gas[-1]),
        wall=Wall(layers=_layers(), ambient_temperature=AMBIENT),
        counter_current=True,
        closures=closures or Closures(),
        measurements={
            "z_gas": Z_GAS_BED,
            "t_gas": t_gas,
            "z_bed": Z_GAS_BED,
            "t_bed": t_bed,
            "z_wall": Z_WALL,
            "t_wall": t_wall,
            "wall_interface": 1,
        },
        name=f"Tscheng 1978 run {run}",
    )
    kw.update(overrides)
    kiln = Kiln.inert(**kw)
    if "bed_dispersion" in overrides:
        return kiln
    # the bed's axial dispersion of Sherritt et al. (2003), as heat: cases take by default
    d = sherritt_dispersion(
        kiln.drum.omega, 2.0 * kiln.drum.radius, kiln.bed.particle_diameter, kiln.mean_fill
    )
    return kiln.replace(bed__dispersion=float(d))


@dataclass(frozen=True)
class RunScore:
    """RMSE (K) of one run: bed and gas in the 1.25-1.78 m window and over the whole length."""

    run: str
    bed_window: float
    gas_window: float
    bed_all: float
    gas_all: float
    wall_all: float
    closure: float
    iterations: int


def _rmse(a, b) -> float:
    return float(np.sqrt(np.mean((np.asarray(a) - np.asarray(b)) ** 2)))


def score_run(run: str, solution) -> RunScore:
    """Compare a solution with the measurements of ``run``."""
    m = solution.measurements
    zb = m["z_bed"]
    win = (zb >= WINDOW[0] - 1e-9) & (zb <= WINDOW[1] + 1e-9)
    tb = solution.bed_temperature_at(zb)
    tg = solution.gas_temperature_at(zb)
    tw = solution.wall_temperature_at(m["z_wall"], interface=m.get("wall_interface", 0))
    return RunScore(
        run=run,
        bed_window=_rmse(tb[win], m["t_bed"][win]),
        gas_window=_rmse(tg[win], m["t_gas"][win]),
        bed_all=_rmse(tb, m["t_bed"]),
        gas_all=_rmse(tg, m["t_gas"]),
        wall_all=_rmse(tw, m["t_wall"]),
        closure=solution.energy_closure,
        iterations=solution.iterations,
    )


def validate_all(closures: Closures | None = None, n_cells: int = 100) -> pd.DataFrame:
    """Solve all 44 runs and score them: one row per run, RMSE in K."""
    import pandas as pd

    from rotarykiln.kiln.steady.solve import solve_kiln

    rows = []
    for run in load_tscheng_runs().index:
        sol = solve_kiln(tscheng_kiln(run, closures), n_cells)
        rows.append(score_run(run, sol).__dict__)
    return pd.DataFrame(rows).set_index("run")
