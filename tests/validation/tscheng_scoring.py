"""Tscheng's (1978) 44 pilot-kiln runs run as users run them, and scored against the data.

Each run is its built-in YAML case ``tscheng_<run>`` (src/rotarykiln/cases/), taken through the
public path: :func:`rotarykiln.case.load_case`, :func:`rotarykiln.kiln.from_case.kiln_from_case`
and :func:`rotarykiln.kiln.steady.solve.solve_kiln` (the case's own cell count). The scores are
RMSE (K) at the measured points of the case: bed and gas in the window 1.25-1.78 m, which the
thesis recommends (the uninsulated stretch ends at 1.22 m; data README), and bed, gas and wall
over the whole length. Used by tests/validation/test_heat_tscheng.py and by
docs/scripts/heat_figures.py (which puts this folder on ``sys.path``).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
import pandas as pd

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln
from rotarykiln.studies.tscheng1978 import tscheng_case_name, tscheng_runs

WINDOW = (1.25, 1.78)  # m, the stretch of the data the thesis recommends (data README)


@dataclass(frozen=True)
class RunScore:
    """RMSE (K) of one run: bed and gas in the window and over the whole length, the wall."""

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


def solve_run(run: str):
    """The :class:`~rotarykiln.kiln.results.solution.KilnSolution` of run ``run``'s case."""
    case = load_case(builtin_case_path(tscheng_case_name(run)))
    kiln, cells = kiln_from_case(case)
    return solve_kiln(kiln, cells)


def score(run: str, solution) -> RunScore:
    """Compare a solution with the measurements its case carries."""
    m = solution.measurements
    zb = np.asarray(m["z_bed"])
    assert np.array_equal(zb, np.asarray(m["z_gas"]))  # bed and gas read at the same places
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


def score_all() -> pd.DataFrame:
    """Solve and score the 44 runs of the data: one row per run (index: run id)."""
    rows = [asdict(score(run, solve_run(run))) for run in tscheng_runs().index]
    return pd.DataFrame(rows).set_index("run")
