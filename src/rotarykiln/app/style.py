"""The page's style sheet, inlined in the page (no asset files, no web fonts: it works offline)."""

from __future__ import annotations

__all__ = ["CSS", "index_string"]

CSS = """
body { margin: 0; font-family: system-ui, -apple-system, "Segoe UI", "DejaVu Sans", sans-serif;
       color: #1f2328; background: #f4f5f7; }
.page { max-width: 1400px; margin: 0 auto; padding: 0 16px 32px; }
.top { display: flex; flex-wrap: wrap; align-items: baseline; gap: 4px 16px;
       padding: 14px 0 10px; }
.top h1 { margin: 0; font-size: 24px; color: #6b3d2e; }
.inputs-panel { position: sticky; top: 8px; max-height: calc(100vh - 64px); overflow-y: auto;
                padding-bottom: 0; }
.run-bar { position: sticky; bottom: 0; z-index: 10; background: #fff; padding: 4px 0 12px;
           border-top: 1px solid #eceef1; margin-top: 12px; }
.stale:not(:empty) { background: #eef4fb; border-left: 3px solid #1a5fb4; padding: 6px 10px;
                     font-size: 14px; margin-bottom: 8px; }
.columns { display: grid; grid-template-columns: minmax(300px, 380px) minmax(0, 1fr);
           gap: 16px; align-items: start; }
@media (max-width: 900px) { .columns { grid-template-columns: minmax(0, 1fr); }
                            .inputs-panel { position: static; max-height: none; } }
.panel { background: #fff; border: 1px solid #d8dbe0; border-radius: 8px; padding: 14px 18px;
         min-width: 0; overflow-wrap: anywhere; }
.panel h2 { font-size: 17px; margin: 8px 0 8px; }
.panel h3 { font-size: 15px; margin: 18px 0 6px; }
.muted { color: #5f6670; }
.small { font-size: 13px; }
.field-label { display: block; font-size: 14px; font-weight: 600; margin: 10px 0 3px; }
.input-label { display: flex; justify-content: space-between; align-items: baseline;
               gap: 8px; }
.input-label .path { overflow: hidden; text-overflow: ellipsis; white-space: nowrap;
                     min-width: 0; }
.path { font-weight: 400; font-family: ui-monospace, "DejaVu Sans Mono", monospace;
        font-size: 11.5px; color: #7a808a; margin-left: 8px; }
.text-input { width: 100%; box-sizing: border-box; padding: 6px 8px; font-size: 15px;
              border: 1px solid #b8bdc5; border-radius: 5px;
              font-family: ui-monospace, "DejaVu Sans Mono", monospace; }
.text-input:focus { outline: 2px solid #8c564b55; border-color: #8c564b; }
.upload { margin-top: 10px; padding: 12px; border: 1.5px dashed #a5abb4; border-radius: 6px;
          text-align: center; font-size: 13.5px; color: #4a5059; cursor: pointer; }
.upload a { color: #1a5fb4; text-decoration: underline; }
.case-info { font-size: 13px; margin-top: 8px; color: #3b4149; }
.error { color: #b00020; font-size: 13.5px; margin-top: 4px; white-space: pre-wrap; }
.error:empty { display: none; }
.field-error:not(:empty) { background: #fdecee; border-left: 3px solid #b00020;
                           padding: 3px 6px; }
.input-row:has(.field-error:not(:empty)) .text-input { border-color: #b00020; }
.buttons { display: flex; gap: 8px; margin-top: 8px; }
.save-button { flex: 0 0 auto; padding: 9px 12px; font-size: 14px; color: #6b3d2e;
               background: #fff; border: 1.5px solid #8c564b; border-radius: 6px;
               cursor: pointer; }
.save-button:hover { background: #fbf6f4; }
.run-button { flex: 1 1 auto; padding: 9px; font-size: 16px; font-weight: 600;
              color: #fff; background: #8c564b; border: none; border-radius: 6px;
              cursor: pointer; }
.run-button:hover { background: #6b3d2e; }
.run-button:disabled { background: #b9a29c; cursor: wait; }
#run-status { margin-top: 6px; }
.case-file { margin-top: 14px; font-size: 13px; }
.yaml { max-height: 360px; overflow: auto; background: #f6f8fa; padding: 8px; font-size: 12px; }
.headline { display: flex; align-items: baseline; gap: 18px; flex-wrap: wrap;
            background: #fbf6f4; border: 1px solid #e6d5cf; border-radius: 8px;
            padding: 10px 16px; margin: 6px 0 10px; }
.headline-label { font-size: 16px; color: #6b3d2e; font-weight: 600; }
.headline-value { font-size: 32px; font-weight: 700; color: #6b3d2e;
                  font-variant-numeric: tabular-nums; overflow-wrap: normal; }
table { border-collapse: collapse; font-size: 14px; max-width: 100%; }
th { text-align: left; font-weight: 500; padding: 3px 14px 3px 0; color: #3b4149; }
td { padding: 3px 8px 3px 0; }
th, td { overflow-wrap: anywhere; vertical-align: top; }
.graph { width: 100%; min-width: 0; }
.model { margin-top: 8px; }
.model h4 { font-size: 14px; margin: 12px 0 4px; }
.note { background: #eef4fb; border-left: 3px solid #1a5fb4; padding: 6px 10px; font-size: 14px; }
code { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: 13px;
       background: #f6f8fa; padding: 1px 4px; border-radius: 3px; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.key-figures { margin-bottom: 6px; }
.warning { background: #fff8e1; border-left: 3px solid #e0a800; padding: 4px 8px;
           margin: 4px 0; font-size: 13px; }
.downloads { columns: 3 180px; padding-left: 18px; font-size: 14px; }
.report-link { display: inline-block; margin: 2px 0 6px; font-weight: 600; }
.all-summary, .run-figures { margin-top: 12px; }
.summary-table { margin-top: 6px; }
.run-figure { max-width: 100%; display: block; margin: 8px 0; }
@media (max-width: 520px) { .page { padding: 0 8px 24px; } .panel { padding: 10px 12px; }
                            .headline { padding: 8px 12px; }
                            .headline-value { font-size: 24px; } }
"""


def index_string() -> str:
    """Dash's page template with :data:`CSS` inlined."""
    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n{%metas%}\n<title>{%title%}</title>\n'
        "{%favicon%}\n{%css%}\n<style>" + CSS + "</style>\n</head>\n<body>\n{%app_entry%}\n"
        "<footer>\n{%config%}\n{%scripts%}\n{%renderer%}\n</footer>\n</body>\n</html>\n"
    )
