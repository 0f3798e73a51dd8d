"""Calibration of case fields to measured data by weighted least squares.

Measured data are a CSV with columns ``quantity, z, value, uncertainty``: a profile quantity
(``bed_temperature``, ``gas_temperature``, ``wall_temperature``, ``shell_temperature``; also
written ``bed``, ``gas temperature``...) at a position z (m from the solids inlet), or a scalar
output of the model (``bed_outlet_temperature_K``, ``shell_loss_W``...) with z empty. Values and
uncertainties (one standard deviation) are in the output's unit (K for temperatures).

The chosen case fields (``"gas.flow=20 kg/h"``, optionally with bounds
``"wall.emissivity=0.8 [0.3, 1]"``) are varied by ``scipy.optimize.least_squares`` on the
residuals ``(model - value) / uncertainty``; the model's profiles (outputs ``"<quantity>@<z>"``,
e.g. :func:`~rotarykiln.studies.models.kiln_profile_model`) are interpolated linearly to the
measured positions. The covariance of the parameters is ``(J^T J)^-1`` of the weighted Jacobian
at the optimum (stated uncertainties taken as true: ``absolute_sigma=True``), or scaled by the
reduced chi-square (``absolute_sigma=False``, when the uncertainties are only relative weights).
"""

from __future__ import annotations

import difflib
import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.studies.io import MAX_DATA_ROWS, read_data_csv, save_figure_atomic, shown
from rotarykiln.studies.models import profile_columns
from rotarykiln.studies.paths import get_path, with_values
from rotarykiln.tables import with_units

__all__ = [
    "CalibrationResult",
    "FitParam",
    "Measurements",
    "calibrate",
    "calibrate_cases",
    "parse_fit",
    "read_measurements",
]

MAX_VALUE = 1e15
"""Largest magnitude of a measured value or uncertainty (in the output's unit)."""
MIN_UNCERTAINTY = 1e-12
"""Smallest uncertainty: the weighted residuals (value/uncertainty) and their squares stay
far from overflow."""
MAX_POSITION = 1e4
"""Largest position z of a measured point, m (the longest kiln length a case accepts)."""

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_FIT = re.compile(rf"^\s*({_NUM})\s*([^\[]*?)\s*(?:\[\s*(.+?)\s*,\s*(.+?)\s*\])?\s*$")


@dataclass(frozen=True)
class FitParam:
    """A case field to fit: path, start value and bounds in ``unit``.

    Attributes
    ----------
    path : str
        Dotted field path.
    x0 : float
        Start value, in ``unit``.
    unit : str
        Unit as typed ("" for a plain number).
    lower, upper : float
        Bounds in ``unit`` (-inf, inf when not given).
    """

    path: str
    x0: float
    unit: str = ""
    lower: float = -math.inf
    upper: float = math.inf

    def value(self, x: float):
        """Case-file value of ``x``: ``"24.6 kg/h"`` or a float."""
        return f"{float(x):.8g} {self.unit}" if self.unit else float(x)


def _in_unit(field: str, text: str, unit: str) -> float:
    from rotarykiln.studies.design import _magnitude

    return _magnitude(field, text, unit, False)


