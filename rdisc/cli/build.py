"""`rdisc build FILE -o OUT.json`: the canonical, thesis-compatible JSON of a description."""

from __future__ import annotations

import argparse

from rdisc.cli.output import compile_and_write


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("build", help="write the canonical JSON of a description")
    p.add_argument("file", metavar="FILE", help="an .rdis (or .json) description")
    p.add_argument("-o", "--output", metavar="OUT", help="where to write the JSON (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.canonical import to_json

    return compile_and_write(args.file, args.output, lambda model, _: to_json(model))
