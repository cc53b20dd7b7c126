"""`rdisc emit-ros`: a ROS 1 node (rospy) for a description: the bridge (rdisc.emit.bridge) with
rospy as its transport. It runs on the system `python3`, where Debian's ROS packages live.

Parameters are private (`_port:=/dev/ttyUSB0`, `~trace`, `~timeout`, each setting by its name);
device errors are logged and published on `~errors`; rospy's shutdown (a signal) closes the
robot, so the terminate hooks' commands are the last written.

A description with a body also gives the node its URDF (`rdisc emit-urdf`'s, a string
constant set as `robot_description` unless `~publish_description` is false) and a
`sensor_msgs/JointState` on `joint_states` for its measured joints, at `~joint_states_rate`
Hz: a ROS timer reads the robot's state snapshot (immutable, so no lock) and converts
each measured state variable with its transmission's `QUANTITY = ...`, compiled by the
driver's expression compiler. A steady rate rather than one message per tick, as ros_control's
joint_state_controller publishes: robot_state_publisher and RViz keep the transforms fresh
while the arm stands still, and the engine needs no hook of its own for the node.

Joints are commanded on `joint_command` (a `sensor_msgs/JointState`): each primitive or
interface all of whose parameters transmissions bind (or that have defaults) is called once
per message naming its joints, with each value converted by its transmission's `raw = ...`,
compiled as the measures are, through the robot's own call (its ranges checked there).
"""

from __future__ import annotations

from collections.abc import Mapping

from rdisc.emit import bridge
from rdisc.emit.bridge import IGNORE, Bridge
from rdisc.emit.python import to_python
from rdisc.emit.python_expr import quoted
from rdisc.emit.python_names import class_name
from rdisc.emit.writer import Writer
from rdisc.semantics import model as m
from rdisc.semantics import ros
from rdisc.source import SourceFile

ROS1_HELPERS = '''\
# ---- the ROS 1 bridge (rdisc emit-ros): topics named after the domain inputs and outputs ----------


def _ros_check_installed(messages: tuple[tuple[str, str], ...]) -> None:
    """Refuse to start, saying what is missing (exit status 2, no traceback), unless this
    python has ROS 1 (rospy) and each message is one of a ROS message package here: its
    package is found (not imported) and holds `msg/_Message.py`, so that the imports
    that follow load ROS messages and nothing else."""
    import importlib.util

    missing = []
    if importlib.util.find_spec("rospy") is None:
        missing.append(f"ROS 1 is not here: {sys.executable} has no rospy; run the node with the python3 "
                       "of a ROS 1 installation (Debian: apt install python3-rospy)")
    for package, message in messages:
        spec = importlib.util.find_spec(package)
        places = list(spec.submodule_search_locations or ()) if spec is not None else []
        if not any(os.path.isfile(os.path.join(place, "msg", f"_{message}.py")) for place in places):
            missing.append(f"{package}/{message} is not a ROS message here: install its package")
    if missing:
        raise _ros_refuse(missing)


'''


def to_ros(model: m.Model, source_name: str, *, sources: Mapping[str, SourceFile] | None = None) -> str:
    """The ROS node for `model`: its generated driver, with the bridge as its main program."""
    return _Ros1(model, source_name).node(to_python(model, source_name, sources=sources),
                                          ROS1_HELPERS + bridge.HELPERS)


