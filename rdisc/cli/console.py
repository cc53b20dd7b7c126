"""`rdisc console FILE (--port P | --sim [--seed N] [--error PRIMITIVE=CODE]...) [--http HOST:PORT [--allow-remote]] [--record FILE.mcap]
[--foxglove [HOST:PORT]]`: a
local web page to bring up and exercise a device (thesis ch. 5), or a simulation of its body.

Connects as `rdisc run` does (startup hooks), then serves the page at the address it prints,
http://HOST:PORT/?token=TOKEN (127.0.0.1:8765 unless asked; the token is the credential, new
each run) until Ctrl-C or SIGTERM, and ends by running the terminate hooks; they also run
whenever the last page closes. An --http beyond loopback needs --allow-remote. With --sim the robot drives the MuJoCo simulation `rdisc sim --realtime` drives (its
time the wall clock's, so what the page commands moves as a device would), and the page
says so and shows the simulated body as it moves; --error answers a primitive with its declared
`error` reply, as `rdisc sim --error` does. With --record, the session is recorded as `rdisc run --record` records it, the
page's calls as the host's; with --foxglove, it is served live to Foxglove as `rdisc run --foxglove`
serves it. Only pages of this console's own address may drive the robot (see rdisc.console).

Exit status: 1 the description has errors or the device failed to connect; 2 a usage error
(a bad --port, --set or --http, an --http beyond loopback without --allow-remote, --port with --sim, --seed or --error without --sim, a bad --error, --sim without a body or MuJoCo, an address
in use, a --record file that cannot be written, or a bad --foxglove); 130 after SIGINT, 143 after SIGTERM.
"""

from __future__ import annotations

import argparse
import asyncio
import math
import os
import signal
import sys

from rdisc import engine
from rdisc.cli import foxglove
from rdisc.cli.address import is_loopback, parse_address
from rdisc.cli.output import EXIT_USAGE, checked
from rdisc.cli.sim import add_error_argument, add_seed_argument, answer_errors, simulation
from rdisc.console import PING_S

DEFAULT_HTTP = "127.0.0.1:8765"


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser(
        "console", help="a local web page to bring up and exercise a device",
        description="Connect to a device (or, with --sim, a simulation of its body) and serve a web page that "
                    "shows the description's graph, a form for each input, interface and primitive, each output "
                    "live, the state, errors and a byte trace. The terminate hooks run when it stops (Ctrl-C) and "
                    "whenever the last page closes. The address it prints carries a token, new each run: only "
                    "whoever has that address can open the page and drive the robot.",
    )
    p.add_argument("file", metavar="FILE", help=".rdis or thesis-style .json description")
    p.add_argument("--port", action="append", default=[], metavar="[CONN=]PORT",
                   help="a pyserial port or URL (/dev/ttyUSB0, socket://host:port); CONN=PORT for one connection")
    p.add_argument("--sim", action="store_true",
                   help="drive a MuJoCo simulation of the description's body on the wall clock, as "
                        "`rdisc sim --realtime` does, in place of the device (no --port)")
    add_seed_argument(p)
    add_error_argument(p)
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="give a setting of the description its value; repeat for several")
    p.add_argument("--timeout", type=float, default=1.0, metavar="S", help="reply timeout in seconds (default 1)")
    p.add_argument("--http", default=DEFAULT_HTTP, metavar="HOST:PORT",
                   help=f"where to serve the page (default {DEFAULT_HTTP}; port 0: any free one); an address beyond "
                        "loopback needs --allow-remote")
    foxglove.add_argument(p)
    p.add_argument("--allow-remote", action="store_true",
                   help="let --http (and --foxglove) name an address beyond loopback (0.0.0.0: every interface): "
                        "anyone on the network who has the printed address, with its token, can then drive the "
                        "robot (and anyone can watch it in Foxglove)")
    p.add_argument("--origin", action="append", default=[], metavar="URL",
                   help="also let pages from this origin (http://name:port) drive the robot, when serving beyond "
                        "loopback")
    p.add_argument("--ping", type=_seconds, default=PING_S, metavar="S",
                   help=f"ping each page every S seconds; one that does not answer within S is closed, and if it "
                        f"was the last, the terminate hooks run (default {PING_S:g})")
    p.add_argument("--record", metavar="FILE.mcap",
                   help="record the session in MCAP as `rdisc run --record` does: the page's calls, outputs, "
                        "the bytes each way, errors (needs the mcap and mcap-ros2-support packages); a file "
                        "that exists is refused unless --force")
    p.add_argument("--force", action="store_true",
                   help="let --record replace a file that exists (never the description or its imports)")
    p.set_defaults(run=run)


