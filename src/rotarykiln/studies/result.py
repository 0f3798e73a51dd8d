"""The table of a sweep, its files and its plot."""

from __future__ import annotations

import difflib
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from rotarykiln.errors import InputError
from rotarykiln.studies.design import CaseSpec, in_unit, si_value, typed_unit
from rotarykiln.studies.io import (
    parquet_available,
    save_figure_atomic,
    shown,
    write_csv_atomic,
    write_parquet_atomic,
)
from rotarykiln.studies.paths import get_path
from rotarykiln.tables import split_unit, with_units

__all__ = ["KEY_OUTPUTS", "SweepResult", "SI_SUFFIX", "sweep_units"]

#: Suffix of the column holding the SI value of a swept path.
SI_SUFFIX = " [SI]"

#: Outputs shown (printed table, one plot panel each) when none are chosen: at most this many.
KEY_OUTPUTS = 5

#: The key outputs of the named models, in the order shown (those a model returns): the kiln
#: (``kiln``, ``kiln_profiles``) and the transport model (``transport``). A reacting bed adds
#: its burn-off or first conversion, any other kiln its thermal efficiency.
_KEY_NAMES = (
    "bed_outlet_temperature_K",
    "gas_outlet_temperature_K",
    "residence_time_s",
    "fill",
    "mean_fill",
    "holdup_kg",
    "mean_residence_time_min",
    "discharge_fill",
)
_KEY_REACTION = ("burn_off_percent", "conversion_")
_KEY_LAST = ("thermal_efficiency",)

# the solver's bookkeeping, not shown by default (last word of the output's name)
_BOOKKEEPING = {"iterations", "residual", "cells", "relative"}

