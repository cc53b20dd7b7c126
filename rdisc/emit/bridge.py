"""The bridge between a description's domain inputs and outputs and a ROS graph, written once
for both ROS versions: `rdisc emit-ros` (ROS 1, rospy) and `rdisc emit-ros2` (ROS 2, over DDS)
are this bridge with a transport each.

A node is the generated Python driver (`rdisc.emit.python`) with the bridge in place of its
command line: one subscription per domain input and one publication per domain output, named
after them, the adapters' messages and field paths taken from their mapping to the transport's
framework (`framework`: a column of stdlib/frameworks.txt, which makes them of the adapter's `ros`
annotations; the Model's `Adapter.frameworks`). Those are checked names (rdisc.semantics.ros), resolved here: the node
reads and writes each field by name in its own code, and nothing it does at run time looks a
name up from text. The semantics are the driver's: one implementation, not a third copy.

What the bridge writes for both: each input's reading of its message and each output's filling
of one (`_ros_read_NAME`, `_ros_fill_NAME`), the stamping of outputs whose message has a header
(`on_output`, the one place: the time the data was read, and the frame), and for a body its
URDF (at the node's settings where the body reads some: rdisc builds it again then), its measured joints' conversion to a JointState, its joint commands through the
transmissions and the simulation of `sim`. A transport (a subclass) writes the program: how it
is started, its parameters, its publishers and subscriptions, and how it stops.
"""

from __future__ import annotations

from pathlib import PurePath

from rdisc.emit.canonical import to_json
from rdisc.emit.python_expr import Compiler, literal, quoted
from rdisc.emit.urdf import to_urdf
from rdisc.emit.writer import Writer
from rdisc.lowering import messages
from rdisc.semantics import model as m
from rdisc.semantics import ros
from rdisc.semantics.covariance import carried, covariances
from rdisc.semantics.model import Type

IGNORE = "  # type: ignore[import-not-found, import-untyped, unused-ignore]"  # Debian's ROS (and rdisc) have no types

MAIN = 'if __name__ == "__main__":\n    sys.exit(main())\n'

HELPERS = '''\
def _ros_refuse(problems: list[str]) -> SystemExit:
    """Say why the node cannot start, on stderr: raise what it gives to end with exit status 2."""
    prog = os.path.basename(sys.argv[0])
    print("\\n".join(f"{prog}: {problem}" for problem in problems), file=sys.stderr)
    return SystemExit(2)


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
    nothing is sent for that target. A message whose names repeat, or whose positions, velocities
    or efforts are not one a name (or none), is reported and nothing of it is sent."""
    given: dict[str, int] = {}
    for at, name in enumerate(msg.name):
        if name in given:  # (the first repeat: a message of many names costs no more)
            report(RdisValueError(f"joint_command: {_ros_names([name])} is named twice"))
            return
        given[name] = at
    values = (msg.position, msg.velocity, msg.effort)
    for quantity, listed in zip(_ROS_QUANTITIES, values):
        if len(listed) and len(listed) != len(given):
            report(RdisValueError(f"joint_command: {len(listed)} {quantity} values for {len(given)} joint names "
                                  "(one for each, or none)"))
            return
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
        report(RdisValueError(f"joint_command: no command takes {_ros_names(unknown)}"))


def _ros_names(names: list[str]) -> str:
    """Joint names for a message: the first five, each cut at 40 characters, and how many more."""
    shown = ", ".join(name if len(name) <= 40 else f"{name[:37]}..." for name in names[:5])
    return shown if len(names) <= 5 else f"{shown} and {len(names) - 5} more"'''


