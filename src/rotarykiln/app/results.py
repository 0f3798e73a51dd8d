"""What a run shows beyond the kiln's profiles, for each model of the case, small enough for the
page: the transport model's bed profile (``transport:``), the predicted residence time
distribution (``rtd:``) and the transverse results of the retort zone (``transverse:``).

:func:`model_results` is called by the run's worker process once the case has run: it reads the
tables the run wrote (``profile.csv``, ``rtd_prediction.csv``), thinned to
:data:`MAX_POINTS` rows, and runs the transverse grid as ``rotarykiln transverse`` does when
its estimated time is within :data:`TRANSVERSE_SECONDS` (else it gives the section's inputs and
the command that runs it). Everything it returns is plain data (lists, numbers, texts).
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from rotarykiln.errors import InputError

__all__ = [
    "MAX_POINTS",
    "MAX_TRANSVERSE_CVS",
    "MAX_TRANSVERSE_DURATION",
    "TRANSVERSE_SECONDS",
    "model_results",
    "thin_rows",
    "transverse_estimate",
    "transverse_inputs",
]

MAX_POINTS = 400
"""Most rows of a curve sent to the page (the tables for download keep every row)."""
TRANSVERSE_SECONDS = 12.0
"""Longest estimated time of a transverse grid run the app does, s (a built-in retort case:
about 2-3 s); a longer one is left to ``rotarykiln transverse``."""
MAX_TRANSVERSE_CVS = 2_000
"""Most stagnant control volumes (``grid.layers`` x ``grid.zones``) of a transverse run in the app."""
MAX_TRANSVERSE_DURATION = 3600.0
"""Longest simulated time of a transverse run, s (the limit of ``rotarykiln transverse``)."""
_SECONDS_PER_STEP_CV = 1.2e-6  # s per time step, control volume and size class (fitted on
# the 16 built-in retort cases: estimate within 20 % of the time taken)
_MIN_CLASSES = 5  # the per-step cost of a few size classes is mostly overhead

_BED_COLUMNS = ("z_m", "depth_m", "fill", "residence_time_s")
_RTD_COLUMNS = ("t_s", "E_1_s", "F")
_SERIES_COLUMNS = ("t_s", "extent_percent", "T_ash_K", "T_shale_K", "volatiles_percent")


def thin_rows(n: int, rows: int = MAX_POINTS) -> np.ndarray:
    """Indices of at most ``rows`` of ``n`` rows, evenly spaced, the first and the last kept.

    >>> thin_rows(5, 3).tolist()
    [0, 2, 4]
    >>> thin_rows(2).tolist()
    [0, 1]
    """
    if n <= rows:
        return np.arange(n)
    return np.unique(np.linspace(0, n - 1, rows).round().astype(int))


def _plain(values) -> list:
    return [float(v) if math.isfinite(float(v)) else None for v in values]


def _columns(path: Path, names: tuple[str, ...]) -> dict[str, list] | None:
    """The columns ``names`` of a CSV table the run wrote, thinned, else None (no such file)."""
    import pandas as pd

    if not path.is_file():
        return None
    frame = pd.read_csv(path)
    keep = thin_rows(len(frame))
    return {c: _plain(frame[c].to_numpy(dtype=float)[keep]) for c in names if c in frame}


def model_results(case, out: Path, source: str) -> dict[str, Any]:
    """The results of the case's transport, RTD and transverse models for the page.

    Parameters
    ----------
    case : Case
        The validated case that has just run into ``out``.
    out : path
        The run's folder (the transverse results are written there too:
        ``transverse_timeseries.csv``, ``transverse_summary.json``).
    source : str
        The case's name as the user knows it (a built-in case's name or a file name), for the
        command that runs a transverse case the app does not.

    Returns
    -------
    dict
        ``bed`` (columns of the bed profile), ``rtd`` (columns of E(t) and F(t)),
        ``transverse`` (:func:`transverse_results`), for the sections the case has.
    """
    out = Path(out)
    found: dict[str, Any] = {}
    if case.transport is not None:
        bed = _columns(out / "profile.csv", _BED_COLUMNS)
        if bed:
            found["bed"] = bed
    if case.rtd is not None:
        rtd = _columns(out / "rtd_prediction.csv", _RTD_COLUMNS)
        if rtd:
            found["rtd"] = rtd
    if case.transverse is not None:
        found["transverse"] = transverse_results(case, out, source)
    return found


def transverse_inputs(case) -> list[tuple[str, str, str]]:
    """The inputs of a case's transverse run as (label, value, unit) rows."""
    sec = case.transverse
    fill = case.bed.mean_fill if case.bed is not None else None
    rows = [
        ("Drum diameter", f"{case.kiln.diameter:.4g}", "m"),
        ("Rotation speed", f"{case.operation.speed * 60 / (2 * math.pi):.4g}", "rpm"),
        ("Fill", "not given" if fill is None else f"{100 * fill:.3g}", "" if fill is None else "%"),
        ("Simulated time", f"{sec.duration:.4g}", "s"),
        ("Shale to ash mass ratio", f"{sec.shale_to_ash:.3g}", "kg/kg"),
    ]
    for label, feed in (("Shale", sec.shale), ("Ash", sec.ash)):
        rows.append((f"{label} mean size", f"{1e3 * feed.mean_size:.3g}", "mm"))
        rows.append((f"{label} initial temperature", f"{feed.temperature:.1f}", "K"))
    rows.append(("Grid", f"{sec.grid.layers} layers x {sec.grid.zones} zones", "control volumes"))
    return rows


