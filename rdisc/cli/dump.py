"""`rdisc dump FILE`: each primitive's wire layout, byte by byte, to check against
the device's manual (header, fields with their widths, length, checksum).
`rdisc dump FILE PRIMITIVE --args K=V ...`: the bytes of one request for those
arguments, made by the engine as a call makes them, held against that table."""

from __future__ import annotations

import argparse
import sys

from rdisc.cli.output import EXIT_USAGE, checked, compile_and_write, write


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("dump", help="print each primitive's wire layout (a byte table), or one request's bytes",
                         description="Print the bytes of each primitive's request and reply, frames included; "
                                     "with PRIMITIVE, the bytes of its request for the values given by --args.")
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("primitive", metavar="PRIMITIVE", nargs="?", help="one primitive whose request to make")
    p.add_argument("--args", metavar="K=V", nargs="+", action="extend", default=[],
                   help="the primitive's arguments by name, read as --call reads them (defaults for those left out)")
    p.add_argument("-o", "--output", metavar="OUT.txt", help="where to write it (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.dump import dump

    if args.primitive is None:
        if args.args:
            print("rdisc dump: --args needs a PRIMITIVE to make a request of", file=sys.stderr)
            return EXIT_USAGE
        return compile_and_write(args.file, args.output, lambda model, _: dump(model))
    return _request(args)


def _request(args: argparse.Namespace) -> int:
    """One request's bytes through the engine (`Robot.request`, no port opened): arguments read
    by `call_values`, as `--call` reads them; one that is refused is said in a line, exit 2."""
    from rdisc import engine
    from rdisc.emit.dump import dump_request
    from rdisc.runtime.device import Description

    compilation = checked(args.file)
    if isinstance(compilation, int):
        return compilation
    assert compilation.model is not None
    device = Description(compilation.model).device
    name = args.primitive
    if name not in device.primitives:
        known = ", ".join(device.primitives) or "none"
        print(f"rdisc dump: {device.name} has no primitive `{name}` (its primitives: {known})", file=sys.stderr)
        return EXIT_USAGE
    try:
        given = engine.named_pairs(args.args, "--args ", "KEY", "`{}`")
        values = engine.call_values(device, "primitive", name, given)
        data = engine.Robot(device).request(name, *values.values())
    except (engine.RdisError, TypeError, ValueError) as err:  # Unbound is a TypeError
        print(f"rdisc dump: {err}", file=sys.stderr)
        return EXIT_USAGE
    shown = ", ".join(f"{key}={engine.shown(value)}" for key, value in values.items())
    return write(dump_request(compilation.model, name, shown, data), args.output, list(compilation.sources))
