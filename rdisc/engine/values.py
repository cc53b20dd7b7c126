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

OutputCallback = Callable[[dict[str, Any]], object]
ErrorCallback = Callable[[BaseException], object]
IoCallback = Callable[[str, str, bytes], object]
"""`(direction, connection, data)`: "write" or "read" and the bytes, or "lines" and the modem
lines a primitive set, as ASCII text such as b"dtr=0 rts=1"."""
