"""`rdisc dump FILE`: each primitive's wire layout, byte by byte, to check against
the device's manual (header, fields with their widths, length, checksum)."""

from __future__ import annotations

import argparse

from rdisc.cli.output import compile_and_write


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("dump", help="print each primitive's wire layout (a byte table)",
                         description="Print the bytes of each primitive's request and reply, frames included.")
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("-o", "--output", metavar="OUT.txt", help="where to write it (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.dump import dump

    return compile_and_write(args.file, args.output, lambda model, _: dump(model))
