"""``rotarykiln transverse CASE``: grid simulation of mixing, segregation and heating (ch 8-9).

CASE is a YAML case file with a ``transverse:`` section or a built-in case name such as
``retort/case02`` (Table 9.2 of Van Puyvelde 1999). Writes to ``--out DIR``: the time series
(``timeseries.csv``), a summary (``summary.json``), figures of the extent of mixing, mean
temperatures and volatile evolution, the stagnant-layer mean sizes, grid colour maps at the
snapshot times, and with ``--gif`` an animation of the temperature field.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rotarykiln.commands._args import add_quantity, get_quantity, out_dir, print_json
from rotarykiln.errors import InputError

__all__ = ["register", "run"]


MAX_DURATION = 3600.0  # s, longest simulated time of the transverse grid


def register(sub) -> None:
    p = sub.add_parser(
        "transverse",
        help="transverse mixing, segregation and solid-to-solid heating (retort zone)",
        description="Example: rotarykiln transverse retort/case02 --out results/case02",
    )
    p.add_argument("case", help="case YAML file, or a built-in case name (retort/case01..16)")
    p.add_argument("--out", help="output folder (default: transverse_<case name>)")
    add_quantity(p, "duration", 'override the simulated time, e.g. "60 s"')
    p.add_argument("--gif", action="store_true", help="also write an animated GIF (Pillow)")
    p.add_argument("--no-plots", action="store_true", help="skip the figures")
    p.add_argument("--json", action="store_true", help="print the summary as JSON")
    p.set_defaults(func=run)


def _load(name: str):
    from rotarykiln.case import load_case
    from rotarykiln.cases import builtin_case_path

    path = Path(name)
    if path.suffix in (".yaml", ".yml") or path.exists():
        return load_case(path), path.stem
    return load_case(builtin_case_path(name)), name.replace("/", "_")


def run(args: argparse.Namespace) -> int:
    import dataclasses

    import numpy as np

    from rotarykiln.outputs import save_figure_atomic, write_frame_atomic, write_json_atomic
    from rotarykiln.transverse.retort import run_retort

    case, stem = _load(args.case)
    spec = retort_spec_from_case(case)
    if args.duration:
        duration = get_quantity(args, "duration", "time")
        if not 0 < duration <= MAX_DURATION:
            raise InputError(
                "--duration",
                message=f"--duration: {' '.join(args.duration)} is not in (0, 1 h] "
                "(the retort-zone grid advances in sub-second steps)",
            )
        spec = dataclasses.replace(spec, duration=duration)
    snaps = tuple(t for t in spec.snapshot_times if t <= spec.duration)
    map_times = snaps
    if args.gif:
        snaps = tuple(sorted(set(snaps) | set(np.arange(0.0, spec.duration + 1e-9, 1.0))))
    spec = dataclasses.replace(spec, snapshot_times=snaps)
    result = run_retort(spec)
    folder = out_dir(args.out, f"transverse_{stem}")
    write_frame_atomic(folder / "timeseries.csv", result.to_frame(), index=False)
    summary = {
        "case": spec.name,
        "active_layer_velocity_m_s": result.geometry.v_al,
        "lowest_cv_velocity_m_s": float(
            result.geometry.cv_velocity.min() * result.geometry.velocity_factor
        ),
        "time_step_s": result.time_step,
        "final_contact_distance_eq6_11_m": result.final_contact_bed,
        # contact over the eq 6.11 final contact: may pass 100 % before the bed de-mixes
        "peak_contact_over_final_contact_percent": float(100 * result.extent.max()),
        "mixing_time_s": result.mixing_time,
        "final_shale_temperature_K": float(result.temperature[-1, 1]),
        "final_ash_temperature_K": float(result.temperature[-1, 0]),
        "volatiles_at_30s_percent": float(100 * np.interp(30.0, result.t, result.volatiles)),
        "final_volatiles_percent": float(100 * result.volatiles[-1]),
        "mass_balance_max_relative_error": result.mass_error,
        "energy_balance_max_relative_error": result.energy_error,
    }
    write_json_atomic(folder / "summary.json", summary)
    if not args.no_plots:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        from rotarykiln.transverse.grid_plot import (
            animate_grid,
            plot_colour_map,
            plot_layer_sizes,
        )

        fig = result.plot()
        save_figure_atomic(folder / "time_series.png", fig, dpi=90)
        plt.close(fig)
        ax = plot_layer_sizes(result)
        save_figure_atomic(folder / "layer_sizes.png", ax.figure, dpi=90)
        plt.close(ax.figure)
        for t in map_times:
            fig, axes = plt.subplots(1, 3, figsize=(13, 3))
            for a, field in zip(axes, ("extent", "size", "temperature"), strict=True):
                plot_colour_map(result, t, field, ax=a)
            save_figure_atomic(folder / f"grid_{t:06.1f}s.png", fig, dpi=80)
            plt.close(fig)
        if args.gif:
            animate_grid(result, folder / "temperature.gif", "temperature")
    if args.json:
        print_json(summary)
    else:
        for k, v in summary.items():
            print(f"{k:34s} {v:.6g}" if isinstance(v, float) else f"{k:34s} {v}")
        print(f"outputs written to {folder}")
    return 0


def retort_spec_from_case(case):
    """Build a :class:`~rotarykiln.transverse.retort.RetortSpec` from a validated Case.

    Raises
    ------
    InputError
        When the case has no ``transverse`` section or no ``bed.fill``.
    """
    from rotarykiln.transverse.retort import RetortSpec

    sec = case.transverse
    if sec is None:
        raise InputError("transverse", message="transverse: missing (required section)")
    if case.bed is None or case.bed.mean_fill is None:
        raise InputError("bed.fill", message="bed.fill: missing (required for transverse)")
    kw = dict(
        name=case.name,
        drum_diameter=case.kiln.diameter,
        omega=case.operation.speed,
        fill=case.bed.mean_fill,
        shale_size=sec.shale.mean_size,
        ash_size=sec.ash.mean_size,
        shale_temperature=sec.shale.temperature,
        ash_temperature=sec.ash.temperature,
        shale_to_ash=sec.shale_to_ash,
        duration=sec.duration,
        distribution=sec.distribution,
        voidage=sec.voidage,
        emissivity=sec.emissivity,
        balance=sec.balance,
        layers=sec.grid.layers,
        zones=sec.grid.zones,
        segregation=sec.segregation,
        snapshot_times=tuple(sec.snapshot_times),
    )
    for feed, prefix in ((sec.shale, "shale"), (sec.ash, "ash")):
        if feed.bulk_density is not None:
            kw[f"{prefix}_bulk_density"] = feed.bulk_density
        if feed.heat_capacity is not None:
            kw[f"{prefix}_cp"] = feed.heat_capacity
    return RetortSpec(**kw)