class Bridge:
    """The node's conversions, body and main, for the inputs and outputs whose adapter names a
    message; a transport writes `main`."""

    private = "~"
    """How a parameter of the node is written in what it says: ROS 1's `~sim`, ROS 2's `sim`."""

    framework = "ros1"
    """The column of the table of frameworks the node speaks: its adapters' messages and paths."""

    def __init__(self, model: m.Model, source_name: str) -> None:
        self.model = model
        self.source_name = source_name
        self.exprs = Compiler()
        self.measured = _measured(model)
        self.commanded = _commanded(model)
        self.reads = body_settings(model)
        self.inputs = [(i, model.adapters[i.adapter]) for i in model.inputs.values()
                       if model.adapters[i.adapter].mapping(self.framework) is not None]
        self.outputs = [(o, model.adapters[o.adapter]) for o in model.outputs.values()
                        if model.adapters[o.adapter].mapping(self.framework) is not None]

    def mapping(self, adapter: m.Adapter) -> m.FrameworkMapping:
        """What an adapter of the node's inputs or outputs is in its framework."""
        found = adapter.mapping(self.framework)
        assert found is not None, adapter.name
        return found

    def type(self, adapter: m.Adapter) -> str:
        """An adapter's message, `pkg/Type` (as the table of message definitions names it)."""
        package, message = ros.message_parts(self.mapping(adapter).type)
        return f"{package}/{message}"

    def paths(self, adapter: m.Adapter) -> list[tuple[m.AdapterField, str]]:
        """Each field of an adapter with its path in the node's message (else its own name)."""
        return [(f, path or f.name) for f, path in zip(adapter.fields, self.mapping(adapter).paths)]

    def message(self, adapter: m.Adapter) -> str:
        """The message class, as ros_main names it: `geometry_msgs_msg.Twist`."""
        package, message = ros.message_parts(self.mapping(adapter).type)
        assert ros.message_problem(f"{package}/{message}") is None
        return f"{package}_msg.{message}"

    def node(self, driver: str, helpers: str) -> str:
        """The node: `driver` (the generated driver) without its main, then `helpers` (the
        transport's, then the bridge's), then what `write` writes, with `ros_main` as the program."""
        assert driver.endswith(MAIN)
        w = Writer()
        self.write(w)
        return (driver[: -len(MAIN)] + helpers + "\n\n\n" + w.text().lstrip("\n") + "\n\n"
                + 'if __name__ == "__main__":\n'
                + '    sys.exit(command_line(ros_main))  # SIGINT and SIGTERM handled from here: 130 or 143, no traceback\n')

    def main(self, w: Writer) -> None:
        """`ros_main`, the node's program: the transport's."""
        raise NotImplementedError

    def write(self, w: Writer) -> None:
        for i, adapter in self.inputs:
            w.blank(2)
            with w.block(f"def _ros_read_{name(i.name)}(msg: Any) -> dict[str, Any]:"):
                w.line(f'"""The fields of input {i.name} from a {self.type(adapter)}."""')
                items = [f"{quoted(f.name)}: {_read('msg', path)}" for f, path in self.paths(adapter)]
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
            with w.block(f"def _ros_fill_{name(o.name)}(msg: Any, contents: dict[str, Any]) -> None:"):
                w.line(f'"""A {self.type(adapter)} filled with the fields of output {o.name}."""')
                for f, path in self.paths(adapter):
                    w.line(_write("msg", path, f"contents[{quoted(f.name)}]"))
                for path, rows in covariances(self.paths(adapter), carried(self.model, o)):  # the noise, row by row
                    w.line(f"msg.{path} = [")
                    with w.indented():
                        w.lines([", ".join(literal(value, Type.FLOAT).text for value in row) + "," for row in rows])
                    w.line("]")
        if self.model.links:
            w.blank(2)
            self.body(w)
        w.blank(2)
        self.main(w)

    def stamped(self, adapter: m.Adapter) -> bool:
        """Whether an adapter's message has a `std_msgs/Header header` to stamp (as the table of
        messages defines it; a message not in it is published as filled)."""
        return self.type(adapter) in messages.DEFINITIONS and any(
            f.name == "header" and f.type == "std_msgs/Header" for f in messages.fields(self.type(adapter)))

    def publishers(self, w: Writer, publisher: str) -> None:
        """`publishers`: each output's publisher (`publisher` formatted with `topic` and `message`),
        message class, filling, and the frame of a stamped message (None: no header)."""
        w.line("# Each output's publisher, message, filling, and for a stamped message the frame id and child")
        w.line("# frame id it names: the body's link its data belongs to (an Odometry's pose is in odom, that")
        w.line("# link its child frame); None: no header.")
        w.line("publishers: dict[str, tuple[Any, Any, Callable[[Any, dict[str, Any]], None], tuple[str, str] | None]] = {")
        with w.indented():
            for o, adapter in self.outputs:
                cls = self.message(adapter)
                w.line(f"{quoted(o.name)}: (")
                with w.indented():
                    w.lines([publisher.format(topic=quoted(o.name), message=cls) + ",", f"{cls},",
                             f"_ros_fill_{name(o.name)},",
                             f"{_frames(ros.header_frames(self.model, o)) if self.stamped(adapter) else None},"])
                w.line("),")
        w.line("}")

    def subscriber(self, w: Writer) -> None:
        """`subscriber(name, read)`: an input's message callback for either ROS, which calls the
        input with the message's values and reports what fails (the node keeps serving). The values
        pass the engine's reader of values from outside (`call_values`), as a console's or a
        recording's do: a NaN or infinite number, an int past 64 bits, an array of the wrong length
        is refused naming its field, where a Twist of inf drove the robot at full speed."""
        with w.block("def subscriber(name: str, read: Callable[[Any], dict[str, Any]]) -> Callable[[Any], None]:"):
            with w.block("def received(msg: Any) -> None:"):
                with w.block("try:"):
                    w.line('robot.call_input(name, **call_values(_DEVICE, "input", name, read(msg)))')
                with w.block("except Exception as err:  # noqa: BLE001 - reported, and the node keeps serving"):
                    w.line("on_error(err)")
            w.line("return received")

    def on_output(self, w: Writer, now: str, publish: str) -> None:
        """`on_output`: an output as its message, published (`publish` formatted with `publisher`
        and `msg`); a message with a header is stamped here, and only here, for both ROS versions:
        the time its data was read (`OutputMessage.read_ns`, not the time of publishing) as `now`
        makes it of nanoseconds, and its frames."""
        with w.block("def on_output(message: OutputMessage) -> None:"):
            w.line('publisher, message_type, fill, frames = publishers[message["name"]]')
            w.line("msg = message_type()")
            w.line('fill(msg, message["contents"])')
            with w.block("if frames is not None:"):
                w.line(f"msg.header.stamp = {now.format(nanoseconds='message.read_ns')}")
                w.line("msg.header.frame_id, child_frame_id = frames")
                with w.block("if child_frame_id:"):
                    w.line("msg.child_frame_id = child_frame_id")
            w.line(publish.format(publisher="publisher", msg="msg"))

    def body(self, w: Writer) -> None:
        """The URDF as a constant, and the measured joints' names and their conversion from the state."""
        w.comment(f"The body, as `rdisc emit-urdf {self.source_name}` writes it: the robot_description parameter.")
        w.line("_ROS_DESCRIPTION = (")
        with w.indented():
            w.lines([quoted(line) for line in to_urdf(self.model, self.source_name).splitlines(keepends=True)])
        w.line(")")
        self.simulation(w)
        if self.reads:
            w.blank(2)
            self.described(w)
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

    def settings(self, given: str) -> str:
        """The settings given to the node, for its body: `given` (a Python expression), or none."""
        return given if self.model.settings else ""

    def description(self, given: str) -> str:
        """What the node publishes as robot_description, given the settings `given` (a Python expression)."""
        return f"_ros_description({given})" if self.reads else "_ROS_DESCRIPTION"

    def described(self, w: Writer) -> None:
        """For a body that reads settings: the URDF at the values the node is given, as `rdisc emit-urdf
        --set` writes it, so that robot_description is the body the device drives."""
        publish = f"{self.private}publish_description"
        w.line(f"_ROS_BODY_SETTINGS = {literal(tuple(self.reads), m.Array(Type.STRING, len(self.reads))).text}")
        w.blank(2)
        with w.block("def _ros_description(given: Mapping[str, Any]) -> str:"):
            w.line('"""The URDF of the body at the settings given: _ROS_DESCRIPTION while those it reads keep their')
            w.line("defaults, else the body rdisc builds again from _ROS_CANONICAL at their values and checks")
            w.line(f"(`rdisc emit-urdf {self.source_name} --set NAME=VALUE`'s). Only then is rdisc imported; without")
            w.line('it, or where the body refuses a value, the node says why and publishes no other body."""')
            w.lines([
                "settings = _ros_settings(given)",
                "changed = [name for name in _ROS_BODY_SETTINGS if settings[name] != _DEVICE.state[name]]",
                "if not changed:",
                "    return _ROS_DESCRIPTION",
                'at = ", ".join(f"{name} = {settings[name]!r}" for name in changed)',
                "try:",
                *(f"    {line}{IGNORE}" for line in ("from rdisc.compile import compile_text",
                                                  "from rdisc.diagnostics import Severity",
                                                  "from rdisc.emit.urdf import to_urdf")),
                "except ImportError as err:",
                '    raise _ros_refuse([(f"robot_description at {at} is the body built again by rdisc, which "',
                '                        f"{sys.executable} cannot import ({err}): put rdisc on PYTHONPATH, "',
                f'                        "or give {publish} false")]) from None',
                f"compilation = compile_text({quoted(_json_name(self.source_name))}, _ROS_CANONICAL, settings=settings)",
                "errors = [f\"{d.code} {d.message}\" for d in compilation.diagnostics.sorted() if d.severity == Severity.ERROR]",
                "if compilation.model is None or errors:",
                '    raise _ros_refuse([f"robot_description at {at}: {error}" for error in errors or ["no model"]])',
                f"return str(to_urdf(compilation.model, {quoted(self.source_name)}))",
            ])

    def simulation(self, w: Writer) -> None:
        """The description as canonical JSON, and the simulation `~sim` (ROS 2: `sim`) builds from
        it: the node carries no .rdis file, and rdisc and MuJoCo are needed only when it simulates."""
        sim = f"{self.private}sim"
        w.blank(2)
        w.comment(f"The description, as `rdisc build {self.source_name}` writes it: `{sim}` checks it again for its body.")
        w.line("_ROS_CANONICAL = (")
        with w.indented():
            w.lines([quoted(line) for line in to_json(self.model).splitlines(keepends=True)])
        w.line(")")
        w.blank(2)
        with w.block("def _ros_settings(given: Mapping[str, Any]) -> dict[str, Any]:"):
            w.line('"""The settings given to the node, each its type and in its range, the others their defaults:')
            w.line('a value that does not fit is said, and the node ends with exit status 2."""')
            w.lines([
                "try:",
                "    return bind_settings(_DEVICE, given)",
                "except (TypeError, ValueError) as err:",
                "    raise _ros_refuse([str(err)]) from None",
            ])
        w.blank(2)
        with w.block("def _ros_simulation(given: Mapping[str, Any] | None = None) -> Simulator:"):
            w.line('"""The MuJoCo simulation of the body on the wall clock (`rdisc sim --realtime`\'s), in place of')
            w.line(f"the device (`{sim}`): rdisc rebuilds the Model from _ROS_CANONICAL at the settings given. Only")
            w.line('here are rdisc and MuJoCo imported; without either the node says which, and ends with exit status 2."""')
            w.line("import importlib.util")
            w.blank()
            w.lines([line.replace("~sim", sim) for line in [
                "settings = _ros_settings(given or {})",
                "missing = [f\"~sim needs {name}, which {sys.executable} cannot import: {hint}\" for name, module, hint in (",
                "    (\"rdisc\", \"rdisc\", \"put rdisc on PYTHONPATH, or pip install 'rdisc[sim]'\"),",
                '    ("MuJoCo", "mujoco", "pip install mujoco"),',
                ") if importlib.util.find_spec(module) is None]",
                "if missing:",
                "    raise _ros_refuse(missing)",
                "try:  # an rdisc found whose own dependencies are not",
                *(f"    {line}{IGNORE}" for line in ("from rdisc.compile import compile_text",
                                                      "from rdisc.diagnostics import Severity",
                                                      "from rdisc.sim import Simulation")),
                "except ImportError as err:",
                '    raise _ros_refuse([f"~sim: rdisc does not load here: {err}"]) from None',
                f"compilation = compile_text({quoted(_json_name(self.source_name))}, _ROS_CANONICAL, settings=settings)",
                "errors = [f\"{d.code} {d.message}\" for d in compilation.diagnostics.sorted() if d.severity == Severity.ERROR]",
                "if compilation.model is None or errors:",
                '    raise _ros_refuse([f"~sim: this rdisc does not take the description the node was made from: {error}"',
                '                       for error in errors or ["no model"]])',
                "try:",
                "    simulation: Simulator = Simulation(compilation.model, realtime=True)",
                "except (ImportError, ValueError) as err:  # a MuJoCo that does not load, or refuses the body",
                '    raise _ros_refuse([f"~sim: MuJoCo does not simulate the body: {err}"]) from None',
                "return simulation",
            ]])