def parse_fit(text: str) -> FitParam:
    """Parse ``"PATH=X0 [LOW, HIGH]"`` (bounds optional, units as typed) into a FitParam.

    Parameters
    ----------
    text : str
        E.g. ``"gas.flow=20 kg/h"``, ``"wall.emissivity=0.8 [0.3, 1]"``.

    Returns
    -------
    FitParam
        Path, start value and bounds in the unit of the start value.

    Examples
    --------
    >>> parse_fit("gas.flow=20 kg/h [10 kg/h, 0.01 kg/s]")
    FitParam(path='gas.flow', x0=20.0, unit='kg/h', lower=10.0, upper=36.0)

    References
    ----------
    Units are read with pint, as everywhere in rotarykiln (rotarykiln.units).
    """
    path, sep, spec = str(text).partition("=")
    path = path.strip()
    if not sep or not path:
        raise InputError("--fit", text, 'PATH=START [LOW, HIGH], e.g. "gas.flow=20 kg/h"')
    m = _FIT.match(spec)
    if m is None:
        raise InputError(path, spec, 'a start value with its unit, bounds optional: "0.8 [0.3, 1]"')
    x0, unit = float(m.group(1)), m.group(2)
    if unit:
        from rotarykiln.units import ureg

        try:
            ureg.Unit(unit)
        except Exception:
            raise InputError(path, spec, "a start value with a known unit") from None
    lo = _in_unit(path, m.group(3), unit) if m.group(3) else -math.inf
    hi = _in_unit(path, m.group(4), unit) if m.group(4) else math.inf
    if not lo < hi or not lo <= x0 <= hi:
        raise InputError(path, spec, "LOW < HIGH with the start value between them")
    return FitParam(path, x0, unit, lo, hi)


@dataclass(frozen=True)
class Measurements:
    """Measured data: one entry per point.

    Attributes
    ----------
    quantity : array of str
        Profile quantity (``bed_temperature``...) or scalar output name.
    z : array, m
        Position from the solids inlet (NaN for a scalar output).
    value : array
        Measured value, in the unit of the output (K for temperatures).
    uncertainty : array
        One standard deviation, same unit, > 0.
    case : array of str
        Name of the case each point belongs to ("" when there is one case).
    """

    quantity: np.ndarray
    z: np.ndarray
    value: np.ndarray
    uncertainty: np.ndarray
    case: np.ndarray | None = None

    @property
    def cases(self) -> np.ndarray:
        """Case name of each point ("" for a single-case fit)."""
        return self.case if self.case is not None else np.full(len(self.value), "", dtype=object)

    def __len__(self) -> int:
        return len(self.value)

    def to_frame(self) -> pd.DataFrame:
        """The data as a table (case if given, quantity, z_m, value, uncertainty)."""
        frame = pd.DataFrame(
            {
                "quantity": self.quantity,
                "z_m": self.z,
                "value": self.value,
                "uncertainty": self.uncertainty,
            }
        )
        if self.case is not None:
            frame.insert(0, "case", self.case)
        # each row in the unit of its quantity (K for the temperatures)
        units = {"value": "@quantity", "uncertainty": "@quantity"}
        return with_units(frame, "studies.calibration.data", units)


_ALIASES = {
    "bed": "bed_temperature",
    "gas": "gas_temperature",
    "wall": "wall_temperature",
    "shell": "shell_temperature",
}


def _normalise_quantity(q: str) -> str:
    q = "_".join(str(q).strip().split())
    return _ALIASES.get(q.lower(), q)


