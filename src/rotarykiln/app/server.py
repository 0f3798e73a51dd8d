"""The Dash application and its web server.

:func:`create_app` builds the app (page, callbacks, the ``/files/<run>/<name>`` route that serves
a run's report and tables); :func:`serve` runs it with Werkzeug's threaded server until
interrupted; :class:`AppServer` runs it in a background thread (tests, notebooks) and stops it.

No client can tie the server up: a request body over
:data:`~rotarykiln.app.checks.MAX_REQUEST_BYTES` is refused (413) before it is read, at most
:data:`MAX_POSTS` posts are handled at once (one more waits up to :data:`POST_WAIT` s, then is
answered 503, busy), a request the app cannot read (nested too deeply, not what a callback takes)
is answered 400 in one line, and runs have their own bounds (:mod:`rotarykiln.app.running`).
"""

from __future__ import annotations

import logging
import threading
from pathlib import Path

__all__ = ["MAX_POSTS", "POST_WAIT", "AppServer", "create_app", "serve"]

MAX_POSTS = 8
"""Most posts (callbacks) the server handles at once; each holds at most its body and its
answer in memory."""
POST_WAIT = 5.0
"""Longest wait of a post for its turn before a busy answer (503), s."""

log = logging.getLogger(__name__)


class _Admission:
    """WSGI middleware: at most ``slots`` posts handled at once; one more waits at most ``wait``
    seconds, then gets 503 (busy)."""

    def __init__(self, app, slots: int = MAX_POSTS, wait: float = POST_WAIT):
        self.app = app
        self.wait = wait
        self._slots = threading.BoundedSemaphore(slots)

    def __call__(self, environ, start_response):
        if environ.get("REQUEST_METHOD") != "POST":
            return self.app(environ, start_response)
        if not self._slots.acquire(timeout=self.wait):
            body = b"the server is busy: try again in a minute\n"
            start_response(
                "503 Service Unavailable",
                [
                    ("Content-Type", "text/plain; charset=utf-8"),
                    ("Content-Length", str(len(body))),
                    ("Retry-After", "30"),
                    ("Connection", "close"),
                ],
            )
            return [body]
        try:
            return self.app(environ, start_response)
        finally:
            self._slots.release()


def create_app(store=None):
    """The Dash app of ``rotarykiln app``; runs go to ``store`` (a
    :class:`~rotarykiln.app.running.RunStore`, a fresh temporary one by default)."""
    from dash import Dash
    from flask import abort, request, send_from_directory
    from werkzeug.exceptions import HTTPException

    from rotarykiln.app.callbacks import register_callbacks
    from rotarykiln.app.checks import MAX_REQUEST_BYTES
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
    server = app.server
    server.config["MAX_CONTENT_LENGTH"] = MAX_REQUEST_BYTES  # 413 before the body is read
    server.wsgi_app = _Admission(server.wsgi_app)

    @server.errorhandler(413)
    def too_large(_):
        return f"the request is too large (at most {MAX_REQUEST_BYTES / 1e6:g} MB)\n", 413

    @server.errorhandler(Exception)
    def unreadable(error):
        """A request no callback can take (JSON nested too deeply, ids or values of the wrong
        shape): a one-line 400, a one-line note in the log, no traceback."""
        if isinstance(error, HTTPException):
            return error
        log.warning(
            "refused a request to %s: %s: %.200s", request.path, type(error).__name__, error
        )
        return f"bad request ({type(error).__name__})\n", 400

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
        self.store = self.app.run_store
        self._server = make_server(host, port, self.app.server, threaded=True)
        self.port = self._server.server_port
        self.url = f"http://{host}:{self.port}/"
        self._thread = threading.Thread(target=self._server.serve_forever, daemon=True)

    def start(self) -> AppServer:
        self.store.start()
        self._thread.start()
        return self

    def stop(self) -> None:
        self._server.shutdown()
        self._server.server_close()
        self._thread.join(timeout=10)
        self.store.close()

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
    app.run_store.start()  # the worker imports the models while the page loads
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
        app.run_store.close()
