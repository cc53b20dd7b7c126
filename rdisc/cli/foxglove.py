"""`--foxglove [HOST:PORT]` of `rdisc run` and `rdisc console`: the live session served to
Foxglove (rdisc.runtime.foxglove), on this machine's loopback unless `--allow-remote`."""

from __future__ import annotations

import argparse
import sys

from rdisc import engine
from rdisc.cli.address import is_loopback, parse_address, shown
from rdisc.cli.output import EXIT_USAGE
from rdisc.runtime.foxglove import FoxgloveServer

DEFAULT_FOXGLOVE = "127.0.0.1:8766"  # the console's page is on 8765 by default
NEEDS = "foxglove-sdk and mcap-ros2-support packages (pip install foxglove-sdk mcap-ros2-support)"


def add_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--foxglove", nargs="?", const=DEFAULT_FOXGLOVE, metavar="HOST:PORT",
                        help=f"serve the session live to Foxglove (its WebSocket protocol) on HOST:PORT (default "
                             f"{DEFAULT_FOXGLOVE}; port 0: any free one): every input, output, state variable and "
                             f"the bytes each way, as channels with the schemas of --record; needs the {NEEDS}; an "
                             "address beyond loopback needs --allow-remote")


def start(args: argparse.Namespace, session: engine.Session, name: str, prog: str) -> FoxgloveServer | int | None:
    """The server `--foxglove` asks for, listening, with a line on stdout that says where; None
    without --foxglove; else (a bad HOST:PORT, one beyond loopback without --allow-remote, the
    packages missing, an address it cannot listen on) EXIT_USAGE, once stderr says why in a line."""
    if args.foxglove is None:
        return None
    try:
        host, port = parse_address(args.foxglove, "--foxglove")
        if not is_loopback(host) and not args.allow_remote:
            raise ValueError(f"--foxglove {args.foxglove} serves beyond this machine, where anyone on the network "
                             "could watch the robot: add --allow-remote if that is meant")
        server = FoxgloveServer(session, name, host, port)
    except ValueError as err:
        print(f"{prog}: {err}", file=sys.stderr)
        return EXIT_USAGE
    except ImportError:
        print(f"{prog}: --foxglove needs the {NEEDS}", file=sys.stderr)
        return EXIT_USAGE
    except RuntimeError as err:  # the SDK's FoxgloveError: the address is in use, or not this machine's
        print(f"{prog}: cannot serve Foxglove on {args.foxglove}: {str(err).removeprefix('FoxgloveError: ')}",
              file=sys.stderr)
        return EXIT_USAGE
    print(f"{prog}: Foxglove on ws://{shown(host, server.port)} (in Foxglove: Open connection, "
          "Foxglove WebSocket)", flush=True)
    if not is_loopback(host):
        print(f"{prog}: WARNING: served beyond this machine ({args.foxglove}): anyone on the network can watch "
              "the robot", flush=True)
    return server
