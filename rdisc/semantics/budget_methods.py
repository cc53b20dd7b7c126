"""The methods of the frozen dataclasses of rdisc/semantics/budget.py, written out ahead of time (why: rdisc/frozen.py).

Written by `python -m rdisc.frozen_writer` from the declarations: do not edit; rerun it after
changing a class's fields (a test holds this file equal to what it writes).
"""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.frozen import DEFAULT, MISSING, Written, classes, field

if TYPE_CHECKING:
    from typing import Any

__all__ = ["dataclass", "field"]

# Each field's setter, `_set_<class>_<field>(instance, value)`: its slot's own `__set__`, bound by
# rdisc.frozen when it makes the class (a third faster than object.__setattr__ with the field's name).
_unbound: Any = None


_set_Exchange_interface = _set_Exchange_bytes = _set_Exchange_wire_ms = _set_Exchange_delay_ms = _unbound


def _init_Exchange(self: Any, interface: Any, bytes: Any, wire_ms: Any, delay_ms: Any) -> None:
    _set_Exchange_interface(self, interface)
    _set_Exchange_bytes(self, bytes)
    _set_Exchange_wire_ms(self, wire_ms)
    _set_Exchange_delay_ms(self, delay_ms)


def _repr_Exchange(self: Any) -> str:
    return f"{self.__class__.__qualname__}(interface={self.interface!r}, bytes={self.bytes!r}, wire_ms={self.wire_ms!r}, delay_ms={self.delay_ms!r})"


def _eq_Exchange(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.interface,
            self.bytes,
            self.wire_ms,
            self.delay_ms,
        ) == (
            other.interface,
            other.bytes,
            other.wire_ms,
            other.delay_ms,
        )
    return NotImplemented


def _hash_Exchange(self: Any) -> int:
    return hash((self.interface, self.bytes, self.wire_ms, self.delay_ms))


_set_SensorLoad_sensor = _set_SensorLoad_bytes = _set_SensorLoad_wire_ms = _set_SensorLoad_rate_hz = _unbound


def _init_SensorLoad(self: Any, sensor: Any, bytes: Any, wire_ms: Any, rate_hz: Any) -> None:
    _set_SensorLoad_sensor(self, sensor)
    _set_SensorLoad_bytes(self, bytes)
    _set_SensorLoad_wire_ms(self, wire_ms)
    _set_SensorLoad_rate_hz(self, rate_hz)


def _repr_SensorLoad(self: Any) -> str:
    return f"{self.__class__.__qualname__}(sensor={self.sensor!r}, bytes={self.bytes!r}, wire_ms={self.wire_ms!r}, rate_hz={self.rate_hz!r})"


def _eq_SensorLoad(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.sensor,
            self.bytes,
            self.wire_ms,
            self.rate_hz,
        ) == (
            other.sensor,
            other.bytes,
            other.wire_ms,
            other.rate_hz,
        )
    return NotImplemented


def _hash_SensorLoad(self: Any) -> int:
    return hash((self.sensor, self.bytes, self.wire_ms, self.rate_hz))


_set_ConnectionBudget_connection = _unbound
_set_ConnectionBudget_baud = _unbound
_set_ConnectionBudget_frequency_hz = _unbound
_set_ConnectionBudget_periodic = _unbound
_set_ConnectionBudget_keepalive = _unbound
_set_ConnectionBudget_keepalive_interval_ms = _unbound
_set_ConnectionBudget_baud_setting = _unbound
_set_ConnectionBudget_bits_per_byte = _unbound
_set_ConnectionBudget_threading = _unbound
_set_ConnectionBudget_rates = _unbound
_set_ConnectionBudget_sensed = _unbound


