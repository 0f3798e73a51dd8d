"""``rotarykiln run CASE.yaml``: validate a case, run the models its sections ask for, write results.

Models are looked up in :data:`RUNNERS` (model name -> "module:function"); each function takes
the validated case and returns a :class:`rotarykiln.commands.model_runs.ModelRun` (its result, its
summary values, and how to write its files). :func:`solve_case` runs them in memory: it is the
one code path of this command and of :func:`rotarykiln.run`.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import sys
import warnings
from pathlib import Path

from rotarykiln.case import load_case
from rotarykiln.commands._args import print_json
from rotarykiln.errors import InputError
from rotarykiln.outputs import (
    MANIFEST,
    no_figures,
    output_set,
    save_figure_atomic,
    write_json_atomic,
    write_text_atomic,
)
from rotarykiln.report import case_summary, format_table

__all__ = [
    "MANIFEST",
    "RUNNERS",
    "case_path",
    "register",
    "run",
    "run_case",
    "run_case_into",
    "solve_case",
]


RUNNERS: dict[str, str] = {
    "transport": "rotarykiln.commands.model_runs:transport_run",
    "kiln": "rotarykiln.commands.kiln_runs:kiln_run",
    "rtd": "rotarykiln.commands.model_runs:rtd_run",
}
"""Model name -> "module:function(case) -> ModelRun", run when the case asks for it
(:func:`wants`: a ``transport:`` or ``rtd:`` section; the kiln model for a case with a heat
source or chemistry, :attr:`rotarykiln.case.Case.has_kiln_model`)."""


def wants(case, model: str) -> bool:
    """Whether the validated ``case`` asks for the model ``model`` of :data:`RUNNERS`."""
    if model == "kiln":
        return case.has_kiln_model
    return getattr(case, model, None) is not None


def solve_case(case) -> dict:
    """Solve every model the validated ``case`` asks for (:data:`RUNNERS`), in memory.

    Returns
    -------
    dict
        Model name -> :class:`rotarykiln.commands.model_runs.ModelRun`, in the order of
        :data:`RUNNERS` (the transport bed profile first: it feeds the kiln's fill and the
        RTD's mean residence time).
    """
    import logging
    import time

    log = logging.getLogger(__name__)
    runs = {}
    for model, target in RUNNERS.items():
        if wants(case, model):
            module, func = target.split(":")
            log.info("%s: the %s model", case.name, model)
            t0 = time.perf_counter()
            runs[model] = getattr(importlib.import_module(module), func)(case)
            log.info("%s: the %s model done in %.3g s", case.name, model, time.perf_counter() - t0)
    return runs


def register(sub) -> None:
    p = sub.add_parser(
        "run",
        help="validate a case file and run it",
        description="Validate a case file (YAML with units) and run every model its sections "
        "switch on (transport, the kiln model, rtd); write summary.json, summary.txt, tables and "
        "figures to --out, all of them or none: a failed or interrupted run leaves the folder as "
        "it was, and a run replaces the files of the previous one (run_files.json), never the "
        "user's. Built-in cases: see src/rotarykiln/cases/README.md. "
        "Example: rotarykiln run limestone_calcination --out lime",
    )
    p.add_argument("case", help="case file (YAML) or the name of a built-in case")
    p.add_argument("--out", help="output folder (default: <case name>-results)")
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    p.add_argument("--no-plots", action="store_true", help="do not write figures")
    p.add_argument(
        "--report",
        action="store_true",
        help="also write report.html: case, warnings, summaries and figures in one offline file",
    )
    p.set_defaults(func=run)


def run_case(
    case,
    out: Path,
    *,
    plots: bool = True,
    report: bool = False,
    source: str | None = None,
    final: Path | None = None,
) -> dict:
    """Run every model a validated case asks for; write summary and figures to ``out``.

    With ``report``, also write ``out/report.html`` (:mod:`rotarykiln.report_html`): the
    warnings of the run are recorded for it (and still shown as usual), ``source`` names the case.
    ``final``: the folder the files will be moved to when ``out`` is a staging folder
    (:func:`rotarykiln.outputs.output_set`); paths in the summary name it, not ``out``.
    """
    before = _stamps(out) if report else {}
    recorder = warnings.catch_warnings(record=True) if report else contextlib.nullcontext([])
    figures = contextlib.nullcontext() if plots else no_figures()
    with recorder as caught, figures:
        summary = case_summary(case)
        sections = {"case": dict(summary)}
        for model, solved in solve_case(case).items():
            result = {**solved.summary, **(solved.write(out) or {})}
            sections[model] = _relocate(result, out, final)
            summary.update(sections[model])
        write_json_atomic(out / "summary.json", summary)
        write_text_atomic(out / "summary.txt", format_table(summary) + "\n")
        if plots and case.bed is not None and case.bed.mean_fill is not None:
            import matplotlib.pyplot as plt

            from rotarykiln.plot import cross_section_figure, regime_map_figure

            for name, fig in (
                (
                    "regime_map.png",
                    regime_map_figure(case.bed.mean_fill, summary["froude"], case.name),
                ),
                (
                    "cross_section.png",
                    cross_section_figure(case.bed.mean_fill, case.kiln.diameter / 2, case.name),
                ),
            ):
                save_figure_atomic(out / name, fig)
                plt.close(fig)
    if report:
        for w in caught:  # recorded for the report; shown as they would have been
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
        from rotarykiln.report_html import write_html_report

        written = [p for p, t in _stamps(out).items() if before.get(p) != t]
        figures = [p for p in written if p.suffix.lower() in (".png", ".svg", ".jpg", ".jpeg")]
        write_html_report(
            out / "report.html",
            case,
            sections=sections,
            warnings=[str(w.message) for w in caught],
            figures=figures,
            files=[p.name for p in written if p not in figures] + ["report.html"],
            source=source,
        )
    return summary


def _stamps(out: Path) -> dict[Path, int]:
    """Files of ``out`` and their modification times (to tell what a run wrote)."""
    return {
        p: p.stat().st_mtime_ns for p in sorted(out.iterdir()) if p.is_file() and p.name[0] != "."
    }


def case_path(spec: str) -> Path:
    """A case file path, or the path of the built-in case of that name (``tscheng_A16``)."""
    path = Path(spec)
    if path.is_file() or path.suffix in (".yaml", ".yml"):
        return path
    from rotarykiln.cases import builtin_case_path, list_builtin_cases

    names = list_builtin_cases()
    if spec in names:
        return builtin_case_path(spec)
    folders = {n.split("/")[0] for n in names if "/" in n}
    if path.suffix or ("/" in spec and spec.split("/")[0] not in folders):
        return path  # looks like a file path: load_case reports it missing
    raise InputError(
        "case",
        message=f"{spec}: no such case file or built-in case (built-in: {', '.join(names)})",
    )


def _relocate(data, staging: Path, final: Path | None):
    """``data`` with the paths into ``staging`` (strings) made paths into ``final``."""
    if final is None:
        return data
    if isinstance(data, dict):
        return {k: _relocate(v, staging, final) for k, v in data.items()}
    if isinstance(data, list | tuple):
        return type(data)(_relocate(v, staging, final) for v in data)
    if isinstance(data, str) and data.startswith(str(staging)):
        return str(final) + data[len(str(staging)) :]
    return data


def run_case_into(case, folder: str | Path, **kwargs) -> dict:
    """:func:`run_case` with its files committed into ``folder`` as a whole, or not at all
    (:func:`rotarykiln.outputs.output_set`): the previous run's files there are replaced, the
    user's own files are kept, a failed or interrupted run changes nothing."""
    folder = Path(folder)
    with output_set(folder) as staging:
        return run_case(case, staging, final=folder, **kwargs)


def run(args: argparse.Namespace) -> int:
    case = load_case(case_path(args.case))
    out = Path(args.out or f"{Path(args.case).stem}-results")
    summary = run_case_into(
        case, out, plots=not args.no_plots, report=args.report, source=args.case
    )
    if args.json:
        print_json(summary)
    else:
        print(format_table(summary))
        print(f"\nresults written to {out}/")
    if case.transverse is not None:
        print(
            f"note: the transverse: section is not run here; run it with "
            f"`rotarykiln transverse {args.case}`",
            file=sys.stderr,
        )
    return 0
