"""A recording run again through a description: the regression test of a description against a
real device's traffic (`rdisc replay FILE.mcap DESCRIPTION`).

The recording (`rdisc run --record`, `engine.Recorder`) holds what ran, in order, and the bytes
each way on every connection. The replay opens the description on ports that give back the
recorded replies, without threads, makes the recorded calls and runs the periodic interfaces and
keepalives where the recording ran them, and records all of it again with the same Recorder.
Then the two recordings are compared, topic by topic: each input and output message field by
field (a header's stamp aside), the bytes written on each connection, and the errors (a refused
reply, a timeout) of one and not the other. Delays are slept as in a live session.
"""

from __future__ import annotations

import difflib
import io
import json
import os
from collections import deque
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from rdisc import engine

SHOWN = 5
"""Differences shown per topic; the others are counted."""


class RecordingError(Exception):
    """A file that is not a recording rdisc can read."""


@dataclass
class Recording:
    """What a replay needs of a recording, and what it compares."""

    settings: dict[str, Any] = field(default_factory=dict)
    timeout: float | None = None  # the reply timeout of the session; None in a recording older than it
    runs: list[dict[str, Any]] = field(default_factory=list)  # in order
    exchanges: dict[str, list[tuple[bytes | None, bytes]]] = field(default_factory=dict)  # by connection
    writes: dict[str, list[bytes]] = field(default_factory=dict)  # by connection
    messages: dict[str, list[dict[str, Any]]] = field(default_factory=dict)  # by input or output, flattened
    errors: list[str] = field(default_factory=list)  # `Type: message`, in order


def read_recording(source: str | os.PathLike[str] | io.BytesIO) -> Recording:
    """A recording's runs, exchanges, writes and messages; RecordingError if it is none."""
    try:
        from mcap.exceptions import McapError
        from mcap.reader import make_reader
        from mcap_ros2.decoder import DecoderFactory
    except ImportError as err:
        raise RecordingError("replaying needs the mcap and mcap-ros2-support packages "
                             "(pip install 'rdisc[record]')") from err
    recording = Recording()
    try:
        stream = open(source, "rb") if isinstance(source, (str, os.PathLike)) else source  # noqa: SIM115
        with stream:
            reader = make_reader(stream, decoder_factories=[DecoderFactory()])
            found = False
            for metadata in reader.iter_metadata():
                if metadata.name == "rdisc":
                    recording.settings = json.loads(metadata.metadata.get("settings", "{}"))
                    timeout = json.loads(metadata.metadata.get("timeout", "null"))
                    recording.timeout = float(timeout) if isinstance(timeout, (int, float)) and timeout > 0 else None
                    found = True
            if not found:
                raise RecordingError("not a recording of rdisc (it has no `rdisc` metadata)")
            for _, channel, _, message in reader.iter_decoded_messages(log_time_order=True):
                _take(recording, channel.topic, message)
    except OSError as err:
        raise RecordingError(err.strerror or str(err)) from None
    except (McapError, ValueError, KeyError, TypeError, IndexError, NotImplementedError) as err:
        raise RecordingError(f"not a readable recording: {err}") from None
    return recording


def _take(recording: Recording, topic: str, message: Any) -> None:
    """One message of the recording, in order."""
    parts = topic.split("/")
    if topic == engine.RUNS_TOPIC:
        run = json.loads(message.data)
        if not isinstance(run, dict):
            raise ValueError(f"a run that is not an object: {message.data!r}")
        recording.runs.append(run)
    elif len(parts) == 4 and parts[1] == "rdisc" and parts[3] in ("write", "read"):
        connection, data = parts[2], bytes(message.data)
        exchanges = recording.exchanges.setdefault(connection, [])
        if parts[3] == "write":
            recording.writes.setdefault(connection, []).append(data)
            exchanges.append((data, b""))
        elif exchanges and exchanges[-1][0] is not None and not exchanges[-1][1]:
            exchanges[-1] = (exchanges[-1][0], data)  # the reply to that write
        else:
            exchanges.append((None, data))  # read with nothing written: a listener's
    elif topic == "/rosout":
        recording.errors.append(message.msg)
    elif len(parts) == 2 and parts[1]:
        contents = json.loads(message.data) if type(message).__name__ == "String" else message
        recording.messages.setdefault(parts[1], []).append(  # a header's stamp is when it was recorded
            {path: value for path, value in _flat(contents) if not path.startswith("header.stamp.")})


