"""`rdisc emit-python FILE -o OUT.py`: a standalone Python driver for a description.

The driver is one module that needs only the standard library and pyserial: a
class named after the robot with a method per domain input, `connect()`, and a
command line with the options of `rdisc run`. It is written only when the
description checks without errors; the same description always gives the same
bytes.
"""

from __future__ import annotations

import argparse
import os

from rdisc.cli.output import compile_and_write


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser(
        "emit-python", help="write a standalone Python driver for a description",
        description="Compile a description into a Python driver module (standard library and pyserial only).",
    )
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("-o", "--output", metavar="OUT.py", help="where to write the driver (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.python import to_python

    name = os.path.basename(args.file)
    return compile_and_write(args.file, args.output,
                             lambda model, sources: to_python(model, name, sources=sources))
