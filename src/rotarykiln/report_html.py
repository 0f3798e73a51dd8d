"""The HTML report of a run: one self-contained file to read offline or send to a colleague.

``rotarykiln run CASE --report`` (and ``rotarykiln demo``) write ``report.html`` beside the other
results: the case with units, the warnings raised during the run, the summary table of every
section run (with the unit of each value), the figures the run wrote (embedded as base64 PNG or
inline SVG), the package version and the hash of the case; for a kiln run also the regime and
cross-section, the energy balance sheet (inputs and outputs, W and % of the input), the balances
and the solver's convergence, and the residence time (its figures beside each). The page is
rendered with jinja2 from ``rotarykiln/templates/report.html``; it loads nothing from the
network.
"""

from __future__ import annotations

import base64
import datetime as _dt
import os
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from rotarykiln.tables import split_unit  # the one suffix -> unit table

__all__ = ["render_html_report", "split_unit", "write_html_report"]


def _shown(value: Any) -> str:
    """A summary value as printed (floats with 5 significant digits, as in summary.txt)."""
    from rotarykiln.report import format_table

    return format_table({"v": value}).split("  ", 1)[1]


def _rows(table: Mapping[str, Any]) -> list[dict[str, str]]:
    keys = [str(k) for k in table]
    first = {k.split("_", 1)[0] for k in keys}
    # the prefix every key of a section's summary shares ("kiln_", "transport_") is not repeated
    prefix = f"{first.pop()}_" if len(first) == 1 and all("_" in k for k in keys) else ""
    rows = []
    for key, value in table.items():
        name, unit = split_unit(str(key).removeprefix(prefix))
        exact = repr(float(value)) if isinstance(value, float) else str(value)
        rows.append(
            {"key": str(key), "name": name, "unit": unit, "value": _shown(value), "exact": exact}
        )
    return rows


def _figure(path: Path) -> dict[str, str]:
    title = path.stem.replace("_", " ")
    if path.suffix.lower() == ".svg":
        text = path.read_text(encoding="utf-8")
        start = text.find("<svg")
        return {"title": title, "file": path.name, "svg": text[start:] if start >= 0 else text}
    data = base64.b64encode(path.read_bytes()).decode("ascii")
    mime = {".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg"}.get(
        path.suffix.lower(), "application/octet-stream"
    )
    return {"title": title, "file": path.name, "src": f"data:{mime};base64,{data}"}


# the energy balance sheet of a kiln run: (summary key after "kiln_energy_", label)
_SHEET_IN = (
    ("sensible_input_solids_W", "solids entering (sensible, above 298.15 K)"),
    ("sensible_input_gas_W", "gas and air entering (sensible)"),
    ("combustion_heat_W", "heat of combustion"),
    ("electric_heating_W", "electric heating"),
    ("sensible_input_air_ingress_W", "air ingress at the feed end (sensible)"),
)
_SHEET_OUT = (
    ("sensible_input_solids_W", "solids entering, carried through"),
    ("heat_to_solids_sensible_W", "heat to the solids, sensible"),
    ("heat_to_solids_reaction_W", "heat to the solids, reactions"),
    ("shell_loss_W", "shell loss"),
    ("exhaust_loss_W", "exhaust (sensible)"),
)
_CONVERGENCE = (
    "cells",
    "newton_iterations",
    "residual",
    "energy_balance_closure",
    "element_balance_closure",
    "energy_closure_relative",
)
_REGIME = (
    "froude",
    "fraction_of_critical",
    "critical_speed_rpm",
    "fill",
    "regime",
    "criterion",
    "regime_by_henein",
    "regime_note",
)
_REGIME_FIGURES = ("regime_map", "cross_section")
_RTD_FIGURES = ("kiln_rtd", "rtd")


def _term(label: str, value: Any, unit: str = "", share: str = "") -> dict[str, str]:
    exact = repr(float(value)) if isinstance(value, float) else str(value)
    return {"name": label, "value": _shown(value), "exact": exact, "unit": unit, "share": share}


