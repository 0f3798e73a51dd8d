"""``rotarykiln bed``: axial bed-depth profile, hold-up and residence time of a drum.

Example::

    rotarykiln bed --diameter 0.4 m --length 2 m --speed 3 rpm --slope 1 deg --feed 62 kg/h \\
        --density 1500 kg/m3 --repose 35 deg --dam 0.05 m --model kramers --out results
"""

from __future__ import annotations

import argparse

from rotarykiln.commands._args import (
    add_quantity,
    get_quantity,
    out_dir,
    plain,
    print_json,
    to_si_within,
)
from rotarykiln.commands.model_runs import write_bed_profile
from rotarykiln.errors import InputError
from rotarykiln.report import format_table
from rotarykiln.transport.solve import N_POINTS_RANGE, solve_bed

__all__ = ["register", "run", "run_case_section"]


def register(sub) -> None:
    p = sub.add_parser(
        "bed",
        help="axial bed-depth profile, hold-up and residence time (Kramers or Scott)",
        description=plain(__doc__),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_quantity(p, "diameter", "drum inner diameter, e.g. 0.4 m")
    add_quantity(p, "length", "drum length, e.g. 2 m")
    add_quantity(p, "speed", "rotation speed, e.g. 3 rpm")
    add_quantity(p, "slope", "drum slope, e.g. 1 deg or 2 %% (a grade)")
    add_quantity(p, "feed", "solids mass feed, e.g. 62 kg/h")
    add_quantity(p, "density", "bulk density, e.g. 1500 kg/m3")
    add_quantity(p, "repose", "dynamic angle of repose, e.g. 35 deg")
    add_quantity(p, "static-repose", "static angle of repose (Scott; default: --repose)")
    add_quantity(p, "dam", "discharge dam height above the wall, e.g. 0.05 m (default: open)")
    p.add_argument(
        "--weir",
        nargs=2,
        action="append",
        metavar=("POSITION", "HEIGHT"),
        help='internal weir (Scott): distance from the discharge and height, e.g. "0.25m" "0.02m"'
        "; repeatable",
    )
    p.add_argument(
        "--model",
        choices=("kramers", "scott"),
        default="kramers",
        help="bed-profile model: Kramers-Croockewit/Saeman (default) or Scott (weirs, friction)",
    )
    p.add_argument(
        "--friction",
        default="static",
        help="Scott's surface friction: zero, dynamic, static (default) or a number",
    )
    p.add_argument(
        "--points",
        type=int,
        default=201,
        help="output points along the drum (2 to 100000, default 201)",
    )
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    p.add_argument("--out", help="write profile.csv, summary.json and profile.png to this folder")
    p.set_defaults(func=run)


def _friction(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return text


def run(args: argparse.Namespace) -> int:
    low, high = N_POINTS_RANGE
    if not low <= args.points <= high:
        raise InputError("--points", args.points, f"an integer in [{low}, {high}]")
    from rotarykiln import case as c  # the physical ranges of a case file

    q = {
        name: get_quantity(args, name, kind, required=True, within=within)
        for name, kind, within in (
            ("diameter", "length", c.Length),
            ("length", "length", c.Length),
            ("speed", "rotation rate", c.RotationRate),
            ("slope", "angle", c.Slope),
            ("feed", "mass flow", c.MassFlow),
            ("density", "density", c.Density),
            ("repose", "angle", c.ReposeAngle),
        )
    }
    if not q["feed"] >= 1e-6:  # a drum that is fed: below 3.6 g/h the hold-up underflows
        raise InputError(
            "--feed", message=f"--feed: {' '.join(args.feed)} is not in [1e-6 kg/s, 1e5 kg/s]"
        )
    weirs = [
        (to_si_within("--weir", pos, c.Position), to_si_within("--weir", h, c.Length))
        for pos, h in args.weir or []
    ]
    profile = solve_bed(
        model=args.model,
        static_repose=get_quantity(args, "static-repose", "angle", within=c.ReposeAngle),
        dam=get_quantity(args, "dam", "length", within=c.Position),
        weirs=weirs,
        friction=_friction(args.friction),
        n_points=args.points,
        **q,
    )
    summary = {k: v for k, v in profile.summary().items() if k != "section_fills"}
    summary["mean_residence_time_min"] = profile.mean_residence_time / 60.0
    if args.out:
        summary.update(write_bed_profile(profile, out_dir(args.out, "bed-results")))
    if args.json:
        print_json(dict(summary, section_fills=profile.summary()["section_fills"]))
    else:
        print(format_table(summary))
    return 0


def run_case_section(case, out) -> dict:
    """Runner for the ``transport:`` section of a case file (see rotarykiln.commands.run): the
    summary of :func:`rotarykiln.commands.model_runs.transport_run` and the files it writes."""
    from rotarykiln.commands.model_runs import transport_run

    run = transport_run(case)
    return {**run.summary, **run.write(out)}
