"""`rdisc emit-mjcf FILE -o OUT.xml`: a description's body as a MuJoCo model.

Links as nested bodies, joints, geometry, inertia and an actuator per transmission's
command (`rdisc.emit.mjcf`); written only when the description checks without errors
(one without links is a world with only its floor).
"""

from __future__ import annotations

import argparse

from rdisc.cli.output import add_settings_argument, emit_body


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser(
        "emit-mjcf", help="write a description's body as a MuJoCo model (MJCF)",
        description="Write the links, joints and transmissions of a description as MJCF, which MuJoCo loads.",
    )
    p.add_argument("file", metavar="FILE", help="an .rdis (or thesis-style .json) description")
    p.add_argument("-o", "--output", metavar="OUT.xml", help="where to write the model (default: stdout)")
    add_settings_argument(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.emit.mjcf import to_mjcf

    return emit_body("emit-mjcf", args.file, args.output, lambda model, _: to_mjcf(model), given=args.set)
