"""`rdisc emit-ros`: a ROS 1 node (rospy) for a description.

The node is the generated Python driver (`rdisc.emit.python`) with a ROS bridge
in place of its command line: one subscriber per domain input and one publisher
per domain output, named after them (so standard ROS remapping renames them),
the adapters' ROS messages and field paths taken from their `ros` annotations
(stdlib/adapters.rdis). Those are checked names (rdisc.semantics.ros), resolved
here: the node imports each message module and reads and writes each field by
name in its own code, and nothing it does at run time looks a name up from text. The semantics are the driver's: one implementation, not
a third copy. It runs on the system `python3`, where Debian's ROS packages live.

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
from pathlib import PurePath

from rdisc.emit.canonical import to_json
from rdisc.emit.python import class_name, to_python
from rdisc.emit.python_expr import Compiler, literal, quoted
from rdisc.emit.urdf import to_urdf
from rdisc.emit.writer import Writer
from rdisc.semantics import model as m
from rdisc.semantics import ros
from rdisc.semantics.model import Type
from rdisc.source import SourceFile

_MAIN = 'if __name__ == "__main__":\n    sys.exit(main())\n'

BRIDGE_HELPERS = '''\
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


def _ros_refuse(problems: list[str]) -> SystemExit:
    """Say why the node cannot start, on stderr: raise what it gives to end with exit status 2."""
    prog = os.path.basename(sys.argv[0])
    print("\\n".join(f"{prog}: {problem}" for problem in problems), file=sys.stderr)
    return SystemExit(2)


def _ros_header(msg: Any, read_ns: int, frame_id: str, child_frame_id: str) -> None:
    """Stamp a message that has a std_msgs/Header (genpy says which: `_has_header`) as an output's
    data: the time it was read (`OutputMessage.read_ns`, not the time of publishing) and its frames:
    the body's link it belongs to (an Odometry's pose is in `odom`, that link its child frame)."""
    if msg._has_header:
        msg.header.stamp.secs, msg.header.stamp.nsecs = divmod(read_ns, 1_000_000_000)
        msg.header.frame_id = frame_id
    if child_frame_id:
        msg.child_frame_id = child_frame_id


def _ros_item(items: Any, index: int) -> Any:
    """A list item of a message, or None past its end."""
    return items[index] if index < len(items) else None


def _ros_with(items: Any, index: int, value: Any) -> list[Any]:
    """A message's list with `value` at `index`, grown with empty items of its type as needed."""
    grown = list(items)
    grown.extend([type(value)()] * (index + 1 - len(grown)))
    grown[index] = value
    return grown


