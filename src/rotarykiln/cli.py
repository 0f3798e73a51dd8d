"""The ``rotarykiln`` command.

Subcommands live in :mod:`rotarykiln.commands`, one module each; a module defines
``register(subparsers)`` (adding its parser and ``set_defaults(func=run)``) and ``run(args) -> int``.
The CLI discovers them, so a new physics package adds its command without touching this file.

User mistakes (:class:`~rotarykiln.errors.InputError`) print one line and exit with code 2, without a
traceback; a failed solve (:class:`~rotarykiln.errors.ConvergenceError`) prints its diagnostics and
exits with code 1. Warnings print as one ``warning:`` line each.
"""

from __future__ import annotations

from rotarykiln.commands._signals import handled, install_early, interruption, signal_exit

install_early()  # the program: SIGINT/SIGTERM print one line from here on, not a traceback

import argparse  # noqa: E402
import importlib  # noqa: E402
import os  # noqa: E402
import pkgutil  # noqa: E402
import sys  # noqa: E402
import warnings  # noqa: E402

__all__ = ["build_parser", "main"]


class _Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line and exits 2."""

    def error(self, message: str):  # noqa: D401 - argparse API
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    from rotarykiln import __version__, commands

    parser = _Parser(
        prog="rotarykiln",
        description="Simulate rotary kilns and rotating drums. Quantities take units: "
        '"--diameter 0.4 m --speed 1.5 rpm --slope 2 deg --feed 62 kg/h".',
    )
    parser.add_argument("--version", action="version", version=f"rotarykiln {__version__}")
    parser.add_argument(
        "-v",
        "--verbose",
        action="count",
        default=0,
        help="log what long runs do on stderr (-v: steps, -vv: details); before the command",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for info in sorted(pkgutil.iter_modules(commands.__path__), key=lambda m: m.name):
        if info.name.startswith("_"):
            continue
        module = importlib.import_module(f"{commands.__name__}.{info.name}")
        module.register(sub)
    return parser


_shown: set[str] = set()


def _show_warning(message, category, filename, lineno, file=None, line=None):
    text = f"warning: {message}"
    if text not in _shown:  # a model called twice with the same values warns once
        _shown.add(text)
        print(text, file=sys.stderr)


def main(argv: list[str] | None = None) -> int:
    """Run the command line ``argv`` (default: ``sys.argv[1:]``); the exit code.

    SIGINT and SIGTERM print one line (``rotarykiln: interrupted`` / ``terminated``) and give
    130 / 143, never a traceback (:mod:`rotarykiln.commands._signals`).
    """
    # called as the program (argv from sys.argv): a signal after the end is ignored, not a
    # traceback of the interpreter's shutdown; called in-process, the caller's handlers return
    with handled(at_exit_ignore=argv is None) as received:
        try:
            return _main(argv)
        except BaseException as exc:
            stop = interruption(received, exc)
            if stop is None:
                raise
            code, text = signal_exit(stop)
            print(f"rotarykiln: {text}", file=sys.stderr)
            return code


def _main(argv: list[str] | None) -> int:
    from rotarykiln.errors import ConvergenceError, InputError

    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    previous = warnings.showwarning
    warnings.showwarning = _show_warning
    _shown.clear()
    handler = _log_to_stderr(getattr(args, "verbose", 0))
    try:
        return int(args.func(args) or 0)
    except InputError as exc:
        print(f"rotarykiln {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except ConvergenceError as exc:
        print(f"rotarykiln {args.command}: solver failed: {exc}", file=sys.stderr)
        return 1
    except BrokenPipeError:  # output piped into a reader that closed early (e.g. `| head`)
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141
    finally:
        warnings.showwarning = previous
        if handler is not None:
            import logging

            logger = logging.getLogger("rotarykiln")
            logger.removeHandler(handler)
            logger.setLevel(handler.previous_level)


def _log_to_stderr(verbosity: int):
    """``-v``: the package's INFO records on stderr, ``-vv``: DEBUG too; the handler or None.

    The library configures no handler (each module has ``logging.getLogger(__name__)``); only
    the command line does, for the ``rotarykiln`` loggers and for the time of one command.
    """
    if not verbosity:
        return None
    import logging

    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(logging.Formatter("%(levelname)s %(name)s: %(message)s"))
    logger = logging.getLogger("rotarykiln")
    handler.previous_level = logger.level
    logger.addHandler(handler)
    logger.setLevel(logging.INFO if verbosity == 1 else logging.DEBUG)
    return handler


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
