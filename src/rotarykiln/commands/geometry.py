"""``rotarykiln geometry``: the partly filled cross-section from one measure of the bed."""

from __future__ import annotations

import argparse
import math

from rotarykiln.commands._args import add_quantity, get_quantity, print_json
from rotarykiln.errors import InputError
from rotarykiln.geometry import CrossSection
from rotarykiln.report import format_table


def register(sub) -> None:
    p = sub.add_parser(
        "geometry",
        help="cross-section geometry from fill, depth, half-angle or chord",
        description="Bed cross-section: give the drum size and ONE of --fill, --depth, "
        "--half-angle, --chord. Example: rotarykiln geometry --diameter 0.4 m --fill 0.15",
    )
    add_quantity(p, "diameter", "drum inner diameter, e.g. 0.4 m")
    add_quantity(p, "radius", "drum inner radius (instead of --diameter)")
    add_quantity(p, "fill", "fill fraction in (0, 1), e.g. 0.15 or 15 %%")
    add_quantity(p, "depth", "bed depth at the chord middle, e.g. 5 cm")
    add_quantity(p, "half-angle", "half of the central angle of the bed, e.g. 40 deg")
    add_quantity(p, "chord", "bed surface width, e.g. 0.3 m (fill <= 0.5 assumed)")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(func=run)


def radius_from_args(args: argparse.Namespace) -> float:
    from rotarykiln.case import Length  # the physical range of a case file

    d = get_quantity(args, "diameter", "length")
    r = get_quantity(args, "radius", "length")
    if (d is None) == (r is None):
        raise InputError("--diameter", message="--diameter/--radius: give exactly one of them")
    radius = r if r is not None else d / 2
    name = "radius" if r is not None else "diameter"
    if radius <= 0:
        raise InputError(name, message=f"--{name}: {' '.join(getattr(args, name))} is not > 0")
    get_quantity(args, name, "length", within=Length)  # and in its physical range
    return radius


def run(args: argparse.Namespace) -> int:
    from rotarykiln.case import Length

    radius = radius_from_args(args)
    given = {
        "fill": get_quantity(args, "fill", "fraction"),
        "depth": get_quantity(args, "depth", "length", within=Length),
        "half-angle": get_quantity(args, "half-angle", "angle"),
        "chord": get_quantity(args, "chord", "length", within=Length),
    }
    present = [k for k, v in given.items() if v is not None]
    if len(present) != 1:
        raise InputError("--fill", message="--fill/--depth/--half-angle/--chord: give exactly one")
    key = present[0]
    value = given[key]
    if key == "fill":
        if not 0 < value < 1:
            raise InputError("--fill", message=f"--fill: {' '.join(args.fill)} is not in (0, 1)")
        cs = CrossSection.from_fill(value, radius)
    elif key == "depth":
        if not 0 < value < 2 * radius:
            raise InputError(
                "--depth", message=f"--depth: {value:g} m is not in (0, {2 * radius:g}) m"
            )
        cs = CrossSection.from_depth(value, radius)
    elif key == "half-angle":
        if not 0 < value < math.pi:
            raise InputError(
                "--half-angle",
                message=f"--half-angle: {' '.join(args.half_angle)} is not in (0, 180) deg",
            )
        cs = CrossSection.from_half_angle(value, radius)
    else:
        cs = CrossSection.from_chord(value, radius)
    data = {k: float(v) for k, v in cs.as_dict().items()}
    if args.json:
        print_json(data)
    else:
        print(format_table(data))
    return 0
