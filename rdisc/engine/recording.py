"""A session as ROS 2 messages on topics (`Session`, the one observer of a robot that its
consumers share), and recordings: that session written to an MCAP file, which `rdisc replay`
runs again through a description.
"""

from __future__ import annotations

import json
import math
import os
import threading
import time
from collections.abc import Callable, Mapping
from typing import Any, NamedTuple

from rdisc.engine.plans import Device, Message
from rdisc.engine.robot import Robot
from rdisc.engine.values import OutputMessage

_SEPARATOR = "=" * 80  # between a ros2msg schema's message and each message it uses
_HEADER = "std_msgs/Header header"  # a message's field, which a session stamps
TEXT_TYPE = "std_msgs/msg/String"
_TEXT_SCHEMA = "string data\n"
_LAYOUT = (_SEPARATOR + "\nMSG: std_msgs/MultiArrayLayout\nMultiArrayDimension[] dim\nuint32 data_offset\n"
           + _SEPARATOR + "\nMSG: std_msgs/MultiArrayDimension\nstring label\nuint32 size\nuint32 stride\n")
BYTES_TYPE = "std_msgs/msg/UInt8MultiArray"
_BYTES_SCHEMA = "MultiArrayLayout layout\nuint8[] data\n" + _LAYOUT
LOG_TYPE = "rcl_interfaces/msg/Log"
_LOG_SCHEMA = ("byte DEBUG=10\nbyte INFO=20\nbyte WARN=30\nbyte ERROR=40\nbyte FATAL=50\n"
               "builtin_interfaces/Time stamp\nuint8 level\nstring name\nstring msg\nstring file\n"
               "string function\nuint32 line\n" + _SEPARATOR + "\nMSG: builtin_interfaces/Time\n"
               "int32 sec\nuint32 nanosec\n")
RUNS_TOPIC = "/rdisc/runs"
STATE_TOPIC = "/state/"  # a state variable's topic is this and its name
_INT64 = (-(2 ** 63), 2 ** 63 - 1)


class Topic(NamedTuple):
    """One channel of a session: its topic, its ROS 2 type and that type's `ros2msg` schema
    (the type's fields, then each message they use under a line of `=` and `MSG: pkg/Type`)."""

    name: str
    type: str
    schema: str


Sink = Callable[[Topic, dict[str, Any], int], object]
"""`(topic, message, stamp)`: one message of a session, as the nested members of its ROS 2
message (what `mcap-ros2-support` encodes), at `stamp` nanoseconds since the epoch."""

_TEXT = (TEXT_TYPE, _TEXT_SCHEMA)
_SCALARS: dict[type, tuple[str, str]] = {  # a state variable's message, by its value's type
    bool: ("std_msgs/msg/Bool", "bool data\n"),
    int: ("std_msgs/msg/Int64", "int64 data\n"),
    float: ("std_msgs/msg/Float64", "float64 data\n"),
    str: _TEXT,
    bytes: (BYTES_TYPE, _BYTES_SCHEMA),
}
_ARRAYS: dict[type, tuple[str, str]] = {  # an array's, by its elements' type
    int: ("std_msgs/msg/Int64MultiArray", "MultiArrayLayout layout\nint64[] data\n" + _LAYOUT),
    float: ("std_msgs/msg/Float64MultiArray", "MultiArrayLayout layout\nfloat64[] data\n" + _LAYOUT),
}


def _state_message(value: Any) -> tuple[str, str]:
    """The std_msgs type (and schema) a state variable's value is carried as: a bool, int or
    float as its std_msgs message, an array of ints or floats as their MultiArray, text as a
    String, bytes as a UInt8MultiArray; any other array as its JSON in a String."""
    if isinstance(value, tuple):
        kinds = {type(v) for v in value}
        return _ARRAYS.get(kinds.pop(), _TEXT) if len(kinds) == 1 else _TEXT
    return _SCALARS.get(type(value), _TEXT)


def _state_members(kind: str, value: Any) -> dict[str, Any]:
    """A state variable's value as the members of its message (`_state_message`)."""
    if kind == TEXT_TYPE and not isinstance(value, str):
        return {"data": json.dumps(value, default=list)}
    if kind == "std_msgs/msg/Int64" or kind == "std_msgs/msg/Int64MultiArray":
        low, high = _INT64  # a wider int is shown at the nearest end of int64 (the checker bounds most)
        value = min(max(value, low), high) if isinstance(value, int) else tuple(min(max(v, low), high) for v in value)
    return {"data": list(value) if isinstance(value, (tuple, bytes)) else value}


