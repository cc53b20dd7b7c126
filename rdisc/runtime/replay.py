"""A recording run again through a description: the regression test of a description against a
real device's traffic (`rdisc replay FILE.mcap DESCRIPTION`).

The recording (`rdisc run --record`, `engine.Recorder`) holds what ran, in order, and the bytes
each way on every connection. The replay opens the description on ports that give back the
recorded replies, without threads, makes the recorded calls and runs the periodic interfaces and
keepalives where the recording ran them, and records all of it again with the same Recorder.
The robot's clock is the recording's (`RecordedClock`): a sensor's value grows old as it did in
the recorded session, so the replay reads it where that session read it and serves the kept
value where that one did, however fast the replay runs.
Then the two recordings are compared, topic by topic: each input and output message field by
field (a header's stamp aside), the bytes written on each connection, and the errors (a refused
reply, a timeout) of one and not the other. Delays are not slept unless asked (`realtime`).
"""

from __future__ import annotations

import difflib
import io
from collections import deque
from collections.abc import Callable, Iterable, Mapping
from typing import Any

from rdisc import engine
from rdisc.recordings import Recording, RecordingError, read_recording

__all__ = ["RecordedClock", "Recording", "RecordingError", "ReplayPort", "differences", "read_recording", "replay"]

SHOWN = 5
"""Differences shown per topic; the others are counted."""


class RecordedClock:
    """The replay's time, in seconds: the recording's timestamps as the replay reaches them (each
    run where it began, each exchange where it ended), and the description's delays between them,
    never the wall clock's. A robot's clock (`Robot._clock`): what a sensor's age is measured on."""

    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        return self.now

    def reach(self, stamp_ns: int) -> None:
        """The recording has come to this time (it never goes back)."""
        self.now = max(self.now, stamp_ns / 1e9)

    def advance(self, seconds: float) -> None:
        """A delay: the recording's time passes as it did."""
        self.now += seconds

    def advancing(self, wait: Callable[[float], None] | None) -> Callable[[float], None]:
        """A robot's way to wait out a delay: `wait` for it (None: not waited for), then `advance`."""
        if wait is None:
            return self.advance

        def waited(seconds: float) -> None:
            wait(seconds)
            self.advance(seconds)
        return waited


class ReplayPort:
    """A port that answers each write with the bytes the recording read after the same write.

    Bytes a description leaves unread are dropped when it next clears the input, as a real
    port's are; a read with nothing recorded for it returns nothing, as a read that times out.
    Each recorded exchange given brings `clock` to the time it ended (`times`, in ns).
    """

    def __init__(self, exchanges: Iterable[tuple[bytes | None, bytes]], times: Iterable[int] = (),
                 clock: RecordedClock | None = None) -> None:
        self._exchanges = deque(exchanges)
        self._times = deque(times)
        self._clock = clock
        self._available = bytearray()
        self.timeout: float | None = 0.0
        self.dtr = self.rts = False  # the modem lines a primitive sets are recorded, nothing more

    def write(self, data: bytes, /) -> int:
        while self._exchanges:  # a listener's bytes recorded before the write come first
            written, read = self._exchanges.popleft()
            self._reached()
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
            self._reached()

    def _reached(self) -> None:
        """The clock at the end of the exchange just given."""
        if self._times:
            stamp = self._times.popleft()
            if self._clock is not None:
                self._clock.reach(stamp)


def replay(recording: Recording, device: engine.Device, *, realtime: bool = False) -> Recording:
    """Run the recording's runs through a device on ports that answer as the recording did,
    and give the recording of that. The reply timeout is the session's, so that a timeout's
    error reads as it did; it is never waited for, as a reply is there at once, or never. The
    description's delays are slept only with `realtime`. The robot's clock is the recording's
    (`RecordedClock`), so its sensors are read where the recorded session read them."""
    robot = engine.Robot(device, timeout=recording.timeout or 0.05)
    clock = RecordedClock()
    robot._clock = clock  # the schedule's and the sensors' time (a simulation's takes it too)
    robot._sleep = clock.advancing(robot._sleep if realtime else None)  # the robot's one way to wait out a delay
    output = io.BytesIO()
    recorder = engine.Recorder(robot, output, recording.settings)
    ports = {name: ReplayPort(recording.exchanges.get(name, ()), recording.exchange_times.get(name, ()), clock)
             for name in device.connections}
    given: dict[str, engine.Port] = dict(ports)
    robot.open(given, threads=False, settings=_settings(recording.settings))
    try:
        for at, run in enumerate(recording.runs):
            if at < len(recording.run_times):
                clock.reach(recording.run_times[at])
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
