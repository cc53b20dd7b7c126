"""ROS 2 message definitions, as data: the one table of the messages rdisc speaks. A recording
(`--record FILE.mcap`) carries each input and output as its adapter's ROS 2 message with these
schemas; the ROS 2 node (`rdisc emit-ros2`) builds its DDS types from them, per distribution.

An MCAP channel of ROS 2 messages names its schema `pkg/msg/Type` and carries the `.msg`
text with every message it uses after it, each under a line of `=` and `MSG: pkg/Type`
(the `ros2msg` encoding that `mcap-ros2-support`, Foxglove and `ros2 bag` read). The
table of frameworks (stdlib/frameworks.txt) makes each adapter's types of its `ros` annotation
(`geometry_msgs/Twist` in ROS 1, `geometry_msgs/msg/Twist` in ROS 2 and Foxglove); these are the definitions of the
ones the standard adapters use, by the ROS 1 style name (the engine has those of a
recording's own channels: bytes, text, log lines).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from rdisc import engine
from rdisc.semantics import model as m
from rdisc.semantics import ros

DEFINITIONS: dict[str, str] = {
    "builtin_interfaces/Time": "int32 sec\nuint32 nanosec\n",
    "std_msgs/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
    "std_msgs/Bool": "bool data\n",
    "geometry_msgs/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/Point": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/Quaternion": "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
    "geometry_msgs/Pose": "Point position\nQuaternion orientation\n",
    "geometry_msgs/Pose2D": "float64 x\nfloat64 y\nfloat64 theta\n",
    "geometry_msgs/Twist": "Vector3 linear\nVector3 angular\n",
    "geometry_msgs/PoseWithCovariance": "Pose pose\nfloat64[36] covariance\n",
    "geometry_msgs/TwistWithCovariance": "Twist twist\nfloat64[36] covariance\n",
    "nav_msgs/Odometry": (
        "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
        "geometry_msgs/TwistWithCovariance twist\n"
    ),
    "sensor_msgs/Range": (
        "uint8 ULTRASOUND=0\nuint8 INFRARED=1\nstd_msgs/Header header\nuint8 radiation_type\n"
        "float32 field_of_view\nfloat32 min_range\nfloat32 max_range\nfloat32 range\n"
    ),
    "sensor_msgs/BatteryState": (
        "uint8 POWER_SUPPLY_STATUS_UNKNOWN=0\nuint8 POWER_SUPPLY_STATUS_CHARGING=1\n"
        "uint8 POWER_SUPPLY_STATUS_DISCHARGING=2\nuint8 POWER_SUPPLY_STATUS_NOT_CHARGING=3\n"
        "uint8 POWER_SUPPLY_STATUS_FULL=4\n"
        "uint8 POWER_SUPPLY_HEALTH_UNKNOWN=0\nuint8 POWER_SUPPLY_HEALTH_GOOD=1\nuint8 POWER_SUPPLY_HEALTH_OVERHEAT=2\n"
        "uint8 POWER_SUPPLY_HEALTH_DEAD=3\nuint8 POWER_SUPPLY_HEALTH_OVERVOLTAGE=4\n"
        "uint8 POWER_SUPPLY_HEALTH_UNSPEC_FAILURE=5\nuint8 POWER_SUPPLY_HEALTH_COLD=6\n"
        "uint8 POWER_SUPPLY_HEALTH_WATCHDOG_TIMER_EXPIRE=7\nuint8 POWER_SUPPLY_HEALTH_SAFETY_TIMER_EXPIRE=8\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_UNKNOWN=0\nuint8 POWER_SUPPLY_TECHNOLOGY_NIMH=1\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_LION=2\nuint8 POWER_SUPPLY_TECHNOLOGY_LIPO=3\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_LIFE=4\nuint8 POWER_SUPPLY_TECHNOLOGY_NICD=5\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_LIMN=6\n"
        "std_msgs/Header header\nfloat32 voltage\nfloat32 temperature\nfloat32 current\nfloat32 charge\n"
        "float32 capacity\nfloat32 design_capacity\nfloat32 percentage\nuint8 power_supply_status\n"
        "uint8 power_supply_health\nuint8 power_supply_technology\nbool present\nfloat32[] cell_voltage\n"
        "float32[] cell_temperature\nstring location\nstring serial_number\n"
    ),
    "sensor_msgs/JointState": (
        "std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\nfloat64[] effort\n"
    ),
    "sensor_msgs/Temperature": "std_msgs/Header header\nfloat64 temperature\nfloat64 variance\n",
    "sensor_msgs/Imu": (  # no standard adapter's: a description's own adapter names it, for its covariances
        "std_msgs/Header header\ngeometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
        "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
        "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n"
    ),
    "std_msgs/String": "string data\n",
    # What a ROS 2 node announces itself with, on `ros_discovery_info` (`ros2 node list` reads it).
    "rmw_dds_common/Gid": "char[24] data\n",
    "rmw_dds_common/NodeEntitiesInfo": (
        "string<=256 node_namespace\nstring<=256 node_name\nGid[] reader_gid_seq\nGid[] writer_gid_seq\n"
    ),
    "rmw_dds_common/ParticipantEntitiesInfo": "Gid gid\nNodeEntitiesInfo[] node_entities_info_seq\n",
}
"""Each message's own fields (and constants), by its ROS 1 style name `pkg/Type`, as ROS 2 Humble
defines it (recordings carry these); a type without a package is of the package of the message
that names it."""

DISTROS = ("humble", "jazzy")
DEFAULT_DISTRO = "jazzy"
_CHANGED: dict[str, dict[str, str]] = {
    "humble": {},
    "jazzy": {
        "sensor_msgs/Range": DEFINITIONS["sensor_msgs/Range"] + "float32 variance\n",
        "rmw_dds_common/Gid": "char[16] data\n",  # a DDS GUID's 16 bytes since Iron, not 24
    },
}
"""Where a later distribution's definition differs from Humble's on the wire."""


def definitions(distro: str) -> dict[str, str]:
    """The table as ROS 2 `distro` (one of DISTROS) defines its messages."""
    return {**DEFINITIONS, **_CHANGED[distro]}


@dataclass(frozen=True, slots=True)
class Field:
    """A member of a message: its name, its type (a primitive, or a message `pkg/Type`), a string's
    bound (`string<=256`), and what it is a list of: None a single value, 0 a sequence, else an
    array of that size; its default, as the definition writes it, or None."""

    name: str
    type: str
    bound: int | None
    size: int | None
    default: str | None


def fields(name: str, distro: str = "humble") -> tuple[Field, ...]:
    """The members of message `name` (`pkg/Type`) in ROS 2 `distro`, constants left out."""
    package = name.split("/")[0]
    found = []
    for line in definitions(distro)[name].splitlines():
        kind, member, *default = line.split()
        if "=" in member:
            continue  # a constant: no member of the message on the wire
        base, _, size = kind.partition("[")
        base, _, bound = base.partition("<=")
        if base not in _PRIMITIVES and "/" not in base:
            base = f"{package}/{base}"
        found.append(Field(member, base, int(bound) if bound else None,
                           None if not size else int(size[:-1] or 0), default[0] if default else None))
    return tuple(found)


def used(names: Iterable[str], distro: str = "humble") -> list[str]:
    """`names` and every message their members are of, each after those it uses (so a type is
    defined before it is named)."""
    order: list[str] = []

    def visit(name: str) -> None:
        if name in order:
            return
        for member in fields(name, distro):
            if member.type not in _PRIMITIVES:
                visit(member.type)
        order.append(name)

    for name in names:
        visit(name)
    return order

_PRIMITIVES = frozenset({"bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16",
                         "int32", "uint32", "int64", "uint64", "string", "wstring"})
_SEPARATOR = "=" * 80


def _uses(name: str) -> list[str]:
    """The messages a definition's fields are of, in the order they first appear."""
    package = name.split("/")[0]
    found: list[str] = []
    for line in DEFINITIONS[name].splitlines():
        kind = line.split()[0].split("[")[0].split("<=")[0]
        if kind in _PRIMITIVES or "=" in line:
            continue
        used = kind if "/" in kind else f"{package}/{kind}"
        if used not in found:
            found.append(used)
    return found