def read_measurements(source) -> Measurements:
    """Read measured data from a CSV path or a DataFrame (quantity, z, value, uncertainty).

    ``z`` may carry a unit in its header (``z [m]``, ``z_m``; metres) and is empty for scalar
    outputs; values within +-:data:`MAX_VALUE`, uncertainties in [:data:`MIN_UNCERTAINTY`,
    :data:`MAX_VALUE`], z in [0, :data:`MAX_POSITION`] m. An optional ``case`` column names the
    case of each point, for a fit over several cases (:func:`calibrate_cases`). A file is read
    within the limits of :func:`rotarykiln.studies.io.read_data_csv` (size, rows, UTF-8).

    Parameters
    ----------
    source : path or DataFrame

    Returns
    -------
    Measurements

    Examples
    --------
    >>> import pandas as pd
    >>> m = read_measurements(pd.DataFrame({"quantity": ["bed", "bed_outlet_temperature_K"],
    ...                                     "z": [0.5, None], "value": [350, 446],
    ...                                     "uncertainty": [5, 2]}))
    >>> [str(q) for q in m.quantity], len(m)
    (['bed_temperature', 'bed_outlet_temperature_K'], 2)

    References
    ----------
    The file layout of issue 13 (quantity, z, value, uncertainty).
    """
    if isinstance(source, pd.DataFrame):
        df = source.copy()
        where = "measurements"
        if len(df) > MAX_DATA_ROWS:
            raise InputError(where, f"{len(df):,} rows", f"at most {MAX_DATA_ROWS:,} rows")
    else:
        where = shown(str(source), 200)
        df = read_data_csv(
            source, "--data", what="data file", comment="#", skipinitialspace=True, dtype=str
        )
    cols = {}
    for c in df.columns:
        key = re.sub(r"[\s_]*[\[(].*$", "", str(c).strip().lower())
        key = {"z_m": "z", "position": "z", "sigma": "uncertainty"}.get(key, key)
        cols[c] = key
    df = df.rename(columns=cols)
    missing = [c for c in ("quantity", "z", "value", "uncertainty") if c not in df]
    if missing:
        raise InputError(
            "--data",
            where,
            f"a CSV with columns quantity, z, value, uncertainty (missing {', '.join(missing)})",
        )
    if df.columns.duplicated().any():
        dup = df.columns[df.columns.duplicated()][0]
        raise InputError("--data", where, f"a CSV with one {shown(dup)} column")
    if not len(df):
        raise InputError("--data", where, "a CSV with at least one data row")
    q = np.array([_normalise_quantity(v) for v in df["quantity"].fillna("")], dtype=object)
    z = _numbers(df["z"])
    v = _numbers(df["value"])
    u = _numbers(df["uncertainty"])
    for i in range(len(df)):
        row = f"{where} row {i + 1}"
        if not q[i]:
            raise InputError(row, "an empty quantity", "a quantity name")
        if len(q[i]) > 200:
            raise InputError(row, f"a quantity of {len(q[i])} characters", "a quantity name")
        if not (math.isfinite(v[i]) and abs(v[i]) <= MAX_VALUE):
            raise InputError(
                row,
                f"value {shown(df['value'].iloc[i])}",
                f"a number in [-{MAX_VALUE:g}, {MAX_VALUE:g}]",
            )
        if not (math.isfinite(u[i]) and MIN_UNCERTAINTY <= u[i] <= MAX_VALUE):
            raise InputError(
                row,
                f"uncertainty {shown(df['uncertainty'].iloc[i])}",
                f"in [{MIN_UNCERTAINTY:g}, {MAX_VALUE:g}] (one standard deviation, > 0)",
            )
        if not math.isnan(z[i]) and not 0 <= z[i] <= MAX_POSITION:
            raise InputError(row, f"z = {z[i]:g} m", f"a position in [0, {MAX_POSITION:g}] m")
        if math.isnan(z[i]) and str(df["z"].iloc[i]).strip() not in ("", "nan", "None", "<NA>"):
            raise InputError(row, f"z = {shown(df['z'].iloc[i])}", "a number (m) or empty")
    case = None
    if "case" in df:
        case = np.array([str(c).strip() for c in df["case"].fillna("")], dtype=object)
    return Measurements(q, z, v, u, case)


def _numbers(column: pd.Series) -> np.ndarray:
    """A column as floats (NaN where a cell is not a number)."""
    return pd.to_numeric(column, errors="coerce").to_numpy(float)


def _absent_but_allowed(base: Mapping, path: str) -> bool:
    """False if ``path`` exists; True for an optional field absent from the case (its parent
    exists and no existing key is a likely misspelling of it: the case schema checks it);
    else the InputError of :func:`get_path` (with its did-you-mean)."""
    try:
        get_path(base, path)
        return False
    except InputError:
        parent, _, last = path.rpartition(".")
        node = get_path(base, parent) if parent else base
        if not isinstance(node, Mapping) or difflib.get_close_matches(
            last, [str(k) for k in node], n=1, cutoff=0.8
        ):
            raise
        return True


