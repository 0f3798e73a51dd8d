"""The HTML report of a run: one self-contained file to read offline or send to a colleague.

``rotarykiln run CASE --report`` (and ``rotarykiln demo``) write ``report.html`` beside the other
results. Every number of the run's summary is shown once, in the section it belongs to, in the
units people read (kW, K with degrees Celsius, kg/h or t/h, minutes), to sensible significant
figures, with values below the balance tolerance shown as 0:

- the case, its values as the user typed them when the case file can be read (else as
  validated, with units), and the warnings raised during the run (once each);
- for a kiln run, the results (outlet temperatures, flows, conversions) beside the profiles;
  measured against computed temperatures at every measured point, with the RMSE per quantity;
  the energy balance sheet (kW and % of the input) with a bar chart of it, the fuel's heating
  values and why the heat of combustion differs from the LHV; the burner (air ratio lambda
  beside the excess air); the regime and the cross-section with their figures; the residence
  time (with the RTD figure); the balances and the solver's convergence;
- the results of the other models run (transport, rtd), the other figures, the files written.

The page is rendered with jinja2 from ``rotarykiln/templates/report.html``; it loads nothing from
the network. Every value carries its summary key(s) (``data-keys``) and its exact SI value
(``data-value``) for a reader or a test to check against ``summary.json``.
"""

from __future__ import annotations

import base64
import datetime as _dt
import io
import math
import os
import re
import warnings as _warnings
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from rotarykiln.report import (
    air_ratio,
    denoise,
    format_power,
    format_quantity,
    significant,
)
from rotarykiln.tables import split_unit  # the one suffix -> unit table

__all__ = [
    "CASE_ECHOES",
    "ENERGY_RTOL",
    "measured_vs_computed",
    "render_html_report",
    "split_unit",
    "typed_case_yaml",
    "write_html_report",
]

ENERGY_RTOL = 1e-6
"""Relative tolerance of the energy balance (the kiln solver's, ``kiln.solve.ENERGY_RTOL``): a
term of the energy sheet below it times the total input is round-off and shown as 0."""

ELEMENT_RTOL = 1e-8
"""Relative tolerance of the element balances (``chemistry.balance.ELEMENT_RTOL``)."""

CASE_ECHOES = ("name", "length_m", "diameter_m", "slope_deg", "speed_rpm", "feed_kg_h")
"""Keys of the case summary that repeat an input: shown in the case section, as typed."""

# --- rows: every summary key shown once -------------------------------------------------------


class _Ledger:
    """The summary keys shown so far: each key goes into one row; a nonzero float equal to one
    already shown with the same unit joins that row (``also``) instead of a row of its own."""

    def __init__(self, flat: Mapping[str, Any], prefixes: Iterable[str] = ("kiln",)):
        self.flat = dict(flat)
        self.prefixes = tuple(f"{p}_" for p in prefixes)
        self.used: dict[str, str] = {}  # key -> where
        self._same: dict[tuple[str, float], dict] = {}

    def has(self, key: str) -> bool:
        return key in self.flat and key not in self.used

    def echo(self, key: str, where: str) -> None:
        """Mark ``key`` as shown elsewhere (the case section)."""
        if key in self.flat:
            self.used.setdefault(key, where)

    def row(
        self,
        key: str | list[str],
        name: str | None = None,
        shown: str | None = None,
        note: str = "",
        where: str = "",
    ) -> dict | None:
        """A row for the summary key(s) ``key`` (None: nothing new to show)."""
        keys = [k for k in ([key] if isinstance(key, str) else key) if self.has(k)]
        if not keys:
            return None
        value = self.flat[keys[0]]
        bare = next((keys[0][len(p) :] for p in self.prefixes if keys[0].startswith(p)), keys[0])
        label, unit = split_unit(bare)
        if name is None:
            name = label
        for k in keys:
            self.used[k] = where
        same = (unit, float(value)) if _is_float(value) and value != 0 else None
        if same is not None and same in self._same:
            earlier = self._same[same]
            earlier["keys"].extend(keys)
            earlier["also"].append(name)
            return None
        row = {
            "keys": keys,
            "name": name,
            "value": shown if shown is not None else format_quantity(value, unit),
            "exact": repr(float(value)) if _is_float(value) else str(value),
            "note": note,
            "also": [],
        }
        if same is not None:
            self._same[same] = row
        return row

    def rows(self, keys: Iterable[str], where: str, **names: str) -> list[dict]:
        out = []
        for key in keys:
            row = self.row(key, names.get(key), where=where)
            if row is not None:
                out.append(row)
        return out

    def left(self, prefix: str = "") -> list[str]:
        return [k for k in self.flat if k.startswith(prefix) and k not in self.used]


