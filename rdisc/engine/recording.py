"""Recordings: a session written to an MCAP file of ROS 2 messages, which `rdisc replay` runs
again through a description.
"""

from __future__ import annotations

import json
import math
import os
import threading
import time
from collections.abc import Mapping
from typing import Any

from rdisc.engine.plans import Message
from rdisc.engine.robot import Robot
from rdisc.engine.values import OutputMessage

_SEPARATOR = "=" * 80  # between a ros2msg schema's message and each message it uses
_HEADER = "std_msgs/Header header"  # a message's field, which a recording stamps
TEXT_TYPE = "std_msgs/msg/String"
_TEXT_SCHEMA = "string data\n"
BYTES_TYPE = "std_msgs/msg/UInt8MultiArray"
_BYTES_SCHEMA = ("MultiArrayLayout layout\nuint8[] data\n" + _SEPARATOR + "\nMSG: std_msgs/MultiArrayLayout\n"
                 "MultiArrayDimension[] dim\nuint32 data_offset\n" + _SEPARATOR
                 + "\nMSG: std_msgs/MultiArrayDimension\nstring label\nuint32 size\nuint32 stride\n")
LOG_TYPE = "rcl_interfaces/msg/Log"
_LOG_SCHEMA = ("byte DEBUG=10\nbyte INFO=20\nbyte WARN=30\nbyte ERROR=40\nbyte FATAL=50\n"
               "builtin_interfaces/Time stamp\nuint8 level\nstring name\nstring msg\nstring file\n"
               "string function\nuint32 line\n" + _SEPARATOR + "\nMSG: builtin_interfaces/Time\n"
               "int32 sec\nuint32 nanosec\n")
RUNS_TOPIC = "/rdisc/runs"