def _energy_sheet(kiln: Mapping[str, Any]) -> dict | None:
    """Inputs and outputs of the energy sheet of a kiln summary (W and % of the input)."""
    get = {k.removeprefix("kiln_energy_"): v for k, v in kiln.items()}
    if "closure_W" not in get:
        return None
    scale = sum(abs(float(get.get(k) or 0.0)) for k, _ in _SHEET_IN) or 1.0

    def terms(spec):  # round-off (|value| < 1e-9 of the input) is not a term of the sheet
        return [
            (label, float(get[k])) for k, label in spec if abs(get.get(k) or 0.0) > 1e-9 * scale
        ]

    ins, outs = terms(_SHEET_IN), terms(_SHEET_OUT)
    total = sum(v for _, v in ins) or 1.0

    def rows(items):
        return [_term(label, v, "W", f"{100.0 * v / total:.1f} %") for label, v in items]

    return {
        "inputs": rows(ins),
        "outputs": rows(outs),
        "total_in": _term("total in", sum(v for _, v in ins), "W", "100 %"),
        "total_out": _term("total out", sum(v for _, v in outs), "W"),
        "closure": _term("closure (in - out)", float(get["closure_W"]), "W"),
        "efficiency": kiln.get("kiln_thermal_efficiency"),
        "supplied": "fuel LHV and electric heating"
        if get.get("fuel_lhv_input_W")
        else "heat given up by the gas and electric heating",
    }


def _picked(table: Mapping[str, Any], names: Iterable[str], prefix: str = "") -> list[dict]:
    out = []
    for n in names:
        key = prefix + n
        if key in table:
            name, unit = split_unit(n)
            out.append(_term(name, table[key], unit))
    return out


def _residence(sections: Mapping[str, Mapping[str, Any]]) -> list[dict]:
    """Residence-time rows of every section (transport, rtd, kiln)."""
    out = []
    for sec, table in sections.items():
        for key, value in table.items():
            if any(w in key for w in ("residence", "peclet", "segregated", "plug_flow")):
                name, unit = split_unit(key)
                shown = name if name.startswith(sec) else f"{name} ({sec})"
                out.append(_term(shown, value, unit))
    return out


def render_html_report(
    case,
    *,
    sections: Mapping[str, Mapping[str, Any]],
    warnings: Iterable[str] = (),
    figures: Iterable[str | os.PathLike] = (),
    files: Iterable[str] = (),
    source: str | None = None,
) -> str:
    """The HTML text of the report of a run.

    Parameters
    ----------
    case : Case
        The validated case that was run.
    sections : mapping
        Section name (``"case"``, ``"kiln"``, ``"transport"``...) -> its flat summary dict.
    warnings : iterable of str
        The warnings raised during the run (shown once each, in order).
    figures : iterable of path
        Figure files to embed (PNG, JPEG or SVG).
    files : iterable of str
        Names of the other files the run wrote (listed, not embedded).
    source : str, optional
        Where the case came from (a file path or a built-in name).

    Returns
    -------
    str
        A complete HTML document that needs no other file.
    """
    import jinja2

    from rotarykiln import __version__
    from rotarykiln.case_io import case_hash, case_to_yaml

    env = jinja2.Environment(
        loader=jinja2.PackageLoader("rotarykiln", "templates"),
        autoescape=jinja2.select_autoescape(["html"]),
        trim_blocks=True,
        lstrip_blocks=True,
    )
    shown_warnings = list(dict.fromkeys(str(w) for w in warnings))
    figs = [_figure(Path(p)) for p in figures]

    def take(stems):
        chosen = [f for f in figs if Path(f["file"]).stem in stems]
        for f in chosen:
            figs.remove(f)
        return chosen

    kiln = sections.get("kiln") or {}
    regime_figs, rtd_figs = take(_REGIME_FIGURES), take(_RTD_FIGURES)
    return env.get_template("report.html").render(
        case=case,
        case_yaml=case_to_yaml(case),
        case_hash=case_hash(case),
        source=source,
        version=__version__,
        created=_dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        warnings=shown_warnings,
        sections=[
            {"name": name, "rows": _rows(table)} for name, table in sections.items() if table
        ],
        figures=figs,
        files=sorted(files),
        regime=_picked(sections.get("case") or {}, _REGIME)
        + ([] if "fill" in (sections.get("case") or {}) else _picked(kiln, ("fill",), "kiln_")),
        regime_figures=regime_figs,
        sheet=_energy_sheet(kiln) if kiln else None,
        convergence=_picked(kiln, _CONVERGENCE, "kiln_"),
        residence=_residence(sections),
        rtd_figures=rtd_figs,
    )


def write_html_report(path: str | os.PathLike, case, **kwargs) -> Path:
    """Render the report (:func:`render_html_report`) and write it atomically to ``path``.

    Parameters
    ----------
    path : str or Path
        The HTML file to write (``<out>/report.html``).
    case : Case
        The validated case that was run.
    **kwargs
        Passed to :func:`render_html_report`.

    Returns
    -------
    Path
        The path written.
    """
    from rotarykiln.outputs import write_text_atomic

    return write_text_atomic(path, render_html_report(case, **kwargs))