def _is_float(value: Any) -> bool:
    return isinstance(value, float) and math.isfinite(value)


# --- the case as typed ------------------------------------------------------------------------


def _case_file(source: str | None) -> Path | None:
    """The case file ``source`` names (a path or a built-in case), if it can be read."""
    if not source:
        return None
    path = Path(source)
    if path.is_file():
        return path
    try:
        from rotarykiln.cases import builtin_case_path, list_builtin_cases

        return builtin_case_path(source) if source in list_builtin_cases() else None
    except (ImportError, OSError, ValueError):  # pragma: no cover - no built-in cases
        return None


def _typed(written: Any, raw: Any) -> Any:
    """The written-back value ``written`` with the values the user typed (``raw``) in place:
    a string typed (``"3 %"``, ``"12 Nm3/h"``) replaces the written one; a bare number replaces
    it only where the written one has no unit either (a bare number is SI: its unit is kept)."""
    if isinstance(written, dict) and isinstance(raw, dict):
        return {k: _typed(v, raw.get(k)) for k, v in written.items()}
    if isinstance(written, list) and isinstance(raw, list):
        if len(raw) == len(written) and all(isinstance(w, dict) for w in written):
            return [_typed(w, r) for w, r in zip(written, raw, strict=True)]
        scalars = all(not isinstance(r, dict | list) for r in raw)
        if scalars and (len(raw) == len(written) or _k_list(written, raw)):
            return [_typed(w, r) for w, r in zip(written, raw, strict=False)]  # k: as typed
        return written
    if raw is None or isinstance(raw, dict | list) or isinstance(written, dict | list):
        return written
    if isinstance(raw, str) or not isinstance(written, str):
        return raw
    return written


def _k_list(written: list, raw: list) -> bool:
    """A lining conductivity typed with fewer coefficients than written back (zeros added)."""
    return (
        len(raw) < len(written)
        and all(not isinstance(w, str) for w in written)
        and all(w == 0 for w in written[len(raw) :])
    )


_K_UNITS = ("W/(m K)", "W/(m K2)", "W/(m K3)")


def _conductivity_units(text: str) -> str:
    """A unit comment after each lining conductivity ``k: [k0, k1, k2]`` (the file takes bare
    coefficients of k = k0 + k1 T + k2 T^2, T in K)."""

    def note(match: re.Match) -> str:
        n = len([c for c in match.group(2).split(",") if c.strip()])
        return f"{match.group(1)}k: [{match.group(2)}]  # {', '.join(_K_UNITS[:n])}, T in K"

    return re.sub(r"^(\s*)k: \[([^\]]*)\]$", note, text, flags=re.M)


def typed_case_yaml(case, source: str | None = None) -> tuple[str, bool]:
    """The case as YAML with units, its values as the user typed them where the case file can be
    read (and still gives this case), else as validated; lining conductivities annotated with
    their units.

    Parameters
    ----------
    case : Case
        The validated case that was run.
    source : str, optional
        Its case file or built-in name.

    Returns
    -------
    (str, bool)
        The YAML text, and whether the typed values were used.

    Examples
    --------
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> text, typed = typed_case_yaml(load_case(builtin_case_path("limestone_fired")),
    ...                               "limestone_fired")
    >>> typed, "slope: 0.03 m/m" in text, "residence_time: 5400 s" in text
    (True, True, True)
    """
    import yaml

    from rotarykiln.case_io import _CaseDumper, case_hash, dump_case

    written = dump_case(case)
    path, typed = _case_file(source), False
    if path is not None:
        try:
            from rotarykiln.case import load_case, read_case_yaml

            with _warnings.catch_warnings():
                _warnings.simplefilter("ignore")
                same = case_hash(load_case(path)) == case_hash(case)
            raw = read_case_yaml(path) if same else None
        except Exception:  # noqa: BLE001 - an unreadable file: the written-back case is shown
            raw = None
        if isinstance(raw, dict):
            written, typed = _typed(written, raw), True
    text = yaml.dump(written, Dumper=_CaseDumper, sort_keys=False, allow_unicode=True, width=100)
    return _conductivity_units(text), typed


# --- measured against computed -----------------------------------------------------------------

_MEASURED_NAMES = {
    "bed": "bed",
    "gas": "gas",
    "gas_thermocouple": "gas, as a bare thermocouple reads it",
    "gas_wall": "gas near the wall",
    "wall": "inner wall",
}


