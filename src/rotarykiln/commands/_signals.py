"""SIGINT and SIGTERM in the ``rotarykiln`` command: one line, never a traceback.

Inside :func:`handled`, SIGINT raises :class:`KeyboardInterrupt` and SIGTERM raises
:class:`Terminated` (a KeyboardInterrupt) in the main thread, so that ``finally`` blocks run (a
run's staging folder is removed, :func:`rotarykiln.outputs.output_set`) and the command prints
one line and exits with 128 + the signal number. Once one signal has been raised, further ones are
ignored while the command unwinds. Deliberately light: no import of numpy or the models, so the
handlers are in place a few milliseconds after Python starts.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading

__all__ = [
    "Terminated",
    "end_program",
    "handled",
    "install_early",
    "interruption",
    "lost_interruption",
    "signal_exit",
]


class Terminated(KeyboardInterrupt):
    """SIGTERM received (raised like Ctrl-C's KeyboardInterrupt, so it unwinds the same way)."""

    signum = signal.SIGTERM


def interruption(received: list, exc: BaseException) -> KeyboardInterrupt | None:
    """The interruption behind ``exc`` when a signal has been ``received``, else None.

    The KeyboardInterrupt of a signal can surface as another error: raised inside a C
    extension's initialisation (matplotlib's ft2font while it is imported) it becomes
    "ImportError: initialization failed". Once a signal has come, such an error is the
    interruption, not a bug.
    """
    if not received or isinstance(exc, KeyboardInterrupt):
        return exc if isinstance(exc, KeyboardInterrupt) else None
    return Terminated() if received[0] == signal.SIGTERM else KeyboardInterrupt()


def signal_exit(exc: KeyboardInterrupt) -> tuple[int, str]:
    """The exit code and the one-line message of an interrupted command."""
    if isinstance(exc, Terminated):
        return 128 + signal.SIGTERM, "terminated"
    return 128 + signal.SIGINT, "interrupted"


def _is_program() -> bool:
    """Whether this process is the ``rotarykiln`` program (console script or ``python -m``)."""
    spec = getattr(sys.modules.get("__main__"), "__spec__", None)
    if spec is not None and spec.name == "rotarykiln.__main__":
        return True
    return bool(sys.argv) and os.path.basename(sys.argv[0]) == "rotarykiln"


def _exit_now(signum, frame):  # before main(): nothing written yet, nothing to clean
    text = "terminated" if signum == signal.SIGTERM else "interrupted"
    try:
        sys.stderr.write(f"rotarykiln: {text}\n")
        sys.stderr.flush()
    finally:
        os._exit(128 + signum)


def _late(signum, frame):
    """A signal after the command's body, while the program ends: what is written stays
    written (stdout flushed), one line, exit 128 + the signal number."""
    try:
        sys.stdout.flush()
    except BaseException:  # noqa: BLE001 - closed, or interrupted in the middle of a flush
        pass
    text = "terminated" if signum == signal.SIGTERM else "interrupted"
    try:
        os.write(2, f"rotarykiln: {text}\n".encode())
    finally:
        os._exit(128 + signum)


def end_program(code: int) -> None:
    """End the program now with ``code``, after its exit handlers and with its output flushed,
    skipping the interpreter's teardown (tenths of a second with the scientific stack loaded).

    Call it last, after :func:`handled` (``at_exit_ignore=True``) has returned: a SIGINT or
    SIGTERM up to the very end is then answered by one line and 128 + the signal number. In
    the teardown Python disarms its handlers, and a signal there ends the process by the signal
    itself (a shell shows the same 130 / 143, but without the line).
    """
    import atexit

    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed pipe or stream: nothing more to write
            pass
    os._exit(code)


def install_early() -> None:
    """In the ``rotarykiln`` program only (not when imported by a test or the app): from the
    first lines of :mod:`rotarykiln.cli` until :func:`handled` takes over, SIGINT and SIGTERM
    print one line and exit at once (no module is half imported into a traceback)."""
    if _is_program() and threading.current_thread() is threading.main_thread():
        for s in (signal.SIGINT, signal.SIGTERM):
            signal.signal(s, _exit_now)


@contextlib.contextmanager
def handled(*, at_exit_ignore: bool):
    """SIGINT -> KeyboardInterrupt, SIGTERM -> :class:`Terminated` inside the block.

    Yields the list of the signals received (empty until one comes): an error raised after a
    signal is the interruption surfacing in another form (see :func:`interruption`).

    ``at_exit_ignore``: on leaving, the program is about to end: a signal from then on (while
    the program returns, runs its exit handlers, flushes its output) prints the same one line
    and ends the program with 128 + the signal number at once (:func:`_late`: no traceback
    of the interpreter's shutdown, and never exit 0 for a run that was signalled before it
    ended). Otherwise the previous handlers are restored (an in-process caller, e.g. a test,
    gets its own handlers back).

    A signal whose handler runs inside a finaliser (a ``__del__`` or a weakref callback, called
    by the garbage collector anywhere) raises where Python cannot propagate it: the exception is
    "ignored". It is not printed (no traceback); the signal stays in the yielded list, and the
    caller ends the command as interrupted all the same (:func:`lost_interruption`).
    """
    if threading.current_thread() is not threading.main_thread():
        yield []
        return
    sigs = (signal.SIGINT, signal.SIGTERM)
    previous = {s: signal.getsignal(s) for s in sigs}
    raised = []

    def on_signal(signum, frame):
        if raised:  # already unwinding: one line, one exit
            return
        raised.append(signum)
        raise Terminated() if signum == signal.SIGTERM else KeyboardInterrupt()

    previous_hook = sys.unraisablehook

    def unraisable(info):
        if raised and isinstance(info.exc_value, KeyboardInterrupt):
            return  # our own interruption, lost in a finaliser: the caller reports it
        previous_hook(info)

    try:
        sys.unraisablehook = unraisable
        for s in sigs:
            signal.signal(s, on_signal)
        yield raised
    finally:
        for s in sigs:
            signal.signal(s, _late if at_exit_ignore else previous[s])
        sys.unraisablehook = previous_hook


def lost_interruption(received: list) -> KeyboardInterrupt | None:
    """The interruption of a signal received but never raised where the command could see it
    (lost in a finaliser, see :func:`handled`), else None."""
    if not received:
        return None
    return Terminated() if received[0] == signal.SIGTERM else KeyboardInterrupt()
