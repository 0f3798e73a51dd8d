"""The ``rotarykiln`` command.

Subcommands live in :mod:`rotarykiln.commands`, one module each; a module defines
``register(subparsers)`` (adding its parser and ``set_defaults(func=run)``) and ``run(args) -> int``,
and :data:`COMMANDS` names it with its one-line help. Only the module of the command being run is
imported (``rotarykiln --version`` and ``rotarykiln --help`` import none), so the command line
starts in a fraction of a second whatever the models import.

User mistakes (:class:`~rotarykiln.errors.InputError`) print one line and exit with code 2, without a
traceback; a failed solve (:class:`~rotarykiln.errors.ConvergenceError`) prints its diagnostics and
exits with code 1. Warnings print as one ``warning:`` line each.
"""

from __future__ import annotations

from rotarykiln.commands._signals import (
    end_program,
    handled,
    install_early,
    interruption,
    lost_interruption,
    signal_exit,
)

install_early()  # the program: SIGINT/SIGTERM print one line from here on, not a traceback

import argparse  # noqa: E402
import importlib  # noqa: E402
import os  # noqa: E402
import sys  # noqa: E402
import warnings  # noqa: E402

__all__ = ["COMMANDS", "build_parser", "main"]

COMMANDS: dict[str, str] = {
    "app": "serve the interactive page (pick a case, edit inputs, run, download)",
    "bed": "axial bed-depth profile, hold-up and residence time (Kramers or Scott)",
    "calibrate": "fit case fields to measured temperatures or outlet values (weighted least squares)",
    "demo": "run the built-in demonstration case",
    "geometry": "cross-section geometry from fill, depth, half-angle or chord",
    "regime": "Froude number, critical speed and bed regime",
    "rtd": "residence time distribution: fit tracer data, predict a kiln",
    "run": "validate a case file and run it",
    "schema": "print the JSON Schema of a case file",
    "sensitivity": "Sobol or Morris sensitivity indices of a model output over case-field "
    "distributions",
    "sweep": "run a model over ranges of case fields in parallel; one table and plots",
    "transient": "run a kiln in time: start-up, upsets, control steps",
    "transverse": "transverse mixing, segregation and solid-to-solid heating (retort zone)",
}
"""Subcommand -> its one-line help; the module ``rotarykiln.commands.<name>`` registers it (its
parser's help is the same line: tests/test_cli.py checks it)."""

_GLOBAL_OPTIONS = {"-v", "--verbose", "-vv", "-vvv", "--version", "-h", "--help"}


class _Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line and exits 2."""

    def error(self, message: str):  # noqa: D401 - argparse API
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


class _Version(argparse.Action):
    """``--version``: the installed version, read from the package metadata only when asked."""

    def __call__(self, parser, namespace, values, option_string=None):
        from rotarykiln import __version__

        print(f"rotarykiln {__version__}")  # on stdout, as argparse's own version action
        parser.exit(0)


def command_of(argv: list[str] | None) -> str | None:
    """The subcommand named in ``argv`` (the first word after the global options), else None."""
    for word in sys.argv[1:] if argv is None else argv:
        if word in _GLOBAL_OPTIONS or (word.startswith("-v") and set(word[1:]) == {"v"}):
            continue
        return word if word in COMMANDS else None
    return None


def build_parser(command: str | None = "*") -> argparse.ArgumentParser:
    """The ``rotarykiln`` parser with the subcommand ``command`` registered in full ("*": all of
    them; None: none, each listed by its help line only, which imports no command module)."""
    parser = _Parser(
        prog="rotarykiln",
        description="Simulate rotary kilns and rotating drums. Quantities take units: "
        '"--diameter 0.4 m --speed 1.5 rpm --slope 2 deg --feed 62 kg/h".',
    )
    parser.add_argument("--version", action=_Version, nargs=0, help="print the version and exit")
    parser.add_argument(
        "-v",
        "--verbose",
        action="count",
        default=0,
        help="log what long runs do on stderr (-v: steps, -vv: details); before the command",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name, help_line in COMMANDS.items():
        if command in ("*", name):
            importlib.import_module(f"rotarykiln.commands.{name}").register(sub)
        else:
            sub.add_parser(name, help=help_line)
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
            code = _main(argv)
            lost = lost_interruption(received)  # raised in a finaliser, where it was swallowed
            if lost is not None:
                code, text = signal_exit(lost)
                print(f"rotarykiln: {text}", file=sys.stderr)
        except BaseException as exc:
            stop = interruption(received, exc)
            if stop is None:
                raise
            code, text = signal_exit(stop)
            print(f"rotarykiln: {text}", file=sys.stderr)
    if argv is None:  # the program: exit handlers, flushed output, no slow interpreter teardown
        end_program(code)  # a signal up to here is answered by its line and 130 / 143
    return code


def _main(argv: list[str] | None) -> int:
    parser = build_parser(command_of(argv))
    args = parser.parse_args(argv)  # --version and --help exit here, before any numerical import
    from rotarykiln.errors import ConvergenceError, InputError

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
    except MemoryError:  # a run larger than this machine: one line, not a traceback
        print(
            f"rotarykiln {args.command}: out of memory (try fewer cells, cases or rows)",
            file=sys.stderr,
        )
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
