"""`rdisc fmt [--check] [--diff] FILE|DIR...`: descriptions rewritten in the canonical layout, every
comment kept (rdisc/format); `-` formats standard input to standard output. `--check` writes
nothing and fails (exit 1, with a diff) when a file would change: for CI and pre-commit hooks."""

from __future__ import annotations

import argparse
import os
import sys
from typing import TYPE_CHECKING

from rdisc.cli.output import EXIT_ERRORS, EXIT_OK, EXIT_USAGE

if TYPE_CHECKING:
    from rdisc.format import FormatError


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("fmt", help="rewrite descriptions in the canonical layout, comments kept",
                         description="Rewrite .rdis descriptions in place in the canonical layout, every comment "
                                     "and doc comment kept where it was written. A file that does not parse is "
                                     "left as it is, its syntax errors shown (exit 2).")
    p.add_argument("files", nargs="+", metavar="FILE",
                   help=".rdis descriptions; a directory: each .rdis file in it; -: standard input to standard output")
    p.add_argument("--check", action="store_true",
                   help="write nothing; exit 1 and show a diff when a file is not formatted")
    p.add_argument("--diff", action="store_true", help="write nothing; show what would change as a unified diff")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    paths: list[str] = []
    for given in args.files:
        if given == "-" or not os.path.isdir(given):
            paths.append(given)
            continue
        found = sorted(os.path.join(given, name) for name in os.listdir(given) if name.endswith(".rdis"))
        if not found:
            print(f"rdisc fmt: no .rdis description in {given}", file=sys.stderr)
            return EXIT_USAGE
        paths += found
    outcomes = [_one(path, dry=args.check or args.diff) for path in paths]
    changed, failed = outcomes.count(True), outcomes.count(None)
    if not args.check and not args.diff and "-" not in paths:
        files = "file" if changed == 1 else "files"
        left = f", {failed} not formatted" if failed else ""
        print(f"rdisc fmt: {changed} {files} reformatted, {outcomes.count(False)} unchanged{left}", file=sys.stderr)
    if failed:
        return EXIT_USAGE
    return EXIT_ERRORS if args.check and changed else EXIT_OK


def _one(path: str, dry: bool) -> bool | None:
    """Format one file (or stdin): whether it changed (or would); None when it cannot be read,
    does not parse, or cannot be written (said on stderr)."""
    from rdisc.compile import read_text
    from rdisc.diagnostics import Diagnostics
    from rdisc.format import FormatError, format_text

    name = "<stdin>" if path == "-" else path
    if path.endswith(".json"):
        print(f"rdisc fmt: {path} is JSON; only .rdis descriptions are formatted", file=sys.stderr)
        return None
    unread = Diagnostics()  # read as `rdisc check` reads it: not a FIFO or a device, UTF-8
    text = sys.stdin.read() if path == "-" else read_text(path, unread)
    if text is None:
        _show(FormatError(name, "", tuple(unread.items)), with_text=False)
        return None
    try:
        formatted = format_text(text, name)
    except FormatError as err:
        _show(err)
        return None
    if dry and formatted != text:
        import difflib

        sys.stdout.writelines(difflib.unified_diff(text.splitlines(keepends=True),
                                                   formatted.splitlines(keepends=True), name, name))
    if path == "-":
        if not dry:
            sys.stdout.write(formatted)
        return formatted != text
    if formatted == text:
        return False
    if not dry:
        try:
            with open(path, "w", encoding="utf-8", newline="\n") as f:
                f.write(formatted)
        except OSError as err:
            print(f"rdisc fmt: cannot write {path}: {err.strerror or err}", file=sys.stderr)
            return None
    return True


def _show(err: FormatError, with_text: bool = True) -> None:
    from rich.console import Console

    from rdisc.diagnostics.text import render
    from rdisc.source import Sources

    sources = Sources()
    if with_text:
        sources.add(err.name, err.text)
    Console(stderr=True, highlight=False).print(render(list(err.diagnostics), sources), soft_wrap=True)