def _ros_yaw(q: Any) -> float:
    """The yaw of a quaternion."""
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def _ros_set_yaw(q: Any, yaw: float) -> None:
    """A quaternion set to a rotation of `yaw` about z."""
    q.x, q.y, q.z, q.w = 0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)'''


JOINT_COMMAND = '''def _ros_joint_command(robot: Robot, msg: Any, report: Callable[[BaseException], None]) -> None:
    """Call each of _ROS_COMMANDS whose joints the JointState `msg` names, all of them, with their
    values through the transmissions; what cannot be sent is reported (an RdisValueError), and
    nothing is sent for that target."""
    given = {name: at for at, name in enumerate(msg.name)}
    values = (msg.position, msg.velocity, msg.effort)
    for kind, target, joints, arguments in _ROS_COMMANDS:
        missing = [joint for joint, _ in joints if joint not in given]
        if len(missing) == len(joints):
            continue
        if missing:
            report(RdisValueError(f"joint_command: {target} takes {', '.join(j for j, _ in joints)} together; "
                                  f"missing: {', '.join(missing)}"))
            continue
        lacking = [f"{_ROS_QUANTITIES[q]} of {joint}" for joint, q in joints if given[joint] >= len(values[q])]
        if lacking:
            report(RdisValueError(f"joint_command: {target}: no {', '.join(lacking)}"))
            continue
        try:
            args = arguments([values[q][given[joint]] for joint, q in joints])
            if kind == "primitive":
                robot.call_primitive(target, *args)
            else:
                robot.call_interface(target, *args)
        except Exception as err:  # noqa: BLE001 - reported, and the other targets still sent
            report(err)
    unknown = [name for name in msg.name if name not in _ROS_COMMANDED]
    if unknown:
        report(RdisValueError(f"joint_command: no command takes {', '.join(unknown)}"))'''


def to_ros(model: m.Model, source_name: str, *, sources: Mapping[str, SourceFile] | None = None) -> str:
    """The ROS node for `model`: its generated driver, with the bridge as its main program."""
    w = Writer()
    bridge = _Bridge(model, source_name)
    bridge.write(w)
    driver = to_python(model, source_name, sources=sources)
    assert driver.endswith(_MAIN)
    return (driver[: -len(_MAIN)] + BRIDGE_HELPERS + "\n\n\n" + w.text().lstrip("\n") + "\n\n"
            + 'if __name__ == "__main__":\n    sys.exit(ros_main())\n')


_IGNORE = "  # type: ignore[import-not-found, import-untyped, unused-ignore]"  # Debian's ROS (and rdisc) have no types


class _Bridge:
    """The node's conversions and main, for the inputs and outputs whose adapter names a message."""

    def __init__(self, model: m.Model, source_name: str) -> None:
        self.model = model
        self.source_name = source_name
        self.exprs = Compiler()
        self.measured = _measured(model)
        self.commanded = _commanded(model)
        self.inputs = [(i, model.adapters[i.adapter]) for i in model.inputs.values()
                       if model.adapters[i.adapter].ros is not None]
        self.outputs = [(o, model.adapters[o.adapter]) for o in model.outputs.values()
                        if model.adapters[o.adapter].ros is not None]

    def message(self, adapter: m.Adapter) -> str:
        """The message class, as ros_main names it: `geometry_msgs_msg.Twist`."""
        assert adapter.ros is not None and ros.message_problem(adapter.ros) is None
        package, _, message = adapter.ros.partition("/")
        return f"{package}_msg.{message}"

    def write(self, w: Writer) -> None:
        for i, adapter in self.inputs:
            w.blank(2)
            with w.block(f"def _ros_read_{_name(i.name)}(msg: Any) -> dict[str, Any]:"):
                w.line(f'"""The fields of input {i.name} from a {adapter.ros}."""')
                items = [f"{quoted(f.name)}: {_read('msg', f.ros or f.name)}" for f in adapter.fields]
                flat = "return {" + ", ".join(items) + "}"
                if len(flat) <= w.width():
                    w.line(flat)
                else:
                    w.line("return {")
                    with w.indented():
                        w.lines([item + "," for item in items])
                    w.line("}")
        for o, adapter in self.outputs:
            w.blank(2)
            with w.block(f"def _ros_fill_{_name(o.name)}(msg: Any, contents: dict[str, Any]) -> None:"):
                w.line(f'"""A {adapter.ros} filled with the fields of output {o.name}."""')
                for f in adapter.fields:
                    w.line(_write("msg", f.ros or f.name, f"contents[{quoted(f.name)}]"))
        if self.model.links:
            w.blank(2)
            self.body(w)
        w.blank(2)
        self.main(w)

    def body(self, w: Writer) -> None:
        """The URDF as a constant, and the measured joints' names and their conversion from the state."""
        w.comment(f"The body, as `rdisc emit-urdf {self.source_name}` writes it: the robot_description parameter.")
        w.line("_ROS_DESCRIPTION = (")
        with w.indented():
            w.lines([quoted(line) for line in to_urdf(self.model, self.source_name).splitlines(keepends=True)])
        w.line(")")
        self.simulation(w)
        if self.commanded:
            w.blank(2)
            self.commands(w)
        if not self.measured:
            return
        w.blank(2)
        w.lines(["_ROS_JOINTS = (", *(f"    {quoted(joint)}," for joint, _ in self.measured), ")"])
        w.blank(2)
        quantities = [q for q in m.Quantity if any(q in measures for _, measures in self.measured)]
        with w.block("def _ros_joint_states(state: StateValues) -> tuple[list[float], list[float], list[float]]:"):
            w.line('"""Position, velocity and effort of each of _ROS_JOINTS, read from the state variables that')
            w.line("measure them through their transmissions' conversions (`position = ...` of `raw`). A quantity")
            w.line('no joint measures is an empty list; one that another joint measures is NaN there."""')
            w.line("return (")
            with w.indented():
                for quantity in m.Quantity:
                    if quantity not in quantities:
                        w.line(f"[],  # no {quantity.value}")
                        continue
                    w.line("[")
                    with w.indented():
                        for joint, measures in self.measured:
                            binding = measures.get(quantity)
                            if binding is None:
                                w.line(f"math.nan,  # {joint}")
                                continue
                            raw = f"state[{quoted(binding.target)}]"
                            raw = raw if binding.index is None else f"{raw}[{binding.index}]"
                            w.line(f"{self.exprs.bound(binding.to_joint, Type.FLOAT, {'raw': raw}).text},")
                    w.line("],")
            w.line(")")

    def commands(self, w: Writer) -> None:
        """Each fully bound command target as its arguments from its joints' values, and the
        function that calls them for a JointState."""
        for k, (_kind, target, params, joints) in enumerate(self.commanded):
            with w.block(f"def _ros_command_{k}(v: list[float]) -> list[Any]:"):
                w.line(f'"""The arguments of {target} from the values of {", ".join(j for j, _ in joints)}."""')
                w.line("return [")
                with w.indented():
                    for param, bound in params:
                        w.lines(self.argument(param, bound, joints))
                w.line("]")
            w.blank(2)
        w.line("# The targets all of whose parameters transmissions bind: kind, name, the joints with the")
        w.line("# quantity of each (0 position, 1 velocity, 2 effort), and the arguments from their values.")
        w.line("_ROS_COMMANDS: tuple[tuple[str, str, tuple[tuple[str, int], ...], Callable[[list[float]], list[Any]]], ...] = (")
        quantities = list(m.Quantity)
        with w.indented():
            for k, (kind, target, _params, joints) in enumerate(self.commanded):
                w.line(f"({quoted(kind)}, {quoted(target)}, (")
                w.lines([f"    ({quoted(j)}, {quantities.index(b.quantity)})," for j, b in joints])
                w.line(f"), _ros_command_{k}),")
        w.line(")")
        w.blank(2)
        w.lines(['_ROS_QUANTITIES = ("position", "velocity", "effort")', "_ROS_COMMANDED = frozenset((",
                 *(f"    {quoted(j)}," for j in dict.fromkeys(j for c in self.commanded for j, _ in c[3])), "))"])
        w.blank(2)
        w.lines(JOINT_COMMAND.splitlines())

    def argument(self, param: m.Parameter, bound: dict[int | None, int],
                 joints: list[tuple[str, m.Binding]]) -> list[str]:
        """One argument: each place's value converted from its joint's (`v[k]`), else the parameter's default."""
        def converted(index: int | None, declared: m.AnyType) -> str:
            k = bound[index]
            binding = joints[k][1]
            return self.exprs.bound(binding.to_device, declared, {binding.quantity.value: f"v[{k}]"}).text
        if not bound:
            assert param.default is not None
            return [literal(param.default, param.type).text + ","]
        if isinstance(param.type, m.Array):
            element = param.type.element
            return ["(", *(f"    {converted(i, element)}," for i in range(param.type.size)), "),"]
        return [converted(None, param.type) + ","]

    def simulation(self, w: Writer) -> None:
        """The description as canonical JSON, and the simulation `~sim` builds from it: the node
        carries no .rdis file, and rdisc and MuJoCo are needed only when it simulates."""
        w.blank(2)
        w.comment(f"The description, as `rdisc build {self.source_name}` writes it: `~sim` checks it again for its body.")
        w.line("_ROS_CANONICAL = (")
        with w.indented():
            w.lines([quoted(line) for line in to_json(self.model).splitlines(keepends=True)])
        w.line(")")
        w.blank(2)
        with w.block("def _ros_simulation() -> Simulator:"):
            w.line('"""The MuJoCo simulation of the body on the wall clock (`rdisc sim --realtime`\'s), in place of')
            w.line("the device (`~sim`): rdisc rebuilds the Model from _ROS_CANONICAL. Only here are rdisc and")
            w.line('MuJoCo imported; without either the node says which, and ends with exit status 2."""')
            w.line("import importlib.util")
            w.blank()
            w.lines([
                "missing = [f\"~sim needs {name}, which {sys.executable} cannot import: {hint}\" for name, module, hint in (",
                "    (\"rdisc\", \"rdisc\", \"put rdisc on PYTHONPATH, or pip install 'rdisc[sim]'\"),",
                '    ("MuJoCo", "mujoco", "pip install mujoco"),',
                ") if importlib.util.find_spec(module) is None]",
                "if missing:",
                "    raise _ros_refuse(missing)",
                "try:  # an rdisc found whose own dependencies are not",
                *(f"    {line}{_IGNORE}" for line in ("from rdisc.compile import compile_text",
                                                      "from rdisc.diagnostics import Severity",
                                                      "from rdisc.sim import Simulation")),
                "except ImportError as err:",
                '    raise _ros_refuse([f"~sim: rdisc does not load here: {err}"]) from None',
                f"compilation = compile_text({quoted(_json_name(self.source_name))}, _ROS_CANONICAL)",
                "errors = [f\"{d.code} {d.message}\" for d in compilation.diagnostics.sorted() if d.severity == Severity.ERROR]",
                "if compilation.model is None or errors:",
                '    raise _ros_refuse([f"~sim: this rdisc does not take the description the node was made from: {error}"',
                '                       for error in errors or ["no model"]])',
                "try:",
                "    simulation: Simulator = Simulation(compilation.model, realtime=True)",
                "except (ImportError, ValueError) as err:  # a MuJoCo that does not load, or refuses the body",
                '    raise _ros_refuse([f"~sim: MuJoCo does not simulate the body: {err}"]) from None',
                "return simulation",
            ])

    def main(self, w: Writer) -> None:
        adapters = [a for _, a in self.inputs] + [a for _, a in self.outputs]
        named = [(package, message) for package, _, message in (a.ros.partition("/") for a in adapters if a.ros)]
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
                w.lines([line + _IGNORE for line in sorted([*imports, "import rospy"])])
            with w.block("except ImportError as err:"):
                w.line('raise _ros_refuse([f"ROS 1 does not load here: {err}"]) from None')
            w.blank()
            w.line("rospy.init_node(ROBOT)")
            if self.model.links:
                w.lines([
                    'if rospy.get_param("~publish_description", True):',
                    '    rospy.set_param("robot_description", _ROS_DESCRIPTION)',
                ])
            if self.measured:
                w.lines([
                    f'joint_states_rate = rospy.get_param("~joint_states_rate", {_rate(self.model)!r})',
                    "if isinstance(joint_states_rate, bool) or not isinstance(joint_states_rate, (int, float)) \\",
                    "        or not 0 < joint_states_rate <= 1000:",
                    '    raise _ros_refuse([f"~joint_states_rate is {joint_states_rate!r}: give Hz, above 0, at most 1000"])',
                ])
            if self.model.links:
                w.lines([
                    'sim = rospy.get_param("~sim", False)',
                    "if not isinstance(sim, bool):",
                    '    raise _ros_refuse([f"~sim is {sim!r}: give true (simulate the body) or false (the device)"])',
                    "simulation = _ros_simulation() if sim else None",
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
            w.line("# Each output's publisher, message, filling, and the frame id and child frame id it names: the")
            w.line("# body's link its data belongs to (an Odometry's pose is in odom, that link its child frame).")
            w.line("publishers: dict[str, tuple[Any, Any, Callable[[Any, dict[str, Any]], None], str, str]] = {")
            with w.indented():
                for o, adapter in self.outputs:
                    cls = self.message(adapter)
                    w.line(f"{quoted(o.name)}: (")
                    with w.indented():
                        w.lines([f"rospy.Publisher({quoted(o.name)}, {cls}, queue_size=10),", f"{cls},",
                                 f"_ros_fill_{_name(o.name)},",
                                 *(f"{quoted(frame)}," for frame in ros.header_frames(self.model, o))])
                    w.line("),")
            w.line("}")
            w.blank()
            with w.block("def on_output(message: OutputMessage) -> None:"):
                w.line('publisher, message_type, fill, frame_id, child_frame_id = publishers[message["name"]]')
                w.line("msg = message_type()")
                w.line('fill(msg, message["contents"])')
                w.line("_ros_header(msg, message.read_ns, frame_id, child_frame_id)")
                w.line("publisher.publish(msg)")
            w.blank()
            with w.block("def on_error(error: BaseException) -> None:"):
                w.line('rospy.logerr("%s: %s", type(error).__name__, error)')
                w.line('errors.publish(std_msgs_msg.String(data=f"{type(error).__name__}: {error}"))')
            w.blank()
            with w.block("def on_io(direction: str, connection: str, data: bytes) -> None:"):
                w.line('shown = data.decode("ascii") if direction == "lines" else data.hex(" ")')
                w.line('arrow = {"write": ">", "read": "<"}.get(direction, direction)')
                w.line('rospy.loginfo("%s %s %s", connection, arrow, shown)')
            w.blank()
            if self.model.settings:  # each given as the private parameter of its name, `_BAUD:=1000000`
                w.lines([
                    'given = (p.name for p in _DEVICE.settings if rospy.has_param(f"~{p.name}"))',
                    'settings = {name: rospy.get_param(f"~{name}") for name in given}',
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
                w.line("rospy.Timer(rospy.Duration(1.0 / joint_states_rate), publish_joint_states)")
                w.blank()
            with w.block("def subscriber(name: str, read: Callable[[Any], dict[str, Any]]) -> Callable[[Any], None]:"):
                with w.block("def received(msg: Any) -> None:"):
                    with w.block("try:"):
                        w.line("robot.call_input(name, **read(msg))")
                    with w.block("except Exception as err:  # noqa: BLE001 - reported, and the node keeps serving"):
                        w.line("on_error(err)")
                w.line("return received")
            w.blank()
            if self.commanded:
                w.line('rospy.Subscriber("joint_command", sensor_msgs_msg.JointState,')
                w.line("                 lambda msg: _ros_joint_command(robot, msg, on_error), queue_size=10)")
            for i, adapter in self.inputs:
                w.line(f"rospy.Subscriber({quoted(i.name)}, {self.message(adapter)},")
                w.line(f"                 subscriber({quoted(i.name)}, _ros_read_{_name(i.name)}), queue_size=10)")
            w.lines([
                "rospy.spin()",
                "# Later signals are ignored to the exit; SIG_IGN set here, outside a handler, takes a",
                "# signal already pending first.",
                "signal.signal(signal.SIGINT, signal.SIG_IGN)",
                "signal.signal(signal.SIGTERM, signal.SIG_IGN)",
                "return 0",
            ])


def _measured(model: m.Model) -> list[tuple[str, dict[m.Quantity, m.Binding]]]:
    """Each joint a transmission measures, in the body's order, with the first measure of each quantity."""
    measures: dict[str, dict[m.Quantity, m.Binding]] = {}
    for transmission in model.transmissions.values():
        for binding in transmission.measures:
            measures.setdefault(transmission.joint, {}).setdefault(binding.quantity, binding)
    return [(joint, measures[joint]) for joint in model.joints if joint in measures]


_Commanded = tuple[str, str, list[tuple[m.Parameter, dict[int | None, int]]], list[tuple[str, m.Binding]]]


def _commanded(model: m.Model) -> list[_Commanded]:
    """Each primitive or interface whose parameters transmissions bind, every element of an array,
    but for those with defaults: its kind, name, each parameter with the place (into the joints) of
    each of its elements, and the joints bound at those places with their first binding there."""
    places: dict[tuple[bool, str], dict[tuple[str, int | None], tuple[str, m.Binding]]] = {}
    for transmission in model.transmissions.values():
        for binding in transmission.commands:
            assert binding.parameter is not None
            at = places.setdefault((binding.interface, binding.target), {})
            at.setdefault((binding.parameter, binding.index), (transmission.joint, binding))
    found: list[_Commanded] = []
    for (interface, target), at in places.items():
        params = (model.interfaces[target] if interface else model.primitives[target]).params
        bound: list[tuple[m.Parameter, dict[int | None, int]]] = []
        joints: list[tuple[str, m.Binding]] = []
        for param in params:
            indexes: list[int | None] = (list(range(param.type.size)) if isinstance(param.type, m.Array)
                                         else [None])
            given = {i: at[(param.name, i)] for i in indexes if (param.name, i) in at}
            if len(given) < len(indexes) and (given or param.default is None):
                break
            bound.append((param, {i: len(joints) + k for k, i in enumerate(given)}))
            joints.extend(given.values())
        else:
            found.append(("interface" if interface else "primitive", target, bound, joints))
    return found


def _rate(model: m.Model) -> float:
    """The default of `~joint_states_rate`: the fastest schedule that runs periodic interfaces
    (the state changes no faster), else joint_state_publisher's 10 Hz."""
    owners = {model.owner(i) for i in model.interfaces.values() if i.periodic}
    rates = [c.frequency_hz for name, c in model.connections.items() if name in owners and c.frequency_hz > 0]
    return float(max(rates, default=10.0))


def _json_name(source_name: str) -> str:
    """The name the embedded JSON is checked under: the description's, ending .json for the JSON importer."""
    return str(PurePath(source_name).with_suffix(".json").name)


def _name(name: str) -> str:
    if not name.isidentifier():
        raise ValueError(f"{name!r} is not a checked name")
    return name


def _read(root: str, path: str) -> str:
    """Python reading a checked field path from the message `root`."""
    assert ros.path_problem(path) is None, path
    steps, conversion = ros.steps(path)
    text = root
    for field, index in steps:
        text = f"{text}.{field}" if index is None else f"_ros_item({text}.{field}, {index})"
    return f"_ros_yaw({text})" if conversion == "yaw" else text


def _write(root: str, path: str, value: str) -> str:
    """A Python statement putting `value` at a checked field path of the message `root`."""
    assert ros.path_problem(path) is None, path
    steps, conversion = ros.steps(path)
    *parents, (field, index) = steps
    holder = root
    for name, item in parents:
        holder = f"{holder}.{name}" if item is None else f"{holder}.{name}[{item}]"
    if conversion == "yaw":
        target = f"{holder}.{field}" if index is None else f"{holder}.{field}[{index}]"
        return f"_ros_set_yaw({target}, {value})"
    if index is None:
        return f"{holder}.{field} = {value}"
    return f"{holder}.{field} = _ros_with({holder}.{field}, {index}, {value})"
