"""The page: a case panel (pick or upload a case, edit its main inputs, run) beside the results
(outlet temperature, key figures, profiles, the bed profile, RTD and transverse results of the
cases that have them, downloads, the run's figures).

Element ids are part of the app's interface: the browser tests find them (``headline`` is there
after every run; ``outlet-temperature`` carries the solver's value in ``data-kelvin`` for a case
with a kiln model; ``bed-profile``, ``rtd`` and ``transverse`` are the sections of those models).
"""

from __future__ import annotations

from dash import dcc, html

from rotarykiln import __version__
from rotarykiln.app.inputs import MainInput
from rotarykiln.app.summary import (
    bed_rows,
    format_kelvin,
    headline,
    key_figures,
    models_run,
    rtd_rows,
    summary_rows,
    transverse_rows,
)

__all__ = ["input_rows", "page", "results_view"]

DEFAULT_CASE = "tscheng_A16"


def page(cases: list[str]) -> html.Div:
    """The whole page, with ``cases`` offered in the built-in case picker."""
    default = DEFAULT_CASE if DEFAULT_CASE in cases else (cases[0] if cases else None)
    return html.Div(
        className="page",
        children=[
            html.Header(
                className="top",
                children=[
                    html.H1("rotarykiln"),
                    html.Span(f"interactive kiln runs · version {__version__}", className="muted"),
                ],
            ),
            html.Div(className="columns", children=[_case_panel(cases, default), _results()]),
            dcc.Store(id="case-store"),
            dcc.Store(id="result-store"),
            dcc.Store(id="run-errors", data={"n": 0, "errors": {}}),
        ],
    )


def _case_panel(cases: list[str], default: str | None) -> html.Div:
    return html.Div(
        className="panel inputs-panel",
        children=[
            html.H2("Case"),
            html.Label("Built-in case", htmlFor="case-picker", className="field-label"),
            dcc.Dropdown(
                id="case-picker",
                options=[{"label": c, "value": c} for c in cases],
                value=default,
                clearable=False,
                searchable=True,
            ),
            dcc.Upload(
                id="case-upload",
                className="upload",
                children=html.Div(["or drop a YAML case file here, or ", html.A("choose one")]),
                multiple=False,
                # no accept= filter: the drop zone would drop a wrong file silently; the app
                # says what is wrong with it instead
            ),
            html.Div(id="upload-error", className="error"),
            html.Div(id="case-info", className="case-info"),
            html.Div(id="case-description", className="muted small"),
            html.Div(id="case-error", className="error"),
            html.H2("Main inputs"),
            html.P(
                'Values take units: "1.5 rpm", "62 kg/h", "2 deg", "535 K". '
                "Other entries of the case file are kept as they are.",
                className="muted small",
            ),
            html.Div(id="inputs"),
            html.Div(
                className="run-bar",
                children=[
                    html.Div(
                        className="buttons",
                        children=[
                            html.Button("Run", id="run-button", className="run-button", n_clicks=0),
                            html.Button(
                                "Save case",
                                id="save-button",
                                className="save-button",
                                n_clicks=0,
                                title="Download the case as edited (YAML with units)",
                            ),
                        ],
                    ),
                    dcc.Download(id="case-download"),
                    html.Div(id="run-error", className="error"),
                    html.Div(id="run-status", className="muted small"),
                ],
            ),
            html.Details(
                [html.Summary("Case file (YAML)"), html.Pre(id="case-yaml", className="yaml")],
                className="case-file",
            ),
        ],
    )


def input_rows(items: list[tuple[MainInput, str]], errors: dict[str, str]) -> list:
    """A labelled text field for each main input, with the place of its error message."""
    rows = []
    for item, text in items:
        rows.append(
            html.Div(
                className="input-row",
                children=[
                    html.Label(
                        [
                            html.Span(item.label),
                            html.Span(item.path, className="path", title=item.path),
                        ],
                        className="field-label input-label",
                    ),
                    dcc.Input(
                        id={"type": "main-input", "path": item.path},
                        value=text,
                        type="text",
                        debounce=True,
                        className="text-input",
                        spellCheck=False,
                        autoComplete="off",
                    ),
                    html.Div(
                        errors.get(item.path, ""),
                        id={"type": "input-error", "path": item.path},
                        className="error field-error",
                    ),
                ],
            )
        )
    if not rows:
        rows.append(html.P("This case has none of the main inputs.", className="muted"))
    return rows


def _results() -> html.Div:
    placeholder = html.P("Pick a case, change an input and press Run.", className="muted")
    return html.Div(
        className="panel results-panel",
        children=[
            html.Div(id="stale-note", className="stale"),
            dcc.Loading(
                type="default",
                delay_show=200,
                children=html.Div(id="results", children=placeholder),
            ),
        ],
    )


def _previous(previous: float | None, kelvin: float) -> html.Div:
    """The change from the previous run's outlet temperature."""
    if previous is None:
        return html.Div(id="outlet-change")
    change = kelvin - previous
    return html.Div(
        f"{change:+.1f} K from the previous run ({previous:.1f} K)",
        id="outlet-change",
        className="muted",
    )


