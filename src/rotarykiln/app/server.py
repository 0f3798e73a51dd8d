"""The Dash application and its web server.

:func:`create_app` builds the app (page, callbacks, the ``/files/<run>/<name>`` route that serves
a run's report and tables); :func:`serve` runs it with Werkzeug's threaded server until
interrupted; :class:`AppServer` runs it in a background thread (tests, notebooks) and stops it.
"""

from __future__ import annotations

import logging
import threading
from pathlib import Path

__all__ = ["AppServer", "create_app", "serve"]


def create_app(store=None):
    """The Dash app of ``rotarykiln app``; runs go to ``store`` (a
    :class:`~rotarykiln.app.running.RunStore`, a fresh temporary one by default)."""
    from dash import Dash
    from flask import abort, request, send_from_directory

    from rotarykiln.app.callbacks import register_callbacks
    from rotarykiln.app.layout import page
    from rotarykiln.app.loading import builtin_cases
    from rotarykiln.app.running import RunStore
    from rotarykiln.app.style import index_string

    store = store or RunStore()
    logging.getLogger("werkzeug").setLevel(logging.WARNING)  # no line per request
    app = Dash(
        __name__,
        title="rotarykiln",
        update_title=None,
        serve_locally=True,
        assets_folder=str(Path(store.root) / ".assets"),  # none: the style is inlined
    )
    app.index_string = index_string()
    app.layout = page(builtin_cases())
    register_callbacks(app, store)

    @app.server.route("/files/<run_id>/<name>")
    def run_file(run_id: str, name: str):
        folder = store.folder(run_id)
        if folder is None or "/" in name or name.startswith(".") or not (folder / name).is_file():
            abort(404)
        attach = bool(request.args.get("download"))
        return send_from_directory(folder, name, as_attachment=attach)

    app.run_store = store
    return app


class AppServer:
    """The app served by Werkzeug in a background thread: ``url``, then :meth:`stop`.

    ``port=0`` takes a free port.
    """

    def __init__(self, host: str = "127.0.0.1", port: int = 0, store=None):
        from werkzeug.serving import make_server

        self.app = create_app(store)
        self._server = make_server(host, port, self.app.server, threaded=True)
        self.port = self._server.server_port
        self.url = f"http://{host}:{self.port}/"
        self._thread = threading.Thread(target=self._server.serve_forever, daemon=True)

    def start(self) -> AppServer:
        self._thread.start()
        return self

    def stop(self) -> None:
        self._server.shutdown()
        self._server.server_close()
        self._thread.join(timeout=10)

    def __enter__(self) -> AppServer:
        return self.start()

    def __exit__(self, *exc) -> None:
        self.stop()


def _check_free(host: str, port: int) -> None:
    """Refuse, in one line, a port another program listens on (Werkzeug would exit)."""
    import socket

    from rotarykiln.errors import InputError

    try:
        family = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)[0][0]
    except OSError as exc:
        raise InputError(
            "--host", message=f"--host: cannot listen on {host} ({exc.strerror or exc})"
        ) from None
    try:
        with socket.socket(family, socket.SOCK_STREAM) as probe:
            probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            probe.bind((host, port))
    except OSError as exc:
        reason = exc.strerror or str(exc)
        raise InputError(
            "--port",
            message=f"--port: cannot listen on {host}:{port} ({reason}); "
            "choose another port, or --port 0 for a free one",
        ) from None


def serve(host: str = "127.0.0.1", port: int = 8050, open_browser: bool = False) -> None:
    """Serve the app until interrupted (Ctrl+C).

    Raises
    ------
    InputError
        The address cannot be listened on (a port in use, an unknown host).
    """
    from werkzeug.serving import make_server

    _check_free(host, port)
    app = create_app()
    server = make_server(host, port, app.server, threaded=True)
    url = f"http://{host}:{server.server_port}/"
    print(f"rotarykiln app: serving on {url} (Ctrl+C stops it)", flush=True)
    if open_browser:
        import webbrowser

        webbrowser.open(url)
    try:
        server.serve_forever()
    finally:
        server.server_close()
