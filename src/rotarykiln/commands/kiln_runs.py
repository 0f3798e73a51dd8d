"""Run the kiln model of a validated case file (``rotarykiln run``, sweeps).

:func:`run_kiln_case` builds (:func:`rotarykiln.kiln.from_case.kiln_from_case`) and solves the
kiln of a :class:`rotarykiln.case.Case`; :func:`kiln_run` solves it as ``rotarykiln run`` does
(in memory) and :func:`kiln_runner` writes that run's files
(``kiln_profiles.csv``, ``kiln_summary.json``, ``kiln_profiles.png``, and for a reacting bed the
residence-time effects with ``kiln_rtd.png``).
"""

from __future__ import annotations

import logging
import warnings
from pathlib import Path

from rotarykiln.commands.model_runs import ModelRun
from rotarykiln.kiln.from_case import default_origins, kiln_from_case
from rotarykiln.kiln.results import closure_warnings
from rotarykiln.kiln.results.solution import KilnSolution
from rotarykiln.kiln.steady.solve import solve_kiln

log = logging.getLogger(__name__)

__all__ = ["bed_peclet", "kiln_run", "kiln_runner", "run_kiln_case"]


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


def kiln_run(case) -> ModelRun:
    """The kiln model of a validated case, solved in memory (``rotarykiln run`` and
    :func:`rotarykiln.run` both go through it).

    A bed that reacts also gets the residence-time effects
    (:func:`rotarykiln.kiln.bed.residence.residence_time_effects`: the segregated-flow conversion
    over the RTD) in its summary and its files (``kiln_rtd.png``), and as
    ``extra["residence"]``.

    The closures' range warnings of the solve are given once per closure, with the heat flow
    the closure feeds, its share of the heat to the solids and the other choices
    (:mod:`rotarykiln.kiln.results.closure_warnings`; also as ``extra["closure_warnings"]``); any other
    warning once per text.

    Returns
    -------
    rotarykiln.commands.model_runs.ModelRun
        ``value``: the :class:`~rotarykiln.kiln.results.solution.KilnSolution`; ``summary``: its
        summary with every key prefixed ``kiln_``; ``write(out)``: ``kiln_profiles.csv``,
        ``kiln_summary.json``, ``kiln_profiles.png`` (and ``kiln_rtd.png``).
    """
    from rotarykiln.kiln.bed.residence import fed_reactant, residence_time_effects

    kiln, cells = kiln_from_case(case)
    log.info(
        "kiln model: %d cells, %s",
        cells,
        "counter-current" if kiln.gas.counter_current else "co-current",
    )
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")  # every closure's check: grouped below
        sol = solve_kiln(kiln, cells)
        # nothing fed reacts: no residence-time effect to show
        rtd = None
        if fed_reactant(kiln) is not None:
            peclet, model = bed_peclet(case, sol.residence_time)
            rtd = residence_time_effects(kiln, sol, peclet=peclet, model=model)
    log.info(
        "kiln solved: bed out %.1f K, gas out %.1f K, heat to solids %.4g W, energy closure %.2g, "
        "elements %.2g, %d Newton iterations",
        sol.bed_outlet_temperature,
        sol.gas_outlet_temperature,
        sol.heat_to_solids,
        sol.energy_closure,
        max(sol.element_closure.values(), default=0.0),
        sol.iterations,
    )
    # one warning per closure out of its range, with the heat flow it feeds and its share
    shown = closure_warnings.emit(caught, sol, default_origins(case))
    extra = rtd.summary() if rtd is not None else {}
    summary = {f"kiln_{k}": v for k, v in sol.summary().items() if k != "name"}
    summary.update({f"kiln_{k}": v for k, v in extra.items()})

    def write(out) -> dict:
        from rotarykiln.outputs import write_solution_files

        out = Path(out)
        if rtd is None:
            return write_solution_files(sol, out, "kiln", dpi=110)
        import matplotlib.pyplot as plt

        from rotarykiln.outputs import save_figure_atomic

        written = write_solution_files(sol, out, "kiln", extra=extra, dpi=100)
        fig = rtd.plot()
        save_figure_atomic(out / "kiln_rtd.png", fig, dpi=100)
        plt.close(fig)
        return written

    closures = [w for w in shown if isinstance(w, closure_warnings.ClosureWarning)]
    return ModelRun(
        "kiln", sol, summary, write, extra={"residence": rtd, "closure_warnings": closures}
    )


def kiln_runner(case, out: Path) -> dict:
    """``rotarykiln run`` runner: solve (:func:`kiln_run`), write profiles, summary and
    figures to ``out``, return the summary."""
    run = kiln_run(case)
    return {**run.summary, **run.write(Path(out))}


def bed_peclet(case, mean_residence_time: float) -> tuple[float | None, str]:
    """The bed's Peclet number of a case and the RTD model it belongs to: ``chemistry.peclet``
    if given, else from the case's ``rtd:`` section
    (:func:`~rotarykiln.commands.model_runs.peclet_from_case` at ``mean_residence_time``, s),
    else None (the kiln's own dispersion correlation); open-open boundaries unless the
    ``rtd:`` section names its model."""
    from rotarykiln.commands.model_runs import peclet_from_case

    pe = case.chemistry.peclet if case.chemistry is not None else None
    if pe is None and case.rtd is not None:
        pe, _ = peclet_from_case(case, mean_residence_time)
        return pe, case.rtd.model
    return pe, "open-open"