def _flat(value: Any, prefix: str = "") -> Iterable[tuple[str, Any]]:
    """A decoded message (or JSON contents) as (field path, value) pairs: `linear.x`, `name[0]`."""
    if isinstance(value, dict):
        members: Iterable[tuple[str, Any]] = value.items()
    elif hasattr(value, "__slots__") and not isinstance(value, (str, bytes)):
        members = ((name, getattr(value, name)) for name in value.__slots__ if not name.startswith("_"))
    elif isinstance(value, (list, tuple, bytes)):
        for i, item in enumerate(value):
            yield from _flat(item, f"{prefix}[{i}]")
        return
    else:
        yield prefix, value
        return
    for name, member in members:
        yield from _flat(member, f"{prefix}.{name}" if prefix else name)


class ReplayPort:
    """A port that answers each write with the bytes the recording read after the same write.

    Bytes a description leaves unread are dropped when it next clears the input, as a real
    port's are; a read with nothing recorded for it returns nothing, as a read that times out.
    """

    def __init__(self, exchanges: Iterable[tuple[bytes | None, bytes]]) -> None:
        self._exchanges = deque(exchanges)
        self._available = bytearray()
        self.timeout: float | None = 0.0
        self.dtr = self.rts = False  # the modem lines a primitive sets are recorded, nothing more

    def write(self, data: bytes, /) -> int:
        while self._exchanges:  # a listener's bytes recorded before the write come first
            written, read = self._exchanges.popleft()
            self._available += read
            if written is not None:
                break
        return len(data)

    def read(self, size: int = 1, /) -> bytes:
        self._listen()
        taken = bytes(self._available[:size])
        del self._available[:size]
        return taken

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes:
        self._listen()
        found = self._available.find(expected)
        end = len(self._available) if found < 0 else found + len(expected)
        if size is not None:
            end = min(end, size)
        taken = bytes(self._available[:end])
        del self._available[:end]
        return taken

    def reset_input_buffer(self) -> None:
        self._available.clear()

    def close(self) -> None:
        """Nothing to close."""

    def _listen(self) -> None:
        """With nothing left to read, the bytes a listener read next, if those come next."""
        if not self._available and self._exchanges and self._exchanges[0][0] is None:
            self._available += self._exchanges.popleft()[1]


def replay(recording: Recording, device: engine.Device) -> Recording:
    """Run the recording's runs through a device on ports that answer as the recording did,
    and give the recording of that. The reply timeout is the session's, so that a timeout's
    error reads as it did; it is never waited for, as a reply is there at once, or never."""
    robot = engine.Robot(device, timeout=recording.timeout or 0.05)
    output = io.BytesIO()
    recorder = engine.Recorder(robot, output, recording.settings)
    ports = {name: ReplayPort(recording.exchanges.get(name, ())) for name in device.connections}
    given: dict[str, engine.Port] = dict(ports)
    robot.open(given, threads=False, settings=_settings(recording.settings))
    try:
        for run in recording.runs:
            try:
                _run(robot, recorder, run)
            except engine.RdisError as err:
                recorder.error(err)
    finally:
        robot.close()
        recorder.finish()
    return read_recording(io.BytesIO(output.getvalue()))


def _settings(values: Mapping[str, Any]) -> dict[str, Any]:
    """Settings as JSON gave them back: arrays as tuples."""
    return {name: tuple(value) if isinstance(value, list) else value for name, value in values.items()}


