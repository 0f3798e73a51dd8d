"""The steady kiln model: one model for every kiln (inert or reacting, air-heated or fired).

Entry points: :class:`Kiln` (inputs; :meth:`Kiln.inert` for a bed that does not react),
:func:`solve_kiln` (Newton on the discretised balances), :class:`KilnSolution` (profiles,
balances, summary), :func:`~rotarykiln.kiln.build.kiln_from_case` and
:func:`~rotarykiln.kiln.run.run_kiln_case` (from a case file),
:mod:`rotarykiln.kiln.tscheng` (Tscheng's validation kilns).
"""

from rotarykiln.kiln.model import Closures, Kiln
from rotarykiln.kiln.solution import KilnSolution
from rotarykiln.kiln.solve import solve_kiln

__all__ = ["Closures", "Kiln", "KilnSolution", "solve_kiln"]
