"""`rdisc run FILE --port P [--call NAME k=v ...]...`: drive a device from the command line.

Loads the description, then does what every generated driver's command line does
(the engine's `run_command`, one implementation for both): connects (startup
hooks), performs the calls in order, then runs until `--duration` seconds after the
startup hooks ended, or until Ctrl-C with `--watch`, or ends when the calls are done. Whatever happens (the end,
a device error, Ctrl-C, SIGTERM), it ends by running the terminate hooks, so a
robot is left stopped.

With `--foxglove [HOST:PORT]` the session is served live to Foxglove (rdisc.cli.foxglove) on
the same channels a `--record` recording has, the state variables besides; beyond loopback
only with `--allow-remote`.

Exit status: 0 done; 1 the description has errors or the device failed; 2 a
usage error (a bad --port, --call or --foxglove, a --foxglove beyond loopback without
--allow-remote or without its packages); 130 after SIGINT, 143 after SIGTERM.
"""

from __future__ import annotations

import argparse

from rdisc import engine
from rdisc.cli import foxglove
from rdisc.cli.output import checked


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser(
        "run", help="run a description against a device: calls, outputs, I/O trace",
        description="Connect to a device, perform calls and show outputs. The terminate hooks always run at the end.",
    )
    p.add_argument("file", metavar="FILE", help=".rdis or thesis-style .json description")
    engine.add_arguments(p)
    foxglove.add_argument(p)
    p.add_argument("--allow-remote", action="store_true",
                   help="let --foxglove name an address beyond loopback (0.0.0.0: every interface): anyone on "
                        "the network can then watch the robot")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    compilation = checked(args.file)
    if isinstance(compilation, int):
        return compilation
    model = compilation.model
    assert model is not None
    from rdisc.runtime.device import Description

    robot = engine.Robot(Description(model).device, timeout=args.timeout)
    session = engine.Session(robot) if args.foxglove is not None else None
    server = foxglove.start(args, session, robot.name, "rdisc run") if session is not None else None
    if isinstance(server, int):
        return server
    try:
        return engine.run_command(args, robot, "rdisc run", inputs=list(compilation.sources), session=session)
    finally:
        if server is not None:
            server.stop()
