"""Sensors (thesis §7.2.4): a primitive's one value, kept for the sensor's cache time.

A reader (an output's fields, an interface's calls, `robot.sensors.NAME`) first makes each
sensor it reads fresh: within the cache time of the last read nothing is sent; after it, one
reader makes the primitive's exchange and the readers that come meanwhile wait for that one
and share it. A value is kept from when its request began, so none is older than the cache
time when it is read; a read that fails raises its error to every reader waiting for it, and
the next reader tries again (the old value is never served in its place).
"""

from __future__ import annotations

import copy
import threading
from collections.abc import Callable, Mapping

from rdisc.engine.plans import Primitive, Sensor
from rdisc.engine.signals import Flag
from rdisc.engine.values import Value


class _Flight:
    """A read in flight: set when it is done; `error`, what it raised."""

    __slots__ = ("done", "error")

    def __init__(self) -> None:
        self.done = Flag()
        self.error: BaseException | None = None


class SensorCache:
    """When each sensor was last read (by the robot's clock), and the reads in flight."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._read_at: dict[str, float] = {}
        self._flights: dict[str, _Flight] = {}

    def age(self, name: str, now: float) -> float | None:
        """Seconds since the sensor's value was read; None: never read."""
        at = self._read_at.get(name)
        return None if at is None else now - at

    def refresh(self, sensor: Sensor, now: float, read: Callable[[Primitive], None]) -> None:
        """Make `sensor` fresh at `now`: nothing when its value is younger than its cache time;
        else wait for the read in flight, or make one (`read` of its primitive)."""
        name = sensor.name
        with self._lock:
            at = self._read_at.get(name)
            if at is not None and now - at < sensor.cache:
                return
            flight = self._flights.get(name)
            if flight is not None:
                leader = False
            else:
                leader, flight = True, _Flight()
                self._flights[name] = flight
        if not leader:
            flight.done.wait()
            if flight.error is not None:
                raise copy.copy(flight.error) from flight.error  # each reader its own
            return
        try:
            read(sensor.primitive)
        except BaseException as err:
            flight.error = err
            raise
        else:
            with self._lock:
                self._read_at[name] = now  # its request began no earlier than this
        finally:
            with self._lock:
                del self._flights[name]
            flight.done.set()


class Sensors:
    """`robot.sensors`: each sensor's value as an attribute of its name, read first when stale."""

    def __init__(self, sensors: Mapping[str, Sensor], read: Callable[[str], Value]) -> None:
        self._sensors = sensors
        self._read = read

    def __getattr__(self, name: str) -> Value:
        if name.startswith("_") or name not in self._sensors:
            raise AttributeError(f"no sensor named {name!r}")
        return self._read(name)

    def __getitem__(self, name: str) -> Value:
        if name not in self._sensors:
            raise KeyError(name)
        return self._read(name)

    def __dir__(self) -> list[str]:
        return sorted(self._sensors)
