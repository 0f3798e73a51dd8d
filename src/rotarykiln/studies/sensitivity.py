"""Global sensitivity indices of any scalar output: Sobol (first and total) and Morris, via SALib.

The design is drawn by SALib on the unit hypercube, mapped to each :class:`~.design.Param`'s
distribution through its inverse CDF, and run by the study runner
(:func:`~rotarykiln.studies.runner.run_sweep`: processes or Dask, stored and resumable); SALib
then analyses the output column. Indices therefore refer to the distributions given, not only to
ranges.
"""

from __future__ import annotations

import difflib
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.studies.design import Param, as_params, cases_from_unit, check_design_size
from rotarykiln.studies.io import save_figure_atomic
from rotarykiln.studies.result import SweepResult
from rotarykiln.studies.runner import run_sweep
from rotarykiln.tables import split_unit, with_units

__all__ = ["SensitivityResult", "sobol_indices", "morris_indices", "METHODS"]

METHODS = ("sobol", "morris")


@dataclass(frozen=True)
class SensitivityResult:
    """Sensitivity indices of one output.

    Attributes
    ----------
    method : str
        ``"sobol"`` or ``"morris"``.
    output : str
        The output analysed.
    indices : pandas.DataFrame
        One row per parameter (index: path). Sobol: ``S1``, ``S1_conf``, ``ST``, ``ST_conf``
        (-, confidence half-widths at 95 %); Morris: ``mu_star``, ``mu_star_conf``, ``mu``,
        ``sigma`` (output units per whole range of the parameter).
    params : tuple of Param
    sweep : SweepResult
        The cases run (one row each).
    """

    method: str
    output: str
    indices: pd.DataFrame
    params: tuple[Param, ...]
    sweep: SweepResult = field(repr=False)

    def to_frame(self) -> pd.DataFrame:
        """The indices table (a copy), parameters as a column.

        Sobol indices are dimensionless; Morris' are in the unit of the output."""
        frame = self.indices.reset_index(names="parameter")
        unit = split_unit(self.output)[1] if self.method == "morris" else "1"
        units = dict.fromkeys(frame.columns[1:], unit)
        return with_units(frame, f"studies.sensitivity.{self.method}", units)

    def ranking(self) -> list[str]:
        """Parameters from the most to the least influential (ST, or mu_star for Morris)."""
        key = "ST" if self.method == "sobol" else "mu_star"
        return list(self.indices.sort_values(key, ascending=False).index)

    def plot(self, ax=None):
        """Tornado chart: horizontal bars with their 95 % intervals, largest on top."""
        import matplotlib.pyplot as plt

        order = self.ranking()[::-1]
        df = self.indices.loc[order]
        if ax is None:
            fig, ax = plt.subplots(figsize=(6.4, 1.0 + 0.45 * len(order)))
        else:
            fig = ax.figure
        y = np.arange(len(order))
        name, unit = split_unit(self.output)
        if self.method == "sobol":
            h = 0.38
            ax.barh(y + h / 2, df["ST"], h, xerr=df["ST_conf"], label="total $S_T$", color="C0")
            ax.barh(
                y - h / 2, df["S1"], h, xerr=df["S1_conf"], label="first order $S_1$", color="C1"
            )
            ax.set_xlabel(f"Sobol index of {name} (-)")
            ax.axvline(0, color="k", lw=0.6)
        else:
            ax.barh(y, df["mu_star"], 0.6, xerr=df["mu_star_conf"], label=r"$\mu^*$", color="C0")
            ax.plot(df["sigma"], y, "kD", ms=5, label=r"$\sigma$")
            ax.set_xlabel(f"Morris elementary effect on {name}" + (f" ({unit})" if unit else ""))
        ax.set_yticks(y, order)
        ax.legend(fontsize="small", loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
        ax.set_title(
            f"{self.method.capitalize()} sensitivity, {len(self.sweep.frame)} cases",
            fontsize="medium",
        )
        fig.tight_layout()
        return fig

    def save_plot(self, path) -> object:
        """Save :meth:`plot` atomically (format by suffix); returns the path."""
        import matplotlib.pyplot as plt

        fig = self.plot()
        try:
            return save_figure_atomic(path, fig, dpi=110)
        finally:
            plt.close(fig)


def _problem(params: Sequence[Param]) -> dict:
    return {
        "num_vars": len(params),
        "names": [p.path for p in params],
        "bounds": [[0.0, 1.0]] * len(params),
    }


def _output_values(res: SweepResult, output: str, method: str) -> np.ndarray:
    if output not in res.outputs:
        hint = [o for o in res.outputs if o.startswith(output)] or difflib.get_close_matches(
            output, res.outputs, n=1, cutoff=0.5
        )
        mean = f" (did you mean {hint[0]}?)" if hint else ""
        if not res.outputs:
            first = res.frame["error"].iloc[0] if len(res.frame) else ""
            raise ConvergenceError(f"every case failed, e.g. {first}")
        stored = " (stored cases are reused on a rerun)" if res.meta.get("store") else ""
        raise InputError(
            "--output",
            output,
            f"an output of the model: {', '.join(res.outputs)}{mean}{stored}",
        )
    failed = res.frame["error"] != ""
    y = pd.to_numeric(res.frame[output], errors="coerce").to_numpy(float)
    if failed.any() or not np.all(np.isfinite(y)):
        n_bad = int((failed | ~np.isfinite(y)).sum())
        first = res.frame.loc[failed, "error"].iloc[0] if failed.any() else "non-numeric output"
        raise ConvergenceError(
            f"{n_bad} of {len(y)} cases failed; {method} indices need every case "
            f"(first error: {first})"
        )
    return y


def _check_output(output):
    if not isinstance(output, str) or not output:
        raise InputError("--output", output, "the name of a scalar output of the model")


def sobol_indices(
    func: Callable[[dict], Mapping],
    base_case: Mapping,
    params,
    output: str,
    n: int = 64,
    *,
    seed: int | None = 0,
    num_resamples: int = 100,
    **runner,
) -> SensitivityResult:
    """First-order and total Sobol indices of ``output`` with bootstrap confidence intervals.

    Saltelli's scheme as sampled by SALib (``SALib.sample.sobol``, scrambled Sobol sequence,
    no second-order terms): ``n (d + 2)`` cases for ``d`` parameters, run by
    :func:`~rotarykiln.studies.runner.run_sweep`.

    Parameters
    ----------
    func : callable
        Model ``case -> dict of scalars`` (module level for processes and Dask).
    base_case : mapping
        The case the parameters modify.
    params : sequence of Param or str
        ``"path=dist(args)"`` (see :func:`~rotarykiln.studies.design.parse_param`).
    output : str
        Name of the scalar output analysed.
    n : int
        Base sample size (a power of 2); cases = n (d + 2).
    seed : int or None
        Seed of the scrambling and the bootstrap.
    num_resamples : int
        Bootstrap resamples of the confidence intervals.
    **runner
        Passed to :func:`run_sweep` (``executor``, ``max_workers``, ``store``, ``progress``...).

    Returns
    -------
    SensitivityResult
        ``indices`` with S1, S1_conf, ST, ST_conf (-).

    Examples
    --------
    >>> from rotarykiln.studies.examples import ishigami
    >>> r = sobol_indices(ishigami, {"x1": 0, "x2": 0, "x3": 0},
    ...                   [f"x{i}=uniform(-3.14159265, 3.14159265)" for i in (1, 2, 3)],
    ...                   "y", n=1024, executor="serial")
    >>> r.ranking()
    ['x1', 'x2', 'x3']

    References
    ----------
    Saltelli et al. (2010), Comput. Phys. Commun. 181, 259-270; Jansen (1999); SALib: Herman &
    Usher (2017), JOSS 2(9), 97; Iwanaga et al. (2022), Socio-Environmental Systems Modelling 4.
    """
    from rotarykiln.extras import require

    sobol_analyze = require("SALib.analyze.sobol", "a Sobol sensitivity study")
    sobol_sample = require("SALib.sample.sobol", "a Sobol sensitivity study")

    _check_output(output)
    params = as_params(params)
    if isinstance(n, bool) or not isinstance(n, int) or n < 2:
        raise InputError("--n", n, "a whole number >= 2 (a power of 2)")
    check_design_size(n * (len(params) + 2), "--n", "Sobol: n (d + 2)")
    problem = _problem(params)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # SALib's balance warning for n not a power of 2
        u = sobol_sample.sample(problem, n, calc_second_order=False, seed=seed)
    u = np.clip(u, 1e-9, 1 - 1e-9)
    cases = cases_from_unit(params, u, "sobol")
    res = run_sweep(func, base_case, cases, **runner)
    y = _output_values(res, output, "Sobol")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        si = sobol_analyze.analyze(
            problem, y, calc_second_order=False, num_resamples=num_resamples, seed=seed
        )
    idx = pd.DataFrame(
        {k: np.asarray(si[k], float) for k in ("S1", "S1_conf", "ST", "ST_conf")},
        index=pd.Index(problem["names"], name="parameter"),
    )
    return SensitivityResult("sobol", output, idx, tuple(params), res)


def morris_indices(
    func: Callable[[dict], Mapping],
    base_case: Mapping,
    params,
    output: str,
    n: int = 10,
    *,
    levels: int = 4,
    seed: int | None = 0,
    **runner,
) -> SensitivityResult:
    """Morris elementary effects (mu*, mu, sigma) of ``output``: a cheap screening.

    ``n`` trajectories of ``d + 1`` cases on a ``levels``-level grid of the unit hypercube;
    unbounded distributions (normal, lognormal) are cut at their 1 % and 99 % quantiles.

    Parameters
    ----------
    func : callable
        Model ``case -> dict of scalars``.
    base_case : mapping
        The case the parameters modify.
    params : sequence of Param or str
    output : str
        Name of the scalar output.
    n : int
        Trajectories; cases = n (d + 1).
    levels : int
        Grid levels (even).
    seed : int or None
        Seed of the trajectories and the bootstrap.
    **runner
        Passed to :func:`run_sweep`.

    Returns
    -------
    SensitivityResult
        ``indices`` with mu_star, mu_star_conf, mu, sigma (output units per whole parameter
        range).

    Examples
    --------
    >>> from rotarykiln.studies.examples import ishigami
    >>> r = morris_indices(ishigami, {"x1": 0, "x2": 0, "x3": 0},
    ...                    [f"x{i}=uniform(-3.14159265, 3.14159265)" for i in (1, 2, 3)],
    ...                    "y", n=20, executor="serial")
    >>> list(r.indices.columns)
    ['mu_star', 'mu_star_conf', 'mu', 'sigma']

    References
    ----------
    Morris (1991), Technometrics 33, 161-174; Campolongo, Cariboni & Saltelli (2007), Environ.
    Model. Softw. 22, 1509-1518 (mu*); SALib: Herman & Usher (2017), JOSS 2(9), 97.
    """
    from rotarykiln.extras import require

    morris_analyze = require("SALib.analyze.morris", "a Morris sensitivity study")
    morris_sample = require("SALib.sample.morris", "a Morris sensitivity study")

    _check_output(output)
    params = as_params(params)
    if isinstance(n, bool) or not isinstance(n, int) or n < 2:
        raise InputError("--n", n, "a whole number of trajectories >= 2")
    check_design_size(n * (len(params) + 1), "--n", "Morris: n (d + 1)")
    if isinstance(levels, bool) or not isinstance(levels, int) or levels < 2 or levels % 2:
        raise InputError("--levels", levels, "an even whole number >= 2")
    problem = _problem(params)
    u = morris_sample.sample(problem, n, num_levels=levels, seed=seed)
    mapped = u.copy()
    for j, p in enumerate(params):
        if not p.bounded:
            mapped[:, j] = 0.01 + 0.98 * u[:, j]
    mapped = np.clip(mapped, 1e-9, 1 - 1e-9)
    cases = cases_from_unit(params, mapped, "morris")
    res = run_sweep(func, base_case, cases, **runner)
    y = _output_values(res, output, "Morris")
    mi = morris_analyze.analyze(problem, u, y, num_levels=levels, seed=seed)
    idx = pd.DataFrame(
        {k: np.asarray(mi[k], float) for k in ("mu_star", "mu_star_conf", "mu", "sigma")},
        index=pd.Index(problem["names"], name="parameter"),
    )
    return SensitivityResult("morris", output, idx, tuple(params), res)