#: Widest header line of the printed table (names wrap after "_" and ".").
_HEADER_WIDTH = 13


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

    # ---------------------------------------------------------------------------------------
    def key_outputs(self) -> list[str]:
        """The outputs shown when none are chosen (at most :data:`KEY_OUTPUTS`).

        For the named models: bed and gas outlet temperatures, residence time and fill, then a
        reacting bed's burn-off (or its first conversion) or else the thermal efficiency; for
        the transport model its four outputs. For any other model: its first scalar outputs
        (not the profiles ``<quantity>@<z>`` nor the solver's bookkeeping), an output whose
        column repeats an earlier one left out.
        """
        names = [o for o in _KEY_NAMES if o in self.outputs]
        if names:
            extra = [o for o in self.outputs if o == _KEY_REACTION[0]]
            extra += [o for o in self.outputs if o.startswith(_KEY_REACTION[1])][:1]
            extra += [o for o in _KEY_LAST if o in self.outputs]
            return (names + extra[:1])[:KEY_OUTPUTS]
        out: list[str] = []
        seen: list[tuple] = []
        for o in self.outputs:
            if "@" in o or o.rsplit("_", 1)[-1] in _BOOKKEEPING or "closure" in o:
                continue
            column = tuple(self.frame[o].tolist())
            if column in seen:  # the same values under another name
                continue
            seen.append(column)
            out.append(o)
            if len(out) == KEY_OUTPUTS:
                break
        return out or list(self.outputs[:1])

    def check_outputs(self, names: Sequence[str] | None, option: str = "outputs") -> list[str]:
        """The chosen outputs (each once, in order), or :meth:`key_outputs` when none.

        A name the model does not return is refused in one line naming the model's outputs
        (and the closest one).
        """
        if not names:
            return self.key_outputs()
        out: list[str] = []
        for name in names:
            if name not in self.outputs:
                hint = difflib.get_close_matches(str(name), self.outputs, n=1, cutoff=0.6)
                mean = f"; did you mean {hint[0]}?" if hint else ""
                raise InputError(
                    option,
                    shown(str(name)),
                    f"an output of the model ({', '.join(self.outputs)}){mean}",
                )
            if name not in out:
                out.append(name)
        return out

    def parameter_units(self) -> dict[str, str]:
        """The unit each swept parameter was typed in (``""``: bare numbers or labels).

        Examples
        --------
        >>> f = pd.DataFrame({"operation.speed": ["1 rpm", "3 rpm"], "x": [1.0, 2.0]})
        >>> SweepResult(f, ("operation.speed", "x"), ()).parameter_units()
        {'operation.speed': 'rpm', 'x': ''}
        """
        return {p: self._typed_unit(p) for p in self.parameters}

    def _typed_unit(self, parameter: str) -> str:
        """The unit of the first value the design gives ``parameter`` (not the base case's:
        one at a time, the rows of that parameter; else every row but the base case)."""
        group = self.frame.get("group", pd.Series("", index=self.frame.index))
        rows = self.frame[parameter][group == parameter]
        if rows.empty:
            rows = self.frame[parameter][group != "base"]
        return typed_unit(rows) or typed_unit(self.frame[parameter])

    def typed_values(self, parameter: str) -> np.ndarray:
        """The values of a swept parameter in the unit it was typed in (NaN for labels)."""
        unit = self._typed_unit(parameter)
        return np.array([in_unit(v, unit) for v in self.frame[parameter]], dtype=float)

    def table(self, outputs: Sequence[str] | None = None) -> pd.DataFrame:
        """The cases with the chosen outputs only: ``case_id``, each parameter in the unit it
        was typed in (column ``"<path> [<unit>]"``; labels as given), the outputs (default
        :meth:`key_outputs`), and ``error`` when a case failed."""
        outs = self.check_outputs(outputs)
        units = self.parameter_units()
        cols: dict[str, object] = {"case_id": self.frame["case_id"].to_numpy()}
        for p in self.parameters:
            values = self.typed_values(p)
            label = f"{p} [{units[p]}]" if units[p] else p
            given = self.frame[p].to_numpy()
            if np.isnan(values).all():  # labels: as given
                cols[label] = given
            elif np.isnan(values).any():  # a value that is not a quantity: as given
                cols[label] = np.array(
                    [g if np.isnan(v) else v for v, g in zip(values, given, strict=True)],
                    dtype=object,
                )
            else:
                cols[label] = values
        for o in outs:
            cols[o] = pd.to_numeric(self.frame[o], errors="coerce").to_numpy(float)
        if self.n_failed:
            cols["error"] = self.frame["error"].fillna("").to_numpy()
        return pd.DataFrame(cols)

    def format_table(
        self,
        outputs: Sequence[str] | None = None,
        width: int = 100,
        max_rows: int = 40,
        error_width: int = 40,
    ) -> str:
        """The :meth:`table` as text for a terminal ``width`` characters wide.

        Headers wrap after ``_`` and ``.`` (at most 13 characters a line; a parameter's unit on
        its own line), numbers take 4 significant digits, errors are cut to ``error_width``
        characters (whole in the files). Columns that do not fit ``width`` go to a further
        block of lines (each block starting with the case number); more than ``max_rows``
        cases show the first 20 and the last 5.
        """
        table = self.table(outputs)
        units = self.parameter_units()
        columns = []
        for c in table.columns:
            label = "case" if c == "case_id" else str(c)
            unit = ""
            for p in self.parameters:
                if c == f"{p} [{units[p]}]" and units[p]:
                    label, unit = p, f"[{units[p]}]"
            header = _wrap(label) + ([unit] if unit else [])
            if c == "error":
                cells = [_cut(str(v), error_width) for v in table[c]]
            elif c == "case_id":
                cells = [str(v) for v in table[c]]
            elif unit or c in self.parameters:
                cells = [_value(v) for v in table[c]]
            else:
                cells = [_number(v) for v in table[c]]
            columns.append((header, cells, c in ("error",)))
        n = len(table)
        rows = list(range(n)) if n <= max_rows else [*range(20), -1, *range(n - 5, n)]
        blocks: list[list[int]] = [[]]
        used = 0
        for j, (header, cells, _) in enumerate(columns):
            w = max([len(x) for x in header] + [len(x) for x in cells])
            if j > 0 and blocks[-1] and used + 2 + w > width:
                blocks.append([0])
                used = max([len(x) for x in columns[0][0]] + [len(x) for x in columns[0][1]])
            blocks[-1].append(j)
            used += (2 if j > 0 else 0) + w
        lines: list[str] = []
        for b, block in enumerate(blocks):
            if b:
                lines.append("")
            widths = {
                j: max([len(x) for x in columns[j][0]] + [len(x) for x in columns[j][1]])
                for j in block
            }

            def line(texts, left, widths=widths, block=block):
                parts = [
                    t.ljust(widths[j]) if left[j] else t.rjust(widths[j])
                    for j, t in zip(block, texts, strict=True)
                ]
                return "  ".join(parts).rstrip()

            left = {j: columns[j][2] for j in block}
            depth = max(len(columns[j][0]) for j in block)
            for k in range(depth):
                head = {j: columns[j][0] for j in block}
                texts = [
                    head[j][k - (depth - len(head[j]))] if k >= depth - len(head[j]) else ""
                    for j in block
                ]
                lines.append(line(texts, left))
            for i in rows:
                if i < 0:
                    lines.append(f"... {n - 25} more cases (all in the CSV/Parquet files) ...")
                    continue
                lines.append(line([columns[j][1][i] for j in block], left))
        return "\n".join(lines)

    def plot(self, outputs: Sequence[str] | None = None, parameters: Sequence[str] | None = None):
        """The chosen outputs against the swept parameters; returns the Figure.

        One panel per output (default :meth:`key_outputs`), the parameter on the x axis in the
        unit it was typed in. A grid: the first parameter on the x axis, one line per
        combination of the others. One at a time with several parameters, or a sampled design
        (Latin hypercube, Sobol, Monte Carlo): one column of panels per parameter (its cases
        and the base case as a dotted line; a scatter of every sample). Axes labelled
        "name (unit)".
        """
        import matplotlib.pyplot as plt

        outs = self.check_outputs(outputs, "plot.outputs")
        pars = list(parameters or self.parameters)
        for p in pars:
            if p not in self.parameters:
                raise InputError("plot.parameters", p, f"one of {', '.join(self.parameters)}")
        units = self.parameter_units()
        ok = self.frame["error"] == ""
        groups = set(self.frame["group"])
        oat = bool(groups - {"grid", "lhs", "sobol", "mc", "sample"})
        sampled = not oat and bool(groups - {"grid"})
        xs = pars if (oat or sampled) and len(pars) > 1 else pars[:1]
        if len(xs) == 1:  # one panel per output, up to 3 a row
            ncols = min(3, len(outs))
            nrows = math.ceil(len(outs) / ncols)
            fig, grid = plt.subplots(
                nrows, ncols, figsize=(3.6 * ncols + 0.6, 2.7 * nrows + 1.0), squeeze=False
            )
            flat = list(grid.ravel())
            for ax in flat[len(outs) :]:
                fig.delaxes(ax)
            axes = [[flat[i]] for i in range(len(outs))]
        else:  # a column of panels per parameter
            fig, axes = plt.subplots(
                len(outs),
                len(xs),
                figsize=(3.8 * len(xs) + 1.2, 2.3 * len(outs) + 0.8),
                squeeze=False,
            )
        legend = None
        for j, p in enumerate(xs):
            x_all = self.typed_values(p)
            labels = None
            if np.isnan(x_all).all():  # labels: one tick each, in order of appearance
                labels = list(dict.fromkeys(str(v) for v in self.frame[p]))
                x_all = np.array([labels.index(str(v)) for v in self.frame[p]], dtype=float)
            if oat:
                lines = [("", (self.frame["group"] == p) & ok)]
                base = ok & (self.frame["group"] == "base")
            elif sampled:
                lines = [("", ok)]
                base = None
            else:
                others = [q for q in self.parameters if q != p]
                lines = [("", ok)]
                if others:
                    keys = self.frame[others].astype(str).agg(", ".join, axis=1)
                    lines = [
                        (
                            _legend(others, self.frame.loc[keys == k, others].iloc[0]),
                            ok & (keys == k),
                        )
                        for k in dict.fromkeys(keys[ok])
                    ]
                base = None
            for i, o in enumerate(outs):
                ax = axes[i][j]
                y_all = pd.to_numeric(self.frame[o], errors="coerce").to_numpy(float)
                for label, mask in lines:
                    m = np.asarray(mask, dtype=bool)
                    x, y = x_all[m], y_all[m]
                    order = np.argsort(x, kind="stable")
                    style = "o" if sampled else "o-"
                    ax.plot(x[order], y[order], style, ms=4, label=label or None)
                if base is not None and base.any():  # the base case: a line and its point
                    b = np.flatnonzero(np.asarray(base))[0]
                    ax.axhline(y_all[b], color="grey", ls=":", lw=1)
                    ax.plot([x_all[b]], [y_all[b]], "o", mfc="none", mec="grey", ms=6)
                if labels is not None:
                    ax.set_xticks(range(len(labels)), labels, fontsize="small")
                if len(xs) == 1 or i == len(outs) - 1:
                    ax.set_xlabel(f"{p} ({units[p]})" if units[p] else p, fontsize="small")
                name, unit = split_unit(o)
                ax.set_ylabel(f"{name} ({unit})" if unit else name, fontsize="small")
                if 1 < len(lines) <= 12 and legend is None:
                    legend = ax.get_legend_handles_labels()
        n_ok = int(ok.sum())
        fig.suptitle(f"sweep of {', '.join(pars)}: {n_ok} case{'s' * (n_ok != 1)}")
        top = 1 - 0.45 / fig.get_figheight()  # room for the title
        if legend is not None:  # the lines of a grid, once, under the title
            rows = math.ceil(len(legend[1]) / 3)
            fig.legend(
                *legend,
                loc="upper center",
                ncols=min(3, len(legend[1])),
                fontsize="small",
                frameon=False,
                bbox_to_anchor=(0.5, top),
            )
            top -= (0.22 * rows + 0.1) / fig.get_figheight()
        fig.tight_layout(rect=(0, 0, 1, top))
        return fig

    def save_plot(self, path, **kwargs) -> Path:
        """Save :meth:`plot` atomically to ``path`` (PNG by suffix); returns the path."""
        import matplotlib.pyplot as plt

        fig = self.plot(**kwargs)
        try:
            return save_figure_atomic(path, fig, dpi=100)
        finally:
            plt.close(fig)


