"""The steady kiln model: one model for every kiln (inert or reacting, air-heated or fired).

Entry points: :class:`Kiln` (inputs; :meth:`Kiln.inert` for a bed that does not react),
:func:`solve_kiln` (Newton on the discretised balances), :class:`KilnSolution` (profiles,
balances, summary), :func:`~rotarykiln.kiln.from_case.kiln_from_case` and
:func:`~rotarykiln.commands.kiln_runs.run_kiln_case` (from a case file),
:mod:`rotarykiln.kiln.tscheng` (Tscheng's validation kilns).
"""

from rotarykiln.kiln.inputs import Closures, Kiln
from rotarykiln.kiln.results.solution import KilnSolution
from rotarykiln.kiln.steady.solve import solve_kiln

__all__ = ["Closures", "Kiln", "KilnSolution", "solve_kiln"]
