"""`rdisc emit-ros FILE -o node.py`: a ROS 1 node (rospy) for a description.

The node is the generated Python driver with a ROS bridge as its program: a
subscriber per domain input, a publisher per domain output, parameters `~port`
(`~port_CONNECTION` for each of several connections), `~trace` and `~timeout`,
device errors logged and published on `~errors`, and the terminate hooks run on
shutdown. With a body, the node sets `robot_description` and publishes `joint_states`.
"""

from __future__ import annotations

import argparse
import os

from rdisc.cli.output import emit_body


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("emit-ros", help="write a ROS 1 node (rospy) for a description",
                         description="Compile a description into a ROS 1 node: its Python driver and a ROS bridge.")
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("-o", "--output", metavar="NODE.py", help="where to write the node (default: stdout)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.ros import to_ros

    name = os.path.basename(args.file)
    return emit_body("emit-ros", args.file, args.output,  # a body XML cannot carry is refused as emit-urdf does
                     lambda model, sources: to_ros(model, name, sources=sources))
