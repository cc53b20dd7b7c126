"""`rdisc run FILE --port P [--call NAME k=v ...]...`: drive a device from the command line.

Loads the description, then does what every generated driver's command line does
(the engine's `run_command`, one implementation for both): connects (startup
hooks), performs the calls in order, then runs until `--duration` seconds after the
startup hooks ended, or until Ctrl-C with `--watch`, or ends when the calls are done. Whatever happens (the end,
a device error, Ctrl-C, SIGTERM), it ends by running the terminate hooks, so a
robot is left stopped.

Exit status: 0 done; 1 the description has errors or the device failed; 2 a
usage error (a bad --port or --call); 130 after SIGINT, 143 after SIGTERM.
"""

from __future__ import annotations

import argparse

from rdisc import engine
from rdisc.cli.output import checked


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser(
        "run", help="run a description against a device: calls, outputs, I/O trace",
        description="Connect to a device, perform calls and show outputs. The terminate hooks always run at the end.",
    )
    p.add_argument("file", metavar="FILE", help=".rdis or thesis-style .json description")
    engine.add_arguments(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    compilation = checked(args.file)
    if isinstance(compilation, int):
        return compilation
    model = compilation.model
    assert model is not None
    from rdisc.runtime.device import Description

    robot = engine.Robot(Description(model).device, timeout=args.timeout)
    return engine.run_command(args, robot, "rdisc run", inputs=list(compilation.sources))
