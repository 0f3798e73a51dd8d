"""``rotarykiln calibrate``: fit case fields to measured data by weighted least squares.

The data are a CSV with columns quantity, z, value, uncertainty: bed, gas, wall or shell
temperatures at positions z (m from the solids inlet) or a scalar output of the model with z
empty (e.g. bed_outlet_temperature_K); values and uncertainties (one standard deviation) in the
output's unit (K). Each ``--fit PATH=START [LOW, HIGH]`` is a case field to fit, with its unit.
Writes OUT/parameters.csv (value, standard error, 95 % interval), OUT/correlation.csv,
OUT/residuals.csv, the residual plot OUT/residuals.png, OUT/calibration.json and the calibrated
case OUT/calibrated.yaml (values with their units).

Several cases (operating points) with the same fitted fields: give them all (``NAME=FILE`` or
built-in names, e.g. ``tscheng_A16``) and name each point's case in a ``case`` column of
the data; the covariance is then scaled by chi2/dof unless ``--absolute-uncertainty``.

Example::

    rotarykiln calibrate tscheng_A16 --model kiln_profiles --data plant.csv \\
        --fit "gas.flow=20 kg/h [5 kg/h, 60 kg/h]" --fit "wall.emissivity=0.8 [0.3, 1]" \\
        --out cal/
"""

from __future__ import annotations

import argparse

from rotarykiln.commands._args import check_count, check_out, out_dir, plain, print_json
from rotarykiln.commands.sweep import _load_case, _load_model, check_printable
from rotarykiln.errors import InputError
from rotarykiln.outputs import write_frame_atomic, write_json_atomic
from rotarykiln.studies.calibration import (
    calibrate,
    calibrate_cases,
    parse_fit,
    read_measurements,
)

__all__ = ["register", "run"]


def register(sub) -> None:
    p = sub.add_parser(
        "calibrate",
        help="fit case fields to measured temperatures or outlet values (weighted least squares)",
        description=plain(__doc__),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "case",
        nargs="+",
        help="case YAML file or built-in case name; several (NAME=FILE) for a joint fit",
    )
    p.add_argument(
        "--model", default="kiln_profiles", help="kiln_profiles (default), kiln or module:function"
    )
    p.add_argument("--data", required=True, help="CSV: quantity, z, value, uncertainty")
    p.add_argument(
        "--fit",
        action="append",
        required=True,
        metavar="PATH=START [LOW, HIGH]",
        help='a field to fit, e.g. "gas.flow=20 kg/h [5 kg/h, 60 kg/h]" (repeatable)',
    )
    p.add_argument(
        "--relative-uncertainty",
        action="store_true",
        help="the uncertainties are only relative weights: scale the covariance by chi2/dof "
        "(the default with several cases)",
    )
    p.add_argument(
        "--absolute-uncertainty",
        action="store_true",
        help="with several cases: the uncertainties are standard deviations",
    )
    p.add_argument("--workers", type=int, default=1, help="processes (several cases)")
    p.add_argument("--max-evaluations", type=int, default=200, help="most model evaluations")
    p.add_argument("--json", action="store_true", help="print the result as JSON")
    p.add_argument("--out", help="output folder (default: calibration/)")
    p.set_defaults(func=run)


def run(args) -> int:
    check_printable(args, ("case",))
    check_count("--workers", args.workers, 1, 1024)
    check_count("--max-evaluations", args.max_evaluations, 1, 1_000_000)
    params = [parse_fit(f) for f in args.fit]
    check_out(args.out or "calibration")  # writable, checked before the fit
    data = read_measurements(args.data)  # within the data-file limits: one line if bad
    func = _load_model(args.model)
    if len(args.case) == 1:
        res = calibrate(
            func,
            _load_case(args.case[0]),
            params,
            data,
            absolute_sigma=not args.relative_uncertainty,
            max_nfev=args.max_evaluations,
        )
    else:
        cases = {}
        for item in args.case:
            name, sep, spec = item.partition("=")
            if not sep:
                name, spec = item, item
            if name in cases:
                raise InputError("case", name, "given once")
            cases[name] = _load_case(spec)
        res = calibrate_cases(
            func,
            cases,
            params,
            data,
            absolute_sigma=args.absolute_uncertainty,
            max_nfev=args.max_evaluations,
            workers=args.workers,
        )
    folder = out_dir(args.out, "calibration")
    table = res.to_frame()
    write_frame_atomic(folder / "parameters.csv", table)
    write_frame_atomic(folder / "correlation.csv", res.correlation, index=True)
    write_frame_atomic(folder / "residuals.csv", res.residuals)
    res.save_plot(folder / "residuals.png")
    res.write_case(folder / "calibrated.yaml")
    for name, case in res.cases.items():  # a joint fit: every calibrated case
        res.write_case(folder / f"calibrated_{name.replace('/', '_')}.yaml", case)
    summary = res.summary()
    write_json_atomic(folder / "calibration.json", summary)
    if args.json:
        print_json(summary)
    else:
        print(table.to_string(index=False, float_format=lambda v: f"{v:.6g}"))
        if len(params) > 1:
            print("correlation:")
            print(res.correlation.to_string(float_format=lambda v: f"{v:.3f}"))
        for p, hit in zip(res.params, res.at_bound, strict=False):
            if hit:
                print(f"note: {p.path} ended on a bound: widen it; its interval is not meaningful")
        print(
            f"{summary['points']} points, chi2/dof = {res.reduced_chi2:.3g}, rms residual "
            f"{summary['rms_residual']:.3g}, {res.nfev} model runs ({res.message}); "
            f"written to {folder}/ (calibrated case: calibrated.yaml)"
        )
    return 0 if res.success else 1
