"""Dynamixel AX-12 (protocol 1.0) as the published driver `pyax12` speaks it, captured on a real pty.

Why: rdisc descriptions of the AX-12 must produce the same bytes as the driver people use, and
decode replies as the device manual says. This module runs `pyax12.connection.Connection` against
an emulated servo on the master side of a pseudo-terminal and records what it really wrote.

The protocol (ROBOTIS AX-12 manual, "Communication Protocol"; Dynamixel protocol 1.0)
-------------------------------------------------------------------------------------
Instruction packet (host -> servo)::

    FF FF  ID  LEN  INSTR  P1 .. PN  CHK

* header: two 0xFF bytes.
* ID: 0x00-0xFD addresses one servo; 0xFE is the broadcast ID (every servo obeys, none answers).
* LEN = N + 2: it counts INSTR, the N parameters and CHK (not the header, ID or LEN itself).
* CHK = ~(ID + LEN + INSTR + P1 + ... + PN) & 0xFF: the low byte of the inverted sum of every byte
  after the header.
* INSTR: PING 0x01 (no parameter), READ_DATA 0x02 (start address, byte count), WRITE_DATA 0x03
  (start address, data bytes...), REG_WRITE 0x04, ACTION 0x05, RESET 0x06 (factory defaults,
  no parameter), SYNC_WRITE 0x83.
* Parameters are control-table bytes; 16-bit values are little-endian (low byte at the lower
  address). Addresses used here: model number 0x00 (2), firmware 0x02, ID 0x03, baud rate 0x04
  (bps = 2 000 000 / (value + 1)), return delay time 0x05 (2 us units), CW/CCW angle limit 0x06/0x08
  (2 each), highest temperature 0x0B, lowest/highest voltage 0x0C/0x0D (0.1 V), max torque 0x0E (2),
  status return level 0x10, torque enable 0x18, LED 0x19, goal position 0x1E (2, 0-1023 = 0-300
  degrees), moving speed 0x20 (2; 0-1023, in wheel mode bit 10 = CW), torque limit 0x22 (2), present
  position 0x24 (2), present speed 0x26 (2; bit 10 = CW), present load 0x28 (2; bits 0-9 magnitude,
  bit 10 = 1 for a CW load, 0 for CCW), present voltage 0x2A (0.1 V), present temperature 0x2B (deg C),
  moving 0x2E (1 = moving).

Status packet (servo -> host), the only reply::

    FF FF  ID  LEN  ERR  P1 .. PN  CHK      LEN = N + 2, CHK = ~(ID + LEN + ERR + P1 + ... + PN) & 0xFF

* ID is the answering servo's; for READ_DATA the N parameters are exactly the bytes asked for.
* ERR bits: 0 input voltage, 1 angle limit, 2 overheating, 3 range, 4 instruction checksum,
  5 overload, 6 instruction; bit 7 is reserved (0). The parameters are valid whatever ERR holds.
* Acknowledgement: a status packet follows every instruction after the return delay time (default
  500 us), as the status return level (0x10) allows: 0 = PING only, 1 = PING and READ_DATA,
  2 = all (default). A broadcast instruction is never answered.

What the driver does
--------------------
`Connection.send` flushes the input, writes the instruction packet, sleeps `waiting_time`
(0.02 s), then reads whatever `in_waiting` says has arrived and parses it as one status packet;
every method (also the writes) goes through it, so a write's status packet is read and its error
bits raise, and a write with no status (broadcast, status return level < 2) returns None quietly.
The harness makes that sleep deterministic: `pyax12.connection.time` is replaced, while a call
runs, by a shim whose `sleep` waits until the emulated servo has handled the packet and its reply
is readable. Unit conversions use Python's round (halves to even: `set_return_delay_time(1, 1)`
sends 0) and floor for degrees (`goto(1, 0, None, True)` sends 511, the manual's 0x1FF = 150 deg).

Bugs and deviations from the manual (entries marked `spec_bytes` / `spec_values`)
------------------------------------------------------------------------------------
1. `get_present_load` inverts the direction: it returns a negative load (its docstring: "clockwise")
   when bit 10 is 0, which the manual defines as a CCW load, and a positive one for a CW load.
   Raw 0x0464 (bit 10 set, CW, magnitude 100) decodes to +100; spec (CW negative) -100.
2. A status packet with more parameters than were read is accepted for one-byte reads: reading
   the temperature (1 byte) with a 2-parameter reply returns the first one. Spec: refuse.
3. No range checks: `goto(1, 1024)` and `goto(..., degrees=True)` past 150 degrees send goal
   positions above 1023, `set_id(1, 254)` writes the broadcast ID as an ID (spec IDs 0-253). Marked
   `spec_bytes=Rejected`. (Negative values do raise ValueError, from the byte conversion.)
4. No reply, or a reply from another ID, makes reads fail with a TypeError (`read_data` returns None
   and the caller indexes it), not a timeout/protocol error; `ping` returns False for both.
5. A reply is whatever arrived within `waiting_time`: a late reply (slow adapter, long return delay)
   is missed and later flushed; bytes before or after the packet (noise) make it fail instead of
   resynchronising on FF FF. Not capturable deterministically here (the shim waits for the reply).
6. Any error bit raises (InstructionError, OverloadError, ...), and the read value is lost although
   the manual says it is valid; bit 7 (reserved) is ignored. Documented, not marked.
7. `get_present_speed` returns the raw value (bit 10 = CW not decoded), unlike `get_present_load`.
   Raw is what the table holds; not marked.
8. RESET, REG_WRITE, ACTION and SYNC_WRITE have no `Connection` method (reset is commented out);
   torque enable and LED have no setter: they are `write_data(id, 0x18 / 0x19, value)` here. The
   spec RESET packet for ID 1 is FF FF 01 02 06 F6.
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Iterator
from types import SimpleNamespace
from typing import Any, NamedTuple

import pyax12.connection
from devices import PtyDevice
from pyax12.connection import Connection

__all__ = ["CALLS", "REPLIES", "Call", "Rejected", "Reply", "published_decode", "published_request"]

BROADCAST = 0xFE


class Rejected(Exception):
    """Marker for `spec_bytes` / `spec_values`: the specification says this must be refused."""


class Call(NamedTuple):
    """One driver call: `Connection.<method>(*args)`; args[0] is the Dynamixel ID."""

    label: str
    method: str
    args: tuple[Any, ...]
    spec_bytes: bytes | type[Exception] | None = None  # set where the driver deviates from the spec


class Reply(NamedTuple):
    """A status packet fed to `Connection.<method>(*args)`, and what the spec says it decodes to."""

    label: str
    method: str
    args: tuple[Any, ...]
    reply: bytes
    spec_values: tuple[Any, ...] | type[Exception] | None = None  # set where the driver deviates


def checksum(body: bytes) -> int:
    """Protocol 1.0 checksum of the bytes after the header (ID to last parameter)."""
    return ~sum(body) & 0xFF


def status(dxl_id: int, params: bytes = b"", error: int = 0) -> bytes:
    """A well-formed status packet."""
    body = bytes([dxl_id, len(params) + 2, error]) + params
    return b"\xff\xff" + body + bytes([checksum(body)])


def _bad_checksum(packet: bytes) -> bytes:
    return packet[:-1] + bytes([packet[-1] ^ 0xFF])


CALLS: list[Call] = [
    Call("ping_id0", "ping", (0,)),
    Call("ping_id1", "ping", (1,)),
    Call("ping_id253", "ping", (0xFD,)),
    Call("ping_broadcast", "ping", (BROADCAST,)),
    Call("ping_id255", "ping", (0xFF,)),  # not an ID: ValueError, nothing sent
    Call("read_position_raw", "read_data", (1, 0x24, 2)),
    Call("read_control_table", "read_data", (1, 0x00, 50)),
    Call("torque_on", "write_data", (1, 0x18, 1)),
    Call("torque_off", "write_data", (1, 0x18, 0)),
    Call("torque_off_broadcast", "write_data", (BROADCAST, 0x18, 0)),
    Call("led_on", "write_data", (1, 0x19, 1)),
    Call("led_off_id253", "write_data", (0xFD, 0x19, 0)),
    Call("present_position", "get_present_position", (1,)),
    Call("present_position_degrees", "get_present_position", (1, True)),
    Call("present_speed", "get_present_speed", (1,)),
    Call("present_load", "get_present_load", (1,)),
    Call("present_voltage", "get_present_voltage", (1,)),
    Call("present_temperature", "get_present_temperature", (1,)),
    Call("is_moving", "is_moving", (1,)),
    Call("goal_position", "get_goal_position", (1,)),
    Call("moving_speed", "get_moving_speed", (1,)),
    Call("torque_limit", "get_torque_limit", (1,)),
    Call("cw_angle_limit", "get_cw_angle_limit", (1,)),
    Call("ccw_angle_limit", "get_ccw_angle_limit", (1,)),
    Call("model_number", "get_model_number", (1,)),
    Call("firmware_version", "get_firmware_version", (1,)),
    Call("baud_rate", "get_baud_rate", (1,)),
    Call("return_delay_time", "get_return_delay_time", (1,)),
    Call("max_temperature", "get_max_temperature", (1,)),
    Call("min_voltage", "get_min_voltage", (1,)),
    Call("max_voltage", "get_max_voltage", (1,)),
    Call("max_torque", "get_max_torque", (1,)),
    Call("status_return_level", "get_status_return_level", (1,)),
    Call("is_torque_enable", "is_torque_enable", (1,)),
    Call("is_led_enabled", "is_led_enabled", (1,)),
    Call("goto_0", "goto", (1, 0)),
    Call("goto_512", "goto", (1, 512)),
    Call("goto_1023", "goto", (1, 1023)),
    Call("goto_1024", "goto", (1, 1024), Rejected),
    Call("goto_negative", "goto", (1, -1)),
    Call("goto_speed_0", "goto", (1, 512, 0)),
    Call("goto_speed_1023", "goto", (1, 300, 1023)),
    Call("goto_broadcast", "goto", (BROADCAST, 512)),
    Call("goto_deg_min", "goto", (1, -150, None, True)),
    Call("goto_deg_0", "goto", (1, 0, None, True)),
    Call("goto_deg_max", "goto", (1, 150, None, True)),
    Call("goto_deg_over", "goto", (1, 151, None, True), Rejected),
    Call("set_speed_0", "set_speed", (1, 0)),
    Call("set_speed_1023", "set_speed", (1, 1023)),
    Call("set_speed_wheel_cw_max", "set_speed", (1, 2047)),
    Call("set_speed_negative", "set_speed", (1, -1)),
    Call("set_id_0", "set_id", (1, 0)),
    Call("set_id_253", "set_id", (1, 0xFD)),
    Call("set_id_254", "set_id", (1, 0xFE), Rejected),
    Call("set_id_negative", "set_id", (1, -1)),
    Call("baud_1mbps", "set_baud_rate", (1, 1000)),
    Call("baud_57600", "set_baud_rate", (1, 57.6)),
    Call("baud_9600_bps", "set_baud_rate", (1, 9600, "bps")),
    Call("baud_raw_0", "set_baud_rate", (1, 0, "raw")),
    Call("baud_raw_254", "set_baud_rate", (1, 254, "raw")),
    Call("return_delay_0", "set_return_delay_time", (1, 0)),
    Call("return_delay_1us", "set_return_delay_time", (1, 1)),  # round(0.5): half to even, 0
    Call("return_delay_500us", "set_return_delay_time", (1, 500)),
    Call("return_delay_raw_254", "set_return_delay_time", (1, 254, "raw")),
    Call("cw_limit_0", "set_cw_angle_limit", (1, 0)),
    Call("cw_limit_1023", "set_cw_angle_limit", (1, 1023)),
    Call("cw_limit_deg_min", "set_cw_angle_limit", (1, -150, True)),
    Call("ccw_limit_0_wheel", "set_ccw_angle_limit", (1, 0)),
    Call("ccw_limit_1023", "set_ccw_angle_limit", (1, 1023)),
    Call("ccw_limit_deg_max", "set_ccw_angle_limit", (1, 150, True)),
]

_POS_512 = status(1, b"\x00\x02")
REPLIES: list[Reply] = [
    Reply("ping_ok", "ping", (1,), status(1)),
    Reply("ping_other_id", "ping", (1,), status(2)),
    Reply("ping_silent", "ping", (1,), b""),
    Reply("position_0", "get_present_position", (1,), status(1, b"\x00\x00")),
    Reply("position_512", "get_present_position", (1,), _POS_512),
    Reply("position_1023", "get_present_position", (1,), status(1, b"\xff\x03")),
    Reply("position_deg_0", "get_present_position", (1, True), status(1, b"\x00\x00")),
    Reply("position_deg_512", "get_present_position", (1, True), _POS_512),
    Reply("position_deg_1023", "get_present_position", (1, True), status(1, b"\xff\x03")),
    Reply("speed_0", "get_present_speed", (1,), status(1, b"\x00\x00")),
    Reply("speed_ccw_max", "get_present_speed", (1,), status(1, b"\xff\x03")),
    Reply("speed_cw_max", "get_present_speed", (1,), status(1, b"\xff\x07")),
    Reply("load_0", "get_present_load", (1,), status(1, b"\x00\x00")),
    Reply("load_ccw_100", "get_present_load", (1,), status(1, b"\x64\x00"), (100,)),
    Reply("load_ccw_max", "get_present_load", (1,), status(1, b"\xff\x03"), (1023,)),
    Reply("load_cw_100", "get_present_load", (1,), status(1, b"\x64\x04"), (-100,)),
    Reply("load_cw_max", "get_present_load", (1,), status(1, b"\xff\x07"), (-1023,)),
    Reply("voltage_0", "get_present_voltage", (1,), status(1, b"\x00")),
    Reply("voltage_12v", "get_present_voltage", (1,), status(1, b"\x78")),
    Reply("voltage_max", "get_present_voltage", (1,), status(1, b"\xff")),
    Reply("temperature_0", "get_present_temperature", (1,), status(1, b"\x00")),
    Reply("temperature_40", "get_present_temperature", (1,), status(1, b"\x28")),
    Reply("temperature_max", "get_present_temperature", (1,), status(1, b"\xff")),
    Reply("moving_no", "is_moving", (1,), status(1, b"\x00")),
    Reply("moving_yes", "is_moving", (1,), status(1, b"\x01")),
    Reply("model_ax12", "get_model_number", (1,), status(1, b"\x0c\x00")),
    Reply("baud_1mbps", "get_baud_rate", (1,), status(1, b"\x01")),
    Reply("write_ack", "goto", (1, 512), status(1)),
    Reply("write_silent", "goto", (1, 512), b""),
    Reply("err_input_voltage", "get_present_temperature", (1,), status(1, b"\x28", 0x01)),
    Reply("err_angle_limit", "goto", (1, 512), status(1, b"", 0x02)),
    Reply("err_overheating", "get_present_temperature", (1,), status(1, b"\x50", 0x04)),
    Reply("err_range", "goto", (1, 512), status(1, b"", 0x08)),
    Reply("err_checksum", "goto", (1, 512), status(1, b"", 0x10)),
    Reply("err_overload", "get_present_position", (1,), status(1, b"\x00\x02", 0x20)),
    Reply("err_instruction", "ping", (1,), status(1, b"", 0x40)),
    Reply("err_reserved_bit7", "get_present_temperature", (1,), status(1, b"\x28", 0x80)),
    Reply("bad_checksum", "get_present_position", (1,), _bad_checksum(_POS_512)),
    Reply("bad_header", "get_present_position", (1,), b"\xff\xfe" + _POS_512[2:]),
    Reply("no_checksum", "get_present_position", (1,), _POS_512[:-1]),
    Reply("truncated", "get_present_position", (1,), _POS_512[:3]),
    Reply("silent", "get_present_position", (1,), b""),
    Reply("other_id", "get_present_position", (1,), status(2, b"\x00\x02")),
    Reply("too_few_params", "get_present_position", (1,), status(1, b"\x00")),
    Reply("too_many_params_2byte", "get_present_position", (1,), status(1, b"\x00\x02\x00")),
    Reply("too_many_params_1byte", "get_present_temperature", (1,), status(1, b"\x28\x00"), Rejected),
    Reply("length_too_big", "get_present_position", (1,), b"\xff\xff\x01\x05\x00\x00\x02\xf5"),
]

# A plausible AX-12 control table (addresses 0-49), so that any read gets a valid answer.
_TABLE = bytes([
    0x0C, 0x00, 0x18, 0x01, 0x01, 0xFA, 0x00, 0x00, 0xFF, 0x03, 0x00, 0x46, 0x3C, 0x8C, 0xFF, 0x03,
    0x02, 0x24, 0x24, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x01, 0x01, 0x20, 0x20, 0x00, 0x02,
    0x00, 0x00, 0xFF, 0x03, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x78, 0x28, 0x00, 0x00, 0x00, 0x00,
    0x20, 0x00,
])


class _Ax12(PtyDevice):
    """An AX-12 on the bus: answers PING/READ_DATA/WRITE_DATA, or `override` once if set."""

    def __init__(self, dxl_id: int) -> None:
        super().__init__()
        self.dxl_id = dxl_id
        self.table = bytearray(_TABLE)
        self.override: bytes | None = None
        self.handled = 0  # instruction packets handled (answered or not)
        self.reply_len = 0  # length of the last answer
        self._pending = bytearray()

    def handle(self, data: bytes) -> None:
        self._pending += data
        while (packet := self._next_packet()) is not None:
            reply = self._answer(packet)
            if self.override is not None:
                reply, self.override = self.override, None
            self.send(reply)
            with self._cond:
                self.handled += 1
                self.reply_len = len(reply)
                self._cond.notify_all()

    def _next_packet(self) -> bytes | None:
        start = self._pending.find(b"\xff\xff")
        if start < 0:
            del self._pending[:-1]
            return None
        del self._pending[:start]
        if len(self._pending) < 4 or len(self._pending) < 4 + self._pending[3]:
            return None
        size = 4 + self._pending[3]
        packet = bytes(self._pending[:size])
        del self._pending[:size]
        return packet

    def _answer(self, packet: bytes) -> bytes:
        dxl_id, instr, params = packet[2], packet[4], packet[5:-1]
        if dxl_id != self.dxl_id or checksum(packet[2:-1]) != packet[-1]:
            return b""
        if instr == 0x01:
            return status(dxl_id)
        if instr == 0x02:
            return status(dxl_id, bytes(self.table[params[0]:params[0] + params[1]]))
        if instr == 0x03:
            self.table[params[0]:params[0] + len(params) - 1] = params[1:]
            return status(dxl_id)
        return status(dxl_id, error=0x40)


@contextlib.contextmanager
def _connection(dxl_id: int) -> Iterator[tuple[_Ax12, Connection]]:
    """A servo with this ID on a pty, and a `Connection` to it whose reply wait is deterministic."""
    with _Ax12(dxl_id if 0 <= dxl_id <= 0xFD else 1) as dev:
        conn = Connection(port=dev.port, baudrate=1_000_000, timeout=0.05)
        seen = 0

        def sleep(_seconds: float) -> None:
            # Stands for the driver's fixed wait: until the servo handled the packet and its
            # whole answer is readable on the driver's side of the pty.
            nonlocal seen
            dev.wait_until(lambda: dev.handled > seen, 2.0, "an instruction packet")
            seen = dev.handled
            deadline = time.monotonic() + 2.0
            while conn.serial_connection.in_waiting < dev.reply_len and time.monotonic() < deadline:
                time.sleep(0.001)

        saved = pyax12.connection.time
        pyax12.connection.time = SimpleNamespace(sleep=sleep)  # type: ignore[assignment]
        try:
            yield dev, conn
        finally:
            pyax12.connection.time = saved
            conn.close()


def _first_id(args: tuple[Any, ...]) -> int:
    return args[0] if args and isinstance(args[0], int) else 1


def published_request(method: str, *args: Any) -> bytes:
    """The bytes `Connection.<method>(*args)` writes (the emulated servo answers validly).

    A driver exception (e.g. ValueError for an out-of-range argument) propagates.
    """
    with _connection(_first_id(args)) as (dev, conn):
        getattr(conn, method)(*args)
        return dev.received


def published_decode(method: str, args: tuple[Any, ...], reply: bytes) -> tuple[Any, ...] | type[Exception]:
    """What `Connection.<method>(*args)` returns when the servo answers `reply` (b"": silence).

    A flat tuple of values (() for None), or the type of the exception the driver raised.
    """
    with _connection(_first_id(args)) as (dev, conn):
        dev.override = reply
        try:
            result = getattr(conn, method)(*args)
        except Exception as exc:  # noqa: BLE001 - the exception type is the result
            return type(exc)
    if result is None:
        return ()
    return tuple(result) if isinstance(result, (tuple, list)) else (result,)