def _time(stamp: int) -> dict[str, int]:
    """Nanoseconds since the epoch as a builtin_interfaces/Time."""
    return {"sec": stamp // 1_000_000_000, "nanosec": stamp % 1_000_000_000}


class Recorder:
    """A session written to an MCAP file of ROS 2 messages in the `ros2` profile (the tests
    read it back with rosbags, an independent reader; `rdisc replay` runs it again through a
    description).

    Topics: each input called and each output delivered on `/NAME`, as its adapter's ROS 2
    message (`Device.messages`), or, for an adapter without one, its fields as JSON in a
    std_msgs/String; the bytes each way on `/rdisc/CONNECTION/write` and `/read`
    (std_msgs/UInt8MultiArray), the modem lines a primitive set on `/rdisc/CONNECTION/lines`;
    what ran, in order, on `/rdisc/runs` (JSON: each call of the host with its values, each
    periodic interface and keepalive a connection's thread started), which is what a replay
    repeats; errors on `/rosout` (rcl_interfaces/Log). Times are the host's clock, in order.
    Needs the `mcap` and `mcap-ros2-support` packages, imported here only (ImportError without).
    """

    def __init__(self, robot: Robot, output: Any, settings: Mapping[str, Any] | None = None, *,
                 replace: bool = False) -> None:
        """`output` a stream, or a path: a new file (FileExistsError if there is one), or, with
        `replace`, one that may be there already."""
        from mcap_ros2.writer import Writer  # only a recording needs it

        self._file: Any = None
        if isinstance(output, (str, os.PathLike)):
            output = self._file = open(output, "wb" if replace else "xb")  # noqa: SIM115 (closed by finish)
        self._writer: Any = Writer(output)
        self._device = robot.device
        delivered = [o for i in robot.device.interfaces.values() for o in i.outputs]
        self._adapters = {o.name: o.adapter for o in delivered}
        self._frames = {o.name: (o.frame, o.child_frame) for o in delivered}
        self._lock = threading.Lock()
        self._time = 0
        self._schemas: dict[str, Any] = {}
        self._writer.add_metadata("rdisc", {"robot": robot.name, "timeout": json.dumps(robot.timeout),
                                            "settings": json.dumps(dict(settings or {}), default=list)})
        robot.on_output(self.output)
        robot.on_error(self.error)
        robot.on_io(self.io)
        robot._run_callbacks.append(self.run)

    def call(self, kind: str, name: str, values: Mapping[str, Any]) -> None:
        """The host calls an input, an interface or a primitive with these values by name."""
        self._write(RUNS_TOPIC, TEXT_TYPE, _TEXT_SCHEMA, {"data": json.dumps({"call": kind, "name": name,
                                                                         "values": dict(values)}, default=bytes.hex)})
        plan = self._device.inputs.get(name) if kind == "input" else None
        if plan is not None:
            self._adapted(name, plan.adapter, dict(values))

    def run(self, connection: str, kind: str, name: str) -> None:
        """A connection's thread starts a periodic interface or its keepalive."""
        run = {kind: name, "connection": connection}
        self._write(RUNS_TOPIC, TEXT_TYPE, _TEXT_SCHEMA, {"data": json.dumps(run)})

    def output(self, message: OutputMessage) -> None:
        """An output delivered: its header (if its message has one) stamped when its data was read,
        in its frame."""
        name = message["name"]
        header = (message.read_ns, *self._frames.get(name, ("", "")))
        self._adapted(name, self._adapters.get(name, ""), message["contents"], header)

    def error(self, error: BaseException) -> None:
        stamp = self._stamp()
        self._write("/rosout", LOG_TYPE, _LOG_SCHEMA, {
            "stamp": _time(stamp), "level": 40,
            "name": self._device.name, "msg": f"{type(error).__name__}: {error}"}, stamp)

    def io(self, direction: str, connection: str, data: bytes) -> None:
        if direction == "lines":
            self._write(f"/rdisc/{connection}/lines", TEXT_TYPE, _TEXT_SCHEMA, {"data": data.decode("ascii")})
        else:
            self._write(f"/rdisc/{connection}/{direction}", BYTES_TYPE, _BYTES_SCHEMA, {"data": list(data)})

    def finish(self) -> None:
        """Write the file's index and close it: call it once the robot is closed."""
        with self._lock:
            try:
                self._writer.finish()
            finally:
                if self._file is not None:
                    self._file.close()

    def _adapted(self, name: str, adapter: str, contents: Mapping[str, Any],
                 header: tuple[int, str, str] | None = None) -> None:
        """An adapter's values on `/NAME`: its ROS 2 message, or JSON text. A message with a
        std_msgs/Header is stamped with `header` (an output's: when its data was read, its frame
        id and child frame id), else (an input) with the time it is recorded at, as a ROS 2
        publisher's is."""
        message = self._device.messages.get(adapter)
        if message is None:
            text = json.dumps(dict(contents), default=list)
            self._write(f"/{name}", TEXT_TYPE, _TEXT_SCHEMA, {"data": text})
            return
        stamp = self._stamp()
        members = ros_message(message, contents)
        if _HEADER in message.definition.partition(_SEPARATOR)[0].splitlines():
            read_ns, frame, child = (stamp, "", "") if header is None else header
            members.setdefault("header", {}).update(stamp=_time(read_ns), frame_id=frame)
            if child:
                members["child_frame_id"] = child
        self._write(f"/{name}", message.type, message.definition, members, stamp)

    def _stamp(self) -> int:
        """Now in nanoseconds, later than every time written before: the file keeps the order."""
        with self._lock:
            self._time = max(time.time_ns(), self._time + 1)
            return self._time

    def _write(self, topic: str, kind: str, schema: str, message: dict[str, Any], stamp: int | None = None) -> None:
        stamp = self._stamp() if stamp is None else stamp
        with self._lock:
            registered = self._schemas.get(kind)
            if registered is None:
                registered = self._schemas[kind] = self._writer.register_msgdef(kind, schema)
            self._writer.write_message(topic, registered, message, log_time=stamp)


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
