"""`rdisc check FILE|DIR...`: diagnostics for people or, with --format json, for editors; a
directory stands for the descriptions in it (.rdis and .json, in sorted order)."""

from __future__ import annotations

import argparse
import os
import sys

from rdisc.cli.output import EXIT_USAGE, exit_code, show
from rdisc.compile import compile_path


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("check", help="check descriptions and report every problem")
    p.add_argument("files", nargs="+", metavar="FILE",
                   help=".rdis or thesis-style .json descriptions; a directory: each .rdis and .json file in it")
    p.add_argument("--format", choices=("text", "json"), default="text",
                   help="text for people (default), json for editors: LSP-shaped diagnostics")
    p.add_argument("-v", "--verbose", action="store_true",
                   help="also print each connection's link budget, after its file's name")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    paths: list[str] = []
    for given in args.files:
        if not os.path.isdir(given):
            paths.append(given)
            continue
        found = sorted(os.path.join(given, name) for name in os.listdir(given)
                       if name.endswith((".rdis", ".json")) and os.path.isfile(os.path.join(given, name)))
        if not found:
            print(f"rdisc check: no .rdis or .json description in {given}", file=sys.stderr)
            return EXIT_USAGE
        paths += found
    compilations = [compile_path(path) for path in paths]
    if args.format == "json":
        import json

        from rdisc.diagnostics.lsp import to_lsp

        items = [d for c in compilations for d in to_lsp(c.diagnostics.sorted(), c.sources)]
        sys.stdout.write(json.dumps(items, indent=2, ensure_ascii=False) + "\n")
    else:
        show(compilations)
    if args.verbose:
        for path, c in zip(paths, compilations):
            for b in c.budgets:
                first, *rest = b.lines()
                print("\n".join([f"{path}: {first}", *rest]))
    return exit_code(compilations)
