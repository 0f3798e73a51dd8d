"""Couplings between the physics packages, made from a case file.

- the axial transport model (``transport:`` section) gives the bed fill along the kiln to the heat
  model, and the mean residence time to the RTD prediction;
- :func:`rtd_runner` is the ``rotarykiln run`` runner of the ``rtd:`` section that supplies that
  mean residence time when the case has a ``transport:`` section and no given one.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError

__all__ = [
    "bed_fill_profile",
    "bed_profile_from_case",
    "rtd_runner",
    "transport_mean_residence_time",
]


def bed_profile_from_case(case, *, n_points: int | None = None):
    """The :class:`~rotarykiln.transport.result.BedProfile` of the case's ``transport:`` model."""
    from rotarykiln.transport.solve import solve_bed

    t, m, op, k = case.transport, case.material, case.operation, case.kiln
    if t is None:
        raise InputError("transport", None, "present (the case has no transport: section)")
    for field, value in (
        ("operation.feed", op.feed),
        ("material.bulk_density", m.bulk_density),
        ("material.repose_angle", m.repose_angle),
    ):
        if value is None:
            raise InputError(field, None, "given when a transport: section sets the bed")
    return solve_bed(
        model=t.model,
        diameter=k.diameter,
        length=k.length,
        speed=op.speed,
        slope=k.slope,
        feed=op.feed,
        density=m.bulk_density,
        repose=m.repose_angle,
        static_repose=m.static_repose_angle,
        dam=t.dam_height,
        weirs=[(w.position, w.height) for w in t.weirs],
        friction=t.friction,
        n_points=n_points or t.n_points,
    )


def bed_fill_profile(case) -> tuple[np.ndarray, np.ndarray]:
    """The local fill along the kiln from the case's ``transport:`` bed model, as ``(z, fill)``.

    This couples the axial transport model (Kramers or Scott, with dams and weirs) to the heat
    model: the bed depth, and with it every exchange area, follows the computed profile.
    """
    profile = bed_profile_from_case(case, n_points=max(case.transport.n_points, 401))
    return np.asarray(profile.z, dtype=float), np.asarray(profile.fill, dtype=float)


def transport_mean_residence_time(case) -> float:
    """Mean residence time (s) of the solids from the case's ``transport:`` model (hold-up / flow)."""
    return float(bed_profile_from_case(case).mean_residence_time)


def rtd_runner(case, out) -> dict:
    """``rotarykiln run`` runner of the ``rtd:`` section, with the transport model's mean residence
    time when the case has a ``transport:`` section (and no given ``rtd.mean_residence_time``)."""
    from rotarykiln.rtd.predict import run_section

    transport = transport_mean_residence_time if case.transport is not None else None
    return run_section(case, out, transport=transport)