def measured_vs_computed(case, solution=None) -> dict[str, list[dict]]:
    """The computed temperature at every measured point of a case, and the residual.

    The solution is evaluated where the kiln model scores it
    (:meth:`rotarykiln.kiln.results.solution.KilnSolution.measured_rmse`): bed and gas linear between
    faces, the wall at the measured interface, the gas readings also through the case's
    thermocouple when it has one.

    Parameters
    ----------
    case : Case
        A validated case with ``measurements``.
    solution : KilnSolution, optional
        Its kiln solution (solved again, warnings silenced, when not given).

    Returns
    -------
    dict
        Measured quantity (``"bed"``, ``"gas"``, ``"gas_thermocouple"``, ``"gas_wall"``,
        ``"wall"``) -> rows ``{"z_m", "measured_K", "computed_K", "residual_K"}`` (residual =
        computed - measured); empty without measurements.
    """
    import numpy as np

    m = case.measurements
    if m is None:
        return {}
    if solution is None:
        from rotarykiln.commands.kiln_runs import run_kiln_case

        with _warnings.catch_warnings():  # the run has shown them; not twice
            _warnings.simplefilter("ignore")
            solution = run_kiln_case(case)
    sol = solution
    at = {
        "bed": sol.bed_temperature_at,
        "gas": sol.gas_temperature_at,
        "gas_wall": sol.gas_temperature_at,
        "wall": lambda z: sol.wall_temperature_at(z, int(m.wall_interface)),
    }
    out: dict[str, list[dict]] = {}
    for key, model in at.items():
        z, t = np.asarray(getattr(m, f"z_{key}"), float), np.asarray(getattr(m, f"t_{key}"), float)
        if not (len(z) and len(t)):
            continue
        out[key] = _points(z, t, model(z))
        tc = m.thermocouple
        if key == "gas" and tc is not None and "gas_velocity" in sol.fluxes:
            cells = sol.gas_thermocouple(tc.diameter, tc.emissivity, tc.bed_view)
            nodes = np.interp(sol.z_nodes, sol.z, cells)
            out["gas_thermocouple"] = _points(z, t, np.interp(z, sol.z_nodes, nodes))
    return out


def _points(z, measured, computed) -> list[dict]:
    return [
        {
            "z_m": float(a),
            "measured_K": float(b),
            "computed_K": float(c),
            "residual_K": float(c - b),
        }
        for a, b, c in zip(z, measured, computed, strict=True)
    ]


def _measured_section(case, ledger: _Ledger, solution=None) -> dict | None:
    if case.measurements is None or not any(k.startswith("kiln_rmse_") for k in ledger.flat):
        return None
    points = measured_vs_computed(case, solution)
    interface = int(case.measurements.wall_interface)
    names = dict(_MEASURED_NAMES)
    if interface:
        names["wall"] = "wall, shell surface" if interface == -1 else f"wall interface {interface}"
    quantities, rows = [], []
    for key, pts in points.items():
        for p in pts:
            rows.append({"quantity": names[key], **_point_text(p), **p})
        res = [p["residual_K"] for p in pts]
        key_rmse = f"kiln_rmse_{key}_K"
        rmse = ledger.flat.get(key_rmse)
        row = ledger.row(key_rmse, names[key], shown="", where="measured")
        quantities.append(
            {
                "name": names[key],
                "points": len(pts),
                "rmse": f"{rmse:.1f} K" if _is_float(rmse) else "",
                "exact": repr(rmse),
                "keys": row["keys"] if row else [],
                "bias": f"{sum(res) / len(res):+.1f} K",
                "worst": f"{max(res, key=abs):+.1f} K",
            }
        )
    return {"points": rows, "quantities": quantities}


def _point_text(p: Mapping[str, float]) -> dict[str, str]:
    return {
        "z": f"{p['z_m']:.2f}",
        "measured": f"{p['measured_K']:.1f}",
        "computed": f"{p['computed_K']:.1f}",
        "residual": f"{p['residual_K']:+.1f}",
    }


# --- the energy balance sheet ------------------------------------------------------------------

# (summary key after "kiln_energy_", label)
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
# summary keys that repeat a term of the sheet
_SHEET_ALIASES = {
    "heat_to_solids_sensible_W": "kiln_heat_to_solids_W",
    "heat_to_solids_reaction_W": "kiln_reaction_heat_W",
    "shell_loss_W": "kiln_shell_loss_W",
}
_COLOURS_IN = ("#8c6d31", "#d95f02", "#e6ab02", "#7570b3", "#a6761d")
_COLOURS_OUT = ("#8c6d31", "#1b9e77", "#66a61e", "#e7298a", "#666666")