def session_topics(device: Device) -> list[Topic]:
    """Every channel a session of `device` may carry, in the order a viewer lists them: each
    input and output as its adapter's message (or its fields as JSON text), each state variable
    (setting included) as its value's std_msgs message on `/state/NAME`, the bytes each way
    (and modem lines, where a primitive sets them) of each connection, what ran, errors."""
    found: dict[str, Topic] = {}
    adapters = {**{name: plan.adapter for name, plan in device.inputs.items()},
                **{o.name: o.adapter for i in device.interfaces.values() for o in i.outputs}}
    for name, adapter in adapters.items():
        message = device.messages.get(adapter)
        found[f"/{name}"] = (Topic(f"/{name}", message.type, message.definition) if message is not None
                             else Topic(f"/{name}", *_TEXT))
    for name, value in device.state.items():
        found[STATE_TOPIC + name] = Topic(STATE_TOPIC + name, *_state_message(value))
    for connection in device.connections:
        for direction in ("write", "read"):
            found[f"/rdisc/{connection}/{direction}"] = Topic(f"/rdisc/{connection}/{direction}", BYTES_TYPE,
                                                              _BYTES_SCHEMA)
        if any(p.lines is not None and p.connection == connection for p in device.primitives.values()):
            found[f"/rdisc/{connection}/lines"] = Topic(f"/rdisc/{connection}/lines", *_TEXT)
    found[RUNS_TOPIC] = Topic(RUNS_TOPIC, *_TEXT)
    found["/rosout"] = Topic("/rosout", LOG_TYPE, _LOG_SCHEMA)
    return list(found.values())