def _wrap(name: str, width: int = _HEADER_WIDTH) -> list[str]:
    """A column name over lines of at most ``width`` characters, broken after "_" and ".".

    Examples
    --------
    >>> _wrap("bed_outlet_temperature_K")
    ['bed_outlet_', 'temperature_K']
    """
    pieces = re.findall(r"[^_.]+[_.]?|[_.]", name) or [name]
    lines = [""]
    for piece in pieces:
        if lines[-1] and len(lines[-1]) + len(piece) > width:
            lines.append("")
        lines[-1] += piece
    return lines


def _float_or_text(v) -> float | str:
    """``v`` as a float, or as text where it is text or not a number (a table cell as given)."""
    if isinstance(v, str):
        return v
    try:
        return float(v)
    except (TypeError, ValueError):
        return str(v)


def _number(v) -> str:
    """A table cell: 4 significant digits, fixed point between 1e-3 and 1e6.

    Examples
    --------
    >>> [_number(v) for v in (1650.228, 0.037862, 21730.99, 3.5, 2.6e-12, 0.0, float("nan"))]
    ['1650', '0.03786', '21731', '3.500', '2.600e-12', '0', '']
    """
    x = _float_or_text(v)
    if isinstance(x, str):
        return x
    if not math.isfinite(x):
        return "" if math.isnan(x) else str(x)
    if x == 0:
        return "0"
    a = abs(x)
    if 1e-3 <= a < 1e6:
        return f"{x:.{max(0, 3 - math.floor(math.log10(a)))}f}"
    return f"{x:.3e}"


def _value(v) -> str:
    """A parameter's cell: its number to 4 significant digits, without trailing zeros.

    Examples
    --------
    >>> [_value(v) for v in (1.0, 2.5, 1.2345678, 12345.0, "steam")]
    ['1', '2.5', '1.235', '12340', 'steam']
    """
    x = _float_or_text(v)
    if isinstance(x, str):
        return x
    return f"{float(f'{x:.4g}'):.10g}" if math.isfinite(x) else ""


def _cut(text: str, width: int) -> str:
    return text if len(text) <= width else text[: width - 3] + "..."


def _legend(names: Sequence[str], values) -> str:
    """A line's label: the other parameters as given (``"gas.flow = 20 kg/h"``)."""
    return ", ".join(f"{n} = {values[n]}" for n in names)
