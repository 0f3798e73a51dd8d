"""Named models for sweeps: ``case dict -> dict of scalars``, picklable for worker processes.

``rotarykiln sweep --model kiln`` looks the name up in :data:`MODELS`; any other model is given as
``module:function``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

__all__ = [
    "MODELS",
    "PROFILE_POINTS",
    "kiln_model",
    "kiln_profile_model",
    "kiln_solutions",
    "profile_columns",
    "transport_model",
]

#: Positions of the axial profiles of :func:`kiln_profile_model` (evenly spaced, ends included).
PROFILE_POINTS = 41


def _scalars(summary: Mapping) -> dict:
    return {k: v for k, v in summary.items() if isinstance(v, int | float | str | bool)}


def _summary_outputs(sol) -> dict:
    import math

    summary = sol.summary()
    summary.pop("name", None)
    out = _scalars(summary)
    return {k: v for k, v in out.items() if not (isinstance(v, float) and math.isnan(v))}


def _profile_outputs(sol) -> dict:
    import numpy as np

    summary = sol.summary()
    summary.pop("name", None)
    out = _scalars(summary)
    z = np.linspace(float(sol.z_nodes[0]), float(sol.z_nodes[-1]), PROFILE_POINTS)
    profiles = {
        "bed_temperature": sol.bed_temperature_at(z),
        "gas_temperature": sol.gas_temperature_at(z),
        "wall_temperature": sol.wall_temperature_at(z, 0),
    }
    if getattr(sol, "t_lining", None) is not None and len(sol.t_lining) > 1:
        profiles["shell_temperature"] = sol.wall_temperature_at(z, -1)
    for q, values in profiles.items():
        for zi, v in zip(z, values, strict=True):
            out[f"{q}@{zi:.4f}"] = float(v)
    return out


def kiln_solutions(cases, warnings_out=None, *, base=None, changes=None) -> list:
    """Solve the steady kiln model of many case dicts together
    (:func:`rotarykiln.kiln.steady.batch.solve_batch`: cases of one model structure and grid
    in batches): per case its :class:`~rotarykiln.kiln.results.solution.KilnSolution`, or the
    exception its parsing, building or solve raised (never raised here).

    ``warnings_out``: a list of one list per case, which receives the warnings of that case.
    ``base`` and ``changes``: the base case dict and, per case, the fields it changes (a
    study's design): the base is then parsed once and each case made by
    :func:`rotarykiln.case.case_with` (the same case as parsing its dict, a fraction of the
    cost).
    """
    import warnings

    from rotarykiln.case import case_with, parse_case
    from rotarykiln.kiln.from_case import kiln_from_case
    from rotarykiln.kiln.steady.batch import solve_batch

    cases = cases if isinstance(cases, Sequence) else list(cases)
    caught = warnings_out if warnings_out is not None else [[] for _ in range(len(cases))]
    out: list = [None] * len(cases)
    by_cells: dict[int, list] = {}
    base_case = None
    if base is not None and changes is not None:
        try:
            base_case = parse_case(base)
        except Exception:  # the base alone is refused: each case parsed as it is
            base_case = None
    for i in range(len(cases)):
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            try:
                if base_case is not None:
                    try:
                        parsed = case_with(base_case, changes[i])
                    except Exception:  # a path case_with does not take: the whole dict
                        parsed = parse_case(cases[i])
                else:
                    parsed = parse_case(cases[i])
                kiln, cells = kiln_from_case(parsed)
                by_cells.setdefault(cells, []).append((i, kiln))
            except Exception as exc:
                out[i] = exc
        caught[i].extend(w)
    for cells, items in by_cells.items():
        per_case: list[list] = []
        sols = solve_batch([k for _, k in items], cells, warnings_out=per_case)
        for (i, _), sol, w in zip(items, sols, per_case, strict=True):
            out[i] = sol
            caught[i].extend(w)
    return out


def _batched(outputs):
    def run(cases, warnings_out=None, *, base=None, changes=None):
        return [
            s if isinstance(s, Exception) else outputs(s)
            for s in kiln_solutions(cases, warnings_out, base=base, changes=changes)
        ]

    return run


def kiln_model(case: dict) -> dict:
    """Steady kiln model of a case (:func:`rotarykiln.commands.kiln_runs.run_kiln_case`): its summary
    as scalars (outlet temperatures, heat flows, shell loss, efficiency, conversions and
    yields of a reacting bed, balances, Newton iterations; NaN values left out).

    ``kiln_model.batched(cases, warnings_out)`` solves many cases together
    (:func:`kiln_solutions`); the sweep runner uses it."""
    from rotarykiln.case import parse_case
    from rotarykiln.commands.kiln_runs import run_kiln_case

    return _summary_outputs(run_kiln_case(parse_case(case)))


def kiln_profile_model(case: dict) -> dict:
    """Steady kiln model: the summary of :func:`kiln_model` plus the axial profiles as scalars.

    Profiles at :data:`PROFILE_POINTS` evenly spaced positions z (m, from the solids inlet),
    named ``"<quantity>@<z>"`` with quantities ``bed_temperature``, ``gas_temperature``,
    ``wall_temperature`` (inner wall surface) and ``shell_temperature`` (lined walls), in K:
    e.g. ``"bed_temperature@1.2200"``. Uncertainty bands and calibration read these columns
    (see :func:`profile_columns`). Batched as :func:`kiln_model`.
    """
    from rotarykiln.case import parse_case
    from rotarykiln.commands.kiln_runs import run_kiln_case

    return _profile_outputs(run_kiln_case(parse_case(case)))


kiln_model.batched = _batched(_summary_outputs)
kiln_profile_model.batched = _batched(_profile_outputs)


def profile_columns(names) -> dict[str, list[tuple[float, str]]]:
    """Profile columns among output names: quantity -> [(z in m, column name)], z ascending.

    Examples
    --------
    >>> profile_columns(["bed_temperature@0.5000", "fill", "bed_temperature@0.0000"])
    {'bed_temperature': [(0.0, 'bed_temperature@0.0000'), (0.5, 'bed_temperature@0.5000')]}
    """
    out: dict[str, list[tuple[float, str]]] = {}
    for n in names:
        q, sep, z = str(n).rpartition("@")
        if not sep or not q:
            continue
        try:
            out.setdefault(q, []).append((float(z), n))
        except ValueError:
            continue
    return {q: sorted(v) for q, v in out.items()}


def transport_model(case: dict) -> dict:
    """Bed profile of a case with a ``transport:`` section: mean fill, hold-up, residence time."""
    from rotarykiln.case import parse_case
    from rotarykiln.commands.model_runs import bed_profile_from_case

    p = bed_profile_from_case(parse_case(case))
    return {
        "mean_fill": float(p.mean_fill),
        "holdup_kg": float(p.holdup_mass) if p.holdup_mass is not None else float("nan"),
        "mean_residence_time_min": float(p.mean_residence_time) / 60.0,
        "discharge_fill": float(p.discharge_fill),
    }


MODELS: dict[str, Callable[[dict], dict]] = {
    "kiln": kiln_model,
    "kiln_profiles": kiln_profile_model,
    "transport": transport_model,
}
"""Model name -> function, for ``rotarykiln sweep --model NAME``."""
