"""`rdisc VERB ...`: one module per verb, each with add_parser() and run(args) -> exit code."""

from __future__ import annotations

import argparse
import sys

from rdisc import __version__
from rdisc.cli import (
    build,
    check,
    console,
    dump,
    emit_mjcf,
    emit_python,
    emit_ros,
    emit_sdf,
    emit_urdf,
    explain,
    graph,
    import_,
    replay,
    run,
    sim,
)

VERBS = (check, build, import_, explain, run, sim, replay, console, emit_python, emit_ros, emit_urdf, emit_sdf,
         emit_mjcf, dump, graph)
EXIT_INTERNAL = 3


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="rdisc",
        description="The RDIS toolchain: check robot device descriptions and turn them into what frameworks use.",
    )
    p.add_argument("--version", action="version", version=f"rdisc {__version__}")
    p.add_argument("--debug", action="store_true", help="show the Python traceback of an internal error")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    for verb in VERBS:
        verb.add_parser(verbs)
    return p


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    try:
        return args.run(args)
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0
    except Exception:
        if args.debug:
            raise
        exc = sys.exc_info()[1]
        print(f"rdisc: internal error: {type(exc).__name__}: {exc}", file=sys.stderr)
        print("This is a bug in rdisc, not in your description; rerun with --debug to see where.", file=sys.stderr)
        return EXIT_INTERNAL
