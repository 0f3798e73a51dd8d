"""Sensitivity studies: sweeps over case fields, run in parallel, gathered in one table.

- :mod:`.design`: :func:`grid` and :func:`one_at_a_time` designs over dotted field paths.
- :mod:`.runner`: :func:`run_sweep` (ProcessPoolExecutor by default, serial, or Dask).
- :mod:`.result`: :class:`SweepResult` (pandas table, atomic CSV/Parquet, plot).
- :mod:`.ahmad2006`: the chapter-5 sensitivity study of seed 004 as a design.
- :mod:`.examples`: cheap model functions for tests and demonstrations.
"""

from rotarykiln.studies.design import CaseSpec, grid, one_at_a_time, si_value
from rotarykiln.studies.paths import get_path, set_path, with_values
from rotarykiln.studies.result import SweepResult
from rotarykiln.studies.runner import run_case, run_sweep

__all__ = [
    "CaseSpec",
    "SweepResult",
    "get_path",
    "grid",
    "one_at_a_time",
    "run_case",
    "run_sweep",
    "set_path",
    "si_value",
    "with_values",
]
