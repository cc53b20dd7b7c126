"""`rdisc build FILE -o OUT.json`: the canonical, thesis-compatible JSON of a description."""

from __future__ import annotations

import argparse

from rdisc.cli.output import EXIT_ERRORS, exit_code, show, write
from rdisc.compile import compile_path


def add_parser(verbs) -> None:
    p = verbs.add_parser("build", help="write the canonical JSON of a description")
    p.add_argument("file", metavar="FILE", help="an .rdis (or .json) description")
    p.add_argument("-o", "--output", metavar="OUT", help="where to write the JSON (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    compilation = compile_path(args.file)
    show([compilation])
    if compilation.model is None:
        return exit_code([compilation]) or EXIT_ERRORS
    from rdisc.emit.canonical import to_json

    return write(to_json(compilation.model), args.output)
