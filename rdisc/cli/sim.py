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
from typing import TYPE_CHECKING

from rdisc import engine
from rdisc.cli.output import EXIT_USAGE, checked

if TYPE_CHECKING:
    from rdisc.semantics.model import Model
    from rdisc.sim import Simulation


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser(
        "sim", help="run a description against a MuJoCo simulation of its body",
        description="Run a description as `rdisc run` does, against a simulation of its links, joints and "
                    "transmissions in place of the device, in simulated time (deterministic) unless --realtime.",
    )
    p.add_argument("file", metavar="FILE", help=".rdis or thesis-style .json description")
    engine.add_arguments(p, ports=False)
    add_seed_argument(p)
    add_error_argument(p)
    p.add_argument("--realtime", action="store_true", help="run on the wall clock instead of simulated time")
    p.set_defaults(run=run)


def add_seed_argument(parser: argparse.ArgumentParser) -> None:
    """`--seed N`, of `rdisc sim` and `rdisc console --sim`."""
    parser.add_argument("--seed", type=int, metavar="N",
                        help="start each joint up to 0.01 rad (m) away from zero, the same way for the same N")


def add_error_argument(parser: argparse.ArgumentParser) -> None:
    """`--error PRIMITIVE=CODE`, of `rdisc sim` and `rdisc console --sim`."""
    parser.add_argument("--error", action="append", default=[], metavar="PRIMITIVE=CODE",
                        help="answer PRIMITIVE with its declared `error` reply, CODE a number or a member of its enum "
                             "(ILLEGAL_DATA_ADDRESS): its call raises RdisDeviceError as the device's would")


def answer_errors(simulated: Simulation, given: list[str], prog: str) -> bool:
    """Tell the simulation to answer each `--error PRIMITIVE=CODE` with its error reply; False once
    stderr says why one cannot be (a usage error)."""
    for one in given:
        primitive, _, code = one.partition("=")
        try:
            if not code:
                raise ValueError("give it as PRIMITIVE=CODE")
            simulated.answer_error(primitive, _code(code))
        except ValueError as err:
            print(f"{prog}: --error {one}: {err}", file=sys.stderr)
            return False
    return True


def simulation(model: Model, path: str, prog: str, *, seed: int | None, realtime: bool) -> Simulation | None:
    """The MuJoCo simulation of `model`'s body (`rdisc sim`, `rdisc console --sim`), or None once
    stderr says why there is none (no `link`, MuJoCo missing, or a body MuJoCo refuses), which
    is a usage error."""
    if not model.links:
        print(f"{prog}: {path} has no body to simulate: it declares no `link`", file=sys.stderr)
        return None
    try:
        from rdisc.sim import Simulation, SimulationError
    except ImportError:
        print(f"{prog}: needs MuJoCo (pip install mujoco, or pip install 'rdisc[sim]')", file=sys.stderr)
        return None
    try:
        return Simulation(model, seed=seed, realtime=realtime)
    except SimulationError as err:  # a mesh it cannot read, contacts past its memory
        print(f"{prog}: {err}", file=sys.stderr)
        return None


def run(args: argparse.Namespace) -> int:
    compilation = checked(args.file, args.set, "rdisc sim")  # its body as the settings given make it
    if isinstance(compilation, int):
        return compilation
    model = compilation.model
    assert model is not None
    simulated = simulation(model, args.file, "rdisc sim", seed=args.seed, realtime=args.realtime)
    if simulated is None or not answer_errors(simulated, args.error, "rdisc sim"):
        return EXIT_USAGE
    from rdisc.runtime.device import Description

    robot = engine.Robot(Description(model).device, timeout=args.timeout)
    from rdisc.sim.odometry import OdometryWatch

    watch = OdometryWatch(model, simulated, show=args.watch)
    if watch.errors:
        robot.on_output(watch)
    status = engine.run_command(args, robot, "rdisc sim", sim=simulated, inputs=list(compilation.sources))
    for warning in simulated.warnings if status == 0 else ():  # what the physics did that the device would not
        print(f"rdisc sim: warning: {warning}", file=sys.stderr)  # (a run that failed says its error alone)
    return status


def _code(text: str) -> int | str:
    """An --error code: a number as a description writes one (2, 0x02), else a member's name."""
    try:
        return int(text, 0)
    except ValueError:
        return text