def ros2_name(name: str) -> str:
    """`geometry_msgs/Twist` as ROS 2 names it: `geometry_msgs/msg/Twist`."""
    package, _, message = name.partition("/")
    return f"{package}/msg/{message}"


def definition(name: str) -> str:
    """The `ros2msg` schema text of a message (`pkg/Type`): its fields, then each message it
    uses, depth first, once, under its `MSG:` line."""
    order: list[str] = []
    todo = [name]
    while todo:
        current = todo.pop(0)
        if current not in order:
            order.append(current)
            todo[:0] = _uses(current)
    parts = [DEFINITIONS[name]]
    parts += [f"{_SEPARATOR}\nMSG: {used}\n{DEFINITIONS[used]}" for used in order[1:]]
    return "".join(parts)


RECORDED = "foxglove"
"""The column of the table of frameworks (stdlib/frameworks.txt) a recording and the live
Foxglove session carry each adapter as: its schema, `ros2msg`, and where each field goes."""


def adapter_message(adapter: m.Adapter) -> engine.Message | None:
    """The message an adapter is recorded as (its Foxglove schema), when it is a `ros2msg` one
    defined here and every field has a path; else None (a recording carries it as JSON text)."""
    mapping = adapter.mapping(RECORDED)
    if mapping is None or mapping.schema_encoding != "ros2msg":
        return None
    package, message = ros.message_parts(mapping.type)
    if f"{package}/{message}" not in DEFINITIONS or any(path is None for path in mapping.paths):
        return None
    return engine.Message(mapping.type, definition(f"{package}/{message}"), tuple(f.name for f in adapter.fields),
                          tuple(p for p in mapping.paths if p is not None))


def recorded_messages(model: m.Model) -> dict[str, engine.Message]:
    """The ROS 2 message of each adapter the description's inputs and outputs use, by adapter."""
    used = dict.fromkeys([*(i.adapter for i in model.inputs.values()), *(o.adapter for o in model.outputs.values())])
    return {name: message for name in used if (message := adapter_message(model.adapters[name])) is not None}