class _Ros1(Bridge):
    """The bridge over rospy."""

    def main(self, w: Writer) -> None:
        adapters = [a for _, a in self.inputs] + [a for _, a in self.outputs]
        named = [ros.message_parts(self.mapping(a).type) for a in adapters]
        if self.measured or self.commanded:
            named.append(("sensor_msgs", "JointState"))
        messages = list(dict.fromkeys([*named, ("std_msgs", "String")]))  # as first named; ~errors' last
        with w.block("def ros_main() -> int:"):
            w.line('"""Run the robot as a ROS node until ROS shuts it down; the terminate hooks run then."""')
            w.line("_ros_check_installed((")
            with w.indented():
                w.lines([f"({quoted(p)}, {quoted(n)})," for p, n in messages])
            w.line("))")
            imports = [f"import {package}.msg as {package}_msg" for package in {p for p, _ in messages}]
            with w.block("try:  # a ROS found but broken (a module of its own missing) is refused, too"):
                w.lines([line + IGNORE for line in sorted([*imports, "import rospy"])])
            with w.block("except ImportError as err:"):
                w.line('raise _ros_refuse([f"ROS 1 does not load here: {err}"]) from None')
            w.blank()
            w.line("# rospy's threads (the master's, the topics', the timers') block SIGINT and SIGTERM, as the")
            w.line("# engine's do: a signal given to one of them would wait for rospy.spin's next turn, 0.5 s later")
            w.line("without_signals(lambda: rospy.init_node(ROBOT))")
            reading = [  # each setting given as the private parameter of its name, `_BAUD:=1000000`
                'given = (p.name for p in _DEVICE.settings if rospy.has_param(f"~{p.name}"))',
                'settings = {name: rospy.get_param(f"~{name}") for name in given}',
            ] if self.model.settings else []
            if self.model.links:  # read before the body, which may follow them
                w.lines([
                    *reading,
                    'if rospy.get_param("~publish_description", True):',
                    f'    rospy.set_param("robot_description", {self.description("settings")})',
                ])
                reading = []
            if self.measured:
                w.lines([
                    f'joint_states_rate = rospy.get_param("~joint_states_rate", {bridge.rate(self.model)!r})',
                    "if isinstance(joint_states_rate, bool) or not isinstance(joint_states_rate, (int, float)) \\",
                    "        or not 0 < joint_states_rate <= 1000:",
                    '    raise _ros_refuse([f"~joint_states_rate is {joint_states_rate!r}: give Hz, above 0, at most 1000"])',
                ])
            if self.model.links:
                w.lines([
                    'sim = rospy.get_param("~sim", False)',
                    "if not isinstance(sim, bool):",
                    '    raise _ros_refuse([f"~sim is {sim!r}: give true (simulate the body) or false (the device)"])',
                    f"simulation = _ros_simulation({self.settings('settings')}) if sim else None",
                ])
            w.line("ros_signal = signal.getsignal(signal.SIGINT)  # rospy's: shuts the node down, logging as it goes")
            w.blank()
            with w.block("def later_signal(signum: int, frame: Any) -> None:"):
                w.line('"""Ignored here, not by SIG_IGN, which makes a signal already pending raise OSError."""')
            w.blank()
            with w.block("def first_signal(signum: int, frame: Any) -> None:"):
                w.line('"""rospy\'s handler, once: a burst of signals would re-enter its logging mid-write."""')
                w.line("signal.signal(signal.SIGINT, later_signal)")
                w.line("signal.signal(signal.SIGTERM, later_signal)")
                with w.block("if callable(ros_signal):"):
                    w.line("ros_signal(signum, frame)")
            w.blank()
            w.lines([
                "signal.signal(signal.SIGINT, first_signal)",
                "signal.signal(signal.SIGTERM, first_signal)",
                "ports: dict[str, str] = {}",
                "connections = _DEVICE.connections",
            ])
            with w.block("for connection in connections.values():"):
                w.lines([
                    'default = connection.address or "/dev/ttyUSB0"',
                    'name = "~port" if len(connections) == 1 else f"~port_{connection.name}"',
                    'ports[connection.name] = str(rospy.get_param(name, rospy.get_param("~port", default)))',
                ])
            w.line('errors = rospy.Publisher("~errors", std_msgs_msg.String, queue_size=10)')
            if self.measured:
                w.line('joint_states = rospy.Publisher("joint_states", sensor_msgs_msg.JointState, queue_size=10)')
            self.publishers(w, "rospy.Publisher({topic}, {message}, queue_size=10)")
            w.blank()
            self.on_output(w, "rospy.Time(*divmod({nanoseconds}, 1_000_000_000))", "{publisher}.publish({msg})")
            w.blank()
            with w.block("def on_error(error: BaseException) -> None:"):
                w.line('rospy.logerr("%s: %s", type(error).__name__, error)')
                with w.block("try:"):
                    w.line('errors.publish(std_msgs_msg.String(data=f"{type(error).__name__}: {error}"))')
                with w.block("except rospy.ROSException:"):
                    w.line("if not rospy.core.is_shutdown_requested():  # closed by the shutdown, whose hooks close the")
                    w.line("    raise  # topics before `rospy.is_shutdown()` is true: no error, logged above")
            w.blank()
            with w.block("def on_io(direction: str, connection: str, data: bytes) -> None:"):
                w.line('shown = data.decode("ascii") if direction == "lines" else data.hex(" ")')
                w.line('arrow = {"write": ">", "read": "<"}.get(direction, direction)')
                w.line('rospy.loginfo("%s %s %s", connection, arrow, shown)')
            w.blank()
            if self.model.settings:
                w.lines([
                    *reading,
                    f'robot = {class_name(self.model.robot.name)}(timeout=float(rospy.get_param("~timeout", 1.0)))',
                    "robot.on_output(on_output)",
                    "robot.on_error(on_error)",
                    'if rospy.get_param("~trace", False):',
                    "    robot.on_io(on_io)",
                    f"robot.open(ports, settings=settings{', sim=simulation' if self.model.links else ''})",
                ])
            else:
                w.lines([
                    'robot = connect(ports, timeout=float(rospy.get_param("~timeout", 1.0)), on_output=on_output,',
                    '                on_error=on_error, on_io=on_io if rospy.get_param("~trace", False) else None'
                    + (", sim=simulation)" if self.model.links else ")"),
                ])
            w.line("rospy.on_shutdown(robot.close)")
            w.blank()
            if self.measured:
                with w.block("def publish_joint_states(event: Any) -> None:"):
                    w.line('"""The measured joints as the robot\'s state snapshot has them now, stamped now."""')
                    with w.block("try:"):
                        w.lines([
                            "position, velocity, effort = _ros_joint_states(robot.state)",
                            "msg = sensor_msgs_msg.JointState(",
                            "    name=list(_ROS_JOINTS), position=position, velocity=velocity, effort=effort)",
                            "msg.header.stamp = rospy.Time.now()",
                            "joint_states.publish(msg)",
                        ])
                    w.lines([
                        "except Exception as err:  # noqa: BLE001 - reported, and the node keeps publishing",
                        "    if not rospy.is_shutdown():  # a publisher closed by the shutdown is no error",
                        "        on_error(err)",
                    ])
                w.blank()
                w.line("without_signals(lambda: rospy.Timer(rospy.Duration(1.0 / joint_states_rate), publish_joint_states))")
                w.blank()
            self.subscriber(w)
            w.blank()
            if self.commanded:
                w.line('without_signals(lambda: rospy.Subscriber("joint_command", sensor_msgs_msg.JointState,')
                w.line("                 lambda msg: _ros_joint_command(robot, msg, on_error), queue_size=10))")
            for i, adapter in self.inputs:
                w.line(f"without_signals(lambda: rospy.Subscriber({quoted(i.name)}, {self.message(adapter)},")
                w.line(f"                 subscriber({quoted(i.name)}, _ros_read_{bridge.name(i.name)}), queue_size=10))")
            w.lines([
                "rospy.spin()",
                "# Later signals are ignored to the exit; SIG_IGN set here, outside a handler, takes a",
                "# signal already pending first.",
                "signal.signal(signal.SIGINT, signal.SIG_IGN)",
                "signal.signal(signal.SIGTERM, signal.SIG_IGN)",
                "return 0",
            ])
