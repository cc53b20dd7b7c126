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

from rdisc.cli.output import EXIT_ERRORS, exit_code, show, write
from rdisc.compile import compile_path


def add_parser(verbs) -> None:
    p = verbs.add_parser(
        "emit-python", help="write a standalone Python driver for a description",
        description="Compile a description into a Python driver module (standard library and pyserial only).",
    )
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("-o", "--output", metavar="OUT.py", help="where to write the driver (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    compilation = compile_path(args.file)
    show([compilation])
    if compilation.model is None or compilation.diagnostics.has_errors():
        return exit_code([compilation]) or EXIT_ERRORS
    from rdisc.emit.python import to_python

    text = to_python(compilation.model, os.path.basename(args.file), sources=compilation.sources)
    return write(text, args.output)