def _time(stamp: int) -> dict[str, int]:
    """Nanoseconds since the epoch as a builtin_interfaces/Time."""
    return {"sec": stamp // 1_000_000_000, "nanosec": stamp % 1_000_000_000}


class Session:
    """A robot's session as ROS 2 messages on the channels `session_topics(device)` names, handed to
    each sink added (`add`): the one observer of a robot that a recording (`Recorder`) and a
    live viewer (`rdisc run --foxglove`) share, so both carry the same messages.

    Topics: each input called and each output delivered on `/NAME`, as its adapter's ROS 2
    message (`Device.messages`), or, for an adapter without one, its fields as JSON in a
    std_msgs/String; each state variable on `/state/NAME` when it changes (seen at each byte
    written or read and each output), for the sinks that take state; the bytes each way on `/rdisc/CONNECTION/write` and
    `/read` (std_msgs/UInt8MultiArray), the modem lines a primitive set on
    `/rdisc/CONNECTION/lines`; what ran, in order, on `/rdisc/runs` (JSON: each call of the host
    with its values, each periodic interface and keepalive a connection's thread started),
    which is what a replay repeats; errors on `/rosout` (rcl_interfaces/Log). Times are the
    host's clock, in order: each message is later than the one before, and sinks get them in
    that order.
    """

    def __init__(self, robot: Robot) -> None:
        self._robot = robot
        self._device = robot.device
        delivered = [o for i in robot.device.interfaces.values() for o in i.outputs]
        self._adapters = {o.name: o.adapter for o in delivered}
        self._frames = {o.name: (o.frame, o.child_frame) for o in delivered}
        self.topics = {topic.name: topic for topic in session_topics(robot.device)}
        self._sinks: list[Sink] = []
        self._state_sinks: list[Sink] = []
        self._lock = threading.RLock()
        self._time = 0
        self._state: dict[str, Any] = {}
        robot.on_output(self.output)
        robot.on_error(self.error)
        robot.on_io(self.io)
        robot._run_callbacks.append(self.run)

    def add(self, sink: Sink, *, state: bool = True) -> None:
        """Hand every message from now on to `sink` too; without `state`, none of `/state/NAME`."""
        with self._lock:
            self._sinks.append(sink)
            if state:
                self._state_sinks.append(sink)

    def call(self, kind: str, name: str, values: Mapping[str, Any]) -> None:
        """The host calls an input, an interface or a primitive with these values by name."""
        self._send(RUNS_TOPIC, {"data": json.dumps({"call": kind, "name": name, "values": dict(values)},
                                                   default=bytes.hex)})
        plan = self._device.inputs.get(name) if kind == "input" else None
        if plan is not None:
            self._adapted(name, plan.adapter, dict(values))

    def run(self, connection: str, kind: str, name: str) -> None:
        """A connection's thread starts a periodic interface or its keepalive."""
        self._send(RUNS_TOPIC, {"data": json.dumps({kind: name, "connection": connection})})

    def output(self, message: OutputMessage) -> None:
        """An output delivered: its header (if its message has one) stamped when its data was read,
        in its frame."""
        name = message["name"]
        header = (message.read_ns, *self._frames.get(name, ("", "")))
        self._adapted(name, self._adapters.get(name, ""), message["contents"], header)
        self._changed_state()

    def error(self, error: BaseException) -> None:
        with self._lock:
            stamp = self._stamp()
            self._send("/rosout", {"stamp": _time(stamp), "level": 40, "name": self._device.name,
                                   "msg": f"{type(error).__name__}: {error}"}, stamp)

    def io(self, direction: str, connection: str, data: bytes) -> None:
        if direction == "lines":
            self._send(f"/rdisc/{connection}/lines", {"data": data.decode("ascii")})
        else:
            self._send(f"/rdisc/{connection}/{direction}", {"data": list(data)})
        self._changed_state()

    def _changed_state(self) -> None:
        """Each state variable whose value is not the one last sent, on its topic, to the sinks
        that take state."""
        with self._lock:
            for name, value in self._robot.state.items() if self._state_sinks else ():
                if name not in self._state or self._state[name] != value:
                    self._state[name] = value
                    topic = self.topics[STATE_TOPIC + name]
                    self._send(topic.name, _state_members(topic.type, value), sinks=self._state_sinks)

    def _adapted(self, name: str, adapter: str, contents: Mapping[str, Any],
                 header: tuple[int, str, str] | None = None) -> None:
        """An adapter's values on `/NAME`: its ROS 2 message, or JSON text. A message with a
        std_msgs/Header is stamped with `header` (an output's: when its data was read, its frame
        id and child frame id), else (an input) with the time it is sent at, as a ROS 2
        publisher's is."""
        message = self._device.messages.get(adapter)
        if message is None:
            self._send(f"/{name}", {"data": json.dumps(dict(contents), default=list)})
            return
        with self._lock:
            stamp = self._stamp()
            members = ros_message(message, contents)
            if _HEADER in message.definition.partition(_SEPARATOR)[0].splitlines():
                read_ns, frame, child = (stamp, "", "") if header is None else header
                members.setdefault("header", {}).update(stamp=_time(read_ns), frame_id=frame)
                if child:
                    members["child_frame_id"] = child
            self._send(f"/{name}", members, stamp)

    def _stamp(self) -> int:
        """Now in nanoseconds, later than every time given before: the messages keep their order."""
        with self._lock:
            self._time = max(time.time_ns(), self._time + 1)
            return self._time

    def _send(self, topic: str, message: dict[str, Any], stamp: int | None = None,
              sinks: list[Sink] | None = None) -> None:
        with self._lock:
            stamp = self._stamp() if stamp is None else stamp
            channel = self.topics.get(topic) or Topic(topic, *_TEXT)
            for sink in self._sinks if sinks is None else sinks:
                sink(channel, message, stamp)


class Recorder:
    """A session written to an MCAP file of ROS 2 messages in the `ros2` profile, on the topics
    of `Session` but the state's, which a replay computes again (the tests read it back with rosbags, an independent reader; `rdisc replay`
    runs it again through a description). Needs the `mcap` and `mcap-ros2-support` packages,
    imported here only (ImportError without).
    """

    def __init__(self, robot: Robot, output: Any, settings: Mapping[str, Any] | None = None, *,
                 replace: bool = False, session: Session | None = None) -> None:
        """`output` a stream, or a path: a new file (FileExistsError if there is one), or, with
        `replace`, one that may be there already. `session`: the robot's, when something else
        observes it too (else the recorder's own)."""
        from mcap_ros2.writer import Writer  # only a recording needs it

        self._file: Any = None
        if isinstance(output, (str, os.PathLike)):
            output = self._file = open(output, "wb" if replace else "xb")  # noqa: SIM115 (closed by finish)
        self._writer: Any = Writer(output)
        self._lock = threading.Lock()
        self._schemas: dict[str, Any] = {}
        self._writer.add_metadata("rdisc", {"robot": robot.name, "timeout": json.dumps(robot.timeout),
                                            "settings": json.dumps(dict(settings or {}), default=list)})
        self.session = session if session is not None else Session(robot)
        self.session.add(self._write, state=False)

    def call(self, kind: str, name: str, values: Mapping[str, Any]) -> None:
        """The host calls an input, an interface or a primitive with these values by name."""
        self.session.call(kind, name, values)

    def run(self, connection: str, kind: str, name: str) -> None:
        """A connection's thread starts a periodic interface or its keepalive."""
        self.session.run(connection, kind, name)

    def error(self, error: BaseException) -> None:
        self.session.error(error)

    def finish(self) -> None:
        """Write the file's index and close it: call it once the robot is closed."""
        with self._lock:
            try:
                self._writer.finish()
            finally:
                if self._file is not None:
                    self._file.close()

    def _write(self, topic: Topic, message: dict[str, Any], stamp: int) -> None:
        with self._lock:
            registered = self._schemas.get(topic.type)
            if registered is None:
                registered = self._schemas[topic.type] = self._writer.register_msgdef(topic.type, topic.schema)
            self._writer.write_message(topic.name, registered, message, log_time=stamp)


def ros_message(message: Message, values: Mapping[str, Any]) -> dict[str, Any]:
    """An adapter's values by field name as the nested members of its ROS 2 message (what
    `mcap-ros2-support` encodes); members no field names keep their defaults."""
    out: dict[str, Any] = {}
    for name, path in zip(message.fields, message.paths):
        value = values[name]
        steps, _, conversion = path.partition(":")
        if conversion == "yaw":
            value = {"x": 0.0, "y": 0.0, "z": math.sin(value / 2), "w": math.cos(value / 2)}
        elif isinstance(value, tuple):
            value = list(value)
        where = out
        names = steps.split(".")
        for step in names[:-1]:
            where = where.setdefault(step, {})
        last, bracket, index = names[-1].partition("[")
        if bracket:
            items = where.setdefault(last, [])
            position = int(index[:-1])
            items.extend([None] * (position + 1 - len(items)))
            items[position] = value
        else:
            where[last] = value
    return out
