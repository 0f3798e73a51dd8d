"""``rotarykiln transient CASE.yaml --events EVENTS.yaml --until "10 h" --out DIR``.

Runs the transient kiln (:mod:`rotarykiln.kiln.transient.integrate`) of a case file under the events of a
transient file (:mod:`rotarykiln.kiln.transient.events`) and writes ``transient_profiles.parquet`` (every
variable against z and t), ``transient_outlets.csv``, ``transient_summary.json``, the z-t heat
map and the outlets against time; with a tracer pulse, its RTD in the summary.
"""

from __future__ import annotations

from rotarykiln.commands._args import out_dir, print_json

__all__ = ["register", "run"]


def register(sub) -> None:
    p = sub.add_parser(
        "transient",
        help="run a kiln in time: start-up, upsets, control steps",
        description="Integrate the kiln of a case file in time (the steady model's cells and "
        "closures with the hold-ups of solids, gas and lining) under the events of a YAML file "
        "(steps and ramps of feed, fuel, air, speed, gas inlet temperature; a drum stop; a "
        "tracer pulse). Writes transient_profiles.parquet, transient_outlets.csv, "
        "transient_summary.json and figures to --out. Example: rotarykiln transient barr_T4 "
        '--events startup.yaml --until "10 h" --out barr-startup',
    )
    p.add_argument("case", help="case file (YAML) or the name of a built-in case")
    p.add_argument(
        "--events",
        help="transient file (YAML): start, events, tracer, wall; or the name of a shipped "
        "example (barr_T4_startup)",
    )
    p.add_argument("--until", required=True, help='end of the run, e.g. "10 h"')
    p.add_argument("--out", help="output folder (default: <case name>-transient)")
    p.add_argument("--cells", type=int, help="cells along the kiln (default: the case's)")
    p.add_argument("--no-plots", action="store_true", help="do not write figures")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    p.set_defaults(func=run)


def run(args) -> int:
    from rotarykiln.case import Cells, Time, check_quantity, load_case
    from rotarykiln.commands.run import case_path
    from rotarykiln.kiln.from_case import kiln_from_case
    from rotarykiln.kiln.transient.events import check_output_size, output_times_bound
    from rotarykiln.kiln.transient.integrate import simulate
    from rotarykiln.transient_file import parse_transient, read_transient_file

    # the ranges of the case file: a run of at most 1e10 s, at most 20,000 cells
    until = check_quantity("--until", args.until, Time)
    if args.cells is not None:
        check_quantity("--cells", args.cells, Cells)
    if args.events:
        from rotarykiln.examples import example_path

        data = read_transient_file(example_path("--events", args.events))
    else:
        data = {}
    case = load_case(case_path(args.case))
    kiln, cells = kiln_from_case(case)
    if args.cells is not None:
        cells = args.cells
    transient = parse_transient(data, kiln, until)
    # the profiles kept: refused before the steady start is solved or anything allocated
    bound = output_times_bound(transient, until)
    check_output_size(cells, bound, "--cells" if args.cells else "output_every")
    out = out_dir(args.out, f"{case.name}-transient".replace(" ", "_"))
    progress = False if args.no_progress else None  # None: a terminal or $ROTARYKILN_PROGRESS
    sol = simulate(kiln, cells, transient, until, progress=progress)
    summary = sol.write(out, plots=not args.no_plots)
    if transient.tracer is not None:
        t0, dt, _ = transient.tracer
        rtd = sol.rtd(t0, dt)
        if not rtd["recovered_fraction"] > 0.99:  # the pulse has not left: no moments yet
            rtd["mean_residence_time_s"] = rtd["variance_s2"] = float("nan")
        summary.update({f"tracer_{k}": v for k, v in rtd.items()})
        from rotarykiln.outputs import write_json_atomic

        write_json_atomic(out / "transient_summary.json", summary)
    if args.json:
        print_json(summary)
    else:
        print(
            f"{sol.name}: {until:g} s simulated in {sol.wall_time:.1f} s; bed outlet "
            f"{summary['bed_outlet_temperature_start_K']:.1f} -> "
            f"{summary['bed_outlet_temperature_end_K']:.1f} K; results in {out}"
        )
    return 0