def _energy_sheet(kiln: Mapping[str, Any]) -> dict | None:
    """Inputs and outputs of the energy sheet of a kiln summary, W and % of the input; a term
    below :data:`ENERGY_RTOL` of the total input is round-off and counts as 0."""
    get = {k.removeprefix("kiln_energy_"): v for k, v in kiln.items()}
    if "closure_W" not in get:
        return None
    raw_in = sum(abs(float(get.get(k) or 0.0)) for k, _ in _SHEET_IN) or 1.0

    def terms(spec, colours):
        out, nil = [], []
        for (k, label), colour in zip(spec, colours, strict=True):
            value = denoise(float(get.get(k) or 0.0), raw_in, ENERGY_RTOL)
            (out if value else nil).append((k, label, value, colour))
        return out, nil

    (ins, nil_in), (outs, nil_out) = terms(_SHEET_IN, _COLOURS_IN), terms(_SHEET_OUT, _COLOURS_OUT)
    total_in = sum(v for _, _, v, _ in ins)
    total_out = sum(v for _, _, v, _ in outs)
    closure = denoise(float(get["closure_W"]), total_in, ENERGY_RTOL)
    return {
        "inputs": ins,
        "outputs": outs,
        "nil": nil_in + [t for t in nil_out if t[0] not in {k for k, *_ in nil_in}],
        "total_in": total_in,
        "total_out": total_out,
        "closure": closure,
        "closure_raw": float(get["closure_W"]),
        "efficiency": kiln.get("kiln_thermal_efficiency"),
        "lhv": float(get.get("fuel_lhv_input_W") or 0.0),
        "hhv": float(get.get("fuel_hhv_input_W") or 0.0),
        "combustion": float(get.get("combustion_heat_W") or 0.0),
    }


def _energy_section(kiln: Mapping[str, Any], ledger: _Ledger) -> dict | None:
    sheet = _energy_sheet(kiln)
    if sheet is None:
        return None
    total = sheet["total_in"] or 1.0
    carried = "kiln_energy_sensible_input_solids_W"

    def line(key, label, value, side):
        keys = [f"kiln_energy_{key}"]
        if side == "out" and key in _SHEET_ALIASES:
            keys.append(_SHEET_ALIASES[key])
        if side == "out" and f"kiln_energy_{key}" == carried:  # the same number as its input
            return _term(label, value, total, keys=[], note="as it entered")
        row = ledger.row(keys, label, shown=format_power(value), where="energy")
        return _term(label, value, total, keys=row["keys"] if row else keys, row=row)

    inputs = [line(k, label, v, "in") for k, label, v, _ in sheet["inputs"]]
    outputs = [line(k, label, v, "out") for k, label, v, _ in sheet["outputs"]]
    nil_keys = [f"kiln_energy_{k}" for k, *_ in sheet["nil"]]
    nil_keys += [_SHEET_ALIASES[k] for k, *_ in sheet["nil"] if k in _SHEET_ALIASES]
    nil = ledger.row(
        nil_keys,
        "nil terms",
        shown="; ".join(label for _, label, *_ in sheet["nil"]),
        where="energy",
    )
    closure = ledger.row(
        "kiln_energy_closure_W",
        "closure (in - out)",
        shown=format_power(sheet["closure"]),
        note=f"0 below {ENERGY_RTOL:g} of the input" if not sheet["closure"] else "",
        where="energy",
    )
    eff = ledger.row(
        "kiln_thermal_efficiency",
        "thermal efficiency",
        shown=(
            f"{100.0 * sheet['efficiency']:.1f} %"
            if _is_float(sheet["efficiency"])
            else str(sheet["efficiency"])
        ),
        note="heat to the solids (sensible + reactions) / "
        + ("fuel LHV input and electric heating" if sheet["lhv"] else "heat the gas gives up"),
        where="energy",
    )
    fuel = []
    if sheet["lhv"]:
        fuel = [
            ledger.row(
                ["kiln_energy_fuel_lhv_input_W", "kiln_burner_fuel_lhv_input_W"],
                "fuel input, lower heating value (LHV)",
                shown=format_power(sheet["lhv"]),
                where="energy",
            ),
            ledger.row(
                ["kiln_energy_fuel_hhv_input_W", "kiln_burner_fuel_hhv_input_W"],
                "fuel input, higher heating value (HHV)",
                shown=format_power(sheet["hhv"]),
                where="energy",
            ),
        ]
    else:  # no burner: the heating values are 0, not terms
        nil_fuel = ["kiln_energy_fuel_lhv_input_W", "kiln_energy_fuel_hhv_input_W"]
        if nil is not None:
            nil["keys"] += [k for k in nil_fuel if ledger.has(k)]
            for k in nil_fuel:
                ledger.echo(k, "energy")
        else:
            nil = ledger.row(nil_fuel, "nil terms", shown="no fuel", where="energy")
    return {
        "inputs": inputs,
        "outputs": outputs,
        "total_in": _term("total in", sheet["total_in"], total),
        "total_out": _term("total out", sheet["total_out"], total),
        "closure": closure,
        "nil": nil,
        "efficiency": eff,
        "fuel": [r for r in fuel if r is not None],
        "gap": _combustion_gap(sheet, kiln),
        "chart": _energy_chart(sheet),
    }


