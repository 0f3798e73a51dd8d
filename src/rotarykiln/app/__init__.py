"""``rotarykiln app``: an interactive page to try a case in a browser (Dash).

Pick a built-in case or upload a YAML case file, edit its main inputs with units, run it as
``rotarykiln run CASE --report`` does, see the outlet temperature, the profiles and the summary,
download the case, the tables and the report.

Modules, one job each: :mod:`~rotarykiln.app.inputs` (the table of main inputs as dotted paths,
edits applied to the case file's raw mapping), :mod:`~rotarykiln.app.loading` (built-in and
uploaded cases), :mod:`~rotarykiln.app.running` (runs and their files),
:mod:`~rotarykiln.app.figures` (Plotly profiles), :mod:`~rotarykiln.app.summary` (the summary as
text), :mod:`~rotarykiln.app.layout`, :mod:`~rotarykiln.app.style` and
:mod:`~rotarykiln.app.callbacks` (the page), :mod:`~rotarykiln.app.server` (the web server).

Dash is an optional dependency: ``pip install "rotarykiln[app]"``.
"""

from __future__ import annotations

__all__ = ["AppServer", "create_app", "serve"]


def __getattr__(name: str):
    if name in __all__:
        from rotarykiln.app import server

        return getattr(server, name)
    raise AttributeError(name)