class _Predictor:
    """Maps model outputs to the measured points; checks quantities and positions once."""

    def __init__(self, outputs: Mapping, meas: Measurements, rows=None):
        profiles = profile_columns(outputs)
        rows = list(range(len(meas))) if rows is None else list(rows)
        scalars = [k for k, v in outputs.items() if "@" not in k and isinstance(v, int | float)]
        self.plan = []
        for i in rows:
            q, z = meas.quantity[i], meas.z[i]
            row = f"measurements row {i + 1}"
            if q in profiles:
                if math.isnan(z):
                    raise InputError(row, q, "given with a position z (a profile quantity)")
                zs = np.array([p for p, _ in profiles[q]])
                if not zs[0] - 1e-9 <= z <= zs[-1] + 1e-9:
                    raise InputError(
                        row,
                        f"{q} at z = {z:g} m",
                        f"inside the model ({zs[0]:g} m to {zs[-1]:g} m)",
                    )
                self.plan.append(("profile", q, z, zs, [c for _, c in profiles[q]]))
            elif q in scalars:
                if not math.isnan(z):
                    raise InputError(row, f"{q} at z = {z:g} m", "given without z (a scalar)")
                self.plan.append(("scalar", q, None, None, None))
            else:
                known = list(profiles) + scalars
                hint = difflib.get_close_matches(q, known, n=1)
                mean = f"; did you mean {hint[0]}?" if hint else ""
                prof = ", ".join(profiles) or "none (use a profile model such as kiln_profiles)"
                raise InputError(
                    row, q, f"a quantity of the model (profiles: {prof}; or a scalar output){mean}"
                )

    def __call__(self, outputs: Mapping) -> np.ndarray:
        out = np.empty(len(self.plan))
        for i, (kind, q, z, zs, cols) in enumerate(self.plan):
            try:
                if kind == "scalar":
                    out[i] = float(outputs[q])
                else:
                    out[i] = np.interp(z, zs, [float(outputs[c]) for c in cols])
            except KeyError:  # the fitted values moved the profile positions or dropped an output
                raise _OutputsChanged(q) from None
        return out


class _OutputsChanged(Exception):
    """The model's outputs (profile positions, output names) changed with the fitted values."""


