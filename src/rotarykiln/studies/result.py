"""The table of a sweep, its files and its plot."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from rotarykiln.errors import InputError
from rotarykiln.studies.design import CaseSpec, si_value
from rotarykiln.studies.io import (
    parquet_available,
    save_figure_atomic,
    write_csv_atomic,
    write_parquet_atomic,
)
from rotarykiln.studies.paths import get_path
from rotarykiln.tables import split_unit, with_units

__all__ = ["SweepResult", "SI_SUFFIX", "sweep_units"]

#: Suffix of the column holding the SI value of a swept path.
SI_SUFFIX = " [SI]"

#: Outputs drawn by :meth:`SweepResult.plot` when none are named.
PLOT_OUTPUTS = 8

# the solver's bookkeeping, not drawn by default (last word of the output's name)
_BOOKKEEPING = {"iterations", "residual", "cells", "relative"}


def profile_unit(quantity: str) -> str:
    """Unit of a profile output ``<quantity>@<z>`` (``bed_temperature`` -> ``"K"``)."""
    return "K" if quantity.endswith("temperature") else ""


def sweep_units(frame: pd.DataFrame, parameters: Sequence[str]) -> dict[str, str]:
    """Units of the columns of a sweep table that do not end in their unit.

    A swept path holds values as given (``""``); its ``<path> [SI]`` column the SI unit of the
    first value with a unit (``""`` when the values are bare numbers or labels); a profile
    output ``<quantity>@<z>`` the unit of the quantity.

    Examples
    --------
    >>> f = pd.DataFrame({"bed.speed": ["1 rpm"], "bed.speed [SI]": [0.1], "fill": [0.1]})
    >>> sweep_units(f, ["bed.speed"])
    {'bed.speed': '', 'bed.speed [SI]': 'rad/s'}
    """
    units: dict[str, str] = {}
    for p in parameters:
        units[p] = ""
        units[p + SI_SUFFIX] = _si_unit(frame[p]) if p in frame else ""
    for c in frame.columns:
        q, sep, _ = str(c).rpartition("@")
        if sep and q:
            units[str(c)] = profile_unit(q)
    return units


def _si_unit(values) -> str:
    from rotarykiln.units import ureg

    for v in values:
        if not isinstance(v, str):
            continue
        try:
            q = ureg.Quantity(v.strip()).to_base_units()
        except Exception:
            continue
        return format(q.units, "~").replace(" ", "").replace("**", "") or "1"
    return ""


@dataclass(frozen=True)
class SweepResult:
    """Results of a sweep: one row per case.

    Attributes
    ----------
    frame : pandas.DataFrame
        Columns ``case_id``, ``group``, each swept path (value as given, the base case's value
        where the case does not set it) and ``<path> [SI]``,
        the outputs, ``error`` ("" when the case ran) and ``elapsed_s``.
    parameters : tuple of str
        Swept paths.
    outputs : tuple of str
        Output names (union over cases).
    wall_time : float
        Wall-clock time of the whole sweep, s.
    executor : str
    """

    frame: pd.DataFrame
    parameters: tuple[str, ...]
    outputs: tuple[str, ...]
    wall_time: float = 0.0
    executor: str = ""
    meta: dict = field(default_factory=dict)

    @classmethod
    def from_rows(
        cls, rows: Sequence[dict], cases: Sequence[CaseSpec], wall_time=0.0, executor="", base=None
    ):
        """Assemble the table; parameters a case does not set show the base case's value."""
        by_id = {c.case_id: c for c in cases}
        params: list[str] = []
        for c in cases:
            for p in c.values:
                if p not in params:
                    params.append(p)
        outputs: list[str] = []
        for r in rows:
            for k in r["outputs"]:
                if k not in outputs:
                    outputs.append(k)
        clash = [
            o for o in outputs if o in params or o in ("case_id", "group", "error", "elapsed_s")
        ]
        if clash:
            raise InputError(
                "sweep.outputs", clash[0], "an output name distinct from parameters and columns"
            )
        base_values = {}
        for p in params:
            try:
                base_values[p] = get_path(base, p) if base is not None else None
            except InputError:  # a path created by the sweep
                base_values[p] = None
        records = []
        for r in sorted(rows, key=lambda r: r["case_id"]):
            spec = by_id[r["case_id"]]
            rec = {"case_id": r["case_id"], "group": r["group"]}
            for p in params:
                v = spec.values.get(p, base_values[p])
                rec[p] = v
                rec[p + SI_SUFFIX] = si_value(v) if v is not None else np.nan
            for o in outputs:
                rec[o] = r["outputs"].get(o)
            rec["error"] = r["error"]
            rec["elapsed_s"] = r["elapsed_s"]
            records.append(rec)
        frame = pd.DataFrame.from_records(records)
        return cls(frame, tuple(params), tuple(outputs), wall_time, executor)

    @classmethod
    def from_records(cls, records: Sequence[dict], params: Sequence[str], **kwargs):
        """Assemble the table from flat records (the runner's and the store's row format)."""
        params = list(params)
        outputs: list[str] = []
        for r in records:
            for k in str(r.get("output_names") or "").split(","):
                if k and k not in outputs:
                    outputs.append(k)
        cols = ["case_id", "group"]
        for p in params:
            cols += [p, p + SI_SUFFIX]
        cols += outputs + ["error", "warnings", "elapsed_s", "hash"]
        frame = pd.DataFrame.from_records(list(records))
        for c in cols:
            if c not in frame:
                frame[c] = None
        return cls(frame[cols].reset_index(drop=True), tuple(params), tuple(outputs), **kwargs)

    # ---------------------------------------------------------------------------------------
    def to_frame(self) -> pd.DataFrame:
        """The table (a copy) with its units in ``attrs`` (see :func:`sweep_units`)."""
        frame = self.frame.copy()
        return with_units(frame, "studies.sweep", sweep_units(frame, self.parameters))

    @property
    def n_failed(self) -> int:
        return int((self.frame["error"] != "").sum())

    @property
    def n_warned(self) -> int:
        """Cases whose model raised warnings (column ``warnings``)."""
        if "warnings" not in self.frame:
            return 0
        return int((self.frame["warnings"].fillna("") != "").sum())

    @property
    def failed(self) -> pd.DataFrame:
        """Rows of cases that failed (with their error message)."""
        return self.frame[self.frame["error"] != ""]

    def write(self, out_dir, name: str = "sweep", parquet: bool | None = None) -> list[Path]:
        """Write ``<name>.csv`` (and ``<name>.parquet`` if possible) atomically; returns paths.

        Parameters
        ----------
        out_dir : path
        name : str
        parquet : bool or None
            None: write Parquet only if pyarrow/fastparquet is importable; True: required.
        """
        out = Path(out_dir)
        paths = [write_csv_atomic(self.frame, out / f"{name}.csv")]
        if parquet is None:
            parquet = parquet_available()
        elif parquet and not parquet_available():
            raise InputError("sweep.parquet", True, "possible: install pyarrow for Parquet output")
        if parquet:
            frame = self.frame.copy()
            for p in self.parameters:  # values as given may mix numbers and strings
                frame[p] = frame[p].astype(str)
            paths.append(write_parquet_atomic(frame, out / f"{name}.parquet"))
        return paths

    def plot(self, outputs: Sequence[str] | None = None, parameters: Sequence[str] | None = None):
        """Outputs against each swept parameter; returns the Figure.

        One column of panels per parameter, one row per output. For one-at-a-time designs each
        panel shows the cases of that parameter plus the base case; for grids with several
        parameters, one line per combination of the other parameters. By default the scalar
        outputs that change across the cases (at most :data:`PLOT_OUTPUTS`; not the profiles
        ``<quantity>@<z>`` nor the solver's bookkeeping); axes labelled "name (unit)".
        """
        import matplotlib.pyplot as plt

        outs = list(outputs) if outputs else self._varying_outputs()
        pars = list(parameters or self.parameters)
        for o in outs:
            if o not in self.outputs:
                raise InputError("plot.outputs", o, f"one of {', '.join(self.outputs)}")
        for p in pars:
            if p not in self.parameters:
                raise InputError("plot.parameters", p, f"one of {', '.join(self.parameters)}")
        units = sweep_units(self.frame, self.parameters)
        fig, axes = plt.subplots(
            max(len(outs), 1),
            len(pars),
            figsize=(3.6 * len(pars) + 1.0, 2.4 * max(len(outs), 1) + 0.8),
            squeeze=False,
        )
        ok = self.frame[self.frame["error"] == ""]
        oat = set(self.frame["group"]) - {"grid"}
        for j, p in enumerate(pars):
            if oat:
                sub = ok[ok["group"] == p]
                base = ok[ok["group"] == "base"]
                groups = [("", sub)]
            else:
                others = [q for q in self.parameters if q != p]
                groups = list(ok.groupby(others, dropna=False)) if others else [("", ok)]
                base = None
            for i, o in enumerate(outs):
                ax = axes[i][j]
                for label, g in groups:
                    x = g[p + SI_SUFFIX].to_numpy(float)
                    y = pd.to_numeric(g[o], errors="coerce").to_numpy(float)
                    order = np.argsort(x)
                    ax.plot(x[order], y[order], "o-", label=str(label) if label != "" else None)
                if base is not None and len(base):
                    ax.axhline(
                        pd.to_numeric(base[o], errors="coerce").iloc[0], color="grey", ls=":", lw=1
                    )
                if i == len(outs) - 1:
                    unit = units.get(p + SI_SUFFIX) or "SI"
                    ax.set_xlabel(f"{p} ({unit})")
                name, unit = split_unit(o)
                ax.set_ylabel(f"{name} ({unit})" if unit else name, fontsize="small")
                if len(groups) > 1 and i == 0:
                    ax.legend(fontsize="x-small")
        n_ok = len(ok)
        fig.suptitle(f"sweep of {', '.join(pars)}: {n_ok} case{'s' * (n_ok != 1)}")
        fig.tight_layout(rect=(0, 0, 1, 1 - 0.4 / fig.get_figheight()))  # room for the title
        return fig

    def _varying_outputs(self) -> list[str]:
        """Scalar outputs that change across the cases that ran, in table order (at most
        :data:`PLOT_OUTPUTS`)."""
        ok = self.frame[self.frame["error"] == ""]
        out = []
        for o in self.outputs:
            if "@" in o or o.rsplit("_", 1)[-1] in _BOOKKEEPING or "closure" in o:
                continue
            y = pd.to_numeric(ok[o], errors="coerce").to_numpy(float)
            y = y[np.isfinite(y)]
            if len(y) > 1 and np.ptp(y) > 1e-9 * max(np.abs(y).max(), 1e-300):
                out.append(o)
        return out[:PLOT_OUTPUTS] or [o for o in self.outputs if "@" not in o][:1]

    def save_plot(self, path, **kwargs) -> Path:
        """Save :meth:`plot` atomically to ``path`` (PNG by suffix); returns the path."""
        import matplotlib.pyplot as plt

        fig = self.plot(**kwargs)
        try:
            return save_figure_atomic(path, fig, dpi=100)
        finally:
            plt.close(fig)
