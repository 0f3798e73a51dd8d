"""The process that runs the app's cases, one at a time, so that a run has bounds the server keeps.

The web server does not run a case itself: it sends the case to a :class:`Worker` (a new Python
process, ``python -m rotarykiln.app.worker``: nothing of the server's threads is copied into it)
over a socket pair and waits for its answer, at most a given time. A run over its time or memory
bound is stopped by killing the process (a solver cannot be interrupted from another thread),
which frees all its memory; the next run starts a new one. The app has two workers, one per lane
of runs (:class:`~rotarykiln.app.running.RunStore`); each is named on its command line
(``heavy``, ``light``). The worker ends when the server's process ends, even killed: it checks
its parent twice a second, and a closed pipe ends it too.
"""

from __future__ import annotations

import contextlib
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import warnings
from multiprocessing.connection import Connection
from pathlib import Path

from rotarykiln.errors import ConvergenceError, InputError

__all__ = ["RunStopped", "Worker", "process_rss"]

START_SECONDS = 120.0
"""Longest start of a worker (its imports: about 2 s), s."""
_POLL = 0.05  # s between checks of a running worker


class RunStopped(RuntimeError):
    """A run the app did not finish: over its time or memory bound, or its process ended."""


def process_rss(pid: int) -> int | None:
    """Resident memory of a process, bytes (Linux ``/proc``), else None."""
    try:
        with open(f"/proc/{pid}/statm", encoding="ascii") as fh:
            pages = int(fh.read().split()[1])
    except (OSError, ValueError, IndexError):
        return None
    return pages * os.sysconf("SC_PAGE_SIZE")


class Worker:
    """One process that runs cases as ``rotarykiln run --report`` does, one at a time (and
    the transverse section of a case as ``rotarykiln transverse`` does, within its bound).

    ``name`` is shown on the process's command line (``python -m rotarykiln.app.worker FD PID
    NAME``), so that ``ps`` tells the workers apart."""

    def __init__(self, name: str = "worker"):
        self.name = name
        ours, theirs = socket.socketpair()
        try:
            self.process = subprocess.Popen(
                [
                    sys.executable,
                    "-m",
                    "rotarykiln.app.worker",
                    str(theirs.fileno()),
                    str(os.getpid()),
                    name,
                ],
                pass_fds=(theirs.fileno(),),
                stdin=subprocess.DEVNULL,
                env={**os.environ, "MPLBACKEND": "Agg"},
            )
        except BaseException:
            ours.close()
            raise
        finally:
            theirs.close()
        self._conn = Connection(ours.detach())
        self._ready = False

    @property
    def pid(self) -> int:
        return self.process.pid

    def alive(self) -> bool:
        return self.process.poll() is None

    def run(self, raw: dict, out: Path, source: str, seconds: float, max_bytes: int) -> dict:
        """Run a raw case into the folder ``out``; what the page shows beside the files:
        ``warnings`` (their texts, as the models give them) and ``models`` (the results of its
        transport, RTD and transverse models: :func:`rotarykiln.app.results.model_results`).

        Raises
        ------
        InputError, ConvergenceError
            As the run raised them (the worker goes on).
        RunStopped
            The run went over ``seconds`` or ``max_bytes`` of resident memory (the worker is
            killed), or the worker ended.
        """
        if not self._ready:
            self._answer(START_SECONDS, None, "start")
            self._ready = True
        self._conn.send((raw, str(out), source))
        kind, *rest = self._answer(seconds, max_bytes, "run")
        if kind == "ok":
            return rest[0]
        if kind == "input":
            message, field = rest
            raise InputError(field, message=message)
        if kind == "convergence":
            raise ConvergenceError(rest[0])
        if kind == "memory":
            raise MemoryError(rest[0])
        raise RuntimeError(f"{rest[0]}: {rest[1]}")

    def _answer(self, seconds: float, max_bytes: int | None, what: str) -> tuple:
        deadline = time.monotonic() + seconds
        while not self._conn.poll(_POLL):
            if not self.alive():
                code = self.process.returncode
                self.stop()
                raise RunStopped(f"the run's process ended (exit code {code}) before its {what}")
            if time.monotonic() > deadline:
                self.stop()
                raise RunStopped(
                    f"the {what} took longer than {seconds:g} s, the app's limit: it was stopped"
                )
            rss = process_rss(self.process.pid) if max_bytes else None
            if rss is not None and rss > max_bytes:
                self.stop()
                raise RunStopped(
                    f"the {what} used more than {max_bytes / 1e9:g} GB of memory, the app's "
                    "limit: it was stopped"
                )
        try:
            return self._conn.recv()
        except (EOFError, OSError):
            self.stop()
            raise RunStopped(f"the run's process ended before its {what}") from None

    def stop(self) -> None:
        """End the process (killed: it may be in the middle of a run)."""
        if self.alive():
            self.process.kill()
        with contextlib.suppress(subprocess.TimeoutExpired):
            self.process.wait(timeout=10)
        with contextlib.suppress(OSError):
            self._conn.close()


def _watch(parent: int) -> None:
    while True:
        time.sleep(0.5)
        if os.getppid() != parent:  # the server ended (killed or not): so does its worker
            os._exit(3)


def _main(conn: Connection, parent: int) -> None:
    """The worker's loop: answer each (raw case, folder, source) with the run's outcome."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl+C stops the server, which stops us
    threading.Thread(target=_watch, args=(parent,), daemon=True).start()
    import matplotlib

    matplotlib.use("Agg")
    import rotarykiln.commands.run  # noqa: F401  (imported once, before the first run)

    conn.send(("ready",))
    while True:
        try:
            job = conn.recv()
        except (EOFError, OSError, KeyboardInterrupt):
            return
        conn.send(_run(*job))


def _run(raw: dict, out: str, source: str) -> tuple:
    from rotarykiln.app.checks import parse_app_case

    try:
        caught = _run_case(parse_app_case(raw, source), Path(out), source)
    except InputError as exc:
        return ("input", str(exc), str(exc.field))
    except ConvergenceError as exc:
        return ("convergence", str(exc))
    except MemoryError as exc:
        return ("memory", f"out of memory ({exc})"[:500])
    except Exception as exc:  # a bug: reported, and the worker goes on
        return ("error", type(exc).__name__, str(exc)[:500])
    return ("ok", caught)


MAX_WARNINGS = 20
"""Most warnings of a run sent to the page (each at most 2,000 characters)."""


def _run_case(case, out: Path, source: str) -> dict:
    """``run_case(..., report=True)``, then the results of the case's other models for the
    page (:func:`rotarykiln.app.results.model_results`), with the warnings of both collected
    (not printed): ``{"warnings": [texts], "models": {...}}``."""
    from rotarykiln.app.results import model_results
    from rotarykiln.commands.run import run_case

    shown: list[str] = []

    def keep(message) -> None:
        text = str(message)[:2000]
        if text not in shown and len(shown) < MAX_WARNINGS:
            shown.append(text)

    def collect(message, category, filename, lineno, file=None, line=None):
        keep(message)

    previous = warnings.showwarning
    warnings.showwarning = collect
    try:
        run_case(case, out, report=True, source=source)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("default")  # once per place and text, in every run
            models = model_results(case, out, source)
        for w in caught:
            keep(w.message)
    finally:
        warnings.showwarning = previous
    return {"warnings": shown, "models": models}


if __name__ == "__main__":  # python -m rotarykiln.app.worker FD PARENT_PID [NAME] (by Worker)
    _main(Connection(int(sys.argv[1])), int(sys.argv[2]))
