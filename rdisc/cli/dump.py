"""`rdisc dump FILE`: each primitive's wire layout, byte by byte, to check against
the device's manual (header, fields with their widths, length, checksum)."""

from __future__ import annotations

import argparse

from rdisc.cli.output import EXIT_ERRORS, exit_code, show, write
from rdisc.compile import compile_path


def add_parser(verbs) -> None:
    p = verbs.add_parser("dump", help="print each primitive's wire layout (a byte table)",
                         description="Print the bytes of each primitive's request and reply, frames included.")
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("-o", "--output", metavar="OUT.txt", help="where to write it (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    compilation = compile_path(args.file)
    show([compilation])
    if compilation.model is None or compilation.diagnostics.has_errors():
        return exit_code([compilation]) or EXIT_ERRORS
    from rdisc.emit.dump import dump

    return write(dump(compilation.model), args.output)
