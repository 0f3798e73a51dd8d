"""The assembled steady kiln model: discretisation, residual, Newton solver, results.

Entry points: :class:`HeatKiln` (inputs), :func:`solve_heat` (solve), :class:`KilnSolution`
(results), :func:`run_heat_case` (from a case file), :mod:`rotarykiln.kiln.tscheng` and
:mod:`rotarykiln.kiln.builtin` (built-in validation and demonstration kilns).
"""

from rotarykiln.kiln.model import Closures, HeatKiln
from rotarykiln.kiln.solution import KilnSolution
from rotarykiln.kiln.solve import solve_heat
from rotarykiln.kiln.sources import CellState, SourceResult, SourceTerms

__all__ = [
    "CellState",
    "Closures",
    "HeatKiln",
    "KilnSolution",
    "SourceResult",
    "SourceTerms",
    "solve_heat",
]