@dataclass(frozen=True)
class CalibrationResult:
    """Fitted parameters, their uncertainty, residuals and the calibrated case.

    Attributes
    ----------
    params : tuple of FitParam
    x : array
        Fitted values, in each parameter's unit.
    covariance : array
        Covariance of ``x`` (units squared).
    ci95 : array, shape (n, 2)
        95 % confidence intervals, in each unit.
    residuals : pandas.DataFrame
        quantity, z_m, value, uncertainty, model, residual (model - value), weighted.
    chi2 : float
        Sum of squared weighted residuals, -.
    dof : int
        Points minus parameters.
    case : dict
        The base case with the fitted values (units as typed).
    success : bool
    message : str
    nfev : int
        Model evaluations.
    absolute_sigma : bool
    at_bound : tuple of bool
        Parameters that ended on a bound (their interval is not meaningful).
    cases : dict
        Name -> calibrated case, for a fit over several cases (:func:`calibrate_cases`).
    """

    params: tuple[FitParam, ...]
    x: np.ndarray
    covariance: np.ndarray
    ci95: np.ndarray
    residuals: pd.DataFrame
    chi2: float
    dof: int
    case: dict = field(repr=False)
    success: bool = True
    message: str = ""
    nfev: int = 0
    absolute_sigma: bool = True
    at_bound: tuple[bool, ...] = ()
    cases: dict = field(default_factory=dict, repr=False)

    @property
    def stderr(self) -> np.ndarray:
        """Standard errors of ``x``, in each unit."""
        return np.sqrt(np.clip(np.diag(self.covariance), 0, None))

    @property
    def correlation(self) -> pd.DataFrame:
        """Correlation matrix of the parameters, -."""
        se = self.stderr
        with np.errstate(invalid="ignore", divide="ignore"):
            c = self.covariance / np.outer(se, se)
        names = [p.path for p in self.params]
        return pd.DataFrame(c, index=names, columns=names)

    @property
    def reduced_chi2(self) -> float:
        """chi2 / dof (about 1 when the model and the uncertainties are right), -."""
        return self.chi2 / self.dof if self.dof > 0 else math.nan

    def to_frame(self) -> pd.DataFrame:
        """One row per parameter: start, fitted value, standard error, 95 % interval, unit."""
        frame = pd.DataFrame(
            {
                "parameter": [p.path for p in self.params],
                "start": [p.x0 for p in self.params],
                "value": self.x,
                "stderr": self.stderr,
                "ci95_low": self.ci95[:, 0],
                "ci95_high": self.ci95[:, 1],
                "unit": [p.unit for p in self.params],
                "at_bound": list(self.at_bound) or [False] * len(self.params),
            }
        )
        cols = ["start", "value", "stderr", "ci95_low", "ci95_high"]
        return with_units(frame, "studies.calibration", dict.fromkeys(cols, "@unit"))

    def summary(self) -> dict:
        """Scalars and tables as plain data (JSON-ready)."""
        return {
            "success": self.success,
            "message": self.message,
            "model_evaluations": self.nfev,
            "points": len(self.residuals),
            "chi2": self.chi2,
            "dof": self.dof,
            "reduced_chi2": self.reduced_chi2,
            "rms_residual": float(np.sqrt(np.mean(self.residuals["residual"] ** 2))),
            "absolute_sigma": self.absolute_sigma,
            "parameters": self.to_frame().to_dict(orient="records"),
            "correlation": self.correlation.round(6).values.tolist(),
        }

    def write_case(self, path, case: dict | None = None) -> Path:
        """Write the calibrated case (or ``case``, one of :attr:`cases`) as YAML with units,
        atomically."""
        import yaml

        from rotarykiln.outputs import write_text_atomic

        lines = ["# calibrated by rotarykiln calibrate (weighted least squares)"]
        for p, x, (lo, hi) in zip(self.params, self.x, self.ci95, strict=True):
            lines.append(f"# {p.path} = {p.value(x)} (95 % interval {lo:.6g} to {hi:.6g})")
        lines.append(f"# chi2 = {self.chi2:.4g} for {self.dof} degrees of freedom")
        body = self.case if case is None else case
        text = "\n".join(lines) + "\n" + yaml.safe_dump(body, sort_keys=False)
        return write_text_atomic(path, text)

    def plot(self):
        """Residual plot: model - measured against z (error bars: the uncertainty), one panel
        per profile quantity plus one for the scalar outputs; returns the Figure."""
        import matplotlib.pyplot as plt

        r = self.residuals
        prof = [
            q
            for q in dict.fromkeys(r["quantity"])
            if r.loc[r["quantity"] == q, "z_m"].notna().all()
        ]
        scal = r[r["z_m"].isna()]
        n = len(prof) + (1 if len(scal) else 0)
        fig, axes = plt.subplots(1, n, figsize=(4.2 * n, 3.4), squeeze=False)
        for ax, q in zip(axes[0], prof, strict=False):
            s = r[r["quantity"] == q]
            ax.errorbar(s["z_m"], s["residual"], yerr=s["uncertainty"], fmt="o", capsize=3)
            ax.axhline(0, color="k", lw=0.7)
            ax.set_xlabel("z (m)")
            ax.set_title(q, fontsize="medium")
        if len(scal):
            ax = axes[0][-1]
            x = np.arange(len(scal))
            ax.errorbar(x, scal["residual"], yerr=scal["uncertainty"], fmt="s", capsize=3)
            ax.axhline(0, color="k", lw=0.7)
            ax.set_xticks(x, scal["quantity"], rotation=20, ha="right", fontsize="x-small")
            ax.set_title("outlet values", fontsize="medium")
        axes[0][0].set_ylabel("model - measured")
        fig.suptitle(
            f"residuals after calibration: chi2/dof = {self.reduced_chi2:.3g}", fontsize="medium"
        )
        fig.tight_layout()
        return fig

    def save_plot(self, path) -> Path:
        """Save :meth:`plot` atomically (format by suffix); returns the path."""
        import matplotlib.pyplot as plt

        fig = self.plot()
        try:
            return save_figure_atomic(path, fig, dpi=110)
        finally:
            plt.close(fig)