def transverse_estimate(spec) -> tuple[float, str]:
    """The estimated time of a transverse run (s) and, when the app does not run it, why
    (else ``""``).

    >>> from rotarykiln.transverse.retort import retort_case
    >>> seconds, why = transverse_estimate(retort_case(2))
    >>> 0.5 < seconds < TRANSVERSE_SECONDS and why == ""
    True
    """
    from rotarykiln.transverse.grid_geometry import build_grid
    from rotarykiln.transverse.retort import SIZE_CLASSES

    cvs = spec.layers * spec.zones
    if cvs > MAX_TRANSVERSE_CVS:
        return math.inf, (
            f"its grid has {cvs} control volumes ({spec.layers} layers x {spec.zones} zones), "
            f"more than the app runs (at most {MAX_TRANSVERSE_CVS})"
        )
    if spec.duration > MAX_TRANSVERSE_DURATION:
        return math.inf, (
            f"its simulated time, {spec.duration:g} s, is longer than the app runs "
            f"(at most {MAX_TRANSVERSE_DURATION:g} s)"
        )
    with warnings.catch_warnings():  # the run itself warns, once
        warnings.simplefilter("ignore")
        geom = build_grid(
            0.5 * spec.drum_diameter, spec.omega, spec.fill, layers=spec.layers, zones=spec.zones
        )
        step = geom.time_step()[0]
    equal = abs(spec.shale_size - spec.ash_size) < 1e-9
    single = spec.distribution == "single" or (spec.distribution == "auto" and equal)
    classes = 1 if single else len(SIZE_CLASSES)
    steps = spec.duration / step
    seconds = steps * (cvs + geom.n_active) * max(classes, _MIN_CLASSES) * _SECONDS_PER_STEP_CV
    if seconds > TRANSVERSE_SECONDS:
        return seconds, (
            f"it would take about {seconds:.0f} s ({steps:.3g} time steps of "
            f"{1e3 * step:.3g} ms over {spec.duration:g} s), longer than the app runs "
            f"(at most {TRANSVERSE_SECONDS:g} s)"
        )
    return seconds, ""


def transverse_results(case, out: Path, source: str) -> dict[str, Any]:
    """The transverse run of a case as ``rotarykiln transverse`` computes it (its time series,
    thinned, and its summary), or, when the app does not run it, why and the command that does.

    Returns
    -------
    dict
        ``inputs`` (rows of :func:`transverse_inputs`), ``command``; and ``series`` (columns)
        with ``summary`` (name -> value) when run, else ``skipped`` (a sentence).
    """
    from rotarykiln.commands.transverse import retort_spec_from_case

    command = f"rotarykiln transverse {source}"
    found: dict[str, Any] = {"inputs": transverse_inputs(case), "command": command}
    try:
        spec = retort_spec_from_case(case)
        seconds, why = transverse_estimate(spec)
    except InputError as exc:
        found["skipped"] = f"The transverse run cannot start: {exc}."
        return found
    if why:
        found["skipped"] = (
            f"The app does not run this transverse section: {why}. Run it with the command "
            "below (for the case as edited here: Save case, and give the command that file)."
        )
        found["estimated_seconds"] = seconds
        return found
    import dataclasses

    from rotarykiln.outputs import write_frame_atomic, write_json_atomic
    from rotarykiln.transverse.retort import run_retort

    result = run_retort(dataclasses.replace(spec, snapshot_times=()))
    frame = result.to_frame()
    write_frame_atomic(out / "transverse_timeseries.csv", frame, index=False)
    summary = {
        "active_layer_velocity_m_s": float(result.geometry.v_al),
        "time_step_s": float(result.time_step),
        "mixing_time_s": float(result.mixing_time),
        "peak_contact_over_final_contact_percent": float(100 * result.extent.max()),
        "final_shale_temperature_K": float(result.temperature[-1, 1]),
        "final_ash_temperature_K": float(result.temperature[-1, 0]),
        "volatiles_at_30s_percent": float(100 * np.interp(30.0, result.t, result.volatiles)),
        "final_volatiles_percent": float(100 * result.volatiles[-1]),
        "mass_balance_max_relative_error": float(result.mass_error),
        "energy_balance_max_relative_error": float(result.energy_error),
    }
    write_json_atomic(out / "transverse_summary.json", {"case": spec.name, **summary})
    keep = thin_rows(len(frame))
    found["series"] = {
        c: _plain(frame[c].to_numpy(dtype=float)[keep]) for c in _SERIES_COLUMNS if c in frame
    }
    found["summary"] = {k: (v if math.isfinite(v) else None) for k, v in summary.items()}
    return found