def body_settings(model: m.Model) -> list[str]:
    """The settings the body reads (its elements' `expressions`), in the order they are declared."""
    elements: list[m.Shape | m.Inertial | m.Spawn | m.Joint | m.Binding | m.Actuator] = [
        *model.joints.values(), *model.actuators.values()]
    for link in model.links.values():
        elements += [*link.visuals, *link.collisions, *(e for e in (link.inertial, link.spawn) if e is not None)]
    for transmission in model.transmissions.values():
        elements += [*transmission.commands, *transmission.measures]
    read = {v.name for e in elements for _, expr in e.expressions for v in m.variables(expr)}
    return [name for name in model.settings if name in read]


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


def rate(model: m.Model) -> float:
    """The default of `~joint_states_rate`: the fastest schedule that runs periodic interfaces
    (the state changes no faster), else joint_state_publisher's 10 Hz."""
    rates = [model.connections[owner].rate_of(i) for i in model.interfaces.values()
             if i.periodic and (owner := model.owner(i)) in model.connections]
    rates = [r for r in rates if r > 0]
    return float(max(rates, default=10.0))


def _json_name(source_name: str) -> str:
    """The name the embedded JSON is checked under: the description's, ending .json for the JSON importer."""
    return str(PurePath(source_name).with_suffix(".json").name)


def name(name: str) -> str:
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


def _frames(frames: tuple[str, str]) -> str:
    """A stamped output's (frame id, child frame id) as source."""
    return f"({quoted(frames[0])}, {quoted(frames[1])})"
