"""Actuators' limits on the commands they are given (thesis §7.2.6): a position a servo is
commanded moves toward the command no faster than its `velocity` and `acceleration` allow, a
speed a wheel is commanded stays within its `velocity` and changes by at most its `acceleration`,
each measured by the robot's clock from the command written before; or, where the description
says `limit refuse`, a command beyond them is an RdisLimitError and nothing is written.

The limits are stated in the joint's units and applied to the device's values (a transmission's
conversion is a ratio: `device = (joint - offset) * reduction`), so the value written is the
device's own, rounded to a whole number where the parameter is one; what the actuator was given
is kept unrounded, so a slow slew still moves by its fraction of a step each call. The first
command an actuator is given has nothing before it: it is written as it is, but for a speed
beyond the wheel's `velocity`.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from rdisc.engine.errors import RdisLimitError

_SLACK = 1e-9  # relative: a command exactly at a limit, as floats compute it, is within it


@dataclass(frozen=True, slots=True)
class ActuatorLimit:
    """One actuator's limits on a primitive's parameter (`param`, its position; `index`, the
    element of an array it is). `quantity` is "position" (a servo) or "velocity" (a wheel); the
    joint's value is `device / reduction + offset`. `velocity` and `acceleration` are in the
    joint's `unit` a second (and a second squared); None: no such limit. `refuse`: a command
    beyond them is refused, else shaped."""

    actuator: str
    param: int
    index: int | None
    quantity: str
    reduction: float
    offset: float = 0.0
    velocity: float | None = None
    acceleration: float | None = None
    refuse: bool = False
    unit: str = "rad"


@dataclass(frozen=True, slots=True)
class _Given:
    """What an actuator was last given: the device's value (unrounded), when, and its speed then
    (device units a second: a position's change over the time since the one before)."""

    value: float
    time: float
    speed: float


class Actuated:
    """Each actuator's last command, by name: what the limits are measured from."""

    def __init__(self) -> None:
        self._given: dict[str, _Given] = {}
        self._lock = threading.Lock()  # the host's calls and the periodic work's command alike

    def limited(self, limits: Sequence[ActuatorLimit], args: list[Any], now: float) -> list[Any]:
        """`args` with each limited value shaped (a new list, arrays copied), or an RdisLimitError for
        the first refused; what each actuator was given is kept only when every value passed."""
        shaped = list(args)
        copied: set[int] = set()
        given: dict[str, _Given] = {}
        with self._lock:
            for limit in limits:
                if limit.index is not None and limit.param not in copied:
                    shaped[limit.param] = list(shaped[limit.param])
                    copied.add(limit.param)
                holder = shaped[limit.param] if limit.index is not None else shaped
                at = limit.index if limit.index is not None else limit.param
                value = holder[at]
                before = self._given.get(limit.actuator)
                if limit.quantity == "position":
                    kept = _position(limit, float(value), before, now)
                else:
                    kept = _velocity(limit, float(value), before, now)
                given[limit.actuator] = kept
                holder[at] = round(kept.value) if type(value) is int else kept.value
            self._given.update(given)
        return shaped


def _position(limit: ActuatorLimit, value: float, before: _Given | None, now: float) -> _Given:
    """A position command: moved toward no faster than the limits allow since the one before."""
    if before is None:
        return _Given(value, now, 0.0)
    scale = abs(limit.reduction)
    fastest = math.inf if limit.velocity is None else limit.velocity * scale
    steepest = math.inf if limit.acceleration is None else limit.acceleration * scale
    elapsed = max(now - before.time, 0.0)
    change = value - before.value
    if change == 0:
        return _Given(value, now, 0.0)
    if limit.refuse:
        speed = math.inf if elapsed == 0 else change / elapsed
        moved = (f"a position of {_joint(limit, value):.6g} {limit.unit} {_after(elapsed)} "
                 f"{_joint(limit, before.value):.6g} {limit.unit}")
        if abs(speed) > fastest * (1 + _SLACK):
            raise _refused(limit, "velocity", f"{moved} moves {_rate(abs(speed) / scale, limit.unit + '/s')}")
        rate = math.inf if elapsed == 0 else abs(speed - before.speed) / elapsed
        if rate > steepest * (1 + _SLACK):
            raise _refused(limit, "acceleration", f"{moved} changes its speed from "
                           f"{before.speed / limit.reduction:.6g} to {speed / limit.reduction:.6g} {limit.unit}/s, "
                           f"{_rate(rate / scale, limit.unit + '/s²')}")
        return _Given(value, now, speed)
    if elapsed == 0:
        return _Given(before.value, now, before.speed)  # no time: no move
    wanted = change / elapsed
    most = min(fastest, math.sqrt(2 * steepest * abs(change)))  # at most a speed it can stop from in time
    speed = math.copysign(min(abs(wanted), most), wanted)
    speed = min(max(speed, before.speed - steepest * elapsed), before.speed + steepest * elapsed)
    if speed == wanted:
        return _Given(value, now, speed)
    return _Given(before.value + speed * elapsed, now, speed)


def _velocity(limit: ActuatorLimit, value: float, before: _Given | None, now: float) -> _Given:
    """A speed command: within the velocity limit, changed by at most the acceleration since the one before."""
    scale = abs(limit.reduction)
    fastest = math.inf if limit.velocity is None else limit.velocity * scale
    if abs(value) > fastest * (1 + _SLACK):
        if limit.refuse:
            raise _refused(limit, "velocity", f"a velocity of {value / limit.reduction:.6g} {limit.unit}/s")
        value = math.copysign(fastest, value)
    if before is None or limit.acceleration is None:
        return _Given(value, now, value)
    steepest = limit.acceleration * scale
    elapsed = max(now - before.time, 0.0)
    change = value - before.value
    rate = math.inf if elapsed == 0 and change else 0.0 if change == 0 else abs(change) / elapsed
    if rate > steepest * (1 + _SLACK):
        if limit.refuse:
            raise _refused(limit, "acceleration", f"a velocity of {value / limit.reduction:.6g} {limit.unit}/s "
                           f"{_after(elapsed)} {before.value / limit.reduction:.6g} {limit.unit}/s changes "
                           f"{_rate(rate / scale, limit.unit + '/s²')}")
        value = before.value + math.copysign(steepest * elapsed, change)
    return _Given(value, now, value)


def _joint(limit: ActuatorLimit, value: float) -> float:
    return value / limit.reduction + limit.offset


def _after(elapsed: float) -> str:
    return "at the same moment as" if elapsed == 0 else f"{elapsed:.6g} s after"


def _rate(value: float, unit: str) -> str:
    return "in no time" if math.isinf(value) else f"at {value:.6g} {unit}"


def _refused(limit: ActuatorLimit, which: str, what: str) -> RdisLimitError:
    """The error of a command beyond a limit, naming the actuator, the limit and the value."""
    most = limit.velocity if which == "velocity" else limit.acceleration
    assert most is not None  # a limit exceeded is one stated
    unit = f"{limit.unit}/s" if which == "velocity" else f"{limit.unit}/s²"
    return RdisLimitError(f"actuator {limit.actuator}: {what}, over its {which} limit of {most:g} {unit}: "
                          "not written (`limit refuse`)", limit.actuator, which, most)
