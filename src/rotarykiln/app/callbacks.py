"""What the page does: load a case, check a field as it is typed, run, show the results.

Errors never replace results: a failed load or run changes only the error messages (next to the
field they concern when it is a shown input, else next to the upload or the Run button), so what
was already computed stays on the page and the fields keep what the user typed.

Every value a callback receives comes from the browser and is checked first
(:mod:`rotarykiln.app.checks`): the case text the page sends back with Run is read again as an
upload is, a case naming a file is refused, and a run goes to the run store's worker within its
bounds (:mod:`rotarykiln.app.running`); a busy server answers so at once.
"""

from __future__ import annotations

import logging
import time
from pathlib import Path

import yaml
from dash import ALL, MATCH, Input, Output, State, ctx, dcc, no_update

from rotarykiln.app.checks import (
    case_from_state,
    check_run_size,
    clicks,
    fields_from_state,
    inputs_from_state,
    outlet_from_state,
    parse_app_case,
    shown_paths,
    source_label,
)
from rotarykiln.app.figures import (
    HEIGHTS,
    bed_profile_figure,
    composition_figure,
    rtd_figure,
    temperature_figure,
    transverse_figure,
)
from rotarykiln.app.inputs import apply_edits, check_value, field_of_error, present_inputs
from rotarykiln.app.layout import input_rows, results_view
from rotarykiln.app.loading import load_builtin, load_upload
from rotarykiln.app.running import RunStopped, RunStore, ServerBusy, outlet_temperature
from rotarykiln.case import MAX_CASE_BYTES
from rotarykiln.case_io import case_to_yaml
from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.yaml_limits import load_yaml_text

__all__ = ["press", "register_callbacks", "render"]

log = logging.getLogger(__name__)


def _dump(raw: dict) -> str:
    return yaml.safe_dump(raw, sort_keys=False, allow_unicode=True, width=100)


def _validate(
    raw: dict, source: str, paths: list[str], max_cells: int
) -> tuple[dict[str, str], str]:
    """Errors of a raw case: (path -> message for a shown input, message for the rest)."""
    try:
        check_run_size(parse_app_case(raw, source=source), max_cells)
    except InputError as exc:
        path = field_of_error(exc, paths)
        return ({path: str(exc)}, "") if path else ({}, str(exc))
    return {}, ""


_KEEP = (no_update, no_update)  # no file, the results panel as it is


def _graph(ident: str, figure, kind: str = "") -> dcc.Graph:
    """A figure drawn as wide as the panel (a phone's screen too), redrawn when it changes."""
    return dcc.Graph(
        id=ident,
        figure=figure,
        responsive=True,
        style={"height": f"{HEIGHTS.get(kind, 400)}px"},
        className="graph",
        config={"displaylogo": False},
    )


def _number(value) -> float | None:
    return float(value) if isinstance(value, int | float) and not isinstance(value, bool) else None


def render(result: dict) -> list:
    """The results panel of a run (the data :func:`press` stores): the kiln's profiles, and the
    figures of the case's other models (bed profile, RTD, transverse run)."""
    raw = load_yaml_text(result.get("case_yaml") or "{}", "the run's case", what="case file")
    figures = []
    for name, profiles in result["profiles"].items():
        title = "" if len(result["profiles"]) == 1 else name
        figures.append(
            _graph(f"temperature-graph-{name}", temperature_figure(profiles, title, raw))
        )
        comp = composition_figure(profiles, title)
        if comp is not None:
            figures.append(_graph(f"composition-graph-{name}", comp))
    models = result.get("models") or {}
    graphs = {}
    if models.get("bed"):
        graphs["bed"] = _graph("bed-profile-graph", bed_profile_figure(models["bed"], ""))
    if models.get("rtd"):
        mean = _number(result["summary"].get("rtd_mean_residence_time_s"))
        graphs["rtd"] = _graph("rtd-graph", rtd_figure(models["rtd"], "", mean))
    series = (models.get("transverse") or {}).get("series")
    if series:
        graphs["transverse"] = _graph(
            "transverse-graph", transverse_figure(series, ""), "transverse"
        )
    return results_view(result, outlet_temperature(result["summary"]), figures, graphs)