def _table(rows: list[tuple[str, str, str]], class_name: str) -> html.Table:
    return html.Table(
        className=class_name,
        children=[
            html.Tbody(
                [
                    html.Tr([html.Th(label), html.Td(value, className="num"), html.Td(unit)])
                    for label, value, unit in rows
                ]
            )
        ],
    )


def _headline(result: dict, outlet: tuple[str, float] | None) -> html.Div:
    """The run's main figure: the bed outlet temperature of a kiln model, else the main
    result of the case's other models (:func:`rotarykiln.app.summary.headline`)."""
    if outlet is not None:
        key, kelvin = outlet
        return html.Div(
            id="headline",
            className="headline",
            children=[
                html.Div("Bed outlet temperature", className="headline-label"),
                html.Div(
                    format_kelvin(kelvin),
                    id="outlet-temperature",
                    className="headline-value",
                    **{"data-kelvin": repr(kelvin), "data-key": key},
                ),
                _previous(result.get("previous_outlet"), kelvin),
            ],
        )
    label, value, note = headline(result["summary"], result.get("models") or {})
    return html.Div(
        id="headline",
        className="headline",
        children=[
            html.Div(label, className="headline-label"),
            html.Div(value, id="headline-value", className="headline-value"),
            html.Div(note, className="muted"),
        ],
    )


def _transverse_section(found: dict, graph) -> html.Div:
    """The transverse results, or why the app did not run them and the command that does;
    the run's inputs below."""
    inputs = _table(found.get("inputs") or [], "model-table")
    if found.get("skipped"):
        body = [
            html.P(found["skipped"], className="note", id="transverse-note"),
            html.P(["Command: ", html.Code(found.get("command", ""))], className="small command"),
            html.H4("Inputs of the transverse run"),
            inputs,
        ]
    else:
        body = [
            html.P(
                [
                    "As ",
                    html.Code(found.get("command", "rotarykiln transverse")),
                    " computes them; the command also draws colour maps of the grid at the "
                    "snapshot times.",
                ],
                className="muted small",
            ),
            _table(transverse_rows(found.get("summary") or {}), "model-table"),
            *([graph] if graph is not None else []),
            html.Details([html.Summary("Inputs of the transverse run"), inputs]),
        ]
    return html.Div(
        [html.H3("Transverse results (retort zone)"), *body], id="transverse", className="model"
    )


def model_sections(result: dict, graphs: dict) -> list:
    """The sections of the case's transport, RTD and transverse models, with their figures
    (``graphs``: model -> graph)."""
    summary, models = result["summary"], result.get("models") or {}
    sections = []
    if "bed" in graphs or "transport_model" in summary:
        sections.append(
            html.Div(
                [
                    html.H3("Bed profile (transport model)"),
                    _table(bed_rows(summary), "model-table"),
                    *([graphs["bed"]] if "bed" in graphs else []),
                ],
                id="bed-profile",
                className="model",
            )
        )
    if "rtd" in graphs or "rtd_model" in summary:
        sections.append(
            html.Div(
                [
                    html.H3("Residence time distribution (predicted)"),
                    _table(rtd_rows(summary), "model-table"),
                    *([graphs["rtd"]] if "rtd" in graphs else []),
                ],
                id="rtd",
                className="model",
            )
        )
    if models.get("transverse"):
        sections.append(_transverse_section(models["transverse"], graphs.get("transverse")))
    return sections


def results_view(
    result: dict,
    outlet: tuple[str, float] | None,
    figures: list,
    graphs: dict | None = None,
) -> list:
    """The results panel of one run (``result``: :meth:`RunResult.to_json`; ``figures``: the
    kiln's; ``graphs``: the other models' by name, ``bed``, ``rtd``, ``transverse``)."""
    graphs = graphs or {}
    run_id = result["run_id"]
    summary = result["summary"]
    links = (
        [
            html.A(
                "Open the report",
                href=f"/files/{run_id}/report.html",
                target="_blank",
                className="report-link",
                id="report-link",
            )
        ]
        if "report.html" in result["files"]
        else []
    )
    downloads = html.Ul(
        [
            html.Li(html.A(name, href=f"/files/{run_id}/{name}?download=1", download=name))
            for name in result["files"]
        ],
        id="downloads",
        className="downloads",
    )
    warnings = (
        html.Div(
            [html.H3("Warnings")] + [html.P(w, className="warning") for w in result["warnings"]],
            id="run-warnings",
        )
        if result["warnings"]
        else html.Div(id="run-warnings")
    )
    images = [
        html.Img(src=f"/files/{run_id}/{name}", alt=name, className="run-figure")
        for name in result["files"]
        if name.endswith(".png")
    ]
    sections = model_sections(result, graphs)
    models = result.get("models") or {}
    return [
        html.H2(result["name"], id="result-title"),
        _headline(result, outlet),
        html.P(
            models_run(summary, models, bool(result["profiles"])),
            className="muted small",
            id="models-run",
        ),
        _table(key_figures(summary), "key-figures"),
        warnings,
        *figures,
        *sections,
        html.H3("Downloads"),
        html.Div(links),
        downloads,
        html.Details(
            [html.Summary("All summary values"), _table(summary_rows(summary), "summary-table")],
            className="all-summary",
        ),
        html.Details(
            [html.Summary("Figures of the run"), *images],
            className="run-figures",
            open=not (figures or graphs),  # the only figures when there is nothing to draw
        ),
    ]
