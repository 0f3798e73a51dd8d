"""``rotarykiln rtd``: residence time distributions from tracer data or for a case.

``rotarykiln rtd fit DATA.csv``: E(t), moments, moment-method and least-squares parameters of a
tracer curve (CSV: a time column with its unit in the header, e.g. ``time [min]``, and a signal
column). ``rotarykiln rtd predict CASE.yaml``: the predicted E(t) of the kiln of a case with an
``rtd:`` section. With ``--out DIR`` the results, a CSV and figures are written there (all files
are computed before any is written, so a failure writes nothing).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from rotarykiln.commands._args import add_quantity, check_out, get_quantity, out_dir, print_json
from rotarykiln.errors import InputError
from rotarykiln.report import format_table
from rotarykiln.studies.io import shown

FIT_MODELS = ("open-open", "closed-closed", "open-closed", "gaussian", "tanks-in-series")


def register(sub) -> None:
    p = sub.add_parser("rtd", help="residence time distribution: fit tracer data, predict a kiln")
    rsub = p.add_subparsers(dest="rtd_command", metavar="{fit,predict}")
    f = rsub.add_parser(
        "fit",
        help="fit an RTD model to a tracer curve (CSV)",
        description="Fit a dispersion model to a tracer curve. Example: rotarykiln rtd fit "
        "tracer.csv --model open-open --length 1.95 m --out fit-results",
    )
    f.add_argument("data", help='CSV file: time column with unit ("time [min]"), signal column')
    f.add_argument("--model", default="open-open", choices=FIT_MODELS, help="RTD model")
    f.add_argument("--time-unit", help="unit of the time column if its header has none")
    f.add_argument(
        "--kind",
        default="concentration",
        choices=("concentration", "mass_fraction", "conductivity", "tracer_mass"),
        help="what the signal column is",
    )
    f.add_argument("--baseline", help='background signal to subtract: a number or "auto"')
    add_quantity(f, "length", "kiln length, for the dispersion coefficient, e.g. 1.95 m")
    f.add_argument("--out", help="output folder (nothing written without it)")
    f.add_argument("--json", action="store_true", help="print JSON")
    f.set_defaults(func=run_fit)
    pr = rsub.add_parser(
        "predict",
        help="predicted RTD of the kiln of a case file",
        description="Predicted E(t) from the rtd: section of a case. Example: rotarykiln rtd "
        "predict kiln.yaml --out rtd-results",
    )
    pr.add_argument("case", help="case file (YAML) with an rtd: section, or a built-in case name")
    pr.add_argument("--out", help="output folder (nothing written without it)")
    pr.add_argument("--json", action="store_true", help="print JSON")
    pr.set_defaults(func=run_predict)
    p.set_defaults(func=_usage(p))


def _usage(parser):
    def show(args) -> int:
        parser.print_help()
        return 2

    return show


MAX_BASELINE = 1e15  # the largest tracer signal a file may hold (rtd.tracer.MAX_SIGNAL)


def _baseline(text):
    if text is None or text == "auto":
        return text
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not abs(value) <= MAX_BASELINE:  # also NaN and inf
        raise InputError(
            "--baseline",
            shown(text),
            f'a finite number in [-{MAX_BASELINE:g}, {MAX_BASELINE:g}] or "auto"',
        )
    return value


def _fit_figure(fit):
    import matplotlib.pyplot as plt

    from rotarykiln.rtd.plots import parity_plot

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    fit.plot(a1)
    mask = fit.data > 0.05 * fit.data.max()
    parity_plot(fit.data[mask] * 60, fit.fitted[mask] * 60, a2, quantity="E(t) (1/min)")
    fig.tight_layout()
    return fig


def run_fit(args: argparse.Namespace) -> int:
    from rotarykiln.case import Length
    from rotarykiln.commands.sweep import check_printable
    from rotarykiln.rtd.fitting import fit_tracer
    from rotarykiln.rtd.tracer import analyse_tracer, read_tracer_csv

    check_printable(args, ("data",))
    if args.time_unit is not None:  # checked even when the header gives the unit
        from rotarykiln.units import to_si

        unit = args.time_unit.strip()
        if not unit or unit[0].isdigit() or shown(unit) != unit:
            raise InputError("--time-unit", shown(args.time_unit), "a unit of time (s, min, h)")
        to_si("--time-unit", f"1 {unit}", "time")
    length = get_quantity(args, "length", "length", within=Length)
    baseline = _baseline(args.baseline)
    check_out(args.out)  # writable, before the fit; created only if there is a result
    # at most MAX_DATA_ROWS samples (studies.io): the tables written are as bounded
    t, signal, name = read_tracer_csv(args.data, time_unit=args.time_unit)
    tracer = analyse_tracer(t, signal, kind=args.kind, baseline=baseline)
    fit = fit_tracer(tracer, model=args.model, length=length)
    summary = {"data": str(args.data), "signal": name, "samples": int(t.size)}
    summary.update(
        {
            "data_mean_s": tracer.mean,
            "data_variance_s2": tracer.variance,
            "data_sigma_theta2": tracer.sigma_theta2,
            "unaccounted_fraction": tracer.unaccounted_fraction,
        }
    )
    summary.update(fit.summary())
    if args.out:
        _write_all(
            out_dir(args.out, "rtd-fit"),
            {"fit.json": summary, "fit.csv": fit.to_frame(), "fit.png": _fit_figure(fit)},
        )
    _show(summary, args.json)
    return 0


def run_predict(args: argparse.Namespace) -> int:
    from rotarykiln.case import load_case
    from rotarykiln.commands.model_runs import predict_from_case
    from rotarykiln.commands.run import case_path
    from rotarykiln.commands.sweep import check_printable

    check_printable(args, ("case",))
    case = load_case(case_path(args.case))
    check_out(args.out)
    pred = predict_from_case(case)
    summary = {"case": case.name, **pred.summary()}
    if args.out:
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4))
        pred.plot(ax)
        _write_all(
            out_dir(args.out, f"{Path(args.case).stem}-rtd"),
            {"prediction.json": summary, "prediction.csv": pred.to_frame(), "prediction.png": fig},
        )
    _show(summary, args.json)
    return 0


def _write_all(folder: Path, items: dict) -> None:
    """Write every output (each atomically); called only once all of them are computed."""
    import matplotlib.pyplot as plt

    from rotarykiln.outputs import save_figure_atomic, write_frame_atomic, write_json_atomic

    for name, obj in items.items():
        if name.endswith(".json"):
            write_json_atomic(folder / name, obj)
        elif name.endswith(".csv"):
            write_frame_atomic(folder / name, obj)
        else:
            save_figure_atomic(folder / name, obj)
            plt.close(obj)


def _show(summary: dict, as_json: bool) -> None:
    if as_json:
        print_json(summary)
        return
    flat = {k: v for k, v in summary.items() if not isinstance(v, dict | list)}
    for key, value in summary.items():
        if isinstance(value, list):
            flat[key] = "[" + ", ".join(f"{v:.5g}" for v in value) + "]"
        elif isinstance(value, dict):
            flat.update({f"{key}.{k}": v for k, v in value.items()})
    print(format_table(flat))
