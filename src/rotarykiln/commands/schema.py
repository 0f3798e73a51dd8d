"""``rotarykiln schema``: the JSON Schema of a case file, for editors and validators.

Quantity fields accept a number (SI) or a string with a unit (``"1.5 rpm"``); unknown keys are
refused. The same schema ships with the package as ``rotarykiln/case.schema.json``. In an editor
with the YAML language server, a case file's first line
``# yaml-language-server: $schema=case.schema.json`` switches the checks on.
"""

from __future__ import annotations

import argparse

from rotarykiln.case import case_json_schema
from rotarykiln.commands._args import plain, print_json
from rotarykiln.outputs import write_json_atomic


def register(sub) -> None:
    p = sub.add_parser(
        "schema",
        help="print the JSON Schema of a case file",
        description=plain(__doc__) + " Example: rotarykiln schema --out case.schema.json",
    )
    p.add_argument("--out", metavar="FILE", help="write the schema to FILE instead of printing it")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    schema = case_json_schema()
    if args.out:
        path = write_json_atomic(args.out, schema)
        print(f"schema written to {path}")
    else:
        print_json(schema)
    return 0
