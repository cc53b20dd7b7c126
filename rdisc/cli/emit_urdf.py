"""`rdisc emit-urdf FILE [-o OUT.urdf]`: the robot's body as URDF (links, joints, and a ros_control
transmission per transmission), written only when the description checks without errors."""

from __future__ import annotations

import argparse
import os

from rdisc.cli.output import emit_body


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("emit-urdf", help="write the robot's body as URDF",
                         description="Write the links, joints and transmissions of a description as URDF "
                                     "(what check_urdf, urchin and ROS read).")
    p.add_argument("file", metavar="FILE", help="an .rdis (or .json) description with links")
    p.add_argument("-o", "--output", metavar="OUT.urdf", help="where to write it (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.urdf import to_urdf

    name = os.path.basename(args.file)
    return emit_body("emit-urdf", args.file, args.output, lambda model, _: to_urdf(model, name))