def _term(label, value, total, keys=(), note="", row=None) -> dict:
    return {
        "name": label,
        "value": format_power(value),
        "exact": repr(float(value)),
        "share": f"{100.0 * value / total:.1f} %",
        "keys": list(keys),
        "note": note,
        "also": row["also"] if row else [],
    }


#: The heat of combustion within this fraction of the LHV input is called the LHV input.
COMBUSTION_GAP_RTOL = 1e-6


def _combustion_gap(sheet: Mapping[str, Any], kiln: Mapping[str, Any]) -> str:
    """Why the heat of combustion is or is not the fuel's LHV input (kiln.firing.flame,
    materials.combustion)."""
    lhv, heat = sheet["lhv"], sheet["combustion"]
    if not lhv or not heat:
        return ""
    gap = lhv - heat
    if abs(gap) <= COMBUSTION_GAP_RTOL * lhv:
        return (
            f"The heat of combustion ({format_power(heat)}) is the LHV input within "
            f"{COMBUSTION_GAP_RTOL:g} of it: the fuel burns completely to CO2 and H2O (vapour) "
            "from streams at 298.15 K, the state of the heating value; the kiln's gas tables "
            "add round-off."
        )
    return (
        f"The heat of combustion ({format_power(heat)}) is {format_power(abs(gap))} "
        f"({100.0 * abs(gap) / lhv:.2g} % of the LHV) {'below' if gap > 0 else 'above'} the "
        "LHV input: the LHV counts complete combustion to CO2 and H2O at 298.15 K, while the "
        "model burns the fuel at the temperature of the unburnt streams, where the products "
        "hold another heat than the reactants (GRI-Mech 3.0); a rich mixture also leaves CO "
        "and H2 unburnt (Cantera's equilibrium products at 1200 K); the kiln's gas tables add "
        "round-off."
    )


def _energy_chart(sheet: Mapping[str, Any]) -> str:
    """An inline SVG of the energy sheet: the inputs and the outputs as two stacked bars."""
    from html import escape

    width, left, bar, top = 760, 60, 34, 10
    span = width - left - 10
    total = max(sheet["total_in"], sheet["total_out"], 1e-300)
    parts = []
    legend = []
    y = top
    for title, items in (("In", sheet["inputs"]), ("Out", sheet["outputs"])):
        parts.append(
            f'<text x="{left - 8}" y="{y + bar / 2 + 5}" text-anchor="end" '
            f'font-size="14" font-weight="bold">{title}</text>'
        )
        x = float(left)
        for _key, label, value, colour in items:
            w = span * value / total
            share = 100.0 * value / sheet["total_in"]
            parts.append(
                f'<rect x="{x:.1f}" y="{y}" width="{max(w, 0.5):.1f}" height="{bar}" '
                f'fill="{colour}"><title>{escape(label)}: {format_power(value)} '
                f"({share:.1f} %)</title></rect>"
            )
            if w > 48:
                parts.append(
                    f'<text x="{x + w / 2:.1f}" y="{y + bar / 2 + 5}" text-anchor="middle" '
                    f'font-size="12" fill="#fff">{share:.0f} %</text>'
                )
            x += w
            if (label, colour) not in [(lb, c) for lb, c, _ in legend]:
                legend.append((label, colour, f"{format_power(value)}, {share:.1f} %"))
        y += bar + 10
    y += 6
    for i, (label, colour, value) in enumerate(legend):
        col, row = i % 2, i // 2
        lx, ly = left + col * (span // 2), y + row * 20
        parts.append(f'<rect x="{lx}" y="{ly}" width="12" height="12" fill="{colour}"/>')
        parts.append(
            f'<text x="{lx + 18}" y="{ly + 11}" font-size="12">{escape(label)}: {value}</text>'
        )
    height = y + 20 * ((len(legend) + 1) // 2) + 4
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}" role="img" font-family="sans-serif" '
        f'aria-label="energy balance: inputs and outputs">{"".join(parts)}</svg>'
    )


