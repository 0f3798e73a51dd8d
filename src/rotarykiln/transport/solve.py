"""Choose and run a bed-profile model by name: the entry point for case files and the kiln model."""

from __future__ import annotations

import numbers

from rotarykiln.errors import InputError
from rotarykiln.transport.kramers import kramers_profile
from rotarykiln.transport.scott import scott_profile
from rotarykiln.transport.weirs import Weir, dam_radius_from_height

__all__ = ["N_POINTS_RANGE", "solve_bed"]

N_POINTS_RANGE = (2, 100_000)
"""Accepted numbers of output points along the drum (inclusive)."""


def solve_bed(
    *,
    model,
    diameter,
    length,
    speed,
    slope,
    feed,
    density,
    repose,
    static_repose=None,
    dam=None,
    weirs=(),
    friction="static",
    n_points=201,
):
    """Run the chosen bed model (``"kramers"`` or ``"scott"``) on SI inputs; return a BedProfile.

    Parameters are SI: diameter, length, dam (height above the wall) in m; speed in rad/s; slope and
    angles of repose in rad; feed in kg/s; density (bulk) in kg/m3. ``weirs`` is a sequence of
    (distance from the discharge m, height m) pairs (Scott's model only); ``n_points``, the
    output points along the drum, an integer in :data:`N_POINTS_RANGE`.
    """
    low, high = N_POINTS_RANGE
    if (
        isinstance(n_points, bool)
        or not isinstance(n_points, numbers.Integral)
        or not low <= n_points <= high
    ):
        raise InputError("n_points", n_points, f"an integer in [{low}, {high}]")
    radius = diameter / 2.0
    if dam is not None and dam > 0:
        dam_radius_from_height(dam, radius, "dam")
    if model == "kramers":
        if weirs:
            raise InputError(
                "weirs", message="weirs: given with the kramers model; they need the scott model"
            )
        return kramers_profile(
            feed,
            density=density,
            length=length,
            radius=radius,
            speed=speed,
            slope=slope,
            repose=repose,
            dam_height=dam,
            n_points=n_points,
        )
    return scott_profile(
        feed,
        density=density,
        length=length,
        radius=radius,
        speed=speed,
        slope=slope,
        dynamic_angle=repose,
        static_angle=static_repose if static_repose is not None else repose,
        discharge_radius=None if not dam else radius - dam,
        weirs=[Weir.from_height(p, h, radius) for p, h in weirs],
        friction=friction,
        n_points=n_points,
    )