def _seconds(text: str) -> float:
    """A time in seconds, more than zero and finite (--ping)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of seconds: {text!r}") from None
    if not 0 < value < math.inf:
        raise argparse.ArgumentTypeError(f"not a time more than zero: {text!r}")
    return value


def run(args: argparse.Namespace) -> int:
    compilation = checked(args.file, args.set, "rdisc console")  # its body as the settings given make it
    if isinstance(compilation, int):
        return compilation
    model = compilation.model
    assert model is not None
    from rdisc.console.page import render
    from rdisc.console.server import Console
    from rdisc.emit.decode import Teller
    from rdisc.runtime.device import Description
    from rdisc.source import place

    device = Description(model).device
    try:
        host, http_port = parse_address(args.http, "--http")
        if not is_loopback(host) and not args.allow_remote:
            raise ValueError(f"--http {args.http} serves beyond this machine, where anyone on the network who has "
                             "the address could drive the robot: add --allow-remote if that is meant")
        if args.sim and args.port:
            raise ValueError("--sim drives a simulation in place of the device: give --port or --sim, not both")
        if args.seed is not None and not args.sim:
            raise ValueError("--seed is for --sim")
        if args.error and not args.sim:
            raise ValueError("--error is for --sim")
        port = None if args.sim else engine.parse_ports(args.port, device)
        settings = engine.bind_settings(device, engine.parse_settings(args.set, device))
    except ValueError as err:
        print(f"rdisc console: {err}", file=sys.stderr)
        return EXIT_USAGE
    main = model.robot.span.path if model.robot.span else None
    page = render(model, lambda span: place(span, compilation.sources, main, os.path.basename(args.file)),
                  simulated=args.sim)
    sim = simulation(model, args.file, "rdisc console", seed=args.seed, realtime=True) if args.sim else None
    if args.sim and (sim is None or not answer_errors(sim, args.error, "rdisc console")):
        return EXIT_USAGE
    robot = engine.Robot(device, timeout=args.timeout)
    session = engine.Session(robot) if args.record or args.foxglove is not None else None
    recorder = (engine.start_recording(robot, args.record, settings, "rdisc console", force=args.force,
                                       inputs=list(compilation.sources), session=session) if args.record else None)
    if args.record and recorder is None:
        return EXIT_USAGE
    live = foxglove.start(args, session, robot.name, "rdisc console") if session is not None else None
    if isinstance(live, int):
        return live
    console = Console(robot, page, session, sim, tell=lambda text: print(text, file=sys.stderr, flush=True),
                      ping=args.ping, teller=Teller(model, device))
    robot.on_error(lambda error: print(f"rdisc console: {type(error).__name__}: {error}", file=sys.stderr, flush=True))

    def listening(bound: int) -> None:
        shown = f"[{host}]" if ":" in host else host
        what = f"{robot.name}, simulated," if sim is not None else robot.name
        print(f"rdisc console: {what} on http://{shown}:{bound}/?token={console.token} (Ctrl-C stops it; the "
              "terminate hooks run)", flush=True)
        if not is_loopback(host):
            print(f"rdisc console: WARNING: served beyond this machine ({args.http}): anyone on the network who "
                  "has this address can drive the robot", flush=True)

    async def serve() -> int:
        stop = asyncio.Event()
        status = [engine.EXIT_OK]

        def stopping(code: int) -> None:
            if not stop.is_set():
                status[0] = code
                stop.set()

        loop = asyncio.get_running_loop()
        loop.add_signal_handler(signal.SIGINT, stopping, engine.EXIT_SIGINT)
        loop.add_signal_handler(signal.SIGTERM, stopping, engine.EXIT_SIGTERM)
        try:
            await asyncio.to_thread(robot.open, port, settings=settings, sim=sim)
            await console.serve(host, http_port, stop, listening, args.origin)
        except engine.RdisError as err:
            print(f"rdisc console: {type(err).__name__}: {err}", file=sys.stderr)
            if session is not None:
                session.error(err)
            status[0] = engine.EXIT_ERROR
        except OSError as err:  # the address is in use, or not this machine's
            print(f"rdisc console: cannot serve on {args.http}: {err.strerror or err}", file=sys.stderr)
            status[0] = EXIT_USAGE
        finally:
            await asyncio.to_thread(robot.close)
            if live is not None:
                live.stop()
            if recorder is not None:
                recorder.finish()
        return status[0]

    return asyncio.run(serve())