def calibrate(
    func: Callable[[dict], Mapping],
    base_case: Mapping,
    params: Sequence,
    measurements,
    *,
    absolute_sigma: bool = True,
    diff_step: float = 1e-6,
    max_nfev: int = 200,
) -> CalibrationResult:
    """Fit case fields to measured data by weighted least squares.

    Parameters
    ----------
    func : callable
        Model ``case -> dict of scalars``; profiles as ``"<quantity>@<z>"`` outputs.
    base_case : mapping
        The case; its other fields stay as they are.
    params : sequence of FitParam or str
        ``"path=start [low, high]"`` (see :func:`parse_fit`).
    measurements : Measurements, DataFrame or path
        See :func:`read_measurements`.
    absolute_sigma : bool
        True: the uncertainties are standard deviations (covariance ``(J^T J)^-1``); False:
        relative weights (covariance scaled by chi2/dof, intervals from Student's t).
    diff_step : float
        Relative finite-difference step of the Jacobian, -.
    max_nfev : int
        Most model evaluations.

    Returns
    -------
    CalibrationResult
        Values, covariance, 95 % intervals, correlation, residuals, calibrated case.

    Examples
    --------
    >>> from rotarykiln.studies.examples import exponential_heating, EXPONENTIAL_CASE
    >>> import pandas as pd
    >>> data = pd.DataFrame({"quantity": "bed", "z": [0.5, 1.0, 1.5, 2.0],
    ...                      "value": [403.7, 480.5, 537.4, 579.5], "uncertainty": 5.0})
    >>> r = calibrate(exponential_heating, EXPONENTIAL_CASE, ["heat.exchange=1 1/m"], data)
    >>> round(float(r.x[0]), 2), r.case["heat"]["exchange"].endswith(" 1/m")
    (0.6, True)

    References
    ----------
    scipy.optimize.least_squares (trust-region reflective); Press et al., Numerical Recipes,
    3rd ed. (2007), sec. 15.5-15.6 (covariance and confidence regions of fitted parameters).
    """
    fit = _fit_params(params)
    meas = (
        measurements if isinstance(measurements, Measurements) else read_measurements(measurements)
    )
    _check_counts(meas, fit)
    create = False
    for p in fit:
        create |= _absent_but_allowed(base_case, p.path)
    return _fit(func, {"": base_case}, fit, meas, create, absolute_sigma, diff_step, max_nfev, 1)