def press(store: RunStore, saving: bool, n_run, n_save, case_data, values, ids, previous):
    """Run (or, with ``saving``, save) the loaded case with the fields' values.

    Returns the outputs of the Run and Save buttons: the new result's inputs and outlet
    temperature (or ``no_update``: what was computed stays), the errors by field, the message
    under the buttons, the status line, the file to download, and the results panel (drawn with
    the status line, in one answer). Every argument but ``store`` and ``saving`` comes from the
    browser and is checked before it is used.
    """
    n_run, n_save = clicks(n_run), clicks(n_save)
    n = n_run + n_save  # a new status line for every press
    what = f"Save {n_save}" if saving else f"Run {n_run}"
    keep = "" if saving else " The results shown are those of the last successful run."
    if not case_data:
        return no_update, no_update, "Load a case first.", f"{what} not done.", *_KEEP
    paths = shown_paths(ids)
    started = time.perf_counter()
    try:
        if not saving:
            store.check_free()  # a busy answer at once, before reading the case
        fields = fields_from_state(values, ids)
        raw, source = case_from_state(case_data)
        raw = apply_edits(raw, fields)
        if saving:
            text = case_to_yaml(parse_app_case(raw, source=source))
            name = f"{Path(source).stem or 'case'}.yaml"
            status = f"{what}: {name}, the case as edited, with units."
            download = dcc.send_string(text, name)
            return no_update, {"n": n, "errors": {}}, "", status, download, no_update
        store.check_free(store.is_light(raw))  # busy at once, before the case is validated
        result = store.run(raw, source=source)
    except InputError as exc:
        path = field_of_error(exc, paths)
        errors = {path: str(exc)} if path else {}
        message = "" if path else str(exc)
        where = "see the field marked" if path else "see above"
        status = f"{what} not done: {where}.{keep}"
        return no_update, {"n": n, "errors": errors}, message, status, *_KEEP
    except ConvergenceError as exc:
        message = f"solver failed: {exc}"
        return no_update, {"n": n, "errors": {}}, message, f"{what} failed.{keep}", *_KEEP
    except ServerBusy as exc:
        status = f"{what} not done: the server is busy, try again.{keep}"
        return no_update, {"n": n, "errors": {}}, str(exc), status, *_KEEP
    except RunStopped as exc:
        message = f"{exc} (fewer solver.cells run faster; `rotarykiln run` has no such limit)"
        return no_update, {"n": n, "errors": {}}, message, f"{what} stopped.{keep}", *_KEEP
    except Exception as exc:  # a bug, not the user's: the app goes on
        log.exception("run failed")
        message = f"internal error: {type(exc).__name__}: {exc}"
        return no_update, {"n": n, "errors": {}}, message, f"{what} failed.{keep}", *_KEEP
    data = result.to_json()
    data["case_yaml"] = _dump(raw)
    data["previous_outlet"] = outlet_from_state(previous)
    outlet = outlet_temperature(data["summary"])
    # the page keeps only what later callbacks need: the inputs of this run and its outlet
    kept = {"inputs": {"source": source, **fields}, "outlet": outlet[1] if outlet else None}
    seconds = time.perf_counter() - started
    status = f"{what} finished in {seconds:.1f} s: {result.name}"
    return kept, {"n": n, "errors": {}}, "", status, no_update, render(data)


def register_callbacks(app, store: RunStore) -> None:
    """Attach the page's callbacks to a Dash ``app`` whose runs go to ``store``."""

    @app.callback(
        Output("case-store", "data"),
        Output("inputs", "children"),
        Output("upload-error", "children"),
        Output("case-error", "children"),
        Output("case-info", "children"),
        Output("case-description", "children"),
        Output("case-yaml", "children"),
        Output("case-picker", "value"),
        Input("case-picker", "value"),
        Input("case-upload", "contents"),
        State("case-upload", "filename"),
    )
    def load(name, contents, filename):
        try:
            if ctx.triggered_id == "case-upload":
                raw = load_upload(contents, filename)
                source = source_label(filename)
                info, picker = f"Loaded: {source} (uploaded)", None
            else:
                if not name:
                    return (no_update,) * 8
                raw = load_builtin(name)
                source, info, picker = name, f"Loaded: {name} (built-in)", no_update
            text = _dump(raw)
            if len(text.encode("utf-8", "surrogatepass")) > MAX_CASE_BYTES:
                raise InputError(
                    source,
                    message=f"{source}: too large for a case file once its YAML aliases are "
                    f"written out (at most {MAX_CASE_BYTES / 1e6:g} MB; a case is a few kB)",
                )
        except InputError as exc:  # nothing else changes: the loaded case stays
            return (no_update,) * 2 + (str(exc),) + (no_update,) * 5
        items = present_inputs(raw)
        paths = [i.path for i, _ in items]
        field_errors, case_error = _validate(raw, source, paths, store.max_cells)
        if case_error:
            case_error = f"This case has an error: {case_error}"
        data = {"yaml": text, "source": source}
        return (
            data,
            input_rows(items, field_errors),
            "",
            case_error,
            info,
            str(raw.get("description") or ""),
            data["yaml"],
            picker,
        )

    @app.callback(
        Output({"type": "input-error", "path": MATCH}, "children"),
        Input({"type": "main-input", "path": MATCH}, "value"),
        Input("run-errors", "data"),
        State({"type": "main-input", "path": MATCH}, "id"),
        prevent_initial_call=True,
    )
    def check_field(value, run_errors, ident):
        try:
            path = next(iter(fields_from_state([value], [ident])))
        except InputError as exc:
            return str(exc)
        if ctx.triggered_id == "run-errors":
            errors = run_errors.get("errors") if isinstance(run_errors, dict) else None
            message = errors.get(path) if isinstance(errors, dict) else None
            if isinstance(message, str):
                return message[:1000]
        try:
            check_value(path, value)
        except InputError as exc:
            return str(exc)
        return ""

    @app.callback(
        Output("result-store", "data"),
        Output("run-errors", "data"),
        Output("run-error", "children"),
        Output("run-status", "children"),
        Output("case-download", "data"),
        Output("results", "children"),
        Input("run-button", "n_clicks"),
        Input("save-button", "n_clicks"),
        State("case-store", "data"),
        State({"type": "main-input", "path": ALL}, "value"),
        State({"type": "main-input", "path": ALL}, "id"),
        State("result-store", "data"),
        prevent_initial_call=True,
        running=[
            (Output("run-button", "disabled"), True, False),
            (Output("save-button", "disabled"), True, False),
        ],
    )
    def run(n_run, n_save, case_data, values, ids, previous):
        saving = ctx.triggered_id == "save-button"
        return press(store, saving, n_run, n_save, case_data, values, ids, previous)

    @app.callback(
        Output("stale-note", "children"),
        Input({"type": "main-input", "path": ALL}, "value"),
        Input({"type": "main-input", "path": ALL}, "id"),
        Input("result-store", "data"),
        State("case-store", "data"),
    )
    def stale(values, ids, result, case_data):
        before = inputs_from_state(result)
        if before is None or not isinstance(case_data, dict):
            return ""
        try:
            now = {
                "source": source_label(case_data.get("source")),
                **fields_from_state(values, ids),
            }
        except InputError:
            return ""
        if now == before:
            return ""
        return "The inputs have changed since these results: press Run to update them."
