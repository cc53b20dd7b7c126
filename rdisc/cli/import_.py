"""`rdisc import FILE.json -o OUT.rdis`: thesis-style JSON back to readable source.

The JSON is checked with the same checker as source (its expressions are parsed,
never evaluated). The source is written whenever the JSON could be read, errors
or not, since fixing a legacy description is easier in .rdis; the exit status
still says whether it checks.
"""

from __future__ import annotations

import argparse

from rdisc.cli.output import EXIT_ERRORS, exit_code, show, write
from rdisc.compile import Compilation, compile_module, read_text
from rdisc.diagnostics import Diagnostics
from rdisc.source import Sources


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("import", help="turn a thesis-style JSON description into .rdis source")
    p.add_argument("file", metavar="FILE", help="a JSON description (Appendix B shape)")
    p.add_argument("-o", "--output", metavar="OUT", help="where to write the .rdis source (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.json_import.document import read
    from rdisc.syntax.printer import print_module

    diagnostics = Diagnostics()
    sources = Sources()
    text = read_text(args.file, diagnostics)
    module = None
    if text is not None:
        sources.add(args.file, text)
        module = read(args.file, text, diagnostics)
    if module is None:
        compilation = Compilation(None, diagnostics, sources)
    else:
        compilation = compile_module(module, diagnostics, sources)
    show([compilation])
    if module is None:
        return exit_code([compilation]) or EXIT_ERRORS
    return write(print_module(module), args.output, list(sources)) or exit_code([compilation])
