"""Studies over case fields: sweeps, sensitivity indices, uncertainty bands, calibration.

- :mod:`.design`: grid, one-at-a-time, Latin hypercube, Sobol and Monte Carlo designs over
  dotted field paths, with units and distributions (:func:`parse_param`).
- :mod:`.runner`: :func:`run_sweep` (processes by default, serial, or dask.distributed), rows
  stored as they arrive in a Parquet dataset (:mod:`.store`), resumable, with progress.
- :mod:`.result`: :class:`SweepResult` (pandas table, atomic CSV/Parquet, plot).
- :mod:`.sensitivity`: Sobol and Morris indices (SALib); :mod:`.uncertainty`: Monte Carlo
  bands; :mod:`.calibration`: weighted least squares to measured data.
- :mod:`.models`: named models (kiln, kiln_profiles, transport); :mod:`.tscheng1978`:
  Tscheng's runs as cases and data.
- :mod:`.ahmad2006`: the chapter-5 sensitivity study of seed 004 as a design.
- :mod:`.examples`: cheap model functions for tests and demonstrations.
"""

from rotarykiln.studies.design import (
    CaseSpec,
    Param,
    grid,
    latin_hypercube,
    monte_carlo,
    one_at_a_time,
    parse_param,
    si_value,
    sobol_sequence,
)
from rotarykiln.studies.paths import get_path, set_path, with_values
from rotarykiln.studies.result import SweepResult
from rotarykiln.studies.runner import run_case, run_sweep

__all__ = [
    "CaseSpec",
    "Param",
    "SweepResult",
    "get_path",
    "grid",
    "latin_hypercube",
    "monte_carlo",
    "one_at_a_time",
    "parse_param",
    "sobol_sequence",
    "run_case",
    "run_sweep",
    "set_path",
    "si_value",
    "with_values",
]
