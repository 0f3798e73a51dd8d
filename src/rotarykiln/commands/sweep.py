"""``rotarykiln sweep``: run a model over a design of case fields, persistently.

The model is a name (``kiln``, ``kiln_profiles``, ``transport``: see :mod:`rotarykiln.studies.models`) or any
importable function ``module:function`` taking a case (nested dict) and returning a dict of
scalars. Values keep their units as in a case file. Designs: ``--grid`` (full factorial),
``--oat`` (one at a time), or ``--lhs N`` / ``--sobol N`` / ``--mc N`` samples of the
``--param PATH=DIST(ARGS)`` distributions (uniform, normal, lognormal, triangular).

The table printed shows the chosen outputs (``--output NAME``, repeatable; by default a few
key ones: outlet temperatures, residence time, fill, and the burn-off or conversion of a reacting
bed or else the thermal efficiency), each parameter in the unit it was typed in; OUT/NAME.csv
holds every output (values as given and in SI), OUT/NAME.png one panel per chosen output.

Rows are appended to the Parquet dataset ``--store`` (default OUT/runs) as they arrive; run the
same command again to resume: only the cases not yet stored run. The exit code is 1 when any
case failed (its error is in the table).

Examples::

    rotarykiln sweep --case charcoal_activation_kramers --model kiln \\
        --grid "operation.speed=1 rpm,2 rpm,4 rpm" \\
        --grid "transport.dam_height=2 cm,4 cm,6 cm" --out speed/

    rotarykiln sweep --case barr_T4 --model kiln \\
        --grid "burner.fuel_flow=1.5 L/s,1.97 L/s,2.5 L/s" \\
        --grid "operation.feed=40 kg/h,62 kg/h,90 kg/h" \\
        --output bed_outlet_temperature_K --output thermal_efficiency --out firing/

    rotarykiln sweep --case barr_T4 --model kiln --lhs 50 \\
        --param "burner.fuel_flow=uniform(1.5 L/s, 2.5 L/s)" \\
        --param "operation.feed=normal(62 kg/h, 5 kg/h)" --out lhs/
"""

from __future__ import annotations

import argparse
import importlib
import re
import shutil
import sys
from pathlib import Path

from rotarykiln.cases import builtin_case_path
from rotarykiln.commands._args import check_count, out_dir, plain, print_json
from rotarykiln.errors import InputError
from rotarykiln.studies import grid, one_at_a_time, run_sweep
from rotarykiln.studies.design import (
    MAX_DESIGN_CASES,
    as_params,
    latin_hypercube,
    monte_carlo,
    sobol_sequence,
)
from rotarykiln.studies.io import shown
from rotarykiln.studies.runner import EXECUTORS

SAMPLED = {"lhs": latin_hypercube, "sobol": sobol_sequence, "mc": monte_carlo}

__all__ = ["register", "run"]