# --- burner, regime, residence, convergence ---------------------------------------------------


def _burner_section(ledger: _Ledger) -> list[dict]:
    rows = []
    for key, label in (
        ("kiln_burner_excess_air", "air ratio, all the air"),
        ("kiln_burner_primary_excess_air", "air ratio, primary air only"),
    ):
        if ledger.has(key):
            value = ledger.flat[key]
            rows.append(
                ledger.row(
                    key,
                    label,
                    shown=air_ratio(value) if _is_float(value) else str(value),
                    note="air over the stoichiometric air of the fuel",
                    where="burner",
                )
            )
    names = {
        "kiln_burner_combustion_model": "combustion model",
        "kiln_burner_products_model": "products model (adiabatic temperature)",
        "kiln_burner_adiabatic_temperature_K": "adiabatic flame temperature",
        "kiln_burner_adiabatic_temperature_frozen_K": "adiabatic temperature, frozen products",
        "kiln_burner_flue_gas_flow_kg_s": "flue gas flow",
    }
    rows += ledger.rows(names, "burner", **names)
    rows += ledger.rows(ledger.left("kiln_burner_"), "burner")
    return [r for r in rows if r is not None]


_CROSS_SECTION = (
    "depth_m",
    "chord_m",
    "exposed_bed_width_m",
    "bed_area_m2",
    "covered_wall_arc_m",
    "exposed_wall_arc_m",
    "freeboard_area_m2",
    "freeboard_hydraulic_diameter_m",
)


def _regime_section(case, case_table: Mapping[str, Any], ledger: _Ledger) -> tuple[list, dict]:
    """Rows of the regime and the cross-section, and (fill, froude) when the report computes
    them: for a kiln whose fill the kiln model computed (from a residence time or the transport
    model) the case summary has no regime; it is computed here (rows without summary keys)."""
    if "fill" in case_table:  # typed in the case: shown there
        ledger.echo("fill", "case")
        kiln_fill = ledger.flat.get("kiln_fill")
        if _is_float(kiln_fill) and math.isclose(kiln_fill, case_table["fill"], rel_tol=1e-9):
            ledger.echo("kiln_fill", "case")
        source, table, extra, rows = ledger, case_table, {}, []
    elif _is_float(ledger.flat.get("kiln_fill")) and case.bed is not None:
        from rotarykiln.geometry import CrossSection
        from rotarykiln.report import regime_summary

        fill, radius = float(ledger.flat["kiln_fill"]), case.kiln.diameter / 2
        table = {
            **{k: float(v) for k, v in CrossSection.from_fill(fill, radius).as_dict().items()},
            **regime_summary(radius, case.operation.speed, fill),
        }
        source, extra = _Ledger(table, ()), {"fill": fill, "froude": table["froude"]}
        rows = [ledger.row("kiln_fill", "fill, computed by the kiln model", where="regime")]
    else:
        return [], {}

    local: list[dict] = []  # rows computed for the report: no summary key to carry

    def take(key, name=None, shown=None, note=""):
        first = key if isinstance(key, str) else key[0]
        owner = ledger if ledger.has(first) else source
        row = owner.row(key, name, shown=shown, note=note, where="regime")
        rows.append(row)
        if row is not None and owner is not ledger:
            local.append(row)

    if "regime" in table:
        take(["regime", "criterion"], "regime", note=str(table.get("criterion", "")))
        take("regime_by_henein", "regime by Henein et al. (1983)")
        take("regime_note", "note", shown=str(table.get("regime_note", "")))
    take("froude", "Froude number", shown=significant(table["froude"], 3))
    take(
        "fraction_of_critical",
        "speed / critical speed",
        shown=f"{100.0 * table['fraction_of_critical']:.2f} %",
    )
    take("critical_speed_rpm", "critical speed", shown=f"{table['critical_speed_rpm']:.1f} rpm")
    if "half_angle_deg" in table:
        take(
            ["half_angle_deg", "half_angle_rad"],
            "bed half angle",
            shown=f"{table['half_angle_deg']:.1f} deg ({table['half_angle_rad']:.4f} rad)",
        )
    for key in _CROSS_SECTION:
        if key in table:
            take(key, shown=f"{significant(table[key], 4)} {split_unit(key)[1]}")
    for row in local:
        row["keys"] = []
    return [r for r in rows if r is not None], extra


