"""`rdisc emit-sdf FILE [-o OUT.sdf]`: the robot's body as an SDF 1.9 model (Gazebo), written only
when the description checks without errors."""

from __future__ import annotations

import argparse
import os

from rdisc.cli.output import add_settings_argument, emit_body


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("emit-sdf", help="write the robot's body as SDF (Gazebo)",
                         description="Write the links and joints of a description as one SDF 1.9 model "
                                     "(what `ign sdf` and Gazebo read).")
    p.add_argument("file", metavar="FILE", help="an .rdis (or .json) description with links")
    p.add_argument("-o", "--output", metavar="OUT.sdf", help="where to write it (default: stdout)")
    add_settings_argument(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.sdf import to_sdf

    name = os.path.basename(args.file)
    return emit_body("emit-sdf", args.file, args.output, lambda model, _: to_sdf(model, name), given=args.set)
