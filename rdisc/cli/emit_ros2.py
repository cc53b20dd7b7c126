"""`rdisc emit-ros2 FILE -o node.py [--distro humble|jazzy]`: a ROS 2 node for a description.

The node is the generated Python driver with a ROS 2 bridge as its program, speaking DDS as ROS 2
does through Cyclone DDS (`pip install cyclonedds` where it runs; no ROS 2 installation needed):
a subscription per domain input, a publication per domain output, `~/errors`, parameters from
`--ros-args -p port:=/dev/ttyUSB0 -p NAME:=VALUE`, the terminate hooks run on SIGINT and SIGTERM.
"""

from __future__ import annotations

import argparse
import os
import sys

from rdisc.cli.output import EXIT_ERRORS, emit_body
from rdisc.lowering.messages import DEFAULT_DISTRO, DISTROS


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("emit-ros2", help="write a ROS 2 node (over DDS, Cyclone DDS) for a description",
                         description="Compile a description into a ROS 2 node: its Python driver and a ROS 2 "
                                     "bridge speaking DDS through Cyclone DDS (no ROS 2 installation needed).")
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("-o", "--output", metavar="NODE.py", help="where to write the node (default: stdout)")
    p.add_argument("--distro", choices=DISTROS, default=DEFAULT_DISTRO,
                   help=f"the ROS 2 distribution whose message definitions the node speaks (default {DEFAULT_DISTRO})")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.ros2 import Ros2Error, to_ros2

    name = os.path.basename(args.file)
    try:
        return emit_body("emit-ros2", args.file, args.output,
                         lambda model, sources: to_ros2(model, name, distro=args.distro, sources=sources))
    except Ros2Error as err:
        print(f"rdisc emit-ros2: {args.file}: {err}", file=sys.stderr)
        return EXIT_ERRORS