_RESIDENCE_WORDS = ("residence", "peclet", "dispersion", "plug_flow", "segregated", "rtd_")


def _residence_keys(ledger: _Ledger) -> list[str]:
    return [
        k
        for k in ledger.left("kiln_")
        if any(w in k for w in _RESIDENCE_WORDS) and "onset" not in k
    ]


def _residence_rows(ledger: _Ledger) -> list[dict]:
    keys = _residence_keys(ledger)
    names = {
        "kiln_residence_time_s": "mean residence time of the solids (kiln model)",
        "kiln_rtd_mean_residence_time_s": "mean residence time of the RTD",
        "kiln_rtd_peclet": "Peclet number of the RTD",
        "kiln_rtd_species": "species followed",
    }
    return ledger.rows(keys, "residence", **names)


def _convergence_rows(ledger: _Ledger) -> list[dict]:
    newton = _newton_tolerance()
    rows = []
    for key, name, tol, note in _CONVERGENCE:
        if not ledger.has(key):
            continue
        if key == "kiln_residual":
            note = f"converged below {newton:g}"
        value = ledger.flat[key]
        shown = None
        if tol is not None and _is_float(value):
            small = denoise(value, 1.0, tol)
            shown = significant(small, 2)
            note = f"0 below the tolerance {tol:g}" if not small else f"tolerance {tol:g}"
        elif _is_float(value):
            shown = significant(value, 2)
        rows.append(ledger.row(key, name, shown=shown, note=note, where="convergence"))
    return [r for r in rows if r is not None]


_CONVERGENCE = (
    ("kiln_cells", "cells", None, ""),
    ("kiln_newton_iterations", "Newton iterations", None, ""),
    ("kiln_residual", "Newton residual, max |R| / Q_ref", None, ""),
    (
        "kiln_energy_balance_closure",
        "energy balance closure, of the heat to the solids",
        ENERGY_RTOL,
        "",
    ),
    ("kiln_energy_closure_relative", "energy sheet closure, of the input", ENERGY_RTOL, ""),
    ("kiln_element_balance_closure", "element balance closure, worst element", ELEMENT_RTOL, ""),
)
"""The solver's figures: (summary key, name, tolerance of a closure or None, note)."""


def _newton_tolerance() -> float:
    import inspect

    from rotarykiln.kiln.steady.solve import solve_kiln

    return float(inspect.signature(solve_kiln).parameters["tol"].default)


_RESULT_NAMES = {
    "kiln_bed_outlet_temperature_K": "solids outlet temperature",
    "kiln_gas_outlet_temperature_K": "gas outlet temperature",
    "kiln_bed_max_temperature_K": "solids maximum temperature",
    "kiln_gas_max_temperature_K": "gas maximum temperature",
    "kiln_gas_min_temperature_K": "gas minimum temperature",
    "kiln_solids_outlet_flow_kg_s": "solids outlet flow",
    "kiln_gas_outlet_flow_kg_s": "gas outlet flow",
    "kiln_exhaust_temperature_K": "exhaust temperature (after the air ingress)",
    "kiln_exhaust_flow_kg_s": "exhaust flow",
    "kiln_exhaust_O2_dry_mole_fraction": "exhaust O2, dry",
    "kiln_exhaust_air_ingress_kg_s": "air ingress at the feed end",
}


def _results_rows(ledger: _Ledger) -> list[dict]:
    rows = ledger.rows(_RESULT_NAMES, "results", **_RESULT_NAMES)
    for row in rows:
        if row["keys"][0] == "kiln_exhaust_O2_dry_mole_fraction" and _is_float(
            ledger.flat[row["keys"][0]]
        ):
            row["value"] = f"{100.0 * ledger.flat[row['keys'][0]]:.2f} vol-%"
    return rows


# --- figures -------------------------------------------------------------------------------------


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


def _drawn(fig, name: str, title: str) -> dict[str, str]:
    """A matplotlib figure embedded as PNG (drawn for the report, not written to a file)."""
    import matplotlib.pyplot as plt

    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=100)
    plt.close(fig)
    data = base64.b64encode(buffer.getvalue()).decode("ascii")
    return {"title": title, "file": name, "src": f"data:image/png;base64,{data}"}


def _regime_figures(case, fill: float, froude: float) -> list[dict[str, str]]:
    from rotarykiln.plot import cross_section_figure, regime_map_figure

    return [
        _drawn(regime_map_figure(fill, froude, case.name), "regime_map.png", "regime map"),
        _drawn(
            cross_section_figure(fill, case.kiln.diameter / 2, case.name),
            "cross_section.png",
            "cross-section",
        ),
    ]


