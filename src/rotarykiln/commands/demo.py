"""``rotarykiln demo``: run the main built-in example and write its results and plots.

The demonstration is Tscheng's hot-air pilot kiln, run A16 (built-in case ``tscheng_A16``):
the steady counter-current kiln model from the measured inputs, with the measured gas, bed and wall
temperatures overlaid on the computed profiles, and the HTML report of the run (``report.html``).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.run import run_case
from rotarykiln.outputs import output_set, write_text_atomic
from rotarykiln.report import format_table

DEMO_CASE = "tscheng_A16"


def register(sub) -> None:
    p = sub.add_parser(
        "demo",
        help="run the built-in demonstration case",
        description="Run Tscheng's hot-air pilot kiln (run A16, built-in case tscheng_A16): "
        "kiln profiles with the measured temperatures, regime map, cross-section, summary, and "
        "the HTML report of the run (report.html).",
    )
    p.add_argument("--out", default="demo-output", help="output folder (default: demo-output)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    path = builtin_case_path(DEMO_CASE)
    case = load_case(path)
    out = Path(args.out or "demo-output")
    with output_set(out) as staging:  # the whole set or nothing, like `rotarykiln run`
        write_text_atomic(staging / "case.yaml", path.read_text(encoding="utf-8"))
        summary = run_case(case, staging, report=True, source=DEMO_CASE, final=out)
    print(format_table(summary))
    print(f"\ndemo results written to {out}/ (open {out / 'report.html'} in a browser)")
    return 0
