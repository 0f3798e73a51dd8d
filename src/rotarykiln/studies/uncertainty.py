"""Uncertainty propagation: Monte Carlo over input distributions, percentile bands of profiles.

The nominal case (the base case as given) and ``n`` samples of the :class:`~.design.Param`
distributions (Latin hypercube by default) run through the study runner; every scalar output
gets its mean, standard deviation and percentiles, and every axial profile (outputs named
``"<quantity>@<z>"``, e.g. from :func:`~rotarykiln.studies.models.kiln_profile_model`) its
5-50-95 % band, drawn around the nominal profile.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.studies.design import (
    CaseSpec,
    Param,
    as_params,
    check_design_size,
    latin_hypercube,
    monte_carlo,
    sobol_sequence,
)
from rotarykiln.studies.io import save_figure_atomic
from rotarykiln.studies.models import profile_columns
from rotarykiln.studies.result import SweepResult, profile_unit
from rotarykiln.studies.runner import run_sweep
from rotarykiln.tables import with_units

__all__ = ["UncertaintyResult", "propagate"]

_DESIGNS = {"lhs": latin_hypercube, "mc": monte_carlo, "sobol": sobol_sequence}


@dataclass(frozen=True)
class UncertaintyResult:
    """Monte Carlo results: the sample table, the nominal outputs, percentiles.

    Attributes
    ----------
    params : tuple of Param
    sweep : SweepResult
        All cases: the nominal one (group ``"nominal"``) and the samples.
    nominal : dict
        Outputs of the nominal case.
    percentiles : tuple of float
        Percentiles of the bands, % (default 5, 50, 95).
    """

    params: tuple[Param, ...]
    sweep: SweepResult = field(repr=False)
    nominal: dict = field(repr=False)
    percentiles: tuple[float, ...] = (5.0, 50.0, 95.0)

    @property
    def samples(self) -> pd.DataFrame:
        """The sample rows that ran (failed ones excluded; see :attr:`n_failed`)."""
        f = self.sweep.to_frame()
        return f[(f["group"] != "nominal") & (f["error"] == "")]

    @property
    def n_failed(self) -> int:
        """Sample cases that failed (excluded from the statistics)."""
        f = self.sweep.frame
        return int(((f["group"] != "nominal") & (f["error"] != "")).sum())

    @property
    def quantities(self) -> list[str]:
        """Profile quantities among the outputs (``bed_temperature``, ...)."""
        return list(profile_columns(self.sweep.outputs))

    def _pcols(self) -> list[str]:
        return [f"p{p:g}" for p in self.percentiles]

    def scalars(self) -> pd.DataFrame:
        """Per numeric scalar output (not profiles): nominal, mean, sd and the percentiles."""
        prof = {c for v in profile_columns(self.sweep.outputs).values() for _, c in v}
        rows = []
        s = self.samples
        for o in self.sweep.outputs:
            if o in prof:
                continue
            y = pd.to_numeric(s[o], errors="coerce").to_numpy(float)
            y = y[np.isfinite(y)]
            nom = self.nominal.get(o)
            if not len(y) or not isinstance(nom, int | float) or isinstance(nom, bool):
                continue
            pct = np.percentile(y, self.percentiles)
            rows.append(
                {"output": o, "nominal": float(nom), "mean": y.mean(), "sd": y.std(ddof=1)}
                | dict(zip(self._pcols(), pct, strict=True))
            )
        # one row per output: each row in the unit of its output (the suffix of ``output``)
        cols = ["nominal", "mean", "sd", *self._pcols()]
        return with_units(pd.DataFrame(rows), "studies.uncertainty", dict.fromkeys(cols, "@output"))

    def bands(self, quantity: str) -> pd.DataFrame:
        """Band of one profile: ``z_m``, ``nominal``, the percentiles (same unit as the output)."""
        cols = profile_columns(self.sweep.outputs)
        if quantity not in cols:
            raise InputError(
                "uncertainty.quantity", quantity, f"a profile: {', '.join(cols) or 'none'}"
            )
        z = np.array([zi for zi, _ in cols[quantity]])
        names = [c for _, c in cols[quantity]]
        values = self.samples[names].apply(pd.to_numeric, errors="coerce").to_numpy(float)
        pct = np.nanpercentile(values, self.percentiles, axis=0)
        out = {"z_m": z, "nominal": [float(self.nominal.get(c, np.nan)) for c in names]}
        out |= {name: pct[i] for i, name in enumerate(self._pcols())}
        unit = profile_unit(quantity)
        cols = ["nominal", *self._pcols()]
        return with_units(pd.DataFrame(out), "studies.uncertainty", dict.fromkeys(cols, unit))

    def to_frame(self) -> pd.DataFrame:
        """All profile bands in one long table (column ``quantity``)."""
        frames = [self.bands(q).assign(quantity=q) for q in self.quantities]
        frame = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()
        units = {profile_unit(q) for q in self.quantities}
        unit = units.pop() if len(units) == 1 else "@quantity"  # else: the unit of each row's
        cols = ["nominal", *self._pcols()]
        return with_units(frame, "studies.uncertainty", dict.fromkeys(cols, unit))

    def plot(self, quantities: Sequence[str] | None = None, ax=None):
        """Bands (shaded p5-p95, dashed median) around the nominal profiles; returns the Figure."""
        import matplotlib.pyplot as plt

        qs = list(quantities or self.quantities)
        if ax is None:
            fig, ax = plt.subplots(figsize=(7.5, 4.5))
        else:
            fig = ax.figure
        lo, mid, hi = self._pcols()[0], self._pcols()[len(self.percentiles) // 2], self._pcols()[-1]
        for i, q in enumerate(qs):
            b = self.bands(q)
            c = f"C{i}"
            ax.fill_between(
                b["z_m"], b[lo], b[hi], color=c, alpha=0.25, lw=0, label=f"{q} {lo[1:]}-{hi[1:]} %"
            )
            ax.plot(b["z_m"], b[mid], color=c, ls="--", lw=1)
            ax.plot(b["z_m"], b["nominal"], color=c, lw=1.8, label=f"{q} nominal")
        ax.set_xlabel("z from the solids inlet (m)")
        ax.set_ylabel("temperature (K)" if all("temperature" in q for q in qs) else "value")
        ax.set_title(f"Monte Carlo, {len(self.samples)} cases (dashed: median)", fontsize="medium")
        ax.legend(fontsize="x-small", ncol=2)
        fig.tight_layout()
        return fig

    def save_plot(self, path, **kwargs):
        """Save :meth:`plot` atomically (format by suffix); returns the path."""
        import matplotlib.pyplot as plt

        fig = self.plot(**kwargs)
        try:
            return save_figure_atomic(path, fig, dpi=110)
        finally:
            plt.close(fig)


def propagate(
    func: Callable[[dict], Mapping],
    base_case: Mapping,
    params,
    n: int = 100,
    *,
    design: str = "lhs",
    seed: int | None = 0,
    percentiles: Sequence[float] = (5.0, 50.0, 95.0),
    **runner,
) -> UncertaintyResult:
    """Propagate input distributions through a model by Monte Carlo.

    Parameters
    ----------
    func : callable
        Model ``case -> dict of scalars`` (profiles as ``"<quantity>@<z>"`` outputs).
    base_case : mapping
        The nominal case (run too, as the reference of the bands).
    params : sequence of Param or str
        ``"path=dist(args)"`` (see :func:`~rotarykiln.studies.design.parse_param`).
    n : int
        Number of samples.
    design : {"lhs", "mc", "sobol"}
        Latin hypercube (default), plain random or scrambled Sobol samples.
    seed : int or None
        Seed of the design.
    percentiles : sequence of float
        Percentiles of the bands, %.
    **runner
        Passed to :func:`~rotarykiln.studies.runner.run_sweep` (executor, store, progress...).

    Returns
    -------
    UncertaintyResult
        Sample table, nominal outputs, :meth:`~UncertaintyResult.bands`,
        :meth:`~UncertaintyResult.scalars`.

    Examples
    --------
    >>> from rotarykiln.studies.examples import first_order_conversion
    >>> base = {"reaction": {"rate_constant": "0.01 1/s"},
    ...         "operation": {"residence_time": "100 s"}}
    >>> r = propagate(first_order_conversion, base,
    ...               ["operation.residence_time=normal(100 s, 10 s)"], 200, executor="serial")
    >>> row = r.scalars().set_index("output").loc["conversion"]
    >>> round(float(row["nominal"]), 3), bool(row["p5"] < row["nominal"] < row["p95"])
    (0.632, True)

    References
    ----------
    JCGM 101:2008, Evaluation of measurement data, Supplement 1: propagation of distributions
    using a Monte Carlo method; McKay, Beckman & Conover (1979), Technometrics 21, 239-245.
    """
    if design not in _DESIGNS:
        raise InputError("uncertainty.design", design, f"one of {', '.join(_DESIGNS)}")
    params = as_params(params)
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 2:
        raise InputError("--n", n, "a whole number of samples >= 2 (a standard deviation)")
    check_design_size(int(n) + 1, "--n", "n samples + the nominal case")
    pct = tuple(float(p) for p in percentiles)
    if len(pct) < 2 or any(not 0 <= p <= 100 for p in pct) or list(pct) != sorted(pct):
        raise InputError("uncertainty.percentiles", pct, "ascending values in [0, 100]")
    samples = _DESIGNS[design](params, n, seed=seed)
    cases = [CaseSpec(0, {}, "nominal")] + [
        CaseSpec(c.case_id + 1, c.values, c.group) for c in samples
    ]
    res = run_sweep(func, base_case, cases, **runner)
    f = res.frame
    nom = f[f["group"] == "nominal"].iloc[0]
    if nom["error"]:
        raise ConvergenceError(f"the nominal case failed: {nom['error']}")
    ok = f[(f["group"] != "nominal") & (f["error"] == "")]
    if len(ok) < 2:
        errors = f.loc[f["error"] != "", "error"]
        first = f" ({errors.iloc[0]})" if len(errors) else ""
        raise ConvergenceError(
            f"{len(f) - 1 - len(ok)} of {len(f) - 1} samples failed; at least 2 must run{first}"
        )
    nominal = {o: nom[o] for o in res.outputs}
    return UncertaintyResult(tuple(params), res, nominal, pct)
