"""``rotarykiln app``: serve the interactive page on this machine (Dash).

Pick a built-in case or upload a YAML case file, edit its main inputs with units ("1.5 rpm",
"62 kg/h"), run it, see the outlet temperature, profiles and summary, download the case, the
tables and the HTML report. Needs the app extra: pip install "rotarykiln[app]".
"""

from __future__ import annotations

import argparse

from rotarykiln.commands._args import plain
from rotarykiln.errors import InputError


def register(sub) -> None:
    p = sub.add_parser(
        "app",
        help="serve the interactive page (pick a case, edit inputs, run, download)",
        description=plain(__doc__) + " Example: rotarykiln app --port 8050 --open",
    )
    p.add_argument("--host", default="127.0.0.1", help="address to listen on (default: 127.0.0.1)")
    p.add_argument(
        "--port", type=int, default=8050, help="port (default: 8050; 0 takes a free one)"
    )
    p.add_argument("--open", action="store_true", help="open the page in the default browser")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if not 0 <= args.port <= 65535:
        raise InputError("--port", args.port, "in [0, 65535]")
    try:
        import dash  # noqa: F401
    except ImportError:
        raise InputError(
            "app",
            message='the app needs Dash: pip install "rotarykiln[app]" (or pip install dash)',
        ) from None
    from rotarykiln.app import serve

    try:
        serve(args.host, args.port, open_browser=args.open)
    except OSError as exc:
        raise InputError(
            "--port", message=f"--port: cannot listen on {args.host}:{args.port} ({exc.strerror})"
        ) from None
    return 0
