"""``rotarykiln sweep``: run a model over a grid or one-at-a-time ranges of case fields.

The model is a name (``heat``, ``transport``: see :mod:`rotarykiln.studies.models`) or any
importable function ``module:function`` taking a case (nested dict) and returning a dict of
scalars. Values keep their units as in a case file.

Example::

    rotarykiln sweep --case charcoal_activation \\
        --model rotarykiln.studies.examples:ortiz_isothermal_burn_off \\
        --oat chemistry.residence_time="3000 s,6480 s,10000 s" \\
        --oat chemistry.gas.steam_flow="0.0025 kg/s,0.005 kg/s" --out results
"""

from __future__ import annotations

import argparse
import importlib
from pathlib import Path

import yaml

from rotarykiln.cases import builtin_case_path
from rotarykiln.commands._args import out_dir, plain, print_json
from rotarykiln.errors import InputError
from rotarykiln.studies import grid, one_at_a_time, run_sweep
from rotarykiln.studies.runner import EXECUTORS

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
        help="model: heat, transport (see rotarykiln.studies.models) or module:function",
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
    p.add_argument("--executor", choices=EXECUTORS, default="process")
    p.add_argument("--workers", type=int, default=None, help="processes (default: all CPUs)")
    p.add_argument("--name", default="sweep", help="base name of the output files")
    p.add_argument("--json", action="store_true", help="print the table as JSON records")
    p.add_argument("--out", help="write NAME.csv (NAME.parquet if pyarrow) and NAME.png here")
    p.set_defaults(func=run)


def _ranges(items: list[str], option: str) -> dict[str, list]:
    out: dict[str, list] = {}
    for item in items:
        path, sep, values = item.partition("=")
        if not sep or not path.strip() or not values.strip():
            raise InputError(option, item, 'PATH=V1,V2,... e.g. operation.speed="1 rpm,2 rpm"')
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
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise InputError("--case", spec, f"a readable YAML case ({exc})") from None
    if not isinstance(data, dict):
        raise InputError("--case", spec, "a YAML mapping")
    return data


def run(args) -> int:
    if bool(args.grid) == bool(args.oat):
        raise InputError("sweep", "--grid/--oat", "exactly one kind of range (--grid or --oat)")
    base = _load_case(args.case)
    func = _load_model(args.model)
    design = (
        grid(_ranges(args.grid, "--grid"))
        if args.grid
        else one_at_a_time(_ranges(args.oat, "--oat"))
    )
    res = run_sweep(func, base, design, executor=args.executor, max_workers=args.workers)
    if args.out:
        folder = out_dir(args.out, "results")
        res.write(folder, name=args.name)
        if res.outputs and len(res.failed) < len(res.frame):
            res.save_plot(folder / f"{args.name}.png")
    if args.json:
        print_json(res.frame.to_dict(orient="records"))
    else:
        cols = [c for c in res.frame.columns if not c.endswith(" [SI]") and c != "elapsed_s"]
        print(res.frame[cols].to_string(index=False))
        print(
            f"{len(res.frame)} cases, {res.n_failed} failed, {res.wall_time:.2f} s ({res.executor})"
        )
    return 0
