"""The one fake port of the tests: an open pyserial-like port in memory.

What the device says comes from a script (bytes said in order whenever the robot reads: they
are the device's next words, so resetting the input keeps them), or from a `Device` that answers
each request as it is written (its answer waits in the input, which a reset empties). A port
with neither is silent: every read times out, empty. Everything written is kept (`written`), and
each write and modem line change is an event, in order (`events`, or a log the test shares with
its callbacks). Real ports over pseudo-terminals (tests/devices) are used where timing or the
operating system's side matters; this one is for bytes alone.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol

Event = tuple[Any, ...]


class Device(Protocol):
    """A device model behind a port: it answers what is written, and may speak unasked."""

    def answer(self, request: bytes) -> bytes:
        """The bytes the device sends for a request (OSError: the device failed)."""
        ...

    def listen(self) -> bytes:
        """The bytes the device sends when the robot reads with nothing waiting (b"": nothing)."""
        ...


def _modem_line(name: str) -> property:
    """A modem line: each level set is recorded among the events."""

    def level(port: ScriptedPort) -> bool:
        return port.levels[name]

    def set_level(port: ScriptedPort, value: bool) -> None:
        port.levels[name] = value
        port.events.append((name, value))

    return property(level, set_level)


class ScriptedPort:
    """A port in memory whose device is scripted by the test: a script of reply bytes, a `Device`,
    or silence; it can also fail (`fail`: a write raises OSError, as a port that was unplugged).

    `events`: ("write", data), ("dtr", level), ("rts", level), ("break", held), and ("reset input", what was
    waiting) when `record_resets`. `on_timeout(seconds)` is told of each read that came back short
    after waiting the port's whole timeout (a test's clock can then advance by it)."""

    dtr = _modem_line("dtr")
    rts = _modem_line("rts")

    def __init__(
        self,
        script: bytes = b"",
        *,
        device: Device | None = None,
        events: list[Event] | None = None,
        record_resets: bool = False,
        timeout: float | None = 0.05,
        fail: bool = False,
        on_timeout: Callable[[float], None] | None = None,
    ) -> None:
        self.script = bytes(script)
        self.device = device
        self.input = bytearray()  # what the device answered and the robot has not read yet
        self.written = bytearray()
        self.given = bytearray()  # every byte a read returned
        self.events: list[Event] = [] if events is None else events
        self.record_resets = record_resets
        self.timeout = timeout
        self.fail = fail
        self.on_timeout = on_timeout
        self.levels = {"dtr": True, "rts": True}  # as pyserial opens a port
        self.breaking = False
        self.closed = False

    @property
    def writes(self) -> list[bytes]:
        """Each write's bytes, in order."""
        return [event[1] for event in self.events if event[0] == "write"]

    def write(self, data: bytes, /) -> int:
        if self.fail:
            raise OSError(5, "the device is gone")
        self.written += data
        self.events.append(("write", bytes(data)))
        if self.device is not None:
            self.input += self.device.answer(bytes(data))
        return len(data)

    @property
    def break_condition(self) -> bool:
        return self.breaking

    @break_condition.setter
    def break_condition(self, value: bool) -> None:
        """pyserial's break: TX held low while True; each change recorded among the events."""
        if self.fail:
            raise OSError(5, "the device is gone")
        self.breaking = value
        self.events.append(("break", value))

    def flush(self) -> None:
        pass

    def _waiting(self) -> bytes:
        """What a read finds: the device's answers, then the script."""
        if not self.input and self.device is not None:
            self.input += self.device.listen()
        return bytes(self.input) + self.script

    def _take(self, count: int, complete: bool) -> bytes:
        answered = bytes(self.input[:count])
        del self.input[:count]
        rest = count - len(answered)
        taken = answered + self.script[:rest]
        self.script = self.script[rest:]
        self.given += taken
        if not complete and self.on_timeout is not None:  # the read waited its whole timeout for more
            self.on_timeout(self.timeout or 0.0)
        return taken

    @property
    def in_waiting(self) -> int:
        """pyserial's count of bytes waiting: the device's answers and the script."""
        return len(self.input) + len(self.script)

    def read(self, size: int = 1, /) -> bytes:
        waiting = self._waiting()
        return self._take(size, len(waiting) >= size)

    def read_until(self, expected: bytes = b"\n", size: int | None = None, /) -> bytes:
        waiting = self._waiting()
        end = waiting.find(expected)
        stop = len(waiting) if end < 0 else end + len(expected)
        if size is not None and size <= stop:
            return self._take(size, True)
        return self._take(stop, end >= 0)

    def reset_input_buffer(self) -> None:
        if self.record_resets:
            self.events.append(("reset input", bytes(self.input)))
        self.input.clear()

    def close(self) -> None:
        self.closed = True
