"""The values plans compute with, as Python types, and the callbacks' signatures: the words
every other module of the engine speaks.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

Value = int | float | bool | str | bytes | tuple[Any, ...]  # an array is a tuple
"""The value of a state variable, a parameter, a field or an output field."""

StateValues = Mapping[str, Any]
"""The state variables by name: a snapshot, never changed in place. (Each value is of
its variable's declared type, which the checker knows and Python's types cannot say.)"""

Args = list[Any]
"""The values of a call's parameters (or an input's fields), by position."""


class OutputMessage(dict[str, Any]):
    """An output as its callbacks get it: `{"name": ..., "contents": {...}}`, and `read_ns`, when
    the state it was computed from was read (the newest reply's, in nanoseconds since the epoch,
    the host's clock; when it was delivered if no reply has changed the state yet). What a
    framework's header stamp carries: the data's time, not the publishing's. A dict, so that it
    compares, prints and serialises as the two keys it holds."""

    __slots__ = ("read_ns",)

    def __init__(self, name: str, contents: dict[str, Any], read_ns: int) -> None:
        super().__init__(name=name, contents=contents)
        self.read_ns = read_ns


OutputCallback = Callable[[OutputMessage], object]
ErrorCallback = Callable[[BaseException], object]
IoCallback = Callable[[str, str, bytes], object]
"""`(direction, connection, data)`: "write" or "read" and the bytes, or "lines" and the modem
lines a primitive set, as ASCII text such as b"dtr=0 rts=1"."""
TraceCallback = Callable[[float, str, str, bytes], object]
"""`(time, kind, connection, data)`: what an I/O callback sees, and "skip" with why a reply was
read past (`skip unmatched`, as UTF-8 text), each stamped when it happened by the robot's clock
(`time.monotonic`, or a simulation's time)."""
