"""`rdisc graph FILE [-o model.svg|model.dot]`: the description as a graph of what refers to
what (thesis ch. 5), laid out by Graphviz."""

from __future__ import annotations

import argparse
import os
import sys
from typing import TYPE_CHECKING

from rdisc.cli.output import EXIT_USAGE, compile_and_write

if TYPE_CHECKING:
    from rdisc.semantics.model import Model
    from rdisc.source import Sources


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("graph", help="draw the description as a graph (SVG by Graphviz, or DOT)",
                         description="Draw connections, frames, primitives, interfaces, inputs, outputs, adapters, "
                                     "state and settings, with an edge for each reference. -o FILE.svg lays it out "
                                     "with Graphviz's dot; -o FILE.dot (or no -o) writes the DOT text.")
    p.add_argument("file", metavar="FILE", help="an .rdis (or .json) description")
    p.add_argument("-o", "--output", metavar="OUT.svg|OUT.dot", help="where to write it (default: DOT on stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.graph import GraphvizMissing, dot, svg
    from rdisc.source import place

    as_svg = args.output is not None and args.output.lower().endswith(".svg")

    def render(model: Model, sources: Sources) -> str:
        main = model.robot.span.path if model.robot.span else None
        text = dot(model, lambda span: place(span, sources, main, os.path.basename(args.file)))
        return svg(text) if as_svg else text

    try:
        return compile_and_write(args.file, args.output, render)
    except GraphvizMissing as err:
        print(f"rdisc graph: {err}", file=sys.stderr)
        return EXIT_USAGE