def calibrate_cases(
    func: Callable[[dict], Mapping],
    cases: Mapping[str, Mapping],
    params: Sequence,
    measurements,
    *,
    absolute_sigma: bool = False,
    diff_step: float = 1e-6,
    max_nfev: int = 200,
    workers: int = 1,
) -> CalibrationResult:
    """Fit case fields shared by several cases (operating points) to their measured data.

    The same fitted values are set in every case (a global factor, a lining property...); the
    measurements name their case in a ``case`` column.

    Parameters
    ----------
    func : callable
        Model ``case -> dict of scalars`` (module level when ``workers`` > 1).
    cases : mapping
        Case name -> case (nested dict).
    params : sequence of FitParam or str
        ``"path=start [low, high]"``; each path must exist in every case.
    measurements : Measurements, DataFrame or path
        With a ``case`` column naming a key of ``cases``.
    absolute_sigma : bool
        False (default here): the uncertainties are relative weights and the covariance is
        scaled by chi2/dof (model error usually dominates over many operating points).
    diff_step : float
        Relative finite-difference step, -.
    max_nfev : int
        Most evaluations (each runs every case).
    workers : int
        Processes evaluating the cases in parallel.

    Returns
    -------
    CalibrationResult
        As :func:`calibrate`; ``cases`` holds every calibrated case and the residual table a
        ``case`` column.

    Examples
    --------
    >>> from rotarykiln.studies.examples import exponential_heating, EXPONENTIAL_CASE
    >>> import copy, pandas as pd
    >>> hot = copy.deepcopy(EXPONENTIAL_CASE); hot["heat"]["gas_temperature"] = "800 K"
    >>> data = pd.DataFrame({"case": ["a", "a", "b", "b"], "quantity": "bed",
    ...                      "z": [0.5, 2.0] * 2, "value": [403.7, 579.5, 429.6, 649.4],
    ...                      "uncertainty": 5.0})
    >>> r = calibrate_cases(exponential_heating, {"a": EXPONENTIAL_CASE, "b": hot},
    ...                     ["heat.exchange=1 1/m"], data)
    >>> round(float(r.x[0]), 2), sorted(r.cases)
    (0.6, ['a', 'b'])

    References
    ----------
    As :func:`calibrate`.
    """
    fit = _fit_params(params)
    meas = (
        measurements if isinstance(measurements, Measurements) else read_measurements(measurements)
    )
    if not isinstance(cases, Mapping) or not cases:
        raise InputError("cases", cases, "a mapping name -> case with at least one case")
    if meas.case is None:
        raise InputError("measurements", "no case column", "a case column naming each point's case")
    names = [str(k) for k in cases]
    for i, c in enumerate(meas.case):
        if c not in cases:
            hint = difflib.get_close_matches(str(c), names, n=1)
            mean = f"; did you mean {hint[0]}?" if hint else ""
            raise InputError(f"measurements row {i + 1}", c, f"one of the cases{mean}")
    _check_counts(meas, fit)
    create = False
    for case in cases.values():
        for p in fit:
            create |= _absent_but_allowed(case, p.path)
    return _fit(func, dict(cases), fit, meas, create, absolute_sigma, diff_step, max_nfev, workers)


def _fit_params(params) -> list[FitParam]:
    fit = [p if isinstance(p, FitParam) else parse_fit(p) for p in params]
    if not fit:
        raise InputError("--fit", message="--fit: missing (at least one PATH=START)")
    paths = [p.path for p in fit]
    if len(set(paths)) != len(paths):
        raise InputError("--fit", paths, "each path once")
    return fit


def _check_counts(meas: Measurements, fit) -> None:
    if len(meas) < len(fit):
        raise InputError(
            "measurements",
            f"{len(meas)} data points",
            f"at least as many as the fitted parameters ({len(fit)})",
        )


def _call_recording(func, case):
    """``func(case)`` in a worker, with its warnings returned (category, text) rather than
    printed by every process."""
    import warnings

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = func(case)
    return out, [(w.category, str(w.message)) for w in caught]


