"""Run the kiln model of a validated case file (``rotarykiln run``, sweeps).

:func:`run_kiln_case` builds (:func:`rotarykiln.kiln.build.kiln_from_case`) and solves the
kiln of a :class:`rotarykiln.case.Case`; :func:`kiln_runner` is the ``rotarykiln run`` runner
(``kiln_profiles.csv``, ``kiln_summary.json``, ``kiln_profiles.png``, and for a reacting bed the
residence-time effects with ``kiln_rtd.png``).
"""

from __future__ import annotations

from pathlib import Path

from rotarykiln.kiln.build import kiln_from_case
from rotarykiln.kiln.solution import KilnSolution
from rotarykiln.kiln.solve import solve_kiln

__all__ = ["kiln_runner", "run_kiln_case"]


def run_kiln_case(case, n_cells: int | None = None) -> KilnSolution:
    """Solve the steady kiln model of a validated case (``solver.cells`` cells by default).

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> sol = run_kiln_case(load_case(builtin_case_path("tscheng_A16")))
    >>> abs(sol.energy_closure) < 1e-6
    True
    >>> sol = run_kiln_case(load_case(builtin_case_path("limestone_calcination")))
    >>> round(sol.summary()["conversion_CaCO3"], 4)
    1.0
    >>> max(sol.element_closure.values()) < 1e-8
    True
    """
    kiln, cells = kiln_from_case(case)
    return solve_kiln(kiln, n_cells or cells)


def kiln_runner(case, out: Path) -> dict:
    """``rotarykiln run`` runner: solve, write profiles, summary and figures, return the summary.

    A bed that reacts also gets the residence-time effects
    (:func:`rotarykiln.kiln.residence.residence_time_effects`: the segregated-flow conversion
    over the RTD) in its summary and ``kiln_rtd.png``.
    """
    from rotarykiln.kiln.run_files import write_solution_files

    kiln, cells = kiln_from_case(case)
    sol = solve_kiln(kiln, cells)
    out = Path(out)
    from rotarykiln.kiln.residence import fed_reactant, residence_time_effects

    if fed_reactant(kiln) is None:  # nothing fed reacts: no residence-time effect to show
        return write_solution_files(sol, out, "kiln", dpi=110)
    import matplotlib.pyplot as plt

    from rotarykiln.outputs import save_figure_atomic

    rtd = residence_time_effects(case, kiln, sol)
    summary = write_solution_files(sol, out, "kiln", extra=rtd.summary(), dpi=100)
    fig = rtd.plot()
    save_figure_atomic(out / "kiln_rtd.png", fig, dpi=100)
    plt.close(fig)
    return summary
