"""Seed 004's chapter-5 sensitivity study (Ahmad 2006, Figs. 5.1-5.5) as a sweep design.

Burn-off and production of the charcoal-activation case against residence time, gas flow,
solid inlet temperature, steam flow and solid flow, one at a time around the built-in case
``cases/charcoal_activation.yaml``. The ranges and Ahmad's reported directions are data:
src/rotarykiln/data/ahmad2006/chapter5_study.yaml (its README gives their provenance: the ranges
are not printed in seed 004, whose figures are lost, and bracket the nominal values by about
x0.3-x3, documented in docs/studies.md). :func:`run_chapter5` runs the design on the kiln model.
"""

from __future__ import annotations

from importlib import resources

import yaml

from rotarykiln.cases import builtin_case
from rotarykiln.studies.design import CaseSpec, one_at_a_time

__all__ = [
    "CHAPTER5_RANGES",
    "CHAPTER5_DIRECTIONS",
    "ahmad_chapter5_design",
    "chapter5_directions",
    "chapter5_params",
    "chapter5_sobol",
    "oat_ranking",
    "run_chapter5",
]


def _study() -> dict:
    """The study of src/rotarykiln/data/ahmad2006/chapter5_study.yaml (README.md beside it)."""
    path = resources.files("rotarykiln") / "data" / "ahmad2006" / "chapter5_study.yaml"
    with path.open("r", encoding="utf-8") as fh:
        return yaml.safe_load(fh)


_STUDY = _study()

#: Field path -> values swept (as in the case file, with units); not printed in seed 004, chosen
#: as documented in docs/studies.md (the data file's README).
CHAPTER5_RANGES: dict[str, list[str]] = _STUDY["ranges"]

#: Sign of d(burn-off)/d(parameter) reported by seed 004 chapter 4.5 (0: "insignificant"); the
#: gas-flow direction is flagged as doubtful (the data file's comments and README).
CHAPTER5_DIRECTIONS: dict[str, int] = _STUDY["directions"]


def ahmad_chapter5_design(ranges: dict | None = None) -> list[CaseSpec]:
    """One-at-a-time design of seed 004 chapter 5 (base case first).

    Examples
    --------
    >>> d = ahmad_chapter5_design()
    >>> len(d), d[0].group, d[1].group
    (29, 'base', 'bed.residence_time')
    """
    return one_at_a_time(ranges or CHAPTER5_RANGES)


def run_chapter5(max_workers: int | None = 2, ranges: dict | None = None):
    """Seed 004's chapter-5 study on the reacting kiln model (charcoal case), one table.

    Returns the :class:`~rotarykiln.studies.result.SweepResult` of
    :func:`rotarykiln.studies.models.kiln_model` over :func:`ahmad_chapter5_design`.
    """
    from rotarykiln.studies.models import kiln_model
    from rotarykiln.studies.runner import run_sweep

    return run_sweep(
        kiln_model,
        builtin_case("charcoal_activation"),
        ahmad_chapter5_design(ranges),
        max_workers=max_workers,
    )


def chapter5_directions(result, output: str = "burn_off_percent", threshold: float = 0.5):
    """Sign of the change of ``output`` over each swept parameter (last minus first value).

    Changes smaller than ``threshold`` (in the output's units) count as 0 ("insignificant").
    Returns a dict path -> (sign, change, first, last).
    """
    import numpy as np

    frame = result.frame
    out = {}
    for path in CHAPTER5_RANGES:
        rows = frame[frame["group"] == path].sort_values(f"{path} [SI]")
        if rows.empty or rows[output].isna().all():
            continue
        first, last = float(rows[output].iloc[0]), float(rows[output].iloc[-1])
        change = last - first
        sign = 0 if abs(change) < threshold else int(np.sign(change))
        out[path] = (sign, change, first, last)
    return out


def chapter5_params(ranges: dict | None = None) -> list[str]:
    """The chapter-5 ranges as uniform distributions from their lowest to their highest value.

    Examples
    --------
    >>> chapter5_params()[0]
    'bed.residence_time=uniform(2000 s, 10000 s)'
    """
    from rotarykiln.studies.design import si_value

    out = []
    for path, values in (ranges or CHAPTER5_RANGES).items():
        lo, hi = min(values, key=si_value), max(values, key=si_value)
        out.append(f"{path}=uniform({lo}, {hi})")
    return out


def chapter5_sobol(n: int = 32, seed: int = 0, **runner):
    """Sobol indices of burn-off over the chapter-5 ranges on the reacting kiln model.

    ``n (d + 2)`` = 7 n cases (d = 5 parameters); ``runner`` goes to
    :func:`~rotarykiln.studies.sensitivity.sobol_indices` (``max_workers``, ``store``...).
    Returns the :class:`~rotarykiln.studies.sensitivity.SensitivityResult`.
    """
    from rotarykiln.studies.models import kiln_model
    from rotarykiln.studies.sensitivity import sobol_indices

    return sobol_indices(
        kiln_model,
        builtin_case("charcoal_activation"),
        chapter5_params(),
        "burn_off_percent",
        n,
        seed=seed,
        **runner,
    )


def oat_ranking(result, output: str = "burn_off_percent") -> list[str]:
    """Parameters of a one-at-a-time study ranked by the spread (max - min) of ``output``."""
    frame = result.frame
    spread = {}
    for path in CHAPTER5_RANGES:
        rows = frame[frame["group"].isin([path, "base"])]
        if len(rows):
            spread[path] = float(rows[output].max() - rows[output].min())
    return sorted(spread, key=spread.get, reverse=True)