def register(sub) -> None:
    p = sub.add_parser(
        "sweep",
        help="run a model over ranges of case fields in parallel; one table and plots",
        description=plain(__doc__),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--case", required=True, help="case YAML file or built-in case name")
    p.add_argument(
        "--model",
        required=True,
        help="model: kiln, kiln_profiles, transport (see rotarykiln.studies.models) or module:function",
    )
    p.add_argument(
        "--grid",
        action="append",
        default=[],
        metavar="PATH=V1,V2",
        help="full-factorial values of a field (repeatable)",
    )
    p.add_argument(
        "--oat",
        action="append",
        default=[],
        metavar="PATH=V1,V2",
        help="one-at-a-time values of a field (repeatable)",
    )
    for kind, what in (
        ("lhs", "Latin hypercube"),
        ("sobol", "scrambled Sobol sequence"),
        ("mc", "Monte Carlo"),
    ):
        p.add_argument(f"--{kind}", type=int, metavar="N", help=f"{what} of N cases over --param")
    add_study_options(p)
    p.add_argument(
        "--output",
        action="append",
        default=[],
        metavar="NAME",
        help="an output printed and plotted (repeatable; default: a few key outputs of the "
        "model); the files hold every output",
    )
    p.add_argument("--name", default="sweep", help="base name of the output files")
    p.add_argument("--json", action="store_true", help="print the table as JSON records")
    p.add_argument("--out", help="write NAME.csv (NAME.parquet if pyarrow) and NAME.png here")
    p.add_argument("--no-plots", action="store_true", help="do not write NAME.png")
    p.set_defaults(func=run)


def add_study_options(p, params: bool = True) -> None:
    """Options shared by sweep, sensitivity and calibrate: params, seed, executor, store."""
    if params:
        p.add_argument(
            "--param",
            action="append",
            default=[],
            metavar="PATH=DIST(ARGS)",
            help='a sampled field, e.g. "operation.speed=uniform(1 rpm, 3 rpm)" (repeatable)',
        )
        p.add_argument("--seed", type=int, default=0, help="random seed of sampled designs")
    p.add_argument("--executor", choices=EXECUTORS, default="process")
    p.add_argument("--workers", type=int, default=None, help="processes (default: all CPUs)")
    p.add_argument(
        "--batch",
        type=int,
        default=None,
        metavar="N",
        help="kiln models: at most N cases solved together on a worker (default: the cases "
        "over two batches per worker, at most 256, fewer if memory is short); 1: one at a time",
    )
    p.add_argument(
        "--scheduler",
        default=None,
        help="with --executor dask: a scheduler address tcp://host:port (default: LocalCluster)",
    )
    p.add_argument(
        "--store", default=None, help="Parquet dataset folder of the runs (default: OUT/runs)"
    )
    p.add_argument(
        "--progress",
        action=argparse.BooleanOptionalAction,
        default=None,
        help="progress bar on stderr (default: when it is a terminal)",
    )


MAX_CASES = MAX_DESIGN_CASES  # cases of any design (grid, oat, --lhs/--sobol/--mc N, sensitivity)


def check_printable(args, positional: tuple[str, ...] = ()) -> None:
    """Refuse any text argument with a control character (a newline, a tab, an escape): every
    message that quotes an argument then stays on one line, whatever echoes it."""
    for key, value in vars(args).items():
        if key in ("func", "command") or key.endswith("_command"):
            continue
        for item in value if isinstance(value, list | tuple) else [value]:
            if isinstance(item, str) and not item.isprintable():
                name = key if key in positional else f"--{key.replace('_', '-')}"
                raise InputError(
                    name, shown(item), "text without control characters (newline, tab...)"
                )


def check_study_options(args) -> None:
    """The shared options in their ranges (one line naming the option otherwise)."""
    check_printable(args, ("case", "data"))
    check_count("--workers", getattr(args, "workers", None), 1, 1024)
    check_count("--batch", getattr(args, "batch", None), 1, 100_000)
    check_count("--seed", getattr(args, "seed", None), 0, 2**32 - 1)


def check_design_values(base: dict, design, option: str, model: str) -> None:
    """Refuse, before anything runs, a design value the case file would refuse (a wrong unit,
    a value out of its physical range), for the models that read a case file (:data:`MODELS`):
    each distinct value of each field is set alone on the base case and validated."""
    from rotarykiln.case import parse_case
    from rotarykiln.studies.models import MODELS
    from rotarykiln.studies.paths import with_values

    if model not in MODELS:
        return  # a user's function: its own input rules
    seen: dict[str, dict[str, object]] = {}
    for spec in design:
        for path, value in spec.values.items():
            seen.setdefault(path, {}).setdefault(repr(value), value)
    for path, values in seen.items():
        items = list(values.values())
        if len(items) > 50:  # a sampled design: its extremes
            items = _extremes(items) or items[:50]
        for value in items:
            try:
                parse_case(with_values(base, {path: value}))
            except InputError as exc:  # one line whatever the case loader quoted
                text = str(exc).replace("\r", "\\r").replace("\n", "\\n")
                raise InputError(option, message=f"{option}: {text}") from None


_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def _extremes(values: list) -> list | None:
    """The smallest and largest of sampled design values: numbers, or quantities of one unit
    (``"1.89 L/s"``, as the samplers write them); None for anything else.

    Examples
    --------
    >>> _extremes(["1.9 L/s", "2.05 L/s", "1.81 L/s"])
    ['1.81 L/s', '2.05 L/s']
    >>> _extremes([3, 1.5, 2]), _extremes(["1 L/s", "2 kg/h"])
    ([1.5, 3], None)
    """
    if all(isinstance(v, int | float) and not isinstance(v, bool) for v in values):
        return [min(values), max(values)]
    parsed = [_QUANTITY.match(v) if isinstance(v, str) else None for v in values]
    if not all(parsed) or len({m.group(2) for m in parsed}) != 1:
        return None
    magnitudes = [float(m.group(1)) for m in parsed]
    lo = min(range(len(values)), key=magnitudes.__getitem__)
    hi = max(range(len(values)), key=magnitudes.__getitem__)
    return [values[lo], values[hi]]


def runner_options(args, folder) -> dict:
    """run_sweep keyword arguments from the shared options."""
    store = args.store or (str(Path(folder) / "runs") if folder is not None else None)
    if args.scheduler and args.executor != "dask":
        raise InputError("--scheduler", args.scheduler, "used with --executor dask")
    return {
        "executor": args.executor,
        "max_workers": args.workers,
        "dask_scheduler": args.scheduler,
        "store": store,
        "progress": args.progress,
        "batch": getattr(args, "batch", None),
    }


def report_warnings(res, command: str) -> None:
    """One stderr line: how many cases warned, and the first distinct message."""
    if res.n_warned:
        w = res.frame["warnings"].fillna("")
        first = w[w != ""].iloc[0].split("; ")[0]
        print(
            f"rotarykiln {command}: {res.n_warned} of {len(res.frame)} cases raised warnings "
            f"(column warnings), e.g. {first}",
            file=sys.stderr,
        )


def _ranges(items: list[str], option: str) -> dict[str, list]:
    out: dict[str, list] = {}
    for item in items:
        path, sep, values = item.partition("=")
        if not sep or not path.strip() or not values.strip():
            raise InputError(
                option, shown(item), 'PATH=V1,V2,... e.g. operation.speed="1 rpm,2 rpm"'
            )
        if path.strip() in out:
            raise InputError(
                option,
                shown(path.strip()),
                f"given once (its values in one {option} PATH=V1,V2,...)",
            )
        parsed = []
        for v in values.split(","):
            v = v.strip()
            try:
                parsed.append(float(v))
            except ValueError:
                parsed.append(v)
        out[path.strip()] = parsed
    return out


def _load_model(spec: str):
    from rotarykiln.studies.models import MODELS

    if spec in MODELS:
        return MODELS[spec]
    mod, sep, name = spec.partition(":")
    if not sep or not mod or not name:
        raise InputError("--model", spec, f"a model name ({', '.join(MODELS)}) or module:function")
    try:
        func = getattr(importlib.import_module(mod), name)
    except (ImportError, AttributeError) as exc:
        raise InputError("--model", spec, f"an importable function ({exc})") from None
    if not callable(func):
        raise InputError("--model", spec, "a callable")
    return func


def _load_case(spec: str) -> dict:
    path = Path(spec)
    if not path.is_file():
        path = builtin_case_path(spec)
    from rotarykiln.case import read_case_data

    data = read_case_data(path)  # one line for a bad file: unreadable, not UTF-8, too large...
    if not isinstance(data, dict):
        raise InputError("--case", spec, "a YAML mapping")
    return data


def run(args) -> int:
    check_printable(args, ("case",))
    kinds = [k for k in ("grid", "oat") if getattr(args, k)]
    kinds += [k for k in SAMPLED if getattr(args, k) is not None]
    if len(kinds) != 1:
        raise InputError(
            "sweep",
            "/".join(f"--{k}" for k in kinds) or "no design",
            "exactly one design (--grid, --oat, --lhs N, --sobol N or --mc N)",
        )
    kind = kinds[0]
    if kind in SAMPLED:
        check_count(f"--{kind}", getattr(args, kind), 1, MAX_CASES)
    check_study_options(args)
    if kind in SAMPLED and not args.param:
        raise InputError(f"--{kind}", getattr(args, kind), "given with --param PATH=DIST(ARGS)")
    if kind not in SAMPLED and args.param:
        raise InputError("--param", args.param[0], "used with --lhs, --sobol or --mc")
    if not re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,80}", args.name) or ".." in args.name:
        raise InputError(
            "--name",
            args.name,
            "a plain file name (letters, digits, '_', '-', '.'; no folder): the files go in --out",
        )
    base = _load_case(args.case)
    func = _load_model(args.model)
    if kind == "grid":
        design = grid(_ranges(args.grid, "--grid"))
    elif kind == "oat":
        design = one_at_a_time(_ranges(args.oat, "--oat"))
    else:
        design = SAMPLED[kind](as_params(args.param), getattr(args, kind), seed=args.seed)
    option = "--param" if kind in SAMPLED else f"--{kind}"
    check_design_values(base, design, option, args.model)
    folder = out_dir(args.out, "results") if args.out else None
    res = run_sweep(func, base, design, **runner_options(args, folder))
    try:
        chosen = res.check_outputs(args.output, "--output") if res.outputs else []
    except InputError as exc:
        if res.meta.get("store"):  # rerunning with the right name costs nothing
            raise InputError(
                "--output",
                message=f"{exc} (the {len(res.frame)} cases are stored: run the "
                f"same command with one of these names, nothing is computed again)",
            ) from None
        raise
    if folder is not None:
        res.write(folder, name=args.name)
        if chosen and len(res.failed) < len(res.frame) and not args.no_plots:
            res.save_plot(folder / f"{args.name}.png", outputs=chosen)
    if args.json:
        print_json(res.frame.to_dict(orient="records"))
    else:
        if chosen:
            width = shutil.get_terminal_size((100, 24)).columns
            print(res.format_table(chosen, width=max(60, width)))
        print(
            f"{len(res.frame)} cases ({res.meta.get('ran', len(res.frame))} run now, "
            f"{res.meta.get('reused', 0)} from the store), {res.n_failed} failed, "
            f"{res.wall_time:.2f} s ({res.executor})"
        )
        if folder is not None:
            print(f"every output in {folder / args.name}.csv")
    report_warnings(res, "sweep")
    if res.n_failed:
        print(
            f"rotarykiln sweep: {res.n_failed} of {len(res.frame)} cases failed "
            "(see the error column)",
            file=sys.stderr,
        )
        return 1
    return 0
