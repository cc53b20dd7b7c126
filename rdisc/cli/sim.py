"""`rdisc sim FILE [--call NAME k=v ...]... [--duration S] [--watch] [--trace] [--seed N] [--realtime]`.

Runs a description as `rdisc run` does (the engine's `run_command`: the same calls,
outputs, trace, settings, recording and exit statuses), against a MuJoCo simulation of
its body in place of the device (`rdisc.sim`): the transmissions turn what the host
commands into the joints' actuators, and the joints into what the device reports. Time
is simulated, so a run takes what the physics needs, not --duration seconds, and gives
the same figures every time; `--realtime` runs on the wall clock instead.

Exit status: as `rdisc run`'s; 2 also when the description has no body or MuJoCo is not
installed.
"""

from __future__ import annotations

import argparse
import sys

from rdisc.cli.output import EXIT_ERRORS, EXIT_USAGE, exit_code, show
from rdisc.compile import compile_path
from rdisc.runtime import engine


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser(
        "sim", help="run a description against a MuJoCo simulation of its body",
        description="Run a description as `rdisc run` does, against a simulation of its links, joints and "
                    "transmissions in place of the device, in simulated time (deterministic) unless --realtime.",
    )
    p.add_argument("file", metavar="FILE", help=".rdis or thesis-style .json description")
    engine.add_arguments(p, ports=False)
    p.add_argument("--seed", type=int, metavar="N",
                   help="start each joint up to 0.01 rad (m) away from zero, the same way for the same N")
    p.add_argument("--realtime", action="store_true", help="run on the wall clock instead of simulated time")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    compilation = compile_path(args.file)
    show([compilation])
    model = compilation.model
    if model is None or compilation.diagnostics.has_errors():
        return exit_code([compilation]) or EXIT_ERRORS
    if not model.links:
        print(f"rdisc sim: {args.file} has no body to simulate: it declares no `link`", file=sys.stderr)
        return EXIT_USAGE
    try:
        from rdisc.sim import Simulation

        simulation = Simulation(model, seed=args.seed, realtime=args.realtime)
    except ImportError:
        print("rdisc sim: needs MuJoCo (pip install mujoco, or pip install 'rdisc[sim]')", file=sys.stderr)
        return EXIT_USAGE
    from rdisc.runtime.device import Description

    robot = engine.Robot(Description(model).device, timeout=args.timeout)
    return engine.run_command(args, robot, "rdisc sim", sim=simulation)
