"""``rotarykiln regime``: Froude number, critical speed and the transverse bed regime."""

from __future__ import annotations

import argparse

from rotarykiln.commands._args import add_quantity, get_quantity, print_json
from rotarykiln.commands.geometry import radius_from_args
from rotarykiln.errors import InputError
from rotarykiln.geometry import fill_from_depth
from rotarykiln.report import format_table, regime_summary


def register(sub) -> None:
    p = sub.add_parser(
        "regime",
        help="Froude number, critical speed and bed regime",
        description="Example: rotarykiln regime --diameter 6 m --speed 5 rpm --fill 0.3",
    )
    add_quantity(p, "diameter", "drum inner diameter, e.g. 6 m")
    add_quantity(p, "radius", "drum inner radius (instead of --diameter)")
    add_quantity(p, "speed", "rotation speed, e.g. 5 rpm")
    add_quantity(p, "fill", "fill fraction in (0, 1)")
    add_quantity(p, "depth", "bed depth (instead of --fill)")
    add_quantity(p, "repose", "dynamic angle of repose (with --wall-friction)")
    p.add_argument("--wall-friction", type=float, help="wall friction coefficient (-)")
    p.add_argument(
        "--criterion",
        choices=["mellmann", "henein"],
        default="mellmann",
        help="regime criterion: Froude bands with fill (Mellmann 2001, default) or fraction of "
        "critical speed (Henein 1983)",
    )
    p.add_argument("--plot", metavar="FILE", help="write the regime map to FILE (png, pdf, svg)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    radius = radius_from_args(args)
    speed = get_quantity(args, "speed", "rotation rate", required=True)
    if not speed > 0:
        raise InputError(
            "--speed", message=f"--speed: {' '.join(args.speed)} is not > 0 (a drum that turns)"
        )
    from rotarykiln.case import Length, ReposeAngle, RotationRate

    get_quantity(args, "speed", "rotation rate", within=RotationRate)  # its physical range
    fill = get_quantity(args, "fill", "fraction")
    depth = get_quantity(args, "depth", "length", within=Length)
    if (fill is None) == (depth is None):
        raise InputError("--fill", message="--fill/--depth: give exactly one of them")
    if fill is None:
        if not 0 < depth < 2 * radius:
            raise InputError(
                "--depth", message=f"--depth: {depth:g} m is not in (0, {2 * radius:g}) m"
            )
        fill = float(fill_from_depth(depth, radius))
    if not 0 < fill < 1:
        raise InputError("--fill", message=f"--fill: {' '.join(args.fill)} is not in (0, 1)")
    repose = get_quantity(args, "repose", "angle", within=ReposeAngle)
    wall_friction = args.wall_friction
    if wall_friction is not None and not 0 <= wall_friction <= 10:
        raise InputError(
            "--wall-friction", message=f"--wall-friction: {wall_friction} is not in [0, 10]"
        )
    summary = regime_summary(
        radius,
        speed,
        fill,
        criterion=args.criterion,
        wall_friction=wall_friction,
        repose_angle=repose,
    )
    if args.plot:
        from rotarykiln.outputs import save_figure_atomic
        from rotarykiln.plot import regime_map_figure

        save_figure_atomic(args.plot, regime_map_figure(fill, summary["froude"]))
    if args.json:
        print_json(summary)
    else:
        print(format_table(summary))
    return 0
