"""`rdisc emit-ros`: a ROS 1 node (rospy) for a description.

The node is the generated Python driver (`rdisc.emit.python`) with a ROS bridge
in place of its command line: one subscriber per domain input and one publisher
per domain output, named after them (so standard ROS remapping renames them),
the adapters' ROS messages and field paths taken from their `ros` annotations
(stdlib/adapters.rdis). The semantics are the driver's: one implementation, not
a third copy. It runs on the system `python3`, where Debian's ROS packages live.
"""

from __future__ import annotations

from collections.abc import Mapping

from rdisc.emit.python import to_python
from rdisc.emit.python_expr import quoted
from rdisc.semantics import model as m
from rdisc.source import SourceFile

_MAIN = 'if __name__ == "__main__":\n    sys.exit(main())\n'

BRIDGE = '''\
# ---- the ROS 1 bridge (rdisc emit-ros): topics named after the domain inputs and outputs ----------


def _ros_type(name: str) -> Any:
    """The message class a ROS type name ("geometry_msgs/Twist") stands for."""
    import importlib

    package, _, message = name.partition("/")
    return getattr(importlib.import_module(f"{package}.msg"), message)


def _ros_step(message: Any, part: str) -> tuple[Any, str, int | None]:
    """(the object holding `part`, its field name, its list index or None)."""
    field, _, rest = part.partition("[")
    return message, field, int(rest.rstrip("]")) if rest else None


def _ros_get(message: Any, path: str) -> Any:
    """The value at `path` in a ROS message: dotted fields, `[i]` list items, `:yaw` a quaternion's yaw."""
    path, _, conversion = path.partition(":")
    for part in path.split("."):
        _, field, index = _ros_step(message, part)
        message = getattr(message, field)
        if index is not None:
            message = message[index] if index < len(message) else None
    if conversion == "yaw":
        q = message
        return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    return message


def _ros_set(message: Any, path: str, value: Any) -> None:
    """Put `value` at `path` in a ROS message (as `_ros_get` reads it)."""
    path, _, conversion = path.partition(":")
    *parents, last = path.split(".")
    for part in parents:
        message = getattr(message, part)
    if conversion == "yaw":
        quaternion = getattr(message, last)
        quaternion.x, quaternion.y = 0.0, 0.0
        quaternion.z, quaternion.w = math.sin(value / 2), math.cos(value / 2)
        return
    _, field, index = _ros_step(message, last)
    if index is None:
        setattr(message, field, value)
        return
    items = list(getattr(message, field))
    items.extend([type(value)()] * (index + 1 - len(items)))
    items[index] = value
    setattr(message, field, items)


def ros_main() -> int:
    """Run the robot as a ROS node until ROS shuts it down; the terminate hooks run then."""
    import importlib

    rospy: Any = importlib.import_module("rospy")  # Debian's python3-rospy: no types to check against
    String = _ros_type("std_msgs/String")
    rospy.init_node(ROBOT)
    ports: dict[str, str] = {}
    connections = _DEVICE.connections
    for connection in connections.values():
        default = connection.address or "/dev/ttyUSB0"
        name = "~port" if len(connections) == 1 else f"~port_{connection.name}"
        ports[connection.name] = str(rospy.get_param(name, rospy.get_param("~port", default)))
    errors = rospy.Publisher("~errors", String, queue_size=10)
    publishers = {output: rospy.Publisher(output, _ros_type(ros), queue_size=10)
                  for output, (ros, _fields) in _ROS_OUTPUTS.items()}

    def on_output(message: dict[str, Any]) -> None:
        ros, fields = _ROS_OUTPUTS[message["name"]]
        msg = _ros_type(ros)()
        for name, path in fields:
            _ros_set(msg, path, message["contents"][name])
        publishers[message["name"]].publish(msg)

    def on_error(error: BaseException) -> None:
        rospy.logerr("%s: %s", type(error).__name__, error)
        errors.publish(String(data=f"{type(error).__name__}: {error}"))

    def on_io(direction: str, connection: str, data: bytes) -> None:
        rospy.loginfo("%s %s %s", connection, ">" if direction == "write" else "<", data.hex(" "))

    robot = connect(ports, timeout=float(rospy.get_param("~timeout", 1.0)), on_output=on_output,
                    on_error=on_error, on_io=on_io if rospy.get_param("~trace", False) else None)
    rospy.on_shutdown(robot.close)

    def subscriber(name: str, fields: tuple[tuple[str, str], ...]) -> Callable[[Any], None]:
        def received(msg: Any) -> None:
            try:
                robot.call_input(name, **{key: _ros_get(msg, path) for key, path in fields})
            except Exception as err:  # noqa: BLE001 - reported, and the node keeps serving
                on_error(err)
        return received

    for name, (ros, fields) in _ROS_INPUTS.items():
        rospy.Subscriber(name, _ros_type(ros), subscriber(name, fields), queue_size=10)
    rospy.spin()
    return 0'''


def to_ros(model: m.Model, source_name: str, *, sources: Mapping[str, SourceFile] | None = None) -> str:
    """The ROS node for `model`: its generated driver, with the bridge as its main program."""
    driver = to_python(model, source_name, sources=sources)
    assert driver.endswith(_MAIN)
    tables = [_table("_ROS_INPUTS", model, model.inputs.values()),
              _table("_ROS_OUTPUTS", model, model.outputs.values())]
    return (driver[: -len(_MAIN)] + "\n".join(tables) + "\n\n" + BRIDGE + "\n\n\n"
            + 'if __name__ == "__main__":\n    sys.exit(ros_main())\n')


def _table(name: str, model: m.Model, elements) -> str:
    """Each input or output with its adapter's ROS message and each field's path in it."""
    lines = [f"{name}: dict[str, tuple[str, tuple[tuple[str, str], ...]]] = {{"]
    for element in elements:
        adapter = model.adapters[element.adapter]
        if adapter.ros is None:
            continue
        paths = ", ".join(f"({quoted(f.name)}, {quoted(f.ros or f.name)})" for f in adapter.fields)
        lines.append(f"    {quoted(element.name)}: ({quoted(adapter.ros)}, ({paths},)),")
    lines.append("}")
    lines.append(f'"""Each domain {"input" if "INPUTS" in name else "output"}: its ROS message type and, '
                 'for each field, its path in it."""')
    return "\n".join(lines) + "\n"
