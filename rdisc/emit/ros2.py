"""`rdisc emit-ros2`: a ROS 2 node for a description, needing no ROS 2 installation: the bridge
(rdisc.emit.bridge) with DDS as its transport, spoken as ROS 2 speaks it through Cyclone DDS's
Python binding (`cyclonedds` on PyPI, the node's one dependency; rdisc never imports it).

The same inputs, outputs, errors, settings and shutdown as the ROS 1 node, under the same topic
names; parameters from `--ros-args -p port:=/dev/ttyUSB0 -p NAME:=VALUE`, read by the driver's
own command line (`--port`, `--set`, `--timeout`, `--trace`), and the run is the driver's
`run_command` until a signal, so the terminate hooks' commands are the last written. Messages are
the ROS 2 distribution's (`--distro`), their DDS types made from rdisc's one table of message
definitions (rdisc/lowering/messages.py), and only messages in it can be spoken.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from rdisc.emit import bridge
from rdisc.emit.bridge import Bridge
from rdisc.emit.python import to_python
from rdisc.emit.python_expr import quoted
from rdisc.emit.python_names import class_name
from rdisc.emit.ros2_helpers import HELPERS
from rdisc.emit.writer import Writer
from rdisc.lowering import messages
from rdisc.semantics import model as m
from rdisc.semantics import ros
from rdisc.source import SourceFile

# A ROS 2 primitive's Cyclone DDS type, and the default of a member of it.
_PRIMITIVES = {
    "bool": ("bool", "False"), "byte": ("byte", "0"), "char": ("uint8", "0"), "float32": ("float32", "0.0"),
    "float64": ("float64", "0.0"), "int8": ("int8", "0"), "uint8": ("uint8", "0"), "int16": ("int16", "0"),
    "uint16": ("uint16", "0"), "int32": ("int32", "0"), "uint32": ("uint32", "0"), "int64": ("int64", "0"),
    "uint64": ("uint64", "0"), "string": ("str", '""'),
}
_DDS_TYPES = frozenset({kind for kind, _ in _PRIMITIVES.values()} - {"bool", "str"}
                       | {"array", "sequence", "bounded_str"})


class Ros2Error(ValueError):
    """A description the ROS 2 node cannot speak: a message, or a field of one, rdisc has no ROS 2 definition of."""


def to_ros2(model: m.Model, source_name: str, *, distro: str = messages.DEFAULT_DISTRO,
            sources: Mapping[str, SourceFile] | None = None) -> str:
    """The ROS 2 node for `model`, speaking ROS 2 `distro`'s messages; Ros2Error says what it cannot speak."""
    node = _Ros2(model, source_name, distro)
    problems = node.problems()
    if problems:
        raise Ros2Error("; ".join(problems))
    driver = to_python(model, source_name, sources=sources)
    end = driver.index('\n"""\n')  # the end of its docstring: what the node needs, and how it runs
    driver = driver[:end] + _header(model, source_name, distro) + driver[end:]
    return node.node(driver, HELPERS + "\n\n\n" + bridge.HELPERS)


def _header(model: m.Model, source_name: str, distro: str) -> str:
    """What the node's docstring says past the driver's: the node's program is not the driver's."""
    return "\n".join([
        "",
        "",
        f"Written by `rdisc emit-ros2 --distro {distro}` from {source_name}, this file runs as a ROS 2 node",
        f"(ROS 2 {distro.capitalize()}'s messages), not as the driver's program above. It needs no ROS 2",
        "installation, only Cyclone DDS's Python binding (`pip install cyclonedds`) and pyserial:",
        "",
        f"    ROS_DOMAIN_ID=0 python {model.robot.name}_node.py --ros-args -p port:=/dev/ttyUSB0",
        "",
        "with `-p NAME:=VALUE` for its port, timeout, trace and settings, and `-r FROM:=TO` remappings.",
    ])


