"""``rotarykiln sensitivity``: Sobol or Morris indices of one scalar output of a model, or
Monte Carlo uncertainty bands (``--method uncertainty``).

The parameters are case fields with distributions (``--param PATH=DIST(ARGS)``: uniform,
normal, lognormal, triangular); the cases run on local processes or Dask and are stored in
OUT/runs (a second run resumes). Writes OUT/indices.csv, OUT/indices.json and the tornado chart
OUT/sensitivity.png. With ``--method uncertainty`` (no ``--output``): the nominal case and N
Latin-hypercube samples; OUT/scalars.csv (nominal, mean, sd, 5-50-95 % of every scalar output),
OUT/bands.csv and OUT/uncertainty.png (5-95 % bands of the axial profiles around the nominal;
use ``--model kiln_profiles``).

Example::

    rotarykiln sensitivity tscheng_A16 --model kiln --method sobol \\
        --param "operation.speed=uniform(1 rpm, 3 rpm)" \\
        --param "gas.temperature=normal(535 K, 10 K)" \\
        --param "gas.flow=uniform(20 kg/h, 30 kg/h)" \\
        --output bed_outlet_temperature_K --n 64 --out sens/

    rotarykiln sensitivity tscheng_A16 --model kiln_profiles --method uncertainty \\
        --param "gas.temperature=normal(535 K, 10 K)" --n 100 --out unc/
"""

from __future__ import annotations

import argparse

from rotarykiln.commands._args import check_count, out_dir, plain, print_json
from rotarykiln.commands.sweep import (
    MAX_CASES,
    _load_case,
    _load_model,
    add_study_options,
    check_design_values,
    check_printable,
    check_study_options,
    report_warnings,
    runner_options,
)
from rotarykiln.errors import InputError
from rotarykiln.outputs import write_frame_atomic, write_json_atomic
from rotarykiln.studies.design import as_params, check_design_size
from rotarykiln.studies.sensitivity import METHODS, morris_indices, sobol_indices
from rotarykiln.studies.uncertainty import propagate

__all__ = ["register", "run"]


def register(sub) -> None:
    p = sub.add_parser(
        "sensitivity",
        help="Sobol or Morris sensitivity indices of a model output over case-field distributions",
        description=plain(__doc__),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("case", help="case YAML file or built-in case name")
    p.add_argument(
        "--model", required=True, help="kiln, kiln_profiles, transport or module:function"
    )
    p.add_argument("--method", choices=(*METHODS, "uncertainty"), default="sobol")
    p.add_argument("--output", help="name of the scalar output analysed (sobol, morris)")
    p.add_argument(
        "--n",
        type=int,
        default=64,
        help="Sobol: base sample (cases = n (d + 2)); Morris: trajectories (n (d + 1)); "
        "uncertainty: samples",
    )
    p.add_argument("--levels", type=int, default=4, help="Morris grid levels")
    add_study_options(p)
    p.add_argument("--json", action="store_true", help="print the indices as JSON")
    p.add_argument("--out", help="output folder (default: sensitivity/)")
    p.set_defaults(func=run)


def check_param_ranges(base: dict, params, model: str) -> None:
    """The extremes of each --param distribution (0.1 % and 99.9 % points) set alone on the
    case and validated (:func:`rotarykiln.commands.sweep.check_design_values`)."""
    from rotarykiln.studies.design import CaseSpec

    design = []
    for p in params:
        for u in (1e-3, 1 - 1e-3):
            value = float(p.ppf([u])[0])
            design.append(CaseSpec(0, {p.path: f"{value!r} {p.unit}".strip()}))
    check_design_values(base, design, "--param", model)


MIN_N = {"sobol": 2, "morris": 2, "uncertainty": 2}
"""Smallest --n of each method (Sobol and Morris: two base samples or trajectories; uncertainty:
two samples for a standard deviation)."""
CASES = {"sobol": ("n (d + 2)", 2), "morris": ("n (d + 1)", 1), "uncertainty": ("n + 1", None)}
"""How many cases each method runs for --n = n and d parameters."""


def design_cases(method: str, n: int, d: int) -> int:
    """Cases run by ``method`` for ``--n n`` and ``d`` parameters."""
    extra = CASES[method][1]
    return n + 1 if extra is None else n * (d + extra)


def run(args) -> int:
    check_printable(args, ("case",))
    if not args.param:
        raise InputError("--param", message="--param: missing (at least one PATH=DIST(ARGS))")
    check_count("--n", args.n, MIN_N[args.method], MAX_CASES)
    check_study_options(args)
    params = as_params(args.param)
    check_design_size(
        design_cases(args.method, args.n, len(params)),
        "--n",
        f"{args.method}: {CASES[args.method][0]} with n = {args.n}, d = {len(params)}",
    )
    base = _load_case(args.case)
    func = _load_model(args.model)
    check_param_ranges(base, params, args.model)
    if args.method != "uncertainty" and not args.output:
        raise InputError(
            "--output", message=f"--output: missing (required with --method {args.method})"
        )
    if args.method == "morris" and (args.levels < 2 or args.levels % 2):
        raise InputError("--levels", args.levels, "an even whole number >= 2")
    folder = out_dir(args.out, "sensitivity")
    opts = runner_options(args, folder)
    if args.method == "uncertainty":
        return _uncertainty(args, func, base, params, folder, opts)
    if args.method == "sobol":
        res = sobol_indices(func, base, params, args.output, args.n, seed=args.seed, **opts)
    else:
        res = morris_indices(
            func, base, params, args.output, args.n, levels=args.levels, seed=args.seed, **opts
        )
    report_warnings(res.sweep, "sensitivity")
    table = res.to_frame()
    write_frame_atomic(folder / "indices.csv", table)
    summary = {
        "method": res.method,
        "output": res.output,
        "cases": len(res.sweep.frame),
        "parameters": [str(p) for p in res.params],
        "ranking": res.ranking(),
        "indices": table.to_dict(orient="records"),
    }
    write_json_atomic(folder / "indices.json", summary)
    res.save_plot(folder / "sensitivity.png")
    if args.json:
        print_json(summary)
    else:
        print(table.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
        extra = ""
        if res.method == "sobol":
            extra = f"; sum of S1 = {table['S1'].sum():.3f}"
        print(
            f"{res.method} indices of {res.output} from {len(res.sweep.frame)} cases "
            f"({res.sweep.meta.get('reused', 0)} from the store){extra}; written to {folder}/"
        )
    return 0


def _uncertainty(args, func, base, params, folder, opts) -> int:
    res = propagate(func, base, params, args.n, seed=args.seed, **opts)
    report_warnings(res.sweep, "sensitivity")
    scalars = res.scalars()
    write_frame_atomic(folder / "scalars.csv", scalars)
    if res.quantities:
        write_frame_atomic(folder / "bands.csv", res.to_frame())
        res.save_plot(folder / "uncertainty.png")
    summary = {
        "method": "uncertainty",
        "cases": len(res.samples),
        "failed": res.n_failed,
        "parameters": [str(p) for p in res.params],
        "profiles": res.quantities,
        "scalars": scalars.to_dict(orient="records"),
    }
    write_json_atomic(folder / "uncertainty.json", summary)
    if args.json:
        print_json(summary)
    else:
        print(scalars.to_string(index=False, float_format=lambda v: f"{v:.5g}"))
        print(
            f"Monte Carlo over {len(res.samples)} samples ({res.n_failed} failed); "
            f"profiles: {', '.join(res.quantities) or 'none'}; written to {folder}/"
        )
    return 0