def _fit(func, cases, fit, meas, create, absolute_sigma, diff_step, max_nfev, workers):
    from concurrent.futures import ProcessPoolExecutor

    from scipy import optimize, stats

    case_of = meas.cases if len(cases) > 1 or "" not in cases else np.full(len(meas), "", object)
    used = [n for n in cases if np.any(case_of == n)]
    rows = {n: np.flatnonzero(case_of == n) for n in used}
    cache: dict[tuple, np.ndarray] = {}
    state: dict = {"predict": {}, "nfev": 0}
    pool = ProcessPoolExecutor(max_workers=workers) if workers > 1 and len(used) > 1 else None

    def with_x(name, x):
        return with_values(
            cases[name], {p.path: p.value(v) for p, v in zip(fit, x, strict=True)}, create=create
        )

    def model(x) -> np.ndarray:
        key = tuple(np.round(x, 14))
        if key in cache:
            return cache[key]
        dicts = [with_x(n, x) for n in used]
        if pool is not None:
            import functools
            import warnings

            outs = []
            for out, caught in pool.map(functools.partial(_call_recording, func), dicts):
                outs.append(out)
                for category, text in caught:
                    warnings.warn(text, category, stacklevel=2)
        else:
            outs = [func(d) for d in dicts]
        state["nfev"] += 1
        y = np.empty(len(meas))
        for n, out in zip(used, outs, strict=True):
            if n not in state["predict"]:
                state["predict"][n] = _Predictor(out, meas, rows[n])
            y[rows[n]] = state["predict"][n](out)
        cache[key] = y
        return y

    def at(x) -> str:
        return ", ".join(f"{p.path}={p.value(v)}" for p, v in zip(fit, x, strict=True))

    def residual(x):
        try:
            r = (model(x) - meas.value) / meas.uncertainty
        except (InputError, MemoryError):  # a user's mistake, or memory: not a solver failure
            raise
        except _OutputsChanged as exc:
            raise InputError(
                "--fit",
                message=f"--fit: {', '.join(p.path for p in fit)} cannot be fitted: changing it "
                f"changes the model's outputs ({exc} moved or vanished; kiln.length and "
                "solver.cells move the profile positions). Fields that can be fitted: numeric "
                "case fields that keep the outputs, e.g. gas.flow, wall.emissivity",
            ) from None
        except Exception as exc:  # a failed solve inside the fit
            raise ConvergenceError(f"the model failed at {at(x)}: {shown(exc, 300)}") from exc
        if not np.all(np.isfinite(r)):
            i = int(np.argmax(~np.isfinite(r)))
            raise ConvergenceError(
                f"the model gave a non-finite residual at {at(x)}",
                point=i + 1,
                quantity=str(meas.quantity[i]),
            )
        return r

    x0 = np.array([p.x0 for p in fit])
    lo = np.array([p.lower for p in fit])
    hi = np.array([p.upper for p in fit])
    try:
        with np.errstate(over="ignore", invalid="ignore"):  # checked below
            sol = optimize.least_squares(
                residual,
                x0,
                bounds=(lo, hi),
                x_scale="jac",
                diff_step=diff_step,
                max_nfev=max_nfev,
                method="trf",
            )
        pred = model(sol.x)
    except ValueError as exc:  # scipy's own checks (a non-finite Jacobian...)
        if isinstance(exc, InputError):
            raise
        raise ConvergenceError(f"the least-squares fit failed: {shown(exc, 300)}") from None
    finally:
        if pool is not None:
            pool.shutdown(cancel_futures=True)
    r = sol.fun
    with np.errstate(over="ignore", invalid="ignore"):
        chi2 = float(r @ r)
        J = sol.jac
        jtj = J.T @ J
    dof = len(meas) - len(fit)
    if not (np.all(np.isfinite(r)) and math.isfinite(chi2) and np.all(np.isfinite(jtj))):
        raise ConvergenceError(
            "the fit's residuals or Jacobian are not finite (values or uncertainties of very "
            "different magnitudes?)",
            chi2=chi2,
        )
    cov = np.linalg.pinv(jtj)
    if not absolute_sigma:
        if dof <= 0:
            raise InputError(
                "measurements", f"{len(meas)} points", "more points than parameters to scale"
            )
        cov = cov * chi2 / dof
        q = stats.t.ppf(0.975, dof)
    else:
        q = stats.norm.ppf(0.975)
    se = np.sqrt(np.clip(np.diag(cov), 0, None))
    if not (np.all(np.isfinite(cov)) and np.all(np.isfinite(sol.x))):
        raise ConvergenceError("the fit's covariance is not finite", chi2=chi2)
    ci = np.column_stack([sol.x - q * se, sol.x + q * se])
    res_frame = meas.to_frame()
    res_frame["model"] = pred
    res_frame["residual"] = pred - meas.value
    res_frame["weighted"] = r
    calibrated = {n: with_x(n, sol.x) for n in cases}
    return CalibrationResult(
        tuple(fit),
        sol.x,
        cov,
        ci,
        res_frame,
        chi2,
        dof,
        next(iter(calibrated.values())),
        bool(sol.success),
        str(sol.message),
        state["nfev"],
        absolute_sigma,
        tuple(bool(a) for a in np.asarray(sol.active_mask) != 0),
        calibrated if len(cases) > 1 or "" not in cases else {},
    )