def _init_ConnectionBudget(
    self: Any,
    connection: Any,
    baud: Any,
    frequency_hz: Any,
    periodic: Any,
    keepalive: Any,
    keepalive_interval_ms: Any,
    baud_setting: Any = DEFAULT,
    bits_per_byte: Any = DEFAULT,
    threading: Any = DEFAULT,
    rates: Any = DEFAULT,
    sensed: Any = DEFAULT,
) -> None:
    _set_ConnectionBudget_connection(self, connection)
    _set_ConnectionBudget_baud(self, baud)
    _set_ConnectionBudget_frequency_hz(self, frequency_hz)
    _set_ConnectionBudget_periodic(self, periodic)
    _set_ConnectionBudget_keepalive(self, keepalive)
    _set_ConnectionBudget_keepalive_interval_ms(self, keepalive_interval_ms)
    _set_ConnectionBudget_baud_setting(self, baud_setting)
    _set_ConnectionBudget_bits_per_byte(self, bits_per_byte)
    _set_ConnectionBudget_threading(self, threading)
    _set_ConnectionBudget_rates(self, rates)
    _set_ConnectionBudget_sensed(self, sensed)


def _repr_ConnectionBudget(self: Any) -> str:
    return f"{self.__class__.__qualname__}(connection={self.connection!r}, baud={self.baud!r}, frequency_hz={self.frequency_hz!r}, periodic={self.periodic!r}, keepalive={self.keepalive!r}, keepalive_interval_ms={self.keepalive_interval_ms!r}, baud_setting={self.baud_setting!r}, bits_per_byte={self.bits_per_byte!r}, threading={self.threading!r}, rates={self.rates!r}, sensed={self.sensed!r})"


def _eq_ConnectionBudget(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return (
            self.connection,
            self.baud,
            self.frequency_hz,
            self.periodic,
            self.keepalive,
            self.keepalive_interval_ms,
            self.baud_setting,
            self.bits_per_byte,
            self.threading,
            self.rates,
            self.sensed,
        ) == (
            other.connection,
            other.baud,
            other.frequency_hz,
            other.periodic,
            other.keepalive,
            other.keepalive_interval_ms,
            other.baud_setting,
            other.bits_per_byte,
            other.threading,
            other.rates,
            other.sensed,
        )
    return NotImplemented


def _hash_ConnectionBudget(self: Any) -> int:
    return hash((
        self.connection,
        self.baud,
        self.frequency_hz,
        self.periodic,
        self.keepalive,
        self.keepalive_interval_ms,
        self.baud_setting,
        self.bits_per_byte,
        self.threading,
        self.rates,
        self.sensed,
    ))


WRITTEN: dict[str, Written] = {
    "Exchange": Written(
        (("interface", MISSING), ("bytes", MISSING), ("wire_ms", MISSING), ("delay_ms", MISSING)),
        {
            "__init__": _init_Exchange,
            "__repr__": _repr_Exchange,
            "__eq__": _eq_Exchange,
            "__hash__": _hash_Exchange,
        },
    ),
    "SensorLoad": Written(
        (("sensor", MISSING), ("bytes", MISSING), ("wire_ms", MISSING), ("rate_hz", MISSING)),
        {
            "__init__": _init_SensorLoad,
            "__repr__": _repr_SensorLoad,
            "__eq__": _eq_SensorLoad,
            "__hash__": _hash_SensorLoad,
        },
    ),
    "ConnectionBudget": Written(
        (
            ("connection", MISSING),
            ("baud", MISSING),
            ("frequency_hz", MISSING),
            ("periodic", MISSING),
            ("keepalive", MISSING),
            ("keepalive_interval_ms", MISSING),
            ("baud_setting", DEFAULT),
            ("bits_per_byte", DEFAULT),
            ("threading", DEFAULT),
            ("rates", DEFAULT),
            ("sensed", DEFAULT),
        ),
        {
            "__init__": _init_ConnectionBudget,
            "__repr__": _repr_ConnectionBudget,
            "__eq__": _eq_ConnectionBudget,
            "__hash__": _hash_ConnectionBudget,
        },
    ),
}
dataclass = classes(WRITTEN)