class _Ros2(Bridge):
    """The bridge over DDS."""

    private = ""
    framework = "ros2"

    def __init__(self, model: m.Model, source_name: str, distro: str) -> None:
        super().__init__(model, source_name)
        self.distro = distro
        self.table = messages.definitions(distro)
        adapters = [a for _, a in self.inputs] + [a for _, a in self.outputs]
        named = [self.type(a) for a in adapters]
        if self.measured or self.commanded:
            named.append("sensor_msgs/JointState")
        base = ["builtin_interfaces/Time", "std_msgs/String", "rmw_dds_common/ParticipantEntitiesInfo"]  # the node's
        self.speaks = list(dict.fromkeys([*named, *base]))

    def problems(self) -> list[str]:
        """What the node cannot speak: each message not in the table, each field path not in its message."""
        found = []
        for adapter in dict.fromkeys(a for _, a in self.inputs + self.outputs):
            if self.type(adapter) not in self.table:
                known = ", ".join(sorted(n for n in self.table if not n.startswith("rmw_dds_common/")))
                found.append(f"adapter {adapter.name}: rdisc has no ROS 2 definition of {self.type(adapter)} "
                             f"(it has {known})")
                continue
            for f, path in self.paths(adapter):
                problem = _member_problem(self.type(adapter), path, self.distro)
                if problem is not None:
                    found.append(f"adapter {adapter.name}, field {f.name}: {problem}")
        return found

    def types(self, w: Writer) -> None:
        """`_ros2_messages`: each message the node speaks, and each one they use, as a DDS type made
        from the table, by package."""
        order = messages.used(self.speaks, self.distro)
        names = _class_names(order)
        structs = {name: [self._member(f, names) for f in messages.fields(name, self.distro)] for name in order}
        words = {word for members in structs.values() for member in members
                 for word in re.findall(r"[a-z_0-9]+", member[1])}
        kinds = sorted(words & _DDS_TYPES, key=lambda kind: [int(p) if p.isdigit() else p for p in re.split(r"(\d+)", kind)])
        with w.block("def _ros2_messages() -> Any:"):
            w.line(f'"""The ROS 2 messages this node speaks, as ROS 2 {self.distro.capitalize()} defines them, each a')
            w.line('Cyclone DDS type; by package (`messages.sensor_msgs.Range`)."""')
            w.line("from types import SimpleNamespace")
            w.blank()
            imports = f"from cyclonedds.idl.types import {', '.join(kinds)}"
            w.lines([imports] if len(imports) <= 84 else  # isort's width, 88, less the indent
                    ["from cyclonedds.idl.types import (", *(f"    {kind}," for kind in kinds), ")"])
            w.blank()
            for name, members in structs.items():
                texts = [f"({quoted(member)}, {kind}, {default})" for member, kind, default in members]
                head = f"{names[name]} = _ros2_struct({quoted(name)}, ("
                flat = head + ", ".join(texts) + ("," if len(texts) == 1 else "") + "))"
                if len(flat) <= w.width():
                    w.line(flat)
                else:
                    w.line(head)
                    with w.indented():
                        w.lines([f"{text}," for text in texts])
                    w.line("))")
            w.line("return SimpleNamespace(")
            with w.indented():
                for package in dict.fromkeys(n.split("/")[0] for n in order):
                    inside = ", ".join(f"{n.split('/')[1]}={names[n]}" for n in order if n.split("/")[0] == package)
                    w.line(f"{package}=SimpleNamespace({inside}),")
            w.line(")")

    def write(self, w: Writer) -> None:
        w.blank(2)
        self.types(w)
        super().write(w)

    def _member(self, f: messages.Field, names: dict[str, str]) -> tuple[str, str, str]:
        """One member of `_ros2_struct`: its name, DDS type and default, as code."""
        if f.type in _PRIMITIVES:
            kind, default = _PRIMITIVES[f.type]
            if f.bound is not None:
                kind = f"bounded_str({f.bound})"
            if f.default is not None:
                default = repr(float(f.default)) if kind.startswith("float") else repr(int(f.default))
        else:
            kind, default = names[f.type], names[f.type]
        if f.size == 0:
            kind, default = f"sequence({kind})", "list"
        elif f.size is not None:
            kind, default = f"array({kind}, {f.size})", f"lambda: [{default}] * {f.size}"
        return f.name, kind, default

    def main(self, w: Writer) -> None:
        packages = sorted({n.split("/")[0] for n in self.speaks} - {"rmw_dds_common"})  # the node's own
        with w.block("def ros_main() -> int:"):
            w.line('"""Run the robot as a ROS 2 node until SIGINT or SIGTERM: the driver\'s run with `--duration inf`,')
            w.line("so the terminate hooks run then and their commands are the last written. Exit status as the")
            w.line('driver\'s: 0, 1 the device failed, 2 a usage error, 130 after SIGINT, 143 after SIGTERM."""')
            w.line("prog = os.path.basename(sys.argv[0])")
            with w.block("try:"):
                own = "parameters" if self.measured or self.model.links else "_"
                w.line(f"words, {own}, remaps = _ros2_command_line(sys.argv[1:])")
                if self.measured:
                    w.line(f'joint_states_rate = float(parameters.get("joint_states_rate", {bridge.rate(self.model)!r}))')
                if self.model.links:
                    w.line('publish_description = _ros2_flag("publish_description", parameters.get("publish_description", "true"))')
                    w.line('sim = _ros2_flag("sim", parameters.get("sim", "false"))')
            with w.block("except ValueError as err:"):
                w.line("raise _ros_refuse([str(err)]) from None")
            if self.measured:
                w.lines([
                    "if not 0 < joint_states_rate <= 1000:",
                    '    raise _ros_refuse([f"joint_states_rate is {joint_states_rate!r}: give Hz, above 0, at most 1000"])',
                ])
            w.line(f'parser = argparse.ArgumentParser(prog=prog, description="{self.model.robot.name} as a ROS 2 node")')
            w.line("add_arguments(parser, _DEVICE)")
            w.line('args = parser.parse_args([*words, "--duration", "inf"])')
            if self.model.links and self.model.settings:
                with w.block("try:  # the settings as `rdisc run --set` reads them, for the body they move"):
                    w.line("given = parse_settings(args.set, _DEVICE)")
                with w.block("except ValueError as err:"):
                    w.line("raise _ros_refuse([str(err)]) from None")
            if self.model.links:
                w.line(f"simulation = _ros_simulation({self.settings('given')}) if sim else None")
            if self.reads:
                w.line(f"description = {self.description('given')} if publish_description else _ROS_DESCRIPTION")
            w.line("_ros2_check_installed()")
            w.line("messages = _ros2_messages()")
            w.lines([f"{package}_msg = messages.{package}" for package in packages])
            w.blank()
            w.line("node = _Ros2Node(ROBOT, remaps, messages)")
            self.publishers(w, "node.publisher({topic}, {message}, node.sensor_data)")
            w.blank()
            self.on_output(w, "_ros2_time({nanoseconds}, builtin_interfaces_msg.Time)", "{publisher}.write({msg})")
            w.blank()
            with w.block("def on_error(error: BaseException) -> None:"):
                w.line('node.errors.write(std_msgs_msg.String(data=f"{type(error).__name__}: {error}"))')
            w.blank()
            w.line(f"robot = {class_name(self.model.robot.name)}(timeout=args.timeout)")
            w.line("robot.on_output(on_output)")
            w.line("robot.on_error(on_error)")
            if self.model.links:
                with w.block("if publish_description:"):
                    w.line('node.publisher("robot_description", std_msgs_msg.String, node.latched).write(')
                    w.line(f"    std_msgs_msg.String(data={'description' if self.reads else '_ROS_DESCRIPTION'}))")
            if self.measured:
                w.line('joint_states = node.publisher("joint_states", sensor_msgs_msg.JointState, node.default)')
                w.line("stopped = threading.Event()")
                w.blank()
                with w.block("def publish_joint_states() -> None:"):
                    w.line('"""The measured joints as the robot\'s state snapshot has them, stamped now, at the rate."""')
                    with w.block("while not stopped.wait(1.0 / joint_states_rate):"):
                        with w.block("try:"):
                            w.lines([
                                "position, velocity, effort = _ros_joint_states(robot.state)",
                                "joint_states.write(sensor_msgs_msg.JointState(",
                                "    header=std_msgs_msg.Header(stamp=_ros2_time(time.time_ns(), builtin_interfaces_msg.Time)),",
                                "    name=list(_ROS_JOINTS), position=position, velocity=velocity, effort=effort))",
                            ])
                        w.line("except Exception as err:  # noqa: BLE001 - reported, and the node keeps publishing")
                        w.line("    on_error(err)")
            w.blank()
            self.subscriber(w)
            w.blank()
            with w.block("def opened() -> None:"):
                w.line('"""The subscriptions, once the startup hooks are done."""')
                if self.commanded:
                    w.line('node.subscription("joint_command", sensor_msgs_msg.JointState,')
                    w.line("                  lambda msg: _ros_joint_command(robot, msg, on_error))")
                for i, adapter in self.inputs:
                    w.line(f"node.subscription({quoted(i.name)}, {self.message(adapter)},")
                    w.line(f"                  subscriber({quoted(i.name)}, _ros_read_{bridge.name(i.name)}))")
                if self.measured:
                    w.line('publisher = threading.Thread(target=publish_joint_states, name="joint_states", daemon=True)')
                    w.line("without_signals(publisher.start)  # signals are the main thread's")
                if not (self.commanded or self.inputs or self.measured):
                    w.line("return")
            w.blank()
            with w.block("try:"):
                w.line(f"return run_command(args, robot, prog{', sim=simulation' if self.model.links else ''}, "
                       "opened=opened)")
            with w.block("finally:"):
                if self.measured:
                    w.line("stopped.set()")
                w.line("node.close()")


