"""`rdisc emit-urdf FILE [-o OUT.urdf] [--ros2-control [mock]]`: the robot's body as URDF (links,
joints, and a ros_control transmission per transmission), with ros2_control's block when asked,
written only when the description checks without errors."""

from __future__ import annotations

import argparse
import os

from rdisc.cli.output import add_settings_argument, emit_body


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("emit-urdf", help="write the robot's body as URDF",
                         description="Write the links, joints and transmissions of a description as URDF "
                                     "(what check_urdf, urchin and ROS read).")
    p.add_argument("file", metavar="FILE", help="an .rdis (or .json) description with links")
    p.add_argument("-o", "--output", metavar="OUT.urdf", help="where to write it (default: stdout)")
    p.add_argument("--ros2-control", nargs="?", const="topic", choices=("topic", "mock"), metavar="mock",
                   help="add a <ros2_control> block for the transmissions' joints: through the ROS 2 node's "
                        "joint_command and joint_states topics (joint_state_topic_hardware_interface), or "
                        "with `mock`, mock_components/GenericSystem")
    add_settings_argument(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.urdf import to_urdf

    name = os.path.basename(args.file)
    hardware = args.ros2_control
    return emit_body("emit-urdf", args.file, args.output,
                     lambda model, _: to_urdf(model, name, ros2_control_hardware=hardware), given=args.set)
