"""`rdisc decode FILE [CAPTURE]`: captured traffic (hex lines, a pyserial spy:// log, or an rdisc
recording, `.mcap`) told as the description's requests and replies, field by field.

Exit status: 0 decoded (unknown bytes are shown as such); 1 the description has errors; 2 the
capture cannot be read, said in a line."""

from __future__ import annotations

import argparse
import sys

from rdisc.cli.output import EXIT_USAGE, checked, write


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("decode", help="decode captured traffic into requests and replies with their fields",
                         description="Decode captured traffic into the description's requests and replies: hex "
                                     "lines (`> 89 00 c8 7f ff` host to device, `< 01` device to host), a pyserial "
                                     "spy:// hex dump, or an rdisc recording (.mcap).")
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("capture", metavar="CAPTURE", nargs="?", default="-",
                   help="the capture (default: hex lines or a spy log on stdin)")
    p.add_argument("-o", "--output", metavar="OUT.txt", help="where to write it (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.capture import CaptureError, read_recording, read_text
    from rdisc.emit.decode import decode

    compilation = checked(args.file)
    if isinstance(compilation, int):
        return compilation
    assert compilation.model is not None
    try:
        if args.capture == "-":
            messages = read_text(sys.stdin, "stdin")
        elif args.capture.endswith(".mcap"):
            messages = read_recording(args.capture)
        else:
            with open(args.capture, encoding="utf-8") as stream:
                messages = read_text(stream, args.capture)
    except CaptureError as err:
        print(f"rdisc decode: {err}", file=sys.stderr)
        return EXIT_USAGE
    except OSError as err:
        print(f"rdisc decode: {args.capture}: {err.strerror or err}", file=sys.stderr)
        return EXIT_USAGE
    except UnicodeDecodeError:
        print(f"rdisc decode: {args.capture}: not text (hex lines or a spy log); a recording ends in .mcap",
              file=sys.stderr)
        return EXIT_USAGE
    from rdisc.runtime.device import Description

    device = Description(compilation.model).device
    return write(decode(compilation.model, device, messages), args.output, list(compilation.sources))