def _class_names(order: list[str]) -> dict[str, str]:
    """Each message's name in `_ros2_messages`: its own, or with its package where two share one."""
    counts: dict[str, int] = {}
    for name in order:
        counts[name.split("/")[1]] = counts.get(name.split("/")[1], 0) + 1
    return {name: name.split("/")[1] if counts[name.split("/")[1]] == 1 else name.replace("/", "_") for name in order}


def _member_problem(message: str, path: str, distro: str) -> str | None:
    """What is wrong with a checked field path in a message of the table, or None: each step a
    member (a list item of a list), ending at a value or a list of values (`:yaw` at a Quaternion)."""
    steps, conversion = ros.steps(path)
    current = message
    for at, (field, index) in enumerate(steps):
        members = {f.name: f for f in messages.fields(current, distro)}
        member = members.get(field)
        if member is None:
            return f"{current} has no member `{field}` (`{path}`)"
        if index is not None and member.size is None:
            return f"`{field}` of {current} is not a list (`{path}`)"
        last = at == len(steps) - 1
        if last and conversion == "yaw":
            return None if member.type == "geometry_msgs/Quaternion" and (member.size is None or index is not None) \
                else f"`:yaw` needs a geometry_msgs/Quaternion, and `{field}` of {current} is not one (`{path}`)"
        if last:
            return None if member.type in _PRIMITIVES else f"`{path}` ends at a {member.type}, not a value"
        if member.type in _PRIMITIVES or (member.size is not None and index is None):
            return f"`{field}` of {current} has no members (`{path}`)"
        current = member.type
    return None