_CAPTIONS = {
    "kiln_profiles": "Temperatures along the kiln (solids enter at z = 0), measured points if any.",
    "regime_map": "Mellmann's regime map with the operating point.",
    "cross_section": "The partly filled cross-section.",
    "kiln_rtd": "Residence time distribution and its effect on the conversion.",
}

# --- the report ----------------------------------------------------------------------------------


def render_html_report(
    case,
    *,
    sections: Mapping[str, Mapping[str, Any]],
    warnings: Iterable[str] = (),
    figures: Iterable[str | os.PathLike] = (),
    files: Iterable[str] = (),
    source: str | None = None,
    solution=None,
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
        Figure files to embed (PNG, JPEG or SVG). When there are some and a kiln case has no
        regime map or cross-section (its fill computed by the kiln model), the report draws
        them from the computed fill.
    files : iterable of str
        Names of the other files the run wrote (listed, not embedded).
    source : str, optional
        Where the case came from (a file path or a built-in name): its values are shown as
        typed when the file can be read.
    solution : KilnSolution, optional
        The kiln solution of the run, for the measured-vs-computed table (solved again from
        the case when not given and the case has measurements).

    Returns
    -------
    str
        A complete HTML document that needs no other file.
    """
    import jinja2

    from rotarykiln import __version__
    from rotarykiln.case_io import case_hash

    env = jinja2.Environment(
        loader=jinja2.PackageLoader("rotarykiln", "templates"),
        autoescape=jinja2.select_autoescape(["html"]),
        trim_blocks=True,
        lstrip_blocks=True,
    )
    flat: dict[str, Any] = {}
    for table in sections.values():
        flat.update(table)
    ledger = _Ledger(flat, sections)
    for key in CASE_ECHOES:
        ledger.echo(key, "case")
    case_table = sections.get("case") or {}
    kiln = sections.get("kiln") or {}

    figs = [_figure(Path(p)) for p in figures]

    def take(stems):
        chosen = [f for f in figs if Path(f["file"]).stem in stems]
        for f in chosen:
            figs.remove(f)
        return chosen

    any_figures = bool(figs)
    results = _results_rows(ledger) if kiln else []
    energy = _energy_section(kiln, ledger) if kiln else None
    burner = _burner_section(ledger) if kiln else []
    measured = _measured_section(case, ledger, solution) if kiln else None
    regime, extra = _regime_section(case, case_table, ledger)
    regime_note = next((r for r in regime if r["name"] == "note"), None)
    regime = [r for r in regime if r is not regime_note]
    regime_figs = take(("regime_map", "cross_section"))
    if extra and any_figures and not regime_figs:
        regime_figs = _regime_figures(case, extra["fill"], extra["froude"])
    later = {k for k, *_ in _CONVERGENCE} | set(_residence_keys(ledger))
    rest = [k for k in ledger.left("kiln_") if k not in later]
    results += ledger.rows(rest, "results")  # conversions, onsets, the rest
    residence = _residence_rows(ledger) if kiln else []
    convergence = _convergence_rows(ledger) if kiln else []
    others = []
    for name, table in sections.items():
        rows = ledger.rows([k for k in table if ledger.has(k)], name)
        if rows:
            others.append({"name": name, "rows": rows})
    result_figs = take(("kiln_profiles",))
    rtd_figs = take(("kiln_rtd", "rtd"))
    for f in (*figs, *regime_figs, *result_figs, *rtd_figs):
        f["caption"] = _CAPTIONS.get(Path(f["file"]).stem, "")
    case_yaml, typed = typed_case_yaml(case, source)
    return env.get_template("report.html").render(
        case=case,
        case_yaml=case_yaml,
        typed=typed,
        echoes=[k for k in CASE_ECHOES if k in flat] + (["fill"] if "fill" in case_table else []),
        echoed_kiln_fill=ledger.used.get("kiln_fill") == "case",
        case_hash=case_hash(case),
        source=source,
        version=__version__,
        created=_dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        warnings=list(dict.fromkeys(str(w) for w in warnings)),
        results=results,
        result_figures=result_figs,
        measured=measured,
        energy=energy,
        burner=burner,
        regime=regime,
        regime_figures=regime_figs,
        regime_note=regime_note,
        residence=residence,
        rtd_figures=rtd_figs,
        convergence=convergence,
        others=others,
        figures=figs,
        files=sorted(files),
        energy_rtol=ENERGY_RTOL,
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
