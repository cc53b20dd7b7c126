"""`rdisc check FILE...`: diagnostics for people or, with --format json, for editors."""

from __future__ import annotations

import argparse
import json
import sys

from rdisc.cli.output import exit_code, show
from rdisc.compile import compile_path


def add_parser(verbs) -> None:
    p = verbs.add_parser("check", help="check descriptions and report every problem")
    p.add_argument("files", nargs="+", metavar="FILE", help=".rdis or thesis-style .json descriptions")
    p.add_argument("--format", choices=("text", "json"), default="text",
                   help="text for people (default), json for editors: LSP-shaped diagnostics")
    p.add_argument("-v", "--verbose", action="store_true", help="also print each connection's link budget")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    compilations = [compile_path(path) for path in args.files]
    if args.format == "json":
        from rdisc.diagnostics.lsp import to_lsp

        items = [d for c in compilations for d in to_lsp(c.diagnostics.sorted(), c.sources)]
        sys.stdout.write(json.dumps(items, indent=2, ensure_ascii=False) + "\n")
    else:
        show(compilations)
    if args.verbose:
        for c in compilations:
            for b in c.budgets:
                print("\n".join(b.lines()))
    return exit_code(compilations)