def _run(robot: engine.Robot, recorder: engine.Recorder, run: Mapping[str, Any]) -> None:
    """One recorded run again: a call of the host, or a connection's periodic interface or keepalive."""
    if "call" in run:
        kind, name = run["call"], run["name"]
        try:  # the values read as `--call` and the console read theirs, then recorded and made as they are
            values = engine.call_values(robot.device, kind, name, run["values"])
            recorder.call(kind, name, values)
            engine.make_call(robot, kind, name, values)
        except engine.RdisError:  # the device's or the values' error, as in a live session (RdisValueError too)
            raise
        except (KeyError, TypeError, ValueError) as err:  # not in this description, or not with these values
            message = err.args[0] if isinstance(err, KeyError) and err.args else err
            raise engine.RdisValueError(f"the recorded call of {kind} {name}: {message}") from None
        return
    connection = robot.device.connections.get(run.get("connection", ""))
    if connection is None:
        raise engine.RdisValueError(f"the recording runs work of connection {run.get('connection')!r}, "
                                    "which this description has not")
    recorder.run(connection.name, "keepalive" if "keepalive" in run else "periodic",
                 run.get("keepalive", run.get("periodic", "")))
    if "keepalive" in run:
        if connection.keepalive is not None:
            hook = connection.keepalive
            robot.call_interface(hook.interface.name, *hook.args(robot.state))
    elif run.get("periodic") in {i.name for i in connection.periodic}:
        robot.call_interface(run["periodic"])


def differences(recorded: Recording, replayed: Recording, device: engine.Device) -> list[str]:
    """Where the replay's messages, bytes written and errors differ from the recording's, in words."""
    lines: list[str] = []
    names = dict.fromkeys([*recorded.messages, *replayed.messages])
    fields = _field_names(device)
    for name in names:
        lines += _compare(f"{name}", recorded.messages.get(name, []), replayed.messages.get(name, []),
                          lambda a, b, name=name: _field_differences(a, b, fields.get(name, {})))
    for connection in dict.fromkeys([*recorded.writes, *replayed.writes]):
        lines += _compare(f"{connection} writes", recorded.writes.get(connection, []),
                          replayed.writes.get(connection, []),
                          lambda a, b: [f"recorded {a.hex(' ')}, replayed {b.hex(' ')}"] if a != b else [])
    return lines + _error_differences(recorded.errors, replayed.errors)


def _error_differences(recorded: list[str], replayed: list[str]) -> list[str]:
    """The errors of one run and not of the other, in order: matched by their text, so one error
    more or less is one line, not a shift of every error after it."""
    lines: list[str] = []
    matcher = difflib.SequenceMatcher(a=recorded, b=replayed, autojunk=False)
    for tag, a_start, a_end, b_start, b_end in matcher.get_opcodes():
        if tag != "equal":
            lines += [f"error #{n + 1}: recorded, not replayed: {text}"
                      for n, text in enumerate(recorded[a_start:a_end], start=a_start)]
            lines += [f"error #{n + 1}: replayed, not recorded: {text}"
                      for n, text in enumerate(replayed[b_start:b_end], start=b_start)]
    if len(lines) > SHOWN:
        lines[SHOWN:] = [f"errors: {len(lines) - SHOWN} more differ"]
    return lines


def _field_names(device: engine.Device) -> dict[str, dict[str, str]]:
    """For each input and output, its adapter's field at each ROS path: fields are named as the
    description names them (`distance`, not `range`)."""
    adapters = {o.name: o.adapter for i in device.interfaces.values() for o in i.outputs}
    adapters.update({i.name: i.adapter for i in device.inputs.values()})
    return {name: {path.partition(":")[0]: f for f, path in zip(message.fields, message.paths)}
            for name, adapter in adapters.items() if (message := device.messages.get(adapter)) is not None}


def _field_differences(recorded: Mapping[str, Any], replayed: Mapping[str, Any],
                       names: Mapping[str, str]) -> list[str]:
    out = []
    for path in dict.fromkeys([*recorded, *replayed]):
        a, b = recorded.get(path, "nothing"), replayed.get(path, "nothing")
        if a != b:
            shown = path if names.get(path, path) == path else f"{names[path]} ({path})"
            out.append(f"{shown}: recorded {a!r}, replayed {b!r}")
    return out


def _compare(what: str, recorded: list[Any], replayed: list[Any], differ: Any) -> list[str]:
    """Two sequences of one topic, item by item: the first few differences, and the counts."""
    lines: list[str] = []
    found = 0
    for n, (a, b) in enumerate(zip(recorded, replayed), start=1):
        found_here = differ(a, b)
        if found_here:
            found += 1
            if found <= SHOWN:
                lines += [f"{what} #{n}: {text}" for text in found_here]
    if found > SHOWN:
        lines.append(f"{what}: {found - SHOWN} more differ")
    if len(recorded) != len(replayed):
        lines.append(f"{what}: recorded {len(recorded)}, replayed {len(replayed)}")
    return lines
