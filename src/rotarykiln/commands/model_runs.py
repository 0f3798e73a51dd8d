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
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from rotarykiln.errors import InputError, check_positive

__all__ = [
    "ModelRun",
    "bed_fill_profile",
    "bed_profile_from_case",
    "peclet_from_case",
    "predict_from_case",
    "rtd_run",
    "rtd_runner",
    "transport_mean_residence_time",
    "transport_run",
    "run_section",
    "write_bed_profile",
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
        return {f"transport_{k}": v for k, v in write_bed_profile(profile, Path(out)).items()}

    return ModelRun("transport", profile, summary, write)


def rtd_run(case) -> ModelRun:
    """The ``rtd:`` section of a case (its predicted E(t)), solved in memory, with the transport
    model's mean residence time when the case has a ``transport:`` section (and no given
    ``rtd.mean_residence_time``)."""

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


def write_bed_profile(profile, out) -> dict:
    """Write a bed profile's ``profile.csv``, ``summary.json`` and ``profile.png`` into the folder
    ``out``; return the summary entries naming the CSV and the figure."""
    import matplotlib

    from rotarykiln.outputs import save_figure_atomic, write_frame_atomic, write_json_atomic

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    write_frame_atomic(out / "profile.csv", profile.to_frame(), index=False)
    write_json_atomic(out / "summary.json", profile.summary())
    ax = profile.plot()
    save_figure_atomic(out / "profile.png", ax.figure, dpi=110, bbox_inches="tight")
    plt.close(ax.figure)
    return {"profile_csv": str(out / "profile.csv"), "profile_png": str(out / "profile.png")}


# --- the rtd: section of a case ------------------------------------------------------------


def _need(value, field: str, why: str):
    if value is None:
        raise InputError(field, "missing", f"given ({why})")
    return value


def peclet_from_case(case, mean_residence_time: float) -> tuple[float, str]:
    """Peclet number of a case from ``rtd.peclet`` or the chosen correlation, and its source."""
    from rotarykiln.rtd.correlations import (
        bongo_njeng_dispersion,
        holdup_fraction,
        sai_dispersion_number,
        sherritt_dispersion,
    )
    from rotarykiln.rtd.dispersion import get_model
    from rotarykiln.rtd.internals import lifter_cross_section, loading_lifter_area
    from rotarykiln.rtd.predict import check_peclet, tau_and_peclet

    sec, kiln, op, mat = case.rtd, case.kiln, case.operation, case.material
    if sec.peclet is not None:
        check_peclet("rtd.peclet", sec.peclet)
        return sec.peclet, "given"
    name = sec.correlation
    why = f"for the {name} correlation"
    if name == "sai1990":
        theta = sec.tracer_repose_angle or _need(mat.repose_angle, "material.repose_angle", why)
        rho = sec.tracer_density or _need(mat.bulk_density, "material.bulk_density", why)
        if not kiln.slope > 0:
            raise InputError("kiln.slope", kiln.slope, f"> 0 {why}")
        with np.errstate(all="ignore"):
            number = float(sai_dispersion_number(theta, kiln.slope, op.speed, rho))
            pe = 1.0 / number if number > 0 else math.inf
        check_peclet("rtd.peclet", pe, f" (from the {name} correlation; or give rtd.peclet)")
        return pe, name
    if name == "sherritt2003":
        dp = _need(mat.particle_size, "material.particle_size", why)
        x = sec.holdup_fraction
        if x is None:
            feed = _need(op.feed, "operation.feed", why + " without rtd.holdup_fraction")
            rho = _need(mat.bulk_density, "material.bulk_density", why)
            x = holdup_fraction(feed, mean_residence_time, rho, kiln.diameter, kiln.length)
        d = float(sherritt_dispersion(op.speed, kiln.diameter, dp, x))
    else:
        lifters = sec.lifters
        if lifters.type == "none":
            raise InputError(
                "rtd.lifters.type", "none", f"straight or rectangular {why} (D = 0 without lifters)"
            )
        beta = mat.static_repose_angle or _need(mat.repose_angle, "material.repose_angle", why)
        arm = 0.0 if lifters.type == "straight" else (lifters.arm or lifters.height)
        area = lifter_cross_section(kiln.diameter / 2, lifters.height, beta, arm=arm)
        d = float(
            bongo_njeng_dispersion(
                _need(op.feed, "operation.feed", why),
                _need(mat.bulk_density, "material.bulk_density", why),
                op.speed,
                kiln.slope,
                beta,
                _need(mat.particle_size, "material.particle_size", why),
                loading_lifter_area(lifters.count, area),
                kiln.diameter,
            )
        )
    if not (math.isfinite(d) and d > 0):
        raise InputError(
            "rtd.correlation",
            f"{name}, which gives D = {d:.3g} m2/s for this case",
            "a correlation giving a dispersion coefficient > 0 (check operation.feed and the "
            "material, or give rtd.peclet)",
        )
    source = f" from the {name} correlation (or give rtd.peclet)"
    _, pe = tau_and_peclet(
        get_model(sec.model), mean_residence_time, d, kiln.length, "rtd.peclet", source
    )
    return pe, name


def predict_from_case(case, *, transport: Callable | None = None):
    """Predicted E(t) of the kiln of a case (its ``rtd`` section).

    Parameters
    ----------
    case : rotarykiln.case.Case
        Validated case with an ``rtd`` section.
    transport : callable, optional
        ``transport(case) -> mean residence time [s]``, used when ``rtd.mean_residence_time`` is
        not given (the hook for the transport model).

    Returns
    -------
    RTDPrediction
    """
    from rotarykiln.rtd.predict import predict_rtd

    sec = case.rtd
    if sec is None:
        raise InputError("rtd", "missing", "an rtd: section in the case")
    mrt = sec.mean_residence_time
    if mrt is None:
        if transport is None:
            raise InputError(
                "rtd.mean_residence_time",
                "missing",
                "given (no transport model is available to compute it)",
            )
        mrt = float(transport(case))
        check_positive("mean residence time from the transport model", mrt, "s")
    pe, source = peclet_from_case(case, mrt)
    return predict_rtd(mrt, peclet=pe, length=case.kiln.length, model=sec.model, source=source)


def run_section(case, out, *, transport: Callable | None = None) -> dict:
    """Runner for ``rotarykiln run``: write rtd_prediction.csv/.png in ``out``, return a summary.

    ``transport`` is passed on to :func:`predict_from_case` (the kiln layer may supply it).
    """
    import matplotlib.pyplot as plt

    from rotarykiln.outputs import save_figure_atomic, write_frame_atomic

    pred = predict_from_case(case, transport=transport)
    fig, ax = plt.subplots(figsize=(6, 4))
    pred.plot(ax)
    ax.set_title(f"{case.name}: predicted RTD", fontsize="medium")
    fig.tight_layout()
    write_frame_atomic(out / "rtd_prediction.csv", pred.to_frame())
    save_figure_atomic(out / "rtd_prediction.png", fig)
    plt.close(fig)
    return pred.summary()
