"""Couplings between the physics packages, made from a case file.

- the axial transport model (``transport:`` section) gives the bed fill along the kiln to the heat
  model, and the mean residence time to the RTD prediction;
- :func:`rtd_runner` is the ``rotarykiln run`` runner of the ``rtd:`` section that supplies that
  mean residence time when the case has a ``transport:`` section and no given one.

:func:`transport_run` and :func:`rtd_run` (like :func:`rotarykiln.commands.kiln_runs.kiln_run`) solve one
model of a case in memory and return a :class:`ModelRun`: the result, its summary values and how
to write its files. ``rotarykiln run`` and :func:`rotarykiln.run` both go through them.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from rotarykiln.errors import InputError

__all__ = [
    "ModelRun",
    "bed_fill_profile",
    "bed_profile_from_case",
    "rtd_run",
    "rtd_runner",
    "transport_mean_residence_time",
    "transport_run",
]


@dataclasses.dataclass(frozen=True)
class ModelRun:
    """One model of a case, solved in memory (one entry of ``rotarykiln run``'s models).

    ``model``: its name (``"transport"``, ``"kiln"``, ``"rtd"``); ``value``: its result object
    (a bed profile, a kiln solution, an RTD prediction); ``summary``: its summary values (the
    keys ``rotarykiln run`` writes to ``summary.json``, files aside); ``write(out)`` writes its
    files into the folder ``out`` and returns the summary entries naming them; ``extra``: other
    results (the kiln's ``residence``-time effects).
    """

    model: str
    value: Any
    summary: dict
    write: Callable[[Path], dict] = dataclasses.field(repr=False)
    extra: dict = dataclasses.field(default_factory=dict, repr=False)


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


def transport_run(case) -> ModelRun:
    """The ``transport:`` model of a case (its bed profile), solved in memory.

    Its files (``profile.csv``, ``profile.png``) are those of ``rotarykiln bed --out``.
    """
    profile = bed_profile_from_case(case)
    summary = {
        "transport_model": profile.model,
        "transport_mean_fill": profile.mean_fill,
        "transport_holdup_kg": profile.holdup_mass,
        "transport_mean_residence_time_min": profile.mean_residence_time / 60.0,
        "transport_discharge_fill": profile.discharge_fill,
    }

    def write(out) -> dict:
        from rotarykiln.commands.bed import _write

        return {f"transport_{k}": v for k, v in _write(profile, Path(out)).items()}

    return ModelRun("transport", profile, summary, write)


def rtd_run(case) -> ModelRun:
    """The ``rtd:`` section of a case (its predicted E(t)), solved in memory, with the transport
    model's mean residence time when the case has a ``transport:`` section (and no given
    ``rtd.mean_residence_time``)."""
    from rotarykiln.rtd.predict import predict_from_case, run_section

    taus: list[float] = []

    def transport(c) -> float:  # solved once, for the prediction and its files
        if not taus:
            taus.append(transport_mean_residence_time(c))
        return taus[0]

    hook = transport if case.transport is not None else None
    prediction = predict_from_case(case, transport=hook)
    return ModelRun(
        "rtd",
        prediction,
        prediction.summary(),
        lambda out: run_section(case, Path(out), transport=hook),
    )


def rtd_runner(case, out) -> dict:
    """``rotarykiln run`` runner of the ``rtd:`` section (:func:`rtd_run`, files written to
    ``out``); returns its summary."""
    run = rtd_run(case)
    return {**run.summary, **run.write(Path(out))}
