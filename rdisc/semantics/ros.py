"""ROS message types and field paths, as an adapter's `ros` annotations name them.

They reach the generated ROS node as Python identifiers (`from geometry_msgs.msg import
Twist`, `msg.linear.x`), so they are checked here for what they are, and nothing else gets
through: a package name (`geometry_msgs`), a message name (`Twist`), field names (letters,
digits and underscores, starting with a letter: never `__class__`), list items `[i]` and a
final `:yaw` (a quaternion read or written as its yaw angle).
"""

from __future__ import annotations

import keyword
import re

from rdisc import TYPE_CHECKING

if TYPE_CHECKING:
    from rdisc.semantics import model as m

MAX_INDEX = 1023  # a list item past it would make the node grow the list that far

_PACKAGE = re.compile(r"[a-z][a-z0-9_]*")
_MESSAGE = re.compile(r"[A-Z][A-Za-z0-9_]*")
_STEP = re.compile(r"([A-Za-z][A-Za-z0-9_]*)(?:\[(0|[1-9][0-9]{0,3})\])?")
CONVERSIONS = ("yaw",)


def message_problem(name: str) -> str | None:
    """What is wrong with a ROS message type name, or None."""
    package, slash, message = name.partition("/")
    if not slash or not _PACKAGE.fullmatch(package) or not _MESSAGE.fullmatch(message) \
            or keyword.iskeyword(package):
        return (f"`{name}` is not a ROS message type: write `package/Message`, the package in lower case "
                "(`geometry_msgs/Twist`)")
    return None


def message_parts(name: str) -> tuple[str, str]:
    """A message type's package and name: ROS 1's `pkg/Type`, ROS 2's `pkg/msg/Type`."""
    package, _, rest = name.partition("/")
    return package, rest.rpartition("/")[2]


def path_problem(path: str) -> str | None:
    """What is wrong with a field path in a ROS message, or None."""
    fields, colon, conversion = path.partition(":")
    if colon and conversion not in CONVERSIONS:
        return f"`:{conversion}` is not a conversion of a field path (there is `:yaw`)"
    for step in fields.split("."):
        found = _STEP.fullmatch(step)
        if found is None:
            return (f"`{step}` in `{path}` is not a ROS field: a name of letters, digits and underscores "
                    "that starts with a letter, optionally with a list item `[i]`")
        if keyword.iskeyword(found.group(1)):
            return f"`{found.group(1)}` in `{path}` is a Python keyword, which no ROS message field can be"
        if found.group(2) is not None and int(found.group(2)) > MAX_INDEX:
            return f"list item `[{found.group(2)}]` in `{path}` is past the last one allowed ({MAX_INDEX})"
    return None


def steps(path: str) -> tuple[list[tuple[str, int | None]], str | None]:
    """A checked path's fields, each with its list item or None, and its conversion or None."""
    fields, _, conversion = path.partition(":")
    out: list[tuple[str, int | None]] = []
    for step in fields.split("."):
        found = _STEP.fullmatch(step)
        assert found is not None, path  # checked by path_problem
        out.append((found.group(1), None if found.group(2) is None else int(found.group(2))))
    return out, conversion or None


ODOMETRY = "nav_msgs/Odometry"
ODOMETRY_FRAME = "odom"  # REP 105's fixed frame of odometry


def header_frames(model: m.Model, output: m.DomainOutput) -> tuple[str, str]:
    """The `header.frame_id` and `child_frame_id` ("": none) of an output's stamped messages, for
    every framework and recording: its link (`Model.frame_id`: its `frame`, else the body's base),
    but an Odometry's pose is in the fixed `odom` frame and its twist in that link, its child
    frame (REP 105). Without a body, neither is named."""
    link = model.frame_id(output)
    if link and model.adapters[output.adapter].ros == ODOMETRY:
        return ODOMETRY_FRAME, link
    return link, ""
