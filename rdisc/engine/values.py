"""The values plans compute with, as Python types, the parameters they are given for (and the
rule of their ranges), and the callbacks' signatures: the words every other module of the
engine speaks.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from rdisc.engine.errors import RdisValueError
from rdisc.engine.operations import FLOAT_MAX

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


@dataclass(frozen=True, slots=True)
class Param:
    """A parameter of an interface or a primitive, or a field of an input's adapter."""

    name: str
    kind: type  # int, float, bool, str or bytes; an array's elements'
    low: float | None = None  # the declared range (for bytes, of the length; for an array, of each element)
    high: float | None = None
    default: Value | None = None  # the value when a call leaves it out
    size: int | None = None  # an array's: its number of elements (0: any); None: not an array
    low_terms: tuple[tuple[int, int], ...] = ()  # a bound that reads earlier parameters (`0..count - 1`):
    high_terms: tuple[tuple[int, int], ...] = ()  # (their index, +1 or -1), each added to `low` or `high`


def _ranged(params: tuple[Param, ...]) -> tuple[int, ...]:
    return tuple(i for i, p in enumerate(params) if p.low is not None)


def held_to(param: Param) -> tuple[Any, Any] | None:
    """The range a one-step request holds a value of `param` to: its declared range; for a float
    without one, the finite floats (NaN and the infinities fail it, and go the general way, which
    refuses them); None for any other."""
    if param.low is not None:
        return param.low, param.high
    return (-FLOAT_MAX, FLOAT_MAX) if param.kind is float and param.size is None else None


def one_step_bounds(params: tuple[Param, ...]) -> tuple[tuple[int, Any, Any], ...]:
    """Each parameter a one-step request holds to a range (`held_to`): (its index, low, high)."""
    return tuple((i, *held) for i, held in ((i, held_to(p)) for i, p in enumerate(params)) if held is not None)


def not_finite(value: Any, what: str) -> RdisValueError:
    """The error of a float given that is NaN or infinite (a clamp or a comparison in a description
    would make it a valid command: an infinite speed full speed)."""
    return RdisValueError(f"{what} is {value!r}: a number must be finite")


def _check_ranges(owner: str, params: tuple[Param, ...], ranged: tuple[int, ...], values: Args,
               role: str = "parameter") -> None:
    """A value outside its parameter's (or setting's) declared range is refused before anything is sent."""
    for i in ranged:
        p, value = params[i], values[i]
        low, high = p.low, p.high
        assert low is not None and high is not None  # `ranged` holds the parameters with a range
        if p.low_terms or p.high_terms:  # checked at each call, over the earlier parameters' values
            low += sum(values[k] * sign for k, sign in p.low_terms)
            high += sum(values[k] * sign for k, sign in p.high_terms)
        if isinstance(value, bytes):
            if not low <= len(value) <= high:
                raise RdisValueError(f"{owner}: {role} {p.name} has {len(value)} bytes, outside {low!r}..{high!r}")
        elif isinstance(value, tuple):
            for k, item in enumerate(value):
                if not low <= item <= high:
                    raise RdisValueError(f"{owner}: {role} {p.name}[{k}] is {item!r}, outside {low!r}..{high!r}")
        elif not low <= value <= high:
            raise RdisValueError(f"{owner}: {role} {p.name} is {value!r}, outside {low!r}..{high!r}")
