"""The kiln model: one model for every kiln (inert or reacting, air-heated, fired, jacketed or
electrically heated; steady and transient).

Entry points: :class:`Kiln` (the inputs as a tree; :meth:`Kiln.inert` for a bed that does not
react), :func:`solve_kiln` (Newton on the discretised balances), :class:`KilnSolution`
(profiles, balances, summary), :func:`~rotarykiln.kiln.from_case.kiln_from_case` (from a case
file), :func:`~rotarykiln.kiln.transient.integrate.simulate` (in time). The layout:
docs/dev/architecture.md.
"""

from rotarykiln.kiln.inputs import Closures, Kiln
from rotarykiln.kiln.results.solution import KilnSolution
from rotarykiln.kiln.steady.solve import solve_kiln

__all__ = ["Closures", "Kiln", "KilnSolution", "solve_kiln"]
