"""`rdisc replay FILE.mcap DESCRIPTION`: a recording's device bytes through a description, and
where its outputs (and the bytes it writes) differ from the recording's.

Exit status: 0 the replay is the recording; 1 it differs (each difference a line), or the
description has errors; 2 the recording cannot be read (not MCAP, damaged, too large, a message
of a type or shape rdisc does not write; or the mcap libraries are missing), said in a line.
The description's delays are not slept unless --realtime.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from rdisc import engine
from rdisc.cli.output import EXIT_ERRORS, EXIT_USAGE, checked_model


def add_parser(verbs: Any) -> None:  # argparse's subparsers
    p = verbs.add_parser(
        "replay", help="replay a recording (rdisc run --record) through a description and report differences",
        description="Feed the device bytes of a recording through a description, making the recorded calls "
                    "in order, and report where its outputs and the bytes it writes differ from the recording.",
    )
    p.add_argument("recording", metavar="FILE.mcap", help="a recording made by rdisc run --record")
    p.add_argument("file", metavar="DESCRIPTION", help=".rdis or thesis-style .json description")
    p.add_argument("--realtime", action="store_true",
                   help="sleep through the description's delays as the session did (default: no sleeping)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.runtime.replay import RecordingError, differences, read_recording, replay

    model = checked_model(args.file)
    if isinstance(model, int):
        return model
    from rdisc.runtime.device import Description

    device = Description(model).device
    try:
        recorded = read_recording(args.recording)
    except RecordingError as err:
        print(f"rdisc replay: {args.recording}: {err}", file=sys.stderr)
        return EXIT_USAGE
    try:
        replayed = replay(recorded, device, realtime=args.realtime)
    except engine.RdisError as err:  # the startup hooks failed
        print(f"rdisc replay: {type(err).__name__}: {err}", file=sys.stderr)
        return EXIT_ERRORS
    except (TypeError, ValueError) as err:  # the recording's settings are not this description's
        print(f"rdisc replay: {args.recording}: {err}", file=sys.stderr)
        return EXIT_USAGE
    found = differences(recorded, replayed, device)
    for line in found:
        print(line)
    if found:
        print(f"rdisc replay: {args.file} differs from {args.recording}", file=sys.stderr)
        return EXIT_ERRORS
    return 0
