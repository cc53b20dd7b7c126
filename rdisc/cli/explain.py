"""`rdisc explain CODE`: the longer explanation of a diagnostic code."""

from __future__ import annotations

import argparse
import sys

from rdisc.cli.output import EXIT_OK, EXIT_USAGE
from rdisc.diagnostics.codes import CODES, lookup


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("explain", help="explain a diagnostic code (E102, unknown-element); all codes without one")
    p.add_argument("code", nargs="?", metavar="CODE")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    if args.code is None:
        for known in CODES.values():
            print(f"{known.id}  {known.name}")
        return EXIT_OK
    code = lookup(args.code)
    if code is None:
        print(f"rdisc: no diagnostic code `{args.code}`; `rdisc explain` lists them", file=sys.stderr)
        return EXIT_USAGE
    print(f"{code.id} ({code.name})\n\n{code.explanation}")
    return EXIT_OK
